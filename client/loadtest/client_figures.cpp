#include "client_figures.hpp"

#include <algorithm>

namespace ocean::loadtest {

void ConnectionParts::add(const ClientConnectionFacts& c) {
  if (c.ttff_s) ttff_s.add(*c.ttff_s);
  else ++clients_without_frame;
  if (c.peak_kbps) peak_kbps.add(*c.peak_kbps);
  if (c.calm_kbps) calm_kbps.add(*c.calm_kbps);
  startup_peak_kbps = std::max(startup_peak_kbps, c.startup_peak_kbps);
}

void ConnectionParts::merge(const ConnectionParts& o) {
  ttff_s.merge(o.ttff_s);
  peak_kbps.merge(o.peak_kbps);
  calm_kbps.merge(o.calm_kbps);
  startup_peak_kbps = std::max(startup_peak_kbps, o.startup_peak_kbps);
  clients_without_frame += o.clients_without_frame;
}

ConnectionFigures ConnectionParts::figures() const {
  ConnectionFigures f;
  f.clients_without_frame = clients_without_frame;
  f.kbps_peak_1s_startup = startup_peak_kbps;
  if (ttff_s.count()) {
    f.ttff_max_s = ttff_s.max();
    f.ttff_p50_s = ttff_s.percentile(50);
  }
  if (peak_kbps.count()) {
    f.kbps_peak_1s = peak_kbps.max();
    f.kbps_peak_1s_p50 = peak_kbps.percentile(50);
  }
  if (calm_kbps.count()) f.kbps_calm = calm_kbps.percentile(50);
  return f;
}

ConnectionFigures connection_figures(std::span<const ClientConnectionFacts> clients) {
  ConnectionParts parts;
  for (const ClientConnectionFacts& c : clients) parts.add(c);
  return parts.figures();
}

}  // namespace ocean::loadtest
