// `signweave import FILE… [--db PATH] [--strict] [--dry-run]`: loads sign files
// (languages.json, <code>/*.jsonl, or a whole data/ directory) into the gesture database through
// the same validation as the server's API (store/data_import.h), and prints the counts and every
// rejected sign with its file, line and reason.
//
// Default: valid signs are written and rejected ones reported (exit 1 if any was rejected).
// --strict: one rejected sign and nothing is written. --dry-run: check only, write nothing.
#include "command.h"

#ifdef SIGNWEAVE_HAS_STORE

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "store/api_error.h"
#include "store/data_import.h"
#include "store/sqlite_db.h"
#include "store/store.h"

namespace sw::cli {
namespace {

int import_command(const std::vector<std::string>& args) {
  std::string db_path = "data/signweave.db";
  std::vector<std::string> files;
  sw::store::ImportMode mode = sw::store::ImportMode::SkipInvalid;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--db" && i + 1 < args.size()) {
      db_path = args[++i];
    } else if (args[i] == "--strict") {
      mode = sw::store::ImportMode::AllOrNothing;
    } else if (args[i] == "--dry-run") {
      mode = sw::store::ImportMode::CheckOnly;
    } else if (args[i].rfind("--", 0) == 0) {
      std::fprintf(stderr, "import: unknown option %s\n", args[i].c_str());
      return 2;
    } else {
      files.push_back(args[i]);
    }
  }
  if (files.empty()) {
    std::fprintf(stderr, "usage: signweave import FILE|DIR... [--db PATH] [--strict] [--dry-run]\n");
    return 2;
  }
  try {
    std::unique_ptr<sw::store::Store> store = sw::store::Store::open(db_path);
    sw::store::FileImportReport report = sw::store::import_paths(*store, files, "import:cli", mode);
    for (const sw::store::ImportRejection& rejection : report.signs.rejected) {
      std::printf("rejected %s:%d: %s\n", rejection.source.c_str(), rejection.line, rejection.message.c_str());
    }
    const char* outcome = mode == sw::store::ImportMode::CheckOnly ? "checked (dry run, nothing written)"
                          : report.signs.committed                 ? "imported"
                                                                   : "not imported (--strict: nothing written)";
    nlohmann::json summary{{"db", db_path},
                           {"files", report.files},
                           {"languages", report.languages},
                           {"created", report.signs.created},
                           {"updated", report.signs.updated},
                           {"unchanged", report.signs.unchanged},
                           {"rejected", report.signs.rejected.size()},
                           {"outcome", outcome}};
    std::printf("%s\n", summary.dump().c_str());
    return report.signs.rejected.empty() ? 0 : 1;
  } catch (const sw::store::ApiError& error) {
    std::fprintf(stderr, "import: %s\n", error.what());
    return 1;
  } catch (const sw::store::DatabaseError& error) {
    std::fprintf(stderr, "import: %s\n", error.what());
    return 1;
  }
}

}  // namespace

SW_CLI_COMMAND("import", "import FILE|DIR... [--db PATH] [--strict] [--dry-run]", import_command);

}  // namespace sw::cli

#endif  // SIGNWEAVE_HAS_STORE
