// The rest of the system libGLU's exports: the tessellator, the NURBS renderer, mipmap building
// and gluScaleImage. ffcompat does not implement them yet. Each exists with its exact prototype
// (a program linked against the system GLU loads ours without a missing symbol), says once on
// stderr that it is not implemented, draws nothing and returns GLU's error value where it has one.
#include "glu_export.h"

#include <cstdio>
#include <cstring>
#include <mutex>

// The objects handed out are real allocations (a program may store, compare and delete them),
// never dereferenced by the stubs below.
class GLUtesselator {
 public:
  int unused;
};
class GLUnurbs {
 public:
  int unused;
};

namespace {

// Once per name: the names are the literals of the stubs below, fewer than kMaxNames.
void not_implemented(const char *name) {
  constexpr int kMaxNames = 64;
  static std::mutex mutex;
  static const char *reported[kMaxNames];
  static int count = 0;
  std::lock_guard<std::mutex> lock(mutex);
  for (int i = 0; i < count; ++i)
    if (std::strcmp(reported[i], name) == 0) return;
  if (count < kMaxNames) reported[count++] = name;
  std::fprintf(stderr, "ffcompat: %s is not implemented by ffcompat's libGLU: it draws and builds nothing\n", name);
}

// The objects of gluNewTess / gluNewNurbsRenderer and their deletion.
template <class T>
T *create(const char *name) {
  not_implemented(name);
  return new T{};
}
template <class T>
void destroy(const char *name, T *object) {
  not_implemented(name);
  delete object;
}

}  // namespace

// ---- tessellator
FFC_GLU_EXPORT GLUtesselator *GLAPIENTRY gluNewTess(void) { return create<GLUtesselator>("gluNewTess"); }
FFC_GLU_EXPORT void GLAPIENTRY gluDeleteTess(GLUtesselator *tess) { destroy("gluDeleteTess", tess); }
FFC_GLU_EXPORT void GLAPIENTRY gluTessBeginPolygon(GLUtesselator *, GLvoid *) { not_implemented("gluTessBeginPolygon"); }
FFC_GLU_EXPORT void GLAPIENTRY gluTessBeginContour(GLUtesselator *) { not_implemented("gluTessBeginContour"); }
FFC_GLU_EXPORT void GLAPIENTRY gluTessVertex(GLUtesselator *, GLdouble *, GLvoid *) { not_implemented("gluTessVertex"); }
FFC_GLU_EXPORT void GLAPIENTRY gluTessEndContour(GLUtesselator *) { not_implemented("gluTessEndContour"); }
FFC_GLU_EXPORT void GLAPIENTRY gluTessEndPolygon(GLUtesselator *) { not_implemented("gluTessEndPolygon"); }
FFC_GLU_EXPORT void GLAPIENTRY gluTessProperty(GLUtesselator *, GLenum, GLdouble) { not_implemented("gluTessProperty"); }
FFC_GLU_EXPORT void GLAPIENTRY gluTessNormal(GLUtesselator *, GLdouble, GLdouble, GLdouble) { not_implemented("gluTessNormal"); }
FFC_GLU_EXPORT void GLAPIENTRY gluTessCallback(GLUtesselator *, GLenum, _GLUfuncptr) { not_implemented("gluTessCallback"); }
FFC_GLU_EXPORT void GLAPIENTRY gluGetTessProperty(GLUtesselator *, GLenum, GLdouble *data) {
  not_implemented("gluGetTessProperty");
  if (data != nullptr) *data = 0.0;
}
FFC_GLU_EXPORT void GLAPIENTRY gluBeginPolygon(GLUtesselator *) { not_implemented("gluBeginPolygon"); }
FFC_GLU_EXPORT void GLAPIENTRY gluNextContour(GLUtesselator *, GLenum) { not_implemented("gluNextContour"); }
FFC_GLU_EXPORT void GLAPIENTRY gluEndPolygon(GLUtesselator *) { not_implemented("gluEndPolygon"); }

// ---- NURBS
FFC_GLU_EXPORT GLUnurbs *GLAPIENTRY gluNewNurbsRenderer(void) { return create<GLUnurbs>("gluNewNurbsRenderer"); }
FFC_GLU_EXPORT void GLAPIENTRY gluDeleteNurbsRenderer(GLUnurbs *nurb) { destroy("gluDeleteNurbsRenderer", nurb); }
FFC_GLU_EXPORT void GLAPIENTRY gluBeginCurve(GLUnurbs *) { not_implemented("gluBeginCurve"); }
FFC_GLU_EXPORT void GLAPIENTRY gluEndCurve(GLUnurbs *) { not_implemented("gluEndCurve"); }
FFC_GLU_EXPORT void GLAPIENTRY gluBeginSurface(GLUnurbs *) { not_implemented("gluBeginSurface"); }
FFC_GLU_EXPORT void GLAPIENTRY gluEndSurface(GLUnurbs *) { not_implemented("gluEndSurface"); }
FFC_GLU_EXPORT void GLAPIENTRY gluBeginTrim(GLUnurbs *) { not_implemented("gluBeginTrim"); }
FFC_GLU_EXPORT void GLAPIENTRY gluEndTrim(GLUnurbs *) { not_implemented("gluEndTrim"); }
FFC_GLU_EXPORT void GLAPIENTRY gluNurbsCurve(GLUnurbs *, GLint, GLfloat *, GLint, GLfloat *, GLint, GLenum) {
  not_implemented("gluNurbsCurve");
}
FFC_GLU_EXPORT void GLAPIENTRY gluNurbsSurface(GLUnurbs *, GLint, GLfloat *, GLint, GLfloat *, GLint, GLint,
                                               GLfloat *, GLint, GLint, GLenum) {
  not_implemented("gluNurbsSurface");
}
FFC_GLU_EXPORT void GLAPIENTRY gluPwlCurve(GLUnurbs *, GLint, GLfloat *, GLint, GLenum) { not_implemented("gluPwlCurve"); }
FFC_GLU_EXPORT void GLAPIENTRY gluNurbsProperty(GLUnurbs *, GLenum, GLfloat) { not_implemented("gluNurbsProperty"); }
FFC_GLU_EXPORT void GLAPIENTRY gluGetNurbsProperty(GLUnurbs *, GLenum, GLfloat *data) {
  not_implemented("gluGetNurbsProperty");
  if (data != nullptr) *data = 0.0f;
}
FFC_GLU_EXPORT void GLAPIENTRY gluNurbsCallback(GLUnurbs *, GLenum, _GLUfuncptr) { not_implemented("gluNurbsCallback"); }
FFC_GLU_EXPORT void GLAPIENTRY gluNurbsCallbackData(GLUnurbs *, GLvoid *) { not_implemented("gluNurbsCallbackData"); }
FFC_GLU_EXPORT void GLAPIENTRY gluNurbsCallbackDataEXT(GLUnurbs *, GLvoid *) { not_implemented("gluNurbsCallbackDataEXT"); }
FFC_GLU_EXPORT void GLAPIENTRY gluLoadSamplingMatrices(GLUnurbs *, const GLfloat *, const GLfloat *, const GLint *) {
  not_implemented("gluLoadSamplingMatrices");
}

// ---- images: GLU returns 0 on success, a GLU error code otherwise.
FFC_GLU_EXPORT GLint GLAPIENTRY gluScaleImage(GLenum, GLsizei, GLsizei, GLenum, const void *, GLsizei, GLsizei,
                                              GLenum, GLvoid *) {
  not_implemented("gluScaleImage");
  return GLU_INVALID_OPERATION;
}
FFC_GLU_EXPORT GLint GLAPIENTRY gluBuild1DMipmaps(GLenum, GLint, GLsizei, GLenum, GLenum, const void *) {
  not_implemented("gluBuild1DMipmaps");
  return GLU_INVALID_OPERATION;
}
FFC_GLU_EXPORT GLint GLAPIENTRY gluBuild2DMipmaps(GLenum, GLint, GLsizei, GLsizei, GLenum, GLenum, const void *) {
  not_implemented("gluBuild2DMipmaps");
  return GLU_INVALID_OPERATION;
}
FFC_GLU_EXPORT GLint GLAPIENTRY gluBuild3DMipmaps(GLenum, GLint, GLsizei, GLsizei, GLsizei, GLenum, GLenum,
                                                  const void *) {
  not_implemented("gluBuild3DMipmaps");
  return GLU_INVALID_OPERATION;
}
FFC_GLU_EXPORT GLint GLAPIENTRY gluBuild1DMipmapLevels(GLenum, GLint, GLsizei, GLenum, GLenum, GLint, GLint, GLint,
                                                       const void *) {
  not_implemented("gluBuild1DMipmapLevels");
  return GLU_INVALID_OPERATION;
}
FFC_GLU_EXPORT GLint GLAPIENTRY gluBuild2DMipmapLevels(GLenum, GLint, GLsizei, GLsizei, GLenum, GLenum, GLint, GLint,
                                                       GLint, const void *) {
  not_implemented("gluBuild2DMipmapLevels");
  return GLU_INVALID_OPERATION;
}
FFC_GLU_EXPORT GLint GLAPIENTRY gluBuild3DMipmapLevels(GLenum, GLint, GLsizei, GLsizei, GLsizei, GLenum, GLenum,
                                                       GLint, GLint, GLint, const void *) {
  not_implemented("gluBuild3DMipmapLevels");
  return GLU_INVALID_OPERATION;
}
