// The channels a frame carries: one row each, in coding order (the order of a chunk body's
// corrections, CODEC.md 6, and of synthesis, 7.2). The codec, the sim's frame, the encoder's truth
// and the load test's verdict iterate this table: their fields are a PerChannel, or, where readers
// name the fields (the sim's Frame, the decoder's ReconstructedFrame), members listed beside the
// struct in the table's order (ChannelMembers, whose length the compiler holds to the table's).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace ocean {

// Which streams carry a channel: every stream, those with normals, the choppy ones
// (Profile::normals / choppy, StreamParams on the wire).
enum class ChannelGroup : std::uint8_t { always, normals, choppy };

// What quantizes a channel (its step is the stream's height_step_m, slope_step or disp_step_m)
// and its fields' fixed point: 2^16 units a step for heights and displacement, 2^12 for slopes;
// a correction counts quarter steps.
enum class ChannelUnit : std::uint8_t { height, slope, displacement };

// How the channel's spectrum follows from the height spectrum H (CODEC.md 7.2); the factored
// kinds' real factor G is the row's (ChannelInfo::factor).
enum class ChannelKind : std::uint8_t {
  none,        // B of an odd channel out: 0
  height,      // H
  slope_x,     // i kx H
  slope_z,     // i kz H
  disp,        // -i G H
  derivative,  // G H
};

// G = sign x (lambda, the scene's choppiness, where `choppy`) x kx^gx kz^gz |k|^gk; 0 at k = 0.
struct ChannelFactor {
  std::uint8_t gx = 0, gz = 0;
  std::int8_t gk = 0;
  bool choppy = false;
  std::int8_t sign = 1;
};

struct ChannelInfo {
  std::string_view name;  // as reports, recordings (.npy) and errors name it
  ChannelGroup group;
  ChannelUnit unit;
  ChannelKind kind;
  ChannelFactor factor = {};  // disp and derivative
};

constexpr bool factored(const ChannelInfo& c) {
  return c.kind == ChannelKind::disp || c.kind == ChannelKind::derivative;
}

// The displacement D = -i lambda k/|k| H (Tessendorf's choppy waves) and its derivatives
// dDx/dx = lambda kx^2/|k| H, ...: the inputs of the Jacobian.
constexpr ChannelFactor displacement_factor(std::uint8_t gx, std::uint8_t gz) { return {gx, gz, -1, true, 1}; }

inline constexpr ChannelInfo kChannels[] = {
    {"height", ChannelGroup::always, ChannelUnit::height, ChannelKind::height},
    {"slope_x", ChannelGroup::normals, ChannelUnit::slope, ChannelKind::slope_x},
    {"slope_z", ChannelGroup::normals, ChannelUnit::slope, ChannelKind::slope_z},
    {"disp_x", ChannelGroup::choppy, ChannelUnit::displacement, ChannelKind::disp, displacement_factor(1, 0)},
    {"disp_z", ChannelGroup::choppy, ChannelUnit::displacement, ChannelKind::disp, displacement_factor(0, 1)},
    {"disp_xx", ChannelGroup::choppy, ChannelUnit::slope, ChannelKind::derivative, displacement_factor(2, 0)},
    {"disp_zz", ChannelGroup::choppy, ChannelUnit::slope, ChannelKind::derivative, displacement_factor(0, 2)},
    {"disp_xz", ChannelGroup::choppy, ChannelUnit::slope, ChannelKind::derivative, displacement_factor(1, 1)},
};
inline constexpr int kChannelCount = static_cast<int>(std::size(kChannels));

// G of a row at (kx, kz) with |k| = k and inv_k = 1 / |k| (0 at k = 0), as the sim evaluates it:
// the products taken left to right from lambda, which the wake's frames' bits depend on. (The
// codec's own order is CODEC.md 7.2's: ModalModel.)
template <typename T>
T channel_factor(const ChannelFactor& f, T lambda, T kx, T kz, T k, T inv_k) {
  T g = f.choppy ? lambda : T(1);
  for (int i = 0; i < f.gx; ++i) g *= kx;
  for (int i = 0; i < f.gz; ++i) g *= kz;
  for (int i = 0; i < f.gk; ++i) g *= k;
  for (int i = 0; i > f.gk; --i) g *= inv_k;
  return f.sign < 0 ? -g : g;
}

// The table's rows by name, in its order.
enum class ChannelId : std::uint8_t { height, slope_x, slope_z, disp_x, disp_z, disp_xx, disp_zz, disp_xz };
constexpr int index_of(ChannelId c) { return static_cast<int>(c); }
static_assert(kChannels[index_of(ChannelId::disp_xz)].name == "disp_xz" && kChannelCount == 8,
              "ChannelId lists kChannels' rows in order");

// Whether a stream with these flags carries the channel.
constexpr bool carried(const ChannelInfo& c, bool normals, bool choppy) {
  return c.group == ChannelGroup::always || (c.group == ChannelGroup::normals && normals) ||
         (c.group == ChannelGroup::choppy && choppy);
}

// One T per channel, in the table's order.
template <typename T>
struct PerChannel {
  std::array<T, kChannelCount> by_index{};
  T& operator[](int c) { return by_index[static_cast<std::size_t>(c)]; }
  const T& operator[](int c) const { return by_index[static_cast<std::size_t>(c)]; }
  T& operator[](ChannelId c) { return (*this)[index_of(c)]; }
  const T& operator[](ChannelId c) const { return (*this)[index_of(c)]; }
  auto begin() { return by_index.begin(); }
  auto end() { return by_index.end(); }
  auto begin() const { return by_index.begin(); }
  auto end() const { return by_index.end(); }
  bool operator==(const PerChannel&) const = default;
};

// The quantization step of a channel's unit in a stream (a Profile, codec::StreamConfig or the
// wire's StreamParams: they name their steps alike).
template <typename Stream>
double step_of(const Stream& s, ChannelUnit unit) {
  switch (unit) {
    case ChannelUnit::height: return static_cast<double>(s.height_step_m);
    case ChannelUnit::slope: return static_cast<double>(s.slope_step);
    case ChannelUnit::displacement: return static_cast<double>(s.disp_step_m);
  }
  return static_cast<double>(s.height_step_m);
}

// Who carries a group's channels, for messages: "<carrier> carries it".
constexpr std::string_view carrier(ChannelGroup g) {
  return g == ChannelGroup::always    ? "every stream"
         : g == ChannelGroup::normals ? "a stream with normals"
                                      : "a choppy stream (displacement and its derivatives)";
}

// A struct's members, one per channel, in the table's order (for the structs whose readers name
// their fields: the sim's frame, the decoder's output).
template <typename S, typename Field>
using ChannelMembers = std::array<Field S::*, kChannelCount>;

}  // namespace ocean
