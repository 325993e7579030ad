// The GLU subset the classic programs use, written on top of the dispatch (glMultMatrixd,
// glOrtho) so it runs on every backend and ffcompat does not depend on libGLU.
#pragma once
#include "gl/dispatch.h"

void gluPerspective(GLdouble fovy_deg, GLdouble aspect, GLdouble z_near, GLdouble z_far);
void gluLookAt(GLdouble eye_x, GLdouble eye_y, GLdouble eye_z, GLdouble center_x, GLdouble center_y,
               GLdouble center_z, GLdouble up_x, GLdouble up_y, GLdouble up_z);
void gluOrtho2D(GLdouble left, GLdouble right, GLdouble bottom, GLdouble top);
