// The built-in scenes, reproducing the seed programs, and the classic GL calls that draw them.
#pragma once
#include <string>

#include "backends/backend.h"
#include "image/image.h"
#include "mesh/mesh.h"

namespace ffc::scene {

enum class Shade { Flat, Smooth };  // glShadeModel
Shade parse_shade(const std::string& s);  // throws std::invalid_argument
const char* to_string(Shade s);

struct Spec {
  std::string name;  // "cube" or "icosphere"
  int depth = 0;     // icosphere subdivision
  Shade shade = Shade::Smooth;
  mesh::NormalSource normals = mesh::NormalSource::Face;
  int width = 0, height = 0;
  double cam_angle_deg = 0, cam_height = 1;  // the cube lab's camera
};

// A built-in scene with the seed program's defaults:
//  cube: seed 000's practice program, 640x640, face normals under GL_SMOOTH;
//  icosphere: seed 004's lighting, 512x512, depth 3, sphere normals under GL_SMOOTH.
// Throws std::invalid_argument for an unknown name.
Spec builtin(const std::string& name);

// The mesh a spec draws (normals updated).
mesh::Mesh build_mesh(const Spec& spec);

// Issues the scene's GL calls through the dispatch on the current context.
void draw(const Spec& spec);

// begin() on the backend, draw, read back.
image::Image render(const Spec& spec, backends::Backend& backend);

}  // namespace ffc::scene
