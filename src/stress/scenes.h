// The small scenes the stress cases are built from: a lit icosphere or a quad grid drawn with
// client arrays, a standard camera and light, and the geometry of the mesh cases (slivers,
// needles, near-duplicate vertices, an icosphere patch subdivided far beyond what float holds).
#pragma once
#include <GL/gl.h>

#include <array>
#include <cstdint>
#include <vector>

namespace ffc::stress::scenes {

// Indexed triangles with per-vertex normals, in double (the float arrays are made when drawn).
struct Geometry {
  std::vector<std::array<double, 3>> positions, normals;
  std::vector<uint32_t> indices;  // triangles
};

// The icosphere of src/mesh at `depth` (radius 1, sphere normals), built once per depth.
const Geometry& sphere(int depth);
// A grid of n x n quads (2 triangles each) in the plane z = 0 over [-1,1]^2, normals +z.
Geometry grid(int n);

// Clears to black, depth test on, projection glFrustum(-0.35, 0.35, -0.35, 0.35, 1, 10), an
// identity modelview. `lit`: GL_LIGHTING with GL_LIGHT0 a white point light at eye (2, 2, 2),
// light ambient 0.1, and a material with ambient 0.2, diffuse (0.8, 0.6, 0.4), specular 0.5 and
// shininess 32.
void standard(bool lit = true);

// Draws g with glDrawElements(GL_TRIANGLES) from float client arrays, positions multiplied by
// `scale` (per axis) and normals by `normal_scale` (in double, then rounded to float).
void draw(const Geometry& g, const std::array<double, 3>& scale, double normal_scale = 1);
inline void draw(const Geometry& g, double scale = 1, double normal_scale = 1) {
  draw(g, {scale, scale, scale}, normal_scale);
}
// The same with double client arrays (GL_DOUBLE), so our double reference sees every bit.
void draw_double(const Geometry& g, double scale = 1);
// Client arrays of 4-component positions (x s, y s, z s, w): the same projective points as
// (x, y, z, 1) when s = w, with the geometry's normals.
void draw_homogeneous(const Geometry& g, double scale, float w);

// Mesh cases.
Geometry slivers();          // a fan of triangles whose apex angle goes down to 1e-7 radians
Geometry needles();          // long triangles 1e-4 to 1e-7 wide, crossing the view
Geometry near_duplicates();  // a grid whose vertices come in pairs one float ulp apart
// One face of the icosahedron subdivided `depth` times toward the sphere, exactly as src/mesh's
// icosphere does (midpoints normalized in double): 4^depth triangles.
Geometry icosphere_patch(int depth);
// The sub-triangle reached by taking child 0 `descend` times, then subdivided `depth` more times:
// a patch small enough (below float's spacing at radius 1) that its vertices collide in float.
Geometry icosphere_deep_patch(int descend, int depth);
// The centroid of a geometry's vertices.
std::array<double, 3> centroid(const Geometry& g);

}  // namespace ffc::stress::scenes
