// The vertex buffer each draw streams into. Only the attributes the linked program reads are sent
// (a_position always; a_normal and a_color when the program has them active: unlit programs read
// no normal, lit ones without colour material no colour), packed, written straight into the
// buffer's storage: mapped with the old storage invalidated (the driver hands fresh storage while
// an earlier draw still reads the old, without waiting for it). The storage grows geometrically
// and is kept, so a steady scene neither allocates nor copies its vertices twice.
#pragma once
#include <cstddef>

#include "backends/glsl/gl_core.h"
#include "state/draw_sink.h"

namespace ffc::glsl {

// A buffer object a draw streams into: its storage grows geometrically and is kept; each draw maps
// the bytes it writes with the old contents invalidated.
class StreamBuffer {
 public:
  StreamBuffer(const CoreGl& gl, GLenum target);  // the context current: makes the buffer
  ~StreamBuffer();
  StreamBuffer(const StreamBuffer&) = delete;
  StreamBuffer& operator=(const StreamBuffer&) = delete;
  // Binds the buffer to its target and maps bytes [0, n) for writing; unmap() when written.
  unsigned char* map(size_t n);
  void unmap();
  // Binds it with `data`'s n bytes as its first n.
  void write(const void* data, size_t n);

 private:
  const CoreGl& gl_;
  GLenum target_;
  GLuint id_ = 0;
  size_t capacity_ = 0;
};

struct VertexFormat {
  bool normal = true, color = true;
  size_t stride() const { return 4 * sizeof(float) + (normal ? 3 * sizeof(float) : 0) + (color ? 4 * sizeof(float) : 0); }
  bool operator==(const VertexFormat& o) const { return normal == o.normal && color == o.color; }
};

// What the linked program reads (its active attributes).
VertexFormat format_of(const CoreGl& gl, GLuint program);

class VertexStream {
 public:
  explicit VertexStream(const CoreGl& gl) : gl_(gl), buffer_(gl, GL_ARRAY_BUFFER) {}
  // Binds the buffer to GL_ARRAY_BUFFER with the vertices in `f`'s layout, the attribute arrays
  // of the bound vertex array object pointing into it.
  void upload(const VertexFormat& f, const state::SinkVertex* v, size_t count);
  size_t bytes() const { return bytes_; }  // the last upload's

 private:
  const CoreGl& gl_;
  StreamBuffer buffer_;
  size_t bytes_ = 0;
  VertexFormat current_;
  bool pointed_ = false;  // the attribute pointers set for current_
};

}  // namespace ffc::glsl
