#include "backends/glsl/material_stream.h"

#include "backends/glsl/shader_gen.h"

namespace ffc::glsl {

void MaterialStream::stream(const CoreGl& gl, const std::vector<state::SinkMaterial>* materials) {
  if (!materials) {
    if (on_)
      for (unsigned a = kMaterial; a < kMaterial + kMaterialCount; ++a) gl.DisableVertexAttribArray(a);
    on_ = false;
    return;
  }
  static_assert(sizeof(state::SinkMaterial) == kMaterialCount * 4 * sizeof(float), "8 vec4 per vertex");
  if (!buffer_) gl.GenBuffers(1, &buffer_);
  gl.BindBuffer(GL_ARRAY_BUFFER, buffer_);
  gl.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(materials->size() * sizeof(state::SinkMaterial)), materials->data(),
                GL_STREAM_DRAW);
  for (unsigned i = 0; i < kMaterialCount; ++i) {
    gl.VertexAttribPointer(kMaterial + i, 4, GL_FLOAT, GL_FALSE, sizeof(state::SinkMaterial),
                           reinterpret_cast<void*>(i * 4 * sizeof(float)));
    gl.EnableVertexAttribArray(kMaterial + i);
  }
  on_ = true;
}

void MaterialStream::destroy(const CoreGl& gl) {
  if (buffer_) gl.DeleteBuffers(1, &buffer_);
  buffer_ = 0;
}

}  // namespace ffc::glsl
