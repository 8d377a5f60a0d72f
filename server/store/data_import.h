// Importing sign files into the store: the shared path behind the server's first start (filling a
// new database from data/), `signweave import FILE…` and nothing else — `POST /api/import` reads
// its body with the same line reader.
//
// Files understood:
//   languages.json            a JSON array of {code, name, spoken, alphabet_script}
//   <dir>/<code>/*.jsonl      one sign object a line; the language is the parent folder's name
//                             unless a line says "language"; alphabet.jsonl / digits.jsonl lines
//                             carry "letter"
//   a directory               languages.json first, then every <code>/*.jsonl below it
// Blank lines and lines starting with '#' or '//' are skipped.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "store/store.h"

namespace sw::store {

struct FileImportReport {
  int languages = 0;
  int files = 0;
  ImportReport signs;  // counts and rejections over every file (each rejection names its file)
};

// Reads JSON lines into import items; a line that is not JSON becomes a rejection instead.
void read_json_lines(std::string_view text, const std::string& source,
                     const std::string& default_language, std::vector<ImportItem>* items,
                     std::vector<ImportRejection>* rejected);

// Imports files and directories. Signs are written in one transaction per call; `mode` decides
// whether one bad sign stops everything (AllOrNothing) or is reported and skipped.
// Unreadable files are rejections with line 0.
FileImportReport import_paths(Store& store, const std::vector<std::string>& paths,
                              const std::string& author, ImportMode mode);

}  // namespace sw::store
