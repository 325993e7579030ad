// The renderers behind one interface. A backend owns an offscreen framebuffer (RGBA8, 24-bit
// depth), makes it current, and points the GL dispatch at itself, so one drawing routine written
// with plain gl* calls renders on any of them.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "image/image.h"

namespace ffc::backends {

class Backend {
 public:
  virtual ~Backend() = default;
  virtual std::string name() const = 0;
  // Makes a width x height framebuffer current, in GL's default state, and loads the dispatch.
  // Throws std::runtime_error if the context cannot be made.
  virtual void begin(int width, int height) = 0;
  // Makes this backend's framebuffer current again, with its state and contents, after another
  // backend's: `ffcompat bench` alternates frames between backends.
  virtual void resume() = 0;
  // Finishes drawing and reads the colour buffer back, top row first, into `out` (whose memory
  // is reused when the size has not changed).
  virtual void read_into(image::Image& out) = 0;
  image::Image read() {
    image::Image img;
    read_into(img);
    return img;
  }
};

// "mesa" (Mesa's fixed-function pipeline, offscreen), "soft" (ours, float) or "soft-double" (ours,
// the double reference), each of ours also as "-spec" (GL 2.1 to the letter where Mesa departs from
// it, docs/deviations.md). Throws std::invalid_argument otherwise, and for "mesa" in a build
// without OSMesa (or a program that does not link ffcompat_mesa).
std::unique_ptr<Backend> make(const std::string& name);

// A backend that lives in another library (Mesa's, in ffcompat_mesa, which needs OSMesa) offers
// itself to make() through this hook when that library is linked. Returns true, for use as a
// static initializer.
using Factory = std::unique_ptr<Backend> (*)();
bool register_backend(const std::string& name, Factory factory);

// The names make() accepts in this program: ours, then the registered ones.
std::vector<std::string> names();

}  // namespace ffc::backends
