// Parsing of ocean-viewer's HOST:PORT option value.
#include "client/viewer/viewer_options.hpp"

#include <cstdio>

namespace ocean::viewer {

bool parse_server_address(const std::string& text, std::string& host, std::string& port, std::string& error) {
  const auto colon = text.rfind(':');
  if (colon == std::string::npos || colon == 0 || colon + 1 == text.size()) {
    error = "--server must be HOST:PORT (e.g. 127.0.0.1:7100), got '" + text + "'";
    return false;
  }
  host = text.substr(0, colon);
  if (host.size() > 2 && host.front() == '[' && host.back() == ']') host = host.substr(1, host.size() - 2);
  port = text.substr(colon + 1);
  int value = 0;
  char tail = 0;
  if (std::sscanf(port.c_str(), "%d%c", &value, &tail) != 1 || value < 1 || value > 65535) {
    error = "--server port must be a number 1..65535, got '" + port + "'";
    return false;
  }
  return true;
}

}  // namespace ocean::viewer
