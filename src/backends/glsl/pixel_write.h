// glDrawPixels and glBitmap on the GLSL backend: soft draws them into its own framebuffer, given
// the core context's colour and depth first (read_depth, Renderer::read_back), and the result is
// written back here: both buffers as textures, one full-window triangle whose fragment shader
// copies each texel's colour and depth (gl_FragDepth), with blending, scissor, culling and offset
// off and the depth test passing always. The renderer sets its own state again at each draw.
#pragma once
#include <cstdint>

#include "backends/glsl/gl_core.h"

namespace ffc::glsl {

// The depth buffer as 24-bit values, GL's rows (the bottom one first).
void read_depth(const CoreGl& gl, uint32_t* depth, int width, int height);

class PixelWriter {
 public:
  // RGBA8 and 24-bit depth, GL's rows.
  void write(const CoreGl& gl, const uint8_t* rgba, const uint32_t* depth, int width, int height);
  void destroy(const CoreGl& gl);

 private:
  GLuint program_ = 0, vao_ = 0, textures_[2] = {0, 0};
};

}  // namespace ffc::glsl
