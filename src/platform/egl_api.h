// libEGL.so.1, loaded on first use with dlopen rather than linked. Two reasons: a program that
// never asks for EGL (the soft backends, OSMesa) neither needs libEGL installed nor pays for
// loading it; and the classic libGL.so.1 (src/classic/gl) can reach Mesa through EGL without
// libEGL becoming one of its own dependencies, so a classic program runs where libEGL is absent.
// RTLD_LOCAL keeps libEGL's symbols out of the global scope; libEGL and Mesa's EGL vendor library
// export and import no gl* names (checked with nm -D), so our libGL's exports cannot shadow them.
#pragma once
#include <EGL/egl.h>

#include <string>

namespace ffc::platform {

struct EglApi {
  decltype(&::eglGetError) GetError = nullptr;
  decltype(&::eglQueryString) QueryString = nullptr;
  decltype(&::eglGetProcAddress) GetProcAddress = nullptr;
  decltype(&::eglGetDisplay) GetDisplay = nullptr;
  decltype(&::eglInitialize) Initialize = nullptr;
  decltype(&::eglBindAPI) BindAPI = nullptr;
  decltype(&::eglQueryAPI) QueryAPI = nullptr;
  decltype(&::eglChooseConfig) ChooseConfig = nullptr;
  decltype(&::eglCreatePbufferSurface) CreatePbufferSurface = nullptr;
  decltype(&::eglDestroySurface) DestroySurface = nullptr;
  decltype(&::eglCreateContext) CreateContext = nullptr;
  decltype(&::eglDestroyContext) DestroyContext = nullptr;
  decltype(&::eglMakeCurrent) MakeCurrent = nullptr;
  decltype(&::eglGetCurrentContext) GetCurrentContext = nullptr;
  decltype(&::eglGetCurrentSurface) GetCurrentSurface = nullptr;
  decltype(&::eglGetCurrentDisplay) GetCurrentDisplay = nullptr;
  std::string error;  // why libEGL could not be loaded; empty when every pointer is set
};

// Loaded once per process and never closed (Mesa's threads and atexit handlers outlive any
// context).
const EglApi& egl_api();

}  // namespace ffc::platform
