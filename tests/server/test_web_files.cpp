// --web-listen's pieces: the fixed set of files it serves from memory, and the Origin rule that
// lets its own page open a WebSocket under whatever name the browser used, and nobody else's.
#include "web_files.hpp"
#include "websocket_link.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace ocean::server;

namespace {

std::filesystem::path web_root_with(const std::vector<std::string>& names) {
  const auto dir = std::filesystem::temp_directory_path() / ("ocean-web-files-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  for (const std::string& name : names) std::ofstream(dir / name) << "contents of " << name;
  return dir;
}

HttpRequest get(const std::string& target, const std::string& accept = "", const std::string& etag = "") {
  return {"GET", target, "HTTP/1.1", accept, etag};
}

// A header line's value in a reply's headers, empty when absent.
std::string header(const HttpReply& reply, const std::string& name) {
  const std::size_t at = reply.headers.find(name + ": ");
  if (at == std::string::npos) return "";
  const std::size_t from = at + name.size() + 2;
  return reply.headers.substr(from, reply.headers.find("\r\n", from) - from);
}

}  // namespace

TEST_CASE("WebFiles serves the page, its script and module with their types, and nothing else") {
  const auto root = web_root_with(WebFiles::names());
  std::string error;
  const auto files = WebFiles::load(root.string(), 7701, error);
  REQUIRE(files);
  CHECK(files->reply(get("/")).content() == "contents of index.html");
  CHECK(files->reply(get("/")).content_type == "text/html; charset=utf-8");
  CHECK(files->reply(get("/index.html")).content() == "contents of index.html");
  CHECK(files->reply(get("/ocean-web.js")).content_type == "text/javascript; charset=utf-8");
  CHECK(files->reply(get("/ocean-web.wasm")).content_type == "application/wasm");
  // The WebSocket's port, and the module's size for the page's progress ("contents of ocean-web.wasm").
  CHECK(files->reply(get("/ocean-web.json")).content() == "{\"ws_port\": 7701, \"wasm_bytes\": 26}\n");
  // Any other name - a file that exists in the folder, a path out of it - is 404.
  std::ofstream(root / "secret.txt") << "not served";
  for (const char* target : {"/secret.txt", "/../index.html", "/web/index.html", "index.html", "/INDEX.HTML"})
    CHECK(files->reply(get(target)).status == 404);
  std::filesystem::remove_all(root);
}

TEST_CASE("WebFiles sends the gzipped copy to a client that takes gzip, and a 304 for the copy a client holds") {
  auto root = web_root_with(WebFiles::names());
  std::ofstream(root / "ocean-web.wasm.gz") << "gzipped module";  // what the build writes beside it
  std::string error;
  const auto files = WebFiles::load(root.string(), 7701, error);
  REQUIRE(files);
  const HttpReply plain = files->reply(get("/ocean-web.wasm"));
  CHECK(plain.content() == "contents of ocean-web.wasm");
  CHECK(header(plain, "Content-Encoding").empty());
  CHECK(header(plain, "Vary") == "Accept-Encoding");
  CHECK(header(plain, "Cache-Control") == "no-cache");  // revalidate: the names carry no version
  for (const char* accept : {"gzip, deflate, br", "br;q=1.0, gzip;q=0.8", "*"}) {
    const HttpReply gz = files->reply(get("/ocean-web.wasm", accept));
    INFO(accept);
    CHECK(gz.content() == "gzipped module");
    CHECK(header(gz, "Content-Encoding") == "gzip");
    CHECK(gz.content_type == "application/wasm");
    CHECK(header(gz, "ETag") != header(plain, "ETag"));  // two representations, two tags
  }
  for (const char* accept : {"GZIP", "x-gzip", "br, gzip ; q=0.5", "gzip;q=1"})
    CHECK(files->reply(get("/ocean-web.wasm", accept)).content() == "gzipped module");
  // Refused by name (q=0 in any spelling) even where "*" would take it, or not taken at all.
  for (const char* accept : {"gzip;q=0, br", "gzip;q=0.0", "gzip; q=0.000, *", "*;q=0", "identity", ""})
    CHECK(files->reply(get("/ocean-web.wasm", accept)).content() == "contents of ocean-web.wasm");
  CHECK(files->reply(get("/ocean-web.wasm", "deflate")).content() == "contents of ocean-web.wasm");
  CHECK(header(files->reply(get("/viewer.js", "gzip")), "Content-Encoding").empty());  // no viewer.js.gz here
  // Revalidation: the tag the client holds gives a 304 with no body; another tag, the file.
  const std::string tag = header(files->reply(get("/ocean-web.wasm", "gzip")), "ETag");
  REQUIRE(tag.size() > 4);
  const HttpReply again = files->reply(get("/ocean-web.wasm", "gzip", tag));
  CHECK(again.status == 304);
  CHECK(again.content().empty());
  CHECK(header(again, "ETag") == tag);
  CHECK(again.to_wire(true).find("Content-Length") == std::string::npos);  // a 304 tells no length (RFC 9110 8.6)
  CHECK(files->reply(get("/ocean-web.wasm", "gzip", "\"x\", " + tag)).status == 304);  // one of a list
  CHECK(files->reply(get("/ocean-web.wasm", "gzip", "\"0000000000000000\"")).status == 200);
  CHECK(files->reply(get("/ocean-web.wasm", "", tag)).status == 200);  // the tag of the other representation
  std::filesystem::remove_all(root);
}

TEST_CASE("WebFiles names the first file a web root lacks") {
  const auto root = web_root_with({"index.html", "viewer.js"});
  std::string error;
  CHECK_FALSE(WebFiles::load(root.string(), 1, error));
  CHECK(error.find("ocean-web.js") != std::string::npos);
  CHECK(error.find("OCEAN_BUILD_WEB") != std::string::npos);
  std::filesystem::remove_all(root);
}

TEST_CASE("the server's own page opens a WebSocket under any host name; other pages do not") {
  const OriginPolicy policy{{"https://ocean.example"}, 8080};
  CHECK(policy.accepts(std::nullopt, "anything"));                              // no Origin: not a browser
  CHECK_FALSE(policy.accepts("", "anything"));                                  // an empty one: where from?
  CHECK(OriginPolicy{{"*"}, 0}.accepts("", "anything"));                        // ... unless any is allowed
  CHECK(policy.accepts("https://ocean.example", "10.0.0.2:7701"));              // the allow-list
  CHECK(policy.accepts("http://10.0.0.2:8080", "10.0.0.2:7701"));               // the page, by address
  CHECK(policy.accepts("http://sea.lan:8080", "sea.lan:7701"));                 // ... by name
  CHECK(policy.accepts("http://[::1]:8080", "[::1]:7701"));                     // ... over IPv6
  CHECK_FALSE(policy.accepts("http://evil.example:8080", "10.0.0.2:7701"));     // another site
  CHECK_FALSE(policy.accepts("http://10.0.0.2:9000", "10.0.0.2:7701"));         // this host's other port
  CHECK_FALSE(policy.accepts("http://10.0.0.2", "10.0.0.2:7701"));              // port 80 is not 8080
  CHECK_FALSE(policy.accepts("ftp://10.0.0.2:8080", "10.0.0.2:7701"));
  CHECK_FALSE(policy.accepts("http://10.0.0.2:8080", ""));                      // no Host: nothing to match
  CHECK(OriginPolicy{{}, 80}.accepts("http://sea.lan", "sea.lan:7701"));        // default port, not written
  CHECK_FALSE(OriginPolicy{{}, 0}.accepts("http://sea.lan:8080", "sea.lan:7701"));  // no page served
}
