#include "timeline_log.hpp"

#include <algorithm>
#include <chrono>
#include <charconv>
#include <cstdio>
#include <random>
#include <thread>

namespace ocean::server {
namespace {

constexpr int kAppendAttempts = 16;  // each lost to a replica that appended first, then caught up

// N from "<head><N as 20 digits>"; false for any other key.
bool parse_index(const std::string& key, const std::string& head, std::uint64_t& index) {
  if (key.size() != head.size() + 20 || key.compare(0, head.size(), head) != 0) return false;
  const auto [end, ec] = std::from_chars(key.data() + head.size(), key.data() + key.size(), index);
  return ec == std::errc() && end == key.data() + key.size();
}

}  // namespace

std::optional<TimelineAddress> parse_timeline_url(std::string_view url, std::string& error) {
  constexpr std::string_view scheme = "etcd://";
  if (url.substr(0, scheme.size()) != scheme) {
    error = "'" + std::string(url) + "' is not etcd://HOST:PORT/PREFIX";
    return std::nullopt;
  }
  const std::string_view rest = url.substr(scheme.size());
  const std::size_t slash = rest.find('/');
  const std::string_view authority = rest.substr(0, slash);
  TimelineAddress address;
  address.prefix = slash == std::string_view::npos ? "" : std::string(rest.substr(slash));
  while (!address.prefix.empty() && address.prefix.back() == '/') address.prefix.pop_back();
  if (address.prefix.empty()) {
    error = "'" + std::string(url) + "' names no key prefix (etcd://HOST:PORT/PREFIX, e.g. /ocean/harbour-1)";
    return std::nullopt;
  }
  const std::size_t colon = authority.rfind(':');
  address.store.host = std::string(authority.substr(0, colon));
  if (colon != std::string_view::npos) {
    const std::string_view port = authority.substr(colon + 1);
    unsigned value = 0;
    const auto [end, ec] = std::from_chars(port.data(), port.data() + port.size(), value);
    if (ec != std::errc() || end != port.data() + port.size() || value == 0 || value > 65535) {
      error = "'" + std::string(url) + "' has no port 1..65535 after its host";
      return std::nullopt;
    }
    address.store.port = static_cast<std::uint16_t>(value);
  }
  if (address.store.host.empty()) {
    error = "'" + std::string(url) + "' names no host";
    return std::nullopt;
  }
  return address;
}

static std::string digits20(std::uint64_t index) {
  char digits[24];
  std::snprintf(digits, sizeof digits, "%020llu", static_cast<unsigned long long>(index));
  return digits;
}

std::string TimelineLog::key(std::uint64_t index) const { return address_.prefix + "/log/" + digits20(index); }

EtcdResult TimelineLog::acknowledge(std::uint64_t origin, std::uint64_t index, std::int64_t lease) const {
  return store_.put(address_.prefix + "/acks/" + digits20(origin), std::to_string(index), lease);
}

TimelineLog::Acks TimelineLog::acks() const {
  Acks acks;
  const std::string head = address_.prefix + "/acks/";
  const EtcdResult range = store_.range(head, address_.prefix + "/acks0", 0);
  acks.error = range.error;
  for (const EtcdKeyValue& kv : range.kvs) {
    std::uint64_t origin = 0, read = 0;
    const auto [end, ec] = std::from_chars(kv.value.data(), kv.value.data() + kv.value.size(), read);
    if (!parse_index(kv.key, head, origin) || ec != std::errc() || end != kv.value.data() + kv.value.size()) {
      acks.error = "the log at " + address_.prefix + " holds an acknowledgement that does not read: " + kv.key;
      return acks;
    }
    acks.read.emplace_back(origin, read);
  }
  return acks;
}

namespace {
std::string decision_bytes(const TimelineLog::Decision& d) { return d.commit ? "commit" : "abort " + d.reason; }
bool parse_decision(const std::string& bytes, TimelineLog::Decision& d) {
  d.commit = bytes == "commit";
  if (!d.commit && bytes.compare(0, 6, "abort ") != 0) return false;
  d.reason = d.commit ? "" : bytes.substr(6);
  return true;
}
}  // namespace

std::string TimelineLog::decide(const Decision& decision, Decision& decided) const {
  const std::string key = address_.prefix + "/decided/" + digits20(decision.index);
  const EtcdResult put = store_.put_if_absent(key, decision_bytes(decision));
  if (!put.error.empty()) return put.error;
  decided = decision;
  if (put.succeeded) return {};
  const EtcdResult stands = store_.range(key, key + '\0', 1);  // decided by another replica first
  if (!stands.error.empty()) return stands.error;
  if (stands.kvs.empty() || !parse_decision(stands.kvs.front().value, decided))
    return "the decision on entry " + std::to_string(decision.index) + " does not read";
  return {};
}

TimelineLog::Decisions TimelineLog::decisions_from(std::uint64_t from, std::size_t max) const {
  Decisions out;
  const std::string head = address_.prefix + "/decided/";
  const EtcdResult range = store_.range(head + digits20(from), address_.prefix + "/decided0", static_cast<std::int64_t>(max));
  out.error = range.error;
  for (const EtcdKeyValue& kv : range.kvs) {
    Decision d;
    if (!parse_index(kv.key, head, d.index) || !parse_decision(kv.value, d)) {
      out.error = "the log at " + address_.prefix + " holds a decision that does not read: " + kv.key;
      return out;
    }
    out.decided.push_back(std::move(d));
  }
  return out;
}

TimelineLog::Appended TimelineLog::append(const std::string& bytes) {
  thread_local std::minstd_rand jitter{std::random_device{}()};
  for (int attempt = 0; attempt < kAppendAttempts; ++attempt) {
    if (attempt > 0) {
      // Taken: another replica appended there. A few milliseconds at random (replicas that keep
      // colliding fall out of step), then after the log's last entry as it is now.
      std::this_thread::sleep_for(std::chrono::microseconds(1000 + jitter() % (4000u << std::min(attempt, 3))));
      const EtcdResult last = store_.range(key(next_), address_.prefix + "/log0", 1, true);
      if (!last.error.empty()) return {last.error, 0};
      std::uint64_t index = 0;
      if (last.kvs.empty() || !parse_index(last.kvs.front().key, address_.prefix + "/log/", index))
        return {"the log at " + address_.prefix + " holds a key that is not an entry's", 0};
      next_ = index + 1;
    }
    const EtcdResult put = store_.put_if_absent(key(next_), bytes);
    if (!put.error.empty() && put.maybe_applied)
      return {"the append's outcome is unknown (it may have been written at " + std::to_string(next_) + "): " + put.error, 0};
    if (!put.error.empty()) return {put.error, 0};
    if (put.succeeded) return {"", next_++};
  }
  return {"the log at " + address_.prefix + " kept growing under " + std::to_string(kAppendAttempts) +
              " attempts to append (too many replicas appending at once)",
          0};
}

TimelineLog::Read TimelineLog::read_from(std::uint64_t from, std::size_t max) const {
  Read read;
  if (max == 0) return read;  // etcd's limit 0 would mean no limit
  const EtcdResult range = store_.range(key(from), address_.prefix + "/log0", static_cast<std::int64_t>(max));
  if (!range.error.empty()) {
    read.error = range.error;
    return read;
  }
  const std::string head = address_.prefix + "/log/";
  for (const EtcdKeyValue& kv : range.kvs) {
    std::uint64_t index = 0;
    if (!parse_index(kv.key, head, index)) {
      read.error = "the log at " + address_.prefix + " holds a key that is not an entry's: " + kv.key;
      return read;
    }
    read.entries.push_back({index, kv.value});
  }
  return read;
}

}  // namespace ocean::server
