#include "server_list.hpp"

#include <algorithm>

namespace ocean::client {

bool parse_server_address(const std::string& text, ServerEndpoint& server, std::string& error) {
  const auto colon = text.rfind(':');
  if (colon == std::string::npos || colon == 0 || colon + 1 == text.size()) {
    error = "--server: '" + text + "' is not HOST:PORT (e.g. 127.0.0.1:7700 or [::1]:7700)";
    return false;
  }
  std::string host = text.substr(0, colon);
  if (host.front() == '[') {
    if (host.size() < 3 || host.back() != ']') {
      error = "--server: '" + text + "' has an unclosed or empty [IPv6] host";
      return false;
    }
    host = host.substr(1, host.size() - 2);
  } else if (host.find(':') != std::string::npos) {
    // An unbracketed v6 literal would be split at its last colon and silently lose a group.
    error = "--server: '" + text + "': write an IPv6 host in brackets, e.g. [::1]:7700";
    return false;
  }
  const std::string port = text.substr(colon + 1);
  const bool digits = port.size() <= 5 && std::all_of(port.begin(), port.end(), [](char c) { return c >= '0' && c <= '9'; });
  if (!digits || std::stol(port) < 1 || std::stol(port) > 65535) {
    error = "--server: '" + text + "' has port '" + port + "'; the port must be a number in 1..65535";
    return false;
  }
  server = {host, port};
  return true;
}

bool parse_server_list(const std::vector<std::string>& values, std::vector<ServerEndpoint>& servers,
                       std::string& error) {
  std::vector<ServerEndpoint> parsed;
  for (const std::string& value : values) {
    std::size_t begin = 0;
    while (true) {
      const std::size_t comma = value.find(',', begin);
      const std::string entry = value.substr(begin, comma == std::string::npos ? std::string::npos : comma - begin);
      if (entry.empty()) {
        error = "--server: empty entry in '" + value + "' (separate HOST:PORT entries with single commas)";
        return false;
      }
      ServerEndpoint server;
      if (!parse_server_address(entry, server, error)) return false;
      parsed.push_back(std::move(server));
      if (comma == std::string::npos) break;
      begin = comma + 1;
    }
  }
  if (parsed.empty()) {
    error = "--server: no server given; expected HOST:PORT[,HOST:PORT...]";
    return false;
  }
  servers = std::move(parsed);
  return true;
}

}  // namespace ocean::client
