#include "scene/scene.h"

#include <cmath>
#include <stdexcept>

#include "mesh/cube.h"
#include "mesh/icosphere.h"

namespace ffc::scene {

Spec builtin(const std::string& name) {
  Spec s;
  s.name = name;
  if (name == "cube") {
    s.width = s.height = 640;
    s.normals = mesh::NormalSource::Face;
  } else if (name == "icosphere") {
    s.width = s.height = 512;
    s.depth = 3;
    s.normals = mesh::NormalSource::Sphere;
  } else {
    throw std::invalid_argument("unknown scene '" + name + "' (cube or icosphere)");
  }
  return s;
}

Description describe(const Spec& spec) {
  Description d;
  d.name = spec.name;
  d.width = spec.width;
  d.height = spec.height;
  d.shade = spec.shade;
  d.camera.fovy_deg = 45;
  d.camera.aspect = 0;  // width / height
  d.camera.z_near = 1;
  d.camera.z_far = 10;
  d.camera.center = {0, 0, 0};
  d.camera.up = {0, 1, 0};
  Object o;
  o.normals = spec.normals;
  o.draw = DrawPath::Auto;
  Light& l0 = d.lights[0];
  l0.enabled = true;
  if (spec.name == "cube") {
    // Seed 000's practice program.
    const double a = spec.cam_angle_deg * M_PI / 180;
    d.camera.eye = {5 * std::sin(a), spec.cam_height, 5 * std::cos(a)};
    d.axes = true;
    d.rescale_normal = true;
    l0.position = {3, 4, 5, 1};
    l0.space = Space::World;  // set after the camera: a point fixed in the world
    l0.diffuse = l0.specular = {1, 1, 1, 1};
    l0.ambient = {.1f, .1f, .1f, 1};
    d.front.ambient = d.front.diffuse = {1, 0, 0, 1};
    d.front.specular = {1, 1, 1, 1};
    d.front.shininess = 10;
    o.kind = Object::Kind::Cube;
    o.color.kind = ColorSource::Kind::Constant;  // ignored while lighting is on, as the seed points out
    o.color.constant = {0, 0, 1, 1};
  } else if (spec.name == "icosphere") {
    // Seed 004's settings; light 0 keeps its default position, (0,0,1,0) in eye space.
    d.camera.eye = {0, 0, 4};
    l0.ambient = {.2f, .2f, .2f, 1};
    l0.diffuse = {1, 1, 1, 1};
    l0.specular = {0, 0, 0, 1};
    d.front.specular = {0, 0, 0, 1};
    d.front.ambient = d.front.diffuse = {.8f, .6f, .4f, 1};
    d.front.shininess = 20;
    o.kind = Object::Kind::Icosphere;
    o.depth = spec.depth;
  } else {
    throw std::invalid_argument("unknown scene '" + spec.name + "' (cube or icosphere)");
  }
  d.objects.push_back(o);
  return d;
}

mesh::Mesh build_mesh(const Spec& spec) {
  if (spec.name == "cube") return mesh::make_cube();
  if (spec.name == "icosphere") return mesh::make_icosphere(spec.depth);
  throw std::invalid_argument("unknown scene '" + spec.name + "' (cube or icosphere)");
}

void draw(const Spec& spec) { draw(describe(spec)); }

image::Image render(const Spec& spec, backends::Backend& backend) { return render(describe(spec), backend); }

}  // namespace ffc::scene
