// glGet's values for the state of OpenGL 2.1 that this pipeline does not model (texture
// environment, stencil, accumulation, pixel transfer and maps, evaluators, selection, hints,
// implementation limits, the buffers' configuration), reported as Mesa 22.3's compatibility
// context (llvmpipe through OSMesa, RGBA8 with a 24-bit depth buffer and no stencil) reports them
// in its default state, so that every glGet name of GL <= 2.1 that Mesa answers has an answer
// here; plus the values derived from modelled state that get.cpp's switch does not list (the
// transposed matrices, the scissor box).
//
// The names are Mesa's main/get_hash_params.py entries that its compatibility API offers and
// whose enums belong to GL 1.0 to 2.1; the values are what Mesa returned (tests/state/
// get_table_test.cpp compares every one of them, through the four glGet functions). Names that
// belong to other work in progress (GL_POINT_*) are not here yet; fog and polygon offset are
// real state (fog.cpp).
#include <algorithm>
#include <glm/gtc/type_ptr.hpp>

#include "state/context.h"

namespace ffc::state {
namespace {

// How glGetIntegerv converts (get.c): Rounded to the nearest integer (IROUND); Normalized maps a
// float's [-1, 1] onto the integer range (FLOAT_TO_INT), as Mesa does for its TYPE_FLOATN values
// (colours, the alpha reference value).
enum Conv : unsigned char { Rounded, Normalized };

struct Constant {
  GLenum name;
  Conv conv;
  unsigned char count;
  double values[12];
};

constexpr double kTenth = double(0.1f);  // Mesa keeps its granularities as floats

// In the order of the enums' values.
constexpr Constant kConstants[] = {
    {GL_INDEX_ARRAY_TYPE, Rounded, 1, {GL_FLOAT}},
    {GL_INDEX_ARRAY_STRIDE, Rounded, 1, {0}},
    {GL_TEXTURE_COORD_ARRAY_SIZE, Rounded, 1, {4}},
    {GL_TEXTURE_COORD_ARRAY_TYPE, Rounded, 1, {GL_FLOAT}},
    {GL_TEXTURE_COORD_ARRAY_STRIDE, Rounded, 1, {0}},
    {GL_EDGE_FLAG_ARRAY_STRIDE, Rounded, 1, {0}},
    {GL_LINE_STIPPLE_PATTERN, Rounded, 1, {65535}},
    {GL_LINE_STIPPLE_REPEAT, Rounded, 1, {1}},
    {GL_LINE_WIDTH_GRANULARITY, Rounded, 1, {kTenth}},
    {GL_LINE_WIDTH_RANGE, Rounded, 2, {1, 255}},
    {GL_POLYGON_MODE, Rounded, 2, {GL_FILL, GL_FILL}},
    {GL_EDGE_FLAG, Rounded, 1, {1}},
    {GL_LIST_BASE, Rounded, 1, {0}},
    {GL_LIST_INDEX, Rounded, 1, {0}},
    {GL_LIST_MODE, Rounded, 1, {0}},
    {GL_DEPTH_WRITEMASK, Rounded, 1, {1}},
    {GL_ACCUM_RED_BITS, Rounded, 1, {0}},
    {GL_ACCUM_GREEN_BITS, Rounded, 1, {0}},
    {GL_ACCUM_BLUE_BITS, Rounded, 1, {0}},
    {GL_ACCUM_ALPHA_BITS, Rounded, 1, {0}},
    {GL_ACCUM_CLEAR_VALUE, Normalized, 4, {0, 0, 0, 0}},
    {GL_ALPHA_TEST_REF, Normalized, 1, {0}},
    {GL_ALPHA_TEST_FUNC, Rounded, 1, {GL_ALWAYS}},
    {GL_BLEND_SRC, Rounded, 1, {GL_ONE}},
    {GL_BLEND_DST, Rounded, 1, {GL_ZERO}},
    {GL_SELECTION_BUFFER_SIZE, Rounded, 1, {0}},
    {GL_LOGIC_OP_MODE, Rounded, 1, {GL_COPY}},
    {GL_STENCIL_BITS, Rounded, 1, {0}},
    {GL_STENCIL_CLEAR_VALUE, Rounded, 1, {0}},
    {GL_STENCIL_FUNC, Rounded, 1, {GL_ALWAYS}},
    // Mesa keeps the stencil masks in 8 bits, with no stencil buffer at all (GL 2.1's state tables
    // give all 1's, which a GLint reads as -1).
    {GL_STENCIL_VALUE_MASK, Rounded, 1, {255}},
    {GL_STENCIL_FAIL, Rounded, 1, {GL_KEEP}},
    {GL_STENCIL_PASS_DEPTH_FAIL, Rounded, 1, {GL_KEEP}},
    {GL_STENCIL_PASS_DEPTH_PASS, Rounded, 1, {GL_KEEP}},
    {GL_STENCIL_REF, Rounded, 1, {0}},
    {GL_STENCIL_WRITEMASK, Rounded, 1, {255}},
    {GL_INDEX_BITS, Rounded, 1, {0}},
    {GL_SUBPIXEL_BITS, Rounded, 1, {8}},
    {GL_AUX_BUFFERS, Rounded, 1, {0}},
    {GL_READ_BUFFER, Rounded, 1, {GL_FRONT}},
    {GL_DRAW_BUFFER, Rounded, 1, {GL_FRONT}},
    {GL_DOUBLEBUFFER, Rounded, 1, {0}},
    {GL_STEREO, Rounded, 1, {0}},
    {GL_MAX_LIST_NESTING, Rounded, 1, {64}},
    {GL_MAX_EVAL_ORDER, Rounded, 1, {30}},
    {GL_MAX_CLIP_PLANES, Rounded, 1, {8}},
    {GL_MAX_TEXTURE_SIZE, Rounded, 1, {16384}},
    {GL_MAX_PIXEL_MAP_TABLE, Rounded, 1, {256}},
    {GL_MAX_ATTRIB_STACK_DEPTH, Rounded, 1, {16}},
    {GL_MAX_NAME_STACK_DEPTH, Rounded, 1, {64}},
    {GL_MAX_VIEWPORT_DIMS, Rounded, 2, {16384, 16384}},  // as Context::Viewport clamps
    {GL_MAX_CLIENT_ATTRIB_STACK_DEPTH, Rounded, 1, {16}},
    {GL_ATTRIB_STACK_DEPTH, Rounded, 1, {0}},
    {GL_CLIENT_ATTRIB_STACK_DEPTH, Rounded, 1, {0}},
    {GL_COLOR_WRITEMASK, Rounded, 4, {1, 1, 1, 1}},
    {GL_CURRENT_INDEX, Rounded, 1, {1}},
    {GL_CURRENT_RASTER_COLOR, Normalized, 4, {1, 1, 1, 1}},
    {GL_CURRENT_RASTER_DISTANCE, Rounded, 1, {0}},
    {GL_CURRENT_RASTER_INDEX, Rounded, 1, {1}},
    {GL_CURRENT_RASTER_POSITION, Rounded, 4, {0, 0, 0, 1}},
    {GL_CURRENT_RASTER_TEXTURE_COORDS, Rounded, 4, {0, 0, 0, 1}},
    {GL_CURRENT_RASTER_POSITION_VALID, Rounded, 1, {1}},
    {GL_CURRENT_TEXTURE_COORDS, Rounded, 4, {0, 0, 0, 1}},
    {GL_INDEX_CLEAR_VALUE, Rounded, 1, {0}},
    {GL_INDEX_MODE, Rounded, 1, {0}},
    {GL_INDEX_WRITEMASK, Rounded, 1, {-1}},
    {GL_NAME_STACK_DEPTH, Rounded, 1, {0}},
    {GL_RGBA_MODE, Rounded, 1, {1}},
    {GL_MAP1_GRID_DOMAIN, Rounded, 2, {0, 1}},
    {GL_MAP1_GRID_SEGMENTS, Rounded, 1, {1}},
    {GL_MAP2_GRID_DOMAIN, Rounded, 4, {0, 1, 0, 1}},
    {GL_MAP2_GRID_SEGMENTS, Rounded, 2, {1, 1}},
    {GL_PERSPECTIVE_CORRECTION_HINT, Rounded, 1, {GL_DONT_CARE}},
    {GL_LINE_SMOOTH_HINT, Rounded, 1, {GL_DONT_CARE}},
    {GL_POLYGON_SMOOTH_HINT, Rounded, 1, {GL_DONT_CARE}},
    {GL_MAP_COLOR, Rounded, 1, {0}},
    {GL_MAP_STENCIL, Rounded, 1, {0}},
    {GL_INDEX_SHIFT, Rounded, 1, {0}},
    {GL_INDEX_OFFSET, Rounded, 1, {0}},
    {GL_RED_SCALE, Rounded, 1, {1}},
    {GL_RED_BIAS, Rounded, 1, {0}},
    {GL_GREEN_SCALE, Rounded, 1, {1}},
    {GL_GREEN_BIAS, Rounded, 1, {0}},
    {GL_BLUE_SCALE, Rounded, 1, {1}},
    {GL_BLUE_BIAS, Rounded, 1, {0}},
    {GL_ALPHA_SCALE, Rounded, 1, {1}},
    {GL_ALPHA_BIAS, Rounded, 1, {0}},
    {GL_DEPTH_SCALE, Rounded, 1, {1}},
    {GL_DEPTH_BIAS, Rounded, 1, {0}},
    {GL_PIXEL_MAP_S_TO_S_SIZE, Rounded, 1, {1}},
    {GL_PIXEL_MAP_I_TO_I_SIZE, Rounded, 1, {1}},
    {GL_PIXEL_MAP_I_TO_R_SIZE, Rounded, 1, {1}},
    {GL_PIXEL_MAP_I_TO_G_SIZE, Rounded, 1, {1}},
    {GL_PIXEL_MAP_I_TO_B_SIZE, Rounded, 1, {1}},
    {GL_PIXEL_MAP_I_TO_A_SIZE, Rounded, 1, {1}},
    {GL_PIXEL_MAP_R_TO_R_SIZE, Rounded, 1, {1}},
    {GL_PIXEL_MAP_G_TO_G_SIZE, Rounded, 1, {1}},
    {GL_PIXEL_MAP_B_TO_B_SIZE, Rounded, 1, {1}},
    {GL_PIXEL_MAP_A_TO_A_SIZE, Rounded, 1, {1}},
    {GL_ZOOM_X, Rounded, 1, {1}},
    {GL_ZOOM_Y, Rounded, 1, {1}},
    {GL_TEXTURE_BINDING_1D, Rounded, 1, {0}},
    {GL_TEXTURE_BINDING_2D, Rounded, 1, {0}},
    {GL_MAX_ELEMENTS_VERTICES, Rounded, 1, {3000}},
    {GL_MAX_ELEMENTS_INDICES, Rounded, 1, {3000}},
    {GL_ALIASED_POINT_SIZE_RANGE, Rounded, 2, {1, 255}},
    {GL_ALIASED_LINE_WIDTH_RANGE, Rounded, 2, {1, 255}},
    {GL_MAX_3D_TEXTURE_SIZE, Rounded, 1, {2048}},
    {GL_TEXTURE_BINDING_3D, Rounded, 1, {0}},
    {GL_BLEND_EQUATION, Rounded, 1, {GL_FUNC_ADD}},
    {GL_BLEND_COLOR, Normalized, 4, {0, 0, 0, 0}},
    {GL_ACTIVE_TEXTURE, Rounded, 1, {GL_TEXTURE0}},
    {GL_CLIENT_ACTIVE_TEXTURE, Rounded, 1, {GL_TEXTURE0}},
    {GL_MAX_TEXTURE_UNITS, Rounded, 1, {8}},
    {GL_TEXTURE_BINDING_CUBE_MAP, Rounded, 1, {0}},
    {GL_MAX_CUBE_MAP_TEXTURE_SIZE, Rounded, 1, {16384}},
    {GL_TEXTURE_COMPRESSION_HINT, Rounded, 1, {GL_DONT_CARE}},
    {GL_NUM_COMPRESSED_TEXTURE_FORMATS, Rounded, 1, {12}},
    // llvmpipe's compressed texture formats: this pipeline has no textures, but Mesa lists them.
    {GL_COMPRESSED_TEXTURE_FORMATS, Rounded, 12, {0x86B0, 0x86B1, 0x83F0, 0x83F2, 0x83F3, 0x9274, 0x9278, 0x9270, 0x9272, 0x9271, 0x9273, 0x9276}},
    {GL_SAMPLE_BUFFERS, Rounded, 1, {0}},
    {GL_SAMPLES, Rounded, 1, {0}},
    {GL_SAMPLE_COVERAGE_VALUE, Rounded, 1, {1}},
    {GL_SAMPLE_COVERAGE_INVERT, Rounded, 1, {0}},
    {GL_BLEND_DST_RGB, Rounded, 1, {GL_ZERO}},
    {GL_BLEND_SRC_RGB, Rounded, 1, {GL_ONE}},
    {GL_BLEND_DST_ALPHA, Rounded, 1, {GL_ZERO}},
    {GL_BLEND_SRC_ALPHA, Rounded, 1, {GL_ONE}},
    {GL_MAX_TEXTURE_LOD_BIAS, Rounded, 1, {16}},
    {GL_GENERATE_MIPMAP_HINT, Rounded, 1, {GL_DONT_CARE}},
    {GL_CURRENT_FOG_COORDINATE, Rounded, 1, {0}},
    {GL_FOG_COORD_ARRAY_TYPE, Rounded, 1, {GL_FLOAT}},
    {GL_FOG_COORD_ARRAY_STRIDE, Rounded, 1, {0}},
    {GL_CURRENT_SECONDARY_COLOR, Normalized, 4, {0, 0, 0, 1}},
    {GL_SECONDARY_COLOR_ARRAY_SIZE, Rounded, 1, {3}},
    {GL_SECONDARY_COLOR_ARRAY_TYPE, Rounded, 1, {GL_FLOAT}},
    {GL_SECONDARY_COLOR_ARRAY_STRIDE, Rounded, 1, {0}},
    {GL_ARRAY_BUFFER_BINDING, Rounded, 1, {0}},
    {GL_ELEMENT_ARRAY_BUFFER_BINDING, Rounded, 1, {0}},
    {GL_VERTEX_ARRAY_BUFFER_BINDING, Rounded, 1, {0}},
    {GL_NORMAL_ARRAY_BUFFER_BINDING, Rounded, 1, {0}},
    {GL_COLOR_ARRAY_BUFFER_BINDING, Rounded, 1, {0}},
    {GL_INDEX_ARRAY_BUFFER_BINDING, Rounded, 1, {0}},
    {GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING, Rounded, 1, {0}},
    {GL_EDGE_FLAG_ARRAY_BUFFER_BINDING, Rounded, 1, {0}},
    {GL_SECONDARY_COLOR_ARRAY_BUFFER_BINDING, Rounded, 1, {0}},
    {GL_FOG_COORD_ARRAY_BUFFER_BINDING, Rounded, 1, {0}},
    {GL_STENCIL_BACK_FUNC, Rounded, 1, {GL_ALWAYS}},
    {GL_STENCIL_BACK_FAIL, Rounded, 1, {GL_KEEP}},
    {GL_STENCIL_BACK_PASS_DEPTH_FAIL, Rounded, 1, {GL_KEEP}},
    {GL_STENCIL_BACK_PASS_DEPTH_PASS, Rounded, 1, {GL_KEEP}},
    {GL_MAX_DRAW_BUFFERS, Rounded, 1, {8}},
    {GL_DRAW_BUFFER0, Rounded, 1, {GL_FRONT}},
    {GL_DRAW_BUFFER1, Rounded, 1, {0}},
    {GL_DRAW_BUFFER2, Rounded, 1, {0}},
    {GL_DRAW_BUFFER3, Rounded, 1, {0}},
    {GL_DRAW_BUFFER4, Rounded, 1, {0}},
    {GL_DRAW_BUFFER5, Rounded, 1, {0}},
    {GL_DRAW_BUFFER6, Rounded, 1, {0}},
    {GL_DRAW_BUFFER7, Rounded, 1, {0}},
    {GL_BLEND_EQUATION_ALPHA, Rounded, 1, {GL_FUNC_ADD}},
    {GL_MAX_VERTEX_ATTRIBS, Rounded, 1, {16}},
    {GL_MAX_TEXTURE_IMAGE_UNITS, Rounded, 1, {32}},
    {GL_MAX_FRAGMENT_UNIFORM_COMPONENTS, Rounded, 1, {16384}},
    {GL_MAX_VERTEX_UNIFORM_COMPONENTS, Rounded, 1, {16384}},
    {GL_MAX_VARYING_FLOATS, Rounded, 1, {128}},
    {GL_MAX_VERTEX_TEXTURE_IMAGE_UNITS, Rounded, 1, {32}},
    {GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, Rounded, 1, {192}},
    {GL_FRAGMENT_SHADER_DERIVATIVE_HINT, Rounded, 1, {GL_DONT_CARE}},
    {GL_CURRENT_PROGRAM, Rounded, 1, {0}},
    {GL_STENCIL_BACK_REF, Rounded, 1, {0}},
    {GL_STENCIL_BACK_VALUE_MASK, Rounded, 1, {255}},
    {GL_STENCIL_BACK_WRITEMASK, Rounded, 1, {255}},
    {GL_MAX_TEXTURE_COORDS, Rounded, 1, {8}},
    {GL_PIXEL_PACK_BUFFER_BINDING, Rounded, 1, {0}},
    {GL_PIXEL_UNPACK_BUFFER_BINDING, Rounded, 1, {0}},
    {GL_CURRENT_RASTER_SECONDARY_COLOR, Normalized, 4, {0, 0, 0, 1}},
};

const Constant* find_constant(GLenum name) {
  for (const Constant& c : kConstants)
    if (c.name == name) return &c;
  return nullptr;
}

}  // namespace

int Context::get_table_values(GLenum pname, GLdouble* out, int& normalized) {
  auto transposed = [&](const glm::dmat4& m) {
    const glm::dmat4 t = glm::transpose(m);
    std::copy(glm::value_ptr(t), glm::value_ptr(t) + 16, out);
    normalized = kFromFloat;  // get.c's TYPE_MATRIX_T converts like TYPE_MATRIX (FLOAT_TO_INT)
    return 16;
  };
  switch (pname) {
    case GL_TRANSPOSE_MODELVIEW_MATRIX: return transposed(modelview());
    case GL_TRANSPOSE_PROJECTION_MATRIX: return transposed(projection());
    case GL_TRANSPOSE_TEXTURE_MATRIX: return transposed(texture());
    case GL_SCISSOR_BOX:
      // No glScissor here: the box stays where Mesa puts it when the context is first made
      // current, the whole window (GL 2.1 section 4.1.2).
      out[0] = 0, out[1] = 0, out[2] = fb_.width, out[3] = fb_.height;
      normalized = kRound;
      return 4;
  }
  const Constant* c = find_constant(pname);
  if (!c) return 0;
  std::copy(c->values, c->values + c->count, out);
  normalized = c->conv == Normalized ? kFromFloat : kRound;
  return c->count;
}

}  // namespace ffc::state
