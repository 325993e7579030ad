// gluCylinder: a (possibly tapered) tube along +z from z = 0 (baseRadius) to z = height
// (topRadius), its slices starting on +y and turning towards +x (x = r sin a, y = r cos a), drawn
// as one quad strip per stack, as SGI's GLU draws it. Flat normals sit half a slice back, at the
// face centres; the texture s runs from 1 at a = 0 down to 0, t from 0 at the base to 1.
#include "glu_quadric.h"

#include <cmath>
#include <initializer_list>

using namespace ffc::glu;

namespace {

struct Tube {
  GLdouble base, height;
  GLfloat delta;  // base - top
  GLint slices, stacks;
  // The circle (sin, cos per slice), and the normals' x and y: smooth ones at the vertices, flat
  // ones at the face centres, both already scaled by height / slant and turned by orientation.
  GLfloat sin_a[kTableSize] = {}, cos_a[kTableSize] = {};
  GLfloat sin_smooth[kTableSize] = {}, cos_smooth[kTableSize] = {};
  GLfloat sin_flat[kTableSize] = {}, cos_flat[kTableSize] = {};
  GLfloat z_normal;

  GLfloat z_at(GLint j) const { return j * height / stacks; }
  GLfloat radius_at(GLint j) const { return base - delta * ((float)j / stacks); }
  GLfloat s_at(GLint i) const { return 1 - (float)i / slices; }
  GLfloat t_at(GLint j) const { return (float)j / stacks; }
};

void vertex(const GLUquadric *q, const Tube &tube, GLint i, GLint j) {
  if (q->texture) glTexCoord2f(tube.s_at(i), tube.t_at(j));
  const GLfloat radius = tube.radius_at(j);
  glVertex3f(radius * tube.sin_a[i], radius * tube.cos_a[i], tube.z_at(j));
}

// The normal of slice i on a ring: the face normal under GLU_FLAT, the vertex one under GLU_SMOOTH.
void ring_normal(const GLUquadric *q, const Tube &tube, GLint i) {
  if (q->normals == GLU_FLAT) glNormal3f(tube.sin_flat[i], tube.cos_flat[i], tube.z_normal);
  if (q->normals == GLU_SMOOTH) glNormal3f(tube.sin_smooth[i], tube.cos_smooth[i], tube.z_normal);
}

// One ring at stack boundary j, as a line strip around the slices.
void ring(const GLUquadric *q, const Tube &tube, GLint j) {
  glBegin(GL_LINE_STRIP);
  for (GLint i = 0; i <= tube.slices; ++i) {
    ring_normal(q, tube, i);
    vertex(q, tube, i, j);
  }
  glEnd();
}

}  // namespace

FFC_GLU_EXPORT void GLAPIENTRY gluCylinder(GLUquadric *quad, GLdouble base, GLdouble top, GLdouble height,
                                           GLint slices, GLint stacks) {
  if (quad == nullptr) return;
  if (slices >= kTableSize) slices = kTableSize - 1;
  if (slices < 2 || stacks < 1 || base < 0.0 || top < 0.0 || height < 0.0)
    return report_error(quad, GLU_INVALID_VALUE);
  Tube tube;
  tube.base = base;
  tube.height = height;
  tube.slices = slices;
  tube.stacks = stacks;
  tube.delta = base - top;
  const GLfloat slant = std::sqrt(tube.delta * tube.delta + height * height);
  if (slant == 0.0) return report_error(quad, GLU_INVALID_VALUE);
  tube.z_normal = tube.delta / slant;
  const GLfloat xy_ratio = height / slant;
  const GLfloat sign_ratio = outside(quad) ? xy_ratio : -xy_ratio;
  for (GLint i = 0; i < slices; ++i) {
    const GLfloat a = 2 * kPi * i / slices;
    const GLfloat face = 2 * kPi * (i - 0.5) / slices;
    tube.sin_a[i] = std::sin(double(a));
    tube.cos_a[i] = std::cos(double(a));
    tube.sin_smooth[i] = sign_ratio * std::sin(double(a));
    tube.cos_smooth[i] = sign_ratio * std::cos(double(a));
    tube.sin_flat[i] = sign_ratio * std::sin(double(face));
    tube.cos_flat[i] = sign_ratio * std::cos(double(face));
  }
  for (GLfloat *table : {tube.sin_a, tube.cos_a, tube.sin_smooth, tube.cos_smooth, tube.sin_flat, tube.cos_flat})
    table[slices] = table[0];  // the loop closes on its first slice

  switch (quad->draw_style) {
    case GLU_FILL:
      // One quad strip per stack (a cone's tip too: its normal differs per slice, a fan could not
      // carry that). Outside: the lower ring's vertex first; inside: the upper one's.
      for (GLint j = 0; j < stacks; ++j) {
        glBegin(GL_QUAD_STRIP);
        for (GLint i = 0; i <= slices; ++i) {
          ring_normal(quad, tube, i);
          vertex(quad, tube, i, outside(quad) ? j : j + 1);
          vertex(quad, tube, i, outside(quad) ? j + 1 : j);
        }
        glEnd();
      }
      break;
    case GLU_POINT:
      glBegin(GL_POINTS);
      for (GLint i = 0; i < slices; ++i) {
        normal_if_any(quad, tube.sin_smooth[i], tube.cos_smooth[i], tube.z_normal);
        for (GLint j = 0; j <= stacks; ++j) vertex(quad, tube, i, j);
      }
      glEnd();
      break;
    case GLU_LINE:
    case GLU_SILHOUETTE:
      // The inner rings belong to GLU_LINE only; both draw the end rings and the lengthwise lines.
      if (quad->draw_style == GLU_LINE)
        for (GLint j = 1; j < stacks; ++j) ring(quad, tube, j);
      ring(quad, tube, 0);
      ring(quad, tube, stacks);
      for (GLint i = 0; i < slices; ++i) {
        normal_if_any(quad, tube.sin_smooth[i], tube.cos_smooth[i], 0.0);
        glBegin(GL_LINE_STRIP);
        for (GLint j = 0; j <= stacks; ++j) vertex(quad, tube, i, j);
        glEnd();
      }
      break;
    default:
      break;
  }
}
