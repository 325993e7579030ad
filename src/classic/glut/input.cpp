// Input events, scripted or from a real window, delivered to a window's callbacks as freeglut's
// X11 event loop delivers them: the modifiers readable with glutGetModifiers during the callback,
// the pointer position with key events, the wheel as buttons 3 and 4 unless a wheel callback is set.
#include "glut_state.h"

namespace ffc::glut {

namespace {

// Calls `f` with `w` current and the modifiers set, then restores both.
template <typename F>
void with_window(Window& w, int modifiers, F f) {
  State& s = state();
  Window* saved = s.current;
  make_current(&w);
  s.modifiers = modifiers;
  f();
  s.modifiers = -1;
  if (saved && window_by_id(saved->id)) make_current(saved);
}

void button(Window& w, const Event& e, int x, int y, int updown) {
  if (e.button >= 3 && e.button <= 4 && w.mouse_wheel) {
    // freeglut reports a wheel step on the press only: wheel 0, direction +1 (3) or -1 (4)
    if (updown == GLUT_DOWN) with_window(w, e.modifiers, [&] { w.mouse_wheel(0, e.button == 3 ? 1 : -1, x, y); });
    return;
  }
  if (w.mouse) with_window(w, e.modifiers, [&] { w.mouse(e.button, updown, x, y); });
}

}  // namespace

void deliver(Window& w, const Event& e) {
  State& s = state();
  const int id = w.id;
  const bool press = e.phase != Event::Release, release = e.phase != Event::Press;
  switch (e.kind) {
    case Event::None:
      break;
    case Event::Key: {
      const unsigned char c = static_cast<unsigned char>(e.code);
      if (press && w.keyboard) with_window(w, e.modifiers, [&] { w.keyboard(c, s.mouse_x, s.mouse_y); });
      if (release && window_by_id(id) && w.keyboard_up)
        with_window(w, e.modifiers, [&] { w.keyboard_up(c, s.mouse_x, s.mouse_y); });
      break;
    }
    case Event::Special:
      if (press && w.special) with_window(w, e.modifiers, [&] { w.special(e.code, s.mouse_x, s.mouse_y); });
      if (release && window_by_id(id) && w.special_up)
        with_window(w, e.modifiers, [&] { w.special_up(e.code, s.mouse_x, s.mouse_y); });
      break;
    case Event::Click:
      s.mouse_x = e.x, s.mouse_y = e.y;
      if (press) button(w, e, e.x, e.y, GLUT_DOWN);
      if (release && window_by_id(id)) button(w, e, e.x, e.y, GLUT_UP);
      break;
    case Event::Drag:
      // Press where it starts, four steps of active motion along the line, release at the end.
      s.mouse_x = e.x, s.mouse_y = e.y;
      button(w, e, e.x, e.y, GLUT_DOWN);
      for (int step = 1; step <= 4 && window_by_id(id); ++step) {
        const int x = e.x + (e.x2 - e.x) * step / 4, y = e.y + (e.y2 - e.y) * step / 4;
        s.mouse_x = x, s.mouse_y = y;
        if (w.motion) with_window(w, 0, [&] { w.motion(x, y); });
      }
      if (window_by_id(id)) button(w, e, e.x2, e.y2, GLUT_UP);
      break;
    case Event::Move:
      s.mouse_x = e.x, s.mouse_y = e.y;
      if (w.passive_motion) with_window(w, 0, [&] { w.passive_motion(e.x, e.y); });
      break;
    case Event::Motion:
      s.mouse_x = e.x, s.mouse_y = e.y;
      if (w.motion) with_window(w, 0, [&] { w.motion(e.x, e.y); });
      break;
  }
}

}  // namespace ffc::glut
