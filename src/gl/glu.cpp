#include "gl/glu.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

// GLU builds these matrices in double and multiplies them onto the current matrix; glm's
// right-handed, [-1,1]-depth versions are the same matrices.
void gluPerspective(GLdouble fovy_deg, GLdouble aspect, GLdouble z_near, GLdouble z_far) {
  glm::dmat4 m = glm::perspectiveRH_NO(glm::radians(fovy_deg), aspect, z_near, z_far);
  glMultMatrixd(glm::value_ptr(m));
}

void gluLookAt(GLdouble eye_x, GLdouble eye_y, GLdouble eye_z, GLdouble center_x, GLdouble center_y,
               GLdouble center_z, GLdouble up_x, GLdouble up_y, GLdouble up_z) {
  glm::dmat4 m = glm::lookAtRH(glm::dvec3(eye_x, eye_y, eye_z), glm::dvec3(center_x, center_y, center_z),
                               glm::dvec3(up_x, up_y, up_z));
  glMultMatrixd(glm::value_ptr(m));
}

void gluOrtho2D(GLdouble left, GLdouble right, GLdouble bottom, GLdouble top) {
  glOrtho(left, right, bottom, top, -1.0, 1.0);
}
