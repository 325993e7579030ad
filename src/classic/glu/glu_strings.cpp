// gluErrorString, gluGetString and gluCheckExtension, with the very strings of the system GLU
// (Debian's libGLU 9.0.2), so that programs printing them print the same lines.
#include "glu_export.h"

#include <cstring>

namespace {

struct ErrorText {
  GLenum code;
  const char *text;
};

// GL's own errors, then GLU's; the tessellator's and the NURBS renderer's have their own tables.
constexpr ErrorText kErrors[] = {
    {GL_NO_ERROR, "no error"},
    {GL_INVALID_ENUM, "invalid enumerant"},
    {GL_INVALID_VALUE, "invalid value"},
    {GL_INVALID_OPERATION, "invalid operation"},
    {GL_STACK_OVERFLOW, "stack overflow"},
    {GL_STACK_UNDERFLOW, "stack underflow"},
    {GL_OUT_OF_MEMORY, "out of memory"},
    {0x0506 /* GL_INVALID_FRAMEBUFFER_OPERATION */, "invalid framebuffer operation"},
    {GLU_INVALID_ENUM, "invalid enumerant"},
    {GLU_INVALID_VALUE, "invalid value"},
    {GLU_OUT_OF_MEMORY, "out of memory"},
    {GLU_INCOMPATIBLE_GL_VERSION, "incompatible gl version"},
    {GLU_INVALID_OPERATION, "invalid operation"},
};

// GLU_TESS_ERROR1 .. GLU_TESS_ERROR6 (100151..100156).
constexpr const char *kTessErrors[] = {
    "gluTessBeginPolygon() must precede a gluTessEndPolygon()",
    "gluTessBeginContour() must precede a gluTessEndContour()",
    "gluTessEndPolygon() must follow a gluTessBeginPolygon()",
    "gluTessEndContour() must follow a gluTessBeginContour()",
    "a coordinate is too large",
    "need combine callback",
};

// GLU_NURBS_ERROR1 .. GLU_NURBS_ERROR37 (100251..100287), spelling included.
constexpr const char *kNurbsErrors[] = {
    "spline order un-supported",
    "too few knots",
    "valid knot range is empty",
    "decreasing knot sequence knot",
    "knot multiplicity greater than order of spline",
    "gluEndCurve() must follow gluBeginCurve()",
    "gluBeginCurve() must precede gluEndCurve()",
    "missing or extra geometric data",
    "can't draw piecewise linear trimming curves",
    "missing or extra domain data",
    "missing or extra domain data",
    "gluEndTrim() must precede gluEndSurface()",
    "gluBeginSurface() must precede gluEndSurface()",
    "curve of improper type passed as trim curve",
    "gluBeginSurface() must precede gluBeginTrim()",
    "gluEndTrim() must follow gluBeginTrim()",
    "gluBeginTrim() must precede gluEndTrim()",
    "invalid or missing trim curve",
    "gluBeginTrim() must precede gluPwlCurve()",
    "piecewise linear trimming curve referenced twice",
    "piecewise linear trimming curve and nurbs curve mixed",
    "improper usage of trim data type",
    "nurbs curve referenced twice",
    "nurbs curve and piecewise linear trimming curve mixed",
    "nurbs surface referenced twice",
    "invalid property",
    "gluEndSurface() must follow gluBeginSurface()",
    "intersecting or misoriented trim curves",
    "intersecting trim curves",
    "UNUSED",
    "unconnected trim curves",
    "unknown knot error",
    "negative vertex count encountered",
    "negative byte-stride encounteed",
    "unknown type descriptor",
    "null control point reference",
    "duplicate point on piecewise linear trimming curve",
};

const GLubyte *bytes(const char *text) { return reinterpret_cast<const GLubyte *>(text); }

}  // namespace

FFC_GLU_EXPORT const GLubyte *GLAPIENTRY gluErrorString(GLenum error) {
  for (const ErrorText &e : kErrors)
    if (e.code == error) return bytes(e.text);
  constexpr GLenum tess_count = sizeof(kTessErrors) / sizeof(kTessErrors[0]);
  constexpr GLenum nurbs_count = sizeof(kNurbsErrors) / sizeof(kNurbsErrors[0]);
  if (error >= GLU_TESS_ERROR1 && error < GLU_TESS_ERROR1 + tess_count)
    return bytes(kTessErrors[error - GLU_TESS_ERROR1]);
  if (error >= GLU_NURBS_ERROR1 && error < GLU_NURBS_ERROR1 + nurbs_count)
    return bytes(kNurbsErrors[error - GLU_NURBS_ERROR1]);
  return nullptr;
}

FFC_GLU_EXPORT const GLubyte *GLAPIENTRY gluGetString(GLenum name) {
  // The extension string names what the system GLU offers, trailing space included, so that
  // programs probing it take the same branches; the entry points behind them report themselves.
  if (name == GLU_VERSION) return bytes("1.3");
  if (name == GLU_EXTENSIONS) return bytes("GLU_EXT_nurbs_tessellator GLU_EXT_object_space_tess ");
  return nullptr;
}

FFC_GLU_EXPORT GLboolean GLAPIENTRY gluCheckExtension(const GLubyte *extName, const GLubyte *extString) {
  if (extName == nullptr || extString == nullptr) return GL_FALSE;
  const char *name = reinterpret_cast<const char *>(extName);
  const size_t length = std::strlen(name);
  // An empty name, or one with a space, is never an extension (as the system GLU answers).
  if (length == 0 || std::strchr(name, ' ') != nullptr) return GL_FALSE;
  // Whole space-separated words only: "a" is not found in "ab".
  for (const char *p = reinterpret_cast<const char *>(extString); *p != '\0';) {
    const size_t word = std::strcspn(p, " ");
    if (word == length && std::strncmp(p, name, length) == 0) return GL_TRUE;
    p += word;
    if (*p == ' ') ++p;
  }
  return GL_FALSE;
}
