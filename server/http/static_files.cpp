// Static file serving (see static_files.h).
#include "http/static_files.h"

#include <dirent.h>
#include <sys/stat.h>
#include <zlib.h>

#include <climits>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <vector>

#include "http/json_reply.h"

namespace sw::http {
namespace {

// Why these limits: the largest file the page loads is the WASM module or the avatar (a few MiB);
// caching files up to 32 MiB and 256 MiB in total keeps every page asset in memory while a stray
// huge file is streamed from disk each time instead of pinning memory.
constexpr std::uint64_t kMaxCachedFileBytes = 32ull * 1024 * 1024;
constexpr std::uint64_t kMaxCacheBytes = 256ull * 1024 * 1024;
// Below this size gzip saves less than the header it adds.
constexpr std::uint64_t kMinGzipBytes = 512;

std::string extension_of(const std::string& path) {
  std::size_t slash = path.find_last_of('/');
  std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot + 1);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

// The page's avatar pack (src/avatar/avatar_pack.h, built into web/gen/): floats and indices,
// about half its size gzipped, like the .glb it is made from.
const char* const kAvatarPackMime = "application/vnd.signweave.avatar-pack";

bool is_compressible(const std::string& mime) {
  return mime.rfind("text/", 0) == 0 || mime.rfind("application/json", 0) == 0 ||
         mime == "application/wasm" || mime == "image/svg+xml" || mime == "model/gltf+json" ||
         mime == "model/gltf-binary" || mime == "application/xml" || mime == kAvatarPackMime;
}

bool gzip_compress(const std::string& input, std::string* output) {
  z_stream stream{};
  // windowBits 15 + 16: a gzip wrapper (RFC 1952) rather than raw zlib.
  if (deflateInit2(&stream, Z_BEST_COMPRESSION, Z_DEFLATED, 15 + 16, 9, Z_DEFAULT_STRATEGY) != Z_OK) {
    return false;
  }
  output->resize(deflateBound(&stream, input.size()));
  stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(input.data()));
  stream.avail_in = static_cast<uInt>(input.size());
  stream.next_out = reinterpret_cast<Bytef*>(output->data());
  stream.avail_out = static_cast<uInt>(output->size());
  int rc = deflate(&stream, Z_FINISH);
  output->resize(stream.total_out);
  deflateEnd(&stream);
  return rc == Z_STREAM_END;
}

bool read_whole_file(const std::string& path, std::string* out) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream buffer;
  buffer << in.rdbuf();
  *out = buffer.str();
  return true;
}

std::string real_path(const std::string& path) {
  char resolved[PATH_MAX];
  return ::realpath(path.c_str(), resolved) ? std::string(resolved) : std::string();
}

bool inside(const std::string& root, const std::string& path) {
  return path.size() > root.size() && path.compare(0, root.size(), root) == 0 && path[root.size()] == '/';
}

// Sends `body` with a fixed length through a content provider: httplib then neither copies it nor
// compresses it again (its own on-the-fly compression ignores an existing Content-Encoding).
void send_body(httplib::Response& res, std::shared_ptr<const std::string> body, const std::string& mime) {
  std::size_t size = body->size();
  res.set_content_provider(size, mime,
                           [body](std::size_t offset, std::size_t length, httplib::DataSink& sink) {
                             if (offset > body->size()) return false;
                             std::size_t count = std::min(length, body->size() - offset);
                             return sink.write(body->data() + offset, count);
                           });
}

}  // namespace

std::string mime_type_for(const std::string& path) {
  static const std::map<std::string, std::string> kTypes = {
      {"html", "text/html; charset=utf-8"},  {"htm", "text/html; charset=utf-8"},
      {"js", "text/javascript; charset=utf-8"}, {"mjs", "text/javascript; charset=utf-8"},
      {"css", "text/css; charset=utf-8"},     {"json", "application/json"},
      {"wasm", "application/wasm"},           {"glb", "model/gltf-binary"},
      {"gltf", "model/gltf+json"},            {"bin", "application/octet-stream"},
      {"svg", "image/svg+xml"},               {"png", "image/png"},
      {"jpg", "image/jpeg"},                  {"jpeg", "image/jpeg"},
      {"webp", "image/webp"},                 {"ico", "image/x-icon"},
      {"woff2", "font/woff2"},                {"woff", "font/woff"},
      {"ttf", "font/ttf"},                    {"otf", "font/otf"},
      {"txt", "text/plain; charset=utf-8"},   {"md", "text/markdown; charset=utf-8"},
      {"map", "application/json"},            {"webmanifest", "application/manifest+json"},
      {"xml", "application/xml"},             {"sigml", "application/xml"},
      {"jsonl", "application/x-ndjson"},      {"bvh", "text/plain; charset=utf-8"},
      {"swavatar", kAvatarPackMime},
  };
  auto found = kTypes.find(extension_of(path));
  return found != kTypes.end() ? found->second : "application/octet-stream";
}

bool accepts_gzip(const std::string& accept_encoding) {
  // Tokens separated by commas, each "coding[;q=value]"; gzip is acceptable unless q=0.
  std::size_t start = 0;
  while (start < accept_encoding.size()) {
    std::size_t end = accept_encoding.find(',', start);
    if (end == std::string::npos) end = accept_encoding.size();
    std::string token = accept_encoding.substr(start, end - start);
    start = end + 1;
    std::string coding, params;
    std::size_t semicolon = token.find(';');
    coding = token.substr(0, semicolon);
    if (semicolon != std::string::npos) params = token.substr(semicolon + 1);
    auto trim = [](std::string s) {
      std::size_t a = s.find_first_not_of(" \t");
      std::size_t b = s.find_last_not_of(" \t");
      return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
    };
    coding = trim(coding);
    for (char& c : coding) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (coding != "gzip" && coding != "x-gzip" && coding != "*") continue;
    params = trim(params);
    if (params.rfind("q=", 0) == 0 && std::strtod(params.c_str() + 2, nullptr) <= 0.0) return false;
    return true;
  }
  return false;
}

StaticFiles::StaticFiles(std::string root, std::string mount) : mount_(std::move(mount)) {
  std::string resolved = real_path(root);
  struct stat info {};
  if (!resolved.empty() && ::stat(resolved.c_str(), &info) == 0 && S_ISDIR(info.st_mode)) {
    root_real_ = resolved;
  }
}

bool StaticFiles::lookup(const std::string& resolved, const struct stat& info, bool want_gzip, bool on_request,
                         std::shared_ptr<const std::string>* body_out,
                         std::shared_ptr<const std::string>* gzip_out) {
  std::int64_t mtime_ns = static_cast<std::int64_t>(info.st_mtim.tv_sec) * 1000000000 + info.st_mtim.tv_nsec;
  std::uint64_t size = static_cast<std::uint64_t>(info.st_size);
  std::shared_ptr<const std::string> body;
  std::shared_ptr<const std::string> gzip_body;
  bool gzip_tried = false;
  {
    std::lock_guard<std::mutex> lock(cache_mutex_);
    auto found = cache_.find(resolved);
    if (found != cache_.end() && (found->second.size != size || found->second.mtime_ns != mtime_ns)) {
      cached_bytes_ -= found->second.size;
      cache_.erase(found);
      found = cache_.end();
    }
    if (found != cache_.end()) {
      body = found->second.body;
      gzip_body = found->second.gzip_body;
      gzip_tried = found->second.gzip_tried;
    }
  }
  if (!body) {
    std::string contents;
    if (!read_whole_file(resolved, &contents)) return false;
    body = std::make_shared<const std::string>(std::move(contents));
  }

  if (want_gzip && !gzip_body && !gzip_tried) {
    // A precompressed sibling wins (made offline at the best ratio), if it is as new as the file.
    struct stat gz_info {};
    std::string gz_path = resolved + ".gz";
    std::string gz_real = real_path(gz_path);
    std::string compressed;
    if (!gz_real.empty() && inside(root_real_, gz_real) && ::stat(gz_real.c_str(), &gz_info) == 0 &&
        S_ISREG(gz_info.st_mode) && gz_info.st_mtim.tv_sec >= info.st_mtim.tv_sec &&
        read_whole_file(gz_real, &compressed)) {
      gzip_body = std::make_shared<const std::string>(std::move(compressed));
    } else {
      if (on_request) compressed_on_request_.fetch_add(1, std::memory_order_relaxed);
      if (gzip_compress(*body, &compressed) && compressed.size() < body->size())
        gzip_body = std::make_shared<const std::string>(std::move(compressed));
    }
  }
  if (size <= kMaxCachedFileBytes) {
    std::lock_guard<std::mutex> lock(cache_mutex_);
    auto found = cache_.find(resolved);
    if (found == cache_.end() && cached_bytes_ + size <= kMaxCacheBytes) {
      cache_[resolved] = CachedFile{size, mtime_ns, body, gzip_body, want_gzip};
      cached_bytes_ += size;
    } else if (found != cache_.end() && want_gzip && !found->second.gzip_tried) {
      found->second.gzip_body = gzip_body;
      found->second.gzip_tried = true;
    }
  }
  *body_out = std::move(body);
  *gzip_out = std::move(gzip_body);
  return true;
}

std::size_t StaticFiles::precompress() {
  if (!valid()) return 0;
  std::size_t files = 0;
  std::vector<std::string> pending{root_real_};
  while (!pending.empty()) {
    std::string dir = std::move(pending.back());
    pending.pop_back();
    DIR* handle = ::opendir(dir.c_str());
    if (!handle) continue;
    std::vector<std::string> names;
    while (const dirent* entry = ::readdir(handle)) {
      if (entry->d_name[0] != '.') names.push_back(entry->d_name);  // dot-files are never served
    }
    ::closedir(handle);
    for (const std::string& name : names) {
      std::string resolved = real_path(dir + "/" + name);
      struct stat info {};
      if (resolved.empty() || !inside(root_real_, resolved) || ::stat(resolved.c_str(), &info) != 0) continue;
      if (S_ISDIR(info.st_mode)) {
        if (resolved == dir + "/" + name) pending.push_back(resolved);  // no symlinked loops
        continue;
      }
      std::uint64_t size = static_cast<std::uint64_t>(info.st_size);
      // Only what serve() would cache and compress: the same conditions as a request with gzip.
      if (!S_ISREG(info.st_mode) || size < kMinGzipBytes || size > kMaxCachedFileBytes ||
          !is_compressible(mime_type_for(resolved)) || extension_of(resolved) == "gz")
        continue;
      std::shared_ptr<const std::string> body, gzip_body;
      if (lookup(resolved, info, /*want_gzip=*/true, /*on_request=*/false, &body, &gzip_body)) ++files;
    }
  }
  return files;
}

void StaticFiles::serve(const httplib::Request& req, httplib::Response& res) {
  if (!valid()) {
    reply_error(res, 404, "no such file (this server has no directory for " + mount_ + ")");
    return;
  }
  // httplib has already percent-decoded req.path, so encoded dots and slashes are visible here.
  std::string relative = req.path.substr(std::min(mount_.size(), req.path.size()));
  if (relative.find('\0') != std::string::npos || relative.find('\\') != std::string::npos) {
    reply_error(res, 400, "path contains a NUL byte or a backslash", {{"path", req.path}});
    return;
  }
  std::string cleaned;
  std::size_t start = 0;
  while (start <= relative.size()) {
    std::size_t end = relative.find('/', start);
    if (end == std::string::npos) end = relative.size();
    std::string segment = relative.substr(start, end - start);
    bool last = end == relative.size();
    start = end + 1;
    if (segment.empty()) {
      if (last) break;  // a trailing slash: the directory's index.html
      continue;         // "//" collapses
    }
    if (segment == ".." || segment == ".") {
      reply_error(res, 400, "path escapes the served directory ('" + segment + "' segment)",
                  {{"path", req.path}});
      return;
    }
    if (segment[0] == '.') {
      reply_error(res, 404, "no such file", {{"path", req.path}});
      return;
    }
    cleaned += "/" + segment;
    if (last) break;
  }

  std::string candidate = root_real_ + cleaned;
  struct stat info {};
  if (::stat(candidate.c_str(), &info) == 0 && S_ISDIR(info.st_mode)) candidate += "/index.html";
  std::string resolved = real_path(candidate);
  if (resolved.empty() || !inside(root_real_, resolved) || ::stat(resolved.c_str(), &info) != 0 ||
      !S_ISREG(info.st_mode)) {
    // A symlink leading out of the root lands here too: to the client it simply does not exist.
    reply_error(res, 404, "no such file", {{"path", req.path}});
    return;
  }

  std::string mime = mime_type_for(resolved);
  std::int64_t mtime_ns = static_cast<std::int64_t>(info.st_mtim.tv_sec) * 1000000000 + info.st_mtim.tv_nsec;
  std::uint64_t size = static_cast<std::uint64_t>(info.st_size);
  bool want_gzip = accepts_gzip(req.get_header_value("Accept-Encoding")) && is_compressible(mime) &&
                   size >= kMinGzipBytes;

  std::shared_ptr<const std::string> body;
  std::shared_ptr<const std::string> gzip_body;
  if (!lookup(resolved, info, want_gzip, /*on_request=*/true, &body, &gzip_body)) {
    reply_error(res, 404, "no such file", {{"path", req.path}});
    return;
  }

  bool send_gzip = want_gzip && gzip_body;
  char etag[64];
  std::snprintf(etag, sizeof etag, "\"%llx-%llx%s\"", static_cast<unsigned long long>(size),
                static_cast<unsigned long long>(mtime_ns), send_gzip ? "-gz" : "");
  res.set_header("ETag", etag);
  res.set_header("Vary", "Accept-Encoding");
  bool revalidate = mime.rfind("text/html", 0) == 0 || mime == "application/json";
  res.set_header("Cache-Control", revalidate ? "no-cache" : "public, max-age=300");
  res.set_header("X-Content-Type-Options", "nosniff");

  std::string if_none_match = req.get_header_value("If-None-Match");
  if (!if_none_match.empty() && (if_none_match == etag || if_none_match == "*" ||
                                 if_none_match.find(etag) != std::string::npos)) {
    res.status = 304;
    return;
  }
  res.status = 200;
  if (send_gzip) {
    res.set_header("Content-Encoding", "gzip");
    send_body(res, gzip_body, mime);
  } else {
    send_body(res, body, mime);
  }
}

}  // namespace sw::http
