/* stderr captured into `captured` while a few calls run, for the tests of the lines libGL.so.1
 * prints (unsupported.c, glsl_unsupported.c). */
#ifndef CAPTURE_STDERR_H
#define CAPTURE_STDERR_H
#include <stdio.h>
#include <string.h>
#include <unistd.h>

static char captured[4096];
static FILE* capture_file;
static int capture_saved;

static void capture_begin(void) {
  fflush(stderr);
  capture_file = tmpfile();
  capture_saved = dup(2);
  dup2(fileno(capture_file), 2);
}

static void capture_end(void) {
  fflush(stderr);
  dup2(capture_saved, 2);
  close(capture_saved);
  rewind(capture_file);
  const size_t n = fread(captured, 1, sizeof captured - 1, capture_file);
  captured[n] = 0;
  fclose(capture_file);
}

/* How many times `what` occurs in what was captured. */
static int lines_naming(const char* what) {
  int n = 0;
  for (const char* p = captured; (p = strstr(p, what)); p += strlen(what)) ++n;
  return n;
}
#endif
