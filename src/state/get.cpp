// glGet (GL 2.1 section 6.1): the values of the modelled state in one list, and the conversions
// of glGetDoublev / glGetFloatv / glGetIntegerv / glGetBooleanv as Mesa's get.c makes them; plus
// glGetPointerv. The state this pipeline does not model answers from get_table.cpp.
#include <algorithm>
#include <cmath>
#include <limits>
#include <glm/gtc/type_ptr.hpp>

#include "state/context.h"

namespace ffc::state {

namespace {
// Mesa's FLOAT_TO_INT (main/macros.h): (GLint)(2147483647.0 * x), truncated, unclamped; out of
// range the x86-64 conversion (cvttsd2si) gives INT_MIN.
GLint float_to_int(double x) {
  const double d = 2147483647.0 * x;
  if (!(d > -2147483649.0 && d < 2147483648.0)) return std::numeric_limits<GLint>::min();
  return GLint(d);
}
}  // namespace

#define FFC_GET(...)                               \
  {                                                \
    const double vals[] = {__VA_ARGS__};           \
    n = int(sizeof vals / sizeof *vals);           \
    std::copy(vals, vals + n, out);                \
  }

// The one list of glGet values: writes up to 16 values to `out` and returns how many (0 after
// recording an error). `normalized` tells glGetIntegerv how to convert: kRound rounds to the
// nearest integer; kFromFloat / kFromDouble map the value's [-1, 1] onto the integer range
// (colours, normals, depth range and depth clear value, as GL 2.1 section 6.1.2 says; and the
// matrices, as Mesa does though the spec says they round: get.c's TYPE_MATRIX uses FLOAT_TO_INT),
// from the value as Mesa stores it: a float, or a double for the depth clear value.
int Context::get_values(GLenum pname, GLdouble* out, int& normalized) {
  normalized = kRound;
  if (!query_allowed()) return 0;
  int n = 0;
  auto vec4 = [&](const glm::dvec4& c, bool color) {
    for (int k = 0; k < 4; ++k) out[k] = c[k];
    n = 4, normalized = color ? kFromFloat : kRound;
  };
  auto mat = [&](const glm::dmat4& m) {
    std::copy(glm::value_ptr(m), glm::value_ptr(m) + 16, out);
    n = 16, normalized = kFromFloat;
  };
  // FLUSH_CURRENT; inside a GL_COMPILE_AND_EXECUTE list's wrapped primitive (the only glBegin a query
  // is taken in) Mesa's immediate mode copies nothing, so a colour sent there is not tracked by
  // colour material either (repro list_wrap_query_copies_nothing.txt).
  if ((pname == GL_CURRENT_COLOR || pname == GL_CURRENT_NORMAL || pname == GL_CURRENT_TEXTURE_COORDS ||
       pname == GL_EDGE_FLAG) && !in_begin_)
    flush_current();
  switch (pname) {
    // The float context reports its float matrices, as Mesa does: the ones it draws with.
    case GL_MODELVIEW_MATRIX: mat(modelview()); break;
    case GL_TEXTURE_MATRIX: mat(texture()); break;
    case GL_PROJECTION_MATRIX: mat(projection()); break;
    case GL_MODELVIEW_STACK_DEPTH: FFC_GET(double(modelview_.size())); break;
    case GL_PROJECTION_STACK_DEPTH: FFC_GET(double(projection_.size())); break;
    case GL_MAX_MODELVIEW_STACK_DEPTH: case GL_MAX_PROJECTION_STACK_DEPTH: FFC_GET(double(kMaxStackDepth)); break;
    case GL_MAX_TEXTURE_STACK_DEPTH: FFC_GET(double(kMaxTextureStackDepth)); break;
    case GL_TEXTURE_STACK_DEPTH: FFC_GET(double(texture_.size())); break;
    case GL_MATRIX_MODE: FFC_GET(double(matrix_mode_)); break;
    case GL_VIEWPORT: FFC_GET(double(viewport_[0]), double(viewport_[1]), double(viewport_[2]), double(viewport_[3])); break;
    case GL_DEPTH_RANGE: FFC_GET(depth_range_.x, depth_range_.y); normalized = kFromFloat; break;
    case GL_MAX_LIGHTS: FFC_GET(8.0); break;
    case GL_LIGHT_MODEL_AMBIENT: vec4(model_.ambient, true); break;
    case GL_LIGHT_MODEL_LOCAL_VIEWER: FFC_GET(double(model_.local_viewer)); break;
    case GL_LIGHT_MODEL_TWO_SIDE: FFC_GET(double(model_.two_side)); break;
    case GL_LIGHT_MODEL_COLOR_CONTROL:
      FFC_GET(double(model_.separate_specular ? GL_SEPARATE_SPECULAR_COLOR : GL_SINGLE_COLOR)); break;
    case GL_SHADE_MODEL: FFC_GET(double(shade_model_)); break;
    case GL_COLOR_MATERIAL_FACE: FFC_GET(double(cm_face_)); break;
    case GL_COLOR_MATERIAL_PARAMETER: FFC_GET(double(cm_mode_)); break;
    case GL_FRONT_FACE: FFC_GET(double(front_face_)); break;
    case GL_POLYGON_MODE: FFC_GET(double(polygon_mode_[0]), double(polygon_mode_[1])); break;
    case GL_CULL_FACE_MODE: FFC_GET(double(cull_mode_)); break;
    case GL_DEPTH_FUNC: FFC_GET(double(depth_func_)); break;
    // A wrapped GL_COMPILE_AND_EXECUTE primitive leaves them as they were (ListState::shown).
    // While a list left Mesa's CurrentExecPrimitive set, as they were then (inside_values_).
    case GL_CURRENT_COLOR: vec4(exec_inside_ ? inside_values_.color : lists_.shown ? lists_.shown_color : color_, true); break;
    case GL_CURRENT_NORMAL: {
      const glm::dvec3& nv = exec_inside_ ? inside_values_.normal : lists_.shown ? lists_.shown_normal : normal_;
      FFC_GET(nv.x, nv.y, nv.z);
      normalized = kFromFloat;
      break;
    }
    case GL_COLOR_CLEAR_VALUE: vec4(glm::dvec4(clear_color_), true); break;
    case GL_DEPTH_CLEAR_VALUE: FFC_GET(clear_depth_); normalized = kFromDouble; break;
    case GL_LINE_WIDTH: FFC_GET(double(line_width_)); break;
    // llvmpipe's limits as Mesa 22.3 reports them: sizes 1 to 255 (LP_MAX_POINT_WIDTH), steps of 0.1.
    case GL_POINT_SIZE: FFC_GET(double(point_size_)); break;
    case GL_POINT_SIZE_RANGE: case GL_ALIASED_POINT_SIZE_RANGE: FFC_GET(1.0, 255.0); break;
    case GL_POINT_SIZE_GRANULARITY: FFC_GET(double(0.1f)); break;
    case GL_RENDER_MODE: FFC_GET(double(render_mode_)); break;
    case GL_DEPTH_BITS: FFC_GET(24.0); break;
    case GL_RED_BITS: case GL_GREEN_BITS: case GL_BLUE_BITS: case GL_ALPHA_BITS: FFC_GET(8.0); break;
    case GL_VERTEX_ARRAY_SIZE: FFC_GET(double(vertex_array_.size)); break;
    case GL_VERTEX_ARRAY_TYPE: FFC_GET(double(vertex_array_.type)); break;
    case GL_VERTEX_ARRAY_STRIDE: FFC_GET(double(vertex_array_.stride)); break;
    case GL_NORMAL_ARRAY_TYPE: FFC_GET(double(normal_array_.type)); break;
    case GL_NORMAL_ARRAY_STRIDE: FFC_GET(double(normal_array_.stride)); break;
    case GL_COLOR_ARRAY_SIZE: FFC_GET(double(color_array_.size)); break;
    case GL_COLOR_ARRAY_TYPE: FFC_GET(double(color_array_.type)); break;
    case GL_COLOR_ARRAY_STRIDE: FFC_GET(double(color_array_.stride)); break;
    case GL_VERTEX_ARRAY: FFC_GET(double(vertex_array_.enabled)); break;
    case GL_NORMAL_ARRAY: FFC_GET(double(normal_array_.enabled)); break;
    case GL_COLOR_ARRAY: FFC_GET(double(color_array_.enabled)); break;
    case GL_PACK_ALIGNMENT: FFC_GET(double(pack_alignment_)); break;
    case GL_UNPACK_ALIGNMENT: FFC_GET(double(unpack_alignment_)); break;
    case GL_PACK_SWAP_BYTES: case GL_PACK_LSB_FIRST: case GL_PACK_ROW_LENGTH: case GL_PACK_IMAGE_HEIGHT:
    case GL_PACK_SKIP_ROWS: case GL_PACK_SKIP_PIXELS: case GL_PACK_SKIP_IMAGES: case GL_UNPACK_SWAP_BYTES:
    case GL_UNPACK_LSB_FIRST: case GL_UNPACK_ROW_LENGTH: case GL_UNPACK_IMAGE_HEIGHT: case GL_UNPACK_SKIP_ROWS:
    case GL_UNPACK_SKIP_PIXELS: case GL_UNPACK_SKIP_IMAGES: {
      const auto it = pixel_store_.find(pname);
      FFC_GET(double(it == pixel_store_.end() ? 0 : it->second));
      break;
    }
    case GL_FEEDBACK_BUFFER_SIZE: FFC_GET(double(feedback_size_)); break;
    case GL_FEEDBACK_BUFFER_TYPE: FFC_GET(double(feedback_type_)); break;
    case GL_CURRENT_RASTER_POSITION:
      FFC_GET(raster_pos_.window.x, raster_pos_.window.y, raster_pos_.window.z, raster_pos_.window.w);
      break;
    case GL_CURRENT_RASTER_COLOR: vec4(raster_pos_.color, true); break;
    case GL_CURRENT_RASTER_POSITION_VALID: FFC_GET(double(raster_pos_.valid)); break;
    case GL_CURRENT_RASTER_DISTANCE: FFC_GET(raster_pos_.distance); break;
    default: {
      const int on = enabled_state(pname);  // every capability glIsEnabled knows is also a glGet value
      if (on >= 0) {
        FFC_GET(double(on));
        break;
      }
      n = attribute_values(pname, out);  // before fog_values, which answers GL_FOG_HINT's default
      if (n == 0) n = fog_values(pname, out, normalized);
      if (n == 0) n = fragment_values(pname, out, normalized);
      if (n == 0) n = list_values(pname, out);
      if (n == 0) n = select_values(pname, out);
      if (n == 0) n = get_table_values(pname, out, normalized);
      if (n == 0) return error(GL_INVALID_ENUM), 0;
    }
  }
  return n;
}
#undef FFC_GET

void Context::GetDoublev(GLenum pname, GLdouble* out) {
  GLdouble v[16];
  int normalized;
  const int n = get_values(pname, v, normalized);
  std::copy(v, v + n, out);
}

void Context::GetFloatv(GLenum pname, GLfloat* out) {
  GLdouble v[16];
  int normalized;
  const int n = get_values(pname, v, normalized);
  for (int k = 0; k < n; ++k) out[k] = GLfloat(v[k]);
}

void Context::GetIntegerv(GLenum pname, GLint* out) {
  GLdouble v[16];
  int normalized;
  const int n = get_values(pname, v, normalized);
  // Other values round to the nearest integer, halves away from zero (Mesa's IROUND).
  for (int k = 0; k < n; ++k)
    out[k] = normalized == kFromFloat    ? float_to_int(double(float(v[k])))
             : normalized == kFromDouble ? float_to_int(v[k])
                                         : GLint(std::lround(v[k]));
}

void Context::GetBooleanv(GLenum pname, GLboolean* out) {
  GLdouble v[16];
  int normalized;
  const int n = get_values(pname, v, normalized);
  // get.c: every type becomes GL_TRUE when non-zero; the float-held values (colours, matrices)
  // are tested as the floats Mesa keeps.
  for (int k = 0; k < n; ++k)
    out[k] = (normalized == kFromFloat ? float(v[k]) != 0.0f : v[k] != 0.0) ? GL_TRUE : GL_FALSE;
}

void Context::GetPointerv(GLenum pname, void** out) {
  if (!outside_begin_end_keeping_vertices()) return;  // the pointer left as it was, as Mesa leaves it
  switch (pname) {
    case GL_VERTEX_ARRAY_POINTER: *out = const_cast<void*>(vertex_array_.pointer); return;
    case GL_NORMAL_ARRAY_POINTER: *out = const_cast<void*>(normal_array_.pointer); return;
    case GL_COLOR_ARRAY_POINTER: *out = const_cast<void*>(color_array_.pointer); return;
    // Arrays this pipeline has no pointer call for: never set, null as in GL's default state.
    case GL_TEXTURE_COORD_ARRAY_POINTER: *out = const_cast<void*>(texcoord_array_.pointer); return;
    case GL_INDEX_ARRAY_POINTER: case GL_EDGE_FLAG_ARRAY_POINTER:
    case GL_FOG_COORD_ARRAY_POINTER: case GL_SECONDARY_COLOR_ARRAY_POINTER:
      *out = nullptr;
      return;
    case GL_SELECTION_BUFFER_POINTER: *out = select_.buffer; return;
    case GL_FEEDBACK_BUFFER_POINTER: *out = feedback_; return;
  }
  error(GL_INVALID_ENUM);
}

}  // namespace ffc::state
