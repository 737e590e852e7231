#include "client_links.hpp"

#include <limits>
#include <memory>

#include "link_model.hpp"

namespace ocean::loadtest {

LinkSpec tcp_view(const LinkSpec& spec, bool loss_as_delay) {
  LinkSpec t;
  t.rate_bps = spec.rate_bps;
  t.delay_ms = spec.delay_ms;
  t.queue_bytes = std::numeric_limits<std::uint32_t>::max();
  if (loss_as_delay) t.retransmit_loss = spec.loss;
  return t;
}

client::ConnectionLinks make_client_links(const LinkSpec& spec, std::uint64_t seed, bool stream_only) {
  client::ConnectionLinks links;
  if (!spec.impaired()) return links;
  std::shared_ptr<Bottleneck> down, up;
  if (spec.rate_bps > 0) {
    down = std::make_shared<Bottleneck>(spec.rate_bps);
    up = std::make_shared<Bottleneck>(spec.rate_bps);
  }
  using Adapter = client::PacketLinkAdapter<LinkModel>;
  links.udp_down = std::make_unique<Adapter>(spec, seed * 4 + 0, down);
  links.udp_up = std::make_unique<Adapter>(spec, seed * 4 + 1, up);
  links.tcp_down = std::make_unique<Adapter>(tcp_view(spec, stream_only), seed * 4 + 2, down);
  links.tcp_up = std::make_unique<Adapter>(tcp_view(spec, stream_only), seed * 4 + 3, up);
  return links;
}

}  // namespace ocean::loadtest
