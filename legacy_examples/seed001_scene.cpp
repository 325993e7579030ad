#include "seed001_scene.h"

#include <cmath>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>
#include <stdexcept>

namespace seed001 {

Lighting step_lighting(int step) {
  if (step < 1 || step > kSteps) throw std::invalid_argument("step " + std::to_string(step) + " is not 1..6");
  Lighting l;
  l.terms = step == 1 ? 1 : step == 2 ? 2 : 3;
  l.per_fragment = step == 4 || step == 6;
  l.averaged_normals = step >= 5;
  return l;
}

std::string step_name(int step) {
  static const char* names[kSteps] = {
      "1-ambient-only-gouraud-facenorm", "2-ambient-diffuse-gouraud-facenorm", "3-all-components-gouraud-facenorm",
      "4-all-components-phong-facenorm", "5-all-components-gouraud-avgnorm",   "6-all-components-phong-avgnorm"};
  if (step < 1 || step > kSteps) throw std::invalid_argument("step " + std::to_string(step) + " is not 1..6");
  return names[step - 1];
}

bool View::on_key(int key) {
  const double ten_degrees = 10 * M_PI / 180;
  switch (key) {
    case '1': cam_ang -= ten_degrees; return true;
    case '3': cam_ang += ten_degrees; return true;
    case '2': cam_height += .1; return true;
    case 'W': cam_height -= .1; return true;
    default: return false;
  }
}

glm::dmat4 projection(const View& v) {
  // glm::perspective takes radians, as PyGLM's glm.perspective does: the handout's 45 is 45 rad.
  return glm::perspective(v.fovy_radians ? 45.0 : glm::radians(45.0), 1.0, 1.0, 10.0);
}

glm::dvec3 eye_position(const View& v) {
  return {5 * std::sin(v.cam_ang), v.cam_height, 5 * std::cos(v.cam_ang)};
}

glm::dmat4 view_matrix(const View& v) { return glm::lookAt(eye_position(v), glm::dvec3(0), glm::dvec3(0, 1, 0)); }

double fovy_degrees(const View& v) {
  // glm builds the matrix from tan(fovy / 2) alone: 45 rad is 22.5 rad per half, the same tangent
  // as 22.5 - 7 pi = 0.5089 rad, so the picture is upright and about 58.3 degrees tall.
  const double half = v.fovy_radians ? 22.5 : glm::radians(22.5);
  return 2 * std::atan(std::tan(half)) * 180 / M_PI;
}

namespace {

const glm::dvec3 kCorners[8] = {{-1, 1, 1}, {1, 1, 1}, {1, -1, 1}, {-1, -1, 1},
                                {-1, 1, -1}, {1, 1, -1}, {1, -1, -1}, {-1, -1, -1}};
// The faces in the handout's order, two triangles each: +z, -z, +y, -y, +x, -x.
const glm::dvec3 kFaceNormals[6] = {{0, 0, 1}, {0, 0, -1}, {0, 1, 0}, {0, -1, 0}, {1, 0, 0}, {-1, 0, 0}};

Vertex vertex(const glm::dvec3& p, const glm::dvec3& n) {
  return {{float(p.x), float(p.y), float(p.z)}, {float(n.x), float(n.y), float(n.z)}};
}

}  // namespace

const std::vector<unsigned>& averaged_normal_indices() {
  static const std::vector<unsigned> indices = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                                3, 6, 2, 3, 7, 6, 1, 2, 6, 1, 6, 5, 0, 7, 3, 0, 4, 7};
  return indices;
}

// The 36-vertex array lists the same triangles as the index array, corner for corner, each vertex
// carrying the normal of its face.
const std::vector<Vertex>& face_normal_vertices() {
  static const std::vector<Vertex> vertices = [] {
    std::vector<Vertex> v;
    const auto& idx = averaged_normal_indices();
    for (size_t i = 0; i < idx.size(); ++i) v.push_back(vertex(kCorners[idx[i]], kFaceNormals[i / 6]));
    return v;
  }();
  return vertices;
}

// The handout's averaged normals are the normalised sum of the normals of the *triangles* at a
// corner (not of its three faces): v1 lies in two +x triangles, one +z and one +y, hence
// (2,1,1)/sqrt(6) = (0.816, 0.408, 0.408) as its table prints.
const std::vector<Vertex>& averaged_normal_vertices() {
  static const std::vector<Vertex> vertices = [] {
    glm::dvec3 sum[8] = {};
    const auto& idx = averaged_normal_indices();
    for (size_t i = 0; i < idx.size(); ++i) sum[idx[i]] += kFaceNormals[i / 6];
    std::vector<Vertex> v;
    for (int c = 0; c < 8; ++c) v.push_back(vertex(kCorners[c], glm::normalize(sum[c])));
    return v;
  }();
  return vertices;
}

namespace {

// A GLSL float literal: "32.0", not "32", which some compilers would take for an int.
std::string float_text(double x) {
  char b[48];
  std::snprintf(b, sizeof b, "%.9g", x);
  std::string s = b;
  if (s.find_first_of(".en") == std::string::npos) s += ".0";
  return s;
}

std::string vec3_text(const glm::dvec3& v) {
  return "vec3(" + float_text(v.x) + ", " + float_text(v.y) + ", " + float_text(v.z) + ")";
}

// The handout's lighting code, once, for the vertex shader (Gouraud) or the fragment shader
// (Phong); the #if switches are the comparison's and are all 0 in the six steps.
const char* kIlluminate = R"(
vec3 illuminate(vec3 normal, vec3 surface_pos)
{
    // light and material properties
    vec3 light_pos = LIGHT_POS;
    vec3 light_color = vec3(1,1,1);
    vec3 material_color = vec3(1,0,0);
    float material_shininess = SHININESS;

    // light components
    vec3 light_ambient = LIGHT_AMBIENT*light_color;
    vec3 light_diffuse = light_color;
    vec3 light_specular = light_color;

    // material components
    vec3 material_ambient = material_color;
    vec3 material_diffuse = material_color;
    vec3 material_specular = vec3(1,1,1);  // white: a non-metal

    vec3 color = light_ambient * material_ambient + GLOBAL_AMBIENT * material_ambient;
#if TERMS >= 2
    vec3 light_dir = normalize(light_pos - surface_pos);
    float diff = max(dot(normal, light_dir), 0);
    color += diff * light_diffuse * material_diffuse;
#endif
#if TERMS >= 3
#if INFINITE_VIEWER
    vec3 view_dir = VIEW_AXIS;
#else
    vec3 view_dir = normalize(view_pos - surface_pos);
#endif
#if HALF_VECTOR
    float spec = pow(max(dot(normal, normalize(light_dir + view_dir)), 0.0), material_shininess);
#else
    vec3 reflect_dir = reflect(-light_dir, normal);
    float spec = pow(max(dot(view_dir, reflect_dir), 0.0), material_shininess);
#endif
#if NL_GUARD
    if (dot(normal, light_dir) <= 0.0) spec = 0.0;
#endif
    color += spec * light_specular * material_specular;
#endif
    return color;
}
)";

const char* kVertexMain = R"(
layout (location = 0) in vec3 vin_pos;
layout (location = 1) in vec3 vin_normal;

uniform mat4 MVP;
uniform mat4 M;
uniform vec3 view_pos;

#if PER_FRAGMENT
out vec3 vout_surface_pos;
out vec3 vout_normal;
#else
out vec4 vout_color;
ILLUMINATE
#endif

void main()
{
    gl_Position = MVP * vec4(vin_pos.xyz, 1.0);
    vec3 surface_pos = vec3(M * vec4(vin_pos, 1));  // where lighting happens: world space
    vec3 normal = normalize(mat3(inverse(transpose(M))) * vin_normal);
#if PER_FRAGMENT
    vout_surface_pos = surface_pos;
    vout_normal = normal;
#else
    vec3 color = illuminate(normal, surface_pos);
#if CLAMP_VERTEX_COLOR
    color = clamp(color, 0.0, 1.0);
#endif
    vout_color = vec4(color, 1.);
#endif
}
)";

const char* kFragmentMain = R"(
out vec4 FragColor;

#if PER_FRAGMENT
in vec3 vout_surface_pos;  // interpolated surface position
in vec3 vout_normal;       // interpolated normal
uniform vec3 view_pos;
ILLUMINATE
void main()
{
    FragColor = vec4(illuminate(normalize(vout_normal), vout_surface_pos), 1.);
}
#else
in vec4 vout_color;  // interpolated colour
void main()
{
    FragColor = vout_color;
}
#endif
)";

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  for (size_t at = 0; (at = s.find(from, at)) != std::string::npos; at += to.size()) s.replace(at, from.size(), to);
  return s;
}

}  // namespace

ShaderText shaders(const Lighting& l, const glm::dvec3& light_pos, const glm::dvec3& view_axis) {
  std::string prelude = "#version 330 core\n#define TERMS " + std::to_string(l.terms) + "\n";
  prelude += "#define PER_FRAGMENT " + std::to_string(int(l.per_fragment)) + "\n";
  prelude += "#define SHININESS " + float_text(l.shininess) + "\n";
  prelude += "#define LIGHT_AMBIENT " + float_text(l.light_ambient) + "\n";
  prelude += "#define GLOBAL_AMBIENT " + float_text(l.global_ambient) + "\n";
  prelude += "#define HALF_VECTOR " + std::to_string(int(l.half_vector)) + "\n";
  prelude += "#define NL_GUARD " + std::to_string(int(l.nl_guard)) + "\n";
  prelude += "#define INFINITE_VIEWER " + std::to_string(int(l.infinite_viewer)) + "\n";
  prelude += "#define CLAMP_VERTEX_COLOR " + std::to_string(int(l.clamp_vertex_colour)) + "\n";
  prelude += "#define LIGHT_POS " + vec3_text(light_pos) + "\n";
  prelude += "#define VIEW_AXIS " + vec3_text(view_axis) + "\n";
  // ILLUMINATE is pasted as text (the preprocessor cannot hold a function body).
  return {prelude + replace_all(kVertexMain, "ILLUMINATE", kIlluminate),
          prelude + replace_all(kFragmentMain, "ILLUMINATE", kIlluminate)};
}

}  // namespace seed001
