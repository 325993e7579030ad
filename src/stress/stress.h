// ffcompat stress: numerical stability on stiff and extreme inputs. A catalogue of small GL
// programs (scales of 1e-30 to 1e30, singular modelviews, zero and huge normals, degenerate
// spots and attenuations, NaN and Inf in the arrays, slivers, 1e20 coordinates, deep icospheres,
// 1x1 and 8192x8192 viewports, ...), each drawn on Mesa, on our float path and on our double
// reference, pictures and feedback both, and judged:
//
//   - ours (soft, soft-double) must never crash, never write a pixel from a non-finite colour and
//     never report a non-finite vertex in feedback;
//   - our float path is compared with our double reference (max_abs_vs_double);
//   - Mesa "agrees" when (1) feedback has the same primitives (count, token and vertex count of
//     each), (2) every colour channel of every feedback vertex is within 1e-4 of our float path's
//     (two non-finite values agree when they are the same: both NaN, or the same infinity), and
//     (3) every channel (RGBA) of every pixel is within one 8-bit step of our float path's picture.
//     Window positions are reported (max_position_px) but are not part of the agreement.
//     Mesa's feedback reports a clipped polygon (v0 .. vn) as the triangles (v_i, v_i+1, v0), ours as
//     one polygon: every backend's feedback is split that way (split_polygons) before comparing, and
//     each triangle is matched at the rotation of its vertices that best fits the window positions.
//
// Each case says, in its note, what OpenGL 2.1 (compatibility) specifies for it and what Mesa
// 22.3 does, and whether a difference from Mesa is allowed (the spec leaves the result undefined
// or unspecified) or is a known Mesa departure from the spec.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "check/feedback.h"
#include "image/image.h"

namespace ffc::stress {

// What Mesa is expected to do, decided from the spec and Mesa's source (the note says why).
enum class MesaExpectation {
  Agree,      // the spec defines the result: a difference from Mesa is a failure
  Undefined,  // the spec leaves it undefined or unspecified: a difference is "ok: ..."
  Deviation,  // Mesa departs from the spec here: a difference is "mesa-deviation: ..."
};

// One backend's run of a case: the picture, the feedback and what went wrong.
struct Run {
  bool ran = false;      // false: skipped
  bool crashed = false;  // threw, died on a signal or ran out of time
  std::string error;     // what happened when crashed
  image::Image image;
  std::vector<check::FeedbackPrimitive> feedback;  // polygons split into triangles (split_polygons)
  uint64_t nonfinite_fragments = 0;  // ours: fragments written from a non-finite colour (raster's count)
  unsigned gl_error = 0;             // the first glGetError after drawing (0: none)
  double seconds = 0;
};

// What the three backends did, for a case's own check.
struct Observed {
  Run mesa, soft, dbl;
};

struct Case {
  std::string name;
  std::string group;  // "scale", "normals", "material", "spot", "attenuation", "position", "viewer", "mesh", ...
  std::string note;   // what the spec says and what Mesa does
  int width = 64, height = 64;
  bool slow = false;  // in the catalogue, but skipped by the CI test
  std::function<void()> draw;  // plain gl* calls through the dispatch, from GL's default state
  MesaExpectation mesa = MesaExpectation::Agree;
  std::string mesa_reason;  // Undefined / Deviation: what the verdict says
  bool skip_mesa = false;   // Mesa is not run (the note says why)
  // Our float path against the double reference: up to 1e-4 is quiet; up to `float_limit` the
  // verdict mentions it with `float_reason`; beyond, the case fails.
  double float_limit = 1e-4;
  std::string float_reason;
  size_t feedback_hint = 0;  // floats of feedback to expect (0: a small buffer that grows)
  // A hand-derived expectation on what was observed: empty passes, otherwise what is wrong.
  std::function<std::string(const Observed&)> check;
};

// The whole catalogue, in order; names are unique.
const std::vector<Case>& catalogue();
const Case* find(const std::string& name);  // null when unknown

struct Options {
  bool mesa = true;      // run Mesa too
  bool isolate = true;   // each backend in a forked child, so a crash cannot take the suite down
  double timeout = 120;  // seconds per backend run (isolated runs only)
};

struct Result {
  std::string name, group;
  bool crashed = false;           // ours (soft or soft-double) threw or died
  uint64_t nan_pixels = 0;        // ours: fragments written from a non-finite colour, soft + soft-double
  uint64_t nan_vertices = 0;      // ours: feedback vertices with a non-finite position or colour
  uint64_t mesa_nan_vertices = 0;  // the same count in Mesa's feedback
  double max_abs_vs_double = 0;   // largest colour difference, our float path against the double one
  bool mesa_ran = false, mesa_crashed = false;
  bool mesa_agrees = false;
  std::string mesa_difference;  // why Mesa does not agree (empty when it does)
  double max_colour_vs_mesa = 0, max_position_px = 0;  // over matched feedback vertices
  double max_position_vs_double_px = 0;                // our float path's window positions against double
  int max_pixel_steps = 0;                             // largest channel difference of the pictures
  uint64_t differing_pixels = 0;                       // pixels more than one step apart
  size_t primitives[3] = {0, 0, 0};                    // feedback primitives: mesa, soft, soft-double
  unsigned gl_errors[3] = {0, 0, 0};                   // first glGetError after drawing, same order
  std::string check_failure;                           // the case's own check, when it failed
  std::string verdict, note;
  double seconds = 0;
  Observed observed;  // kept only when asked (run(..., keep = true))
};

Result run(const Case& c, const Options& o = {}, bool keep = false);

// Polygons of more than three vertices as the fan of triangles (v_i, v_i+1, v0), i = 1 .. n-2:
// how Mesa's feedback reports a clipped polygon. Points, lines and triangles are kept.
std::vector<check::FeedbackPrimitive> split_polygons(const std::vector<check::FeedbackPrimitive>& f);

// Vertices in feedback with a non-finite position or colour.
uint64_t nonfinite_vertices(const std::vector<check::FeedbackPrimitive>& f);

}  // namespace ffc::stress
