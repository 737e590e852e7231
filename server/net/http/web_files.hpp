// WebFiles: the browser viewer's files as --web-listen serves them - the page, its script and the
// WebAssembly module, read once at startup from --web-root, plus /ocean-web.json telling the page
// which port the WebSocket listener has. Only these names are served: no path from a request
// ever reaches the file system. Each file is sent gzipped to a client that takes gzip (the build
// writes NAME.gz beside NAME; without it, as is), with an ETag of its content so a page loaded
// again costs a 304 per file, not the module again.
#pragma once

#include "http_connection.hpp"
#include "http_request_parser.hpp"

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace ocean::server {

class WebFiles {
 public:
  // Connections to the page listener at once (one host: an eighth). Replies share the files, so a
  // connection costs a socket and its buffers; the descriptors stay well inside a default
  // RLIMIT_NOFILE of 1024 beside the viewers'.
  static constexpr std::size_t kMaxConnections = 256;

  // The files a web root must hold (the output of -DOCEAN_BUILD_WEB=ON).
  static const std::vector<std::string>& names();
  // Reads every file of names() from root; nullopt with error naming the first one missing.
  static std::optional<WebFiles> load(const std::string& root, std::uint16_t ws_port, std::string& error);

  HttpReply reply(const HttpRequest& request) const;
  std::size_t total_bytes() const;

 private:
  struct Variant {
    HttpReply reply;
    std::string etag;  // quoted, as in the reply's ETag header; empty for generated replies
  };
  struct Variants {
    Variant identity;
    std::optional<Variant> gzip;
  };
  std::map<std::string, Variants> replies_;  // by request target
};

// The first folder among --web-root's defaults (the build tree's web/, then the installed
// share/ocean/web) that holds the page; empty when none does.
std::string default_web_root();

}  // namespace ocean::server
