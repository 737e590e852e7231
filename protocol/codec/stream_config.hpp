// StreamConfig: what a codec stream is (grid, patch, physics, rate, quantization steps, channels),
// mirroring the server's Welcome.StreamParams. Encoder and decoder must be built from equal values.
#pragma once

#include "common/cascade.hpp"
#include "common/channels.hpp"
#include "common/wake_lattice.hpp"
#include "profile.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace ocean::codec {

inline constexpr std::size_t kMaxCascades = 4;


// L of a power of two n = 2^L (a lattice's side).
int log2_of(int n);

struct StreamConfig {
  std::uint8_t profile_id = 1;
  std::uint16_t grid = 64;       // grid x grid samples, power of two in [16, 256]
  double patch_x_m = 256.0;      // patch extent along x (columns), > 0
  double patch_z_m = 256.0;      // along z (rows), > 0
  double gravity_mps2 = 9.81;    // > 0
  double depth_m = 0.0;          // water depth; 0 = deep water
  std::uint16_t rate_hz = 30;    // frames per second, 1..240
  // Server ticks per second, the unit of StateId / chunk tick numbers; 0 = rate_hz (every tick is
  // a frame). A stream at a lower rate than its server carries every (tick_rate_hz / rate_hz)-th
  // tick, and a delta still advances the state by (tick - baseline) steps of 1 / tick_rate_hz.
  std::uint16_t tick_rate_hz = 0;
  float height_step_m = 0.01f;   // height error bound is step / 2; in [1e-4, 1] m
  float slope_step = 1.0f / 256; // slope error bound is step / 2 (normals only); in [1e-5, 0.5]
  float disp_step_m = 0.01f;     // displacement error bound is step / 2 (choppy only); in [1e-4, 1]
  bool normals = true;           // stream slopes dh/dx, dh/dz
  // Stream the horizontal displacement and its derivatives (the Jacobian's inputs, bounded by
  // slope_step / 2): codec version 3.
  bool choppy = false;
  // The stream's lattices (codec version 5, CODEC.md 7.8): empty for one, `grid` samples over the
  // patch above with every wave; else each cascade's, over the patch above times its scale, with
  // `grid` the first cascade's. A stream's state, fields and items are its lattices' in this order.
  std::vector<Cascade> cascades;
  // After the sea's lattices, when wake.grid != 0 (codec version 6).
  WakeLattice wake;

  // One lattice as the codec uses it.
  struct Lattice {
    int n;
    double patch_x_m, patch_z_m;
    WaveBand band;
    std::size_t modes_at;    // where its half spectrum starts in the stream's
    std::size_t samples_at;  // where its samples start in the stream's fields
    bool wake = false;       // the wake lattice: starts at rest, damped, corrected as forced
  };
  bool has_wake() const { return wake.grid != 0; }
  std::vector<Lattice> lattices() const;
  std::size_t samples() const;  // every lattice's n^2
  std::size_t modes() const;    // every lattice's n (n/2 + 1)

  // The profile's grid/rate/steps/channels with the scene's patch and physics.
  // depth_m as on the wire: 0 for deep water (model::wire_depth converts a scene's infinity).
  static StreamConfig from_profile(const Profile& profile, double patch_x_m, double patch_z_m,
                                   double gravity_mps2, double depth_m);

  int grid_log2() const;
  std::uint16_t effective_tick_rate_hz() const { return tick_rate_hz != 0 ? tick_rate_hz : rate_hz; }
  double dt_s() const { return 1.0 / effective_tick_rate_hz(); }  // one tick step
};

bool operator==(const StreamConfig& a, const StreamConfig& b);

// Whether the stream carries the channel.
inline bool carries(const StreamConfig& config, const ChannelInfo& channel) {
  return carried(channel, config.normals, config.choppy);
}

// The fields a profile fixes, under the same names in Profile, StreamConfig and the wire's
// StreamParams: one list for every copy between them.
template <typename From, typename To>
void copy_profile_fields(const From& from, To& to) {
  to.grid = from.grid;
  to.rate_hz = from.rate_hz;
  to.height_step_m = from.height_step_m;
  to.slope_step = from.slope_step;
  to.disp_step_m = from.disp_step_m;
  to.normals = from.normals;
  to.choppy = from.choppy;
  to.cascades.assign(from.cascades.begin(), from.cascades.end());
}

// Empty if usable, else a message naming the first bad field, its value and the allowed range.
std::string validate(const StreamConfig& config);

}  // namespace ocean::codec
