// Differential harness for GL state: runs one call sequence on Mesa (the oracle) and on our
// context, each in a fresh context in GL's default state, and compares the error codes and a
// read-back of every piece of state the context can report (glGet*, glGetLightfv,
// glGetMaterialfv, glIsEnabled).
#pragma once
#include <GL/osmesa.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "backends/backend.h"
#include "gl/dispatch.h"
#include "state/soft_gl.h"

namespace ffc::state_test {

enum Side { kMesa, kSoft };
inline const char* side_name(Side s) { return s == kMesa ? "mesa" : "soft"; }

// ---------------------------------------------------------------- enum names, for messages

inline const std::unordered_map<GLenum, const char*>& enum_names() {
#define N(e) {e, #e}
  static const std::unordered_map<GLenum, const char*> names = {
      N(GL_NO_ERROR), N(GL_INVALID_ENUM), N(GL_INVALID_VALUE), N(GL_INVALID_OPERATION), N(GL_STACK_OVERFLOW),
      N(GL_STACK_UNDERFLOW), N(GL_OUT_OF_MEMORY),
      N(GL_LIGHT0), N(GL_LIGHT1), N(GL_LIGHT2), N(GL_LIGHT3), N(GL_LIGHT4), N(GL_LIGHT5), N(GL_LIGHT6),
      N(GL_LIGHT7), N(GL_FRONT), N(GL_BACK), N(GL_AMBIENT), N(GL_DIFFUSE), N(GL_SPECULAR), N(GL_POSITION),
      N(GL_SPOT_DIRECTION), N(GL_SPOT_EXPONENT), N(GL_SPOT_CUTOFF), N(GL_CONSTANT_ATTENUATION),
      N(GL_LINEAR_ATTENUATION), N(GL_QUADRATIC_ATTENUATION), N(GL_EMISSION), N(GL_SHININESS),
      N(GL_COLOR_INDEXES), N(GL_MODELVIEW_MATRIX), N(GL_PROJECTION_MATRIX), N(GL_MODELVIEW_STACK_DEPTH),
      N(GL_PROJECTION_STACK_DEPTH), N(GL_MAX_MODELVIEW_STACK_DEPTH), N(GL_MAX_PROJECTION_STACK_DEPTH),
      N(GL_MATRIX_MODE), N(GL_VIEWPORT), N(GL_DEPTH_RANGE), N(GL_MAX_LIGHTS), N(GL_LIGHT_MODEL_AMBIENT),
      N(GL_LIGHT_MODEL_LOCAL_VIEWER), N(GL_LIGHT_MODEL_TWO_SIDE), N(GL_LIGHT_MODEL_COLOR_CONTROL),
      N(GL_SHADE_MODEL), N(GL_COLOR_MATERIAL_FACE), N(GL_COLOR_MATERIAL_PARAMETER), N(GL_FRONT_FACE),
      N(GL_CULL_FACE_MODE), N(GL_DEPTH_FUNC), N(GL_CURRENT_COLOR), N(GL_CURRENT_NORMAL),
      N(GL_COLOR_CLEAR_VALUE), N(GL_DEPTH_CLEAR_VALUE), N(GL_LINE_WIDTH), N(GL_POINT_SIZE),
      N(GL_POINT_SIZE_RANGE), N(GL_POINT_SIZE_GRANULARITY), N(GL_ALIASED_POINT_SIZE_RANGE), N(GL_RENDER_MODE), N(GL_DEPTH_BITS),
      N(GL_RED_BITS), N(GL_GREEN_BITS), N(GL_BLUE_BITS), N(GL_ALPHA_BITS), N(GL_VERTEX_ARRAY_SIZE),
      N(GL_VERTEX_ARRAY_TYPE), N(GL_VERTEX_ARRAY_STRIDE), N(GL_NORMAL_ARRAY_TYPE), N(GL_NORMAL_ARRAY_STRIDE),
      N(GL_COLOR_ARRAY_SIZE), N(GL_COLOR_ARRAY_TYPE), N(GL_COLOR_ARRAY_STRIDE), N(GL_VERTEX_ARRAY),
      N(GL_NORMAL_ARRAY), N(GL_COLOR_ARRAY), N(GL_LIGHTING), N(GL_NORMALIZE), N(GL_RESCALE_NORMAL),
      N(GL_COLOR_MATERIAL), N(GL_DEPTH_TEST), N(GL_CULL_FACE), N(GL_BLEND), N(GL_DITHER), N(GL_LINE_SMOOTH),
      N(GL_POINT_SMOOTH), N(GL_POLYGON_SMOOTH), N(GL_SCISSOR_TEST), N(GL_STENCIL_TEST), N(GL_ALPHA_TEST),
      N(GL_FOG), N(GL_TEXTURE_2D), N(GL_MULTISAMPLE), N(GL_POLYGON_OFFSET_FILL), N(GL_LINE_STIPPLE),
      N(GL_PACK_ALIGNMENT), N(GL_UNPACK_ALIGNMENT), N(GL_FEEDBACK_BUFFER_SIZE), N(GL_FEEDBACK_BUFFER_TYPE),
      N(GL_TEXTURE_COORD_ARRAY), N(GL_INDEX_ARRAY), N(GL_EDGE_FLAG_ARRAY), N(GL_RENDER), N(GL_FEEDBACK),
      N(GL_SELECT), N(GL_FOG_COORD_ARRAY), N(GL_SECONDARY_COLOR_ARRAY), N(GL_AUTO_NORMAL), N(GL_CLIP_PLANE0),
      N(GL_CLIP_PLANE1), N(GL_CLIP_PLANE2), N(GL_CLIP_PLANE3), N(GL_CLIP_PLANE4), N(GL_CLIP_PLANE5),
      {GL_CLIP_PLANE0 + 6, "GL_CLIP_PLANE6"}, {GL_CLIP_PLANE0 + 7, "GL_CLIP_PLANE7"}, N(GL_COLOR_LOGIC_OP),
      N(GL_COLOR_SUM), N(GL_INDEX_LOGIC_OP), N(GL_MAP1_COLOR_4), N(GL_MAP1_INDEX), N(GL_MAP1_NORMAL),
      N(GL_MAP1_TEXTURE_COORD_1), N(GL_MAP1_TEXTURE_COORD_2), N(GL_MAP1_TEXTURE_COORD_3),
      N(GL_MAP1_TEXTURE_COORD_4), N(GL_MAP1_VERTEX_3), N(GL_MAP1_VERTEX_4), N(GL_MAP2_COLOR_4), N(GL_MAP2_INDEX),
      N(GL_MAP2_NORMAL), N(GL_MAP2_TEXTURE_COORD_1), N(GL_MAP2_TEXTURE_COORD_2), N(GL_MAP2_TEXTURE_COORD_3),
      N(GL_MAP2_TEXTURE_COORD_4), N(GL_MAP2_VERTEX_3), N(GL_MAP2_VERTEX_4), N(GL_POINT_SPRITE),
      N(GL_POLYGON_OFFSET_LINE), N(GL_POLYGON_OFFSET_POINT), N(GL_POLYGON_STIPPLE), N(GL_SAMPLE_ALPHA_TO_COVERAGE),
      N(GL_SAMPLE_ALPHA_TO_ONE), N(GL_SAMPLE_COVERAGE), N(GL_TEXTURE_1D), N(GL_TEXTURE_3D), N(GL_TEXTURE_CUBE_MAP),
      N(GL_TEXTURE_GEN_S), N(GL_TEXTURE_GEN_T), N(GL_TEXTURE_GEN_R), N(GL_TEXTURE_GEN_Q),
      N(GL_VERTEX_PROGRAM_POINT_SIZE), N(GL_VERTEX_PROGRAM_TWO_SIDE), N(GL_TEXTURE), N(GL_MODELVIEW),
      N(GL_PROJECTION), N(GL_2D), N(GL_3D), N(GL_3D_COLOR), N(GL_SMOOTH), N(GL_FLAT), N(GL_CW), N(GL_CCW),
      N(GL_FRONT_AND_BACK), N(GL_AMBIENT_AND_DIFFUSE), N(GL_SINGLE_COLOR), N(GL_SEPARATE_SPECULAR_COLOR),
      N(GL_PACK_SWAP_BYTES), N(GL_PACK_LSB_FIRST), N(GL_PACK_ROW_LENGTH), N(GL_PACK_IMAGE_HEIGHT),
      N(GL_PACK_SKIP_ROWS), N(GL_PACK_SKIP_PIXELS), N(GL_PACK_SKIP_IMAGES), N(GL_UNPACK_SWAP_BYTES),
      N(GL_UNPACK_LSB_FIRST), N(GL_UNPACK_ROW_LENGTH), N(GL_UNPACK_IMAGE_HEIGHT), N(GL_UNPACK_SKIP_ROWS),
      N(GL_UNPACK_SKIP_PIXELS), N(GL_UNPACK_SKIP_IMAGES),
      N(GL_FLOAT), N(GL_DOUBLE), N(GL_SHORT), N(GL_INT), N(GL_BYTE), N(GL_UNSIGNED_BYTE),
  };
#undef N
  return names;
}

inline std::string enum_name(GLenum e) {
  const auto& n = enum_names();
  if (auto it = n.find(e); it != n.end()) return it->second;
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%04X", e);
  return buf;
}

// ---------------------------------------------------------------- contexts

// Entry points that src/gl/gl_functions.inc does not list, resolved from each side's loader.
struct Extra {
  void(APIENTRY* Lightiv)(GLenum, GLenum, const GLint*) = nullptr;
  void(APIENTRY* LightModeliv)(GLenum, const GLint*) = nullptr;
  void(APIENTRY* Materialiv)(GLenum, GLenum, const GLint*) = nullptr;
};
inline Extra& ext() {
  static Extra e;
  return e;
}

constexpr int kWidth = 16, kHeight = 16;

// Both backends, made once per process and destroyed when the tests end (a global test
// environment's TearDown). Not static objects: Mesa's own exit handlers stop llvmpipe's threads
// before static destructors run, and OSMesaDestroyContext after that crashes.
struct Backends : ::testing::Environment {
  std::unique_ptr<backends::Backend> mesa, soft;
  void TearDown() override { mesa.reset(), soft.reset(); }
};
inline Backends& backends_env() {
  static Backends* env = static_cast<Backends*>(::testing::AddGlobalTestEnvironment(new Backends));
  return *env;
}
inline const bool kBackendsRegistered = (backends_env(), true);  // registered before RUN_ALL_TESTS

inline backends::Backend& backend(Side s) {
  Backends& b = backends_env();
  if (!b.mesa) b.mesa = backends::make("mesa"), b.soft = backends::make("soft");
  return s == kMesa ? *b.mesa : *b.soft;
}

// A fresh context on side s, in GL's default state, with the dispatch pointing at it.
inline void fresh_context(Side s) {
  backend(s).begin(kWidth, kHeight);
  auto load = [s](const char* name) -> void* {
    return s == kMesa ? reinterpret_cast<void*>(OSMesaGetProcAddress(name)) : state::proc_address(name);
  };
  Extra& e = ext();
  e.Lightiv = reinterpret_cast<decltype(e.Lightiv)>(load("glLightiv"));
  e.LightModeliv = reinterpret_cast<decltype(e.LightModeliv)>(load("glLightModeliv"));
  e.Materialiv = reinterpret_cast<decltype(e.Materialiv)>(load("glMaterialiv"));
  if (!e.Lightiv || !e.LightModeliv || !e.Materialiv)
    throw std::runtime_error(std::string(side_name(s)) + ": glLightiv/glLightModeliv/glMaterialiv missing");
}

// ---------------------------------------------------------------- the read-back

enum class Query { Lightfv, Materialfv, Doublev, Floatv, Integerv, IsEnabled };

struct Probe {
  Query q;
  GLenum a, b;  // light or face and pname; pname or cap (b unused)
  int slots;    // values read back, sentinel-initialised (a short write shows as the sentinel)
};

inline std::string probe_name(const Probe& p) {
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

inline const std::vector<GLenum>& light_pnames() {
  static const std::vector<GLenum> v = {GL_AMBIENT,       GL_DIFFUSE,     GL_SPECULAR,
                                        GL_POSITION,      GL_SPOT_DIRECTION, GL_SPOT_EXPONENT,
                                        GL_SPOT_CUTOFF,   GL_CONSTANT_ATTENUATION, GL_LINEAR_ATTENUATION,
                                        GL_QUADRATIC_ATTENUATION};
  return v;
}
inline const std::vector<GLenum>& material_pnames() {
  static const std::vector<GLenum> v = {GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION, GL_SHININESS, GL_COLOR_INDEXES};
  return v;
}
// Every glGet pname the context reports (Context::GetDoublev's list).
inline const std::vector<GLenum>& get_pnames() {
  static const std::vector<GLenum> v = {
      GL_MODELVIEW_MATRIX, GL_PROJECTION_MATRIX, GL_MODELVIEW_STACK_DEPTH, GL_PROJECTION_STACK_DEPTH,
      GL_MAX_MODELVIEW_STACK_DEPTH, GL_MAX_PROJECTION_STACK_DEPTH, GL_MATRIX_MODE, GL_VIEWPORT, GL_DEPTH_RANGE,
      GL_MAX_LIGHTS, GL_LIGHT_MODEL_AMBIENT, GL_LIGHT_MODEL_LOCAL_VIEWER, GL_LIGHT_MODEL_TWO_SIDE,
      GL_LIGHT_MODEL_COLOR_CONTROL, GL_SHADE_MODEL, GL_COLOR_MATERIAL_FACE, GL_COLOR_MATERIAL_PARAMETER,
      GL_FRONT_FACE, GL_CULL_FACE_MODE, GL_DEPTH_FUNC, GL_CURRENT_COLOR, GL_CURRENT_NORMAL, GL_COLOR_CLEAR_VALUE,
      GL_DEPTH_CLEAR_VALUE, GL_LINE_WIDTH, GL_POINT_SIZE, GL_POINT_SIZE_RANGE, GL_POINT_SIZE_GRANULARITY,
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
      GL_POLYGON_OFFSET_FACTOR, GL_POLYGON_OFFSET_UNITS};
  return v;
}
// Every capability glIsEnabled answers for: the modelled ones, the client arrays, and those GL
// knows that the pipeline accepts without modelling.
inline const std::vector<GLenum>& caps() {
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
// The client arrays among caps().
inline bool is_client_array(GLenum c) {
  return c == GL_VERTEX_ARRAY || c == GL_NORMAL_ARRAY || c == GL_COLOR_ARRAY || c == GL_TEXTURE_COORD_ARRAY ||
         c == GL_INDEX_ARRAY || c == GL_EDGE_FLAG_ARRAY || c == GL_FOG_COORD_ARRAY || c == GL_SECONDARY_COLOR_ARRAY;
}

inline const std::vector<Probe>& probes() {
  static const std::vector<Probe> v = [] {
    std::vector<Probe> p;
    for (int i = 0; i < 8; ++i)
      for (GLenum pn : light_pnames()) p.push_back({Query::Lightfv, GLenum(GL_LIGHT0 + i), pn, 4});
    for (GLenum f : {GL_FRONT, GL_BACK})
      for (GLenum pn : material_pnames()) p.push_back({Query::Materialfv, f, pn, 4});
    for (Query q : {Query::Doublev, Query::Floatv, Query::Integerv}) {
      for (GLenum pn : get_pnames()) p.push_back({q, pn, 0, 16});
      for (GLenum c : caps())  // every capability is a glGet value too
        if (std::find(get_pnames().begin(), get_pnames().end(), c) == get_pnames().end()) p.push_back({q, c, 0, 16});
    }
    for (GLenum c : caps()) p.push_back({Query::IsEnabled, c, 0, 1});
    return p;
  }();
  return v;
}

constexpr double kSentinel = -7777;

// Runs one probe on the current context, appending p.slots values.
inline void read_probe(const Probe& p, std::vector<double>& out) {
  switch (p.q) {
    case Query::Lightfv: case Query::Materialfv: case Query::Floatv: {
      GLfloat v[16];
      std::fill(v, v + 16, GLfloat(kSentinel));
      if (p.q == Query::Lightfv) glGetLightfv(p.a, p.b, v);
      else if (p.q == Query::Materialfv) glGetMaterialfv(p.a, p.b, v);
      else glGetFloatv(p.a, v);
      out.insert(out.end(), v, v + p.slots);
      break;
    }
    case Query::Doublev: {
      GLdouble v[16];
      std::fill(v, v + 16, kSentinel);
      glGetDoublev(p.a, v);
      out.insert(out.end(), v, v + p.slots);
      break;
    }
    case Query::Integerv: {
      GLint v[16];
      std::fill(v, v + 16, GLint(kSentinel));
      glGetIntegerv(p.a, v);
      out.insert(out.end(), v, v + p.slots);
      break;
    }
    case Query::IsEnabled: out.push_back(glIsEnabled(p.a)); break;
  }
}

// The whole read-back: one value per probe slot, then the error the read-back itself raised
// (which must be GL_NO_ERROR).
struct Snapshot {
  std::vector<double> values;
  GLenum probe_error = GL_NO_ERROR;
};

inline Snapshot snapshot() {
  Snapshot s;
  s.values.reserve(2048);
  for (const Probe& p : probes()) read_probe(p, s.values);
  s.probe_error = glGetError();
  return s;
}

// How value i of a snapshot compares: values read back as floats or doubles within a relative
// tolerance; integers (glGetIntegerv, glIsEnabled) exactly, as the conversion is part of what is
// checked; but the matrices' integers (mapped like colours, from Mesa's float products) within the
// same tolerance relative to 2^31.
enum class SlotKind : char { Real, Integer, MatrixInteger };
inline SlotKind slot_kind(size_t i) {
  static const std::vector<SlotKind> v = [] {
    std::vector<SlotKind> r;
    for (const Probe& p : probes()) {
      SlotKind k = SlotKind::Real;
      if (p.q == Query::IsEnabled) k = SlotKind::Integer;
      if (p.q == Query::Integerv)
        k = p.a == GL_MODELVIEW_MATRIX || p.a == GL_PROJECTION_MATRIX ? SlotKind::MatrixInteger : SlotKind::Integer;
      r.insert(r.end(), p.slots, k);
    }
    return r;
  }();
  return i < v.size() ? v[i] : SlotKind::Real;
}

inline bool close(double a, double b, double rel);
// Whether values a and b of slot i agree within rel (see slot_kind).
inline bool slot_close(size_t i, double a, double b, double rel) {
  switch (slot_kind(i)) {
    case SlotKind::Real: return close(a, b, rel);
    case SlotKind::Integer: return a == b;
    case SlotKind::MatrixInteger: return std::fabs(a - b) <= rel * 2147483648.0;
  }
  return false;
}

// Label of value i of a snapshot.
inline std::string slot_name(size_t i) {
  for (const Probe& p : probes()) {
    if (i < size_t(p.slots)) return probe_name(p) + (p.slots > 1 ? "[" + std::to_string(i) + "]" : "");
    i -= p.slots;
  }
  return "?";
}

// Equal within rel relative to max(1, |a|, |b|); NaN equals NaN.
inline bool close(double a, double b, double rel) {
  if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
  if (a == b) return true;
  return std::fabs(a - b) <= rel * std::max({1.0, std::fabs(a), std::fabs(b)});
}

inline std::string num(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

// Compares two snapshots slot by slot; names up to 12 differing slots.
inline ::testing::AssertionResult same_state(const char* what_a, const Snapshot& a, const char* what_b,
                                             const Snapshot& b, double rel,
                                             const std::vector<std::string>& unchecked = {}) {
  std::string msg;
  int bad = 0;
  if (a.probe_error != GL_NO_ERROR || b.probe_error != GL_NO_ERROR) {
    msg += "\n  the read-back raised " + enum_name(a.probe_error) + " (" + what_a + ") / " +
           enum_name(b.probe_error) + " (" + what_b + ")";
    ++bad;
  }
  for (size_t i = 0; i < a.values.size() && i < b.values.size(); ++i) {
    if (slot_close(i, a.values[i], b.values[i], rel)) continue;
    if (!unchecked.empty() && std::find(unchecked.begin(), unchecked.end(), slot_name(i)) != unchecked.end()) continue;
    if (++bad <= 12)
      msg += "\n  " + slot_name(i) + ": " + what_a + " " + num(a.values[i]) + ", " + what_b + " " + num(b.values[i]);
  }
  if (bad == 0) return ::testing::AssertionSuccess();
  if (bad > 12) msg += "\n  ... and " + std::to_string(bad - 12) + " more";
  return ::testing::AssertionFailure() << what_a << " and " << what_b << " differ in " << bad << " values:" << msg;
}

// ---------------------------------------------------------------- running a case

// Values a case reads back itself (return values, output buffers), compared like the state.
struct Observed {
  std::vector<std::pair<std::string, double>> values;
};
inline Observed*& observed_sink() {
  static Observed* o = nullptr;
  return o;
}
inline void observe(const std::string& label, double v) {
  if (observed_sink()) observed_sink()->values.emplace_back(label, v);
}

struct Outcome {
  GLenum setup_error = GL_NO_ERROR;  // raised by the setup (must be none)
  GLenum error = GL_NO_ERROR;        // the first glGetError after the call
  GLenum error_after = GL_NO_ERROR;  // the second (must be none)
  Snapshot before, after;
  Observed observed;
};

using Calls = std::function<void()>;

inline Outcome run(Side s, const Calls& setup, const Calls& call) {
  Outcome o;
  fresh_context(s);
  if (setup) setup();
  o.setup_error = glGetError();
  while (glGetError() != GL_NO_ERROR) {
  }
  o.before = snapshot();
  observed_sink() = &o.observed;
  call();
  observed_sink() = nullptr;
  o.error = glGetError();
  o.error_after = glGetError();
  o.after = snapshot();
  return o;
}

// Where Mesa 22.3 departs from GL 2.1 in a row's outcome (the error code is Mesa's either way).
enum class Deviation {
  None,
  // Mesa records the error and then applies the call all the same; GL 2.1 section 2.5 says a
  // command that raises an error is ignored, and ours ignores it: our state after the call must
  // be Mesa's state before it, and Mesa's state must have changed (so a fixed Mesa shows).
  MesaAppliesOnError,
  // Mesa reads outside the client arrays (no error defined), leaving garbage in the current
  // values; ours ignores the call: our state after it must be Mesa's state before it.
  MesaReadsOutOfBounds,
};

// One row: a setup of valid calls, the call(s) under test, and the error Mesa raises for them
// (pinned, so a change in the oracle shows).
struct Case {
  std::string name;
  Calls setup;
  Calls call;
  GLenum mesa_error;
  Deviation deviation = Deviation::None;
  // Slots (as slot_name spells them) left out of the comparison with Mesa after the call, where
  // Mesa leaves undefined values (it passes uninitialised memory along).
  std::vector<std::string> unchecked = {};
};

inline std::string case_name(const ::testing::TestParamInfo<Case>& info) { return info.param.name; }
inline void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

// The comparison every row makes: Mesa raises the pinned error; ours raises the same; the next
// glGetError is GL_NO_ERROR on both; after an error the state read back is exactly what it was
// before the call (on both); and the state and observed values agree with Mesa's: within `rel`
// relative to max(1, |value|) (see slot_kind for the integers).
inline void check_case(const Case& c, double rel = 1e-6) {
  const Outcome m = run(kMesa, c.setup, c.call);
  const Outcome s = run(kSoft, c.setup, c.call);
  EXPECT_EQ(enum_name(m.setup_error), "GL_NO_ERROR") << "the setup raised an error on Mesa";
  EXPECT_EQ(enum_name(s.setup_error), "GL_NO_ERROR") << "the setup raised an error on soft";
  EXPECT_EQ(enum_name(m.error), enum_name(c.mesa_error)) << "Mesa's error is not the one pinned";
  EXPECT_EQ(enum_name(s.error), enum_name(m.error)) << "soft's error differs from Mesa's";
  EXPECT_EQ(enum_name(m.error_after), "GL_NO_ERROR") << "Mesa: second glGetError";
  EXPECT_EQ(enum_name(s.error_after), "GL_NO_ERROR") << "soft: second glGetError";
  EXPECT_TRUE(same_state("mesa", m.before, "soft", s.before, rel)) << "state before the call";
  if (c.deviation == Deviation::None) {
    if (c.mesa_error != GL_NO_ERROR) {
      EXPECT_TRUE(same_state("mesa before", m.before, "mesa after", m.after, 0)) << "Mesa changed state on error";
      EXPECT_TRUE(same_state("soft before", s.before, "soft after", s.after, 0)) << "soft changed state on error";
    }
    EXPECT_TRUE(same_state("mesa", m.after, "soft", s.after, rel, c.unchecked)) << "state after the call";
  } else {
    EXPECT_TRUE(same_state("soft before", s.before, "soft after", s.after, 0)) << "soft changed state";
    EXPECT_TRUE(same_state("mesa before", m.before, "soft after", s.after, rel)) << "soft's state after the call";
    if (c.deviation == Deviation::MesaAppliesOnError) {
      EXPECT_FALSE(same_state("mesa before", m.before, "mesa after", m.after, 0))
          << "Mesa no longer changes state on this error: drop the row's deviation";
    }
  }
  ASSERT_EQ(m.observed.values.size(), s.observed.values.size());
  for (size_t i = 0; i < m.observed.values.size(); ++i)
    EXPECT_TRUE(close(m.observed.values[i].second, s.observed.values[i].second, rel))
        << m.observed.values[i].first << ": mesa " << num(m.observed.values[i].second) << ", soft "
        << num(s.observed.values[i].second);
}

// ---------------------------------------------------------------- call helpers for the tables

// The calls `c`, between glBegin(GL_TRIANGLES) and glEnd.
inline Calls inside(Calls c) {
  return [c] {
    glBegin(GL_TRIANGLES);
    c();
    glEnd();
  };
}

inline void light4(GLenum l, GLenum p, float a, float b, float c, float d) {
  const GLfloat v[] = {a, b, c, d};
  glLightfv(l, p, v);
}
inline void light1(GLenum l, GLenum p, float a) { light4(l, p, a, 0, 0, 0); }
inline void lightiv4(GLenum l, GLenum p, GLint a, GLint b, GLint c, GLint d) {
  const GLint v[] = {a, b, c, d};
  ext().Lightiv(l, p, v);
}
inline void model4(GLenum p, float a, float b, float c, float d) {
  const GLfloat v[] = {a, b, c, d};
  glLightModelfv(p, v);
}
inline void modeliv4(GLenum p, GLint a, GLint b, GLint c, GLint d) {
  const GLint v[] = {a, b, c, d};
  ext().LightModeliv(p, v);
}
inline void material4(GLenum f, GLenum p, float a, float b, float c, float d) {
  const GLfloat v[] = {a, b, c, d};
  glMaterialfv(f, p, v);
}
inline void materialiv4(GLenum f, GLenum p, GLint a, GLint b, GLint c, GLint d) {
  const GLint v[] = {a, b, c, d};
  ext().Materialiv(f, p, v);
}

}  // namespace ffc::state_test
