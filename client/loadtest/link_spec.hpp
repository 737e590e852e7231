// LinkSpec: the impairments of one simulated network link, parsed from a netem-like string
// such as "rate=256kbit,delay=80ms,jitter=20ms,loss=5%,reorder=1%,dup=0.5%,queue=64kB".
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace ocean::loadtest {

struct LinkSpec {
  double rate_bps = 0.0;        // 0 = unlimited
  double delay_ms = 0.0;        // one-way base delay
  double jitter_ms = 0.0;       // delay varies uniformly in [delay - jitter, delay + jitter]
  double loss = 0.0;            // probability in [0, 1]
  double reorder = 0.0;         // probability a packet skips the FIFO order (sent with base delay only)
  double duplicate = 0.0;       // probability a packet is delivered twice
  std::uint32_t queue_bytes = 64 * 1024;  // token-bucket queue; packets beyond it are dropped (tail drop)
  // TCP's view of loss below it (tcp_view): no message is lost, but one with a lost segment
  // arrives a retransmission late (link_model.cpp), and nothing sent after it overtakes it.
  double retransmit_loss = 0.0;

  bool impaired() const {
    return rate_bps > 0 || delay_ms > 0 || jitter_ms > 0 || loss > 0 || reorder > 0 || duplicate > 0;
  }
};

struct LinkSpecResult {
  LinkSpec spec;
  std::string error;  // empty on success; otherwise names the bad field and what is allowed
};

LinkSpecResult parse_link_spec(std::string_view text);

// A rate such as "32kbit", "2mbit", "4kbps" (bytes) or a bare number of bits per second; nullopt
// when it is none of these or negative.
std::optional<double> parse_rate_bps(std::string_view text);
std::string to_string(const LinkSpec& spec);

}  // namespace ocean::loadtest
