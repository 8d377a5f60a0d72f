// File and directory import (see data_import.h).
#include "store/data_import.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "store/api_error.h"
#include "store/sign_json.h"

namespace sw::store {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// Why 64 MiB: the largest sign file we expect (a full lexicon with SiGML) is a few MiB; a file
// far beyond that is a mistake (a database dump, a video) and should not be read into memory.
constexpr std::uintmax_t kMaxImportFileBytes = 64ull * 1024 * 1024;

bool read_file(const fs::path& path, std::string* out, std::string* error) {
  std::error_code code;
  std::uintmax_t size = fs::file_size(path, code);
  if (code) {
    *error = "cannot read: " + code.message();
    return false;
  }
  if (size > kMaxImportFileBytes) {
    *error = "file is larger than 64 MiB";
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    *error = "cannot open for reading";
    return false;
  }
  std::ostringstream buffer;
  buffer << in.rdbuf();
  *out = buffer.str();
  return true;
}

}  // namespace

void read_json_lines(std::string_view text, const std::string& source,
                     const std::string& default_language, std::vector<ImportItem>* items,
                     std::vector<ImportRejection>* rejected) {
  int line_number = 0;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(start, end - start);
    ++line_number;
    start = end + 1;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    std::size_t first = line.find_first_not_of(" \t");
    if (first == std::string_view::npos) {
      if (end == text.size()) break;
      continue;
    }
    std::string_view content = line.substr(first);
    if (content[0] == '#' || content.substr(0, 2) == "//") continue;
    try {
      json parsed = parse_json_document(line);
      items->push_back(ImportItem{source, line_number, std::move(parsed), default_language});
    } catch (const ApiError& error) {
      rejected->push_back(ImportRejection{source, line_number, error.status(), error.what(), error.detail()});
    }
    if (end == text.size()) break;
  }
}

FileImportReport import_paths(Store& store, const std::vector<std::string>& paths,
                              const std::string& author, ImportMode mode) {
  FileImportReport report;
  std::vector<fs::path> language_files;
  std::vector<fs::path> sign_files;
  for (const std::string& given : paths) {
    fs::path path(given);
    std::error_code code;
    if (fs::is_directory(path, code)) {
      if (fs::exists(path / "languages.json")) language_files.push_back(path / "languages.json");
      std::vector<fs::path> found;
      for (auto it = fs::recursive_directory_iterator(path, code);
           !code && it != fs::recursive_directory_iterator(); it.increment(code)) {
        if (it->is_regular_file() && it->path().extension() == ".jsonl") found.push_back(it->path());
      }
      std::sort(found.begin(), found.end());
      sign_files.insert(sign_files.end(), found.begin(), found.end());
    } else if (path.filename() == "languages.json" || path.extension() == ".json") {
      language_files.push_back(path);
    } else {
      sign_files.push_back(path);
    }
  }

  // Languages first: signs reference them.
  for (const fs::path& file : language_files) {
    ++report.files;
    std::string text, error;
    if (!read_file(file, &text, &error)) {
      report.signs.rejected.push_back(ImportRejection{file.string(), 0, 400, error, json::object()});
      continue;
    }
    try {
      json document = parse_json_document(text);
      if (!document.is_array()) {
        throw ApiError(400, "languages file must hold a JSON array of language objects");
      }
      std::vector<Language> languages;
      for (const json& entry : document) languages.push_back(parse_language(entry));
      store.upsert_languages(languages);
      report.languages += static_cast<int>(languages.size());
    } catch (const ApiError& error) {
      report.signs.rejected.push_back(
          ImportRejection{file.string(), 0, error.status(), error.what(), error.detail()});
    }
  }

  std::vector<ImportItem> items;
  std::vector<ImportRejection> unreadable;
  for (const fs::path& file : sign_files) {
    ++report.files;
    std::string text, error;
    if (!read_file(file, &text, &error)) {
      unreadable.push_back(ImportRejection{file.string(), 0, 400, error, json::object()});
      continue;
    }
    // data/<code>/lexicon.jsonl: the folder names the sign language.
    std::string language = file.parent_path().filename().string();
    read_json_lines(text, file.string(), language, &items, &unreadable);
  }
  // With all-or-nothing, a file that cannot be read stops the import; the signs are still
  // checked so that one run reports every problem.
  bool blocked = mode == ImportMode::AllOrNothing && (!unreadable.empty() || !report.signs.rejected.empty());
  ImportReport signs = store.import_items(items, author, blocked ? ImportMode::CheckOnly : mode);
  signs.rejected.insert(signs.rejected.end(), unreadable.begin(), unreadable.end());
  signs.rejected.insert(signs.rejected.end(), report.signs.rejected.begin(), report.signs.rejected.end());
  std::sort(signs.rejected.begin(), signs.rejected.end(),
            [](const ImportRejection& a, const ImportRejection& b) {
              return std::tie(a.source, a.line) < std::tie(b.source, b.line);
            });
  report.signs = std::move(signs);
  return report;
}

}  // namespace sw::store
