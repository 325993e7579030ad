// ffcompat's glad-style GL dispatch: every gl* call of a legacy program goes through a function
// pointer loaded from whichever context is current (Mesa through OSMesa or GLX, or ours later), so
// one source runs on any backend. Include this instead of <GL/gl.h>.
#pragma once
#include <GL/gl.h>  // types and enums only: the names below shadow its prototypes

#include <string>
#include <vector>

#define FFC_GL_FUNCTION(ret, name, params) extern ret(APIENTRY* ffc_gl##name) params;
#include "gl_functions.inc"
#undef FFC_GL_FUNCTION

#include "gl_names.inc"

namespace ffc::gl {

// Resolves a GL function name ("glBegin") to its address in the current context, or null.
using Loader = void* (*)(const char* name);

// Loads every entry point; returns the names the loader could not resolve (empty on success).
std::vector<std::string> load(Loader loader);

}  // namespace ffc::gl
