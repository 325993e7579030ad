// The OSMesa platform of the classic mesa backend (mesa_surface.h): libOSMesa loaded with dlopen
// into a scope of its own (RTLD_LOCAL | RTLD_DEEPBIND). Linking libOSMesa would put Mesa's gl*
// symbols beside ours, and whichever the loader met first would win; loaded this way, the
// program's gl* calls reach our exports, and Mesa's own internal calls stay inside Mesa.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "mesa_surface.h"

namespace ffc::classic {

class OsMesaSurface final : public MesaSurface {
 public:
  // A width x height RGBA context with a 24-bit depth buffer, made current. Null with `why` set
  // when OSMesa cannot be loaded or the context cannot be made.
  static std::unique_ptr<MesaSurface> make(int width, int height, std::string& why);
  ~OsMesaSurface() override;  // finishes the queued drawing first: see finish_and_destroy in osmesa.cpp
  OsMesaSurface(const OsMesaSurface&) = delete;
  OsMesaSurface& operator=(const OsMesaSurface&) = delete;

  bool make_current() override;
  // A new framebuffer, the context's state kept: the queued drawing is finished into the old one,
  // and OSMesa takes the new size when the context is next made current (now, if it is current).
  void resize(int width, int height) override;
  // Each entry point by OSMesaGetProcAddress.
  void fill(Table& table) const override;
  // Finishes drawing and copies the picture, top row first.
  void read_rgba(unsigned char* out) override;

 private:
  OsMesaSurface() = default;
  void* context_ = nullptr;  // OSMesaContext
  int width_ = 0, height_ = 0;
  std::vector<uint8_t> buffer_;  // OSMesa renders here, bottom row first
};

}  // namespace ffc::classic
