// The ideal picture that finer tessellation converges to: the exact unit sphere centred on the
// origin, ray-cast through every pixel centre with the description's camera, and lit per pixel by
// the same lighting equation in double (lighting::prepare<double> / light<double>) with the lights
// placed in eye space as the GL scene places them. The colour is clamped and converted to 8 bits as
// the renderers convert (raster::to_unorm8: half to even).
#pragma once
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "image/image.h"
#include "lighting/lighting.h"
#include "scene/description.h"

namespace ffc::report {

// The lighting state GL holds once the description's calls are made, as the double lighting
// stage takes it: light positions and spot directions in eye space, the key as our context builds
// it (state/light.cpp).
struct LightingState {
  lighting::LightParams lights[8];
  lighting::MaterialParams materials[2];
  lighting::ModelParams model;
  lighting::Key key;
};
LightingState lighting_state(const scene::Description& d);

// gluLookAt's matrix for the description's camera, and the projection (aspect 0: width / height).
glm::dmat4 view_matrix(const scene::Camera& c);
glm::dmat4 projection_matrix(const scene::Camera& c, int width, int height);

struct Ideal {
  image::Image image;               // RGBA8; background where the sphere does not cover
  std::vector<glm::dvec3> exact;    // per pixel, top row first: the clamped colour before conversion
  std::vector<uint8_t> covered;     // per pixel: 1 where a pixel centre's ray hits the sphere
  size_t covered_count = 0;
};

// Ray-casts the unit sphere for the description's size, camera, lights, light model and front
// material (the objects are not read: the sphere stands in for them). Throws std::invalid_argument
// for what the ideal does not model: scene transforms, colour material (the glColor would have to
// be known per pixel) and lighting off.
Ideal ray_cast_sphere(const scene::Description& d);

}  // namespace ffc::report
