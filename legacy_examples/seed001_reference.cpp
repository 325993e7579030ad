#include "seed001_reference.h"

#include <cmath>
#include <cstdlib>
#include <limits>
#include <vector>

namespace seed001 {

glm::dvec3 illuminate(const Lighting& l, const View& v, const glm::dvec3& normal, const glm::dvec3& pos) {
  const glm::dvec3 material(1, 0, 0);
  glm::dvec3 colour = (l.light_ambient + l.global_ambient) * material;
  if (l.terms < 2) return colour;
  const glm::dvec3 light_dir = glm::normalize(l.light_pos - pos);
  const double n_dot_l = glm::dot(normal, light_dir);
  colour += std::max(n_dot_l, 0.0) * material;
  if (l.terms < 3) return colour;
  // A rigid view keeps every dot product: lighting in eye space is lighting in world space.
  const glm::dvec3 eye = eye_position(v);
  const glm::dvec3 view_dir = l.infinite_viewer ? glm::normalize(eye) : glm::normalize(eye - pos);
  double spec;
  if (l.half_vector) {
    spec = std::pow(std::max(glm::dot(normal, glm::normalize(light_dir + view_dir)), 0.0), l.shininess);
  } else {
    const glm::dvec3 reflect_dir = -light_dir - 2 * glm::dot(normal, -light_dir) * normal;  // GLSL's reflect()
    spec = std::pow(std::max(glm::dot(view_dir, reflect_dir), 0.0), l.shininess);
  }
  if (l.nl_guard && n_dot_l <= 0) spec = 0;
  return colour + glm::dvec3(spec);  // white light, white material specular
}

namespace {

struct Corner {
  glm::dvec3 pos, normal;
};

// The triangle's corners as the vertex shader sees them: the float data, normals normalised.
void triangle_corners(const Lighting& l, int t, Corner c[3]) {
  for (int k = 0; k < 3; ++k) {
    const Vertex& vx = l.averaged_normals ? averaged_normal_vertices()[averaged_normal_indices()[3 * t + k]]
                                          : face_normal_vertices()[3 * t + k];
    c[k].pos = {vx.pos[0], vx.pos[1], vx.pos[2]};
    c[k].normal = glm::normalize(glm::dvec3(vx.normal[0], vx.normal[1], vx.normal[2]));
  }
}

// Möller-Trumbore: the ray's parameter and the barycentric weights of the hit, or false.
bool intersect(const glm::dvec3& o, const glm::dvec3& d, const Corner c[3], double& t, glm::dvec3& w) {
  const glm::dvec3 e1 = c[1].pos - c[0].pos, e2 = c[2].pos - c[0].pos;
  const glm::dvec3 p = glm::cross(d, e2);
  const double det = glm::dot(e1, p);
  if (std::abs(det) < 1e-14) return false;
  const glm::dvec3 s = o - c[0].pos;
  const double u = glm::dot(s, p) / det;
  const glm::dvec3 q = glm::cross(s, e1);
  const double vv = glm::dot(d, q) / det;
  if (u < 0 || vv < 0 || u + vv > 1) return false;
  t = glm::dot(e2, q) / det;
  w = {1 - u - vv, u, vv};
  return t > 0;
}

int hit_triangle(const Lighting& l, const View& v, double px, double py, glm::dvec3& weights, Corner hit[3]) {
  // The pixel centre's ray: from the near plane to the far plane through inverse(P V).
  const glm::dmat4 inv = glm::inverse(projection(v) * view_matrix(v));
  const double nx = px / v.width * 2 - 1, ny = 1 - py / v.height * 2;
  const glm::dvec4 a = inv * glm::dvec4(nx, ny, -1, 1), b = inv * glm::dvec4(nx, ny, 1, 1);
  const glm::dvec3 o = glm::dvec3(a) / a.w, d = glm::dvec3(b) / b.w - o;
  int best = -1;
  double best_t = std::numeric_limits<double>::infinity();
  for (int t = 0; t < 12; ++t) {
    Corner c[3];
    triangle_corners(l, t, c);
    double tt;
    glm::dvec3 w;
    if (intersect(o, d, c, tt, w) && tt < best_t) {
      best_t = tt, best = t, weights = w;
      for (int k = 0; k < 3; ++k) hit[k] = c[k];
    }
  }
  return best;
}

}  // namespace

PixelRef reference_pixel(const Lighting& l, const View& v, int x, int y) {
  PixelRef r;
  glm::dvec3 w;
  Corner c[3];
  r.triangle = hit_triangle(l, v, x + 0.5, y + 0.5, w, c);
  if (r.triangle < 0) return r;
  r.face = r.triangle / 2;
  r.point = w.x * c[0].pos + w.y * c[1].pos + w.z * c[2].pos;
  glm::dvec3 colour(0);
  if (l.per_fragment) {
    // Phong: the normal and the position interpolated, the normal normalised again.
    colour = illuminate(l, v, glm::normalize(w.x * c[0].normal + w.y * c[1].normal + w.z * c[2].normal), r.point);
  } else {
    // Gouraud: three vertex colours, interpolated unclamped unless the lighting clamps them.
    for (int k = 0; k < 3; ++k) {
      glm::dvec3 ck = illuminate(l, v, c[k].normal, c[k].pos);
      if (l.clamp_vertex_colour) ck = glm::clamp(ck, 0.0, 1.0);
      colour += w[k] * ck;
    }
  }
  r.colour = glm::clamp(colour, 0.0, 1.0);
  return r;
}

ReferenceCheck check_against_reference(const ffc::image::Image& img, const Lighting& l, const View& v0) {
  View v = v0;
  v.width = img.width, v.height = img.height;
  const int w = img.width, h = img.height;
  std::vector<PixelRef> refs(size_t(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) refs[size_t(y) * w + x] = reference_pixel(l, v, x, y);
  ReferenceCheck r;
  double sum = 0;
  for (int y = 1; y + 1 < h; ++y)
    for (int x = 1; x + 1 < w; ++x) {
      const int face = refs[size_t(y) * w + x].face;
      bool same = true;
      for (int dy = -1; dy <= 1 && same; ++dy)
        for (int dx = -1; dx <= 1 && same; ++dx) same = refs[size_t(y + dy) * w + x + dx].face == face;
      if (!same) continue;
      const uint8_t* px = img.at(x, y);
      if (face < 0) {
        ++r.background;
        r.background_wrong += px[0] || px[1] || px[2];
        continue;
      }
      const glm::dvec3& c = refs[size_t(y) * w + x].colour;
      int d = 0;
      for (int k = 0; k < 3; ++k) d = std::max(d, std::abs(int(px[k]) - int(std::lround(255 * c[k]))));
      ++r.pixels;
      sum += d;
      if (d > r.max_diff || r.worst_x < 0) r.max_diff = d, r.worst_x = x, r.worst_y = y;
    }
  r.mean_diff = r.pixels ? sum / r.pixels : 0;
  return r;
}

GuardSweep sweep_nl_guard(const Lighting& l0) {
  Lighting l = l0;
  l.terms = 3, l.nl_guard = false;
  GuardSweep g;
  constexpr int kGrid = 16;
  for (int a = 0; a < 36; ++a)
    for (int h = -6; h <= 6; ++h) {
      View v;
      v.cam_ang = a * 10 * M_PI / 180, v.cam_height = h * 0.5;
      const glm::dvec3 eye = eye_position(v);
      double camera_max = 0;
      for (int t = 0; t < 12; ++t) {
        Corner c[3];
        triangle_corners(l, t, c);
        const glm::dvec3 geometric = glm::cross(c[1].pos - c[0].pos, c[2].pos - c[0].pos);
        for (int i = 0; i <= kGrid; ++i)
          for (int j = 0; i + j <= kGrid; ++j) {
            const double u = double(i) / kGrid, w = double(j) / kGrid;
            const glm::dvec3 p = (1 - u - w) * c[0].pos + u * c[1].pos + w * c[2].pos;
            if (glm::dot(geometric, eye - p) <= 0) continue;  // seen from behind: hidden on a convex cube
            const glm::dvec3 n = glm::normalize((1 - u - w) * c[0].normal + u * c[1].normal + w * c[2].normal);
            if (glm::dot(n, l.light_pos - p) > 0) continue;  // lit side: the guard changes nothing
            const double steps = 255 * (illuminate(l, v, n, p).g);  // green: specular alone (red material)
            if (steps > camera_max) camera_max = steps;
            if (steps > g.max_steps)
              g.max_steps = steps, g.cam_angle_deg = a * 10, g.cam_height = v.cam_height, g.point = p, g.face = t / 2;
          }
      }
      ++g.cameras;
      g.cameras_affected += camera_max >= 0.5;
    }
  return g;
}

}  // namespace seed001
