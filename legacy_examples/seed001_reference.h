// Seed 001's lighting on the CPU in double: the handout's equation at a point, and the colour a
// pixel of the picture should have (the pixel centre's ray hits the cube; Gouraud interpolates the
// three vertex colours, Phong the normal and the position, with the hit point's barycentric
// weights, which are the perspective-correct weights GL interpolates with). What the tests and
// `seed001 --check` hold the GL pictures to.
#pragma once
#include <glm/glm.hpp>

#include "image/image.h"
#include "seed001_scene.h"

namespace seed001 {

// The shader's illuminate() in double, unclamped, in world space (eye_space and infinite_viewer
// follow the lighting's switches; eye space gives the same value but for rounding).
glm::dvec3 illuminate(const Lighting& l, const View& v, const glm::dvec3& normal, const glm::dvec3& pos);

struct PixelRef {
  int triangle = -1;     // which of the 12 triangles the centre's ray hits first; -1: background
  int face = -1;         // triangle / 2: +z, -z, +y, -y, +x, -x
  glm::dvec3 colour{0};  // what GL should write, in [0,1] (clamped as the framebuffer clamps)
  glm::dvec3 point{0};   // the hit point (world)
};
// Pixel (x, y) of the picture, top row first, at the view's size.
PixelRef reference_pixel(const Lighting& l, const View& v, int x, int y);

// A picture held to the reference: every pixel whose 3x3 neighbourhood shows one face (the
// colour, max over RGB of |picture - round(255 * reference)|) and every pixel whose neighbourhood
// shows only background (black).
struct ReferenceCheck {
  int pixels = 0, background = 0;  // how many of each were compared
  int max_diff = 0;                // in 8-bit steps
  double mean_diff = 0;
  int worst_x = -1, worst_y = -1;
  int background_wrong = 0;  // background pixels that are not black
};
ReferenceCheck check_against_reference(const ffc::image::Image& img, const Lighting& l, const View& v);

// What GL's N.L test would take away: over the seeds' cameras (every 10 degrees around, heights
// -3 to 3 every 0.5), the largest specular term (in 8-bit steps) the handout's equation gives a
// point the camera sees where N.L <= 0 (the light behind the surface), with the lighting's normals
// interpolated over each triangle (sampled on a grid, corners included). Fixed function gives 0 there.
struct GuardSweep {
  int cameras = 0;
  int cameras_affected = 0;  // where some visible point gets half a step or more
  double max_steps = 0;
  double cam_angle_deg = 0, cam_height = 0;
  glm::dvec3 point{0};
  int face = -1;
};
GuardSweep sweep_nl_guard(const Lighting& l);

}  // namespace seed001
