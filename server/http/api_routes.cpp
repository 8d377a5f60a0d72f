// Request routing and the API handlers (see api_routes.h).
#include "http/api_routes.h"

#include <cctype>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <initializer_list>

#include "http/json_reply.h"
#include "store/api_error.h"
#include "store/data_import.h"
#include "store/sign_export.h"
#include "store/sign_json.h"
#include "store/sign_validation.h"
#include "store/utf8_text.h"

namespace sw::http {
namespace {

using nlohmann::json;
using store::ApiError;

std::vector<std::string> split_path(const std::string& path) {
  std::vector<std::string> segments;
  std::size_t start = 1;
  while (start <= path.size()) {
    std::size_t end = path.find('/', start);
    if (end == std::string::npos) end = path.size();
    segments.push_back(path.substr(start, end - start));
    start = end + 1;
  }
  if (!segments.empty() && segments.back().empty()) segments.pop_back();  // trailing slash
  return segments;
}

std::int64_t parse_id(const std::string& text) {
  std::int64_t id = 0;
  auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), id);
  if (error != std::errc() || end != text.data() + text.size() || id <= 0) {
    throw ApiError(400, "sign id must be a positive integer, not '" + text + "'", json{{"id", text}});
  }
  return id;
}

// Query parameters: only the listed ones, each at most once, each valid UTF-8.
void check_params(const httplib::Request& req, std::initializer_list<const char*> allowed) {
  for (const auto& [name, value] : req.params) {
    bool known = false;
    for (const char* a : allowed) known = known || name == a;
    if (!known) {
      throw ApiError(400, "unknown query parameter '" + name + "'",
                     json{{"parameter", name}, {"allowed", std::vector<std::string>(allowed.begin(), allowed.end())}});
    }
    if (req.get_param_value_count(name) > 1) {
      throw ApiError(400, "query parameter '" + name + "' given more than once", json{{"parameter", name}});
    }
    if (!store::is_valid_utf8(value)) {
      throw ApiError(400, "query parameter '" + name + "' is not valid UTF-8", json{{"parameter", name}});
    }
  }
}

std::string param(const httplib::Request& req, const char* name) {
  return req.has_param(name) ? req.get_param_value(name) : std::string();
}

void require_json_content_type(const httplib::Request& req) {
  std::string type = req.get_header_value("Content-Type");
  for (char& c : type) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (type.rfind("application/json", 0) != 0) {
    throw ApiError(415, "send the sign as Content-Type: application/json",
                   json{{"content_type", req.get_header_value("Content-Type")}});
  }
}

// If-Match: "<revision>" (a weak W/ prefix and a bare number are accepted too).
std::int64_t require_if_match(const httplib::Request& req) {
  if (!req.has_header("If-Match")) {
    throw ApiError(428,
                   "If-Match header required: send the revision you edited, e.g. If-Match: \"3\" "
                   "(GET the sign: its ETag is the revision)",
                   json{{"header", "If-Match"}});
  }
  std::string value = req.get_header_value("If-Match");
  std::string_view view(value);
  if (view.rfind("W/", 0) == 0) view.remove_prefix(2);
  if (view.size() >= 2 && view.front() == '"' && view.back() == '"') view = view.substr(1, view.size() - 2);
  std::int64_t revision = 0;
  auto [end, error] = std::from_chars(view.data(), view.data() + view.size(), revision);
  if (view.empty() || error != std::errc() || end != view.data() + view.size() || revision <= 0) {
    throw ApiError(400, "If-Match must be a quoted revision number such as \"3\", not " + value,
                   json{{"header", "If-Match"}, {"value", value}});
  }
  return revision;
}

std::string etag_for(std::int64_t revision) { return "\"" + std::to_string(revision) + "\""; }

json hit_to_json(const store::SearchHit& hit) {
  json out{{"id", hit.sign_id},     {"language", hit.language}, {"gloss", hit.gloss},
           {"notation", hit.notation}, {"format", hit.format},   {"revision", hit.revision},
           {"keywords", hit.keywords}, {"match", {{"type", hit.match_type}}}};
  if (!hit.match_field.empty()) {
    out["match"]["field"] = hit.match_field;
    out["match"]["text"] = hit.match_text;
  }
  if (hit.match_type == "fuzzy") out["match"]["distance"] = hit.distance;
  return out;
}

json token_to_json(const store::LookupToken& token) {
  json out{{"text", token.text}, {"offset", token.offset}};
  switch (token.type) {
    case store::LookupToken::Type::Sign:
      out["type"] = "sign";
      out["sign_id"] = token.sign_id;
      out["gloss"] = token.gloss;
      out["alternatives"] = token.alternatives;
      out["match"] = json{{"type", token.match_type}, {"form", token.match_form}, {"text", token.match_text}};
      break;
    case store::LookupToken::Type::Fingerspell: {
      out["type"] = "fingerspell";
      json letters = json::array();
      for (const store::LookupLetter& letter : token.letters) {
        json entry{{"letter", letter.letter}};
        entry["sign_id"] = letter.sign_id ? json(*letter.sign_id) : json(nullptr);
        if (letter.sign_id) entry["gloss"] = letter.gloss;
        letters.push_back(entry);
      }
      out["letters"] = letters;
      break;
    }
    case store::LookupToken::Type::Pause:
      out["type"] = "pause";
      out["duration_s"] = token.pause_s;
      break;
  }
  return out;
}

json rejection_to_json(const store::ImportRejection& rejection) {
  return json{{"source", rejection.source}, {"line", rejection.line}, {"status", rejection.status},
              {"error", rejection.message}, {"detail", rejection.detail}};
}

}  // namespace

ApiRoutes::ApiRoutes(store::Store& store, Metrics& metrics, const std::string& web_dir,
                     const std::string& models_dir, ApiLimits limits)
    : store_(store), metrics_(metrics), web_(web_dir, "/"), models_(models_dir, "/models/"),
      limits_(limits) {
  // Compressed once here, before the server listens, so no page load pays zlib's best level.
  web_.precompress();
  models_.precompress();
}

void ApiRoutes::handle(const httplib::Request& req, httplib::Response& res) {
  auto start = std::chrono::steady_clock::now();
  std::string label = "unrouted";
  try {
    std::size_t header_bytes = 0;
    for (const auto& [key, value] : req.headers) header_bytes += key.size() + value.size() + 4;
    if (header_bytes > limits_.max_header_bytes) {
      throw ApiError(431, "request headers are larger than " + std::to_string(limits_.max_header_bytes) + " bytes",
                     json{{"limit_bytes", limits_.max_header_bytes}});
    }
    route(req, res, &label);
  } catch (const ApiError& error) {
    reply_error(res, error.status(), error.what(), error.detail());
    if (error.status() == 401) res.set_header("WWW-Authenticate", "Bearer realm=\"signweave\"");
  } catch (const store::DatabaseError& error) {
    int primary = error.code() & 0xFF;
    if (primary == SQLITE_BUSY || primary == SQLITE_LOCKED) {
      res.set_header("Retry-After", "1");
      reply_error(res, 503, "the database is busy; retry shortly");
    } else {
      std::fprintf(stderr, "signweave-server: database error on %s %s: %s\n", req.method.c_str(),
                   req.path.c_str(), error.what());
      reply_error(res, 500, "database error (logged on the server)");
    }
  } catch (const std::exception& error) {
    std::fprintf(stderr, "signweave-server: internal error on %s %s: %s\n", req.method.c_str(),
                 req.path.c_str(), error.what());
    reply_error(res, 500, "internal error (logged on the server)");
  }
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  metrics_.record(label, res.status, seconds);
}

void ApiRoutes::route(const httplib::Request& req, httplib::Response& res, std::string* label) {
  const std::string& method = req.method;
  const bool is_get = method == "GET" || method == "HEAD";
  auto method_not_allowed = [&](const char* allow) {
    res.set_header("Allow", allow);
    throw ApiError(405, "method " + method + " not allowed here (allowed: " + allow + ")",
                   json{{"allow", allow}});
  };

  if (req.path == "/healthz") {
    *label = "/healthz";
    if (!is_get) method_not_allowed("GET, HEAD");
    healthz(req, res);
    return;
  }
  if (req.path == "/metrics") {
    *label = "/metrics";
    if (!is_get) method_not_allowed("GET, HEAD");
    metrics(req, res);
    return;
  }
  if (req.path == "/api" || req.path.rfind("/api/", 0) == 0) {
    std::vector<std::string> segments = split_path(req.path);
    if (segments.size() == 2 && segments[1] == "languages") {
      *label = "/api/languages";
      if (!is_get) method_not_allowed("GET, HEAD");
      get_languages(req, res);
      return;
    }
    if (segments.size() == 2 && segments[1] == "lookup") {
      *label = "/api/lookup";
      if (!is_get) method_not_allowed("GET, HEAD");
      lookup(req, res);
      return;
    }
    if (segments.size() == 2 && segments[1] == "import") {
      *label = "/api/import";
      if (method != "POST") method_not_allowed("POST");
      import_signs(req, res);
      return;
    }
    if (segments.size() == 2 && segments[1] == "signs") {
      *label = "/api/signs";
      if (is_get) {
        search_signs(req, res);
      } else if (method == "POST") {
        create_sign(req, res);
      } else {
        method_not_allowed("GET, HEAD, POST");
      }
      return;
    }
    if (segments.size() == 3 && segments[1] == "signs") {
      *label = "/api/signs/{id}";
      std::int64_t id = parse_id(segments[2]);
      if (is_get) {
        get_sign(req, res, id);
      } else if (method == "PUT") {
        update_sign(req, res, id);
      } else if (method == "DELETE") {
        delete_sign(req, res, id);
      } else {
        method_not_allowed("GET, HEAD, PUT, DELETE");
      }
      return;
    }
    if (segments.size() == 4 && segments[1] == "signs" && segments[3] == "history") {
      *label = "/api/signs/{id}/history";
      std::int64_t id = parse_id(segments[2]);
      if (!is_get) method_not_allowed("GET, HEAD");
      sign_history(req, res, id);
      return;
    }
    *label = "/api/unknown";
    throw ApiError(404, "no API route " + req.path + " (see docs/API.md)", json{{"path", req.path}});
  }
  if (req.path == "/models" || req.path.rfind("/models/", 0) == 0) {
    *label = "/models/*";
    if (!is_get) method_not_allowed("GET, HEAD");
    models_.serve(req, res);
    return;
  }
  *label = "static";
  if (!is_get) method_not_allowed("GET, HEAD");
  web_.serve(req, res);
}

std::string ApiRoutes::authenticate(const httplib::Request& req) {
  if (!req.has_header("Authorization")) {
    throw ApiError(401, "missing Authorization: Bearer <token> header (create a token with "
                        "signweave-server --create-token NAME)",
                   json{{"header", "Authorization"}});
  }
  std::string value = req.get_header_value("Authorization");
  const std::string scheme = "Bearer ";
  if (value.size() <= scheme.size() || strncasecmp(value.c_str(), scheme.c_str(), scheme.size()) != 0) {
    throw ApiError(401, "Authorization must use the Bearer scheme: Authorization: Bearer <token>",
                   json{{"header", "Authorization"}});
  }
  store::TokenCheck check = store_.verify_token(value.substr(scheme.size()));
  if (check.result != store::TokenCheck::Result::Valid) {
    throw ApiError(403, "the bearer token is not valid for this server", json{{"header", "Authorization"}});
  }
  return check.name;
}

void ApiRoutes::get_languages(const httplib::Request& req, httplib::Response& res) {
  check_params(req, {});
  json languages = json::array();
  for (const store::Language& language : store_.languages()) languages.push_back(store::language_to_json(language));
  reply_json(res, 200, json{{"languages", languages}});
}

void ApiRoutes::search_signs(const httplib::Request& req, httplib::Response& res) {
  check_params(req, {"q", "lang", "limit", "cursor"});
  store::SearchQuery query;
  query.text = param(req, "q");
  query.language = param(req, "lang");
  query.cursor = param(req, "cursor");
  if (query.text.size() > store::kMaxQueryBytes) {
    throw ApiError(400, "q is longer than " + std::to_string(store::kMaxQueryBytes) + " bytes",
                   json{{"parameter", "q"}, {"limit_bytes", store::kMaxQueryBytes}});
  }
  if (req.has_param("limit")) {
    std::string text = param(req, "limit");
    int limit = 0;
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), limit);
    if (error != std::errc() || end != text.data() + text.size() || limit < 1 || limit > store::kMaxSearchLimit) {
      throw ApiError(400, "limit must be an integer from 1 to " + std::to_string(store::kMaxSearchLimit),
                     json{{"parameter", "limit"}, {"value", text}});
    }
    query.limit = limit;
  }
  store::SearchPage page = store_.search(query);
  json hits = json::array();
  for (const store::SearchHit& hit : page.hits) hits.push_back(hit_to_json(hit));
  json body{{"hits", hits}, {"total", page.total}};
  body["next_cursor"] = page.next_cursor.empty() ? json(nullptr) : json(page.next_cursor);
  reply_json(res, 200, body);
}

// GET /api/signs/{id}?format=: the sign as a notation file to download (store/sign_export.h).
static void reply_export(const httplib::Request& req, httplib::Response& res, const store::SignRecord& sign) {
  if (sign.deleted) {
    throw ApiError(410, "sign " + std::to_string(sign.id) + " was deleted",
                   json{{"id", sign.id}, {"current_revision", sign.revision}});
  }
  std::string format = param(req, "format");
  store::SignExport exported = store::export_sign(sign, format);
  std::string etag = "\"" + std::to_string(sign.revision) + "-" + format + "\"";
  res.set_header("ETag", etag);
  res.set_header("Cache-Control", "no-cache");
  // RFC 6266: an ASCII name for old clients, the gloss's own (UTF-8, percent-encoded) for the rest.
  std::string encoded;
  for (unsigned char c : exported.file_name) {
    static const char kHex[] = "0123456789ABCDEF";
    if (std::isalnum(c) || c == '.' || c == '-' || c == '_') {
      encoded.push_back(static_cast<char>(c));
    } else {
      encoded += {'%', kHex[c >> 4], kHex[c & 15]};
    }
  }
  std::string ascii_name = "sign-" + std::to_string(sign.id) + exported.file_name.substr(exported.file_name.find('.'));
  res.set_header("Content-Disposition",
                 "attachment; filename=\"" + ascii_name + "\"; filename*=UTF-8''" + encoded);
  if (req.get_header_value("If-None-Match") == etag) {
    res.status = 304;
    return;
  }
  res.status = 200;
  res.set_content(exported.body, exported.content_type);
}

void ApiRoutes::get_sign(const httplib::Request& req, httplib::Response& res, std::int64_t id) {
  check_params(req, {"format"});
  if (req.has_param("format")) {
    std::optional<store::SignRecord> sign = store_.get_sign(id);
    if (!sign) throw ApiError(404, "no sign with id " + std::to_string(id), json{{"id", id}});
    reply_export(req, res, *sign);
    return;
  }
  // Why 20000 entries: several times the largest lexicon we ship; past it the cache starts over
  // rather than growing with every id a client invents.
  constexpr std::size_t kMaxCachedSigns = 20000;
  std::int64_t generation = store_.content_generation();
  CachedSign entry;
  bool hit = false;
  {
    std::lock_guard<std::mutex> lock(sign_cache_mutex_);
    auto found = sign_cache_.find(id);
    if (found != sign_cache_.end() && found->second.generation == generation) {
      entry = found->second;
      hit = true;
    }
  }
  if (!hit) {
    std::optional<store::SignRecord> sign = store_.get_sign(id);
    if (!sign) throw ApiError(404, "no sign with id " + std::to_string(id), json{{"id", id}});
    entry.generation = generation;
    entry.revision = sign->revision;
    entry.deleted = sign->deleted;
    if (!sign->deleted) entry.body = store::sign_to_json(*sign).dump(-1, ' ', false, json::error_handler_t::replace);
    // A write between reading the generation and the sign would store a newer sign under an
    // older generation: harmless, the next request sees a newer generation and reloads.
    std::lock_guard<std::mutex> lock(sign_cache_mutex_);
    if (sign_cache_.size() >= kMaxCachedSigns) sign_cache_.clear();
    sign_cache_[id] = entry;
  }
  if (entry.deleted) {
    throw ApiError(410, "sign " + std::to_string(id) + " was deleted; GET /api/signs/" +
                            std::to_string(id) + "/history has its revisions",
                   json{{"id", id}, {"current_revision", entry.revision}});
  }
  std::string etag = etag_for(entry.revision);
  res.set_header("ETag", etag);
  res.set_header("Cache-Control", "no-cache");
  if (req.get_header_value("If-None-Match") == etag) {
    res.status = 304;
    return;
  }
  res.status = 200;
  res.set_content(entry.body, "application/json");
}

void ApiRoutes::create_sign(const httplib::Request& req, httplib::Response& res) {
  std::string author = authenticate(req);
  require_json_content_type(req);  // before the parameters: httplib reads a form body into them
  check_params(req, {});
  if (req.body.size() > limits_.max_sign_body_bytes) {
    throw ApiError(413, "a sign body is at most " + std::to_string(limits_.max_sign_body_bytes) + " bytes",
                   json{{"limit_bytes", limits_.max_sign_body_bytes}});
  }
  store::SignInput input = store::parse_sign_input(store::parse_json_document(req.body), true);
  store::SignRecord sign = store_.create_sign(input, author);
  res.set_header("Location", "/api/signs/" + std::to_string(sign.id));
  res.set_header("ETag", etag_for(sign.revision));
  reply_json(res, 201, store::sign_to_json(sign));
}

void ApiRoutes::update_sign(const httplib::Request& req, httplib::Response& res, std::int64_t id) {
  std::string author = authenticate(req);
  require_json_content_type(req);
  check_params(req, {});
  std::int64_t expected = require_if_match(req);
  if (req.body.size() > limits_.max_sign_body_bytes) {
    throw ApiError(413, "a sign body is at most " + std::to_string(limits_.max_sign_body_bytes) + " bytes",
                   json{{"limit_bytes", limits_.max_sign_body_bytes}});
  }
  store::SignInput input = store::parse_sign_input(store::parse_json_document(req.body), false);
  store::SignRecord sign = store_.update_sign(id, expected, input, author);
  res.set_header("ETag", etag_for(sign.revision));
  reply_json(res, 200, store::sign_to_json(sign));
}

void ApiRoutes::delete_sign(const httplib::Request& req, httplib::Response& res, std::int64_t id) {
  std::string author = authenticate(req);
  check_params(req, {});
  std::int64_t expected = require_if_match(req);
  store::SignRecord sign = store_.delete_sign(id, expected, author);
  reply_json(res, 200, json{{"id", sign.id}, {"deleted", true}, {"revision", sign.revision}});
}

void ApiRoutes::sign_history(const httplib::Request& req, httplib::Response& res, std::int64_t id) {
  check_params(req, {});
  json revisions = json::array();
  for (const store::RevisionRecord& revision : store_.history(id)) revisions.push_back(store::revision_to_json(revision));
  reply_json(res, 200, json{{"id", id}, {"revisions", revisions}});
}

void ApiRoutes::lookup(const httplib::Request& req, httplib::Response& res) {
  check_params(req, {"text", "lang"});
  if (!req.has_param("lang")) {
    throw ApiError(400, "missing query parameter 'lang' (a sign language code from /api/languages)",
                   json{{"parameter", "lang"}});
  }
  std::string text = param(req, "text");
  if (text.size() > store::kMaxLookupBytes) {
    throw ApiError(400, "text is longer than " + std::to_string(store::kMaxLookupBytes) + " bytes",
                   json{{"parameter", "text"}, {"limit_bytes", store::kMaxLookupBytes}});
  }
  store::LookupResult result = store_.lookup(text, param(req, "lang"));
  json tokens = json::array();
  for (const store::LookupToken& token : result.tokens) tokens.push_back(token_to_json(token));
  reply_json(res, 200, json{{"language", result.language}, {"text", text}, {"tokens", tokens}});
}

void ApiRoutes::import_signs(const httplib::Request& req, httplib::Response& res) {
  std::string author = authenticate(req);
  check_params(req, {"lang"});
  std::string language = param(req, "lang");
  std::size_t bad = store::find_invalid_utf8(req.body);
  if (bad != std::string::npos) {
    throw ApiError(400, "body is not valid UTF-8 (byte " + std::to_string(bad) + ")", json{{"offset", bad}});
  }
  std::vector<store::ImportItem> items;
  std::vector<store::ImportRejection> rejected;
  store::read_json_lines(req.body, "request body", language, &items, &rejected);
  if (items.empty() && rejected.empty()) {
    throw ApiError(400, "the body holds no sign lines (one JSON object per line)");
  }
  // Lines that are not even JSON stop the import, but the others are still checked so that one
  // answer lists every problem of the file.
  store::ImportReport report = store_.import_items(
      items, "import:" + author,
      rejected.empty() ? store::ImportMode::AllOrNothing : store::ImportMode::CheckOnly);
  report.rejected.insert(report.rejected.end(), rejected.begin(), rejected.end());
  if (!report.rejected.empty()) {
    json lines = json::array();
    for (const store::ImportRejection& rejection : report.rejected) lines.push_back(rejection_to_json(rejection));
    throw ApiError(422,
                   std::to_string(report.rejected.size()) + " of " +
                       std::to_string(items.size() + rejected.size()) +
                       " lines rejected; nothing was imported",
                   json{{"rejected", lines}});
  }
  reply_json(res, 200, json{{"created", report.created}, {"updated", report.updated},
                            {"unchanged", report.unchanged}, {"rejected", json::array()}});
}

void ApiRoutes::healthz(const httplib::Request& req, httplib::Response& res) {
  check_params(req, {"deep"});
  json body{{"status", "ok"}, {"schema_version", store_.schema_version()},
            {"signs", store_.count_live_signs()}, {"checks", store::synthesis_check_enabled() ? json::array({"parse", "synthesis"}) : json::array({"parse"})}};
  std::string deep = param(req, "deep");
  if (!deep.empty() && deep != "0") {
    std::string detail;
    bool ok = store_.integrity_check(&detail);
    body["integrity"] = detail;
    body["fingerprint"] = store_.content_fingerprint();
    if (!ok) {
      body["status"] = "corrupt";
      reply_json(res, 503, body);
      return;
    }
  }
  res.set_header("Cache-Control", "no-store");
  reply_json(res, 200, body);
}

void ApiRoutes::metrics(const httplib::Request& req, httplib::Response& res) {
  check_params(req, {});
  char gauges[1024];
  std::snprintf(gauges, sizeof gauges,
                "# HELP signweave_db_size_bytes Database file plus its WAL, in bytes.\n"
                "# TYPE signweave_db_size_bytes gauge\n"
                "signweave_db_size_bytes %lld\n"
                "# HELP signweave_signs Live signs in the database.\n"
                "# TYPE signweave_signs gauge\n"
                "signweave_signs %lld\n"
                "# HELP signweave_static_gzip_on_request_total Static files gzipped while a request waited.\n"
                "# TYPE signweave_static_gzip_on_request_total counter\n"
                "signweave_static_gzip_on_request_total %llu\n",
                static_cast<long long>(store_.database_size_bytes()),
                static_cast<long long>(store_.count_live_signs()),
                static_cast<unsigned long long>(web_.compressed_on_request() + models_.compressed_on_request()));
  res.status = 200;
  res.set_header("Cache-Control", "no-store");
  res.set_content(metrics_.render(gauges), "text/plain; version=0.0.4; charset=utf-8");
}

}  // namespace sw::http
