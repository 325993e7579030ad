// Scene files in TOML (toml++), read into a scene::Description.
//
// Every key is optional unless marked required; unknown keys are errors (typos are caught), and so
// is every wrong type or value outside GL's range. Defaults are GL's initial state, except that
// lighting and the depth test are on. Colours are [r, g, b] or [r, g, b, a] (alpha 1 when left
// out); numbers may be written as integers or floats.
//
//   name = "spotlight"              # for reports; default: the file's name without .toml
//   size = [512, 512]               # framebuffer width, height: 1..16384 (default 512 x 512)
//   background = [0, 0, 0, 1]       # glClearColor, components 0..1 (default [0, 0, 0, 0])
//   shade = "smooth"                # glShadeModel: flat | smooth
//   lighting = true                 # GL_LIGHTING
//   depth_test = true               # GL_DEPTH_TEST
//   normalize = false               # GL_NORMALIZE
//   rescale_normal = false          # GL_RESCALE_NORMAL
//   cull_face = "none"              # none | back | front | front_and_back (glCullFace)
//   front_face = "ccw"              # ccw | cw (glFrontFace)
//   axes = false                    # seed 000's unit axes, unlit, drawn before lighting is enabled
//   transforms = [{ rotate = [30, 0, 1, 0] }, { translate = [0, 0, -1] }, { scale = [1, 2, 1] }]
//                                   # after the camera, before every mesh's own; applied in order
//                                   # (glRotated(angle, axis), glTranslated, glScaled)
//
//   [camera]                        # glLoadIdentity on each matrix, the projection, gluLookAt
//   projection = "perspective"      # perspective | frustum | ortho
//   fovy = 45                       # perspective only: degrees, 0 < fovy < 180
//   aspect = 1.5                    # perspective only: > 0 (default: width / height)
//   left = -1, right = 1, bottom = -1, top = 1   # frustum and ortho only: left != right, bottom != top
//   near = 1                        # perspective, frustum: 0 < near < far; ortho: near != far
//   far = 10
//   eye = [0, 0, 5]                 # gluLookAt; eye != center, up not along the line of sight
//   center = [0, 0, 0]
//   up = [0, 1, 0]
//
//   [light_model]
//   ambient = [0.2, 0.2, 0.2, 1]    # GL_LIGHT_MODEL_AMBIENT
//   local_viewer = false            # GL_LIGHT_MODEL_LOCAL_VIEWER
//   two_sided = false               # GL_LIGHT_MODEL_TWO_SIDE
//   separate_specular = false       # GL_LIGHT_MODEL_COLOR_CONTROL = GL_SEPARATE_SPECULAR_COLOR
//
//   [material]                      # both faces (GL_FRONT_AND_BACK)
//   ambient = [0.2, 0.2, 0.2, 1]
//   diffuse = [0.8, 0.8, 0.8, 1]
//   ambient_and_diffuse = [1, 0, 0] # sets both (not together with ambient or diffuse)
//   specular = [0, 0, 0, 1]
//   emission = [0, 0, 0, 1]
//   shininess = 0                   # 0..128
//   [material.front]                # the same keys for one face, on top of the ones above
//   [material.back]
//
//   [color_material]                # its presence enables GL_COLOR_MATERIAL
//   enabled = true
//   face = "front_and_back"         # front | back | front_and_back
//   mode = "ambient_and_diffuse"    # ambient | diffuse | specular | emission | ambient_and_diffuse
//
//   [[light]]                       # up to 8; each listed light is enabled unless enabled = false
//   index = 0                       # 0..7, each at most once (default: its place in the list)
//   enabled = true
//   ambient = [0, 0, 0, 1]          # default GL's: light 0 has white diffuse and specular,
//   diffuse = [1, 1, 1, 1]          #   the others black
//   specular = [1, 1, 1, 1]
//   position = [0, 0, 1, 0]         # [x, y, z, w]; w = 0: directional
//   space = "eye"                   # eye: set before the camera (moves with it); world: after
//                                   #   gluLookAt, before the transforms (fixed in the world)
//   spot_direction = [0, 0, -1]     # in the same space as the position
//   spot_exponent = 0               # 0..128
//   spot_cutoff = 180               # 0..90, or 180 (no spot)
//   constant_attenuation = 1        # >= 0 each
//   linear_attenuation = 0
//   quadratic_attenuation = 0
//
//   [[mesh]]                        # at least one; drawn in order, each in glPushMatrix/glPopMatrix
//   source = "cube"                 # required: "cube" (the seeds' cube of side 2), "icosphere:N"
//                                   #   (depth N = 0..10; "icosphere" is depth 3), or a mesh file
//                                   #   (.obj, .off, .ply, .stl) relative to this file's folder
//   normals = "face"                # face | average | area | angle | max | sphere | file (the file's);
//                                   #   any other name mesh::parse_normal_source knows
//   draw = "auto"                   # auto | arrays (glDrawArrays) | elements (glDrawElements) |
//                                   #   immediate (glBegin/glNormal3f/glVertex3f/glEnd);
//                                   #   auto: arrays for face normals, elements otherwise
//   color = "none"                  # the glColor sent: none | normal | position (per vertex) |
//                                   #   [r, g, b(, a)] components 0..1 (one glColor)
//   transforms = [{ translate = [1, 0, 0] }]   # this mesh's, after the scene's
//   [mesh.material]                 # this mesh's materials: the scene's with these keys on top
//   [mesh.material.front]           #   (same keys as [material])
//
// Errors throw FileError: "path:line:column: what is wrong", pointing at the offending key or
// value (at the table for a missing key). Nothing is returned unless the whole file is valid.

#include "scene/file.h"

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <toml++/toml.h>
#include <type_traits>

#include "mesh/icosphere.h"
#include "scene/mesh_file.h"

namespace ffc::scene {

namespace fs = std::filesystem;

static std::string where_prefix(const std::string& path, int line, int column) {
  if (line <= 0) return path + ": ";
  return path + ":" + std::to_string(line) + ":" + std::to_string(column) + ": ";
}

FileError::FileError(const std::string& path, int line, int column, const std::string& message)
    : std::runtime_error(where_prefix(path, line, column) + message),
      path_(path),
      line_(line),
      column_(column),
      message_(message) {}

bool is_scene_file(const std::string& name) {
  return name.size() > 5 && name.compare(name.size() - 5, 5, ".toml") == 0;
}

namespace {

std::string fmt(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
}

std::string type_name(const toml::node& n) {
  std::ostringstream s;
  s << n.type();
  return s.str();
}

std::string join(std::initializer_list<const char*> names) {
  std::string s;
  size_t i = 0;
  for (const char* n : names) {
    s += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + std::string(n);
    ++i;
  }
  return s;
}

class Parser {
 public:
  Parser(std::string path) : path_(std::move(path)), base_(fs::path(path_).parent_path()) {}

  Description parse(const toml::table& root) {
    Description d;
    d.source = path_;
    d.name = fs::path(path_).stem().string();
    check_keys(root, "the scene file",
               {"name", "size", "background", "shade", "lighting", "depth_test", "normalize", "rescale_normal",
                "cull_face", "front_face", "axes", "transforms", "camera", "light_model", "material",
                "color_material", "light", "mesh"});
    if (auto* n = root.get("name")) d.name = string(*n, "name");
    if (auto* n = root.get("size")) {
      const toml::array& a = array(*n, "size", 2, 2);
      d.width = integer(a[0], "size[0] (width)", 1, 16384);
      d.height = integer(a[1], "size[1] (height)", 1, 16384);
    }
    if (auto* n = root.get("background")) d.background = color(*n, "background", true);
    if (auto* n = root.get("shade")) d.shade = name(*n, "shade", parse_shade);
    if (auto* n = root.get("lighting")) d.lighting = boolean(*n, "lighting");
    if (auto* n = root.get("depth_test")) d.depth_test = boolean(*n, "depth_test");
    if (auto* n = root.get("normalize")) d.normalize = boolean(*n, "normalize");
    if (auto* n = root.get("rescale_normal")) d.rescale_normal = boolean(*n, "rescale_normal");
    if (auto* n = root.get("axes")) d.axes = boolean(*n, "axes");
    if (auto* n = root.get("cull_face")) {
      const std::string s = string(*n, "cull_face");
      if (s == "none")
        d.cull_face = false;
      else {
        d.cull_face = true;
        d.cull_mode = name(*n, "cull_face", [](const std::string& v) {
          try {
            return parse_face(v);
          } catch (const std::invalid_argument&) {
            throw std::invalid_argument("unknown cull face '" + v + "' (none, back, front or front_and_back)");
          }
        });
      }
    }
    if (auto* n = root.get("front_face")) {
      const std::string s = string(*n, "front_face");
      if (s != "ccw" && s != "cw") fail(*n, "front_face: unknown winding '" + s + "' (ccw or cw)");
      d.front_face_cw = s == "cw";
    }
    if (auto* n = root.get("transforms")) d.transforms = transforms(*n, "transforms");
    if (auto* n = root.get("camera")) d.camera = camera(*n);
    if (auto* n = root.get("light_model")) d.light_model = light_model(*n);
    if (auto* n = root.get("material")) material_block(*n, "material", d.front, d.back);
    if (auto* n = root.get("color_material")) d.color_material = color_material(*n);
    if (auto* n = root.get("light")) lights(*n, d);
    const toml::node* meshes = root.get("mesh");
    if (!meshes) fail(root, "a scene needs at least one [[mesh]]");
    const toml::array& a = array_of_tables(*meshes, "mesh", "[[mesh]]");
    if (a.empty()) fail(*meshes, "a scene needs at least one [[mesh]]");
    for (size_t i = 0; i < a.size(); ++i) d.objects.push_back(object(*a[i].as_table(), i, d));
    return d;
  }

 private:
  std::string path_;
  fs::path base_;

  [[noreturn]] void fail(const toml::source_region& r, const std::string& msg) const {
    throw FileError(path_, int(r.begin.line), int(r.begin.column), msg);
  }
  [[noreturn]] void fail(const toml::node& n, const std::string& msg) const { fail(n.source(), msg); }

  void check_keys(const toml::table& t, const std::string& where, std::initializer_list<const char*> allowed) const {
    for (auto&& [k, v] : t) {
      bool ok = false;
      for (const char* a : allowed) ok = ok || k.str() == a;
      if (!ok) fail(k.source(), "unknown key '" + std::string(k.str()) + "' in " + where + " (expected " + join(allowed) + ")");
    }
  }

  const toml::table& table(const toml::node& n, const std::string& what) const {
    if (!n.is_table()) fail(n, what + ": expected a table, got " + type_name(n));
    return *n.as_table();
  }

  const toml::array& array(const toml::node& n, const std::string& what, size_t min, size_t max) const {
    if (!n.is_array()) fail(n, what + ": expected an array, got " + type_name(n));
    const toml::array& a = *n.as_array();
    if (a.size() < min || a.size() > max) {
      const std::string want = min == max ? std::to_string(min) : std::to_string(min) + " or " + std::to_string(max);
      fail(n, what + ": expected " + want + " elements, got " + std::to_string(a.size()));
    }
    return a;
  }

  const toml::array& array_of_tables(const toml::node& n, const std::string& what, const std::string& syntax) const {
    if (!n.is_array_of_tables())
      fail(n, what + ": expected an array of tables (" + syntax + "), got " + type_name(n));
    return *n.as_array();
  }

  bool boolean(const toml::node& n, const std::string& what) const {
    if (!n.is_boolean()) fail(n, what + ": expected true or false, got " + type_name(n));
    return n.as_boolean()->get();
  }

  std::string string(const toml::node& n, const std::string& what) const {
    if (!n.is_string()) fail(n, what + ": expected a string, got " + type_name(n));
    return n.as_string()->get();
  }

  template <class F>
  std::invoke_result_t<F, const std::string&> name(const toml::node& n, const std::string& what, F parse) const {
    const std::string s = string(n, what);
    try {
      return parse(s);
    } catch (const std::invalid_argument& e) {
      fail(n, what + ": " + e.what());
    }
  }

  double number(const toml::node& n, const std::string& what) const {
    if (!n.is_number()) fail(n, what + ": expected a number, got " + type_name(n));
    const double v = n.is_integer() ? double(n.as_integer()->get()) : n.as_floating_point()->get();
    if (!std::isfinite(v)) fail(n, what + ": " + fmt(v) + " is not a finite number");
    return v;
  }

  // A value GL receives as a float.
  float number_f(const toml::node& n, const std::string& what) const {
    const double v = number(n, what);
    if (std::fabs(v) > FLT_MAX) fail(n, what + ": " + fmt(v) + " does not fit in a float");
    return float(v);
  }

  double number_in(const toml::node& n, const std::string& what, double lo, double hi) const {
    const double v = number(n, what);
    if (v < lo || v > hi) fail(n, what + ": " + fmt(v) + " is outside " + fmt(lo) + ".." + fmt(hi));
    return v;
  }

  int integer(const toml::node& n, const std::string& what, int lo, int hi) const {
    if (!n.is_integer()) fail(n, what + ": expected an integer, got " + type_name(n));
    const int64_t v = n.as_integer()->get();
    if (v < lo || v > hi) fail(n, what + ": " + std::to_string(v) + " is outside " + std::to_string(lo) + ".." + std::to_string(hi));
    return int(v);
  }

  Color color(const toml::node& n, const std::string& what, bool unit_range) const {
    const toml::array& a = array(n, what + " (a colour, [r, g, b] or [r, g, b, a])", 3, 4);
    Color c{0, 0, 0, 1};
    for (size_t i = 0; i < a.size(); ++i) {
      const std::string w = what + "[" + std::to_string(i) + "]";
      c[i] = unit_range ? float(number_in(a[i], w, 0, 1)) : number_f(a[i], w);
    }
    return c;
  }

  Vec3 vec3(const toml::node& n, const std::string& what) const {
    const toml::array& a = array(n, what + " ([x, y, z])", 3, 3);
    return {number(a[0], what + "[0]"), number(a[1], what + "[1]"), number(a[2], what + "[2]")};
  }

  Vec3f vec3f(const toml::node& n, const std::string& what) const {
    const toml::array& a = array(n, what + " ([x, y, z])", 3, 3);
    return {number_f(a[0], what + "[0]"), number_f(a[1], what + "[1]"), number_f(a[2], what + "[2]")};
  }

  std::vector<Transform> transforms(const toml::node& n, const std::string& what) const {
    if (!n.is_array()) fail(n, what + ": expected an array of { translate | rotate | scale = [...] }, got " + type_name(n));
    std::vector<Transform> out;
    const toml::array& a = *n.as_array();
    for (size_t i = 0; i < a.size(); ++i) {
      const std::string w = what + "[" + std::to_string(i) + "]";
      const toml::table& t = table(a[i], w);
      check_keys(t, w, {"translate", "rotate", "scale"});
      if (t.size() != 1) fail(a[i], w + ": expected exactly one of translate, rotate or scale");
      if (auto* v = t.get("translate")) {
        const Vec3 x = vec3(*v, w + ".translate");
        out.push_back(translate(x[0], x[1], x[2]));
      } else if (auto* v = t.get("scale")) {
        const Vec3 x = vec3(*v, w + ".scale");
        out.push_back(scale(x[0], x[1], x[2]));
      } else {
        const toml::node& r = *t.get("rotate");
        const toml::array& ra = array(r, w + ".rotate ([angle in degrees, x, y, z])", 4, 4);
        const double angle = number(ra[0], w + ".rotate[0]");
        const Vec3 axis{number(ra[1], w + ".rotate[1]"), number(ra[2], w + ".rotate[2]"), number(ra[3], w + ".rotate[3]")};
        if (axis[0] == 0 && axis[1] == 0 && axis[2] == 0) fail(r, w + ".rotate: the axis [0, 0, 0] has no direction");
        out.push_back(rotate(angle, axis[0], axis[1], axis[2]));
      }
    }
    return out;
  }

  Camera camera(const toml::node& node) const {
    const toml::table& t = table(node, "camera");
    check_keys(t, "[camera]", {"projection", "fovy", "aspect", "left", "right", "bottom", "top", "near", "far", "eye", "center", "up"});
    Camera c;
    if (auto* n = t.get("projection")) c.projection = name(*n, "camera.projection", [](const std::string& s) {
        if (s == "perspective") return Camera::Projection::Perspective;
        if (s == "frustum") return Camera::Projection::Frustum;
        if (s == "ortho") return Camera::Projection::Ortho;
        throw std::invalid_argument("unknown projection '" + s + "' (perspective, frustum or ortho)");
      });
    const bool perspective = c.projection == Camera::Projection::Perspective;
    const std::string proj = to_string(c.projection);
    for (const char* k : {"fovy", "aspect"})
      if (auto* n = t.get(k); n && !perspective)
        fail(*n, std::string("camera.") + k + " applies to the perspective projection only (this camera is " + proj + ")");
    for (const char* k : {"left", "right", "bottom", "top"})
      if (auto* n = t.get(k); n && perspective)
        fail(*n, std::string("camera.") + k + " applies to frustum and ortho projections only (this camera is perspective)");
    if (auto* n = t.get("fovy")) {
      c.fovy_deg = number(*n, "camera.fovy");
      if (c.fovy_deg <= 0 || c.fovy_deg >= 180) fail(*n, "camera.fovy: " + fmt(c.fovy_deg) + " is not between 0 and 180 degrees (exclusive)");
    }
    if (auto* n = t.get("aspect")) {
      c.aspect = number(*n, "camera.aspect");
      if (c.aspect <= 0) fail(*n, "camera.aspect: " + fmt(c.aspect) + " is not positive");
    }
    if (auto* n = t.get("left")) c.left = number(*n, "camera.left");
    if (auto* n = t.get("right")) c.right = number(*n, "camera.right");
    if (auto* n = t.get("bottom")) c.bottom = number(*n, "camera.bottom");
    if (auto* n = t.get("top")) c.top = number(*n, "camera.top");
    if (auto* n = t.get("near")) c.z_near = number(*n, "camera.near");
    if (auto* n = t.get("far")) c.z_far = number(*n, "camera.far");
    auto at = [&](const char* a, const char* b) -> const toml::node& {
      if (auto* n = t.get(a)) return *n;
      if (auto* n = t.get(b)) return *n;
      return node;
    };
    if (!perspective && c.left == c.right) fail(at("right", "left"), "camera: left and right are both " + fmt(c.left));
    if (!perspective && c.bottom == c.top) fail(at("top", "bottom"), "camera: bottom and top are both " + fmt(c.top));
    if (c.projection == Camera::Projection::Ortho) {
      if (c.z_near == c.z_far) fail(at("far", "near"), "camera: near and far are both " + fmt(c.z_near));
    } else if (!(c.z_near > 0 && c.z_far > c.z_near)) {
      fail(at("near", "far"), "camera: near " + fmt(c.z_near) + " and far " + fmt(c.z_far) + " must satisfy 0 < near < far");
    }
    if (auto* n = t.get("eye")) c.eye = vec3(*n, "camera.eye");
    if (auto* n = t.get("center")) c.center = vec3(*n, "camera.center");
    if (auto* n = t.get("up")) c.up = vec3(*n, "camera.up");
    const Vec3 f{c.center[0] - c.eye[0], c.center[1] - c.eye[1], c.center[2] - c.eye[2]};
    if (f[0] == 0 && f[1] == 0 && f[2] == 0) fail(at("center", "eye"), "camera: eye and center are the same point");
    const Vec3 s{f[1] * c.up[2] - f[2] * c.up[1], f[2] * c.up[0] - f[0] * c.up[2], f[0] * c.up[1] - f[1] * c.up[0]};
    if (s[0] == 0 && s[1] == 0 && s[2] == 0) fail(at("up", "eye"), "camera: up is zero or along the line of sight");
    return c;
  }

  LightModel light_model(const toml::node& node) const {
    const toml::table& t = table(node, "light_model");
    check_keys(t, "[light_model]", {"ambient", "local_viewer", "two_sided", "separate_specular"});
    LightModel m;
    if (auto* n = t.get("ambient")) m.ambient = color(*n, "light_model.ambient", false);
    if (auto* n = t.get("local_viewer")) m.local_viewer = boolean(*n, "light_model.local_viewer");
    if (auto* n = t.get("two_sided")) m.two_sided = boolean(*n, "light_model.two_sided");
    if (auto* n = t.get("separate_specular")) m.separate_specular = boolean(*n, "light_model.separate_specular");
    return m;
  }

  // The keys of one material table onto `m` (and onto `also` unless null).
  void material_keys(const toml::table& t, const std::string& what, Material& m, Material* also) const {
    auto set = [&](auto field, auto value) {
      m.*field = value;
      if (also) also->*field = value;
    };
    if (auto* ad = t.get("ambient_and_diffuse")) {
      for (const char* k : {"ambient", "diffuse"})
        if (t.get(k)) fail(*ad, what + ": ambient_and_diffuse and " + k + " both given");
      const Color c = color(*ad, what + ".ambient_and_diffuse", false);
      set(&Material::ambient, c);
      set(&Material::diffuse, c);
    }
    if (auto* n = t.get("ambient")) set(&Material::ambient, color(*n, what + ".ambient", false));
    if (auto* n = t.get("diffuse")) set(&Material::diffuse, color(*n, what + ".diffuse", false));
    if (auto* n = t.get("specular")) set(&Material::specular, color(*n, what + ".specular", false));
    if (auto* n = t.get("emission")) set(&Material::emission, color(*n, what + ".emission", false));
    if (auto* n = t.get("shininess")) set(&Material::shininess, float(number_in(*n, what + ".shininess", 0, 128)));
  }

  void material_block(const toml::node& node, const std::string& what, Material& front, Material& back) const {
    const toml::table& t = table(node, what);
    check_keys(t, "[" + what + "]", {"ambient", "diffuse", "ambient_and_diffuse", "specular", "emission", "shininess", "front", "back"});
    material_keys(t, what, front, &back);
    for (auto [face, m] : {std::pair<const char*, Material*>{"front", &front}, {"back", &back}}) {
      if (auto* n = t.get(face)) {
        const std::string w = what + "." + face;
        const toml::table& ft = table(*n, w);
        check_keys(ft, "[" + w + "]", {"ambient", "diffuse", "ambient_and_diffuse", "specular", "emission", "shininess"});
        material_keys(ft, w, *m, nullptr);
      }
    }
  }

  ColorMaterial color_material(const toml::node& node) const {
    const toml::table& t = table(node, "color_material");
    check_keys(t, "[color_material]", {"enabled", "face", "mode"});
    ColorMaterial c;
    c.enabled = true;
    if (auto* n = t.get("enabled")) c.enabled = boolean(*n, "color_material.enabled");
    if (auto* n = t.get("face")) c.face = name(*n, "color_material.face", parse_face);
    if (auto* n = t.get("mode")) c.mode = name(*n, "color_material.mode", parse_color_mode);
    return c;
  }

  void lights(const toml::node& node, Description& d) const {
    const toml::array& a = array_of_tables(node, "light", "[[light]]");
    std::map<int, const toml::node*> seen;
    for (size_t i = 0; i < a.size(); ++i) {
      const toml::table& t = *a[i].as_table();
      const std::string w = "light[" + std::to_string(i) + "]";
      check_keys(t, "[[light]] " + std::to_string(i),
                 {"index", "enabled", "ambient", "diffuse", "specular", "position", "space", "spot_direction",
                  "spot_exponent", "spot_cutoff", "constant_attenuation", "linear_attenuation", "quadratic_attenuation"});
      int index = int(i);
      const toml::node* at = &a[i];
      if (auto* n = t.get("index")) {
        index = integer(*n, w + ".index", 0, max_lights - 1);
        at = n;
      } else if (i >= size_t(max_lights)) {
        fail(a[i], w + ": GL has 8 lights (0..7); this is the " + std::to_string(i + 1) + "th");
      }
      if (auto it = seen.find(index); it != seen.end())
        fail(*at, w + ": light " + std::to_string(index) + " is already described at line " +
                      std::to_string(it->second->source().begin.line));
      seen[index] = at;
      Light l = default_light(index);
      l.enabled = true;
      if (auto* n = t.get("enabled")) l.enabled = boolean(*n, w + ".enabled");
      if (auto* n = t.get("ambient")) l.ambient = color(*n, w + ".ambient", false);
      if (auto* n = t.get("diffuse")) l.diffuse = color(*n, w + ".diffuse", false);
      if (auto* n = t.get("specular")) l.specular = color(*n, w + ".specular", false);
      if (auto* n = t.get("position")) {
        const toml::array& p = array(*n, w + ".position ([x, y, z, w]; w = 0: directional)", 4, 4);
        for (size_t k = 0; k < 4; ++k) l.position[k] = number_f(p[k], w + ".position[" + std::to_string(k) + "]");
      }
      if (auto* n = t.get("space")) l.space = name(*n, w + ".space", parse_space);
      if (auto* n = t.get("spot_direction")) l.spot_direction = vec3f(*n, w + ".spot_direction");
      if (auto* n = t.get("spot_exponent")) l.spot_exponent = float(number_in(*n, w + ".spot_exponent", 0, 128));
      if (auto* n = t.get("spot_cutoff")) {
        const double c = number(*n, w + ".spot_cutoff");
        if (!((c >= 0 && c <= 90) || c == 180))
          fail(*n, w + ".spot_cutoff: " + fmt(c) + " is outside GL's range (0..90, or 180 for no spot)");
        l.spot_cutoff = float(c);
      }
      for (auto [key, field] : {std::pair<const char*, float Light::*>{"constant_attenuation", &Light::constant_attenuation},
                                {"linear_attenuation", &Light::linear_attenuation},
                                {"quadratic_attenuation", &Light::quadratic_attenuation}})
        if (auto* n = t.get(key)) {
          const double v = number(*n, w + "." + key);
          if (v < 0) fail(*n, w + "." + key + ": " + fmt(v) + " is negative (GL needs >= 0)");
          l.*field = number_f(*n, w + "." + key);
        }
      d.lights[size_t(index)] = l;
    }
  }

  Object object(const toml::table& t, size_t i, const Description& d) const {
    const std::string w = "mesh[" + std::to_string(i) + "]";
    check_keys(t, "[[mesh]] " + std::to_string(i), {"source", "normals", "draw", "color", "transforms", "material"});
    Object o;
    const toml::node* src = t.get("source");
    if (!src) fail(t, w + ": source is required (\"cube\", \"icosphere:N\" or a mesh file)");
    const std::string s = string(*src, w + ".source");
    if (s == "cube") {
      o.kind = Object::Kind::Cube;
    } else if (s == "icosphere" || s.rfind("icosphere:", 0) == 0) {
      o.kind = Object::Kind::Icosphere;
      o.depth = 3;
      if (s != "icosphere") {
        const std::string n = s.substr(10);
        const bool digits = !n.empty() && n.size() <= 3 && n.find_first_not_of("0123456789") == std::string::npos;
        if (!digits)
          fail(*src, w + ".source: '" + s + "': the icosphere depth must be a number 0.." + std::to_string(mesh::kMaxIcosphereDepth));
        if (const std::string e = mesh::icosphere_depth_error(std::stoi(n)); !e.empty()) fail(*src, w + ".source: " + e);
        o.depth = std::stoi(n);
      }
    } else {
      o.kind = Object::Kind::File;
      if (s.empty()) fail(*src, w + ".source: empty (\"cube\", \"icosphere:N\" or a mesh file)");
      const fs::path p(s);
      o.path = (p.is_absolute() ? p : base_ / p).lexically_normal().string();
      try {
        o.file = std::make_shared<const MeshFile>(read_mesh_file(o.path));
      } catch (const std::exception& e) {
        fail(*src, w + ".source: " + e.what());
      }
    }
    if (auto* n = t.get("normals")) {
      const std::string v = string(*n, w + ".normals");
      try {
        set_normals(o, v);
      } catch (const std::invalid_argument& e) {
        fail(*n, w + ".normals: " + e.what());
      }
      if (o.file_normals && !(o.file && o.file->has_normals))
        fail(*n, w + ".normals: \"file\" needs a mesh file with vertex normals; " +
                     (o.file ? "'" + o.path + "' has none" : "'" + s + "' is built in"));
    }
    if (auto* n = t.get("draw")) o.draw = name(*n, w + ".draw", parse_draw_path);
    if (auto* n = t.get("color")) {
      if (n->is_string()) {
        const std::string c = string(*n, w + ".color");
        if (c == "none") o.color.kind = ColorSource::Kind::None;
        else if (c == "normal") o.color.kind = ColorSource::Kind::Normal;
        else if (c == "position") o.color.kind = ColorSource::Kind::Position;
        else fail(*n, w + ".color: unknown colour source '" + c + "' (none, normal, position or [r, g, b(, a)])");
      } else if (n->is_array()) {
        o.color.kind = ColorSource::Kind::Constant;
        o.color.constant = color(*n, w + ".color", true);
      } else {
        fail(*n, w + ".color: expected \"none\", \"normal\", \"position\" or [r, g, b(, a)], got " + type_name(*n));
      }
    }
    if (auto* n = t.get("transforms")) o.transforms = transforms(*n, w + ".transforms");
    if (auto* n = t.get("material")) {
      Material front = d.front, back = d.back;
      material_block(*n, w + ".material", front, back);
      o.front = front;
      o.back = back;
    }
    return o;
  }
};

}  // namespace

Description parse_scene(std::string_view text, const std::string& path) {
  toml::table root;
  try {
    root = toml::parse(text, path);
  } catch (const toml::parse_error& e) {
    throw FileError(path, int(e.source().begin.line), int(e.source().begin.column),
                    "TOML syntax: " + std::string(e.description()));
  }
  return Parser(path).parse(root);
}

Description load_file(const std::string& path) {
  std::error_code ec;
  // fs::status follows links: a link to /dev/zero is a character device, not a scene file.
  const fs::file_status st = fs::status(path, ec);
  if (!fs::exists(st)) throw FileError(path, 0, 0, "the scene file does not exist");
  if (fs::is_directory(st)) throw FileError(path, 0, 0, "is a directory, not a scene file");
  // A FIFO would block the read until a writer came; a device like /dev/zero never ends.
  if (!fs::is_regular_file(st)) throw FileError(path, 0, 0, "is not a regular file (a FIFO, device or socket), not a scene file");
  const uintmax_t size = fs::file_size(path, ec);
  if (ec) throw FileError(path, 0, 0, "the scene file cannot be read: " + ec.message());
  if (size > kMaxSceneFileBytes)
    throw FileError(path, 0, 0, "the scene file is " + std::to_string(size) + " bytes, over the limit of " +
                                    std::to_string(kMaxSceneFileBytes) + " (a scene file is a page of TOML; meshes go in mesh files)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(path, 0, 0, "the scene file cannot be opened");
  // Read at most the limit, even if the file grew since it was measured.
  std::string text;
  char chunk[65536];
  while (in && text.size() <= kMaxSceneFileBytes) {
    in.read(chunk, sizeof chunk);
    text.append(chunk, size_t(in.gcount()));
  }
  if (in.bad()) throw FileError(path, 0, 0, "the scene file cannot be read");
  if (text.size() > kMaxSceneFileBytes) throw FileError(path, 0, 0, "the scene file grew past the size limit while being read");
  return parse_scene(text, path);
}

}  // namespace ffc::scene
