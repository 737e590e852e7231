#include "client/render/channel_upload.hpp"

namespace ocean::render {

bool upload_channels(Renderer& renderer, const client::FrameChannels& f, std::size_t samples, FoamMemory& foam,
                     double dt_s) {
  const bool slopes = f.slope_x.size() == samples && f.slope_z.size() == samples;
  const bool choppy = f.disp_x.size() == samples && f.disp_z.size() == samples && f.jacobian.size() == samples;
  const float* jacobian = choppy ? foam.update(f.jacobian, dt_s).data() : nullptr;
  return renderer.upload_frame(f.height.data(), slopes ? f.slope_x.data() : nullptr, slopes ? f.slope_z.data() : nullptr,
                               choppy ? f.disp_x.data() : nullptr, choppy ? f.disp_z.data() : nullptr, jacobian);
}

}  // namespace ocean::render
