#include "platform/egl_api.h"

#include <dlfcn.h>

#include <type_traits>

namespace ffc::platform {

const EglApi& egl_api() {
  static const EglApi loaded = [] {
    EglApi a;
    void* lib = dlopen("libEGL.so.1", RTLD_NOW | RTLD_LOCAL);
    if (!lib) {
      const char* e = dlerror();
      a.error = std::string("egl: cannot load libEGL.so.1 (Debian: libegl1 and libegl-mesa0): ") + (e ? e : "?");
      return a;
    }
    auto find = [&](auto& fn, const char* name) {
      fn = reinterpret_cast<std::remove_reference_t<decltype(fn)>>(dlsym(lib, name));
      if (!fn && a.error.empty()) a.error = std::string("egl: libEGL.so.1 lacks ") + name;
    };
    find(a.GetError, "eglGetError");
    find(a.QueryString, "eglQueryString");
    find(a.GetProcAddress, "eglGetProcAddress");
    find(a.GetDisplay, "eglGetDisplay");
    find(a.Initialize, "eglInitialize");
    find(a.BindAPI, "eglBindAPI");
    find(a.QueryAPI, "eglQueryAPI");
    find(a.ChooseConfig, "eglChooseConfig");
    find(a.CreatePbufferSurface, "eglCreatePbufferSurface");
    find(a.DestroySurface, "eglDestroySurface");
    find(a.CreateContext, "eglCreateContext");
    find(a.DestroyContext, "eglDestroyContext");
    find(a.MakeCurrent, "eglMakeCurrent");
    find(a.GetCurrentContext, "eglGetCurrentContext");
    find(a.GetCurrentSurface, "eglGetCurrentSurface");
    find(a.GetCurrentDisplay, "eglGetCurrentDisplay");
    return a;
  }();
  return loaded;
}

}  // namespace ffc::platform
