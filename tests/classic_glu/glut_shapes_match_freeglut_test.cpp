// The GLUT shapes and text of ffcompat against freeglut 3.4.0: the probe (glut_probe.c) prints
// every GL call of every solid and wire shape (sizes, subdivisions, degenerate arguments), the
// teapot family across size changes, and every glyph and metric of the nine fonts; built on
// freeglut (run under xvfb-run, as glutInit needs a display) and on our sources, the outputs must
// be the same line for line, floats in exact hexadecimal.
#include "probe_output.h"

#include <gtest/gtest.h>

#include <cstdlib>

#ifdef FFCOMPAT_GLUT_PROBE_SYSTEM

TEST(ClassicGlut, ShapesAndTextMatchFreeglut) {
  if (std::system("command -v xvfb-run > /dev/null 2>&1") != 0) GTEST_SKIP() << "xvfb-run is not installed";
  const ffc::test::ProbeOutput system =
      ffc::test::run_probe(std::string("xvfb-run -a ") + FFCOMPAT_GLUT_PROBE_SYSTEM + " 2>/dev/null");
  const ffc::test::ProbeOutput ours = ffc::test::run_probe(std::string(FFCOMPAT_GLUT_PROBE_OURS) + " 2>/dev/null");
  ASSERT_EQ(system.status, 0) << "freeglut probe failed (no X display?)";
  ASSERT_EQ(ours.status, 0) << "our probe failed";
  // Every part must have drawn something for the comparison to mean anything.
  ASSERT_GT(ffc::test::count_prefix(system.lines, "DrawElements 0x"), 5000u);
  ASSERT_GT(ffc::test::count_prefix(system.lines, "DrawArrays 0x"), 100u);
  ASSERT_GT(ffc::test::count_prefix(system.lines, "Bitmap "), 1700u);
  ASSERT_GT(ffc::test::count_prefix(system.lines, "Translatef "), 200u);
  EXPECT_PRED_FORMAT2(ffc::test::same_lines, system.lines, ours.lines);
}

#endif
