// What the stress catalogue's cases are made of (stress/cases_*.cpp, one file per group, put in
// order by stress/cases.cpp): the normal modes, the hand-derived checks and the scenes they draw.
// Not an interface beyond the catalogue.
#pragma once
#include <array>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gl/dispatch.h"
#include "gl/glu.h"
#include "stress/scenes.h"
#include "stress/stress.h"

namespace ffc::stress::kit {

using scenes::Geometry;

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
inline constexpr double kInf = std::numeric_limits<double>::infinity();

enum class Normals { Plain, Normalize, Rescale };

inline void enable(Normals m) {
  if (m == Normals::Normalize) glEnable(GL_NORMALIZE);
  if (m == Normals::Rescale) glEnable(GL_RESCALE_NORMAL);
}

inline const char* suffix(Normals m) {
  return m == Normals::Normalize ? "normalize" : m == Normals::Rescale ? "rescale" : "plain";
}

inline std::string num(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

// --- hand-derived checks

// Every feedback vertex of our two backends has colour `want` (within `tol`).
inline std::function<std::string(const Observed&)> all_vertices_are(glm::dvec4 want, double tol = 1e-5) {
  return [=](const Observed& o) -> std::string {
    for (const Run* r : {&o.soft, &o.dbl}) {
      if (r->feedback.empty()) return "no primitives in our feedback";
      for (const auto& p : r->feedback)
        for (const auto& v : p.vertices)
          for (int k = 0; k < 4; ++k)
            if (!(std::abs(v.color[k] - want[k]) <= tol)) {
              std::ostringstream s;
              s << (r == &o.soft ? "float" : "double") << " vertex colour (" << v.color.r << ", " << v.color.g << ", "
                << v.color.b << ", " << v.color.a << ") where the hand-derived colour is (" << want.r << ", "
                << want.g << ", " << want.b << ", " << want.a << ")";
              return s.str();
            }
    }
    return "";
  };
}

inline std::string expect_no_primitives(const Observed& o) {
  if (!o.soft.feedback.empty() || !o.dbl.feedback.empty())
    return "our feedback has " + std::to_string(o.soft.feedback.size()) + " primitives where the spec clips all";
  return "";
}

// --- scenes

// The standard sphere (icosphere depth 3) behind translate(0, 0, -4), rotate(30, 1, 1, 0) and
// scale(s); its positions are multiplied by 1/s so the picture stays the same when the inverse
// transpose of the modelview does its job.
inline std::function<void()> scaled_sphere(glm::dvec3 s, Normals m, bool rotate = true) {
  return [=] {
    scenes::standard();
    enable(m);
    // A flattened sphere's front and back lie at one depth: only the front is drawn. (A sphere
    // scaled to a point has no pixels: its triangles stay, for feedback.)
    const int zeros = (s.x == 0) + (s.y == 0) + (s.z == 0);
    if (zeros == 1 || zeros == 2) glEnable(GL_CULL_FACE);
    glTranslatef(0, 0, -4);
    if (rotate) glRotatef(30, 1, 1, 0);
    glScaled(s.x, s.y, s.z);
    auto inv = [](double x) { return x != 0 ? 1 / x : 1.0; };
    scenes::draw(scenes::sphere(3), {inv(s.x), inv(s.y), inv(s.z)});
  };
}

// The standard sphere at (0, 0, -4) with its normals multiplied by `k`.
inline std::function<void()> sphere_normals_times(double k, Normals m) {
  return [=] {
    scenes::standard();
    enable(m);
    const GLfloat e[] = {0.1f, 0.05f, 0, 1};
    glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, e);
    glTranslatef(0, 0, -4);
    scenes::draw(scenes::sphere(3), 1, k);
  };
}

// A 16x16 grid facing the viewer at z = -3 (its centre is a grid vertex, on the optical axis,
// window (32, 32)), lit by GL_LIGHT0 set up by `light` (in eye space), no other light.
inline std::function<void()> lit_grid(std::function<void()> light, int n = 16) {
  return [=] {
    scenes::standard();
    light();
    glTranslatef(0, 0, -3);
    scenes::draw(scenes::grid(n), 0.9);
  };
}

inline void spot(glm::vec4 pos, glm::vec3 dir, float cutoff, float exponent) {
  const GLfloat p[] = {pos.x, pos.y, pos.z, pos.w}, d[] = {dir.x, dir.y, dir.z};
  glLightfv(GL_LIGHT0, GL_POSITION, p);
  glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, d);
  glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, cutoff);
  glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, exponent);
}

// A grid of quads drawn from a float array with one poisoned value (at vertex `at`, component
// `k`: 0-2 position, 3-5 normal).
inline std::function<void()> poisoned_grid(int at, int k, double value) {
  return [=] {
    scenes::standard();
    glTranslatef(0, 0, -3);
    const Geometry g = scenes::grid(8);
    std::vector<float> v;
    for (size_t i = 0; i < g.positions.size(); ++i) {
      for (int c = 0; c < 3; ++c) v.push_back(float(g.positions[i][c] * 0.9));
      for (int c = 0; c < 3; ++c) v.push_back(float(g.normals[i][c]));
    }
    v[size_t(at) * 6 + size_t(k)] = float(value);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glVertexPointer(3, GL_FLOAT, 6 * sizeof(float), v.data());
    glNormalPointer(GL_FLOAT, 6 * sizeof(float), v.data() + 3);
    glDrawElements(GL_TRIANGLES, GLsizei(g.indices.size()), GL_UNSIGNED_INT, g.indices.data());
  };
}

// The sphere with its normals in an integer type (GL 2.1 table 2.9 maps them to [-1, 1]), the
// extremes included: each normal scaled to the type's range, and every 7th vertex's normal
// replaced by the most negative value on every axis.
template <typename T>
inline std::function<void()> integer_normals(GLenum type, bool normalize) {
  return [=] {
    scenes::standard();
    if (normalize) glEnable(GL_NORMALIZE);
    glTranslatef(0, 0, -4);
    const Geometry& g = scenes::sphere(3);
    std::vector<float> p;
    std::vector<T> n;
    const double range = double(std::numeric_limits<T>::max());
    for (size_t i = 0; i < g.positions.size(); ++i)
      for (int c = 0; c < 3; ++c) {
        p.push_back(float(g.positions[i][c]));
        n.push_back(i % 7 == 3 ? std::numeric_limits<T>::min() : T(std::lround(g.normals[i][c] * range)));
      }
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, p.data());
    glNormalPointer(type, 0, n.data());
    glDrawElements(GL_TRIANGLES, GLsizei(g.indices.size()), GL_UNSIGNED_INT, g.indices.data());
  };
}

// Geometry drawn with face normals under a directional light, fitted to the view by glOrtho.
inline std::function<void()> mesh_scene(std::function<Geometry()> make, Normals m, double extent = 1.3) {
  auto g = std::make_shared<Geometry>();
  auto made = std::make_shared<bool>(false);
  return [=] {
    if (!*made) *g = make(), *made = true;
    scenes::standard();
    enable(m);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-extent, extent, -extent, extent, -10, 10);
    glMatrixMode(GL_MODELVIEW);
    const GLfloat dir[] = {0.3f, 0.4f, 1, 0};
    glLightfv(GL_LIGHT0, GL_POSITION, dir);
    glRotatef(-20, 1, 0, 0);
    scenes::draw(*g);
  };
}

// A modelview looking at `target` (a point near the unit sphere) from outside along its direction.
inline void gluLookAtLike(const std::array<double, 3>& target) {
  const double len = std::sqrt(target[0] * target[0] + target[1] * target[1] + target[2] * target[2]);
  const double e[3] = {target[0] / len * 2, target[1] / len * 2, target[2] / len * 2};
  gluLookAt(e[0], e[1], e[2], target[0], target[1], target[2], 0, 1, 0);
}

// A patch of the icosphere seen face on from outside, its centroid in the middle, 1.2 wide.
inline void draw_patch_face_on(const Geometry& g) {
  scenes::standard();
  const auto ctr = scenes::centroid(g);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-0.6, 0.6, -0.6, 0.6, -3, 3);
  glMatrixMode(GL_MODELVIEW);
  gluLookAtLike(ctr);
  scenes::draw(g);
}

// Shared by the notes of the cases that invert a stiff modelview.
inline const std::string kMesaInverse =
    " Mesa inverts the modelview in float by its kind (m_matrix.c): a uniform scale with rotation "
    "takes 1/(sum of squares of a row), a scale without rotation 1/s per axis, anything else "
    "the 3x3 adjugate, refused when |det| < 1e-25; a refused matrix is 'singular' and its inverse "
    "is the identity.";

// Each group's cases, appended to `out` in the catalogue's order.
void add_scale(std::vector<Case>& out);
void add_normals(std::vector<Case>& out);
void add_material(std::vector<Case>& out);
void add_spot(std::vector<Case>& out);
void add_attenuation(std::vector<Case>& out);
void add_positions_w(std::vector<Case>& out);
void add_viewer(std::vector<Case>& out);
void add_meshes(std::vector<Case>& out);
void add_viewports(std::vector<Case>& out);
void add_arrays(std::vector<Case>& out);

}  // namespace ffc::stress::kit
