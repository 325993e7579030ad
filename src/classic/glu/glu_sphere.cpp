// gluSphere: stacks from the +z pole (j = 0) to the -z pole (j = stacks), slices from +y towards
// +x, as SGI's GLU draws it: without texture the two polar stacks are triangle fans and the rest
// quad strips; with texture every stack is a quad strip (the pole needs a texture coordinate per
// slice). Flat normals sit half a step back in both angles; GLU_FLAT's first fan vertex keeps
// whatever normal was current, a quirk of GLU reproduced here.
#include "glu_quadric.h"

#include <cmath>
#include <initializer_list>

using namespace ffc::glu;

namespace {

struct Globe {
  GLint slices, stacks;
  // Around (a, per slice): sin/cos of the vertex angle and of the face-centre angle.
  GLfloat sin_a[kTableSize] = {}, cos_a[kTableSize] = {};
  GLfloat sin_a_flat[kTableSize] = {}, cos_a_flat[kTableSize] = {};
  // Down (b, per stack boundary): radius * sin/cos for positions; sin/cos for the normals, both
  // at the vertices and at the face centres, negated inside.
  GLfloat ring_radius[kTableSize] = {}, ring_z[kTableSize] = {};
  GLfloat sin_b[kTableSize] = {}, cos_b[kTableSize] = {};
  GLfloat sin_b_flat[kTableSize] = {}, cos_b_flat[kTableSize] = {};

  GLfloat s_at(GLint i) const { return 1 - (float)i / slices; }
  GLfloat t_at(GLint j) const { return 1 - (float)j / stacks; }
};

void vertex(const GLUquadric *q, const Globe &g, GLint i, GLint j) {
  if (q->texture) glTexCoord2f(g.s_at(i), g.t_at(j));
  glVertex3f(g.ring_radius[j] * g.sin_a[i], g.ring_radius[j] * g.cos_a[i], g.ring_z[j]);
}

// A normal from an angle around (as sin/cos) and the sine/cosine of the angle down.
void normal(GLfloat sin_around, GLfloat cos_around, GLfloat sin_down, GLfloat cos_down) {
  glNormal3f(sin_around * sin_down, cos_around * sin_down, cos_down);
}

// One polar cap as a triangle fan around the pole (`top`: the +z one), its rim the ring next to
// the pole; rim normals take that ring's down angle (smooth) or the cap's face centre (flat).
void cap(const GLUquadric *q, const Globe &g, GLdouble radius, bool top) {
  const GLint rim = top ? 1 : g.stacks - 1;
  const GLint pole = top ? 0 : g.stacks;
  GLfloat s3 = 0.0, c3 = 0.0;
  if (q->normals == GLU_FLAT) {
    s3 = g.sin_b_flat[top ? 1 : g.stacks];
    c3 = g.cos_b_flat[top ? 1 : g.stacks];
  } else if (q->normals == GLU_SMOOTH) {
    s3 = g.sin_b[rim];
    c3 = g.cos_b[rim];
    // The pole's own normal, set before the fan begins. GLU indexes the around-table by the pole's
    // stack number here; it only matters at the pole, where the down sine is (nearly) zero.
    normal(g.sin_a[pole], g.cos_a[pole], g.sin_b[pole], g.cos_b[pole]);
  }
  glBegin(GL_TRIANGLE_FAN);
  glVertex3f(0.0, 0.0, top ? radius : -radius);
  // The fan turns so that its triangles face out: top cap backwards outside, bottom cap forwards.
  const bool backwards = top == outside(q);
  for (GLint k = 0; k <= g.slices; ++k) {
    const GLint i = backwards ? g.slices - k : k;
    if (q->normals == GLU_SMOOTH) normal(g.sin_a[i], g.cos_a[i], s3, c3);
    // Flat, turning backwards: each vertex takes the face ahead of it, the first none.
    if (q->normals == GLU_FLAT && !backwards) normal(g.sin_a_flat[i], g.cos_a_flat[i], s3, c3);
    if (q->normals == GLU_FLAT && backwards && i != g.slices)
      normal(g.sin_a_flat[i + 1], g.cos_a_flat[i + 1], s3, c3);
    vertex(q, g, i, rim);
  }
  glEnd();
}

}  // namespace

FFC_GLU_EXPORT void GLAPIENTRY gluSphere(GLUquadric *quad, GLdouble radius, GLint slices, GLint stacks) {
  if (quad == nullptr) return;
  if (slices >= kTableSize) slices = kTableSize - 1;
  if (stacks >= kTableSize) stacks = kTableSize - 1;
  if (slices < 2 || stacks < 1 || radius < 0.0) return report_error(quad, GLU_INVALID_VALUE);
  Globe g;
  g.slices = slices;
  g.stacks = stacks;
  const double sign = outside(quad) ? 1.0 : -1.0;
  for (GLint i = 0; i < slices; ++i) {
    const GLfloat a = 2 * kPi * i / slices;
    const GLfloat face = 2 * kPi * (i - 0.5) / slices;
    g.sin_a[i] = std::sin(double(a));
    g.cos_a[i] = std::cos(double(a));
    g.sin_a_flat[i] = std::sin(double(face));
    g.cos_a_flat[i] = std::cos(double(face));
  }
  for (GLint j = 0; j <= stacks; ++j) {
    const GLfloat b = kPi * j / stacks;
    const GLfloat face = kPi * (j - 0.5) / stacks;
    g.sin_b[j] = sign * std::sin(double(b));
    g.cos_b[j] = sign * std::cos(double(b));
    g.ring_radius[j] = radius * std::sin(double(b));
    g.ring_z[j] = radius * std::cos(double(b));
    g.sin_b_flat[j] = sign * std::sin(double(face));
    g.cos_b_flat[j] = sign * std::cos(double(face));
  }
  g.ring_radius[0] = 0;  // exactly on the axis at both poles
  g.ring_radius[stacks] = 0;
  for (GLfloat *table : {g.sin_a, g.cos_a, g.sin_a_flat, g.cos_a_flat}) table[slices] = table[0];

  switch (quad->draw_style) {
    case GLU_FILL: {
      GLint first = 0, last = stacks;
      if (!quad->texture) {
        first = 1;
        last = stacks - 1;
        cap(quad, g, radius, true);
        cap(quad, g, radius, false);
      }
      for (GLint j = first; j < last; ++j) {
        // Each quad strip pairs ring j+1 with ring j (outside) or j with j+1 (inside).
        const GLint lead = outside(quad) ? j + 1 : j, follow = outside(quad) ? j : j + 1;
        glBegin(GL_QUAD_STRIP);
        for (GLint i = 0; i <= slices; ++i) {
          if (quad->normals == GLU_SMOOTH) normal(g.sin_a[i], g.cos_a[i], g.sin_b[lead], g.cos_b[lead]);
          vertex(quad, g, i, lead);
          if (quad->normals == GLU_SMOOTH) normal(g.sin_a[i], g.cos_a[i], g.sin_b[follow], g.cos_b[follow]);
          if (quad->normals == GLU_FLAT)
            normal(g.sin_a_flat[i], g.cos_a_flat[i], g.sin_b_flat[j + 1], g.cos_b_flat[j + 1]);
          vertex(quad, g, i, follow);
        }
        glEnd();
      }
      break;
    }
    case GLU_POINT:
      glBegin(GL_POINTS);
      for (GLint j = 0; j <= stacks; ++j)
        for (GLint i = 0; i < slices; ++i) {
          if (quad->normals != GLU_NONE) normal(g.sin_a[i], g.cos_a[i], g.sin_b[j], g.cos_b[j]);
          vertex(quad, g, i, j);
        }
      glEnd();
      break;
    case GLU_LINE:
    case GLU_SILHOUETTE:
      // Both draw the full wire frame: the inner latitude circles, then the meridians.
      for (GLint j = 1; j < stacks; ++j) {
        glBegin(GL_LINE_STRIP);
        for (GLint i = 0; i <= slices; ++i) {
          if (quad->normals == GLU_FLAT) normal(g.sin_a_flat[i], g.cos_a_flat[i], g.sin_b[j], g.cos_b[j]);
          if (quad->normals == GLU_SMOOTH) normal(g.sin_a[i], g.cos_a[i], g.sin_b[j], g.cos_b[j]);
          vertex(quad, g, i, j);
        }
        glEnd();
      }
      for (GLint i = 0; i < slices; ++i) {
        glBegin(GL_LINE_STRIP);
        for (GLint j = 0; j <= stacks; ++j) {
          if (quad->normals == GLU_FLAT) normal(g.sin_a[i], g.cos_a[i], g.sin_b_flat[j], g.cos_b_flat[j]);
          if (quad->normals == GLU_SMOOTH) normal(g.sin_a[i], g.cos_a[i], g.sin_b[j], g.cos_b[j]);
          vertex(quad, g, i, j);
        }
        glEnd();
      }
      break;
    default:
      break;
  }
}
