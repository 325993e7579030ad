// Running a stream on one side (Mesa through OSMesa, or our context) in a forked child with a time
// limit: a crash or hang of either GL is reported with the call it happened in, never fatal to the
// tester. What the child saw comes back through a pipe: the error after every call, the values
// calls returned, every checkpoint's read-back, the output buffers (glGet*, feedback,
// glReadPixels) and the picture at the end.
#pragma once
#include <GL/gl.h>

#include <cstdint>
#include <string>
#include <vector>

#include "difftest/stream.h"

namespace ffc::difftest {

enum class Side { Mesa, Soft };
const char* side_name(Side s);

struct RunOptions {
  int width = 32, height = 32;  // the framebuffer
  double timeout = 10;          // seconds a side may take before it counts as hung
  bool isolate = true;          // false: run in this process (a crash then ends it)
  // Test hooks: the child kills itself with SIGSEGV, or spins forever, at this call.
  int crash_at = -1, hang_at = -1;
};

// An output buffer after the run, decoded to numbers: floats, doubles and integers as they are,
// glReadPixels' pixels normalised to [0, 1] by their type (so one 8-bit step is 1/255).
struct Output {
  int call = 0;
  std::vector<double> values;
};

struct SideResult {
  enum class Status { Ok, Crashed, Hung } status = Status::Ok;
  int call = -1;      // Crashed, Hung: the call running (== stream size: in the read-back at the end)
  std::string what;   // Crashed: the signal or exception
  std::vector<GLenum> errors;   // glGetError after each call (a checkpoint's: the read-back's)
  std::vector<double> returns;  // what each call returned (NaN for void)
  std::vector<std::vector<double>> checkpoints;
  std::vector<Output> outputs;
  int width = 0, height = 0;
  std::vector<uint8_t> pixels;  // RGBA8, top row first
  std::vector<std::string> deviations;  // soft: Context::deviations() after the run
  double seconds = 0;
};

SideResult run_side(const Stream& s, Side side, const RunOptions& o = {});

// Runs the stream on the current context, with the dispatch bound to `side` (the child's work;
// exposed so a test can run a stream in process). `progress` receives each call's index as it
// starts.
SideResult execute(const Stream& s, Side side, const RunOptions& o, volatile int* progress);

}  // namespace ffc::difftest
