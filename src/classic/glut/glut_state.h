// The state of our GLUT runtime: the windows, their callbacks, the global callbacks and options.
// One process-wide instance (glut::state()); GLUT is single-threaded by contract.
#pragma once
#include <GL/freeglut.h>
#include <GL/freeglut_ucall.h>

#include <cstdarg>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "glut_script.h"

struct ffcompat_surface;

namespace ffc::glut {

// A callback registered either plainly (glutDisplayFunc) or with user data (glutDisplayFuncUcall),
// called the same way: freeglut keeps one form too, the plain one through a trampoline.
template <typename... A>
struct Callback {
  void (*plain)(A...) = nullptr;
  void (*ucall)(A..., void*) = nullptr;
  void* data = nullptr;
  void set(void (*f)(A...)) { plain = f, ucall = nullptr, data = nullptr; }
  void set(void (*f)(A..., void*), void* d) { plain = nullptr, ucall = f, data = d; }
  explicit operator bool() const { return plain || ucall; }
  void operator()(A... a) const {
    if (ucall)
      ucall(a..., data);
    else if (plain)
      plain(a...);
  }
};

struct Window {
  int id = 0;
  std::string title;
  int x = 0, y = 0, width = 0, height = 0;
  unsigned mode = 0;  // the display mode it was created with
  ffcompat_surface* surface = nullptr;
  void* user_data = nullptr;  // glutSetWindowData
  int cursor = GLUT_CURSOR_INHERIT;
  bool visible = true;
  bool fullscreen = false;
  bool init_work = true;       // the first turn of the loop tells position, size, visibility
  bool redisplay = false;      // glutPostRedisplay: display at the next turn
  bool reshape_pending = false;  // glutReshapeWindow: the new size is told at the next turn
  int wanted_width = 0, wanted_height = 0;
  int frames = 0;  // frames this window has shown
  Callback<> display, overlay_display, close, wm_close, init_context;
  Callback<int, int> reshape, position, motion, passive_motion;
  Callback<unsigned char, int, int> keyboard, keyboard_up;
  Callback<int, int, int> special, special_up;
  Callback<int, int, int, int> mouse, mouse_wheel;
  Callback<int> visibility, window_status, entry;
};

struct State {
  bool initialised = false;
  std::string program_name;
  // glutInit* values, used by the next glutCreateWindow
  int init_x = -1, init_y = -1, init_width = 300, init_height = 300;
  unsigned init_mode = GLUT_RGBA | GLUT_SINGLE | GLUT_DEPTH;
  bool forced_size = false;  // FFCOMPAT_RUN_SIZE: every window takes that size
  int forced_width = 0, forced_height = 0;
  // glutSetOption
  int action_on_window_close = GLUT_ACTION_EXIT;
  int key_repeat = GLUT_KEY_REPEAT_DEFAULT;
  bool ignore_key_repeat = false;
  int rendering_context = GLUT_USE_CURRENT_CONTEXT;
  int direct_rendering = GLUT_TRY_DIRECT_CONTEXT;
  bool visualize_normals = false, skip_stale_motion = false;  // join dots: font.h
  int context_major = 1, context_minor = 0, context_flags = 0, context_profile = 0;
  int menu_font_unused = 0;
  // windows by id; ids start at 1 and are not reused
  std::map<int, std::unique_ptr<Window>> windows;
  int next_window_id = 1;
  Window* current = nullptr;
  // global callbacks
  Callback<> idle;
  Callback<int> app_status;
  void (*error_func)(const char*, va_list, void*) = nullptr;
  void* error_data = nullptr;
  bool error_plain = false;  // error_func holds a plain glutInitErrorFunc callback
  void (*warning_func)(const char*, va_list, void*) = nullptr;
  void* warning_data = nullptr;
  bool warning_plain = false;
  // timers, ordered by trigger time, then by registration
  struct Timer {
    long long trigger_ms;
    long long order;
    Callback<int> callback;
    int value;
  };
  std::vector<Timer> timers;
  long long timer_order = 0;
  // modifiers during an input callback, -1 outside one (freeglut warns then)
  int modifiers = -1;
  int mouse_x = 0, mouse_y = 0;  // the last pointer position, window coordinates
  bool running = false;          // inside glutMainLoop
  bool leave = false;            // glutLeaveMainLoop
};

State& state();

// Aborts with freeglut's wording (through glutInitErrorFunc's callback when one is set).
[[noreturn]] void error(const char* fmt, ...);
void warning(const char* fmt, ...);
// Says once on stderr that `name` does nothing here (and why, when `why` is given).
void say_once(const char* name, const char* why = nullptr);
// Initialises on first use, as freeglut requires glutInit first but some programs forget.
void require_init(const char* caller);

Window* window_by_id(int id);
// The current window, or an error naming the caller when there is none (as freeglut does).
Window& current_window(const char* caller);
void make_current(Window* w);
void screen_size(int* w, int* h);  // window.cpp

// The headless driver and the real window share these (loop.cpp).
bool headless();
// Elapsed milliseconds since glutInit: the simulated clock in headless runs, the wall clock
// otherwise.
long long elapsed_ms();
void reset_wall_clock();  // glutInit: GLUT_ELAPSED_TIME counts from here
// A frame became visible (glutSwapBuffers, or the end of a single-buffered display).
void frame_shown(Window& w);
// Runs one turn of the loop: input, timers, window work (glutMainLoopEvent's body).
void loop_turn();
// Writes frame `index` of window `id` as OUT/frame-NNN.png (window 1) or
// OUT/window-ID-frame-NNN.png (others), RGB (frames.cpp).
void write_frame(const std::string& out, int id, int index, int width, int height, const unsigned char* rgba);
// Input from a script or a real window, delivered to the current callbacks of `w`.
void deliver(Window& w, const Event& e);

// GLFW window mode (glfw_window.cpp): opens the window for `w`; shows a frame; reads input into
// the callbacks; true while the window is open.
bool windowed();
void windowed_open(Window& w);
void windowed_show(Window& w, const unsigned char* rgba_top_first);
void windowed_poll();
// Waits for input at most `ms` milliseconds (forever when negative).
void windowed_wait(long long ms);
bool windowed_should_close();
void windowed_close();
void windowed_title(Window& w);  // glutSetWindowTitle on the shown window

}  // namespace ffc::glut
