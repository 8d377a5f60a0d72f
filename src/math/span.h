// Span: a non-owning view of contiguous elements (C++17 has no std::span).
//
// Jobs (skeleton/local_to_model.h) take their inputs and outputs as spans so that they never
// allocate or own buffers: the caller decides where the data lives — a std::vector natively, a
// block of WASM memory handed to JS as a typed-array view in the page.
#pragma once

#include <cstddef>
#include <vector>

namespace sw::math {

template <typename T>
struct Span {
  T* data = nullptr;
  std::size_t size = 0;

  constexpr Span() = default;
  constexpr Span(T* begin, std::size_t count) : data(begin), size(count) {}
  // Views of a vector; const T binds to a const vector, non-const T only to a mutable one.
  template <typename U>
  Span(std::vector<U>& v) : data(v.data()), size(v.size()) {}  // NOLINT: implicit by design
  template <typename U>
  Span(const std::vector<U>& v) : data(v.data()), size(v.size()) {}  // NOLINT: implicit by design

  T& operator[](std::size_t i) const { return data[i]; }
  T* begin() const { return data; }
  T* end() const { return data + size; }
  bool empty() const { return size == 0; }
};

}  // namespace sw::math
