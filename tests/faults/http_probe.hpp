// HTTP probes of the server's metrics endpoint: a blocking GET with a deadline, and reading one
// series of the Prometheus text (/metrics) by its exact name and labels.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace ocean::faults {

struct HttpReply {
  int status = 0;
  std::string body;
};

// GET http://127.0.0.1:port/path; nullopt when it does not answer within timeout_s.
std::optional<HttpReply> http_get(std::uint16_t port, const std::string& path, double timeout_s = 2.0);

// The value of `series` (e.g. `ocean_rejects_total{reason="bad_cookie"}`) in a /metrics body.
std::optional<double> metric_value(const std::string& metrics, const std::string& series);
// Sum over every series of a metric name (all label sets).
double metric_sum(const std::string& metrics, const std::string& name);
// `series` read from the server's /metrics now: 0 when absent, -1 when it does not answer.
double scrape(std::uint16_t metrics_port, const std::string& series);
// ocean_rejects_total{reason} read from the server's /metrics now, as scrape().
double rejects(std::uint16_t metrics_port, const std::string& reason);

}  // namespace ocean::faults
