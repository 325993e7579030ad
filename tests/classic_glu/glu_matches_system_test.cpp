// libGLU.so.1 of ffcompat against the system's: the probe (glu_probe.c) prints every GL call GLU
// makes for quadrics in every style, normal mode, orientation and texture setting, the matrices of
// the matrix helpers, projections and strings; built on either library, the two outputs must be
// the same, line for line (floats in exact hexadecimal).
#include "probe_output.h"

#include <gtest/gtest.h>

#ifdef FFCOMPAT_GLU_PROBE_SYSTEM

TEST(ClassicGlu, QuadricsMatricesAndStringsMatchTheSystemGlu) {
  const ffc::test::ProbeOutput system = ffc::test::run_probe(FFCOMPAT_GLU_PROBE_SYSTEM);
  const ffc::test::ProbeOutput ours = ffc::test::run_probe(FFCOMPAT_GLU_PROBE_OURS);
  ASSERT_EQ(system.status, 0) << "system probe failed";
  ASSERT_EQ(ours.status, 0) << "our probe failed";
  // The probe must have drawn something for the comparison to mean anything.
  ASSERT_GT(ffc::test::count_prefix(system.lines, "Begin 0x"), 10000u);
  // Of the six gluPerspective calls three are degenerate (no matrix); each gluLookAt gives one;
  // two of the four pick regions are valid (a translation and a scale each).
  ASSERT_EQ(ffc::test::count_prefix(system.lines, "MultMatrixd"), 3u);
  ASSERT_EQ(ffc::test::count_prefix(system.lines, "MultMatrixf"), 5u);
  ASSERT_EQ(ffc::test::count_prefix(system.lines, "Scalef"), 2u);
  EXPECT_PRED_FORMAT2(ffc::test::same_lines, system.lines, ours.lines);
}

// A program linked with the system's -lGLU, unchanged, loads ours when our folder comes first on
// the library path (same SONAME, same unversioned symbols), and prints the same.
TEST(ClassicGlu, AProgramLinkedWithTheSystemGluRunsOnOurs) {
  const std::string with_ours = std::string("LD_LIBRARY_PATH=") + FFCOMPAT_CLASSIC_GLU_DIR + " ";
  const ffc::test::ProbeOutput system = ffc::test::run_probe(FFCOMPAT_GLU_PROBE_SYSTEM);
  const ffc::test::ProbeOutput swapped = ffc::test::run_probe(with_ours + FFCOMPAT_GLU_PROBE_SYSTEM);
  const ffc::test::ProbeOutput loaded = ffc::test::run_probe(with_ours + "ldd " + FFCOMPAT_GLU_PROBE_SYSTEM);
  ASSERT_EQ(swapped.status, 0);
  // The loader took ours.
  bool ours_loaded = false;
  for (const std::string &line : loaded.lines)
    ours_loaded |= line.find("libGLU.so.1 => " FFCOMPAT_CLASSIC_GLU_DIR "/libGLU.so.1") != std::string::npos;
  EXPECT_TRUE(ours_loaded);
  EXPECT_PRED_FORMAT2(ffc::test::same_lines, system.lines, swapped.lines);
}

#endif
