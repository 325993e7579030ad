// Lit vertices as a GL implementation reports them: glRenderMode(GL_FEEDBACK) with GL_3D_COLOR
// gives, per primitive after clipping and culling, each vertex's window position and its lit,
// clamped primary colour. That is Mesa's vertex-level oracle, and our context speaks it too.
#pragma once
#include <functional>
#include <glm/glm.hpp>
#include <vector>

#include "backends/backend.h"

namespace ffc::check {

struct FeedbackVertex {
  glm::dvec3 position;  // window coordinates
  glm::dvec4 color;
};

struct FeedbackPrimitive {
  unsigned token;  // GL_POINT_TOKEN, GL_LINE_TOKEN, GL_LINE_RESET_TOKEN or GL_POLYGON_TOKEN
  std::vector<FeedbackVertex> vertices;
};

// begin() on the backend, then runs `draw` in feedback mode and parses what comes back. The buffer
// grows until everything fits. Throws std::runtime_error on a malformed stream.
std::vector<FeedbackPrimitive> capture(backends::Backend& backend, int width, int height,
                                       const std::function<void()>& draw);

// Parses a GL_3D_COLOR feedback buffer.
std::vector<FeedbackPrimitive> parse(const float* buffer, int count);

}  // namespace ffc::check
