// The vertex stage's parts that its callers share (not an interface: included by src/state's
// .cpp files only). The stage itself is vertex_stage.cpp.
#pragma once
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>

namespace ffc::state {

// One vertex as the stage takes it: object-space position, normal and colour, in double, as
// fetched from the client arrays, the current values or immediate mode's kept vertices.
struct VertexIn {
  glm::dvec4 obj;
  glm::dvec3 normal;
  glm::dvec4 color;
};

// Immediate mode's kept vertices (Context::list_pos_, list_normal_, list_color_): positions in
// float, normals and colours in double, a list null where the current value stands for every
// vertex. The float stage reads them straight into its columns (VertexStage::fetch_list), the
// values fetch(i) gives without a record in double between; the double stage calls fetch(i).
struct ListFetch {
  const glm::vec4* pos = nullptr;
  const glm::dvec3* normal = nullptr;  // null: cur_normal
  const glm::dvec4* color = nullptr;   // null: cur_color
  glm::dvec3 cur_normal{0};
  glm::dvec4 cur_color{0};
  VertexIn operator()(int i) const {
    const size_t k = size_t(i);
    return {glm::dvec4(pos[k]), normal ? normal[k] : cur_normal, color ? color[k] : cur_color};
  }
};

// The float stage's transforms on columns (vertex_stage_simd.cpp, Highway, the scalar code's bits
// on every target). Columns are read and written up to `count` rounded up to a multiple of the
// vector length (lighting::kSoaPad covers every target); `clip` only up to `count`.
//   transform_columns: clip = to_clip x obj, and eye = *to_eye x obj where to_eye is given, as
//     fmat::transform computes them; with eye_w_one the eye w column is 1 instead (the stage
//     lights at w = 1 outside spec mode: that row is not computed);
//   eye_normal_columns: the object normals times M^-1 as a row vector, normalized (a normal of
//     length 0 or NaN kept as it is: returns true when one was met) or divided by
//     `rescale` when it is positive, in double, then rounded to float.
void transform_columns(const glm::mat4& to_clip, const glm::mat4* to_eye, const float* const obj[4], size_t count,
                       glm::vec4* clip, float* const eye[4], bool eye_w_one = false);
bool eye_normal_columns(const glm::dmat3& inv, bool normalize, double rescale, const double* const raw[3],
                        size_t count, float* const out[3]);
// Columns from `count` packed elements of `comps` floats (3 or 4; any alignment): out[k][j] is
// component k of element j, in float or (the normals' columns) in double. Reads nothing past
// element count - 1 and writes nothing past out[k][count - 1].
void float_columns(const uint8_t* packed, int comps, size_t count, float* const out[4]);
void double_columns(const uint8_t* packed, size_t count, double* const out[3]);

}  // namespace ffc::state
