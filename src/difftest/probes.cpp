#include "difftest/probes.h"

#include <algorithm>
#include <cmath>

#include "difftest/stream.h"
#include "gl/dispatch.h"

namespace ffc::difftest {

namespace {

constexpr double kSentinel = -7777;

}  // namespace

const std::vector<GLenum>& light_pnames() {
  static const std::vector<GLenum> v = {GL_AMBIENT,       GL_DIFFUSE,     GL_SPECULAR,
                                        GL_POSITION,      GL_SPOT_DIRECTION, GL_SPOT_EXPONENT,
                                        GL_SPOT_CUTOFF,   GL_CONSTANT_ATTENUATION, GL_LINEAR_ATTENUATION,
                                        GL_QUADRATIC_ATTENUATION};
  return v;
}
const std::vector<GLenum>& material_pnames() {
  static const std::vector<GLenum> v = {GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION, GL_SHININESS, GL_COLOR_INDEXES};
  return v;
}
// Every glGet pname the context reports (Context::GetDoublev's list).
const std::vector<GLenum>& get_pnames() {
  static const std::vector<GLenum> v = {
      GL_MODELVIEW_MATRIX, GL_PROJECTION_MATRIX, GL_MODELVIEW_STACK_DEPTH, GL_PROJECTION_STACK_DEPTH,
      GL_MAX_MODELVIEW_STACK_DEPTH, GL_MAX_PROJECTION_STACK_DEPTH, GL_MATRIX_MODE, GL_VIEWPORT, GL_DEPTH_RANGE,
      GL_MAX_LIGHTS, GL_LIGHT_MODEL_AMBIENT, GL_LIGHT_MODEL_LOCAL_VIEWER, GL_LIGHT_MODEL_TWO_SIDE,
      GL_LIGHT_MODEL_COLOR_CONTROL, GL_SHADE_MODEL, GL_COLOR_MATERIAL_FACE, GL_COLOR_MATERIAL_PARAMETER,
      GL_FRONT_FACE, GL_CULL_FACE_MODE, GL_DEPTH_FUNC, GL_CURRENT_COLOR, GL_CURRENT_NORMAL, GL_COLOR_CLEAR_VALUE,
      GL_DEPTH_CLEAR_VALUE, GL_CURRENT_RASTER_POSITION, GL_CURRENT_RASTER_COLOR,
      GL_CURRENT_RASTER_POSITION_VALID, GL_CURRENT_RASTER_DISTANCE, GL_LINE_WIDTH, GL_POINT_SIZE, GL_POINT_SIZE_RANGE, GL_POINT_SIZE_GRANULARITY,
      GL_ALIASED_POINT_SIZE_RANGE, GL_RENDER_MODE, GL_DEPTH_BITS, GL_RED_BITS, GL_GREEN_BITS, GL_BLUE_BITS,
      GL_ALPHA_BITS, GL_VERTEX_ARRAY_SIZE, GL_VERTEX_ARRAY_TYPE, GL_VERTEX_ARRAY_STRIDE, GL_NORMAL_ARRAY_TYPE,
      GL_NORMAL_ARRAY_STRIDE, GL_COLOR_ARRAY_SIZE, GL_COLOR_ARRAY_TYPE, GL_COLOR_ARRAY_STRIDE, GL_VERTEX_ARRAY,
      GL_NORMAL_ARRAY, GL_COLOR_ARRAY, GL_LIGHTING, GL_NORMALIZE, GL_RESCALE_NORMAL, GL_COLOR_MATERIAL,
      GL_DEPTH_TEST, GL_CULL_FACE, GL_LIGHT0, GL_LIGHT1, GL_LIGHT2, GL_LIGHT3, GL_LIGHT4, GL_LIGHT5, GL_LIGHT6,
      GL_LIGHT7, GL_FEEDBACK_BUFFER_SIZE, GL_FEEDBACK_BUFFER_TYPE, GL_PACK_SWAP_BYTES, GL_PACK_LSB_FIRST,
      GL_PACK_ROW_LENGTH, GL_PACK_IMAGE_HEIGHT, GL_PACK_SKIP_ROWS, GL_PACK_SKIP_PIXELS, GL_PACK_SKIP_IMAGES,
      GL_PACK_ALIGNMENT, GL_UNPACK_SWAP_BYTES, GL_UNPACK_LSB_FIRST, GL_UNPACK_ROW_LENGTH, GL_UNPACK_IMAGE_HEIGHT,
      GL_UNPACK_SKIP_ROWS, GL_UNPACK_SKIP_PIXELS, GL_UNPACK_SKIP_IMAGES, GL_UNPACK_ALIGNMENT, GL_FOG_MODE,
      GL_FOG_DENSITY, GL_FOG_START, GL_FOG_END, GL_FOG_COLOR, GL_FOG_INDEX, GL_FOG_HINT, GL_FOG_COORD_SRC,
      GL_POLYGON_OFFSET_FACTOR, GL_POLYGON_OFFSET_UNITS,
      // display lists
      GL_LIST_INDEX, GL_LIST_MODE, GL_LIST_BASE, GL_MAX_LIST_NESTING,
      // selection
      GL_NAME_STACK_DEPTH, GL_MAX_NAME_STACK_DEPTH, GL_SELECTION_BUFFER_SIZE,
      // the other current values, hints, the texture coordinate array
      GL_CURRENT_TEXTURE_COORDS, GL_EDGE_FLAG, GL_PERSPECTIVE_CORRECTION_HINT, GL_POINT_SMOOTH_HINT,
      GL_LINE_SMOOTH_HINT, GL_POLYGON_SMOOTH_HINT, GL_GENERATE_MIPMAP_HINT, GL_TEXTURE_COMPRESSION_HINT,
      GL_FRAGMENT_SHADER_DERIVATIVE_HINT, GL_TEXTURE_COORD_ARRAY_SIZE, GL_TEXTURE_COORD_ARRAY_TYPE,
      GL_TEXTURE_COORD_ARRAY_STRIDE};
  return v;
}
// Every capability glIsEnabled answers for: the modelled ones, the client arrays, and those GL
// knows that the pipeline accepts without modelling.
const std::vector<GLenum>& capabilities() {
  static const std::vector<GLenum> v = {
      GL_LIGHTING, GL_NORMALIZE, GL_RESCALE_NORMAL, GL_COLOR_MATERIAL, GL_DEPTH_TEST, GL_CULL_FACE, GL_LIGHT0,
      GL_LIGHT1, GL_LIGHT2, GL_LIGHT3, GL_LIGHT4, GL_LIGHT5, GL_LIGHT6, GL_LIGHT7,
      // client arrays
      GL_VERTEX_ARRAY, GL_NORMAL_ARRAY, GL_COLOR_ARRAY, GL_TEXTURE_COORD_ARRAY, GL_INDEX_ARRAY,
      GL_EDGE_FLAG_ARRAY, GL_FOG_COORD_ARRAY, GL_SECONDARY_COLOR_ARRAY,
      // accepted, not modelled
      GL_ALPHA_TEST, GL_AUTO_NORMAL, GL_BLEND, GL_CLIP_PLANE0, GL_CLIP_PLANE1, GL_CLIP_PLANE2, GL_CLIP_PLANE3,
      GL_CLIP_PLANE4, GL_CLIP_PLANE5, GL_CLIP_PLANE0 + 6, GL_CLIP_PLANE0 + 7, GL_COLOR_LOGIC_OP, GL_COLOR_SUM,
      GL_DITHER, GL_FOG, GL_INDEX_LOGIC_OP, GL_LINE_SMOOTH, GL_LINE_STIPPLE, GL_MAP1_COLOR_4, GL_MAP1_INDEX,
      GL_MAP1_NORMAL, GL_MAP1_TEXTURE_COORD_1, GL_MAP1_TEXTURE_COORD_2, GL_MAP1_TEXTURE_COORD_3,
      GL_MAP1_TEXTURE_COORD_4, GL_MAP1_VERTEX_3, GL_MAP1_VERTEX_4, GL_MAP2_COLOR_4, GL_MAP2_INDEX, GL_MAP2_NORMAL,
      GL_MAP2_TEXTURE_COORD_1, GL_MAP2_TEXTURE_COORD_2, GL_MAP2_TEXTURE_COORD_3, GL_MAP2_TEXTURE_COORD_4,
      GL_MAP2_VERTEX_3, GL_MAP2_VERTEX_4, GL_MULTISAMPLE, GL_POINT_SMOOTH, GL_POINT_SPRITE,
      GL_POLYGON_OFFSET_FILL, GL_POLYGON_OFFSET_LINE, GL_POLYGON_OFFSET_POINT, GL_POLYGON_SMOOTH,
      GL_POLYGON_STIPPLE, GL_SAMPLE_ALPHA_TO_COVERAGE, GL_SAMPLE_ALPHA_TO_ONE, GL_SAMPLE_COVERAGE,
      GL_SCISSOR_TEST, GL_STENCIL_TEST, GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP,
      GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R, GL_TEXTURE_GEN_Q, GL_VERTEX_PROGRAM_POINT_SIZE,
      GL_VERTEX_PROGRAM_TWO_SIDE};
  return v;
}
const std::vector<Probe>& probes() {
  static const std::vector<Probe> v = [] {
    std::vector<Probe> p;
    for (int i = 0; i < 8; ++i)
      for (GLenum pn : light_pnames()) p.push_back({Query::Lightfv, GLenum(GL_LIGHT0 + i), pn, 4});
    for (GLenum f : {GL_FRONT, GL_BACK})
      for (GLenum pn : material_pnames()) p.push_back({Query::Materialfv, f, pn, 4});
    for (Query q : {Query::Doublev, Query::Floatv, Query::Integerv}) {
      for (GLenum pn : get_pnames()) p.push_back({q, pn, 0, 16});
      for (GLenum c : capabilities())
        if (std::find(get_pnames().begin(), get_pnames().end(), c) == get_pnames().end()) p.push_back({q, c, 0, 16});
    }
    for (GLenum c : capabilities()) p.push_back({Query::IsEnabled, c, 0, 1});
    return p;
  }();
  return v;
}

std::string probe_name(const Probe& p) {
  switch (p.q) {
    case Query::Lightfv: return "glGetLightfv(" + enum_name(p.a) + ", " + enum_name(p.b) + ")";
    case Query::Materialfv: return "glGetMaterialfv(" + enum_name(p.a) + ", " + enum_name(p.b) + ")";
    case Query::Doublev: return "glGetDoublev(" + enum_name(p.a) + ")";
    case Query::Floatv: return "glGetFloatv(" + enum_name(p.a) + ")";
    case Query::Integerv: return "glGetIntegerv(" + enum_name(p.a) + ")";
    case Query::IsEnabled: return "glIsEnabled(" + enum_name(p.a) + ")";
  }
  return "?";
}

std::vector<double> read_back() {
  std::vector<double> out;
  out.reserve(4096);
  for (const Probe& p : probes()) {
    if (p.q == Query::Doublev) {
      GLdouble v[16];
      std::fill(v, v + 16, kSentinel);
      glGetDoublev(p.a, v);
      out.insert(out.end(), v, v + p.slots);
    } else if (p.q == Query::Integerv) {
      GLint v[16];
      std::fill(v, v + 16, GLint(kSentinel));
      glGetIntegerv(p.a, v);
      out.insert(out.end(), v, v + p.slots);
    } else if (p.q == Query::IsEnabled) {
      out.push_back(glIsEnabled(p.a));
    } else {
      GLfloat v[16];
      std::fill(v, v + 16, GLfloat(kSentinel));
      if (p.q == Query::Lightfv) glGetLightfv(p.a, p.b, v);
      else if (p.q == Query::Materialfv) glGetMaterialfv(p.a, p.b, v);
      else glGetFloatv(p.a, v);
      out.insert(out.end(), v, v + p.slots);
    }
  }
  out.push_back(glGetError());
  return out;
}

const Probe* probe_of(size_t i) {
  for (const Probe& p : probes()) {
    if (i < size_t(p.slots)) return &p;
    i -= size_t(p.slots);
  }
  return nullptr;
}

bool slot_close(size_t i, double a, double b, double rel) {
  if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
  if (a == b) return true;
  const Probe* p = probe_of(i);
  if (!p || p->q == Query::IsEnabled) return false;
  if (p->q == Query::Integerv) {
    // Values GL maps linearly onto the integers (colours, normals, depths: 2.13.7, 6.1.2) are floats
    // underneath: compared as the floats are, scaled.
    switch (p->a) {
      case GL_MODELVIEW_MATRIX: case GL_PROJECTION_MATRIX: case GL_CURRENT_COLOR: case GL_CURRENT_NORMAL:
      case GL_CURRENT_RASTER_COLOR: case GL_COLOR_CLEAR_VALUE:
      case GL_LIGHT_MODEL_AMBIENT: case GL_FOG_COLOR: case GL_DEPTH_RANGE: case GL_DEPTH_CLEAR_VALUE:
        return std::fabs(a - b) <= rel * 2147483648.0;
      default: return false;
    }
  }
  return std::fabs(a - b) <= rel * std::max({1.0, std::fabs(a), std::fabs(b)});
}

}  // namespace ffc::difftest
