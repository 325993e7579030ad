// Comparing what the two sides saw: the error after every call, the values calls returned, every
// checkpoint's read-back, the output buffers (feedback within 1e-5 a value, glReadPixels within
// one 8-bit step, glGet outputs within 1e-6 relative) and the final picture (one step).
#pragma once
#include <string>
#include <vector>

#include "difftest/runner.h"

namespace ffc::difftest {

struct Mismatch {
  // error, return, state, output, feedback, readpixels, pixels, crash, hang
  std::string kind;
  // The kind and what it concerns: "error glDepthRange", "state glGetFloatv(GL_DEPTH_RANGE)",
  // "crash soft glRasterPos2f". The shrinker keeps a stream that shows the same key.
  std::string key;
  int call = -1;       // the call it shows at (the checkpoint, the call of the buffer), -1: the end
  std::string detail;  // the values, for people
};

// Every distinct key the two runs differ in, in stream order. A side that crashed or hung gives
// one mismatch and nothing else is compared.
std::vector<Mismatch> compare(const Stream& s, const SideResult& mesa, const SideResult& soft);

}  // namespace ffc::difftest
