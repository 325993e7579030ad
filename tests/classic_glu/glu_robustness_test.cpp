// ffcompat's libGLU on bad input and in its unimplemented parts (glu_robustness.c): no crash,
// failures as return values, nothing drawn without a quadric, and one stderr line per
// unimplemented entry point, however often it is called.
#include "probe_output.h"

#include <gtest/gtest.h>

#include <algorithm>

#ifdef FFCOMPAT_GLU_ROBUSTNESS_PROBE

namespace {

size_t count_line(const std::vector<std::string> &lines, const std::string &line) {
  return size_t(std::count(lines.begin(), lines.end(), line));
}

}  // namespace

TEST(ClassicGlu, BadInputFailsWithoutCrashingAndUnimplementedCallsSaySoOnce) {
  const ffc::test::ProbeOutput out = ffc::test::run_probe(std::string(FFCOMPAT_GLU_ROBUSTNESS_PROBE) + " 2>&1");
  ASSERT_EQ(out.status, 0);
  const std::vector<std::string> expected = {
      "project 0", "project out 0", "unproject 0", "unproject4 0", "no such error 1", "null extension 0",
      "tess 1",    "tess property 0", "nurbs 1",   "mipmaps 100904", "scale 100904", "done"};
  for (const std::string &line : expected) EXPECT_EQ(count_line(out.lines, line), 1u) << line;
  // Nothing reached GL: no quadric, no pick matrix.
  EXPECT_EQ(ffc::test::count_prefix(out.lines, "Begin"), 0u);
  EXPECT_EQ(ffc::test::count_prefix(out.lines, "Translatef"), 0u);
  const std::string says = " is not implemented by ffcompat's libGLU: it draws and builds nothing";
  for (const char *name : {"gluNewTess", "gluTessBeginPolygon", "gluTessVertex", "gluGetTessProperty",
                           "gluDeleteTess", "gluNewNurbsRenderer", "gluBuild2DMipmaps", "gluScaleImage"})
    EXPECT_EQ(count_line(out.lines, std::string("ffcompat: ") + name + says), 1u) << name;
}

#endif
