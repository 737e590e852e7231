// The tick file has NpyWriter's layout: a fixed 128-byte header, so the length can be patched.
#include "frame_recorder.hpp"

#include <array>
#include <algorithm>
#include <bit>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace ocean::client {
TickNpyWriter::TickNpyWriter(const std::string& path) : path_(path) {
  file_ = std::fopen(path.c_str(), "wb");
  if (!file_) throw std::runtime_error("cannot open " + path + " for writing");
  write_header();
}

TickNpyWriter::~TickNpyWriter() {
  try {
    close();
  } catch (...) {
  }
}

void TickNpyWriter::write_header() { write_npy_header(file_, path_, "<i8", "(" + std::to_string(count_) + ",)"); }

void TickNpyWriter::append(std::int64_t value) {
  if (!file_) throw std::runtime_error(path_ + " is closed");
  std::uint8_t le[8];
  const auto u = std::bit_cast<std::uint64_t>(value);
  for (int b = 0; b < 8; ++b) le[b] = static_cast<std::uint8_t>(u >> (8 * b));
  if (std::fseek(file_, 0, SEEK_END) != 0 || std::fwrite(le, 1, 8, file_) != 8)
    throw std::runtime_error("write failed on " + path_);
  ++count_;
}

void TickNpyWriter::close() {
  if (!file_) return;
  std::FILE* f = file_;
  write_header();
  file_ = nullptr;
  if (std::fclose(f) != 0) throw std::runtime_error("closing " + path_ + " failed");
}

std::string ticks_path_for(const std::string& heights_path) {
  const std::string ext = ".npy";
  if (heights_path.size() > ext.size() && heights_path.compare(heights_path.size() - ext.size(), ext.size(), ext) == 0)
    return heights_path.substr(0, heights_path.size() - ext.size()) + ".ticks.npy";
  return heights_path + ".ticks.npy";
}

namespace {

// Every field a ReconstructedFrame may carry (its channels, then the Jacobian), as the recording
// names its file.
struct ChannelField {
  std::string_view name;
  std::vector<float> codec::ReconstructedFrame::*field;
};
constexpr auto kRecordedFields = [] {
  std::array<ChannelField, kChannelCount + 1> all{};
  for (std::size_t ch = 0; ch < kChannelCount; ++ch) all[ch] = {kChannels[ch].name, codec::kReconstructedChannels[ch]};
  all[kChannelCount] = {"jacobian", &codec::ReconstructedFrame::jacobian};
  return all;
}();

// "run.npy" + "height" -> "run.height.npy".
std::string beside(const std::string& path, const std::string& what) {
  const std::string ticks = ticks_path_for(path);
  return ticks.substr(0, ticks.size() - std::string("ticks.npy").size()) + what + ".npy";
}

}  // namespace

struct FrameRecorder::Channel {
  std::vector<float> codec::ReconstructedFrame::*field;
  NpyWriter writer;
};

std::vector<int> stream_lattices(const protocol::StreamParams& stream) {
  std::vector<int> sizes;
  if (stream.cascades.empty()) sizes.push_back(stream.grid);
  for (const Cascade& c : stream.cascades) sizes.push_back(c.grid);
  if (stream.wake.grid != 0) sizes.push_back(stream.wake.grid);  // CODEC.md 10: the wake lattice last
  return sizes;
}

FrameRecorder::FrameRecorder(std::string heights_path) : path_(std::move(heights_path)) {}
FrameRecorder::~FrameRecorder() = default;

void FrameRecorder::open(std::span<const int> lattices, const codec::ReconstructedFrame& frame) {
  lattices_.assign(lattices.begin(), lattices.end());
  std::size_t samples = 0;
  for (const int n : lattices_) samples += static_cast<std::size_t>(n) * n;
  heights_.emplace(path_, lattices_.front(), lattices_.front());
  ticks_.emplace(ticks_path_for(path_));
  baselines_.emplace(beside(path_, "baselines"));
  TickNpyWriter sizes(beside(path_, "lattices"));
  for (const int n : lattices_) sizes.append(n);
  sizes.close();
  for (const ChannelField& c : kRecordedFields)
    if ((frame.*c.field).size() == samples)
      channels_.push_back(std::unique_ptr<Channel>(
          new Channel{c.field, NpyWriter(beside(path_, std::string(c.name)), 1, static_cast<int>(samples))}));
}

bool FrameRecorder::append(std::int64_t tick, std::span<const int> lattices, const codec::ReconstructedFrame& frame) {
  if (lattices.empty()) return false;
  if (!heights_) open(lattices, frame);
  if (!std::equal(lattices.begin(), lattices.end(), lattices_.begin(), lattices_.end())) return false;
  const auto first = static_cast<std::size_t>(lattices_.front()) * lattices_.front();
  if (frame.height.size() < first) return false;
  for (const auto& c : channels_)
    if ((frame.*c->field).size() != static_cast<std::size_t>(c->writer.cols())) return false;
  heights_->append(std::span<const float>(frame.height).first(first));
  ticks_->append(tick);
  baselines_->append(static_cast<std::int64_t>(frame.baseline));
  for (const auto& c : channels_) c->writer.append(frame.*c->field);
  return true;
}

void FrameRecorder::close() {
  if (heights_) heights_->close();
  if (ticks_) ticks_->close();
  if (baselines_) baselines_->close();
  for (const auto& c : channels_) c->writer.close();
}

}  // namespace ocean::client
