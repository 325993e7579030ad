// Which instructions our code may name. On x86-64 the portable loops use SSE2 intrinsics (every
// x86-64 CPU has them); the vector kernels are Highway's (raster/wide/), compiled for every
// target and chosen at run time. Everywhere else, and on x86 when built with FFCOMPAT_PORTABLE (the CMake option of
// that name, to test them there), every use of intrinsics gives way to a plain C++ twin with the
// same bits: the reference rasterizer (raster/reference.cpp) and the bit-for-bit tests hold both.
#pragma once

#if (defined(__x86_64__) || (defined(__i386__) && defined(__SSE2__))) && !defined(FFCOMPAT_PORTABLE)
#define FFCOMPAT_X86 1
#else
#define FFCOMPAT_X86 0
#endif
