// StaticFiles: serves one directory (the page in web/, the avatar in models/) safely and fast.
//
// - Paths are confined to the root: "..", "." and empty segments, backslashes and NUL are refused
//   (after URL decoding, so %2e%2e and %2f cannot smuggle them in), dot-files are hidden, and the
//   resolved real path must lie inside the root's real path, so a symlink pointing out of the
//   root is not followed.
// - MIME types by extension, the ones the page depends on exactly: application/wasm (streaming
//   compilation needs it), text/javascript for .js/.mjs (module scripts), model/gltf-binary.
// - Strong ETag from size and mtime; If-None-Match answers 304. Cache-Control: HTML and JSON
//   "no-cache" (always revalidate: they name the other files), everything else a short max-age.
// - gzip when Accept-Encoding allows it: a precompressed "<file>.gz" beside the file if present,
//   otherwise compressed once in memory with zlib and cached (compressible types only).
//   precompress() does that for every file at server start-up, so no page load waits for zlib at
//   its best level (the WASM modules and the avatar took tens of milliseconds each, more on a
//   loaded machine, on the first request of each).
//
// Does not: list directories, serve ranges of compressed bodies, or watch files (a changed file
// is noticed by its size/mtime on the next request).
#pragma once

#include <httplib.h>
#include <sys/stat.h>

#include <atomic>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>

namespace sw::http {

class StaticFiles {
 public:
  // `root` must be a directory; `mount` is the URL prefix it answers ("/" or "/models/").
  StaticFiles(std::string root, std::string mount);

  bool valid() const { return !root_real_.empty(); }
  const std::string& root() const { return root_real_; }
  // Serves `req.path` (which starts with the mount prefix). Always answers: 200/304, or a JSON
  // 400 (unsafe path) / 404 / 405.
  void serve(const httplib::Request& req, httplib::Response& res);
  // Reads and gzips every compressible file under the root into the cache (within the cache's
  // limits). Returns how many files are now cached with their gzip form decided.
  std::size_t precompress();
  // How many times a request had to run zlib itself (0 after precompress() unless files changed).
  std::uint64_t compressed_on_request() const { return compressed_on_request_.load(std::memory_order_relaxed); }

 private:
  struct CachedFile {
    std::uint64_t size = 0;
    std::int64_t mtime_ns = 0;
    std::shared_ptr<const std::string> body;
    std::shared_ptr<const std::string> gzip_body;  // null until asked for (or not compressible)
    bool gzip_tried = false;
  };

  // The cached body and gzip form of `resolved` (read and compressed if absent or stale).
  bool lookup(const std::string& resolved, const struct stat& info, bool want_gzip, bool on_request,
              std::shared_ptr<const std::string>* body, std::shared_ptr<const std::string>* gzip_body);

  std::string root_real_;
  std::string mount_;
  std::mutex cache_mutex_;
  std::map<std::string, CachedFile> cache_;  // real path -> contents
  std::uint64_t cached_bytes_ = 0;
  std::atomic<std::uint64_t> compressed_on_request_{0};
};

// The MIME type for a file name (by its last extension).
std::string mime_type_for(const std::string& path);
bool accepts_gzip(const std::string& accept_encoding);

}  // namespace sw::http
