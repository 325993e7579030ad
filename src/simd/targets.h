// The Highway targets our vector code is compiled for (the raster kernels, the vertex stage's
// columns, the index range): all Highway attains, but SVE's (their vectors have no size known to
// the compiler and cannot be members of our structs or arrays: broadcast planes, column blocks);
// on AArch64 NEON runs. Included before hwy/foreach_target.h; each file's dispatch table
// holds only what that file compiled, so this choice is local to the files that include it.
#pragma once
#ifndef HWY_DISABLED_TARGETS
#define HWY_DISABLED_TARGETS (HWY_SVE | HWY_SVE2 | HWY_SVE_256 | HWY_SVE2_128)
#endif
