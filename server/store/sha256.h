// SHA-256 (FIPS 180-4), for hashing API tokens: the database keeps only salt + SHA-256(salt ||
// token), never the token itself. Written here because the store must not depend on OpenSSL.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace sw::store {

std::array<std::uint8_t, 32> sha256(std::string_view data);
std::string sha256_hex(std::string_view data);
std::string to_hex(const std::uint8_t* bytes, std::size_t count);
// Compares without an early exit, so the time taken says nothing about where two hashes differ.
bool constant_time_equal(std::string_view a, std::string_view b);

}  // namespace sw::store
