// gluDisk and gluPartialDisk: a flat ring in z = 0 between two radii, angles measured from +y
// towards +x (x = r sin a, y = r cos a), in loops from the outer edge inwards, as SGI's GLU draws
// it. The one normal is +z (-z inside); texture coordinates map the outer circle onto the unit
// square's inscribed circle.
#include "glu_quadric.h"

#include <cmath>

using namespace ffc::glu;

namespace {

struct Ring {
  GLdouble outer;
  GLfloat delta;  // outer - inner
  GLint slices, loops;
  GLfloat sin_a[kTableSize] = {}, cos_a[kTableSize] = {};

  GLfloat radius_at(GLint j) const { return outer - delta * ((float)j / loops); }
};

// Vertex i of the circle of the given radius; tex_scale is that radius over the outer one, halved.
void vertex(const GLUquadric *q, const Ring &ring, GLint i, GLfloat radius) {
  if (q->texture) {
    const GLfloat tex_scale = radius / ring.outer / 2;
    glTexCoord2f(tex_scale * ring.sin_a[i] + 0.5, tex_scale * ring.cos_a[i] + 0.5);
  }
  glVertex3f(radius * ring.sin_a[i], radius * ring.cos_a[i], 0.0);
}

void circle(const GLUquadric *q, const Ring &ring, GLint j) {
  const GLfloat radius = ring.radius_at(j);
  glBegin(GL_LINE_STRIP);
  for (GLint i = 0; i <= ring.slices; ++i) vertex(q, ring, i, radius);
  glEnd();
}

void spoke(const GLUquadric *q, const Ring &ring, GLint i) {
  glBegin(GL_LINE_STRIP);
  for (GLint j = 0; j <= ring.loops; ++j) vertex(q, ring, i, ring.radius_at(j));
  glEnd();
}

}  // namespace

FFC_GLU_EXPORT void GLAPIENTRY gluPartialDisk(GLUquadric *quad, GLdouble inner, GLdouble outer, GLint slices,
                                              GLint loops, GLdouble start, GLdouble sweep) {
  if (quad == nullptr) return;
  if (slices >= kTableSize) slices = kTableSize - 1;
  if (slices < 2 || loops < 1 || outer <= 0.0 || inner < 0.0 || inner > outer)
    return report_error(quad, GLU_INVALID_VALUE);
  // GLU's clamping, including its quirk that a sweep below -360 becomes a full +360.
  if (sweep < -360.0) sweep = 360.0;
  if (sweep > 360.0) sweep = 360.0;
  if (sweep < 0) {
    start += sweep;
    sweep = -sweep;
  }
  const bool full = sweep == 360.0;
  // A partial disk has one spoke more than slices; a full one closes on its first.
  const GLint spokes = full ? slices : slices + 1;
  Ring ring;
  ring.outer = outer;
  ring.delta = outer - inner;
  ring.slices = slices;
  ring.loops = loops;
  const GLfloat start_radians = start / 180.0 * kPi;
  for (GLint i = 0; i <= slices; ++i) {
    const GLfloat a = start_radians + ((kPi * sweep) / 180.0) * i / slices;
    ring.sin_a[i] = std::sin(double(a));
    ring.cos_a[i] = std::cos(double(a));
  }
  if (full) {
    ring.sin_a[slices] = ring.sin_a[0];
    ring.cos_a[slices] = ring.cos_a[0];
  }
  normal_if_any(quad, 0.0, 0.0, outside(quad) ? 1.0 : -1.0);

  switch (quad->draw_style) {
    case GLU_FILL: {
      GLint bands = loops;
      if (inner == 0.0) {
        // The innermost loop is a fan around the centre, turning so that it faces the normal.
        bands = loops - 1;
        glBegin(GL_TRIANGLE_FAN);
        if (quad->texture) glTexCoord2f(0.5, 0.5);
        glVertex3f(0.0, 0.0, 0.0);
        const GLfloat radius = outer - ring.delta * ((float)(loops - 1) / loops);
        for (GLint k = 0; k <= slices; ++k) vertex(quad, ring, outside(quad) ? slices - k : k, radius);
        glEnd();
      }
      for (GLint j = 0; j < bands; ++j) {
        const GLfloat low = ring.radius_at(j), high = ring.radius_at(j + 1);
        glBegin(GL_QUAD_STRIP);
        for (GLint i = 0; i <= slices; ++i) {
          vertex(quad, ring, i, outside(quad) ? low : high);
          vertex(quad, ring, i, outside(quad) ? high : low);
        }
        glEnd();
      }
      break;
    }
    case GLU_POINT:
      glBegin(GL_POINTS);
      for (GLint i = 0; i < spokes; ++i)
        for (GLint j = 0; j <= loops; ++j) vertex(quad, ring, i, ring.radius_at(j));
      glEnd();
      break;
    case GLU_LINE:
      if (inner == outer) {
        // A ring of no width: one circle, its texture on the unit circle itself.
        glBegin(GL_LINE_STRIP);
        for (GLint i = 0; i <= slices; ++i) {
          if (quad->texture) glTexCoord2f(ring.sin_a[i] / 2 + 0.5, ring.cos_a[i] / 2 + 0.5);
          glVertex3f(inner * ring.sin_a[i], inner * ring.cos_a[i], 0.0);
        }
        glEnd();
        break;
      }
      for (GLint j = 0; j <= loops; ++j) circle(quad, ring, j);
      for (GLint i = 0; i < spokes; ++i) spoke(quad, ring, i);
      break;
    case GLU_SILHOUETTE:
      // The outline only: the two straight edges of a partial disk, then the outer and inner arcs.
      if (sweep < 360.0) {
        spoke(quad, ring, 0);
        spoke(quad, ring, slices);
      }
      circle(quad, ring, 0);
      if (inner != outer) circle(quad, ring, loops);
      break;
    default:
      break;
  }
}

FFC_GLU_EXPORT void GLAPIENTRY gluDisk(GLUquadric *quad, GLdouble inner, GLdouble outer, GLint slices, GLint loops) {
  gluPartialDisk(quad, inner, outer, slices, loops, 0.0, 360.0);
}
