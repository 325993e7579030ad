// Windows: each one an ffcompat_surface of libGL.so.1, made current by glutSetWindow.
#include <cstdio>
#include <cstdlib>

#include "../gl/ffcompat_surface.h"
#include "glut_state.h"

namespace ffc::glut {

Window* window_by_id(int id) {
  auto it = state().windows.find(id);
  return it == state().windows.end() ? nullptr : it->second.get();
}

Window& current_window(const char* caller) {
  require_init(caller);
  if (!state().current) error(" ERROR:  Function <%s> called with no current window defined.", caller);
  return *state().current;
}

void make_current(Window* w) {
  state().current = w;
  if (w && w->surface) ffcompat_surface_make_current(w->surface);
}

// The screen: the forced window size when one is given (so that glutFullScreen keeps the frames'
// size), otherwise 1024x768.
void screen_size(int* w, int* h) {
  const State& s = state();
  *w = s.forced_size ? s.forced_width : 1024;
  *h = s.forced_size ? s.forced_height : 768;
}

namespace {

// Asks for a new size; the loop tells the program at its next turn (freeglut's GLUT_SIZE_WORK).
void request_size(Window& w, int width, int height) {
  if (state().forced_size) return;  // FFCOMPAT_RUN_SIZE pins every window's size
  if (width <= 0 || height <= 0) return;
  w.wanted_width = width, w.wanted_height = height, w.reshape_pending = true;
}

int create(const char* title, int x, int y, int width, int height) {
  State& s = state();
  auto w = std::make_unique<Window>();
  w->id = s.next_window_id++;
  w->title = title ? title : "";
  w->mode = s.init_mode;
  if (s.forced_size) width = s.forced_width, height = s.forced_height;
  w->width = width > 0 ? width : 300;
  w->height = height > 0 ? height : 300;
  w->x = x >= 0 ? x : 0;
  w->y = y >= 0 ? y : 0;
  w->surface = ffcompat_surface_create(w->width, w->height);
  if (!w->surface) error("Unable to create a %dx%d window (ffcompat_surface_create failed)", w->width, w->height);
  Window* raw = w.get();
  s.windows[raw->id] = std::move(w);
  make_current(raw);
  if (windowed()) windowed_open(*raw);
  return raw->id;
}

}  // namespace

}  // namespace ffc::glut

using namespace ffc::glut;

extern "C" {

int glutCreateWindow(const char* title) {
  require_init("glutCreateWindow");
  const State& s = state();
  return create(title, s.init_x, s.init_y, s.init_width, s.init_height);
}

// A subwindow is drawn as a window of its own: there is no compositing of children into their
// parent here, so its frames are written beside the main window's (frame names carry its id).
int glutCreateSubWindow(int window, int x, int y, int width, int height) {
  require_init("glutCreateSubWindow");
  if (!window_by_id(window)) error(" ERROR:  Function <%s> called with invalid window %d", "glutCreateSubWindow", window);
  say_once("glutCreateSubWindow", "the subwindow is drawn as a separate picture, not inside its parent");
  return create("", x, y, width, height);
}

void glutDestroyWindow(int window) {
  State& s = state();
  Window* w = window_by_id(window);
  if (!w) return;
  if (w->close) {
    Window* saved = s.current;
    make_current(w);
    w->close();
    if (saved != w) make_current(saved);
  }
  if (windowed() && w->id == 1) windowed_close();
  ffcompat_surface_destroy(w->surface);
  if (s.current == w) s.current = nullptr;
  s.windows.erase(window);
}

void glutSetWindow(int window) {
  require_init("glutSetWindow");
  Window* w = window_by_id(window);
  if (!w) {
    error(" ERROR:  Function <%s> called with invalid window %d", "glutSetWindow", window);
  }
  make_current(w);
}

int glutGetWindow(void) {
  require_init("glutGetWindow");
  return state().current ? state().current->id : 0;
}

void glutSetWindowTitle(const char* title) {
  Window& w = current_window("glutSetWindowTitle");
  w.title = title ? title : "";
  if (windowed()) windowed_title(w);
}

void glutSetIconTitle(const char* title) {
  (void)title;
  current_window("glutSetIconTitle");
}

void glutReshapeWindow(int width, int height) {
  Window& w = current_window("glutReshapeWindow");
  w.fullscreen = false;
  request_size(w, width, height);
}

void glutPositionWindow(int x, int y) {
  Window& w = current_window("glutPositionWindow");
  w.fullscreen = false;
  if ((x != w.x || y != w.y) && w.position) {
    w.x = x, w.y = y;
    w.position(x, y);
  }
  w.x = x, w.y = y;
}

void glutShowWindow(void) {
  Window& w = current_window("glutShowWindow");
  if (!w.visible) {
    w.visible = true, w.redisplay = true;
    if (w.window_status) w.window_status(GLUT_FULLY_RETAINED);
    else if (w.visibility) w.visibility(GLUT_VISIBLE);
  }
}

void glutHideWindow(void) {
  Window& w = current_window("glutHideWindow");
  if (w.visible) {
    w.visible = false;
    if (w.window_status) w.window_status(GLUT_HIDDEN);
    else if (w.visibility) w.visibility(GLUT_NOT_VISIBLE);
  }
}

void glutIconifyWindow(void) {
  glutHideWindow();
}

void glutPushWindow(void) { current_window("glutPushWindow"); }
void glutPopWindow(void) { current_window("glutPopWindow"); }

// Full screen: the window takes the screen's size (headless: the forced size, so the frames keep
// theirs, or 1024x768).
void glutFullScreen(void) {
  Window& w = current_window("glutFullScreen");
  if (w.fullscreen) return;
  int sw = 0, sh = 0;
  screen_size(&sw, &sh);
  w.fullscreen = true;
  request_size(w, sw, sh);
}

void glutLeaveFullScreen(void) {
  Window& w = current_window("glutLeaveFullScreen");
  w.fullscreen = false;
}

void glutFullScreenToggle(void) {
  Window& w = current_window("glutFullScreenToggle");
  if (w.fullscreen) glutLeaveFullScreen();
  else glutFullScreen();
}

void glutPostRedisplay(void) {
  current_window("glutPostRedisplay").redisplay = true;
}

void glutPostWindowRedisplay(int window) {
  Window* w = window_by_id(window);
  if (!w) error(" ERROR:  Function <%s> called with invalid window %d", "glutPostWindowRedisplay", window);
  w->redisplay = true;
}

// Double-buffered windows show a frame here; a single-buffered one shows what it drew when its
// display callback returns (loop.cpp), so a glutSwapBuffers there only finishes the drawing.
void glutSwapBuffers(void) {
  Window& w = current_window("glutSwapBuffers");
  if (w.mode & GLUT_DOUBLE) frame_shown(w);
}

void glutSetCursor(int cursor) {
  current_window("glutSetCursor").cursor = cursor;
}

void glutWarpPointer(int x, int y) {
  current_window("glutWarpPointer");
  state().mouse_x = x, state().mouse_y = y;
}

void glutSetWindowData(void* data) { current_window("glutSetWindowData").user_data = data; }
void* glutGetWindowData(void) { return current_window("glutGetWindowData").user_data; }

// Key repeat: a scripted key is one press and one release, so there is nothing to repeat; the
// settings are kept for glutGet/glutDeviceGet.
void glutIgnoreKeyRepeat(int ignore) { state().ignore_key_repeat = ignore != 0; }
void glutSetKeyRepeat(int repeatMode) { state().key_repeat = repeatMode; }

}  // extern "C"
