// ffcompat's public interface: an offscreen OpenGL 1.x fixed-function context on one of ffcompat's
// backends ("soft", ours; "mesa", Mesa through OSMesa, when the build has it), and the gl* entry
// points of legacy programs, which go to whichever context is current.
//
//   ffcompat::Context ctx("soft", 64, 64);  // made current
//   glClear(GL_COLOR_BUFFER_BIT); glBegin(GL_TRIANGLES); ... glEnd();
//   std::vector<std::uint8_t> rgba = ctx.read_pixels();
//
// Link with ffcompat::ffcompat (CMake: find_package(ffcompat)) or `pkg-config --static --libs
// ffcompat`. Include this instead of <GL/gl.h>: the gl* names below are macros that call through
// the dispatch's function pointers (ffc_glBegin, ...), which a Context fills when made current.
#pragma once
#include <GL/gl.h>  // types and enums only: the names below shadow its prototypes

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#define FFC_GL_FUNCTION(ret, name, params) extern ret(APIENTRY* ffc_gl##name) params;
#include "ffcompat/gl_functions.inc"
#undef FFC_GL_FUNCTION

#include "ffcompat/gl_names.inc"

namespace ffcompat {

// The library's version, "MAJOR.MINOR.PATCH".
const char* version();

// The backend names Context accepts in this program ("soft", "soft-double", "soft-spec",
// "soft-double-spec", and "mesa" when the library was built with OSMesa).
std::vector<std::string> backends();

// One offscreen framebuffer (RGBA8, 24-bit depth) with its GL state, in GL's default state when
// made. Contexts on several backends may live side by side; the gl* calls go to the current one.
class Context {
 public:
  // Makes the context and makes it current. Throws std::invalid_argument for a backend this
  // build does not have (naming why), std::runtime_error if the context cannot be made.
  Context(const std::string& backend, int width, int height);
  ~Context();
  Context(Context&&) noexcept;
  Context& operator=(Context&&) noexcept;
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  // Makes this context current again (after another one), with its state and contents.
  void make_current();
  // Finishes drawing and returns the colour buffer, RGBA8, width*height*4 bytes, top row first
  // (glReadPixels's rows flipped).
  std::vector<std::uint8_t> read_pixels();

  int width() const;
  int height() const;
  std::string backend() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ffcompat
