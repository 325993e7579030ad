#include "table.h"

#include <GL/gl.h>

#include <atomic>
#include <cstdio>

#include "state/context.h"

namespace ffc::classic {

const char* const kEntryNames[kEntryCount] = {
#define FFC_CLASSIC_GL(R, N, P, A, G) #N,
#include "gl_exports.inc"
#undef FFC_CLASSIC_GL
};

thread_local const Table* g_current __attribute__((tls_model("initial-exec"))) = nullptr;

namespace {
std::atomic<bool> g_reported[kEntryCount];
std::atomic<bool> g_reported_no_surface{false};
}  // namespace

void unavailable(Entry e) {
  const Table* t = g_current;
  if (!t) {
    // A program that calls GL before its window exists: say so once, do nothing.
    if (!g_reported_no_surface.exchange(true))
      std::fprintf(stderr, "ffcompat: %s called with no current GL surface; GL calls do nothing until one is made\n",
                   kEntryNames[e]);
    return;
  }
  if (t->soft) {
    if (state::Context* ctx = state::Context::current()) ctx->record_error(GL_INVALID_OPERATION);
    if (!g_reported[e].exchange(true))
      std::fprintf(stderr, "ffcompat: %s is not implemented by the %s backend; it records GL_INVALID_OPERATION\n",
                   kEntryNames[e], t->backend);
  } else if (!g_reported[e].exchange(true)) {
    std::fprintf(stderr, "ffcompat: %s is not provided by the %s backend; the call does nothing\n", kEntryNames[e],
                 t->backend);
  }
}

}  // namespace ffc::classic
