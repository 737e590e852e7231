#include "epoch.hpp"
#include "listen_address.hpp"

#include <catch2/catch.hpp>

using namespace ocean::server;

TEST_CASE("epochs parse from Unix milliseconds and RFC 3339", "[epoch]") {
  std::string error;
  CHECK(parse_epoch_ms("0", error) == 0);
  CHECK(parse_epoch_ms("-1500", error) == -1500);
  CHECK(parse_epoch_ms("1795280400000", error) == 1795280400000);
  // Expected values from Python's datetime.timestamp().
  CHECK(parse_epoch_ms("2026-11-21T17:00:00Z", error) == 1795280400000);
  CHECK(parse_epoch_ms("2026-11-21t17:00:00z", error) == 1795280400000);
  CHECK(parse_epoch_ms("2026-11-21 18:00:00.25+01:00", error) == 1795280400250);
  CHECK(parse_epoch_ms("2026-11-21T18:00:00.2509999+01:00", error) == 1795280400250);
  CHECK(parse_epoch_ms("2000-02-29T23:59:59-05:30", error) == 951888599000);
  CHECK(parse_epoch_ms("1970-01-01T00:00:00Z", error) == 0);
  CHECK(error.empty());
  for (const char* bad : {"", "now", "2026-11-21T17:00:00", "2026-11-21", "2026-13-01T00:00:00Z",
                          "2026-11-21T24:00:00Z", "2026-11-21T17:00:00.Z", "2026-11-21T17:00:00Zjunk", "12ms"}) {
    INFO(bad);
    error.clear();
    CHECK_FALSE(parse_epoch_ms(bad, error));
    CHECK(error.find("RFC 3339") != std::string::npos);
  }
}

TEST_CASE("listen addresses parse strictly", "[address]") {
  std::string error;
  CHECK(parse_listen_address("0.0.0.0:7700", error) == ListenAddress{"0.0.0.0", 7700});
  CHECK(parse_listen_address("*:80", error) == ListenAddress{"0.0.0.0", 80});
  CHECK(parse_listen_address("[::]:65535", error) == ListenAddress{"::", 65535});
  CHECK(parse_listen_address("[::1]:0", error) == ListenAddress{"::1", 0});
  CHECK(ListenAddress{"::1", 9}.to_string() == "[::1]:9");
  CHECK(ListenAddress{"10.0.0.1", 9}.to_string() == "10.0.0.1:9");
  CHECK(error.empty());
  for (const char* bad : {"", "7700", ":7700", "1.2.3.4:", "1.2.3.4:65536", "1.2.3.4:-1", "1.2.3.4:80x",
                          "example.com:80", "1.2.3:80", "[::1:80"}) {
    INFO(bad);
    error.clear();
    CHECK_FALSE(parse_listen_address(bad, error));
    CHECK_FALSE(error.empty());
  }
}
