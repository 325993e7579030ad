// Differential harness for GL state: runs one call sequence on Mesa (the oracle) and on our
// context, each in a fresh context in GL's default state, and compares the error codes and a
// read-back of every piece of state the context can report (glGet*, glGetLightfv,
// glGetMaterialfv, glIsEnabled).
#pragma once
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
#include "backends/mesa/mesa_backend.h"
#include "difftest/probes.h"
#include "difftest/stream.h"
#include "gl/dispatch.h"
#include "state/soft_gl.h"

namespace ffc::state_test {

enum Side { kMesa, kSoft };
inline const char* side_name(Side s) { return s == kMesa ? "mesa" : "soft"; }

// ---------------------------------------------------------------- enum names, for messages

// The fuzzer's table (src/difftest/enums.cpp), "0x..." for others; 0 reads as GL_NO_ERROR here, as
// these messages name errors far more often than primitives.
inline std::string enum_name(GLenum e) { return difftest::error_name(e); }

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
    return s == kMesa ? backends::mesa_proc_address(static_cast<backends::MesaBackend&>(backend(kMesa)).platform(), name)
                      : state::proc_address(name);
  };
  Extra& e = ext();
  e.Lightiv = reinterpret_cast<decltype(e.Lightiv)>(load("glLightiv"));
  e.LightModeliv = reinterpret_cast<decltype(e.LightModeliv)>(load("glLightModeliv"));
  e.Materialiv = reinterpret_cast<decltype(e.Materialiv)>(load("glMaterialiv"));
  if (!e.Lightiv || !e.LightModeliv || !e.Materialiv)
    throw std::runtime_error(std::string(side_name(s)) + ": glLightiv/glLightModeliv/glMaterialiv missing");
}

// ---------------------------------------------------------------- the read-back

// The probes and their list are the library's (src/difftest/probes.h), shared with ffcompat fuzz.
using difftest::Probe;
using difftest::probes;
using difftest::probe_name;
using difftest::Query;
inline const std::vector<GLenum>& caps() { return difftest::capabilities(); }
// The client arrays among caps().
inline bool is_client_array(GLenum c) {
  return c == GL_VERTEX_ARRAY || c == GL_NORMAL_ARRAY || c == GL_COLOR_ARRAY || c == GL_TEXTURE_COORD_ARRAY ||
         c == GL_INDEX_ARRAY || c == GL_EDGE_FLAG_ARRAY || c == GL_FOG_COORD_ARRAY || c == GL_SECONDARY_COLOR_ARRAY;
}

struct Snapshot {
  std::vector<double> values;
  GLenum probe_error = GL_NO_ERROR;
};

inline Snapshot snapshot() {
  Snapshot s;
  s.values = difftest::read_back();
  s.probe_error = GLenum(s.values.back());  // read_back's last value: the error the read-back raised
  s.values.pop_back();
  return s;
}

inline bool slot_close(size_t i, double a, double b, double rel) { return difftest::slot_close(i, a, b, rel); }

inline std::string slot_name(size_t i) {
  for (const Probe& p : probes()) {
    if (i < size_t(p.slots)) return probe_name(p) + (p.slots > 1 ? "[" + std::to_string(i) + "]" : "");
    i -= p.slots;
  }
  return "?";
}

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

// The picture, every byte, as observed values (16 x 16 RGBA).
inline void observe_picture(const char* label) {
  static GLubyte px[kWidth * kHeight * 4];
  glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, px);
  for (size_t i = 0; i < sizeof px; ++i) observe(std::string(label) + "[" + std::to_string(i) + "]", px[i]);
}

// Feedback into a buffer of `size` floats: the count glRenderMode returns on leaving feedback
// mode (-1 on overflow), and the buffer with 8 floats past its end, which must stay untouched.
inline Calls feedback_into(GLsizei size, GLenum type, const Calls& draw) {
  return [=] {
    static GLfloat buf[520];  // size + 8 at most
    std::fill(std::begin(buf), std::end(buf), -7.0f);
    glFeedbackBuffer(size, type, buf);
    glRenderMode(GL_FEEDBACK);
    draw();
    observe("count", glRenderMode(GL_RENDER));
    for (GLsizei i = 0; i < size + 8; ++i) observe("buf[" + std::to_string(i) + "]", buf[i]);
  };
}

}  // namespace ffc::state_test
