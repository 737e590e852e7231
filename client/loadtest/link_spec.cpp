// Parsing of link strings; every failure names the key and the form it accepts.
#include "link_spec.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace ocean::loadtest {
namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

// Splits "80ms" into 80 and "ms"; false when there is no leading number.
bool split_number(std::string_view v, double& number, std::string_view& unit) {
  const char* first = v.data();
  const char* last = v.data() + v.size();
  auto [ptr, ec] = std::from_chars(first, last, number);
  if (ec != std::errc() || !std::isfinite(number)) return false;
  unit = std::string_view(ptr, static_cast<std::size_t>(last - ptr));
  return true;
}

struct Unit {
  std::string_view name;
  double factor;
};

bool scaled(std::string_view v, std::initializer_list<Unit> units, double& out) {
  double number = 0;
  std::string_view unit;
  if (!split_number(v, number, unit)) return false;
  for (const Unit& u : units) {
    if (u.name == unit) {
      out = number * u.factor;
      return out >= 0;
    }
  }
  return false;
}

bool percentage(std::string_view v, double& out) {
  double number = 0;
  std::string_view unit;
  if (!split_number(v, number, unit) || (unit != "%" && !unit.empty())) return false;
  out = unit == "%" ? number / 100.0 : number;
  return out >= 0 && out <= 1;
}

bool rate(std::string_view v, double& out) {
  return scaled(v, {{"bit", 1}, {"kbit", 1e3}, {"mbit", 1e6}, {"gbit", 1e9}, {"bps", 8}, {"kbps", 8e3}, {"mbps", 8e6}}, out);
}

}  // namespace

std::optional<double> parse_rate_bps(std::string_view text) {
  text = trim(text);
  double bps = 0;
  if (rate(text, bps) || scaled(text, {{"", 1}}, bps)) return bps;
  return std::nullopt;
}

LinkSpecResult parse_link_spec(std::string_view text) {
  LinkSpecResult result;
  LinkSpec& s = result.spec;
  text = trim(text);
  if (text.empty() || text == "none") return result;
  while (!text.empty()) {
    const std::size_t comma = text.find(',');
    const std::string_view item = trim(text.substr(0, comma));
    text = comma == std::string_view::npos ? std::string_view{} : text.substr(comma + 1);
    const std::size_t eq = item.find('=');
    if (eq == std::string_view::npos) {
      result.error = "link: '" + std::string(item) + "' is not key=value (keys: rate, delay, jitter, loss, reorder, dup, queue)";
      return result;
    }
    const std::string_view key = trim(item.substr(0, eq));
    const std::string_view value = trim(item.substr(eq + 1));
    bool ok = false;
    const char* allowed = "";
    if (key == "rate") {
      ok = rate(value, s.rate_bps);
      allowed = "a rate such as 256kbit, 2mbit or 32kbps (bytes), >= 0";
    } else if (key == "delay") {
      ok = scaled(value, {{"ms", 1}, {"s", 1e3}, {"us", 1e-3}}, s.delay_ms);
      allowed = "a duration such as 80ms, >= 0";
    } else if (key == "jitter") {
      ok = scaled(value, {{"ms", 1}, {"s", 1e3}, {"us", 1e-3}}, s.jitter_ms);
      allowed = "a duration such as 20ms, >= 0";
    } else if (key == "loss") {
      ok = percentage(value, s.loss);
      allowed = "a percentage in [0%, 100%]";
    } else if (key == "reorder") {
      ok = percentage(value, s.reorder);
      allowed = "a percentage in [0%, 100%]";
    } else if (key == "dup" || key == "duplicate") {
      ok = percentage(value, s.duplicate);
      allowed = "a percentage in [0%, 100%]";
    } else if (key == "queue") {
      double bytes = 0;
      ok = scaled(value, {{"B", 1}, {"", 1}, {"kB", 1024}, {"KB", 1024}, {"MB", 1024 * 1024}}, bytes) && bytes >= 1500 && bytes <= 1e9;
      s.queue_bytes = static_cast<std::uint32_t>(bytes);
      allowed = "a size such as 64kB, between 1500 B and 1 GB";
    } else {
      result.error = "link: unknown key '" + std::string(key) + "' (keys: rate, delay, jitter, loss, reorder, dup, queue)";
      return result;
    }
    if (!ok) {
      result.error = "link: " + std::string(key) + "='" + std::string(value) + "' is invalid: expected " + allowed;
      return result;
    }
  }
  if (s.jitter_ms > s.delay_ms) {
    result.error = "link: jitter (" + std::to_string(s.jitter_ms) + " ms) must not exceed delay (" + std::to_string(s.delay_ms) + " ms)";
  }
  return result;
}

std::string to_string(const LinkSpec& s) {
  char buf[200];
  std::snprintf(buf, sizeof buf, "rate=%gkbit,delay=%gms,jitter=%gms,loss=%g%%,reorder=%g%%,dup=%g%%,queue=%uB",
                s.rate_bps / 1e3, s.delay_ms, s.jitter_ms, s.loss * 100, s.reorder * 100, s.duplicate * 100, s.queue_bytes);
  return buf;
}

}  // namespace ocean::loadtest
