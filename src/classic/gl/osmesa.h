// The mesa backend of libGL.so.1: a Mesa context through OSMesa, loaded with dlopen into a scope
// of its own (RTLD_LOCAL | RTLD_DEEPBIND). Linking libOSMesa would put Mesa's gl* symbols beside
// ours, and whichever the loader met first would win; loaded this way, the program's gl* calls
// reach our exports, and Mesa's own internal calls stay inside Mesa.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "table.h"

namespace ffc::classic {

class OsMesaSurface {
 public:
  // A width x height RGBA context with a 24-bit depth buffer, made current. Null with `why` set
  // when OSMesa cannot be loaded or the context cannot be made.
  static std::unique_ptr<OsMesaSurface> make(int width, int height, std::string& why);
  ~OsMesaSurface();  // finishes the queued drawing first: see finish_and_destroy in osmesa.cpp
  OsMesaSurface(const OsMesaSurface&) = delete;
  OsMesaSurface& operator=(const OsMesaSurface&) = delete;

  bool make_current();
  // A new framebuffer, the context's state kept: the queued drawing is finished into the old one,
  // and OSMesa takes the new size when the context is next made current (now, if it is current).
  void resize(int width, int height);
  // Each entry point by OSMesaGetProcAddress.
  void fill(Table& table) const;
  // Finishes drawing and copies the picture, top row first.
  void read_rgba(unsigned char* out);

 private:
  OsMesaSurface() = default;
  void* context_ = nullptr;  // OSMesaContext
  int width_ = 0, height_ = 0;
  std::vector<uint8_t> buffer_;  // OSMesa renders here, bottom row first
};

}  // namespace ffc::classic
