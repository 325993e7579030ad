// Selection (GL 2.1 section 5.2; Mesa's feedback.c): glSelectBuffer, the name stack, and the hit
// records written as glRenderMode leaves GL_SELECT or the name stack changes. A primitive hits
// when it survives clipping and culling; its window z values (the ones feedback would report,
// Context::feedback_primitive) widen the hit's depth range.
#include <algorithm>

#include "state/context.h"

namespace ffc::state {

void Context::select_put(GLuint v) {
  if (select_.count < select_.size) select_.buffer[select_.count] = v;
  ++select_.count;
}

void Context::select_hit(double z) {
  const float f = float(z);
  select_.hit = true;
  if (f < select_.min_z) select_.min_z = f;
  if (f > select_.max_z) select_.max_z = f;
}

// A hit record: the number of names, the depth range scaled to unsigned int as Mesa scales it (the
// float 2^32 times z, converted as x86-64 converts a float above 2^32 - 1: through a 64-bit integer,
// keeping the low 32 bits), then the names from the bottom of the stack.
void Context::write_hit() {
  auto scaled = [](float z) { return GLuint(uint64_t(int64_t(4294967296.0f * z))); };
  select_put(GLuint(select_.names.size()));
  select_put(scaled(select_.min_z));
  select_put(scaled(select_.max_z));
  for (GLuint n : select_.names) select_put(n);
  ++select_.hits;
  select_.hit = false;
  select_.min_z = 1, select_.max_z = -1;
}

void Context::SelectBuffer(GLsizei size, GLuint* buffer) {
  if (!outside_begin_end_or_compiling()) return;
  if (size < 0) return error(GL_INVALID_VALUE);
  if (render_mode_ == GL_SELECT) return error(GL_INVALID_OPERATION);
  select_.buffer = buffer, select_.size = size, select_.count = 0;
  select_.hit = false;
  select_.min_z = 1, select_.max_z = -1;
}

// The name stack calls do nothing outside selection mode; inside it, a pending hit is written
// before the stack changes, and not when the call is an error (measured for glLoadName and
// glPopName).
bool Context::name_stack_call() { return outside_begin_end() && render_mode_ == GL_SELECT; }

void Context::InitNames() {
  if (!name_stack_call()) return;
  if (select_.hit) write_hit();
  select_.names.clear();
  select_.min_z = 1, select_.max_z = -1;
}

void Context::LoadName(GLuint name) {
  if (!name_stack_call()) return;
  if (select_.names.empty()) return error(GL_INVALID_OPERATION);
  if (select_.hit) write_hit();
  select_.names.back() = name;
}

void Context::PushName(GLuint name) {
  if (!name_stack_call()) return;
  if (select_.names.size() >= SelectState::kMaxDepth) return error(GL_STACK_OVERFLOW);
  if (select_.hit) write_hit();
  select_.names.push_back(name);
}

void Context::PopName() {
  if (!name_stack_call()) return;
  if (select_.names.empty()) return error(GL_STACK_UNDERFLOW);
  if (select_.hit) write_hit();
  select_.names.pop_back();
}

// Leaving selection mode: the pending hit written, then the number of hits, or -1 when the
// records did not fit.
GLint Context::leave_select() {
  if (select_.hit) write_hit();
  const GLint result = select_.count > select_.size ? -1 : select_.hits;
  select_.count = 0, select_.hits = 0;
  select_.names.clear();
  return result;
}

int Context::select_values(GLenum pname, GLdouble* out) {
  switch (pname) {
    case GL_NAME_STACK_DEPTH: out[0] = double(select_.names.size()); return 1;
    case GL_MAX_NAME_STACK_DEPTH: out[0] = SelectState::kMaxDepth; return 1;
    case GL_SELECTION_BUFFER_SIZE: out[0] = select_.size; return 1;
  }
  return 0;
}

}  // namespace ffc::state
