// The vertex stage's parts that its callers share (not an interface: included by src/state's
// .cpp files only). The stage itself is vertex_stage.cpp.
#pragma once
#include <glm/glm.hpp>

namespace ffc::state {

// One vertex as the stage takes it: object-space position, normal and colour, in double, as
// fetched from the client arrays, the current values or immediate mode's kept vertices.
struct VertexIn {
  glm::dvec4 obj;
  glm::dvec3 normal;
  glm::dvec4 color;
};

}  // namespace ffc::state
