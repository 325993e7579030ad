// The real window of windowed runs (`ffcompat run --window`, or a program started with a DISPLAY
// and no FFCOMPAT_RUN_OUT): GLFW shows each frame the program's surface made, and its input goes
// to the program's GLUT callbacks.
//
// Our libGL.so.1 is the process's libGL, so the window must not draw through GLX or plain gl*
// symbols (they would be ours): GLFW makes an EGL context for OpenGL ES 2, and the frame is drawn
// as a texture through function pointers from glfwGetProcAddress.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cctype>
#include <cstdio>
#include <cstring>

#include "../gl/ffcompat_surface.h"
#include "glut_state.h"

namespace ffc::glut {

namespace {

// The few OpenGL ES 2 entry points the window needs, by pointer.
struct Es2 {
  unsigned (*CreateShader)(unsigned);
  void (*ShaderSource)(unsigned, int, const char* const*, const int*);
  void (*CompileShader)(unsigned);
  unsigned (*CreateProgram)();
  void (*AttachShader)(unsigned, unsigned);
  void (*BindAttribLocation)(unsigned, unsigned, const char*);
  void (*LinkProgram)(unsigned);
  void (*UseProgram)(unsigned);
  void (*GenTextures)(int, unsigned*);
  void (*BindTexture)(unsigned, unsigned);
  void (*TexParameteri)(unsigned, unsigned, int);
  void (*TexImage2D)(unsigned, int, int, int, int, int, unsigned, unsigned, const void*);
  void (*PixelStorei)(unsigned, int);
  void (*VertexAttribPointer)(unsigned, int, unsigned, unsigned char, int, const void*);
  void (*EnableVertexAttribArray)(unsigned);
  void (*DrawArrays)(unsigned, int, int);
  void (*Viewport)(int, int, int, int);
  void (*ClearColor)(float, float, float, float);
  void (*Clear)(unsigned);
};

// GLES 2 enum values (from the ES 2 specification's tables)
constexpr unsigned kVertexShader = 0x8B31, kFragmentShader = 0x8B30, kTexture2D = 0x0DE1, kRgba = 0x1908,
                   kUnsignedByte = 0x1401, kFloat = 0x1406, kTriangleStrip = 0x0005, kLinear = 0x2601,
                   kMinFilter = 0x2801, kMagFilter = 0x2800, kWrapS = 0x2802, kWrapT = 0x2803,
                   kClampToEdge = 0x812F, kUnpackAlignment = 0x0CF5, kColorBufferBit = 0x4000;

struct Shown {
  GLFWwindow* window = nullptr;
  int glut_id = 0;
  Es2 gl{};
  unsigned program = 0, texture = 0;
  bool buttons[8] = {};
  int modifiers = 0;
};

Shown& shown() {
  static Shown s;
  return s;
}

template <typename F>
void load(F& f, const char* name) {
  f = reinterpret_cast<F>(glfwGetProcAddress(name));
  if (!f) error("windowed run: OpenGL ES 2 has no %s", name);
}

void load_es2(Es2& g) {
  load(g.CreateShader, "glCreateShader");
  load(g.ShaderSource, "glShaderSource");
  load(g.CompileShader, "glCompileShader");
  load(g.CreateProgram, "glCreateProgram");
  load(g.AttachShader, "glAttachShader");
  load(g.BindAttribLocation, "glBindAttribLocation");
  load(g.LinkProgram, "glLinkProgram");
  load(g.UseProgram, "glUseProgram");
  load(g.GenTextures, "glGenTextures");
  load(g.BindTexture, "glBindTexture");
  load(g.TexParameteri, "glTexParameteri");
  load(g.TexImage2D, "glTexImage2D");
  load(g.PixelStorei, "glPixelStorei");
  load(g.VertexAttribPointer, "glVertexAttribPointer");
  load(g.EnableVertexAttribArray, "glEnableVertexAttribArray");
  load(g.DrawArrays, "glDrawArrays");
  load(g.Viewport, "glViewport");
  load(g.ClearColor, "glClearColor");
  load(g.Clear, "glClear");
}

unsigned shader(const Es2& g, unsigned kind, const char* text) {
  const unsigned s = g.CreateShader(kind);
  g.ShaderSource(s, 1, &text, nullptr);
  g.CompileShader(s);
  return s;
}

int glfw_modifiers(int mods) {
  return ((mods & GLFW_MOD_SHIFT) ? GLUT_ACTIVE_SHIFT : 0) | ((mods & GLFW_MOD_CONTROL) ? GLUT_ACTIVE_CTRL : 0) |
         ((mods & GLFW_MOD_ALT) ? GLUT_ACTIVE_ALT : 0);
}

Window* glut_window() { return window_by_id(shown().glut_id); }

void send(Event e) {
  if (Window* w = glut_window()) deliver(*w, e);
}

// A GLFW key as GLUT sees it: a special key, or the character the keyboard layout gives.
bool key_event(int key, int scancode, int mods, Event& e) {
  static const struct { int glfw, glut; } specials[] = {
      {GLFW_KEY_UP, GLUT_KEY_UP}, {GLFW_KEY_DOWN, GLUT_KEY_DOWN}, {GLFW_KEY_LEFT, GLUT_KEY_LEFT},
      {GLFW_KEY_RIGHT, GLUT_KEY_RIGHT}, {GLFW_KEY_PAGE_UP, GLUT_KEY_PAGE_UP},
      {GLFW_KEY_PAGE_DOWN, GLUT_KEY_PAGE_DOWN}, {GLFW_KEY_HOME, GLUT_KEY_HOME}, {GLFW_KEY_END, GLUT_KEY_END},
      {GLFW_KEY_INSERT, GLUT_KEY_INSERT}};
  e.modifiers = glfw_modifiers(mods);
  for (const auto& s : specials)
    if (key == s.glfw) return e.kind = Event::Special, e.code = s.glut, true;
  if (key >= GLFW_KEY_F1 && key <= GLFW_KEY_F12) return e.kind = Event::Special, e.code = GLUT_KEY_F1 + key - GLFW_KEY_F1, true;
  e.kind = Event::Key;
  switch (key) {
    case GLFW_KEY_ESCAPE: e.code = 27; return true;
    case GLFW_KEY_ENTER: case GLFW_KEY_KP_ENTER: e.code = 13; return true;
    case GLFW_KEY_TAB: e.code = 9; return true;
    case GLFW_KEY_BACKSPACE: e.code = 8; return true;
    case GLFW_KEY_DELETE: e.code = 127; return true;
    case GLFW_KEY_SPACE: e.code = ' '; return true;
    default: break;
  }
  const char* name = glfwGetKeyName(key, scancode);
  if (!name || std::strlen(name) != 1) return false;
  int c = static_cast<unsigned char>(name[0]);
  if (std::isalpha(c)) {
    if (mods & GLFW_MOD_CONTROL) c = std::toupper(c) - '@';
    else if (mods & GLFW_MOD_SHIFT) c = std::toupper(c);
  }
  e.code = c;
  return true;
}

void on_key(GLFWwindow*, int key, int scancode, int action, int mods) {
  Event e;
  if (action == GLFW_REPEAT && state().ignore_key_repeat) return;
  if (!key_event(key, scancode, mods, e)) return;
  e.phase = action == GLFW_RELEASE ? Event::Release : Event::Press;
  send(e);
}

void on_button(GLFWwindow* win, int button, int action, int mods) {
  double x = 0, y = 0;
  glfwGetCursorPos(win, &x, &y);
  Event e;
  e.kind = Event::Click;
  e.phase = action == GLFW_PRESS ? Event::Press : Event::Release;
  e.button = button == GLFW_MOUSE_BUTTON_LEFT ? GLUT_LEFT_BUTTON
             : button == GLFW_MOUSE_BUTTON_RIGHT ? GLUT_RIGHT_BUTTON
             : button == GLFW_MOUSE_BUTTON_MIDDLE ? GLUT_MIDDLE_BUTTON : button;
  e.x = int(x), e.y = int(y), e.modifiers = glfw_modifiers(mods);
  if (button >= 0 && button < 8) shown().buttons[button] = action == GLFW_PRESS;
  send(e);
}

void on_cursor(GLFWwindow*, double x, double y) {
  bool down = false;
  for (bool b : shown().buttons) down |= b;
  Event e;
  e.kind = down ? Event::Motion : Event::Move;
  e.x = int(x), e.y = int(y);
  send(e);
}

void on_scroll(GLFWwindow* win, double, double dy) {
  if (dy == 0) return;
  double x = 0, y = 0;
  glfwGetCursorPos(win, &x, &y);
  Event e;
  e.kind = Event::Click;
  e.button = dy > 0 ? 3 : 4;
  e.x = int(x), e.y = int(y);
  send(e);
}

void on_enter(GLFWwindow*, int entered) {
  Window* w = glut_window();
  if (w && w->entry) {
    Window* saved = state().current;
    make_current(w);
    w->entry(entered ? GLUT_ENTERED : GLUT_LEFT);
    if (saved && window_by_id(saved->id)) make_current(saved);
  }
}

}  // namespace

void windowed_open(Window& w) {
  Shown& s = shown();
  if (s.window) return;  // one real window: the first; others are drawn but not shown
  if (!glfwInit()) error("windowed run: GLFW could not start (is DISPLAY set? try without --window)");
  glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
  glfwWindowHint(GLFW_CONTEXT_CREATION_API, GLFW_EGL_CONTEXT_API);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 2);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
  s.window = glfwCreateWindow(w.width, w.height, w.title.c_str(), nullptr, nullptr);
  if (!s.window) error("windowed run: GLFW could not open an EGL / OpenGL ES 2 window");
  s.glut_id = w.id;
  ffcompat_surface_make_current(nullptr);  // see windowed_show
  glfwMakeContextCurrent(s.window);
  load_es2(s.gl);
  const Es2& g = s.gl;
  const char* vs =
      "attribute vec2 p; varying vec2 t;\n"
      "void main() { t = vec2(p.x * 0.5 + 0.5, 0.5 - p.y * 0.5); gl_Position = vec4(p, 0.0, 1.0); }\n";
  const char* fs =
      "precision mediump float; varying vec2 t; uniform sampler2D image;\n"
      "void main() { gl_FragColor = vec4(texture2D(image, t).rgb, 1.0); }\n";
  s.program = g.CreateProgram();
  g.AttachShader(s.program, shader(g, kVertexShader, vs));
  g.AttachShader(s.program, shader(g, kFragmentShader, fs));
  g.BindAttribLocation(s.program, 0, "p");
  g.LinkProgram(s.program);
  g.GenTextures(1, &s.texture);
  g.BindTexture(kTexture2D, s.texture);
  g.TexParameteri(kTexture2D, kMinFilter, int(kLinear));
  g.TexParameteri(kTexture2D, kMagFilter, int(kLinear));
  g.TexParameteri(kTexture2D, kWrapS, int(kClampToEdge));
  g.TexParameteri(kTexture2D, kWrapT, int(kClampToEdge));
  glfwSetKeyCallback(s.window, on_key);
  glfwSetMouseButtonCallback(s.window, on_button);
  glfwSetCursorPosCallback(s.window, on_cursor);
  glfwSetScrollCallback(s.window, on_scroll);
  glfwSetCursorEnterCallback(s.window, on_enter);
  glfwMakeContextCurrent(nullptr);
  if (w.surface) ffcompat_surface_make_current(w.surface);
}

void windowed_show(Window& w, const unsigned char* rgba) {
  Shown& s = shown();
  if (!s.window) return;
  // The mesa backend's OSMesa and GLFW's EGL share Mesa's record of the current context (one
  // libglapi): EGL would take OSMesa's context for its own and crash (measured). So no surface is
  // current while the window draws, and the EGL context is released before the surface returns.
  ffcompat_surface_make_current(nullptr);
  glfwMakeContextCurrent(s.window);
  const Es2& g = s.gl;
  int ww = 0, wh = 0, fw = 0, fh = 0;
  glfwGetWindowSize(s.window, &ww, &wh);
  if (ww != w.width || wh != w.height) glfwSetWindowSize(s.window, w.width, w.height);  // glutReshapeWindow
  glfwGetFramebufferSize(s.window, &fw, &fh);
  g.Viewport(0, 0, fw, fh);
  g.ClearColor(0, 0, 0, 1);
  g.Clear(kColorBufferBit);
  g.UseProgram(s.program);
  g.BindTexture(kTexture2D, s.texture);
  g.PixelStorei(kUnpackAlignment, 1);
  g.TexImage2D(kTexture2D, 0, int(kRgba), w.width, w.height, 0, kRgba, kUnsignedByte, rgba);
  static const float quad[] = {-1, -1, 1, -1, -1, 1, 1, 1};
  g.VertexAttribPointer(0, 2, kFloat, 0, 0, quad);
  g.EnableVertexAttribArray(0);
  g.DrawArrays(kTriangleStrip, 0, 4);
  glfwSwapBuffers(s.window);
  glfwMakeContextCurrent(nullptr);
  if (Window* current = state().current) ffcompat_surface_make_current(current->surface);
}

void windowed_poll() {
  if (shown().window) glfwPollEvents();
}

void windowed_wait(long long ms) {
  if (!shown().window) return;
  glfwWaitEventsTimeout(ms < 0 ? 0.1 : ms / 1000.0);
}

bool windowed_should_close() {
  return shown().window && glfwWindowShouldClose(shown().window);
}

void windowed_title(Window& w) {
  if (shown().window && w.id == shown().glut_id) glfwSetWindowTitle(shown().window, w.title.c_str());
}

void windowed_close() {
  Shown& s = shown();
  if (!s.window) return;
  glfwDestroyWindow(s.window);
  s.window = nullptr;
  glfwTerminate();
}

}  // namespace ffc::glut
