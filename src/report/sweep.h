// The sweep behind `ffcompat report`: the icosphere at each depth, under two lighting setups, with
// each shading (GL_FLAT with face normals; GL_SMOOTH with the vertex-normal weightings and the
// exact sphere normals), through each backend; every picture compared with the ray-cast ideal and
// its frames timed.
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "backends/backend.h"
#include "image/image.h"
#include "mesh/mesh.h"
#include "report/ideal.h"
#include "scene/description.h"

namespace ffc::report {

// A lighting setup: the scene without its object (camera, lights, materials), 512x512 unless resized.
//  seed:     seed 004: directional light 0 at its default position (0,0,1,0) in eye space, ambient
//            .2, diffuse 1, no specular; material ambient and diffuse (.8,.6,.4), shininess 20.
//  specular: the cube lab's light and material: light 0 at (3,4,5,1) in the world (set after the
//            camera), ambient .1, diffuse and specular 1; material ambient and diffuse (1,0,0),
//            specular white, shininess 10.
// Both: gluPerspective(45, w/h, 1, 10), eye (0,0,4) looking at the origin, black background.
struct Lighting {
  std::string name;
  scene::Description scene;  // no objects
};
Lighting lighting(const std::string& name, int size = 512);  // throws std::invalid_argument
const std::vector<std::string>& lighting_names();             // seed, specular

// A shading: glShadeModel and the normals sent.
struct Shading {
  std::string name;  // flat, smooth-average, smooth-area, smooth-angle, smooth-max, smooth-sphere
  scene::Shade shade;
  mesh::NormalSource normals;
};
const std::vector<Shading>& shadings();
const Shading& shading(const std::string& name);  // throws std::invalid_argument

// The icosphere of one depth, built once, with its normals and draw arrays per shading.
class DepthMesh {
 public:
  explicit DepthMesh(int depth);
  int depth() const { return depth_; }
  size_t triangles() const { return mesh_.n_faces(); }
  size_t vertices() const { return mesh_.n_vertices(); }
  const mesh::Mesh& mesh() const { return mesh_; }
  // The client arrays a shading draws (built on first use): unshared corners for face normals
  // (glDrawArrays), shared vertices and indices otherwise (glDrawElements), as scene::draw does.
  const mesh::DrawArrays& arrays(const Shading& s);
  // Milliseconds to compute the shading's normals from the positions: OpenMesh's face normals for
  // flat, mesh::update_normals (face normals, then OpenMesh's average) for average,
  // mesh::vertex_normals for the others; the median of `runs`.
  double normals_ms(const Shading& s, int runs);

 private:
  int depth_;
  mesh::Mesh mesh_;
  std::vector<std::pair<std::string, std::unique_ptr<mesh::DrawArrays>>> arrays_;
};

// The full Description of one picture: the lighting setup, the shade model, and the icosphere
// object of that depth with the shading's normals.
scene::Description describe(const Lighting& l, int depth, const Shading& s);

// One frame: the lighting setup's state through scene::draw (its Description without objects,
// with the shading's shade model), then the arrays drawn as scene::draw draws an object (client
// arrays; glDrawArrays for unshared corners, glDrawElements otherwise), then read back. The
// backend must have begun at the setup's size; frames can follow each other on one context. The
// same pixels as scene::render(describe(...)) without rebuilding the mesh every frame
// (tests/report checks that they agree).
image::Image frame(const Lighting& l, const Shading& s, const mesh::DrawArrays& arrays, backends::Backend& b);
// The same into `out`, whose memory is reused (the timed frames allocate nothing for the picture).
void frame(const Lighting& l, const Shading& s, const mesh::DrawArrays& arrays, backends::Backend& b, image::Image& out);

struct Row {
  int depth = 0;
  std::string shading, shade_model, normals, scene, backend;
  size_t triangles = 0, vertices = 0;
  double rmse = 0, rmse_exact = 0;
  int max_error = 0;
  size_t both_pixels = 0, silhouette_pixels = 0;
  double silhouette_share = 0;
  double ms_per_frame = 0;
  int frames = 0;
  double normals_ms = 0;
};

struct SweepOptions {
  int min_depth = 0, max_depth = 8;
  std::vector<std::string> lightings = {"seed", "specular"};
  std::vector<std::string> shadings;  // empty: all
  std::vector<std::string> backends = {"mesa", "soft", "soft-double"};
  int size = 512;
  int frames = 5;       // timed frames per picture (after one untimed warm-up frame)
  int frames_deep = 3;  // at depths >= deep_depth
  int deep_depth = 7;
  // Fast pictures take more frames, up to max_frames, until min_timed_ms have been timed: a median
  // of more samples is steadier on a busy machine, and costs little where frames are short.
  double min_timed_ms = 60;
  int max_frames = 25;
  // Pictures kept for the page (written by the caller): these depths, on this backend.
  std::vector<int> keep_depths = {1, 3, 5};
  std::vector<std::string> keep_shadings = {"flat", "smooth-average"};
  std::string keep_backend = "mesa";
};

struct Kept {
  std::string scene, shading;
  int depth;
  image::Image picture;
};

struct SweepResult {
  std::vector<Row> rows;
  std::vector<Kept> kept;
  std::vector<std::pair<std::string, Ideal>> ideals;         // per lighting setup
  std::vector<std::pair<std::string, double>> floors;        // rounding_floor per setup
  double seconds = 0;
};

// Progress: work done and in all (in units proportional to the expected run time, so the deep
// pictures weigh what they cost), and what is running now ("picture 17/324: depth 3 seed flat mesa").
using Progress = std::function<void(size_t done, size_t total, const std::string& now)>;

SweepResult run_sweep(const SweepOptions& o, const Progress& progress = nullptr);

}  // namespace ffc::report
