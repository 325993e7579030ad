#include "check/feedback.h"

#include <stdexcept>
#include <string>

#include "gl/dispatch.h"

namespace ffc::check {

std::vector<FeedbackPrimitive> parse(const float* b, int count) {
  std::vector<FeedbackPrimitive> out;
  int i = 0;
  auto vertex = [&]() {
    if (i + 7 > count) throw std::runtime_error("feedback: truncated vertex at " + std::to_string(i));
    FeedbackVertex v{{b[i], b[i + 1], b[i + 2]}, {b[i + 3], b[i + 4], b[i + 5], b[i + 6]}};
    i += 7;
    return v;
  };
  while (i < count) {
    const unsigned token = unsigned(b[i++]);
    FeedbackPrimitive p{token, {}};
    switch (token) {
      case GL_POINT_TOKEN: p.vertices.push_back(vertex()); break;
      case GL_LINE_TOKEN:
      case GL_LINE_RESET_TOKEN:
        p.vertices.push_back(vertex());
        p.vertices.push_back(vertex());
        break;
      case GL_POLYGON_TOKEN: {
        if (i >= count) throw std::runtime_error("feedback: polygon without a count");
        const int n = int(b[i++]);
        for (int k = 0; k < n; ++k) p.vertices.push_back(vertex());
        break;
      }
      case GL_PASS_THROUGH_TOKEN: ++i; continue;
      default: throw std::runtime_error("feedback: unexpected token " + std::to_string(token));
    }
    out.push_back(std::move(p));
  }
  return out;
}

std::vector<FeedbackPrimitive> capture(backends::Backend& backend, int width, int height,
                                       const std::function<void()>& draw) {
  for (size_t size = size_t(1) << 16;; size *= 4) {
    if (size > (size_t(1) << 31)) throw std::runtime_error("feedback: more than 2^31 values");
    std::vector<float> buffer(size);
    backend.begin(width, height);
    glFeedbackBuffer(GLsizei(size), GL_3D_COLOR, buffer.data());
    glRenderMode(GL_FEEDBACK);
    draw();
    const GLint n = glRenderMode(GL_RENDER);
    if (n >= 0) return parse(buffer.data(), n);
  }
}

}  // namespace ffc::check
