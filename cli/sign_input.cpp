// Reading signs for check/coverage (see sign_input.h).
#include "sign_input.h"

#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

namespace sw::cli {
namespace {

using notation::NotationFormat;

bool ends_with(const std::string& s, const char* suffix) {
  const std::string x(suffix);
  return s.size() >= x.size() && s.compare(s.size() - x.size(), x.size(), x) == 0;
}

std::vector<InputSign> parse_jsonl(const std::string& text, const InputOptions& options) {
  std::vector<InputSign> out;
  std::istringstream in(text);
  std::string line;
  int line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    InputSign sign;
    sign.line = line_number;
    const nlohmann::json j = nlohmann::json::parse(line, nullptr, /*allow_exceptions=*/false);
    auto diagnostic = [&](const std::string& message) {
      notation::Diagnostic d;
      d.line = line_number;
      d.message = message;
      sign.parse.diagnostics.push_back(d);
      out.push_back(sign);
    };
    if (!j.is_object()) {
      diagnostic("expected a JSON object on this line, found " + std::string(j.is_discarded() ? "invalid JSON" : j.type_name()));
      continue;
    }
    const auto string_field = [&](const char* key) -> std::string {
      const auto it = j.find(key);
      return it != j.end() && it->is_string() ? it->get<std::string>() : std::string();
    };
    const std::string gloss = string_field("gloss");
    std::string field = options.jsonl_field;
    if (field.empty()) {
      for (const char* k : {"hamnosys", "names", "notation"}) {
        if (!string_field(k).empty()) {
          field = k;
          break;
        }
      }
    }
    const std::string value = field.empty() ? std::string() : string_field(field.c_str());
    if (value.empty()) {
      sign.parse.gloss = gloss;
      diagnostic("expected a non-empty " + (field.empty() ? std::string("hamnosys, names or notation") : field) + " field, found none");
      continue;
    }
    NotationFormat format = notation::detect_format(value);
    if (field == "hamnosys" || field == "names") format = NotationFormat::HamNoSys;
    if (const std::string f = string_field("format"); !f.empty()) notation::format_from_name(f, &format);
    // One sign per line: newlines inside the field would split it.
    std::string one_line = value;
    for (char& c : one_line) {
      if (c == '\n' || c == '\r') c = ' ';
    }
    std::vector<notation::SignParse> parsed = notation::parse_signs(one_line, format);
    sign.format = format;
    if (parsed.empty()) {
      sign.parse.gloss = gloss;
      diagnostic("expected a sign in the " + field + " field, found none");
      continue;
    }
    sign.parse = std::move(parsed[0]);
    if (sign.parse.gloss.empty()) sign.parse.gloss = gloss;
    if (sign.parse.spec && sign.parse.spec->gloss.empty()) sign.parse.spec->gloss = gloss;
    for (notation::Diagnostic& d : sign.parse.diagnostics) d.line = line_number;  // column: within the field
    out.push_back(std::move(sign));
  }
  return out;
}

}  // namespace

bool read_text(const std::string& path, std::string* text, std::string* error) {
  std::stringstream buffer;
  if (path == "-") {
    buffer << std::cin.rdbuf();
  } else {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
      *error = "cannot open '" + path + "'";
      return false;
    }
    buffer << in.rdbuf();
  }
  *text = buffer.str();
  return true;
}

std::vector<InputSign> parse_input(const std::string& path, const std::string& text, const InputOptions& options) {
  if (ends_with(path, ".jsonl")) return parse_jsonl(text, options);
  const NotationFormat format = notation::detect_format(text);
  std::vector<InputSign> out;
  for (notation::SignParse& p : notation::parse_signs(text, format)) {
    InputSign s;
    s.format = format;
    s.line = p.line;
    s.parse = std::move(p);
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace sw::cli
