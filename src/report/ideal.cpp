#include "report/ideal.h"

#include <cmath>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

#include "raster/raster.h"

namespace ffc::report {

namespace {

glm::dvec4 d4(const scene::Color& c) { return {c[0], c[1], c[2], c[3]}; }

lighting::MaterialParams material(const scene::Material& m) {
  lighting::MaterialParams p;
  p.ambient = d4(m.ambient), p.diffuse = d4(m.diffuse), p.specular = d4(m.specular), p.emission = d4(m.emission);
  p.shininess = m.shininess;
  return p;
}

}  // namespace

glm::dmat4 view_matrix(const scene::Camera& c) {
  return glm::lookAtRH(glm::dvec3(c.eye[0], c.eye[1], c.eye[2]), glm::dvec3(c.center[0], c.center[1], c.center[2]),
                       glm::dvec3(c.up[0], c.up[1], c.up[2]));
}

glm::dmat4 projection_matrix(const scene::Camera& c, int width, int height) {
  switch (c.projection) {
    case scene::Camera::Projection::Perspective:
      return glm::perspectiveRH_NO(glm::radians(c.fovy_deg), c.aspect > 0 ? c.aspect : double(width) / height,
                                   c.z_near, c.z_far);
    case scene::Camera::Projection::Frustum:
      return glm::frustumRH_NO(c.left, c.right, c.bottom, c.top, c.z_near, c.z_far);
    case scene::Camera::Projection::Ortho: return glm::orthoRH_NO(c.left, c.right, c.bottom, c.top, c.z_near, c.z_far);
  }
  throw std::logic_error("unknown projection");
}

LightingState lighting_state(const scene::Description& d) {
  LightingState s;
  const glm::dmat4 view = view_matrix(d.camera);
  for (int i = 0; i < scene::max_lights; ++i) {
    const scene::Light& l = d.lights[size_t(i)];
    const scene::Light def = scene::default_light(i);
    lighting::LightParams& p = s.lights[i];
    p.enabled = l.enabled;
    p.ambient = d4(l.ambient), p.diffuse = d4(l.diffuse), p.specular = d4(l.specular);
    const glm::dvec4 pos(l.position[0], l.position[1], l.position[2], l.position[3]);
    const glm::dvec3 dir(l.spot_direction[0], l.spot_direction[1], l.spot_direction[2]);
    const bool world = l.space == scene::Space::World;
    // As scene::draw places them: GL transforms by the modelview current when they are set.
    p.position = world ? view * pos : pos;
    const bool dir_set = l.spot_direction != def.spot_direction || (world && l.spot_cutoff != def.spot_cutoff);
    p.spot_direction = world && dir_set ? glm::dmat3(view) * dir : dir;
    p.spot_exponent = l.spot_exponent, p.spot_cutoff = l.spot_cutoff;
    p.constant_attenuation = l.constant_attenuation, p.linear_attenuation = l.linear_attenuation;
    p.quadratic_attenuation = l.quadratic_attenuation;
  }
  s.materials[0] = material(d.front);
  s.materials[1] = material(d.back);
  s.model.ambient = d4(d.light_model.ambient);
  s.model.local_viewer = d.light_model.local_viewer;
  s.model.two_side = d.light_model.two_sided;
  s.model.separate_specular = d.light_model.separate_specular;
  s.model.color_material = false;
  s.key = lighting::make_key(s.lights, s.materials, s.model, d.normalize, d.rescale_normal);
  return s;
}

Ideal ray_cast_sphere(const scene::Description& d) {
  if (!d.transforms.empty()) throw std::invalid_argument("ideal sphere: scene transforms are not modelled");
  if (d.color_material.enabled) throw std::invalid_argument("ideal sphere: colour material is not modelled");
  if (!d.lighting) throw std::invalid_argument("ideal sphere: lighting is off");
  if (d.width <= 0 || d.height <= 0) throw std::invalid_argument("ideal sphere: empty picture");
  const LightingState st = lighting_state(d);
  const lighting::Prepared<double> prepared = lighting::prepare<double>(st.lights, st.materials, st.model, st.key);
  const glm::dmat4 view = view_matrix(d.camera);
  const glm::dmat4 unproject = glm::inverse(projection_matrix(d.camera, d.width, d.height) * view);
  const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(glm::dmat3(view)));
  const glm::dvec4 white(1, 1, 1, 1);  // the current colour: unused without colour material

  Ideal out;
  out.image = image::Image(d.width, d.height);
  out.exact.assign(size_t(d.width) * d.height, glm::dvec3(0));
  out.covered.assign(size_t(d.width) * d.height, 0);
  uint8_t background[4];
  for (int k = 0; k < 4; ++k) background[k] = raster::to_unorm8(d.background[size_t(k)]);
  for (int row = 0; row < d.height; ++row) {
    const double wy = d.height - 1 - row + 0.5;  // window y of the pixel centre: GL's row 0 is the bottom
    for (int col = 0; col < d.width; ++col) {
      const double wx = col + 0.5;
      const double nx = 2 * wx / d.width - 1, ny = 2 * wy / d.height - 1;
      // The pixel centre on the near and far planes, in world (= object) space.
      glm::dvec4 a = unproject * glm::dvec4(nx, ny, -1, 1), b = unproject * glm::dvec4(nx, ny, 1, 1);
      const glm::dvec3 o = glm::dvec3(a) / a.w, dir = glm::dvec3(b) / b.w - o;
      // |o + t dir|^2 = 1, the near root within [0, 1] (between the clip planes).
      const double qa = glm::dot(dir, dir), qb = glm::dot(o, dir), qc = glm::dot(o, o) - 1;
      const double disc = qb * qb - qa * qc;
      uint8_t* px = out.image.at(col, row);
      const size_t i = size_t(row) * d.width + col;
      double t = -1;
      if (disc >= 0) {
        const double sq = std::sqrt(disc);
        // Stable roots: q = -(qb + sign(qb) sq); t1 = q / qa, t2 = qc / q.
        const double q = -(qb + (qb >= 0 ? sq : -sq));
        double t1 = q / qa, t2 = q != 0 ? qc / q : t1;
        if (t1 > t2) std::swap(t1, t2);
        t = t1 >= 0 ? t1 : t2;
      }
      if (!(t >= 0 && t <= 1)) {
        for (int k = 0; k < 4; ++k) px[k] = background[k];
        continue;
      }
      const glm::dvec3 p = o + t * dir;
      const glm::dvec3 n = glm::normalize(p);  // the unit sphere's exact normal
      const glm::dvec4 pe = view * glm::dvec4(p, 1);
      const glm::dvec3 ne = glm::normalize(normal_matrix * n);
      const lighting::Lit<double> lit = lighting::light<double>(prepared, pe, ne, white);
      glm::dvec3 c = glm::dvec3(lit.primary[0]);
      if (st.model.separate_specular) c = glm::clamp(c + glm::dvec3(lit.secondary[0]), 0.0, 1.0);
      out.exact[i] = c;
      out.covered[i] = 1;
      ++out.covered_count;
      for (int k = 0; k < 3; ++k) px[k] = raster::to_unorm8(c[k]);
      px[3] = raster::to_unorm8(lit.primary[0].a);
    }
  }
  return out;
}

}  // namespace ffc::report
