/* While the mesa backend draws, Mesa's platform library (libOSMesa, or libEGL on the EGL
 * platform) is loaded but none of its symbols is visible to the program: the program's gl* names
 * are ffcompat's exports, and ffcompat_get_proc_address hands out those same addresses. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <string.h>

#include "classic_test.h"

/* <GL/glx.h>'s, without the X11 headers it brings. */
extern void (*glXGetProcAddressARB(const GLubyte* name))(void);

int main(void) {
  require_ffcompat();
  ffcompat_surface* s = surface_on("mesa", 16, 16);

  /* Mesa is in the process (privately) through one of its platforms ... */
  void* osmesa = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_NOLOAD);
  void* egl = dlopen("libEGL.so.1", RTLD_NOW | RTLD_NOLOAD);
  CHECK(osmesa != NULL || egl != NULL, "neither libOSMesa.so.8 nor libEGL.so.1 is loaded while the mesa backend runs");
  /* ... but their names are not in the global scope. */
  CHECK(dlsym(RTLD_DEFAULT, "OSMesaCreateContext") == NULL, "OSMesaCreateContext is visible");
  CHECK(dlsym(RTLD_DEFAULT, "OSMesaGetProcAddress") == NULL, "OSMesaGetProcAddress is visible");
  CHECK(dlsym(RTLD_DEFAULT, "eglGetDisplay") == NULL, "eglGetDisplay is visible");
  CHECK(dlsym(RTLD_DEFAULT, "eglGetProcAddress") == NULL, "eglGetProcAddress is visible");

  /* glBegin, as the program and the global scope see it, is ffcompat's libGL.so.1's. */
  Dl_info gl, ours;
  CHECK(dladdr((void*)&glBegin, &gl) && dladdr((void*)ffcompat_surface_create, &ours) &&
            gl.dli_fbase == ours.dli_fbase,
        "glBegin comes from %s, not from %s", gl.dli_fname, ours.dli_fname);
  void* by_name = dlsym(RTLD_DEFAULT, "glBegin");
  CHECK(by_name == (void*)&glBegin, "dlsym's glBegin %p, the program's %p", by_name, (void*)&glBegin);
  if (osmesa) CHECK(dlsym(osmesa, "glBegin") != by_name, "Mesa's glBegin is ours");
  if (egl) {
    typedef void* (*EglProc)(const char*);
    const EglProc egl_proc = (EglProc)dlsym(egl, "eglGetProcAddress");
    CHECK(egl_proc && egl_proc("glBegin") != by_name, "EGL's glBegin is ours");
  }

  CHECK(ffcompat_get_proc_address("glBegin") == (void*)&glBegin, "get_proc_address(glBegin)");
  CHECK(ffcompat_get_proc_address("glMultiTexCoord4svARB") == (void*)&glMultiTexCoord4svARB, "the last ARB one");
  CHECK(ffcompat_get_proc_address("glNoSuchFunction") == NULL, "an unknown name has an address");
  CHECK(ffcompat_get_proc_address("ffcompat_surface_create") == NULL, "a non-GL name has an address");
  CHECK((void*)glXGetProcAddressARB((const GLubyte*)"glEnd") == (void*)&glEnd, "glXGetProcAddressARB(glEnd)");
  CHECK(glXGetProcAddressARB((const GLubyte*)"glXCreateContext") == NULL, "a GLX function has an address");

  /* A call through the address reaches Mesa. */
  typedef const GLubyte* (*GetString)(GLenum);
  const GetString get_string = (GetString)ffcompat_get_proc_address("glGetString");
  const char* renderer = get_string ? (const char*)get_string(GL_RENDERER) : NULL;
  CHECK(renderer && strstr(renderer, "llvmpipe"), "renderer %s", renderer ? renderer : "(null)");

  ffcompat_surface_destroy(s);
  return finish();
}
