// The round GLUT shapes: sphere, cone, cylinder and torus, generated and drawn as freeglut 3.4.0
// does: unique vertices (with extra rings where a cap needs its own normals), indices for one
// triangle strip per stack (solid), line strips and loops along both directions (wire). The sine
// tables are built from a single-precision angle step with sines taken in double, which decides
// the last bits of every vertex.
#include "shapes.h"

#include <cmath>
#include <cstdlib>
#include <vector>

namespace {

using Indices = std::vector<GLushort>;

// n + 1 samples of the circle (or half of it), the last equal to the first (or to -1 for the
// half circle's cosine). A negative n runs the circle clockwise.
struct Circle {
  std::vector<GLfloat> sin, cos;
  Circle(int n, bool half) : sin(size_t(std::abs(n)) + 1), cos(size_t(std::abs(n)) + 1) {
    const int size = std::abs(n);
    const GLfloat step = (half ? 1 : 2) * GLfloat(M_PI) / GLfloat(n == 0 ? 1 : n);
    sin[0] = 0.0f;
    cos[0] = 1.0f;
    for (int i = 1; i < size; ++i) {
      sin[i] = GLfloat(std::sin(double(step * i)));
      cos[i] = GLfloat(std::cos(double(step * i)));
    }
    sin[size] = half ? 0.0f : sin[0];
    cos[size] = half ? -1.0f : cos[0];
  }
};

struct Buffers {
  std::vector<GLfloat> vertices, normals;
  void add(GLfloat x, GLfloat y, GLfloat z, GLfloat nx, GLfloat ny, GLfloat nz) {
    vertices.insert(vertices.end(), {x, y, z});
    normals.insert(normals.end(), {nx, ny, nz});
  }
  GLsizei count() const { return GLsizei(vertices.size() / 3); }
};

// Triangle strips around the stacks of a shape whose ring k starts at vertex `first + k * slices`.
void ring_strip(Indices &strip, GLushort a, GLushort b, int slices) {
  for (int j = 0; j < slices; ++j) strip.insert(strip.end(), {GLushort(a + j), GLushort(b + j)});
  strip.insert(strip.end(), {a, b});  // closing the strip on its first pair
}

void draw_solid_strips(const Buffers &b, const Indices &strip, GLsizei parts) {
  ffc::glut::draw_solid(b.vertices.data(), b.normals.data(), nullptr, b.count(), strip.data(), parts,
                        GLsizei(strip.size()) / parts);
}

// ---- sphere: the top vertex, stacks - 1 rings of `slices` from the top down, the bottom vertex
void sphere(GLfloat radius, GLint slices, GLint stacks, bool wire) {
  if (slices <= 0 || stacks < 2) return;
  const Circle around(-slices, false), down(stacks, true);
  Buffers b;
  b.add(0.f, 0.f, radius, 0.f, 0.f, 1.f);
  for (int i = 1; i < stacks; ++i)
    for (int j = 0; j < slices; ++j) {
      const GLfloat x = around.cos[j] * down.sin[i], y = around.sin[j] * down.sin[i], z = down.cos[i];
      b.add(x * radius, y * radius, z * radius, x, y, z);
    }
  b.add(0.f, 0.f, -radius, 0.f, 0.f, -1.f);
  const GLushort last = GLushort(b.count() - 1);
  if (wire) {
    Indices slice_lines, stack_loops;
    for (int i = 0; i < stacks - 1; ++i)
      for (int j = 0; j < slices; ++j) stack_loops.push_back(GLushort(1 + i * slices + j));
    for (int i = 0; i < slices; ++i) {
      slice_lines.push_back(0);
      for (int j = 0; j < stacks - 1; ++j) slice_lines.push_back(GLushort(1 + i + j * slices));
      slice_lines.push_back(last);
    }
    ffc::glut::draw_wire(b.vertices.data(), b.normals.data(), slice_lines.data(), slices, stacks + 1,
                         GL_LINE_STRIP, stack_loops.data(), stacks - 1, slices);
    return;
  }
  Indices strip;
  for (int j = 0; j < slices; ++j) strip.insert(strip.end(), {GLushort(j + 1), GLushort(0)});
  strip.insert(strip.end(), {GLushort(1), GLushort(0)});
  for (int i = 0; i < stacks - 2; ++i) {
    const GLushort ring = GLushort(1 + i * slices);
    ring_strip(strip, GLushort(ring + slices), ring, slices);
  }
  const GLushort bottom_ring = GLushort(1 + (stacks - 2) * slices);
  for (int j = 0; j < slices; ++j) strip.insert(strip.end(), {last, GLushort(bottom_ring + j)});
  strip.insert(strip.end(), {last, bottom_ring});
  draw_solid_strips(b, strip, stacks);
}

// Cone and cylinder share their layout from the base up: vertex 0 the base centre, then the base
// ring (normal -z), then the side rings from z = 0, ring k at 1 + k * slices.

// The base fan (as a strip through the centre), then one strip per stack of the side.
Indices base_and_side_strips(int slices, int stacks) {
  Indices strip;
  for (int j = 0; j < slices; ++j) strip.insert(strip.end(), {GLushort(0), GLushort(j + 1)});
  strip.insert(strip.end(), {GLushort(0), GLushort(1)});
  for (int i = 0; i < stacks; ++i) {
    const GLushort ring = GLushort(1 + (i + 1) * slices);
    ring_strip(strip, ring, GLushort(ring + slices), slices);
  }
  return strip;
}

// Lengthwise lines from the first side ring to ring stacks + 1, then `loops` side rings as loops.
void draw_side_wire(const Buffers &b, int slices, int stacks, int loops) {
  Indices stack_loops, slice_lines;
  for (int i = 0; i < loops; ++i)
    for (int j = 0; j < slices; ++j) stack_loops.push_back(GLushort(1 + (i + 1) * slices + j));
  for (int i = 0; i < slices; ++i)
    slice_lines.insert(slice_lines.end(), {GLushort(1 + i + slices), GLushort(1 + i + (stacks + 1) * slices)});
  ffc::glut::draw_wire(b.vertices.data(), b.normals.data(), slice_lines.data(), 1, slices * 2, GL_LINES,
                       stack_loops.data(), loops, slices);
}

// ---- cone: the base centre, the base ring (normal -z), then stacks + 1 side rings up to the tip
void cone(GLfloat base, GLfloat height, GLint slices, GLint stacks, bool wire) {
  if (slices <= 0 || stacks < 1) return;
  const GLfloat z_step = height / stacks, r_step = base / stacks;
  const GLfloat side_cos = GLfloat(height / std::sqrt(double(height * height + base * base)));
  const GLfloat side_sin = GLfloat(base / std::sqrt(double(height * height + base * base)));
  const Circle around(-slices, false);
  Buffers b;
  GLfloat z = 0, r = base;
  b.add(0.f, 0.f, z, 0.f, 0.f, -1.f);
  for (int j = 0; j < slices; ++j) b.add(around.cos[j] * r, around.sin[j] * r, z, 0.f, 0.f, -1.f);
  for (int i = 0; i < stacks + 1; ++i) {
    for (int j = 0; j < slices; ++j)
      b.add(around.cos[j] * r, around.sin[j] * r, z, around.cos[j] * side_cos, around.sin[j] * side_cos, side_sin);
    z += z_step;
    r -= r_step;
  }
  if (wire) return draw_side_wire(b, slices, stacks, stacks);
  draw_solid_strips(b, base_and_side_strips(slices, stacks), stacks + 1);
}

// ---- cylinder: the z = 0 cap (centre and ring, normal -z), stacks + 1 side rings, the top cap
// (ring and centre, normal +z)
void cylinder(GLfloat radius, GLfloat height, GLint slices, GLint stacks, bool wire) {
  if (slices <= 0 || stacks < 1) return;
  const GLfloat z_step = height / stacks;
  const Circle around(-slices, false);
  Buffers b;
  GLfloat z = 0;
  b.add(0.f, 0.f, 0.f, 0.f, 0.f, -1.f);
  for (int j = 0; j < slices; ++j) b.add(around.cos[j] * radius, around.sin[j] * radius, z, 0.f, 0.f, -1.f);
  for (int i = 0; i < stacks + 1; ++i) {
    for (int j = 0; j < slices; ++j)
      b.add(around.cos[j] * radius, around.sin[j] * radius, z, around.cos[j], around.sin[j], 0.f);
    z += z_step;
  }
  z -= z_step;
  for (int j = 0; j < slices; ++j) b.add(around.cos[j] * radius, around.sin[j] * radius, z, 0.f, 0.f, 1.f);
  b.add(0.f, 0.f, height, 0.f, 0.f, 1.f);
  const GLushort last = GLushort(b.count() - 1);
  if (wire) return draw_side_wire(b, slices, stacks, stacks + 1);
  Indices strip = base_and_side_strips(slices, stacks);
  const GLushort top_ring = GLushort(1 + (stacks + 2) * slices);
  for (int j = 0; j < slices; ++j) strip.insert(strip.end(), {GLushort(top_ring + j), last});
  strip.insert(strip.end(), {top_ring, last});
  draw_solid_strips(b, strip, stacks + 2);
}

// ---- torus: rings around z (psi), sides around the tube (phi), vertex (ring j, side i) at
// j * sides + i
void torus(GLfloat inner, GLfloat outer, GLint sides, GLint rings, bool wire) {
  if (sides < 2 || rings < 2) return;
  const Circle psi(rings, false), phi(-sides, false);
  Buffers b;
  for (int j = 0; j < rings; ++j)
    for (int i = 0; i < sides; ++i)
      b.add(psi.cos[j] * (outer + phi.cos[i] * inner), psi.sin[j] * (outer + phi.cos[i] * inner), phi.sin[i] * inner,
            psi.cos[j] * phi.cos[i], psi.sin[j] * phi.cos[i], phi.sin[i]);
  if (wire) {
    Indices ring_loops, side_loops;
    for (int j = 0; j < rings; ++j)
      for (int i = 0; i < sides; ++i) ring_loops.push_back(GLushort(j * sides + i));
    for (int i = 0; i < sides; ++i)
      for (int j = 0; j < rings; ++j) side_loops.push_back(GLushort(j * sides + i));
    ffc::glut::draw_wire(b.vertices.data(), b.normals.data(), ring_loops.data(), rings, sides, GL_LINE_LOOP,
                         side_loops.data(), sides, rings);
    return;
  }
  Indices strip;
  for (int i = 0; i < sides; ++i) {
    const int next = i == sides - 1 ? -i : 1;  // the last side pairs with the first
    for (int j = 0; j < rings; ++j) strip.insert(strip.end(), {GLushort(j * sides + i), GLushort(j * sides + i + next)});
    strip.insert(strip.end(), {GLushort(i), GLushort(i + next)});
  }
  draw_solid_strips(b, strip, sides);
}

}  // namespace

FFC_GLUT_EXPORT void FGAPIENTRY glutSolidSphere(double radius, GLint slices, GLint stacks) {
  sphere(GLfloat(radius), slices, stacks, false);
}
FFC_GLUT_EXPORT void FGAPIENTRY glutWireSphere(double radius, GLint slices, GLint stacks) {
  sphere(GLfloat(radius), slices, stacks, true);
}
FFC_GLUT_EXPORT void FGAPIENTRY glutSolidCone(double base, double height, GLint slices, GLint stacks) {
  cone(GLfloat(base), GLfloat(height), slices, stacks, false);
}
FFC_GLUT_EXPORT void FGAPIENTRY glutWireCone(double base, double height, GLint slices, GLint stacks) {
  cone(GLfloat(base), GLfloat(height), slices, stacks, true);
}
FFC_GLUT_EXPORT void FGAPIENTRY glutSolidCylinder(double radius, double height, GLint slices, GLint stacks) {
  cylinder(GLfloat(radius), GLfloat(height), slices, stacks, false);
}
FFC_GLUT_EXPORT void FGAPIENTRY glutWireCylinder(double radius, double height, GLint slices, GLint stacks) {
  cylinder(GLfloat(radius), GLfloat(height), slices, stacks, true);
}
FFC_GLUT_EXPORT void FGAPIENTRY glutSolidTorus(double innerRadius, double outerRadius, GLint sides, GLint rings) {
  torus(GLfloat(innerRadius), GLfloat(outerRadius), sides, rings, false);
}
FFC_GLUT_EXPORT void FGAPIENTRY glutWireTorus(double innerRadius, double outerRadius, GLint sides, GLint rings) {
  torus(GLfloat(innerRadius), GLfloat(outerRadius), sides, rings, true);
}
