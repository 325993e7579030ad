// The glut*Func and glut*FuncUcall registrations: each stores the callback on the current window
// (or globally: idle, timers, app status). <GL/freeglut.h> declares every one, so the compiler
// checks each prototype against freeglut's.
#include "glut_state.h"

using namespace ffc::glut;

namespace {
template <typename C, typename F>
void set_on_current(const char* name, C Window::*member, F f) {
  (current_window(name).*member).set(f);
}
template <typename C, typename F>
void set_on_current(const char* name, C Window::*member, F f, void* data) {
  (current_window(name).*member).set(f, data);
}
}  // namespace

extern "C" {
void glutDisplayFunc(void (*callback)(void)) {
  if (!callback) error("Fatal error in program.  NULL display callback not permitted in GLUT 3.0+ or freeglut 2.0.1+");
  set_on_current("glutDisplayFunc", &Window::display, callback);
}
void glutDisplayFuncUcall(void (*callback)(void*), void* user_data) {
  if (!callback) error("Fatal error in program.  NULL display callback not permitted in GLUT 3.0+ or freeglut 2.0.1+");
  set_on_current("glutDisplayFuncUcall", &Window::display, callback, user_data);
}
void glutOverlayDisplayFunc(void (*callback)(void)) {
  set_on_current("glutOverlayDisplayFunc", &Window::overlay_display, callback);
}
void glutOverlayDisplayFuncUcall(void (*callback)(void*), void* user_data) {
  set_on_current("glutOverlayDisplayFuncUcall", &Window::overlay_display, callback, user_data);
}
void glutCloseFunc(void (*callback)(void)) {
  set_on_current("glutCloseFunc", &Window::close, callback);
}
void glutCloseFuncUcall(void (*callback)(void*), void* user_data) {
  set_on_current("glutCloseFuncUcall", &Window::close, callback, user_data);
}
void glutWMCloseFunc(void (*callback)(void)) {
  set_on_current("glutWMCloseFunc", &Window::wm_close, callback);
}
void glutWMCloseFuncUcall(void (*callback)(void*), void* user_data) {
  set_on_current("glutWMCloseFuncUcall", &Window::wm_close, callback, user_data);
}
void glutInitContextFunc(void (*callback)(void)) {
  set_on_current("glutInitContextFunc", &Window::init_context, callback);
}
void glutInitContextFuncUcall(void (*callback)(void*), void* user_data) {
  set_on_current("glutInitContextFuncUcall", &Window::init_context, callback, user_data);
}
void glutReshapeFunc(void (*callback)(int, int)) {
  set_on_current("glutReshapeFunc", &Window::reshape, callback);
}
void glutReshapeFuncUcall(void (*callback)(int, int, void*), void* user_data) {
  set_on_current("glutReshapeFuncUcall", &Window::reshape, callback, user_data);
}
void glutPositionFunc(void (*callback)(int, int)) {
  set_on_current("glutPositionFunc", &Window::position, callback);
}
void glutPositionFuncUcall(void (*callback)(int, int, void*), void* user_data) {
  set_on_current("glutPositionFuncUcall", &Window::position, callback, user_data);
}
void glutMotionFunc(void (*callback)(int, int)) {
  set_on_current("glutMotionFunc", &Window::motion, callback);
}
void glutMotionFuncUcall(void (*callback)(int, int, void*), void* user_data) {
  set_on_current("glutMotionFuncUcall", &Window::motion, callback, user_data);
}
void glutPassiveMotionFunc(void (*callback)(int, int)) {
  set_on_current("glutPassiveMotionFunc", &Window::passive_motion, callback);
}
void glutPassiveMotionFuncUcall(void (*callback)(int, int, void*), void* user_data) {
  set_on_current("glutPassiveMotionFuncUcall", &Window::passive_motion, callback, user_data);
}
void glutKeyboardFunc(void (*callback)(unsigned char, int, int)) {
  set_on_current("glutKeyboardFunc", &Window::keyboard, callback);
}
void glutKeyboardFuncUcall(void (*callback)(unsigned char, int, int, void*), void* user_data) {
  set_on_current("glutKeyboardFuncUcall", &Window::keyboard, callback, user_data);
}
void glutKeyboardUpFunc(void (*callback)(unsigned char, int, int)) {
  set_on_current("glutKeyboardUpFunc", &Window::keyboard_up, callback);
}
void glutKeyboardUpFuncUcall(void (*callback)(unsigned char, int, int, void*), void* user_data) {
  set_on_current("glutKeyboardUpFuncUcall", &Window::keyboard_up, callback, user_data);
}
void glutSpecialFunc(void (*callback)(int, int, int)) {
  set_on_current("glutSpecialFunc", &Window::special, callback);
}
void glutSpecialFuncUcall(void (*callback)(int, int, int, void*), void* user_data) {
  set_on_current("glutSpecialFuncUcall", &Window::special, callback, user_data);
}
void glutSpecialUpFunc(void (*callback)(int, int, int)) {
  set_on_current("glutSpecialUpFunc", &Window::special_up, callback);
}
void glutSpecialUpFuncUcall(void (*callback)(int, int, int, void*), void* user_data) {
  set_on_current("glutSpecialUpFuncUcall", &Window::special_up, callback, user_data);
}
void glutMouseFunc(void (*callback)(int, int, int, int)) {
  set_on_current("glutMouseFunc", &Window::mouse, callback);
}
void glutMouseFuncUcall(void (*callback)(int, int, int, int, void*), void* user_data) {
  set_on_current("glutMouseFuncUcall", &Window::mouse, callback, user_data);
}
void glutMouseWheelFunc(void (*callback)(int, int, int, int)) {
  set_on_current("glutMouseWheelFunc", &Window::mouse_wheel, callback);
}
void glutMouseWheelFuncUcall(void (*callback)(int, int, int, int, void*), void* user_data) {
  set_on_current("glutMouseWheelFuncUcall", &Window::mouse_wheel, callback, user_data);
}
void glutEntryFunc(void (*callback)(int)) {
  set_on_current("glutEntryFunc", &Window::entry, callback);
}
void glutEntryFuncUcall(void (*callback)(int, void*), void* user_data) {
  set_on_current("glutEntryFuncUcall", &Window::entry, callback, user_data);
}

// Visibility and window status share one notification, as in freeglut: the last one set is told.
void glutVisibilityFunc(void (*callback)(int)) {
  Window& w = current_window("glutVisibilityFunc");
  w.visibility.set(callback);
  if (callback) w.window_status = {};
}
void glutVisibilityFuncUcall(void (*callback)(int, void*), void* user_data) {
  Window& w = current_window("glutVisibilityFuncUcall");
  w.visibility.set(callback, user_data);
  if (callback) w.window_status = {};
}
void glutWindowStatusFunc(void (*callback)(int)) {
  Window& w = current_window("glutWindowStatusFunc");
  w.window_status.set(callback);
  if (callback) w.visibility = {};
}
void glutWindowStatusFuncUcall(void (*callback)(int, void*), void* user_data) {
  Window& w = current_window("glutWindowStatusFuncUcall");
  w.window_status.set(callback, user_data);
  if (callback) w.visibility = {};
}

void glutIdleFunc(void (*callback)(void)) {
  require_init("glutIdleFunc");
  state().idle.set(callback);
}
void glutIdleFuncUcall(void (*callback)(void*), void* user_data) {
  require_init("glutIdleFuncUcall");
  state().idle.set(callback, user_data);
}

void glutAppStatusFunc(void (*callback)(int)) { state().app_status.set(callback); }
void glutAppStatusFuncUcall(void (*callback)(int, void*), void* user_data) { state().app_status.set(callback, user_data); }

namespace {
void add_timer(unsigned int msecs, const Callback<int>& cb, int value) {
  State& s = state();
  const long long trigger = elapsed_ms() + msecs;
  State::Timer t{trigger, s.timer_order++, cb, value};
  // kept sorted by trigger time; a timer set for the same time fires after those set before it
  auto it = s.timers.begin();
  while (it != s.timers.end() && it->trigger_ms <= trigger) ++it;
  s.timers.insert(it, t);
}
}  // namespace

void glutTimerFunc(unsigned int time, void (*callback)(int), int value) {
  require_init("glutTimerFunc");
  Callback<int> cb;
  cb.set(callback);
  add_timer(time, cb, value);
}
void glutTimerFuncUcall(unsigned int time, void (*callback)(int, void*), int value, void* user_data) {
  require_init("glutTimerFuncUcall");
  Callback<int> cb;
  cb.set(callback, user_data);
  add_timer(time, cb, value);
}

}  // extern "C"
