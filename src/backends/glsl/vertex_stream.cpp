#include "backends/glsl/vertex_stream.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "backends/glsl/shader_gen.h"

namespace ffc::glsl {

VertexFormat format_of(const CoreGl& gl, GLuint program) {
  VertexFormat f;
  f.normal = gl.GetAttribLocation(program, "a_normal") >= 0;
  f.color = gl.GetAttribLocation(program, "a_color") >= 0;
  return f;
}

StreamBuffer::StreamBuffer(const CoreGl& gl, GLenum target) : gl_(gl), target_(target) { gl_.GenBuffers(1, &id_); }

StreamBuffer::~StreamBuffer() { gl_.DeleteBuffers(1, &id_); }

unsigned char* StreamBuffer::map(size_t n) {
  gl_.BindBuffer(target_, id_);
  if (n > capacity_) {
    capacity_ = std::max(n, 2 * capacity_);
    gl_.BufferData(target_, GLsizeiptr(capacity_), nullptr, GL_STREAM_DRAW);
  }
  if (n == 0) return nullptr;
  void* at = gl_.MapBufferRange(target_, 0, GLsizeiptr(n), GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_BUFFER_BIT);
  if (!at) throw std::runtime_error("glsl: a stream buffer could not be mapped");
  return static_cast<unsigned char*>(at);
}

void StreamBuffer::unmap() { gl_.UnmapBuffer(target_); }

void StreamBuffer::write(const void* data, size_t n) {
  if (unsigned char* to = map(n)) {
    std::memcpy(to, data, n);
    unmap();
  }
}

namespace {

// The fields of `f` of each vertex, in order, into `to`.
template <bool kNormal, bool kColor>
void pack(const state::SinkVertex* v, size_t count, unsigned char* to) {
  for (size_t i = 0; i < count; ++i) {
    std::memcpy(to, &v[i].position, sizeof v[i].position), to += sizeof v[i].position;
    if (kNormal) std::memcpy(to, &v[i].normal, sizeof v[i].normal), to += sizeof v[i].normal;
    if (kColor) std::memcpy(to, &v[i].color, sizeof v[i].color), to += sizeof v[i].color;
  }
}

}  // namespace

void VertexStream::upload(const VertexFormat& f, const state::SinkVertex* v, size_t count) {
  bytes_ = count * f.stride();
  if (unsigned char* to = buffer_.map(bytes_)) {
    if (f.normal && f.color) pack<true, true>(v, count, to);
    else if (f.normal) pack<true, false>(v, count, to);
    else if (f.color) pack<false, true>(v, count, to);
    else pack<false, false>(v, count, to);
    buffer_.unmap();
  }
  if (pointed_ && f == current_) return;
  const GLsizei stride = GLsizei(f.stride());
  size_t offset = 0;
  auto point = [&](GLuint attribute, bool on, GLint size) {
    if (!on) return gl_.DisableVertexAttribArray(attribute);
    gl_.VertexAttribPointer(attribute, size, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offset));
    gl_.EnableVertexAttribArray(attribute);
    offset += size_t(size) * sizeof(float);
  };
  point(kPosition, true, 4);
  point(kNormal, f.normal, 3);
  point(kColor, f.color, 4);
  current_ = f, pointed_ = true;
}

}  // namespace ffc::glsl
