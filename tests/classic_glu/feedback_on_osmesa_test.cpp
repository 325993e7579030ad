// Our libGLU and GLUT shapes on a real GL: the probes run on OSMesa in feedback mode
// (feedback_harness.c), lit so that colours carry the normals; built on the system libraries and
// on ours, they must print the same lines and the same feedback (length and hash of its bytes).
#include "probe_output.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

namespace {

// The feedback line, checked to be there and to hold a real amount of geometry.
std::string feedback_line(const ffc::test::ProbeOutput &out, size_t at_least) {
  if (out.lines.empty() || out.lines.back().rfind("feedback ", 0) != 0) return "";
  const size_t values = std::strtoul(out.lines.back().c_str() + 9, nullptr, 10);
  return values >= at_least ? out.lines.back() : "";
}

}  // namespace

#ifdef FFCOMPAT_GLU_FEEDBACK_SYSTEM
TEST(ClassicGluOnOSMesa, QuadricsGiveTheSystemGlusFeedback) {
  const ffc::test::ProbeOutput system = ffc::test::run_probe(FFCOMPAT_GLU_FEEDBACK_SYSTEM);
  const ffc::test::ProbeOutput ours = ffc::test::run_probe(FFCOMPAT_GLU_FEEDBACK_OURS);
  ASSERT_EQ(system.status, 0);
  ASSERT_EQ(ours.status, 0);
  ASSERT_NE(feedback_line(system, 1000000), "") << "the system probe drew too little";
  EXPECT_NE(system.lines.back().find("error 0x0"), std::string::npos);
  EXPECT_PRED_FORMAT2(ffc::test::same_lines, system.lines, ours.lines);
}
#endif

#ifdef FFCOMPAT_GLUT_FEEDBACK_SYSTEM
TEST(ClassicGluOnOSMesa, GlutShapesAndTextGiveFreeglutsFeedback) {
  if (std::system("command -v xvfb-run > /dev/null 2>&1") != 0) GTEST_SKIP() << "xvfb-run is not installed";
  const ffc::test::ProbeOutput system =
      ffc::test::run_probe(std::string("xvfb-run -a ") + FFCOMPAT_GLUT_FEEDBACK_SYSTEM + " 2>/dev/null");
  const ffc::test::ProbeOutput ours = ffc::test::run_probe(std::string(FFCOMPAT_GLUT_FEEDBACK_OURS) + " 2>/dev/null");
  ASSERT_EQ(system.status, 0);
  ASSERT_EQ(ours.status, 0);
  ASSERT_NE(feedback_line(system, 1000000), "") << "the freeglut probe drew too little";
  EXPECT_NE(system.lines.back().find("error 0x0"), std::string::npos);
  EXPECT_PRED_FORMAT2(ffc::test::same_lines, system.lines, ours.lines);
}
#endif
