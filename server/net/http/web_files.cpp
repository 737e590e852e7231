#include "web_files.hpp"

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

std::optional<WebFiles> WebFiles::load(const std::string& root, std::uint16_t ws_port, std::string& error) {
  WebFiles files;
  for (const std::string& name : names()) {
    const std::filesystem::path path = std::filesystem::path(root) / name;
    std::ifstream in(path, std::ios::binary);
    if (!in) {
      error = "--web-root '" + root + "' has no " + name + " (build the web viewer with -DOCEAN_BUILD_WEB=ON)";
      return std::nullopt;
    }
    HttpReply reply{200, content_type(name), {},
                    std::make_shared<const std::string>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>())};
    files.replies_["/" + name] = std::move(reply);
  }
  files.replies_["/"] = files.replies_["/index.html"];
  files.replies_["/ocean-web.json"] = {200, "application/json", "{\"ws_port\": " + std::to_string(ws_port) + "}\n"};
  return files;
}

HttpReply WebFiles::reply(const HttpRequest& request) const {
  const auto found = replies_.find(request.target);
  if (found == replies_.end()) return {404, "text/plain; charset=utf-8", "not found\n"};
  return found->second;
}

std::size_t WebFiles::total_bytes() const {
  std::size_t n = 0;
  for (const auto& [target, reply] : replies_) n += reply.content().size();
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
