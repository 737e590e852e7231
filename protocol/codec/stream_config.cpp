// StreamConfig factory and validation.
#include "stream_config.hpp"

#include "chunk_format.hpp"

#include <cmath>
#include <sstream>

namespace ocean::codec {

StreamConfig StreamConfig::from_profile(const Profile& profile, double patch_x_m, double patch_z_m,
                                        double gravity_mps2, double depth_m) {
  StreamConfig c;
  c.profile_id = profile.id;
  copy_profile_fields(profile, c);
  c.patch_x_m = patch_x_m;
  c.patch_z_m = patch_z_m;
  c.gravity_mps2 = gravity_mps2;
  c.depth_m = depth_m;  // 0 = deep water, as on the wire (model::wire_depth converts a scene's)
  return c;
}

int log2_of(int n) {
  int b = 0;
  while ((1 << b) < n) ++b;
  return b;
}

int StreamConfig::grid_log2() const { return log2_of(grid); }

std::vector<StreamConfig::Lattice> StreamConfig::lattices() const {
  std::vector<Lattice> out;
  std::size_t modes_at = 0, samples_at = 0;
  const auto add = [&](int n, double scale, WaveBand band) {
    out.push_back({n, patch_x_m * scale, patch_z_m * scale, band, modes_at, samples_at, false});
    modes_at += static_cast<std::size_t>(n) * (n / 2 + 1);
    samples_at += static_cast<std::size_t>(n) * n;
  };
  if (cascades.empty()) add(grid, 1.0, {});
  for (const Cascade& c : cascades) add(c.grid, static_cast<double>(c.patch_scale), c.band);
  if (has_wake()) out.push_back({wake.grid, wake.size_m, wake.size_m, {}, modes_at, samples_at, true});
  return out;
}

std::size_t StreamConfig::samples() const {
  const auto all = lattices();
  return all.back().samples_at + static_cast<std::size_t>(all.back().n) * all.back().n;
}

std::size_t StreamConfig::modes() const {
  const auto all = lattices();
  return all.back().modes_at + static_cast<std::size_t>(all.back().n) * (all.back().n / 2 + 1);
}

bool operator==(const StreamConfig& a, const StreamConfig& b) {
  return a.profile_id == b.profile_id && a.grid == b.grid && a.patch_x_m == b.patch_x_m &&
         a.patch_z_m == b.patch_z_m && a.gravity_mps2 == b.gravity_mps2 && a.depth_m == b.depth_m &&
         a.rate_hz == b.rate_hz && a.effective_tick_rate_hz() == b.effective_tick_rate_hz() && a.height_step_m == b.height_step_m && a.slope_step == b.slope_step &&
         a.disp_step_m == b.disp_step_m && a.normals == b.normals && a.choppy == b.choppy &&
         a.cascades == b.cascades && a.wake == b.wake;
}

std::string validate(const StreamConfig& c) {
  std::ostringstream m;
  auto finite_pos = [](double v) { return std::isfinite(v) && v > 0.0; };
  if (c.grid < 16 || c.grid > 256 || (c.grid & (c.grid - 1)) != 0)
    m << "grid = " << c.grid << ": must be a power of two in [16, 256]";
  else if (!finite_pos(c.patch_x_m) || c.patch_x_m > 1e6)
    m << "patch_x_m = " << c.patch_x_m << ": must be in (0, 1e6] metres";
  else if (!finite_pos(c.patch_z_m) || c.patch_z_m > 1e6)
    m << "patch_z_m = " << c.patch_z_m << ": must be in (0, 1e6] metres";
  else if (!finite_pos(c.gravity_mps2) || c.gravity_mps2 > 1000.0)
    m << "gravity_mps2 = " << c.gravity_mps2 << ": must be in (0, 1000]";
  else if (!std::isfinite(c.depth_m) || c.depth_m < 0.0)
    m << "depth_m = " << c.depth_m << ": must be finite and >= 0 (0 = deep water)";
  else if (c.rate_hz < 1 || c.rate_hz > 240)
    m << "rate_hz = " << c.rate_hz << ": must be in [1, 240]";
  else if (c.tick_rate_hz != 0 && (c.tick_rate_hz > 240 || c.tick_rate_hz < c.rate_hz))
    m << "tick_rate_hz = " << c.tick_rate_hz << ": must be 0 (= rate_hz) or in [rate_hz, 240]";
  else if (!(c.height_step_m >= 1e-4f && c.height_step_m <= 1.0f))
    m << "height_step_m = " << c.height_step_m << ": must be in [1e-4, 1]";
  else if ((c.normals || c.choppy) && !(c.slope_step >= 1e-5f && c.slope_step <= 0.5f))
    m << "slope_step = " << c.slope_step << ": must be in [1e-5, 0.5] when slopes or choppy channels are streamed";
  else if (c.choppy && !(c.disp_step_m >= 1e-4f && c.disp_step_m <= 1.0f))
    m << "disp_step_m = " << c.disp_step_m << ": must be in [1e-4, 1] when choppy channels are streamed";
  else if (c.cascades.size() > kMaxCascades)
    m << "cascades: " << c.cascades.size() << ", at most " << kMaxCascades;
  else if (!c.cascades.empty() && c.cascades[0].grid != c.grid)
    m << "grid = " << c.grid << ": must be the first cascade's, " << c.cascades[0].grid;
  for (std::size_t i = 0; i < c.cascades.size() && m.str().empty(); ++i) {
    const Cascade& cascade = c.cascades[i];
    const std::string problem = cascade_problem(cascade);
    if (!problem.empty())
      m << "cascade " << i << ": " << problem;
    else if (cascade.grid > 256)
      m << "cascade " << i << ": grid = " << cascade.grid << ": must be at most 256";
    else if (c.patch_x_m * cascade.patch_scale > 1e6 || c.patch_z_m * cascade.patch_scale > 1e6)
      m << "cascade " << i << ": its patch, " << cascade.patch_scale << " x the stream's, exceeds 1e6 metres";
  }
  if (const char* problem = c.has_wake() ? wake_problem(c.wake) : nullptr; m.str().empty() && problem)
    m << problem << " (grid " << c.wake.grid << ", size " << c.wake.size_m << " m, decay " << c.wake.decay_per_s
      << "/s, viscosity " << c.wake.viscosity_m2ps << " m^2/s)";
  return m.str();
}

}  // namespace ocean::codec
