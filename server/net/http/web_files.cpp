#include "web_files.hpp"

#include "common/fnv1a.hpp"

#include <cstdio>
#include <string>
#include <cstdlib>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace ocean::server {

namespace {

std::string content_type(const std::string& name) {
  const auto ends = [&](std::string_view suffix) {
    return name.size() >= suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
  };
  if (ends(".html")) return "text/html; charset=utf-8";
  if (ends(".js")) return "text/javascript; charset=utf-8";
  if (ends(".wasm")) return "application/wasm";  // streaming compilation needs exactly this type
  return "application/octet-stream";
}

}  // namespace

const std::vector<std::string>& WebFiles::names() {
  static const std::vector<std::string> kNames = {"index.html", "viewer.js", "ocean-web.js", "ocean-web.wasm"};
  return kNames;
}

namespace {

std::shared_ptr<const std::string> read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return nullptr;
  return std::make_shared<const std::string>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// FNV-1a 64 of the content, quoted: strong enough to tell two builds' files apart.
std::string etag_of(std::string_view content) {
  const std::uint64_t h = common::fnv1a(content.data(), content.size());
  char text[24];
  std::snprintf(text, sizeof text, "\"%016llx\"", static_cast<unsigned long long>(h));
  return text;
}

// "gzip" among the codings the client takes (RFC 9110 12.5.3): names are case-insensitive, and
// q=0 (or 0.0, 0.000) refuses one; "*" stands for any coding not named.
bool takes_gzip(std::string_view accept) {
  std::optional<bool> gzip, any;
  while (!accept.empty()) {
    const std::size_t comma = accept.find(',');
    std::string_view item = accept.substr(0, comma);
    accept = comma == std::string_view::npos ? std::string_view() : accept.substr(comma + 1);
    const std::size_t semicolon = item.find(';');
    std::string coding(item.substr(0, semicolon));
    std::erase_if(coding, [](char c) { return c == ' ' || c == '\t'; });
    for (char& c : coding) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    bool wanted = true;
    if (semicolon != std::string_view::npos) {
      const std::string_view params = item.substr(semicolon + 1);
      if (const std::size_t q = params.find("q="); q != std::string_view::npos)
        wanted = std::strtod(std::string(params.substr(q + 2)).c_str(), nullptr) > 0.0;
    }
    if (coding == "gzip" || coding == "x-gzip") gzip = wanted;
    else if (coding == "*") any = wanted;
  }
  return gzip.value_or(any.value_or(false));
}

}  // namespace

std::optional<WebFiles> WebFiles::load(const std::string& root, std::uint16_t ws_port, std::string& error) {
  WebFiles files;
  for (const std::string& name : names()) {
    const std::filesystem::path path = std::filesystem::path(root) / name;
    const auto content = read_file(path);
    if (!content) {
      error = "--web-root '" + root + "' has no " + name + " (build the web viewer with -DOCEAN_BUILD_WEB=ON)";
      return std::nullopt;
    }
    const std::string etag = etag_of(*content), gz_etag = etag.substr(0, etag.size() - 1) + "-gz\"";
    const std::string cache = "Cache-Control: no-cache\r\nVary: Accept-Encoding\r\n";
    Variants v{{{200, content_type(name), {}, content, cache + "ETag: " + etag + "\r\n"}, etag}, std::nullopt};
    if (const auto gz = read_file(path.string() + ".gz"))
      v.gzip = Variant{{200, content_type(name), {}, gz, cache + "Content-Encoding: gzip\r\nETag: " + gz_etag + "\r\n"},
                       gz_etag};
    files.replies_["/" + name] = std::move(v);
  }
  files.replies_["/"] = files.replies_["/index.html"];
  // The module's size as the page's script reads it (decompressed), for its loading progress.
  const std::size_t wasm_bytes = files.replies_["/ocean-web.wasm"].identity.reply.content().size();
  files.replies_["/ocean-web.json"] = {{{200, "application/json",
                                         "{\"ws_port\": " + std::to_string(ws_port) +
                                             ", \"wasm_bytes\": " + std::to_string(wasm_bytes) + "}\n"},
                                        {}},
                                       std::nullopt};
  return files;
}

HttpReply WebFiles::reply(const HttpRequest& request) const {
  const auto found = replies_.find(request.target);
  if (found == replies_.end()) return {404, "text/plain; charset=utf-8", "not found\n"};
  const Variants& v = found->second;
  const Variant& chosen = v.gzip && takes_gzip(request.accept_encoding) ? *v.gzip : v.identity;
  // The copy the client holds is this one: only the headers again.
  if (!chosen.etag.empty() && !request.if_none_match.empty() &&
      (request.if_none_match == "*" || request.if_none_match.find(chosen.etag) != std::string::npos))
    return {304, chosen.reply.content_type, {}, nullptr, chosen.reply.headers};
  return chosen.reply;
}

std::size_t WebFiles::total_bytes() const {
  std::size_t n = 0;
  for (const auto& [target, v] : replies_)
    n += v.identity.reply.content().size() + (v.gzip ? v.gzip->reply.content().size() : 0);
  return n;
}

std::string default_web_root() {
  for (const char* dir : {
#ifdef OCEAN_WEB_BUILD_DIR
           OCEAN_WEB_BUILD_DIR,
#endif
#ifdef OCEAN_WEB_INSTALL_DIR
           OCEAN_WEB_INSTALL_DIR,
#endif
           ""}) {
    if (*dir && std::filesystem::exists(std::filesystem::path(dir) / "index.html")) return dir;
  }
  return "";
}

}  // namespace ocean::server
