/* Shared by the classic C test programs: they are linked with the system's -lGL, as a user's
 * program is, and run with build/classic first on LD_LIBRARY_PATH. The surface API is declared
 * weak, so the link succeeds against the system's libGL.so and each function is null unless
 * ffcompat's libGL.so.1 was the one loaded. */
#ifndef CLASSIC_TEST_H
#define CLASSIC_TEST_H
#include <GL/gl.h>
#include <stdio.h>
#include <stdlib.h>

#include "ffcompat_surface.h"

#pragma weak ffcompat_surface_create
#pragma weak ffcompat_surface_make_current
#pragma weak ffcompat_surface_read_rgba
#pragma weak ffcompat_surface_width
#pragma weak ffcompat_surface_height
#pragma weak ffcompat_surface_backend
#pragma weak ffcompat_surface_destroy
#pragma weak ffcompat_get_proc_address
#pragma weak ffcompat_surface_resize

static int failures = 0;
#define CHECK(cond, ...)                                          \
  do {                                                            \
    if (!(cond)) {                                                \
      fprintf(stdout, "%s:%d: FAILED: %s: ", __FILE__, __LINE__, #cond); \
      fprintf(stdout, __VA_ARGS__);                               \
      fprintf(stdout, "\n");                                      \
      ++failures;                                                 \
    }                                                             \
  } while (0)

/* Stops at once when the program is not running on ffcompat's libGL.so.1. */
static void require_ffcompat(void) {
  if (!ffcompat_surface_create) {
    printf("FAILED: the system's libGL.so.1 was loaded, not ffcompat's (is build/classic first on LD_LIBRARY_PATH?)\n");
    exit(1);
  }
}

/* A surface on the named backend (FFCOMPAT_BACKEND is how the library picks it). */
static ffcompat_surface* surface_on(const char* backend, int w, int h) {
  setenv("FFCOMPAT_BACKEND", backend, 1);
  ffcompat_surface* s = ffcompat_surface_create(w, h);
  if (!s) {
    printf("FAILED: no %s surface\n", backend);
    exit(1);
  }
  return s;
}

static inline int finish(void) {
  if (failures) printf("%d check(s) failed\n", failures);
  else printf("all checks passed\n");
  return failures ? 1 : 0;
}
#endif
