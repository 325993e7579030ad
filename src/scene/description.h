// A scene as plain data: the whole fixed-function lighting state of a picture (lights, light model,
// materials, colour material, shade model, normal handling, culling), the camera, the object
// transforms and the meshes with their normals, colours and draw paths. Built in code
// (scene::describe for the built-in scenes) or read from a TOML scene file (scene/file.h); drawn
// with draw() through the GL dispatch. Nothing here is hidden: a checker can read every value GL
// will be given.
//
// Values are what GL receives: colours, light and material parameters as the floats glLightfv /
// glMaterialfv / glColor4f take, camera and transforms as the doubles of gluPerspective /
// glTranslated. Defaults are GL's initial state (OpenGL 2.1, tables 6.9 to 6.11), except that
// lighting and the depth test are on and the camera looks at the origin from (0, 0, 5).
#pragma once
#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "mesh/mesh.h"

namespace ffc::scene {

using Color = std::array<float, 4>;  // RGBA
using Vec3f = std::array<float, 3>;
using Vec4f = std::array<float, 4>;
using Vec3 = mesh::Vec3;  // double

enum class Shade { Flat, Smooth };        // glShadeModel
enum class Space { Eye, World };          // where a light's position and spot direction are given
enum class Face { Front, Back, FrontAndBack };
enum class ColorMode { Ambient, Diffuse, Specular, Emission, AmbientAndDiffuse };  // glColorMaterial
enum class DrawPath { Auto, Arrays, Elements, Immediate };

// Names as the scene files and the command line spell them ("flat", "front_and_back", ...).
// parse_* throw std::invalid_argument naming the accepted values.
const char* to_string(Shade v);
const char* to_string(Space v);
const char* to_string(Face v);
const char* to_string(ColorMode v);
const char* to_string(DrawPath v);
Shade parse_shade(const std::string& s);
Space parse_space(const std::string& s);
Face parse_face(const std::string& s);
ColorMode parse_color_mode(const std::string& s);
DrawPath parse_draw_path(const std::string& s);

// One glLight. `space` says which modelview is current when the position and spot direction are
// set: Eye = identity (the light moves with the camera), World = the camera's (after gluLookAt,
// before the object transforms: the light stays put in the world).
struct Light {
  bool enabled = false;
  Color ambient{0, 0, 0, 1}, diffuse{0, 0, 0, 1}, specular{0, 0, 0, 1};
  Vec4f position{0, 0, 1, 0};  // w = 0: directional
  Space space = Space::Eye;
  Vec3f spot_direction{0, 0, -1};  // only a spot uses it: a world-space light with cutoff 180 and
                                   // this default leaves GL's (eye-space) default untouched
  float spot_exponent = 0;  // [0, 128]
  float spot_cutoff = 180;  // [0, 90], or 180: no spot
  float constant_attenuation = 1, linear_attenuation = 0, quadratic_attenuation = 0;  // >= 0
};
constexpr int max_lights = 8;
Light default_light(int index);  // GL's: light 0 has white diffuse and specular, the others black
std::array<Light, max_lights> default_lights();

struct LightModel {
  Color ambient{0.2f, 0.2f, 0.2f, 1};
  bool local_viewer = false;
  bool two_sided = false;
  bool separate_specular = false;  // GL_LIGHT_MODEL_COLOR_CONTROL = GL_SEPARATE_SPECULAR_COLOR
};

struct Material {
  Color ambient{0.2f, 0.2f, 0.2f, 1}, diffuse{0.8f, 0.8f, 0.8f, 1}, specular{0, 0, 0, 1},
      emission{0, 0, 0, 1};
  float shininess = 0;  // [0, 128]
};

struct ColorMaterial {
  bool enabled = false;
  Face face = Face::FrontAndBack;
  ColorMode mode = ColorMode::AmbientAndDiffuse;
};

// The glColor an object is drawn with (what GL_COLOR_MATERIAL picks up; ignored by lighting
// otherwise). Normal: per vertex, (n + 1) / 2 of the normal sent. Position: per vertex,
// (p - min) / (max - min) over the mesh's bounding box (object space). Both with alpha 1.
struct ColorSource {
  enum class Kind { None, Constant, Normal, Position } kind = Kind::None;
  Color constant{1, 1, 1, 1};  // Kind::Constant
};

// glTranslated(v), glRotated(angle_deg, v), glScaled(v).
struct Transform {
  enum class Kind { Translate, Rotate, Scale } kind = Kind::Translate;
  Vec3 v{0, 0, 0};
  double angle_deg = 0;
};
Transform translate(double x, double y, double z);
Transform rotate(double angle_deg, double x, double y, double z);
Transform scale(double x, double y, double z);

// The projection (glLoadIdentity on GL_PROJECTION, then one of gluPerspective, glFrustum,
// glOrtho) and the view (gluLookAt on a fresh modelview).
struct Camera {
  enum class Projection { Perspective, Frustum, Ortho } projection = Projection::Perspective;
  double fovy_deg = 45;
  double aspect = 0;  // 0: the framebuffer's width / height
  double left = -1, right = 1, bottom = -1, top = 1;  // frustum and ortho
  double z_near = 1, z_far = 10;
  Vec3 eye{0, 0, 5}, center{0, 0, 0}, up{0, 1, 0};
};
const char* to_string(Camera::Projection p);

// A mesh file as read through OpenMesh (scene/mesh_file.h): points, and the file's vertex normals
// when it has them.
struct MeshFile {
  mesh::Mesh mesh;
  bool has_normals = false;
  // An OBJ whose faces give one vertex several normals (per-corner `f v//vn`): the triangles with
  // those vertices split, one per normal, so that `normals = "file"` draws every corner's own.
  // Empty when the per-vertex normals in `mesh` already say everything.
  std::optional<mesh::Layout> corner_normals;
};

// One mesh of the scene, drawn inside glPushMatrix / glPopMatrix after the scene's transforms.
struct Object {
  enum class Kind { Cube, Icosphere, File } kind = Kind::Cube;
  int depth = 0;        // Icosphere: subdivision depth 0..12
  std::string path;     // File: the path (a scene file's relative paths are resolved against its folder)
  std::shared_ptr<const MeshFile> file;  // File: the mesh as read; null: read `path` when drawn
  mesh::NormalSource normals = mesh::NormalSource::Face;  // the normals sent (mesh::layout)...
  bool file_normals = false;  // ...unless a File object sends the file's own vertex normals
  DrawPath draw = DrawPath::Auto;  // Auto: arrays for face normals, elements otherwise (the seeds')
  ColorSource color;
  std::vector<Transform> transforms;
  std::optional<Material> front, back;  // this object's materials instead of the scene's
};
std::string to_string(const Object& o);  // "cube", "icosphere:3" or the path

// An object's normals by name: "file" for a mesh file's own, otherwise mesh::to_string's names
// ("face", "average", "sphere", ...). set_normals throws std::invalid_argument for an unknown name.
std::string normals_name(const Object& o);
void set_normals(Object& o, const std::string& name);

struct Description {
  std::string name;    // for reports: "cube", "icosphere", a scene file's name
  std::string source;  // the scene file it was read from, if any
  int width = 512, height = 512;
  Color background{0, 0, 0, 0};  // glClearColor
  Camera camera;
  bool lighting = true, depth_test = true;
  bool axes = false;  // seed 000's unit axes (red x, green y, blue z), unlit, drawn first
  Shade shade = Shade::Smooth;
  bool normalize = false, rescale_normal = false;
  bool cull_face = false;
  Face cull_mode = Face::Back;
  bool front_face_cw = false;  // glFrontFace(GL_CW)
  LightModel light_model;
  std::array<Light, max_lights> lights = default_lights();
  Material front, back;
  ColorMaterial color_material;
  std::vector<Transform> transforms;  // after the camera, before every object's own
  std::vector<Object> objects;
};

// Field-by-field equality (an Object's loaded file is compared by path, not by content).
bool operator==(const Light& a, const Light& b);
bool operator==(const LightModel& a, const LightModel& b);
bool operator==(const Material& a, const Material& b);
bool operator==(const ColorMaterial& a, const ColorMaterial& b);
bool operator==(const ColorSource& a, const ColorSource& b);
bool operator==(const Transform& a, const Transform& b);
bool operator==(const Camera& a, const Camera& b);
bool operator==(const Object& a, const Object& b);
bool operator==(const Description& a, const Description& b);
inline bool operator!=(const Light& a, const Light& b) { return !(a == b); }
inline bool operator!=(const LightModel& a, const LightModel& b) { return !(a == b); }
inline bool operator!=(const Material& a, const Material& b) { return !(a == b); }
inline bool operator!=(const ColorMaterial& a, const ColorMaterial& b) { return !(a == b); }
inline bool operator!=(const ColorSource& a, const ColorSource& b) { return !(a == b); }
inline bool operator!=(const Transform& a, const Transform& b) { return !(a == b); }
inline bool operator!=(const Camera& a, const Camera& b) { return !(a == b); }
inline bool operator!=(const Object& a, const Object& b) { return !(a == b); }
inline bool operator!=(const Description& a, const Description& b) { return !(a == b); }

// The mesh an object draws: the seeds' cube, the icosphere, or the file's mesh (read now if the
// object has not been loaded). Face normals updated; vertex normals averaged unless the object
// takes the file's. Throws std::runtime_error (a mesh file that cannot be read, file normals
// asked of a file without them).
mesh::Mesh build_mesh(const Object& o);

// The vertices the object sends, in double (mesh::layout; file normals as read).
mesh::Layout layout(const Object& o);

// Per-vertex colours for a layout (empty unless the object's colour varies per vertex).
std::vector<Color> vertex_colors(const Object& o, const mesh::Layout& l);

// The draw path actually taken: Auto resolved.
DrawPath resolved_draw_path(const Object& o);

// Issues the whole description through the dispatch on the current context, which must be in
// GL's default state (a backend's fresh context). A state call is made only where the described
// value differs from GL's default; order-dependent calls follow the seeds: eye-space lights before
// gluLookAt, the axes before lighting is enabled, world-space lights after gluLookAt, then the
// scene transforms and each object in its own glPushMatrix. Builds the meshes before the first GL
// call, so a mesh that cannot be built throws without drawing anything.
void draw(const Description& d);

// Builds the meshes now and returns what issues one frame of `d` with them: for drawing the same
// scene many times (benchmarks) without building meshes inside the timed frames.
std::function<void()> frame(const Description& d);

}  // namespace ffc::scene
