// The built-in scenes, reproducing the seed programs, as Descriptions; and rendering a scene
// (built-in or described) through a backend.
#pragma once
#include <string>

#include "backends/backend.h"
#include "image/image.h"
#include "mesh/mesh.h"
#include "scene/description.h"

namespace ffc::scene {

// A built-in scene and the options the command line varies.
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

// The built-in scene as a Description, drawing what the seed program draws:
//  cube: gluPerspective(45, w/h, 1, 10), gluLookAt from (5 sin a, h, 5 cos a) at the origin; the
//    unlit unit axes; light 0 at (3,4,5,1) set after the camera (ambient .1, diffuse and specular
//    white); GL_RESCALE_NORMAL; on GL_FRONT a red ambient and diffuse, white specular, shininess
//    10; the cube of side 2 with glColor blue (ignored while lighting is on).
//  icosphere: the same projection, gluLookAt from (0,0,4); light 0 keeps its default position
//    (0,0,1,0) in eye space (ambient .2, diffuse white, specular black); on GL_FRONT an ambient
//    and diffuse of (.8,.6,.4), no specular, shininess 20; the icosphere of the spec's depth.
// Both draw with client arrays: glDrawArrays for face normals, glDrawElements otherwise.
// Throws std::invalid_argument for an unknown name.
Description describe(const Spec& spec);

// The mesh a spec draws (normals updated).
mesh::Mesh build_mesh(const Spec& spec);

// Issues the scene's GL calls through the dispatch on the current context: draw(describe(spec)).
void draw(const Spec& spec);

// Builds the meshes, begin() on the backend at the described size, draw, read back.
image::Image render(const Description& d, backends::Backend& backend);
image::Image render(const Spec& spec, backends::Backend& backend);

}  // namespace ffc::scene
