// The sky faces as a GL cube-map texture (bilinear, no mipmaps: the sky is smooth and a
// software rasteriser pays for every extra texel fetch).
#pragma once

#include <GLES2/gl2.h>

#include "client/render/sky_faces.hpp"

namespace ocean::render {

GLuint create_sky_texture(const SkyFaces& faces);

}  // namespace ocean::render
