// Selection mode's state (GL 2.1 section 5.2, table 6.41): the buffer, the name stack and the hit
// being gathered (selection.cpp).
#pragma once
#include <GL/gl.h>

#include <vector>

namespace ffc::state {

struct SelectState {
  GLuint* buffer = nullptr;
  GLsizei size = 0;   // GL_SELECTION_BUFFER_SIZE
  GLsizei count = 0;  // values written (or that would have been: past `size` they overflow)
  GLint hits = 0;
  std::vector<GLuint> names;  // GL_NAME_STACK_DEPTH = names.size()
  bool hit = false;           // a primitive has hit since the last record
  float min_z = 1, max_z = -1;
  static constexpr size_t kMaxDepth = 64;  // GL_MAX_NAME_STACK_DEPTH, as Mesa's
};

}  // namespace ffc::state
