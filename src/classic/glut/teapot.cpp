// glutSolid/WireTeapot, Teacup and Teaspoon: freeglut 3.4.0's patches evaluated as it evaluates
// them (8 x 8 samples per patch solid, 10 x 10 wire, in single precision with the same order of
// sums), so that the vertices, normals, texture coordinates and draw calls come out identical.
// Like freeglut, each object keeps its arrays between calls: the normals are those of the first
// call's size; a call with another size recomputes the positions only.
#include "shapes.h"
#include "teapot_data.h"

#include <cmath>
#include <vector>

namespace {

struct Teaset {
  const GLfloat (*points)[3];
  const int (*patches)[16];
  int input_patches;
  bool lid_and_bottom_fix;  // the teapot's lid top and bottom centre get straight normals
  bool turn_and_mirror;     // first six patches turned four ways, the rest mirrored (else as is)
  GLfloat z_offset;         // recentres the object on the origin
  int patch_count() const { return turn_and_mirror ? 6 * 4 + (input_patches - 6) * 2 : input_patches; }
};

const Teaset kTeapot = {ffc::glut::kTeapotPoints, ffc::glut::kTeapotPatches, 10, true, true, 1.575f};
const Teaset kTeacup = {ffc::glut::kTeacupPoints, ffc::glut::kTeacupPatches, 7, false, true, 1.5121f};
const Teaset kTeaspoon = {ffc::glut::kTeaspoonPoints, ffc::glut::kTeaspoonPatches, 16, false, false, -0.0315f};

constexpr int kSolidSamples = 8, kWireSamples = 10;

// The cubic Bernstein polynomials and their derivatives at n evenly spaced parameters.
struct Bernstein {
  std::vector<GLfloat> value, slope;  // [sample * 4 + k]
  explicit Bernstein(int n) : value(size_t(n) * 4), slope(size_t(n) * 4) {
    for (int s = 0; s < n; ++s) {
      const GLfloat x = s / (n - 1.f), inv = 1.f - x, x2 = x * x, inv2 = inv * inv;
      GLfloat *v = &value[size_t(s) * 4], *d = &slope[size_t(s) * 4];
      v[0] = inv * inv2;
      d[0] = -3 * inv2;
      v[1] = 3 * x * inv2;
      d[1] = 3 * inv2 - 6 * x * inv;
      v[2] = 3 * x2 * inv;
      d[2] = 6 * x * inv - 3 * x2;
      v[3] = x * x2;
      d[3] = 3 * x2;
    }
  }
};

// Copies a patch's n*n values (xyz) into the following slots: three quarter turns about y
// (copies = 4), or one mirror image across z = 0 with its rows reversed to keep the winding
// (copies = 2).
void replicate(int copies, int value_count, int n, GLfloat *v) {
  if (copies == 4) {
    for (int o = 0; o < value_count; o += 3) {
      GLfloat *a = v + value_count + o, *b = v + 2 * value_count + o, *c = v + 3 * value_count + o;
      a[0] = v[o + 2], a[1] = v[o + 1], a[2] = -v[o + 0];
      b[0] = -v[o + 0], b[1] = v[o + 1], b[2] = -v[o + 2];
      c[0] = -v[o + 2], c[1] = v[o + 1], c[2] = v[o + 0];
    }
  } else if (copies == 2) {
    for (int row = 0; row < n; ++row) {
      const GLfloat *from = v + (n - row - 1) * n * 3;
      GLfloat *to = v + value_count + row * n * 3;
      for (int k = 0; k < n * 3; k += 3) to[k] = from[k], to[k + 1] = from[k + 1], to[k + 2] = -from[k + 2];
    }
  }
}

// Samples one patch into `vertices` (which start at zero) and, when `normals` is given, its unit
// normals from the cross product of the two partial derivatives; returns the values written.
int evaluate(const GLfloat cp[4][4][3], int n, const Bernstein &b, int copies, int normal_fix, GLfloat *vertices,
             GLfloat *normals) {
  const int value_count = n * n * 3;
  for (int u = 0, o = 0; u < n; ++u)
    for (int v = 0; v < n; ++v, o += 3) {
      GLfloat du[3] = {0, 0, 0}, dv[3] = {0, 0, 0};
      for (int i = 0; i <= 3; ++i) {
        GLfloat row[3] = {0, 0, 0}, row_slope[3] = {0, 0, 0};
        for (int j = 0; j <= 3; ++j)
          for (int k = 0; k < 3; ++k) {
            row[k] += b.value[v * 4 + j] * cp[i][j][k];
            row_slope[k] += b.slope[v * 4 + j] * cp[i][j][k];
          }
        for (int k = 0; k < 3; ++k) {
          vertices[o + k] += b.value[u * 4 + i] * row[k];
          du[k] += b.value[u * 4 + i] * row_slope[k];
          dv[k] += b.slope[u * 4 + i] * row[k];
        }
      }
      if (normals == nullptr) continue;
      GLfloat *nrm = normals + o;
      nrm[0] = du[1] * dv[2] - du[2] * dv[1];
      nrm[1] = du[2] * dv[0] - du[0] * dv[2];
      nrm[2] = du[0] * dv[1] - du[1] * dv[0];
      const GLfloat length = GLfloat(std::sqrt(double(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2])));
      for (int k = 0; k < 3; ++k) nrm[k] /= length;
    }
  // The first row of the lid's top and of the bottom's centre collapse to a point: no tangent
  // there, so the normal is set straight up (1) or down (2).
  if (normals != nullptr && normal_fix != 0)
    for (int o = 0; o < n * 3; o += 3) normals[o] = 0.f, normals[o + 1] = normal_fix == 1 ? 1.f : -1.f, normals[o + 2] = 0.f;
  replicate(copies, value_count, n, vertices);
  if (normals != nullptr) replicate(copies, value_count, n, normals);
  return value_count * copies;
}

struct Arrays {
  std::vector<GLfloat> vertices, normals, texcoords;
  std::vector<GLushort> indices;
  GLfloat last_scale = 0.f;
  bool ready = false;
};

void build_indices(Arrays &a, int n, int patches, bool wire) {
  for (int p = 0; p < patches; ++p) {
    const int first = n * n * p;
    if (wire) {
      for (int c = 0; c < n; ++c)
        for (int r = 0; r < n; ++r) a.indices.push_back(GLushort(first + r * n + c));
    } else {
      for (int r = 0; r < n - 1; ++r)
        for (int c = 0; c < n - 1; ++c) {
          const int above = first + r * n + c, below = above + n;  // two triangles per cell
          a.indices.insert(a.indices.end(), {GLushort(above), GLushort(below), GLushort(below + 1), GLushort(above),
                                             GLushort(below + 1), GLushort(above + 1)});
        }
    }
  }
  if (wire)  // then the lines along the other parameter, appended
    for (int p = 0; p < patches; ++p)
      for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c) a.indices.push_back(GLushort(n * n * p + r * n + c));
}

void draw_teaset(const Teaset &set, Arrays &a, GLfloat scale, bool wire) {
  const int n = wire ? kWireSamples : kSolidSamples;
  static const Bernstein solid_basis(kSolidSamples), wire_basis(kWireSamples);
  const Bernstein &basis = wire ? wire_basis : solid_basis;
  const int patches = set.patch_count();
  const int vertex_count = n * n * patches;
  if (!a.ready || scale != a.last_scale) {
    a.vertices.assign(size_t(vertex_count) * 3, 0.f);
    if (!a.ready) a.normals.assign(size_t(vertex_count) * 3, 0.f);
    for (int p = 0, o = 0; p < set.input_patches; ++p) {
      const int copies = set.turn_and_mirror ? (p < 6 ? 4 : 2) : 1;
      const int normal_fix = set.lid_and_bottom_fix ? (p == 3 ? 1 : p == 5 ? 2 : 0) : 0;
      // The data are z-up; GLUT's teapot is y-up, half size, centred: folded into the points.
      GLfloat cp[4][4][3];
      for (int i = 0; i < 16; ++i) {
        const GLfloat *q = set.points[set.patches[p][i]];
        cp[i / 4][i % 4][0] = q[0] * scale / 2.f;
        cp[i / 4][i % 4][1] = (q[2] - set.z_offset) * scale / 2.f;
        cp[i / 4][i % 4][2] = -q[1] * scale / 2.f;
      }
      o += evaluate(cp, n, basis, copies, normal_fix, a.vertices.data() + o, a.ready ? nullptr : a.normals.data() + o);
    }
    a.last_scale = scale;
    if (!a.ready) {
      if (!wire) {
        for (int r = 0; r < n; ++r)
          for (int c = 0; c < n; ++c) a.texcoords.insert(a.texcoords.end(), {r / (n - 1.f), c / (n - 1.f)});
        const std::vector<GLfloat> first_patch = a.texcoords;  // the same (u, v) grid on every patch
        for (int p = 1; p < patches; ++p) a.texcoords.insert(a.texcoords.end(), first_patch.begin(), first_patch.end());
      }
      build_indices(a, n, patches, wire);
      a.ready = true;
    }
  }
  if (wire)
    ffc::glut::draw_wire(a.vertices.data(), a.normals.data(), a.indices.data(), patches * n * 2, n, GL_LINE_STRIP);
  else
    ffc::glut::draw_solid(a.vertices.data(), a.normals.data(), a.texcoords.data(), vertex_count, a.indices.data(), 1,
                          GLsizei(a.indices.size()));
}

Arrays teapot_solid, teapot_wire, teacup_solid, teacup_wire, teaspoon_solid, teaspoon_wire;

}  // namespace

FFC_GLUT_EXPORT void FGAPIENTRY glutSolidTeapot(double size) { draw_teaset(kTeapot, teapot_solid, GLfloat(size), false); }
FFC_GLUT_EXPORT void FGAPIENTRY glutWireTeapot(double size) { draw_teaset(kTeapot, teapot_wire, GLfloat(size), true); }
FFC_GLUT_EXPORT void FGAPIENTRY glutSolidTeacup(double size) {
  draw_teaset(kTeacup, teacup_solid, GLfloat(size) / 2.5f, false);
}
FFC_GLUT_EXPORT void FGAPIENTRY glutWireTeacup(double size) { draw_teaset(kTeacup, teacup_wire, GLfloat(size) / 2.5f, true); }
FFC_GLUT_EXPORT void FGAPIENTRY glutSolidTeaspoon(double size) {
  draw_teaset(kTeaspoon, teaspoon_solid, GLfloat(size) / 2.5f, false);
}
FFC_GLUT_EXPORT void FGAPIENTRY glutWireTeaspoon(double size) {
  draw_teaset(kTeaspoon, teaspoon_wire, GLfloat(size) / 2.5f, true);
}
