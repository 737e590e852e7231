#include "etcd_gateway.hpp"

#include <asio/connect.hpp>
#include <asio/io_context.hpp>
#include <asio/ip/tcp.hpp>
#include <asio/read.hpp>
#include <asio/write.hpp>
#include <nlohmann/json.hpp>
#include <sodium.h>

#include <algorithm>
#include <chrono>
#include <cctype>

namespace ocean::server {
namespace {

using nlohmann::json;

std::string lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

// A chunked body's data (RFC 9112 7.1); false when it is cut short or malformed.
bool unchunk(const std::string& body, std::string& out) {
  std::size_t at = 0;
  while (true) {
    const std::size_t eol = body.find("\r\n", at);
    if (eol == std::string::npos) return false;
    std::size_t size = 0;
    try {
      size = std::stoul(body.substr(at, eol - at), nullptr, 16);
    } catch (...) {
      return false;
    }
    if (size == 0) return true;
    if (eol + 2 + size > body.size()) return false;
    out.append(body, eol + 2, size);
    at = eol + 2 + size + 2;
  }
}

// One POST with "Connection: close", read to the end, within timeout_s; the body of a 200.
std::string post(const EtcdEndpoint& endpoint, const std::string& path, const std::string& body, double timeout_s,
                 std::string& error) {
  asio::io_context io;
  asio::ip::tcp::socket socket(io);
  std::error_code ec;
  asio::ip::tcp::resolver resolver(io);
  const auto addresses = resolver.resolve(endpoint.host, std::to_string(endpoint.port), ec);
  const std::string where = endpoint.host + ":" + std::to_string(endpoint.port);
  if (ec) {
    error = "cannot resolve the store's host " + where + ": " + ec.message();
    return {};
  }
  const std::string request = "POST " + path + " HTTP/1.1\r\nHost: " + where +
                              "\r\nContent-Type: application/json\r\nConnection: close\r\nContent-Length: " +
                              std::to_string(body.size()) + "\r\n\r\n" + body;
  std::string response;
  std::error_code failure;
  bool done = false;
  asio::async_connect(socket, addresses, [&](std::error_code e, const auto&) {
    if (e) {
      failure = e;
      done = true;
      return;
    }
    asio::async_write(socket, asio::buffer(request), [&](std::error_code w, std::size_t) {
      if (w) {
        failure = w;
        done = true;
        return;
      }
      asio::async_read(socket, asio::dynamic_buffer(response), [&](std::error_code r, std::size_t) {
        if (r && r != asio::error::eof) failure = r;
        done = true;
      });
    });
  });
  io.run_for(std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::duration<double>(timeout_s)));
  if (!done) {
    error = "the store at " + where + " did not answer within " + std::to_string(timeout_s).substr(0, 4) + " s";
    return {};
  }
  if (failure) {
    error = "the store at " + where + " is unreachable: " + failure.message();
    return {};
  }
  const std::size_t head_end = response.find("\r\n\r\n");
  if (response.compare(0, 9, "HTTP/1.1 ") != 0 || head_end == std::string::npos) {
    error = "the store at " + where + " did not answer in HTTP/1.1";
    return {};
  }
  const std::string status = response.substr(9, 3);
  std::string content = response.substr(head_end + 4);
  if (lower(response.substr(0, head_end)).find("transfer-encoding: chunked") != std::string::npos) {
    std::string data;
    if (!unchunk(content, data)) {
      error = "the store at " + where + " sent a malformed chunked body";
      return {};
    }
    content = std::move(data);
  }
  if (status != "200") {
    error = "the store at " + where + " answered " + status + " to " + path + ": " + content.substr(0, 200);
    return {};
  }
  return content;
}

std::int64_t number(const json& value) {  // the gateway writes 64-bit integers as strings
  if (value.is_string()) return std::stoll(value.get<std::string>());
  return value.is_number_integer() ? value.get<std::int64_t>() : 0;
}

}  // namespace

std::string to_base64(const std::string& bytes) {
  std::string out(sodium_base64_ENCODED_LEN(bytes.size(), sodium_base64_VARIANT_ORIGINAL), '\0');
  sodium_bin2base64(out.data(), out.size(), reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(),
                    sodium_base64_VARIANT_ORIGINAL);
  out.resize(out.size() - 1);  // the terminating NUL
  return out;
}

bool from_base64(const std::string& text, std::string& bytes) {
  bytes.assign(text.size() / 4 * 3 + 3, '\0');
  std::size_t length = 0;
  if (sodium_base642bin(reinterpret_cast<unsigned char*>(bytes.data()), bytes.size(), text.data(), text.size(),
                        nullptr, &length, nullptr, sodium_base64_VARIANT_ORIGINAL) != 0)
    return false;
  bytes.resize(length);
  return true;
}

EtcdResult EtcdGateway::call(const std::string& path, const std::string& body) const {
  EtcdResult result;
  const std::string content = post(endpoint_, path, body, timeout_s_, result.error);
  if (!result.error.empty()) return result;
  const json answer = json::parse(content, nullptr, false);
  if (answer.is_discarded() || !answer.is_object() || !answer.contains("header")) {
    result.error = "the store answered " + path + " with no etcd reply: " + content.substr(0, 200);
    return result;
  }
  try {
    result.revision = number(answer["header"].value("revision", json(0)));
    result.succeeded = answer.value("succeeded", false);
    result.more = answer.value("more", false);
    for (const json& kv : answer.value("kvs", json::array())) {
      EtcdKeyValue item;
      if (!from_base64(kv.value("key", ""), item.key) || !from_base64(kv.value("value", ""), item.value))
        throw std::invalid_argument("a key or value is not base64");
      item.mod_revision = number(kv.value("mod_revision", json(0)));
      result.kvs.push_back(std::move(item));
    }
  } catch (const std::exception& e) {
    result.error = std::string("the store's answer to ") + path + " does not read: " + e.what();
  }
  return result;
}

EtcdResult EtcdGateway::put_if_absent(const std::string& key, const std::string& value) const {
  const std::string k = to_base64(key);
  const json request = {
      {"compare", json::array({{{"target", "CREATE"}, {"key", k}, {"create_revision", "0"}}})},
      {"success", json::array({{{"request_put", {{"key", k}, {"value", to_base64(value)}}}}})}};
  return call("/v3/kv/txn", request.dump());
}

EtcdResult EtcdGateway::range(const std::string& from, const std::string& to, std::int64_t limit, bool descending) const {
  json request = {{"key", to_base64(from)}, {"range_end", to_base64(to)}, {"limit", std::to_string(limit)}};
  if (descending) {
    request["sort_order"] = "DESCEND";
    request["sort_target"] = "KEY";
  }
  return call("/v3/kv/range", request.dump());
}

}  // namespace ocean::server
