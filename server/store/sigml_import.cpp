// SiGML collection import (see sigml_import.h).
#include "store/sigml_import.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "notation/diagnostic.h"
#include "notation/parse.h"

namespace sw::store {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

bool has_sigml_extension(const fs::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return extension == ".sigml";
}

std::vector<fs::path> sigml_files(const std::string& path) {
  std::vector<fs::path> files;
  std::error_code error;
  if (fs::is_directory(path, error)) {
    for (const fs::directory_entry& entry : fs::directory_iterator(path, error)) {
      if (entry.is_regular_file(error) && has_sigml_extension(entry.path()))
        files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
  } else if (has_sigml_extension(path)) {
    files.push_back(path);
  }
  return files;
}

// The sign element that starts at `offset`, as its own document (its lines as written).
std::string sign_document(const std::string& text, std::size_t offset) {
  std::size_t name_end = text.find_first_of(" \t\r\n/>", offset + 1);
  std::string name = text.substr(offset + 1, name_end - offset - 1);
  std::string closing = "</" + name + ">";
  std::size_t end = text.find(closing, offset);
  end = end == std::string::npos ? text.size() : end + closing.size();
  std::size_t start = offset;  // from the start of its line when only indentation precedes it
  while (start > 0 && (text[start - 1] == ' ' || text[start - 1] == '\t')) --start;
  if (start > 0 && text[start - 1] != '\n') start = offset;
  return "<sigml>\n" + text.substr(start, end - start) + "\n</sigml>\n";
}

ImportRejection rejection(const std::string& source, int line, const std::string& message,
                          json detail = json::object()) {
  return ImportRejection{source, line, 422, message, std::move(detail)};
}

}  // namespace

bool is_sigml_collection(const std::string& path) {
  std::error_code error;
  if (fs::is_directory(path, error) && fs::exists(fs::path(path) / "languages.json", error))
    return false;
  return !sigml_files(path).empty();
}

int read_sigml_file(const std::string& path, const std::string& text, const std::string& language,
                    std::vector<ImportItem>* items, std::vector<ImportRejection>* rejected) {
  notation::NotationFormat format = notation::detect_format(text);
  bool has_signs = text.find("<hns_sign") != std::string::npos ||
                   text.find("<hamgestural_sign") != std::string::npos;
  if (!has_signs ||
      (format != notation::NotationFormat::HSiGML && format != notation::NotationFormat::GSiGML)) {
    rejected->push_back(
        rejection(path, 0, "not a SiGML sign file (no hns_sign or hamgestural_sign element)"));
    return 0;
  }
  const std::string stem = fs::path(path).stem().string();
  int unnamed = 0;
  int signs = 0;
  for (const notation::SignParse& sign : notation::parse_signs(text, format)) {
    // A document-level problem (broken XML) belongs to no sign: the file is rejected, line given.
    bool document_level = !sign.spec && sign.gloss.empty() &&
                          text.compare(sign.offset, 9, "<hns_sign") != 0 &&
                          text.compare(sign.offset, 17, "<hamgestural_sign") != 0;
    signs += document_level ? 0 : 1;
    if (!sign.ok()) {
      const notation::Diagnostic* first = nullptr;
      for (const notation::Diagnostic& d : sign.diagnostics) {
        if (d.severity == notation::Severity::Error) {
          first = &d;
          break;
        }
      }
      std::string message = first ? notation::format_diagnostic(*first) : "no sign could be read";
      rejected->push_back(rejection(path, sign.line,
                                    (document_level       ? std::string("the document")
                                     : sign.gloss.empty() ? std::string("a sign")
                                                          : "'" + sign.gloss + "'") +
                                        " does not parse: " + message,
                                    json{{"gloss", sign.gloss}}));
      continue;
    }
    std::string gloss = sign.gloss;
    if (gloss.empty()) gloss = ++unnamed == 1 ? stem : stem + "#" + std::to_string(unnamed);
    ImportItem item;
    item.source = path;
    item.line = sign.line;
    item.default_language = language;
    item.sign = json{{"gloss", gloss},
                     {"notation", sign_document(text, sign.offset)},
                     {"format", notation::format_name(format)}};
    items->push_back(std::move(item));
  }
  return signs;
}

std::vector<SigmlFileReport> import_sigml_collection(Store& store, const std::string& path,
                                                     const std::string& language,
                                                     const std::string& author, ImportMode mode) {
  std::vector<SigmlFileReport> reports;
  for (const fs::path& file : sigml_files(path)) {
    SigmlFileReport report;
    report.file = file.string();
    std::ifstream in(file, std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    std::vector<ImportItem> items;
    std::vector<ImportRejection> unread;
    if (!in) {
      unread.push_back(rejection(report.file, 0, "cannot read the file"));
    } else {
      report.signs = read_sigml_file(report.file, buffer.str(), language, &items, &unread);
    }
    if (!items.empty()) report.import = store.import_items(items, author, mode);
    report.import.rejected.insert(report.import.rejected.end(), unread.begin(), unread.end());
    std::sort(report.import.rejected.begin(), report.import.rejected.end(),
              [](const ImportRejection& a, const ImportRejection& b) { return a.line < b.line; });
    reports.push_back(std::move(report));
  }
  return reports;
}

}  // namespace sw::store
