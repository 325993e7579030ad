// Seed 001 ("8 - Lab - Lighting"): the red cube lit by GLSL 330 core shaders in six steps, as data.
// What a step computes (Lighting), where it is seen from (View), the handout's two vertex layouts,
// and the shader text. The GL side is seed001_renderer.h, the same equation in double on the CPU
// seed001_reference.h.
//
// The handout lights in world space with constants written into the shaders: a white point light
// at (3,2,4), ambient 0.1 of the light's colour, a red material with white specular, shininess 32,
// and reflection-vector specular pow(max(V.R, 0), 32) with no N.L test. Each difference from GL's
// fixed function can be switched here one at a time, so `ffcompat seeds` can measure what each
// one does to the picture; the six steps leave every switch off.
#pragma once
#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace seed001 {

struct Lighting {
  int terms = 3;                  // 1 ambient; 2 + diffuse; 3 + specular
  bool per_fragment = false;      // Phong shading (lit in the fragment shader) instead of Gouraud
  bool averaged_normals = false;  // 8 vertices with averaged normals, glDrawElements (steps 5, 6)
  glm::dvec3 light_pos{3, 2, 4};  // world space
  double shininess = 32;
  double light_ambient = 0.1;     // light_ambient = 0.1 * light_color
  // Not in the handout; for the comparison with seed 000's fixed-function cube:
  double global_ambient = 0;      // GL's light-model ambient (0.2 by default) times the material's
  bool half_vector = false;       // Blinn's pow(N.H, s), as GL, instead of pow(V.R, s)
  bool nl_guard = false;          // no specular where N.L <= 0, as GL
  bool infinite_viewer = false;   // view direction fixed along the camera's axis (GL's default)
  bool eye_space = false;         // lit in eye space (positions, normals, light through V)
  bool clamp_vertex_colour = false;  // Gouraud: each vertex colour clamped to [0,1], as GL does
};

constexpr int kSteps = 6;
// The handout's step (1..6); throws std::invalid_argument otherwise.
Lighting step_lighting(int step);
// The handout's program name: "1-ambient-only-gouraud-facenorm", ...
std::string step_name(int step);

// The seeds' camera: 5 units from the origin at angle `cam_ang` (radians) around the y axis and
// height `cam_height`, looking at the origin (keys 1/3 turn it by 10 degrees, 2/W move it by 0.1).
// The handout's projection is glm.perspective(45, 1, 1, 10): glm takes radians, so 45 there is 45
// radians, a field of view of about 58.3 degrees, not 45 degrees; fovy_radians = false gives
// seed 000's gluPerspective(45, ...) instead (degrees), as the comparison uses.
struct View {
  double cam_ang = 0, cam_height = 1;
  bool fovy_radians = true;
  int width = 640, height = 640;
  bool on_key(int key);  // the seeds' camera keys; true if the key was one
};
glm::dmat4 projection(const View& v);  // P (aspect 1, as the handout)
glm::dmat4 view_matrix(const View& v);  // V
glm::dvec3 eye_position(const View& v);
double fovy_degrees(const View& v);  // the field of view the projection really has

// One vertex of the handout's arrays: position then normal.
struct Vertex {
  float pos[3], normal[3];
};
const std::vector<Vertex>& face_normal_vertices();     // 36: each triangle with its face's normal
const std::vector<Vertex>& averaged_normal_vertices();  // 8: the handout's averaged normals
const std::vector<unsigned>& averaged_normal_indices();  // 36: 12 triangles

// The shaders for a lighting (GLSL 330 core). `light_pos` and `view_axis` are the light's
// position and, for an infinite viewer, the view direction in the space the shader lights in
// (world, or eye with eye_space): written into the text as the handout writes its constants.
struct ShaderText {
  std::string vertex, fragment;
};
ShaderText shaders(const Lighting& l, const glm::dvec3& light_pos, const glm::dvec3& view_axis);

}  // namespace seed001
