// The one entry point for every notation (see parse.h): format detection, names, and dispatch to
// the format's reader.
#include "notation/parse.h"

#include "notation/formula.h"
#include "notation/hamnosys.h"
#include "notation/sigml.h"
#include "notation/text_position.h"

namespace sw::notation {
namespace {

std::string_view skip_space(std::string_view text) {
  std::size_t i = 0;
  // A UTF-8 byte order mark is not content.
  if (text.size() >= 3 && text.substr(0, 3) == "\xEF\xBB\xBF") i = 3;
  while (i < text.size() && (text[i] == ' ' || text[i] == '\t' || text[i] == '\r' || text[i] == '\n')) ++i;
  return text.substr(i);
}

bool has_hamnosys_code_point(std::string_view text) {
  std::size_t i = 0;
  while (i < text.size()) {
    const char32_t c = decode_utf8(text, &i);
    if (c >= 0xE000 && c <= 0xE0FF) return true;
  }
  return false;
}

// "hamflathand,hamextfingeru": symbol names (a word starting with "ham" outside any quotes).
bool has_hamnosys_names(std::string_view text) {
  for (std::size_t i = text.find("ham"); i != std::string_view::npos; i = text.find("ham", i + 3)) {
    const bool word_start = i == 0 || !((text[i - 1] >= 'a' && text[i - 1] <= 'z') ||
                                        (text[i - 1] >= 'A' && text[i - 1] <= 'Z') || text[i - 1] == '_');
    if (word_start && i + 3 < text.size() && text[i + 3] >= 'a' && text[i + 3] <= 'z') return true;
  }
  return false;
}

}  // namespace

NotationFormat detect_format(std::string_view text) {
  const std::string_view body = skip_space(text);
  if (!body.empty() && body[0] == '<') {
    return body.find("hamgestural_sign") != std::string_view::npos ? NotationFormat::GSiGML
                                                                    : NotationFormat::HSiGML;
  }
  if (has_hamnosys_code_point(body)) return NotationFormat::HamNoSys;
  if (body.find("R(") == std::string_view::npos && has_hamnosys_names(body)) {
    return NotationFormat::HamNoSys;
  }
  return NotationFormat::Formula;
}

const char* format_name(NotationFormat format) {
  switch (format) {
    case NotationFormat::Formula: return "formula";
    case NotationFormat::HamNoSys: return "hamnosys";
    case NotationFormat::HSiGML: return "hsigml";
    case NotationFormat::GSiGML: return "gsigml";
  }
  return "formula";
}

bool format_from_name(std::string_view name, NotationFormat* out) {
  for (NotationFormat f : {NotationFormat::Formula, NotationFormat::HamNoSys, NotationFormat::HSiGML,
                           NotationFormat::GSiGML}) {
    if (name == format_name(f)) {
      *out = f;
      return true;
    }
  }
  return false;
}

std::vector<SignParse> parse_signs(std::string_view text, NotationFormat format) {
  switch (format) {
    case NotationFormat::Formula:
      return parse_formula_text(text);
    case NotationFormat::HamNoSys:
      return parse_hamnosys_text(text);
    case NotationFormat::HSiGML:
    case NotationFormat::GSiGML:
      // One reader for both: a SiGML document may mix hns_sign and hamgestural_sign.
      return parse_sigml_text(text);
  }
  return {};
}

std::string print_notation(const std::vector<SignSpec>& signs, NotationFormat format) {
  switch (format) {
    case NotationFormat::HSiGML: return print_hsigml(signs);
    case NotationFormat::GSiGML: return print_gsigml(signs);
    case NotationFormat::Formula:
    case NotationFormat::HamNoSys: break;
  }
  std::string out;
  for (const SignSpec& s : signs) {
    if (format == NotationFormat::Formula) {
      out += print_formula_line(s);
    } else {
      std::string gloss;
      for (char c : s.gloss) gloss += (c == '=' || c == '#' || c == '\n' || c == '\r') ? '_' : c;
      out += (gloss.empty() ? "" : gloss + " = ") + print_hamnosys(s, HamNoSysSpelling::Unicode);
    }
    out += '\n';
  }
  return out;
}

ParseOutcome parse_notation(std::string_view text, NotationFormat format) {
  ParseOutcome outcome;
  for (SignParse& sign : parse_signs(text, format)) {
    if (sign.ok()) outcome.signs.push_back(std::move(*sign.spec));
    outcome.diagnostics.insert(outcome.diagnostics.end(), sign.diagnostics.begin(),
                               sign.diagnostics.end());
  }
  if (outcome.signs.empty() && outcome.diagnostics.empty()) {
    const LineIndex index(text);
    outcome.diagnostics.push_back(index.make(0, 0, "", "expected at least one sign, found none"));
  }
  return outcome;
}

}  // namespace sw::notation
