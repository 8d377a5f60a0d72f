// Stored sign -> another notation (see sign_export.h).
#include "store/sign_export.h"

#include <cctype>

#include <nlohmann/json.hpp>

#include "notation/parse.h"
#include "notation/sign_spec_json.h"
#include "store/api_error.h"

namespace sw::store {
namespace {

// A file name from the gloss: letters, digits and - _ kept (any script), others become '_'.
std::string file_stem(const std::string& gloss) {
  std::string stem;
  for (unsigned char c : gloss) {
    bool keep = c >= 0x80 || std::isalnum(c) || c == '-' || c == '_';
    stem.push_back(keep ? static_cast<char>(c) : '_');
  }
  return stem.empty() ? "sign" : stem;
}

}  // namespace

const std::vector<std::string>& export_formats() {
  static const std::vector<std::string> formats{"sigml", "hsigml", "gsigml", "hamnosys", "formula"};
  return formats;
}

SignExport export_sign(const SignRecord& sign, const std::string& format) {
  notation::NotationFormat target = notation::NotationFormat::HSiGML;
  if (format != "sigml" && !notation::format_from_name(format, &target)) {
    throw ApiError(
        400, "format must be one of sigml, hsigml, gsigml, hamnosys, formula, not '" + format + "'",
        nlohmann::json{{"parameter", "format"}, {"allowed", export_formats()}});
  }
  notation::NotationFormat stored = notation::NotationFormat::Formula;
  if (!notation::format_from_name(sign.format, &stored))
    stored = notation::detect_format(sign.notation);
  std::vector<notation::SignParse> parsed = notation::parse_signs(sign.notation, stored);
  if (parsed.size() != 1 || !parsed[0].ok()) {
    nlohmann::json diagnostics = parsed.empty()
                                     ? nlohmann::json::array()
                                     : notation::diagnostics_to_json(parsed[0].diagnostics);
    throw ApiError(
        422,
        "the stored notation of sign " + std::to_string(sign.id) + " does not parse as one sign",
        nlohmann::json{{"id", sign.id}, {"diagnostics", diagnostics}});
  }
  notation::SignSpec spec = *parsed[0].spec;
  spec.gloss = sign.gloss;  // the database's gloss, whatever the notation text called it
  SignExport out;
  out.body = notation::print_notation({spec}, target);
  const bool xml =
      target == notation::NotationFormat::HSiGML || target == notation::NotationFormat::GSiGML;
  out.content_type = xml ? "application/xml; charset=utf-8" : "text/plain; charset=utf-8";
  out.file_name = file_stem(sign.gloss) + (xml ? ".sigml" : "." + format + ".txt");
  return out;
}

}  // namespace sw::store
