// glutInit and the glutInit* / glutSetOption family: what the next window and the loop will use.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <set>
#include <string>

#include "font.h"
#include "glut_state.h"

namespace ffc::glut {

State& state() {
  static State s;
  return s;
}

namespace {
// What a geometry string gave (the meaning of X's XParseGeometry flags).
enum { XValue = 1, YValue = 2, WidthValue = 4, HeightValue = 8, XNegative = 16, YNegative = 32 };

// freeglut prefixes its messages with the program's name; ours say "ffcompat glut" too, so that a
// user reading stderr knows which GLUT spoke.
void vreport(const char* fmt, va_list ap) {
  std::fprintf(stderr, "freeglut (ffcompat) (%s): ", state().program_name.empty() ? "?" : state().program_name.c_str());
  std::vfprintf(stderr, fmt, ap);
  std::fprintf(stderr, "\n");
}

// "WxH+X+Y" and its parts, as X's geometry strings (-geometry): width and height, then signed
// offsets. Returns the XParseGeometry flags of what was given.
int parse_geometry(const char* text, int* x, int* y, unsigned* w, unsigned* h) {
  int flags = 0;
  const char* p = text;
  if (*p == '=') ++p;
  char* end = nullptr;
  if (*p != '+' && *p != '-' && *p != 'x') {
    const unsigned long v = std::strtoul(p, &end, 10);
    if (end == p) return 0;
    *w = unsigned(v), flags |= WidthValue, p = end;
  }
  if (*p == 'x' || *p == 'X') {
    ++p;
    const unsigned long v = std::strtoul(p, &end, 10);
    if (end == p) return 0;
    *h = unsigned(v), flags |= HeightValue, p = end;
  }
  if (*p == '+' || *p == '-') {
    const bool neg = *p == '-';
    const long v = std::strtol(p + 1, &end, 10);
    if (end == p + 1) return 0;
    *x = int(neg ? -v : v), flags |= XValue | (neg ? XNegative : 0), p = end;
    if (*p == '+' || *p == '-') {
      const bool negy = *p == '-';
      const long vy = std::strtol(p + 1, &end, 10);
      if (end == p + 1) return 0;
      *y = int(negy ? -vy : vy), flags |= YValue | (negy ? YNegative : 0), p = end;
    }
  }
  return *p ? 0 : flags;
}
}  // namespace

namespace {
// Through the program's glutInitErrorFunc / glutInitWarningFunc callback when it set one (plain or
// with user data), else on stderr.
void vsay(void (*func)(const char*, va_list, void*), bool plain, void* data, const char* fmt, va_list ap) {
  if (!func) vreport(fmt, ap);
  else if (plain) reinterpret_cast<void (*)(const char*, va_list)>(reinterpret_cast<void*>(func))(fmt, ap);
  else func(fmt, ap, data);
}
}  // namespace

void error(const char* fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  const State& s = state();
  vsay(s.error_func, s.error_plain, s.error_data, fmt, ap);
  va_end(ap);
  std::exit(1);  // freeglut exits after the error callback returns too
}

void warning(const char* fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  const State& s = state();
  vsay(s.warning_func, s.warning_plain, s.warning_data, fmt, ap);
  va_end(ap);
}

void say_once(const char* name, const char* why) {
  static std::mutex m;
  static std::set<std::string> said;
  std::lock_guard<std::mutex> lock(m);
  if (!said.insert(name).second) return;
  std::fprintf(stderr, "ffcompat glut: %s is not supported here%s%s\n", name, why ? ": " : "", why ? why : "");
}

void require_init(const char* caller) {
  if (!state().initialised)
    error(" ERROR:  Function <%s> called without first calling 'glutInit'.", caller);
}

}  // namespace ffc::glut

using namespace ffc::glut;

extern "C" {

void glutInit(int* argcp, char** argv) {
  State& s = state();
  if (s.initialised) error("illegal glutInit() reinitialization attempt");
  s.initialised = true;
  if (argcp && argv && *argcp > 0 && argv[0]) {
    s.program_name = argv[0];
  }
  reset_wall_clock();
  // GLUT's own options are taken out of argv, the rest close up (freeglut does the same, and
  // complains about a missing value the same way).
  if (argcp && argv) {
    int out = 1;
    const int argc = *argcp;
    for (int i = 1; i < argc; ++i) {
      const char* a = argv[i];
      if (!std::strcmp(a, "-display") || !std::strcmp(a, "-geometry")) {
        if (i + 1 >= argc) error("%s parameter must be followed by %s", a, a[1] == 'd' ? "display name" : "geometry spec");
        if (a[1] == 'g') {
          int x = s.init_x, y = s.init_y;
          unsigned w = unsigned(s.init_width), h = unsigned(s.init_height);
          const int flags = parse_geometry(argv[i + 1], &x, &y, &w, &h);
          if ((flags & (WidthValue | HeightValue)) == (WidthValue | HeightValue)) s.init_width = int(w), s.init_height = int(h);
          if (flags & XValue) s.init_x = x;
          if (flags & YValue) s.init_y = y;
        }
        ++i;  // -display is taken and ignored: there is no X display to choose
      } else if (!std::strcmp(a, "-direct")) {
        s.direct_rendering = GLUT_FORCE_DIRECT_CONTEXT;
      } else if (!std::strcmp(a, "-indirect")) {
        s.direct_rendering = GLUT_FORCE_INDIRECT_CONTEXT;
      } else if (!std::strcmp(a, "-iconic") || !std::strcmp(a, "-gldebug") || !std::strcmp(a, "-sync")) {
        // taken: no icon, and errors are reported by our libGL anyway
      } else {
        argv[out++] = argv[i];
      }
    }
    for (int i = out; i < argc; ++i) argv[i] = nullptr;
    *argcp = out;
  }
  if (const char* size = std::getenv("FFCOMPAT_RUN_SIZE")) {
    int w = 0, h = 0;
    char tail = 0;
    if (std::sscanf(size, "%dx%d%c", &w, &h, &tail) == 2 && w > 0 && h > 0 && w <= 16384 && h <= 16384) {
      s.forced_size = true, s.forced_width = w, s.forced_height = h;
    } else {
      std::fprintf(stderr, "ffcompat glut: FFCOMPAT_RUN_SIZE='%s' is not WxH (e.g. 200x200); ignored\n", size);
    }
  }
}

void glutInitWindowPosition(int x, int y) {
  state().init_x = x, state().init_y = y;
}

void glutInitWindowSize(int width, int height) {
  // freeglut keeps a non-positive size as "let the window system choose": 300x300 here.
  state().init_width = width > 0 ? width : 300;
  state().init_height = height > 0 ? height : 300;
}

void glutInitDisplayMode(unsigned int mode) {
  state().init_mode = mode;
}

void glutInitDisplayString(const char* displayMode) {
  (void)displayMode;
  say_once("glutInitDisplayString", "the window keeps its RGBA, 24-bit depth format");
}

void glutSetOption(GLenum what, int value) {
  State& s = state();
  switch (what) {
    case GLUT_INIT_WINDOW_X: s.init_x = value; break;
    case GLUT_INIT_WINDOW_Y: s.init_y = value; break;
    case GLUT_INIT_WINDOW_WIDTH: s.init_width = value; break;
    case GLUT_INIT_WINDOW_HEIGHT: s.init_height = value; break;
    case GLUT_INIT_DISPLAY_MODE: s.init_mode = unsigned(value); break;
    case GLUT_ACTION_ON_WINDOW_CLOSE: s.action_on_window_close = value; break;
    case GLUT_RENDERING_CONTEXT: s.rendering_context = value; break;
    case GLUT_DIRECT_RENDERING: s.direct_rendering = value; break;
    case GLUT_WINDOW_CURSOR:
      if (s.current) s.current->cursor = value;
      break;
    case GLUT_AUX: case GLUT_MULTISAMPLE: break;  // no such buffers: accepted, as freeglut does
    case GLUT_SKIP_STALE_MOTION_EVENTS: s.skip_stale_motion = value != 0; break;
    case GLUT_GEOMETRY_VISUALIZE_NORMALS: s.visualize_normals = value != 0; break;
    case GLUT_STROKE_FONT_DRAW_JOIN_DOTS: stroke_font_draw_join_dots = value != 0; break;
    default: warning("glutSetOption(): missing enum handle %d", int(what));
  }
}

void glutInitContextVersion(int majorVersion, int minorVersion) {
  state().context_major = majorVersion, state().context_minor = minorVersion;
}
void glutInitContextFlags(int flags) { state().context_flags = flags; }
void glutInitContextProfile(int profile) { state().context_profile = profile; }

void glutInitErrorFunc(void (*callback)(const char* fmt, va_list ap)) {
  state().error_func = reinterpret_cast<void (*)(const char*, va_list, void*)>(reinterpret_cast<void*>(callback));
  state().error_plain = true, state().error_data = nullptr;
}
void glutInitErrorFuncUcall(void (*callback)(const char* fmt, va_list ap, void* user_data), void* user_data) {
  state().error_func = callback, state().error_plain = false, state().error_data = user_data;
}
void glutInitWarningFunc(void (*callback)(const char* fmt, va_list ap)) {
  state().warning_func = reinterpret_cast<void (*)(const char*, va_list, void*)>(reinterpret_cast<void*>(callback));
  state().warning_plain = true, state().warning_data = nullptr;
}
void glutInitWarningFuncUcall(void (*callback)(const char* fmt, va_list ap, void* user_data), void* user_data) {
  state().warning_func = callback, state().warning_plain = false, state().warning_data = user_data;
}

// Ends the GLUT session: windows go, and glutInit may be called again (freeglut's glutExit).
void glutExit(void) {
  State& s = state();
  while (!s.windows.empty()) glutDestroyWindow(s.windows.begin()->first);
  s.timers.clear();
  s.idle = {};
  s.initialised = false;
}

}  // extern "C"
