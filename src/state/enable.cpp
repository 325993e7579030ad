// glEnable / glDisable / glIsEnabled and the client-state switches (GL 2.1 section 2.12 and
// table 6.x): the capabilities the pipeline models are fields of Context; the others GL knows are
// recorded by name and reported, as Mesa's enable.c does.
#include "state/context.h"
#include "state/gl_rules.h"

namespace ffc::state {

bool* Context::capability(GLenum cap) {
  switch (cap) {
    case GL_LIGHTING: return &lighting_;
    case GL_NORMALIZE: return &normalize_;
    case GL_RESCALE_NORMAL: return &rescale_normal_;
    case GL_COLOR_MATERIAL: return &color_material_;
    case GL_DEPTH_TEST: return &depth_test_;
    case GL_CULL_FACE: return &cull_face_;
    case GL_FOG: return &fog_;
    case GL_POLYGON_OFFSET_FILL: return &offset_fill_;
    case GL_SCISSOR_TEST: case GL_ALPHA_TEST: case GL_BLEND: case GL_LINE_STIPPLE: return fragment_capability(cap);
    default: {
      const int i = light_index(cap);
      return i >= 0 ? &lights_[i].enabled : nullptr;
    }
  }
}

namespace {
// Capabilities and client arrays GL 2.1 knows that this pipeline does not model, with their
// defaults (GL 2.1 tables 6.x; GL_DITHER and GL_MULTISAMPLE start enabled): glEnable / glDisable /
// glEnableClientState / glDisableClientState record them and glIsEnabled / glGet report them, as
// Mesa 22.3's compatibility context does. Imaging-subset capabilities (GL_COLOR_TABLE,
// GL_CONVOLUTION_1D, GL_HISTOGRAM, ...) are not here: Mesa has no ARB_imaging and rejects them.
struct OtherEnable {
  GLenum name;
  bool initial;
};
constexpr OtherEnable kOtherCaps[] = {
    {GL_ALPHA_TEST, false}, {GL_AUTO_NORMAL, false}, {GL_BLEND, false}, {GL_CLIP_PLANE0, false},
    {GL_CLIP_PLANE1, false}, {GL_CLIP_PLANE2, false}, {GL_CLIP_PLANE3, false}, {GL_CLIP_PLANE4, false},
    {GL_CLIP_PLANE5, false}, {GL_CLIP_PLANE0 + 6, false}, {GL_CLIP_PLANE0 + 7, false}, {GL_COLOR_LOGIC_OP, false},
    {GL_COLOR_SUM, false}, {GL_DITHER, true}, {GL_INDEX_LOGIC_OP, false}, {GL_LINE_SMOOTH, false},
    {GL_LINE_STIPPLE, false}, {GL_MAP1_COLOR_4, false}, {GL_MAP1_INDEX, false}, {GL_MAP1_NORMAL, false},
    {GL_MAP1_TEXTURE_COORD_1, false}, {GL_MAP1_TEXTURE_COORD_2, false}, {GL_MAP1_TEXTURE_COORD_3, false},
    {GL_MAP1_TEXTURE_COORD_4, false}, {GL_MAP1_VERTEX_3, false}, {GL_MAP1_VERTEX_4, false},
    {GL_MAP2_COLOR_4, false}, {GL_MAP2_INDEX, false}, {GL_MAP2_NORMAL, false}, {GL_MAP2_TEXTURE_COORD_1, false},
    {GL_MAP2_TEXTURE_COORD_2, false}, {GL_MAP2_TEXTURE_COORD_3, false}, {GL_MAP2_TEXTURE_COORD_4, false},
    {GL_MAP2_VERTEX_3, false}, {GL_MAP2_VERTEX_4, false}, {GL_MULTISAMPLE, true}, {GL_POINT_SMOOTH, false},
    {GL_POINT_SPRITE, false}, {GL_POLYGON_OFFSET_LINE, false},
    {GL_POLYGON_OFFSET_POINT, false}, {GL_POLYGON_SMOOTH, false}, {GL_POLYGON_STIPPLE, false},
    {GL_SAMPLE_ALPHA_TO_COVERAGE, false}, {GL_SAMPLE_ALPHA_TO_ONE, false}, {GL_SAMPLE_COVERAGE, false},
    {GL_SCISSOR_TEST, false}, {GL_STENCIL_TEST, false}, {GL_TEXTURE_1D, false}, {GL_TEXTURE_2D, false},
    {GL_TEXTURE_3D, false}, {GL_TEXTURE_CUBE_MAP, false}, {GL_TEXTURE_GEN_S, false}, {GL_TEXTURE_GEN_T, false},
    {GL_TEXTURE_GEN_R, false}, {GL_TEXTURE_GEN_Q, false}, {GL_VERTEX_PROGRAM_POINT_SIZE, false},
    {GL_VERTEX_PROGRAM_TWO_SIDE, false}};
constexpr OtherEnable kOtherArrays[] = {{GL_TEXTURE_COORD_ARRAY, false}, {GL_INDEX_ARRAY, false},
                                        {GL_EDGE_FLAG_ARRAY, false}, {GL_FOG_COORD_ARRAY, false},
                                        {GL_SECONDARY_COLOR_ARRAY, false}};

template <size_t N>
const OtherEnable* find_enable(const OtherEnable (&table)[N], GLenum name) {
  for (const OtherEnable& e : table)
    if (e.name == name) return &e;
  return nullptr;
}
}  // namespace

// Mesa's _mesa_set_enable returns before its FLUSH_VERTICES when the capability already has the
// value asked for (and raises GL_INVALID_ENUM without one): a glEnable that changes nothing leaves
// the vbo format and its pending values alone (measured: ColorMaterialFlushStreams, Flush267).
void Context::set_enabled(GLenum cap, bool on) {
  if (!outside_begin_end_keeping_vertices()) return;
  // Mesa's glEnable / glDisable also take the client arrays, as glEnableClientState does (GL 2.1:
  // GL_INVALID_ENUM).
  if (cap == GL_VERTEX_ARRAY || cap == GL_NORMAL_ARRAY || cap == GL_COLOR_ARRAY || find_enable(kOtherArrays, cap))
    return flush_vertices(), set_client_state(cap, on);
  bool* c = capability(cap);
  if (!c) {
    if (!find_enable(kOtherCaps, cap)) return error(GL_INVALID_ENUM);
    if (enabled_state(cap) != int(on)) flush_vertices(), other_enables_[cap] = on;  // recorded, not modelled
    return;
  }
  if (*c == on) return;
  flush_vertices();
  if (cap == GL_COLOR_MATERIAL) {
    flush_current();  // Mesa's enable.c: pending values first, then the tracking
    *c = on;
    constants_dirty_ = true;
    if (on) update_color_material();
    return;
  }
  *c = on;
  constants_dirty_ = true;
}

int Context::enabled_state(GLenum cap) {
  switch (cap) {
    case GL_VERTEX_ARRAY: return vertex_array_.enabled;
    case GL_NORMAL_ARRAY: return normal_array_.enabled;
    case GL_COLOR_ARRAY: return color_array_.enabled;
  }
  if (bool* c = capability(cap)) return *c;
  const OtherEnable* o = find_enable(kOtherCaps, cap);
  if (!o) o = find_enable(kOtherArrays, cap);
  if (!o) return -1;
  const auto it = other_enables_.find(cap);
  return it != other_enables_.end() ? it->second : o->initial;
}

GLboolean Context::IsEnabled(GLenum cap) {
  if (in_begin_ || exec_inside_) return error(GL_INVALID_OPERATION), GL_FALSE;  // checked while a list compiles too (measured)
  const int on = enabled_state(cap);
  if (on < 0) return error(GL_INVALID_ENUM), GL_FALSE;
  return GLboolean(on);
}

void Context::set_client_state(GLenum array, bool on) {
  if (!outside_begin_end_keeping_vertices()) return;
  ClientArray* a = array == GL_VERTEX_ARRAY   ? &vertex_array_
                   : array == GL_NORMAL_ARRAY ? &normal_array_
                   : array == GL_COLOR_ARRAY  ? &color_array_
                                              : nullptr;
  if (!a) {
    if (find_enable(kOtherArrays, array)) other_enables_[array] = on;
    else error(GL_INVALID_ENUM);
    if (array == GL_TEXTURE_COORD_ARRAY) texcoord_array_.enabled = on;  // kept here too for the fetch
    return;
  }
  a->enabled = on;
}

}  // namespace ffc::state
