// `signweave import FILE… [--db PATH] [--strict] [--dry-run]`: loads sign files
// (languages.json, <code>/*.jsonl, or a whole data/ directory) into the gesture database through
// the same validation as the server's API (store/data_import.h), and prints the counts and every
// rejected sign with its file, line and reason.
//
// A SiGML collection (a folder of .sigml files, or one such file; store/sigml_import.h) needs
// `--lang CODE` and is reported per file: one JSON line each with the signs found, created,
// updated, unchanged and every rejected sign with its line and reason.
//
// Default: valid signs are written and rejected ones reported (exit 1 if any was rejected).
// --strict: one rejected sign and nothing is written. --dry-run: check only, write nothing.
#include "command.h"
#include "project_root.h"
#include "store/sign_validation.h"

#ifdef SIGNWEAVE_HAS_STORE

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "store/api_error.h"
#include "store/data_import.h"
#include "store/sigml_import.h"
#include "store/sqlite_db.h"
#include "store/store.h"

namespace sw::cli {
namespace {

nlohmann::json rejection_json(const sw::store::ImportRejection& rejection) {
  nlohmann::json out{{"line", rejection.line}, {"reason", rejection.message}};
  if (rejection.detail.is_object() && rejection.detail.contains("gloss"))
    out["gloss"] = rejection.detail["gloss"];
  return out;
}

int import_sigml(sw::store::Store& store, const std::vector<std::string>& collections,
                 const std::string& language, sw::store::ImportMode mode) {
  if (language.empty()) {
    std::fprintf(
        stderr,
        "import: a SiGML collection needs --lang CODE (the sign language its signs are in)\n");
    return 2;
  }
  if (!store.language(language)) {
    std::fprintf(stderr, "import: no sign language '%s' in the database\n", language.c_str());
    return 2;
  }
  nlohmann::json total{{"files", 0},   {"signs", 0},     {"created", 0},
                       {"updated", 0}, {"unchanged", 0}, {"rejected", 0}};
  for (const std::string& collection : collections) {
    for (const sw::store::SigmlFileReport& file :
         sw::store::import_sigml_collection(store, collection, language, "import:cli", mode)) {
      nlohmann::json rejected = nlohmann::json::array();
      for (const sw::store::ImportRejection& r : file.import.rejected)
        rejected.push_back(rejection_json(r));
      nlohmann::json line{{"file", file.file},
                          {"signs", file.signs},
                          {"created", file.import.created},
                          {"updated", file.import.updated},
                          {"unchanged", file.import.unchanged},
                          {"rejected", rejected}};
      std::printf("%s\n", line.dump().c_str());
      total["files"] = total["files"].get<int>() + 1;
      for (const char* key : {"signs", "created", "updated", "unchanged"})
        total[key] = total[key].get<int>() + line[key].get<int>();
      total["rejected"] = total["rejected"].get<int>() + static_cast<int>(rejected.size());
    }
  }
  total["outcome"] =
      mode == sw::store::ImportMode::CheckOnly ? "checked (dry run, nothing written)" : "imported";
  std::printf("%s\n", nlohmann::json({{"summary", total}}).dump().c_str());
  return total["rejected"].get<int>() == 0 && total["files"].get<int>() > 0 ? 0 : 1;
}

int import_command(const std::vector<std::string>& args) {
  std::string db_path = "data/signweave.db";
  std::vector<std::string> files;
  std::string language;
  sw::store::ImportMode mode = sw::store::ImportMode::SkipInvalid;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--db" && i + 1 < args.size()) {
      db_path = args[++i];
    } else if (args[i] == "--lang" && i + 1 < args.size()) {
      language = args[++i];
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
    std::fprintf(
        stderr,
        "usage: signweave import FILE|DIR... [--db PATH] [--lang CODE] [--strict] [--dry-run]\n");
    return 2;
  }
  {
    // The same two-stage check as the server: parse, then synthesise on the project's avatar.
    std::string avatar_error;
    if (!sw::store::load_validation_avatar(sw::cli::project_root() + "/models/signweave-avatar.glb",
                                           &avatar_error)) {
      std::fprintf(stderr, "import: cannot load the avatar that validates signs: %s\n",
                   avatar_error.c_str());
      return 1;
    }
  }
  try {
    std::unique_ptr<sw::store::Store> store = sw::store::Store::open(db_path);
    std::vector<std::string> collections;
    for (const std::string& file : files) {
      if (sw::store::is_sigml_collection(file)) collections.push_back(file);
    }
    if (!collections.empty()) {
      if (collections.size() != files.size()) {
        std::fprintf(stderr, "import: import SiGML collections and data files in separate runs\n");
        return 2;
      }
      return import_sigml(*store, collections, language, mode);
    }
    sw::store::FileImportReport report = sw::store::import_paths(*store, files, "import:cli", mode);
    for (const sw::store::ImportRejection& rejection : report.signs.rejected) {
      std::printf("rejected %s:%d: %s\n", rejection.source.c_str(), rejection.line,
                  rejection.message.c_str());
    }
    const char* outcome = mode == sw::store::ImportMode::CheckOnly
                              ? "checked (dry run, nothing written)"
                          : report.signs.committed ? "imported"
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

SW_CLI_COMMAND("import",
               "import FILE|DIR... [--db PATH] [--lang CODE] [--strict] [--dry-run]   (DIR of "
               ".sigml files: --lang)",
               import_command);

}  // namespace sw::cli

#endif  // SIGNWEAVE_HAS_STORE
