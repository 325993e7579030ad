#include "scene/description.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "mesh/cube.h"
#include "mesh/icosphere.h"
#include "scene/mesh_file.h"

namespace ffc::scene {

namespace {

template <class E>
using Names = std::initializer_list<std::pair<E, const char*>>;

template <class E>
const char* name_of(E v, Names<E> names) {
  for (const auto& [e, n] : names)
    if (e == v) return n;
  return "?";
}

template <class E>
E parse_name(const std::string& s, Names<E> names, const char* what) {
  std::string accepted;
  size_t i = 0;
  for (const auto& [e, n] : names) {
    if (s == n) return e;
    accepted += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + std::string(n);
    ++i;
  }
  throw std::invalid_argument("unknown " + std::string(what) + " '" + s + "' (" + accepted + ")");
}

const Names<Shade> shade_names = {{Shade::Flat, "flat"}, {Shade::Smooth, "smooth"}};
const Names<Space> space_names = {{Space::Eye, "eye"}, {Space::World, "world"}};
const Names<Face> face_names = {{Face::Front, "front"}, {Face::Back, "back"}, {Face::FrontAndBack, "front_and_back"}};
const Names<ColorMode> color_mode_names = {{ColorMode::Ambient, "ambient"},
                                           {ColorMode::Diffuse, "diffuse"},
                                           {ColorMode::Specular, "specular"},
                                           {ColorMode::Emission, "emission"},
                                           {ColorMode::AmbientAndDiffuse, "ambient_and_diffuse"}};
const Names<DrawPath> draw_names = {{DrawPath::Auto, "auto"},
                                    {DrawPath::Arrays, "arrays"},
                                    {DrawPath::Elements, "elements"},
                                    {DrawPath::Immediate, "immediate"}};
const Names<Camera::Projection> projection_names = {{Camera::Projection::Perspective, "perspective"},
                                                    {Camera::Projection::Frustum, "frustum"},
                                                    {Camera::Projection::Ortho, "ortho"}};

}  // namespace

const char* to_string(Shade v) { return name_of(v, shade_names); }
const char* to_string(Space v) { return name_of(v, space_names); }
const char* to_string(Face v) { return name_of(v, face_names); }
const char* to_string(ColorMode v) { return name_of(v, color_mode_names); }
const char* to_string(DrawPath v) { return name_of(v, draw_names); }
const char* to_string(Camera::Projection p) { return name_of(p, projection_names); }
Shade parse_shade(const std::string& s) { return parse_name(s, shade_names, "shade model"); }
Space parse_space(const std::string& s) { return parse_name(s, space_names, "light space"); }
Face parse_face(const std::string& s) { return parse_name(s, face_names, "face"); }
ColorMode parse_color_mode(const std::string& s) { return parse_name(s, color_mode_names, "colour material mode"); }
DrawPath parse_draw_path(const std::string& s) { return parse_name(s, draw_names, "draw path"); }

Light default_light(int index) {
  if (index < 0 || index >= max_lights) throw std::out_of_range("light index " + std::to_string(index) + " is not 0..7");
  Light l;
  if (index == 0) l.diffuse = l.specular = {1, 1, 1, 1};
  return l;
}

std::array<Light, max_lights> default_lights() {
  std::array<Light, max_lights> a;
  for (int i = 0; i < max_lights; ++i) a[size_t(i)] = default_light(i);
  return a;
}

Transform translate(double x, double y, double z) { return {Transform::Kind::Translate, {x, y, z}, 0}; }
Transform rotate(double angle_deg, double x, double y, double z) {
  return {Transform::Kind::Rotate, {x, y, z}, angle_deg};
}
Transform scale(double x, double y, double z) { return {Transform::Kind::Scale, {x, y, z}, 0}; }

std::string to_string(const Object& o) {
  switch (o.kind) {
    case Object::Kind::Cube: return "cube";
    case Object::Kind::Icosphere: return "icosphere:" + std::to_string(o.depth);
    case Object::Kind::File: return o.path;
  }
  return "?";
}

std::string normals_name(const Object& o) { return o.file_normals ? "file" : mesh::to_string(o.normals); }

void set_normals(Object& o, const std::string& name) {
  if (name == "file") {
    o.file_normals = true;
    return;
  }
  try {
    o.normals = mesh::parse_normal_source(name);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string(e.what()) + ", or file for a mesh file's own");
  }
  o.file_normals = false;
}

// --- equality ---

bool operator==(const Light& a, const Light& b) {
  return a.enabled == b.enabled && a.ambient == b.ambient && a.diffuse == b.diffuse && a.specular == b.specular &&
         a.position == b.position && a.space == b.space && a.spot_direction == b.spot_direction &&
         a.spot_exponent == b.spot_exponent && a.spot_cutoff == b.spot_cutoff &&
         a.constant_attenuation == b.constant_attenuation && a.linear_attenuation == b.linear_attenuation &&
         a.quadratic_attenuation == b.quadratic_attenuation;
}
bool operator==(const LightModel& a, const LightModel& b) {
  return a.ambient == b.ambient && a.local_viewer == b.local_viewer && a.two_sided == b.two_sided &&
         a.separate_specular == b.separate_specular;
}
bool operator==(const Material& a, const Material& b) {
  return a.ambient == b.ambient && a.diffuse == b.diffuse && a.specular == b.specular && a.emission == b.emission &&
         a.shininess == b.shininess;
}
bool operator==(const ColorMaterial& a, const ColorMaterial& b) {
  return a.enabled == b.enabled && a.face == b.face && a.mode == b.mode;
}
bool operator==(const ColorSource& a, const ColorSource& b) {
  return a.kind == b.kind && (a.kind != ColorSource::Kind::Constant || a.constant == b.constant);
}
bool operator==(const Transform& a, const Transform& b) {
  return a.kind == b.kind && a.v == b.v && a.angle_deg == b.angle_deg;
}
bool operator==(const Camera& a, const Camera& b) {
  return a.projection == b.projection && a.fovy_deg == b.fovy_deg && a.aspect == b.aspect && a.left == b.left &&
         a.right == b.right && a.bottom == b.bottom && a.top == b.top && a.z_near == b.z_near &&
         a.z_far == b.z_far && a.eye == b.eye && a.center == b.center && a.up == b.up;
}
bool operator==(const Object& a, const Object& b) {
  return a.kind == b.kind && a.depth == b.depth && a.path == b.path && a.file_normals == b.file_normals &&
         (a.file_normals || a.normals == b.normals) && a.draw == b.draw &&
         a.color == b.color && a.transforms == b.transforms && a.front == b.front && a.back == b.back;
}
bool operator==(const Description& a, const Description& b) {
  return a.name == b.name && a.source == b.source && a.width == b.width && a.height == b.height &&
         a.background == b.background && a.camera == b.camera && a.lighting == b.lighting &&
         a.depth_test == b.depth_test && a.axes == b.axes && a.shade == b.shade && a.normalize == b.normalize &&
         a.rescale_normal == b.rescale_normal && a.cull_face == b.cull_face && a.cull_mode == b.cull_mode &&
         a.front_face_cw == b.front_face_cw && a.light_model == b.light_model && a.lights == b.lights &&
         a.front == b.front && a.back == b.back && a.color_material == b.color_material &&
         a.transforms == b.transforms && a.objects == b.objects;
}

// --- geometry ---

mesh::Mesh build_mesh(const Object& o) {
  switch (o.kind) {
    case Object::Kind::Cube:
      if (o.file_normals) throw std::runtime_error("the built-in cube has no file normals");
      return mesh::make_cube();
    case Object::Kind::Icosphere: {
      if (o.file_normals) throw std::runtime_error("the built-in icosphere has no file normals");
      mesh::Mesh m = mesh::make_icosphere(o.depth);
      return m;
    }
    case Object::Kind::File: {
      std::shared_ptr<const MeshFile> f = o.file;
      if (!f) f = std::make_shared<MeshFile>(read_mesh_file(o.path));
      if (o.file_normals && !f->has_normals)
        throw std::runtime_error("mesh file '" + o.path + "' has no vertex normals (normals = \"file\")");
      mesh::Mesh m = f->mesh;
      m.update_face_normals();
      if (!o.file_normals) m.update_vertex_normals();
      return m;
    }
  }
  throw std::logic_error("unknown object kind");
}

mesh::Layout layout(const Object& o) {
  if (o.kind == Object::Kind::File && o.file_normals) {
    const std::shared_ptr<const MeshFile> f = o.file ? o.file : std::make_shared<MeshFile>(read_mesh_file(o.path));
    if (f->corner_normals) return *f->corner_normals;  // per-corner normals, vertices split
  }
  // File normals are the vertex normals as read: the shared-vertex layout of averaged normals
  // (which reads the mesh's vertex normals) takes them as they stand, since build_mesh left them.
  return mesh::layout(build_mesh(o), o.file_normals ? mesh::NormalSource::Average : o.normals);
}

std::vector<Color> vertex_colors(const Object& o, const mesh::Layout& l) {
  std::vector<Color> c;
  if (o.color.kind == ColorSource::Kind::Normal) {
    c.reserve(l.vertices.size());
    for (const auto& v : l.vertices)
      c.push_back({float((v.normal[0] + 1) / 2), float((v.normal[1] + 1) / 2), float((v.normal[2] + 1) / 2), 1});
  } else if (o.color.kind == ColorSource::Kind::Position && !l.vertices.empty()) {
    Vec3 lo = l.vertices[0].position, hi = lo;
    for (const auto& v : l.vertices)
      for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], v.position[k]), hi[k] = std::max(hi[k], v.position[k]);
    c.reserve(l.vertices.size());
    for (const auto& v : l.vertices) {
      Color col{0, 0, 0, 1};
      for (int k = 0; k < 3; ++k) col[k] = hi[k] > lo[k] ? float((v.position[k] - lo[k]) / (hi[k] - lo[k])) : 0.5f;
      c.push_back(col);
    }
  }
  return c;
}

DrawPath resolved_draw_path(const Object& o) {
  if (o.draw != DrawPath::Auto) return o.draw;
  return !o.file_normals && o.normals == mesh::NormalSource::Face ? DrawPath::Arrays : DrawPath::Elements;
}

}  // namespace ffc::scene
