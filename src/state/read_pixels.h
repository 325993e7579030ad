// glReadPixels' validation and packing (GL 2.1 sections 4.3.2 and 3.6), as Mesa 22.3 does them
// (main/readpix.c, main/format_utils.h, the generated format_pack.c) for an RGBA8 colour buffer
// and a 24-bit depth buffer with no stencil buffer.
#pragma once
#include <GL/gl.h>

#include "raster/raster.h"

namespace ffc::state {

// The GL_PACK_* values glReadPixels honours. GL_PACK_LSB_FIRST applies to GL_BITMAP data only,
// which glReadPixels cannot return here (GL_COLOR_INDEX and GL_STENCIL_INDEX are errors), and
// GL_PACK_IMAGE_HEIGHT / GL_PACK_SKIP_IMAGES to 3D images only.
struct PackState {
  int alignment = 4, row_length = 0, skip_rows = 0, skip_pixels = 0;
  bool swap_bytes = false;
};

// The error glReadPixels records for this format and type (after the size check), or
// GL_NO_ERROR where it reads.
GLenum read_pixels_error(GLenum format, GLenum type);

// Packs the framebuffer's rectangle (x, y, w, h) (GL's window coordinates, y up) into `out`;
// pixels outside the framebuffer are left untouched. The format and type must be readable.
void pack_pixels(const raster::Framebuffer& fb, int x, int y, int w, int h, GLenum format, GLenum type,
                 const PackState& pack, void* out);

}  // namespace ffc::state
