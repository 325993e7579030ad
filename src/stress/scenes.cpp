#include "stress/scenes.h"

#include <cmath>
#include <map>
#include <mutex>

#include "gl/dispatch.h"
#include "mesh/icosphere.h"
#include "mesh/mesh.h"

namespace ffc::stress::scenes {

namespace {

using V = std::array<double, 3>;

V add(const V& a, const V& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }

// src/mesh/icosphere.cpp's midpoint: the sum normalized, in double, in the same order of operations.
V mid(const V& a, const V& b) {
  const V m = add(a, b);
  const double len = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
  return {m[0] / len, m[1] / len, m[2] / len};
}

// A triangle (a, b, c) subdivided `depth` times as the icosphere does, on a barycentric grid:
// vertex (i, j) of level d (N = 2^d, i + j <= N) sits at a + i/N (b - a) + j/N (c - a) before
// the projection; a vertex with both coordinates even is the level-(d-1) vertex (i/2, j/2), the
// others are midpoints of the coarse edge through them.
Geometry subdivide(const V& a, const V& b, const V& c, int depth) {
  std::vector<V> level = {a, b, c};  // N = 1: (0,0), (1,0), (0,1)
  auto at = [](int n, int i, int j) { return size_t(j) * (2 * n + 3 - j) / 2 + i; };  // row j has n + 1 - j entries
  int n = 1;
  for (int d = 0; d < depth; ++d) {
    const int m = 2 * n;
    std::vector<V> next(size_t(m + 1) * (m + 2) / 2);
    for (int j = 0; j <= m; ++j)
      for (int i = 0; i + j <= m; ++i) {
        V p;
        if (i % 2 == 0 && j % 2 == 0) p = level[at(n, i / 2, j / 2)];
        else if (j % 2 == 0) p = mid(level[at(n, (i - 1) / 2, j / 2)], level[at(n, (i + 1) / 2, j / 2)]);
        else if (i % 2 == 0) p = mid(level[at(n, i / 2, (j - 1) / 2)], level[at(n, i / 2, (j + 1) / 2)]);
        else p = mid(level[at(n, (i - 1) / 2, (j + 1) / 2)], level[at(n, (i + 1) / 2, (j - 1) / 2)]);
        next[at(m, i, j)] = p;
      }
    level = std::move(next);
    n = m;
  }
  Geometry g;
  g.positions = level;
  g.normals = level;  // on the unit sphere: the sphere normal is the position
  for (auto& p : g.normals) {
    const double len = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    p = {p[0] / len, p[1] / len, p[2] / len};
  }
  g.indices.reserve(size_t(n) * n * 3);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i + j < n; ++i) {
      g.indices.insert(g.indices.end(), {uint32_t(at(n, i, j)), uint32_t(at(n, i + 1, j)), uint32_t(at(n, i, j + 1))});
      if (i + j < n - 1)
        g.indices.insert(g.indices.end(),
                         {uint32_t(at(n, i + 1, j)), uint32_t(at(n, i + 1, j + 1)), uint32_t(at(n, i, j + 1))});
    }
  return g;
}

// Face normals from src/mesh (OpenMesh, double), one vertex per triangle corner.
Geometry with_face_normals(const std::vector<mesh::Vec3>& p, const std::vector<mesh::Tri>& t) {
  mesh::Mesh m = mesh::build(p, t);
  mesh::update_normals(m);
  const mesh::Layout l = mesh::layout(m, mesh::NormalSource::Face);
  Geometry g;
  for (const auto& v : l.vertices) {
    g.indices.push_back(uint32_t(g.positions.size()));
    g.positions.push_back(v.position);
    g.normals.push_back(v.normal);
  }
  return g;
}

}  // namespace

const Geometry& sphere(int depth) {
  static std::mutex lock;
  static std::map<int, Geometry> cache;
  std::lock_guard<std::mutex> hold(lock);
  auto it = cache.find(depth);
  if (it != cache.end()) return it->second;
  const mesh::Layout l = mesh::layout(mesh::make_icosphere(depth), mesh::NormalSource::Sphere);
  Geometry g;
  for (const auto& v : l.vertices) g.positions.push_back(v.position), g.normals.push_back(v.normal);
  g.indices = l.indices;
  return cache[depth] = std::move(g);
}

Geometry grid(int n) {
  Geometry g;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      g.positions.push_back({-1 + 2.0 * i / n, -1 + 2.0 * j / n, 0});
      g.normals.push_back({0, 0, 1});
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const uint32_t a = uint32_t(j * (n + 1) + i), b = a + 1, c = a + uint32_t(n + 1), d = c + 1;
      g.indices.insert(g.indices.end(), {a, b, d, a, d, c});
    }
  return g;
}

void standard(bool lit) {
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.35, 0.35, -0.35, 0.35, 1, 10);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  if (!lit) return;
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  const GLfloat pos[] = {2, 2, 2, 1}, amb[] = {0.1f, 0.1f, 0.1f, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  glLightfv(GL_LIGHT0, GL_AMBIENT, amb);
  const GLfloat ma[] = {0.2f, 0.2f, 0.2f, 1}, md[] = {0.8f, 0.6f, 0.4f, 1}, ms[] = {0.5f, 0.5f, 0.5f, 1};
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, ma);
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, md);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, ms);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 32);
}

namespace {

// g's triangles from positions of `size` components and normals, both of `type`, as client arrays.
void draw_arrays(const Geometry& g, GLint size, GLenum type, const void* positions, const void* normals) {
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glVertexPointer(size, type, 0, positions);
  glNormalPointer(type, 0, normals);
  glDrawElements(GL_TRIANGLES, GLsizei(g.indices.size()), GL_UNSIGNED_INT, g.indices.data());
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisableClientState(GL_NORMAL_ARRAY);
}

}  // namespace

void draw(const Geometry& g, const std::array<double, 3>& scale, double normal_scale) {
  std::vector<float> p, n;
  p.reserve(g.positions.size() * 3), n.reserve(g.normals.size() * 3);
  for (const auto& v : g.positions)
    for (int k = 0; k < 3; ++k) p.push_back(float(v[k] * scale[k]));
  for (const auto& v : g.normals)
    for (double x : v) n.push_back(float(x * normal_scale));
  draw_arrays(g, 3, GL_FLOAT, p.data(), n.data());
}

void draw_homogeneous(const Geometry& g, double scale, float w) {
  std::vector<float> p, n;
  for (size_t i = 0; i < g.positions.size(); ++i) {
    for (int k = 0; k < 3; ++k) p.push_back(float(g.positions[i][k] * scale)), n.push_back(float(g.normals[i][k]));
    p.push_back(w);
  }
  draw_arrays(g, 4, GL_FLOAT, p.data(), n.data());
}

void draw_double(const Geometry& g, double scale) {
  std::vector<double> p, n;
  for (const auto& v : g.positions)
    for (double x : v) p.push_back(x * scale);
  for (const auto& v : g.normals)
    for (double x : v) n.push_back(x);
  draw_arrays(g, 3, GL_DOUBLE, p.data(), n.data());
}

Geometry slivers() {
  // A fan around the origin: apex angles from 0.5 down to 1e-7 radians, each triangle reaching
  // out to radius 1; the thinnest are far below a pixel wide.
  std::vector<mesh::Vec3> p = {{0, 0, 0}};
  std::vector<mesh::Tri> t;
  double angle = -2.0;
  for (double a : {0.5, 0.1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 0.3, 1e-7, 1e-6, 0.2}) {
    p.push_back({std::cos(angle), std::sin(angle), 0});
    p.push_back({std::cos(angle + a), std::sin(angle + a), 0.1});
    t.push_back({0, int(p.size()) - 2, int(p.size()) - 1});
    angle += a + 0.3;
  }
  return with_face_normals(p, t);
}

Geometry needles() {
  // Long triangles across the view, 1e-4 to 1e-7 wide at their base, tilted so their normals vary.
  std::vector<mesh::Vec3> p;
  std::vector<mesh::Tri> t;
  int k = 0;
  for (double w : {1e-4, 1e-5, 1e-6, 1e-7}) {
    const double y = -0.8 + 0.5 * k++;
    const int b = int(p.size());
    p.push_back({-1.2, y, 0.2});
    p.push_back({1.2, y + 0.3, -0.2});
    p.push_back({1.2, y + 0.3 + w, -0.2 + w});
    t.push_back({b, b + 1, b + 2});
  }
  return with_face_normals(p, t);
}

Geometry near_duplicates() {
  // A 6x6 grid on a gentle bump; every other column is doubled by a vertex one float ulp to the
  // right, joined by triangles of (nearly) zero area.
  std::vector<mesh::Vec3> p;
  std::vector<mesh::Tri> t;
  const int n = 6;
  std::vector<std::vector<int>> col(n + 1);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x = -1 + 2.0 * i / n, y = -1 + 2.0 * j / n, z = 0.3 * std::exp(-(x * x + y * y));
      col[j].push_back(int(p.size()));
      p.push_back({x, y, z});
      if (i % 2 == 1 && i < n) {  // the twin, one float step to the right
        col[j].push_back(int(p.size()));
        p.push_back({double(std::nextafter(float(x), 2.0f)), y, z});
      }
    }
  for (int j = 0; j < n; ++j)
    for (size_t i = 0; i + 1 < col[j].size(); ++i) {
      const int a = col[j][i], b = col[j][i + 1], c = col[j + 1][i], d = col[j + 1][i + 1];
      t.push_back({a, b, d});
      t.push_back({a, d, c});
    }
  return with_face_normals(p, t);
}

Geometry icosphere_patch(int depth) {
  const auto& p = mesh::icosahedron_positions();
  const mesh::Tri t = mesh::icosahedron_triangles()[0];
  return subdivide(p[t[0]], p[t[1]], p[t[2]], depth);
}

Geometry icosphere_deep_patch(int descend, int depth) {
  const auto& p = mesh::icosahedron_positions();
  const mesh::Tri t = mesh::icosahedron_triangles()[0];
  V a = p[t[0]], b = p[t[1]], c = p[t[2]];
  for (int d = 0; d < descend; ++d) {  // child 0: (v1, v12, v31)
    const V ab = mid(a, b), ca = mid(c, a);
    b = ab, c = ca;
  }
  return subdivide(a, b, c, depth);
}

std::array<double, 3> centroid(const Geometry& g) {
  V s = {0, 0, 0};
  for (const auto& v : g.positions) s = add(s, v);
  const double n = double(g.positions.size());
  return {s[0] / n, s[1] / n, s[2] / n};
}

}  // namespace ffc::stress::scenes
