// signweave-server: the gesture database over HTTP, and the page beside it.
//
//   signweave-server [--port 8080] [--host 127.0.0.1] [--db PATH] [--web DIR] [--data DIR]
//                    [--models DIR] [--threads N] [--token-file PATH]
//   signweave-server --db PATH --create-token NAME     print a new API token once, then exit
//
// First start (the database file does not exist yet): the schema is created and filled from
// --data (languages.json, <code>/*.jsonl), every sign validated like any write; rejected signs
// are listed on stderr. An admin token is created when none exists yet, from SIGNWEAVE_ADMIN_TOKEN
// (the token you chose) or into --token-file (a new one, mode 0600).
//
// SIGTERM/SIGINT: stop accepting, let in-flight requests finish, checkpoint the WAL, exit 0.
// Durability: synchronous=FULL (sqlite_db.h): an answered write is on disk, kill -9 or not.
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "http/http_server.h"
#include "store/api_error.h"
#include "store/data_import.h"
#include "store/sign_validation.h"
#include "store/store.h"

namespace {

struct Flags {
  sw::http::ServerConfig server;
  std::string db = "signweave.db";
  std::string data_dir = "data";
  bool models_given = false;
  std::string token_file;
  std::string create_token;
};

int usage(const char* problem) {
  if (problem) std::fprintf(stderr, "signweave-server: %s\n", problem);
  std::fprintf(stderr,
               "usage: signweave-server [--port N] [--host ADDR] [--db PATH] [--web DIR] [--data DIR]\n"
               "                        [--models DIR] [--threads N] [--token-file PATH]\n"
               "       signweave-server --db PATH --create-token NAME\n");
  return 2;
}

bool parse_int(const std::string& text, int low, int high, int* out) {
  char* end = nullptr;
  long value = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || value < low || value > high) return false;
  *out = static_cast<int>(value);
  return true;
}

bool file_exists(const std::string& path) {
  struct stat info {};
  return ::stat(path.c_str(), &info) == 0;
}

std::string parent_of(const std::string& path) {
  std::string trimmed = path;
  while (trimmed.size() > 1 && trimmed.back() == '/') trimmed.pop_back();
  std::size_t slash = trimmed.find_last_of('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : trimmed.substr(0, slash);
}

void fill_from_data(sw::store::Store& store, const std::string& data_dir) {
  if (!file_exists(data_dir)) {
    std::fprintf(stderr, "signweave-server: no data directory %s: starting with an empty database\n",
                 data_dir.c_str());
    return;
  }
  sw::store::FileImportReport report =
      sw::store::import_paths(store, {data_dir}, "import:first-start", sw::store::ImportMode::SkipInvalid);
  std::fprintf(stderr,
               "signweave-server: filled the new database from %s: %d languages, %d signs created, "
               "%zu rejected\n",
               data_dir.c_str(), report.languages, report.signs.created, report.signs.rejected.size());
  for (const sw::store::ImportRejection& rejection : report.signs.rejected) {
    std::fprintf(stderr, "  rejected %s:%d: %s\n", rejection.source.c_str(), rejection.line,
                 rejection.message.c_str());
  }
}

void ensure_admin_token(sw::store::Store& store, const Flags& flags) {
  const char* chosen = std::getenv("SIGNWEAVE_ADMIN_TOKEN");
  if (chosen && *chosen) {
    if (!store.has_token_value(chosen)) {
      std::string name = "admin (SIGNWEAVE_ADMIN_TOKEN)";
      for (int n = 2; ; ++n) {
        try {
          store.create_token(name, chosen);
          break;
        } catch (const sw::store::ApiError& error) {
          if (error.status() != 409) throw;
          name = "admin (SIGNWEAVE_ADMIN_TOKEN) " + std::to_string(n);
        }
      }
      std::fprintf(stderr, "signweave-server: registered the token from SIGNWEAVE_ADMIN_TOKEN\n");
    }
    return;
  }
  if (store.count_tokens() > 0) return;
  if (!flags.token_file.empty()) {
    std::string token = store.create_token("admin");
    int fd = ::open(flags.token_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    if (fd < 0 || ::write(fd, token.data(), token.size()) != static_cast<ssize_t>(token.size())) {
      std::fprintf(stderr, "signweave-server: cannot write the admin token to %s\n", flags.token_file.c_str());
    } else {
      std::fprintf(stderr, "signweave-server: admin API token written to %s\n", flags.token_file.c_str());
    }
    if (fd >= 0) ::close(fd);
    return;
  }
  std::fprintf(stderr,
               "signweave-server: no API tokens yet; writes need one. Create one with\n"
               "  signweave-server --db %s --create-token NAME\n"
               "or start with SIGNWEAVE_ADMIN_TOKEN=<secret> or --token-file PATH.\n",
               flags.db.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  Flags flags;
  std::vector<std::string> args(argv + 1, argv + argc);
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& flag = args[i];
    if (flag == "-h" || flag == "--help") {
      usage(nullptr);
      return 0;
    }
    if (i + 1 >= args.size()) return usage(("missing value after " + flag).c_str());
    const std::string& value = args[++i];
    if (flag == "--port") {
      if (!parse_int(value, 0, 65535, &flags.server.port)) return usage("--port takes 0..65535");
    } else if (flag == "--host") {
      flags.server.host = value;
    } else if (flag == "--db") {
      flags.db = value;
    } else if (flag == "--web") {
      flags.server.web_dir = value;
    } else if (flag == "--data") {
      flags.data_dir = value;
    } else if (flag == "--models") {
      flags.server.models_dir = value;
      flags.models_given = true;
    } else if (flag == "--threads") {
      if (!parse_int(value, 2, 4096, &flags.server.threads)) return usage("--threads takes 2..4096");
    } else if (flag == "--token-file") {
      flags.token_file = value;
    } else if (flag == "--create-token") {
      flags.create_token = value;
    } else {
      return usage(("unknown flag " + flag).c_str());
    }
  }
  // The avatar lives next to the page in the repository: <repo>/web and <repo>/models.
  if (!flags.models_given) flags.server.models_dir = parent_of(flags.server.web_dir) + "/models";

  // Block the stop signals in every thread (the workers inherit the mask); one thread waits for
  // them with sigwait, so shutdown runs as ordinary code, not inside a signal handler.
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGTERM);
  sigaddset(&stop_signals, SIGINT);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);
  signal(SIGPIPE, SIG_IGN);  // a client that hangs up mid-answer must not kill the server

  // Every sign written is synthesised on the avatar the page plays (second stage of the check).
  {
    std::string avatar_error;
    if (!sw::store::load_validation_avatar(flags.server.models_dir + "/signweave-avatar.glb",
                                           &avatar_error)) {
      std::fprintf(stderr, "signweave-server: cannot load the avatar that validates signs: %s\n",
                   avatar_error.c_str());
      return 1;
    }
  }

  std::unique_ptr<sw::store::Store> store;
  bool fresh = !file_exists(flags.db);
  try {
    store = sw::store::Store::open(flags.db);
    if (!flags.create_token.empty()) {
      std::string token = store->create_token(flags.create_token);
      std::printf("%s\n", token.c_str());
      std::fprintf(stderr, "signweave-server: token '%s' created; it is shown only this once\n",
                   flags.create_token.c_str());
      return 0;
    }
    if (fresh) fill_from_data(*store, flags.data_dir);
    ensure_admin_token(*store, flags);
    store->prepare_search();
  } catch (const sw::store::ApiError& error) {
    std::fprintf(stderr, "signweave-server: %s\n", error.what());
    return 1;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "signweave-server: %s\n", error.what());
    return 1;
  }

  sw::http::HttpServer server(*store, flags.server);
  std::string error;
  int port = server.bind(&error);
  if (port < 0) {
    std::fprintf(stderr, "signweave-server: %s\n", error.c_str());
    return 1;
  }
  std::printf("signweave-server: listening on http://%s:%d (db %s, web %s)\n", flags.server.host.c_str(),
              port, flags.db.c_str(), flags.server.web_dir.c_str());
  std::fflush(stdout);

  std::thread signal_waiter([&server, stop_signals] {
    int received = 0;
    sigwait(&stop_signals, &received);
    std::fprintf(stderr, "signweave-server: %s received, finishing requests in progress\n",
                 received == SIGTERM ? "SIGTERM" : "SIGINT");
    server.stop();
  });
  signal_waiter.detach();

  bool served = server.run();
  try {
    store->checkpoint();
  } catch (const std::exception& failure) {
    std::fprintf(stderr, "signweave-server: WAL checkpoint failed: %s\n", failure.what());
  }
  std::fprintf(stderr, "signweave-server: stopped\n");
  return served ? 0 : 1;
}
