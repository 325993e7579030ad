// The Highway targets the raster kernels are compiled for: all Highway attains, but SVE's (their
// vectors have no size known to the compiler and cannot be members of our structs of broadcast
// planes); on AArch64 NEON runs. Included before hwy/foreach_target.h; each file's dispatch table
// holds only what that file compiled, so this choice is local to the files that include it.
#pragma once
#ifndef HWY_DISABLED_TARGETS
#define HWY_DISABLED_TARGETS (HWY_SVE | HWY_SVE2 | HWY_SVE_256 | HWY_SVE2_128)
#endif
