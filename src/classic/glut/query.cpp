// glutGet, glutDeviceGet, glutLayerGet, glutGetModifiers, glutExtensionSupported and
// glutGetProcAddress: what a program can ask about its windows, devices and GL.
#include <dlfcn.h>

#include <cstring>

#include "font.h"
#include "glut_state.h"

using namespace ffc::glut;

extern "C" {

int glutGet(GLenum what) {
  State& s = state();
  const Window* w = s.current;
  const unsigned mode = w ? w->mode : 0;
  int sw = 0, sh = 0;
  switch (what) {
    case GLUT_INIT_STATE: return s.initialised;
    case GLUT_ELAPSED_TIME: return int(elapsed_ms());
    case GLUT_INIT_WINDOW_X: return s.init_x;
    case GLUT_INIT_WINDOW_Y: return s.init_y;
    case GLUT_INIT_WINDOW_WIDTH: return s.init_width;
    case GLUT_INIT_WINDOW_HEIGHT: return s.init_height;
    case GLUT_INIT_DISPLAY_MODE: return int(s.init_mode);
    case GLUT_INIT_MAJOR_VERSION: return s.context_major;
    case GLUT_INIT_MINOR_VERSION: return s.context_minor;
    case GLUT_INIT_FLAGS: return s.context_flags;
    case GLUT_INIT_PROFILE: return s.context_profile;
    case GLUT_ACTION_ON_WINDOW_CLOSE: return s.action_on_window_close;
    case GLUT_VERSION: return 30400;  // the freeglut whose behaviour this follows (3.4.0)
    case GLUT_RENDERING_CONTEXT: return s.rendering_context;
    case GLUT_DIRECT_RENDERING: return s.direct_rendering;
    case GLUT_SKIP_STALE_MOTION_EVENTS: return s.skip_stale_motion;
    case GLUT_GEOMETRY_VISUALIZE_NORMALS: return s.visualize_normals;
    case GLUT_STROKE_FONT_DRAW_JOIN_DOTS: return stroke_font_draw_join_dots;
    case GLUT_SCREEN_WIDTH: screen_size(&sw, &sh); return sw;
    case GLUT_SCREEN_HEIGHT: screen_size(&sw, &sh); return sh;
    // at 96 dots per inch
    case GLUT_SCREEN_WIDTH_MM: screen_size(&sw, &sh); return int(sw * 25.4 / 96 + 0.5);
    case GLUT_SCREEN_HEIGHT_MM: screen_size(&sw, &sh); return int(sh * 25.4 / 96 + 0.5);
    case GLUT_MENU_NUM_ITEMS: return 0;
    case GLUT_DISPLAY_MODE_POSSIBLE:
      // what a surface has: RGBA, depth, double buffering; no stencil, accumulation, stereo, index
      return !(s.init_mode & (GLUT_INDEX | GLUT_STENCIL | GLUT_ACCUM | GLUT_STEREO | GLUT_LUMINANCE));
    case GLUT_WINDOW_BORDER_WIDTH: case GLUT_WINDOW_HEADER_HEIGHT: return 0;
    default: break;
  }
  // The rest describe the current window; freeglut answers 0 when there is none.
  if (!w) return 0;
  switch (what) {
    case GLUT_WINDOW_X: return w->x;
    case GLUT_WINDOW_Y: return w->y;
    case GLUT_WINDOW_WIDTH: return w->width;
    case GLUT_WINDOW_HEIGHT: return w->height;
    case GLUT_WINDOW_BUFFER_SIZE: return (mode & GLUT_ALPHA) ? 32 : 24;
    case GLUT_WINDOW_RED_SIZE: case GLUT_WINDOW_GREEN_SIZE: case GLUT_WINDOW_BLUE_SIZE: return 8;
    case GLUT_WINDOW_ALPHA_SIZE: return (mode & GLUT_ALPHA) ? 8 : 0;
    case GLUT_WINDOW_DEPTH_SIZE: return 24;  // every surface has a 24-bit depth buffer
    case GLUT_WINDOW_STENCIL_SIZE:
    case GLUT_WINDOW_ACCUM_RED_SIZE: case GLUT_WINDOW_ACCUM_GREEN_SIZE:
    case GLUT_WINDOW_ACCUM_BLUE_SIZE: case GLUT_WINDOW_ACCUM_ALPHA_SIZE: return 0;
    case GLUT_WINDOW_DOUBLEBUFFER: return (mode & GLUT_DOUBLE) ? 1 : 0;
    case GLUT_WINDOW_RGBA: return 1;
    case GLUT_WINDOW_PARENT: case GLUT_WINDOW_NUM_CHILDREN: case GLUT_WINDOW_COLORMAP_SIZE: return 0;
    case GLUT_WINDOW_NUM_SAMPLES: case GLUT_WINDOW_STEREO: case GLUT_WINDOW_SRGB: return 0;
    case GLUT_WINDOW_CURSOR: return w->cursor;
    case GLUT_WINDOW_FORMAT_ID: return 0;
    case GLUT_FULL_SCREEN: return w->fullscreen;
    default:
      warning("glutGet(): missing enum handle %d", int(what));
      return -1;
  }
}

int glutDeviceGet(GLenum what) {
  State& s = state();
  switch (what) {
    case GLUT_HAS_KEYBOARD: case GLUT_HAS_MOUSE: return 1;
    case GLUT_NUM_MOUSE_BUTTONS: return 3;
    case GLUT_HAS_SPACEBALL: case GLUT_HAS_DIAL_AND_BUTTON_BOX: case GLUT_HAS_TABLET:
    case GLUT_NUM_SPACEBALL_BUTTONS: case GLUT_NUM_BUTTON_BOX_BUTTONS: case GLUT_NUM_DIALS:
    case GLUT_NUM_TABLET_BUTTONS: case GLUT_HAS_JOYSTICK: case GLUT_OWNS_JOYSTICK:
    case GLUT_JOYSTICK_BUTTONS: case GLUT_JOYSTICK_AXES: case GLUT_JOYSTICK_POLL_RATE: return 0;
    case GLUT_DEVICE_IGNORE_KEY_REPEAT: return s.ignore_key_repeat;
    case GLUT_DEVICE_KEY_REPEAT: return s.key_repeat;
    default:
      warning("glutDeviceGet(): missing enum handle %d", int(what));
      return -1;
  }
}

int glutLayerGet(GLenum what) {
  switch (what) {
    case GLUT_OVERLAY_POSSIBLE: case GLUT_HAS_OVERLAY: case GLUT_TRANSPARENT_INDEX: case GLUT_NORMAL_DAMAGED: return 0;
    case GLUT_LAYER_IN_USE: return GLUT_NORMAL;
    case GLUT_OVERLAY_DAMAGED: return -1;
    default:
      warning("glutLayerGet(): missing enum handle %d", int(what));
      return -1;
  }
}

// Only during an input callback, as in freeglut (which warns and answers 0 elsewhere).
int glutGetModifiers(void) {
  if (state().modifiers < 0) {
    warning("glutGetModifiers() called outside an input callback");
    return 0;
  }
  return state().modifiers;
}

// Whole-word search of GL_EXTENSIONS of the current window's GL.
int glutExtensionSupported(const char* extension) {
  if (!state().current) error(" ERROR:  Function <%s> called with no current window defined.", "glutExtensionSupported");
  if (!extension || !*extension || std::strchr(extension, ' ')) return 0;
  const char* list = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  if (!list) return 0;
  const size_t n = std::strlen(extension);
  for (const char* p = list; (p = std::strstr(p, extension)) != nullptr; p += n)
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return 1;
  return 0;
}

// glut* names from this library; gl* names from our libGL, through its ffcompat_get_proc_address
// (which answers for the calls it supports), else as exported symbols.
GLUTproc glutGetProcAddress(const char* procName) {
  if (!procName) return nullptr;
  if (std::strncmp(procName, "glut", 4) == 0) {
    Dl_info self{};
    if (dladdr(reinterpret_cast<void*>(&glutGetProcAddress), &self) && self.dli_fname) {
      if (void* h = dlopen(self.dli_fname, RTLD_LAZY | RTLD_NOLOAD)) {
        void* f = dlsym(h, procName);
        dlclose(h);
        if (f) return reinterpret_cast<GLUTproc>(f);
      }
    }
    return nullptr;
  }
  using GetProc = void* (*)(const char*);
  static GetProc get = reinterpret_cast<GetProc>(dlsym(RTLD_DEFAULT, "ffcompat_get_proc_address"));
  if (get) return reinterpret_cast<GLUTproc>(get(procName));
  return reinterpret_cast<GLUTproc>(dlsym(RTLD_DEFAULT, procName));
}

}  // extern "C"
