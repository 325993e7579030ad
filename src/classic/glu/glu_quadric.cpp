// The quadric object: creation, settings and the error callback. An invalid setting leaves the
// quadric as it was and reports GLU_INVALID_ENUM to the callback, as GLU does.
#include "glu_quadric.h"

#include <new>

namespace ffc::glu {

void report_error(GLUquadric *quadric, GLenum error) {
  if (quadric != nullptr && quadric->error_callback != nullptr) quadric->error_callback(error);
}

}  // namespace ffc::glu

using ffc::glu::report_error;

FFC_GLU_EXPORT GLUquadric *GLAPIENTRY gluNewQuadric(void) { return new (std::nothrow) GLUquadric{}; }

FFC_GLU_EXPORT void GLAPIENTRY gluDeleteQuadric(GLUquadric *quad) { delete quad; }

FFC_GLU_EXPORT void GLAPIENTRY gluQuadricCallback(GLUquadric *quad, GLenum which, _GLUfuncptr CallBackFunc) {
  if (quad == nullptr) return;
  if (which != GLU_ERROR) return report_error(quad, GLU_INVALID_ENUM);
  quad->error_callback = reinterpret_cast<void(GLAPIENTRY *)(GLenum)>(CallBackFunc);
}

FFC_GLU_EXPORT void GLAPIENTRY gluQuadricNormals(GLUquadric *quad, GLenum normal) {
  if (quad == nullptr) return;
  if (normal != GLU_SMOOTH && normal != GLU_FLAT && normal != GLU_NONE) return report_error(quad, GLU_INVALID_ENUM);
  quad->normals = normal;
}

FFC_GLU_EXPORT void GLAPIENTRY gluQuadricTexture(GLUquadric *quad, GLboolean texture) {
  if (quad != nullptr) quad->texture = texture;
}

FFC_GLU_EXPORT void GLAPIENTRY gluQuadricOrientation(GLUquadric *quad, GLenum orientation) {
  if (quad == nullptr) return;
  if (orientation != GLU_OUTSIDE && orientation != GLU_INSIDE) return report_error(quad, GLU_INVALID_ENUM);
  quad->orientation = orientation;
}

FFC_GLU_EXPORT void GLAPIENTRY gluQuadricDrawStyle(GLUquadric *quad, GLenum draw) {
  if (quad == nullptr) return;
  if (draw != GLU_POINT && draw != GLU_LINE && draw != GLU_FILL && draw != GLU_SILHOUETTE)
    return report_error(quad, GLU_INVALID_ENUM);
  quad->draw_style = draw;
}
