#include "etcd_gateway.hpp"

#include <asio/connect.hpp>
#include <asio/io_context.hpp>
#include <asio/ip/tcp.hpp>
#include <asio/read.hpp>
#include <asio/write.hpp>
#include <nlohmann/json.hpp>
#include <sodium.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <chrono>
#include <stdexcept>

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
    std::uint64_t size = 0;
    const auto [end, ec] = std::from_chars(body.data() + at, body.data() + eol, size, 16);
    if (ec != std::errc() || end == body.data() + at) return false;  // a chunk extension ends the digits: taken as none
    if (size == 0) return true;
    const std::size_t data = eol + 2;
    if (size > body.size() - data || body.size() - data - size < 2 || body.compare(data + size, 2, "\r\n") != 0)
      return false;
    out.append(body, data, size);
    at = data + size + 2;
  }
}

// A 200's body from a whole HTTP/1.1 response, or the error naming what came instead.
std::string reply_body(const std::string& response, const std::string& where, const std::string& path,
                       std::string& error) {
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
  if (status != "200") error = "the store at " + where + " answered " + status + " to " + path + ": " + content.substr(0, 200);
  return content;
}

// One POST with "Connection: close", read to the end, within timeout_s; the body of a 200. `sent`
// tells whether the request went out (an error after it leaves what the store did unknown).
std::string post(const EtcdEndpoint& endpoint, const std::string& path, const std::string& body, double timeout_s,
                 std::string& error, bool& sent) {
  asio::io_context io;
  asio::ip::tcp::socket socket(io);
  std::error_code ec;
  const std::string where = endpoint.host + ":" + std::to_string(endpoint.port);
  // A numeric host needs no lookup; a name's lookup (getaddrinfo) is not bounded by the timeout.
  asio::ip::tcp::resolver resolver(io);
  const auto addresses = resolver.resolve(endpoint.host, std::to_string(endpoint.port),
                                          asio::ip::resolver_base::numeric_service, ec);
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
  const auto finish = [&](std::error_code e) {
    failure = e;
    done = true;
  };
  asio::async_connect(socket, addresses, [&](std::error_code e, const auto&) {
    if (e) return finish(e);
    asio::async_write(socket, asio::buffer(request), [&](std::error_code w, std::size_t) {
      if (w) return finish(w);
      sent = true;
      asio::async_read(socket, asio::dynamic_buffer(response),
                       [&](std::error_code r, std::size_t) { finish(r == asio::error::eof ? std::error_code() : r); });
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
  return reply_body(response, where, path, error);
}

std::int64_t number(const json& value) {  // the gateway writes 64-bit integers as strings
  if (!value.is_string()) return value.is_number_integer() ? value.get<std::int64_t>() : 0;
  const std::string& text = value.get_ref<const std::string&>();
  std::int64_t n = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
  if (ec != std::errc() || end != text.data() + text.size()) throw std::invalid_argument("'" + text + "' is not an integer");
  return n;
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

static void read_answer(const std::string& path, const json& answer, EtcdResult& result);

EtcdResult EtcdGateway::call(const std::string& path, const std::string& body) const {
  EtcdResult result;
  const std::string content = post(endpoint_, path, body, timeout_s_, result.error, result.maybe_applied);
  if (result.error.empty()) result.maybe_applied = false;  // answered: the reply says what happened
  if (!result.error.empty()) return result;
  json answer = json::parse(content, nullptr, false);
  // A stream's call (lease keepalive) answers its one message as {"result": ...}.
  if (answer.is_object() && answer.contains("result") && !answer.contains("header")) answer = answer["result"];
  if (answer.is_discarded() || !answer.is_object() || !answer.contains("header")) {
    result.error = "the store answered " + path + " with no etcd reply: " + content.substr(0, 200);
    return result;
  }
  read_answer(path, answer, result);
  return result;
}

static void read_answer(const std::string& path, const json& answer, EtcdResult& result) {
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
    result.lease = number(answer.value("ID", json(0)));
    result.ttl_s = number(answer.value("TTL", json(0)));
  } catch (const std::exception& e) {
    result.error = std::string("the store's answer to ") + path + " does not read: " + e.what();
  }
}

EtcdResult EtcdGateway::put(const std::string& key, const std::string& value, std::int64_t lease) const {
  json request = {{"key", to_base64(key)}, {"value", to_base64(value)}};
  if (lease != 0) request["lease"] = std::to_string(lease);
  return call("/v3/kv/put", request.dump());
}

EtcdResult EtcdGateway::lease_grant(std::int64_t ttl_s) const {
  return call("/v3/lease/grant", json{{"TTL", std::to_string(ttl_s)}}.dump());
}

EtcdResult EtcdGateway::lease_revoke(std::int64_t lease) const {
  return call("/v3/lease/revoke", json{{"ID", std::to_string(lease)}}.dump());
}

EtcdResult EtcdGateway::lease_keepalive(std::int64_t lease) const {
  return call("/v3/lease/keepalive", json{{"ID", std::to_string(lease)}}.dump());
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
