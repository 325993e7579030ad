// The main loop, in freeglut's order: each turn takes input, fires the timers that are due, then
// does each window's work (first the notifications of a new window, position, size and
// visibility, then a posted redisplay); between turns the idle callback runs, or the loop sleeps.
//
// Headless (FFCOMPAT_RUN_OUT set, or no DISPLAY, unless FFCOMPAT_RUN_WINDOW=1) the loop runs on a
// simulated clock and stops the process with status 0 once FFCOMPAT_RUN_FRAMES frames have been
// shown (docs/run.md):
//   - frame k (from 0) is shown no earlier than k * 1000 / 60 ms: a swap waits for the next
//     "vertical blank" of a 60 Hz screen, so GLUT_ELAPSED_TIME reads 0, 16, 33, 50, ... in the
//     display callbacks of a program that redraws as fast as it can;
//   - a turn of the idle callback that shows no frame costs 1 ms;
//   - sleeping moves the clock to the next timer;
//   - with nothing at all to wait for (no idle, no timer, no input, no redisplay posted), the
//     screen is exposed: every visible window is asked to redisplay, as a window manager does,
//     so a program that draws only on demand still gives its N frames;
//   - scripted input event i is delivered at the turn after frame i is shown.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "../gl/ffcompat_surface.h"
#include "glut_state.h"

namespace ffc::glut {

namespace {

struct Run {
  bool headless = true;
  bool windowed = false;
  int frames = 1;             // stop after this many frames (headless; windowed when given)
  bool frames_given = false;
  std::string out;            // FFCOMPAT_RUN_OUT: where frames are written ("" = nowhere)
  std::vector<Event> keys, clicks;
  size_t next_slot = 0;       // the next scripted turn to deliver
  int shown = 0;              // frames shown, all windows together
  long long now_ms = 0;       // the simulated clock
  int turns_without_frame = 0, exposes_without_frame = 0;
};

std::vector<Event> parse_env(const char* name, std::vector<Event> (*parse)(const std::string&)) {
  const char* text = std::getenv(name);
  if (!text) return {};
  try {
    return parse(text);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ffcompat glut: %s: %s\n", name, e.what());
    std::exit(1);
  }
}

Run& run() {
  static Run r = [] {
    Run r;
    const char* out = std::getenv("FFCOMPAT_RUN_OUT");
    const char* display = std::getenv("DISPLAY");
    const char* window = std::getenv("FFCOMPAT_RUN_WINDOW");
    const bool want_window = window && std::string(window) == "1";
    r.windowed = want_window || (!out && display && *display);
    r.headless = !r.windowed;
    if (out) r.out = out;
    r.keys = parse_env("FFCOMPAT_RUN_KEYS", parse_keys);
    r.clicks = parse_env("FFCOMPAT_RUN_CLICKS", parse_clicks);
    r.frames = int(1 + std::max(r.keys.size(), r.clicks.size()));
    if (const char* n = std::getenv("FFCOMPAT_RUN_FRAMES")) {
      char* end = nullptr;
      const long v = std::strtol(n, &end, 10);
      if (*n && !*end && v >= 1 && v <= 100000) {
        r.frames = int(v), r.frames_given = true;
      } else {
        std::fprintf(stderr, "ffcompat glut: FFCOMPAT_RUN_FRAMES='%s' is not a count from 1 to 100000\n", n);
        std::exit(1);
      }
    }
    return r;
  }();
  return r;
}

std::chrono::steady_clock::time_point wall_start = std::chrono::steady_clock::now();

// The window that scripted input goes to: the first one still open.
Window* input_window() {
  return state().windows.empty() ? nullptr : state().windows.begin()->second.get();
}

void notify_size(Window& w) {
  if (w.reshape) w.reshape(w.width, w.height);
  else glViewport(0, 0, w.width, w.height);  // freeglut's default reshape
}

void display(Window& w) {
  State& s = state();
  Window* saved = s.current;
  make_current(&w);
  w.redisplay = false;
  w.display();
  // A single-buffered window shows what was drawn once its display callback returns.
  if (!(w.mode & GLUT_DOUBLE) && window_by_id(w.id)) frame_shown(w);
  if (saved && window_by_id(saved->id)) make_current(saved);
}

void fire_timers() {
  State& s = state();
  const long long now = elapsed_ms();
  while (!s.timers.empty() && s.timers.front().trigger_ms <= now) {
    State::Timer t = s.timers.front();
    s.timers.erase(s.timers.begin());
    t.callback(t.value);
  }
}

// The notifications of a new window, in the order freeglut's X11 events give them, before the
// timers of the same turn: position, size (the reshape callback, or freeglut's default
// glViewport), visibility.
void init_work(Window& w) {
  State& s = state();
  const int id = w.id;
  Window* saved = s.current;
  make_current(&w);
  w.init_work = false;
  if (w.position) w.position(w.x, w.y);
  if (window_by_id(id)) notify_size(w);
  if (window_by_id(id)) {
    if (w.window_status) w.window_status(GLUT_FULLY_RETAINED);
    else if (w.visibility) w.visibility(GLUT_VISIBLE);
  }
  if (window_by_id(id)) {
    if (!w.display) error("ERROR:  No display callback registered for window %d\n", w.id);
    w.redisplay = true;
  }
  if (saved && window_by_id(saved->id)) make_current(saved);
}

// One window's work after the timers: a resize asked for, then a posted redisplay.
void window_work(Window& w) {
  State& s = state();
  const int id = w.id;
  if (w.reshape_pending) {
    w.reshape_pending = false;
    if ((w.wanted_width != w.width || w.wanted_height != w.height) &&
        ffcompat_surface_resize(w.surface, w.wanted_width, w.wanted_height) == 0) {
      Window* saved = s.current;
      make_current(&w);
      w.width = w.wanted_width, w.height = w.wanted_height;
      notify_size(w);
      if (!window_by_id(id)) return;
      w.redisplay = true;
      if (saved && window_by_id(saved->id)) make_current(saved);
    }
  }
  if (w.redisplay && w.visible) display(w);
}

// Windows may come and go in callbacks: walk the ids, not the map's iterators.
template <typename F>
void each_window(F f) {
  std::vector<int> ids;
  for (auto& [id, w] : state().windows) ids.push_back(id);
  for (int id : ids)
    if (Window* w = window_by_id(id)) f(*w);
}

void deliver_script() {
  Run& r = run();
  const size_t slots = std::max(r.keys.size(), r.clicks.size());
  if (r.next_slot >= slots || int(r.next_slot) >= r.shown) return;
  const size_t i = r.next_slot++;
  Window* w = input_window();
  if (!w) return;
  if (i < r.keys.size()) deliver(*w, r.keys[i]);
  w = input_window();
  if (w && i < r.clicks.size()) deliver(*w, r.clicks[i]);
}

bool script_pending() {
  const Run& r = run();
  return r.next_slot < std::max(r.keys.size(), r.clicks.size()) && int(r.next_slot) < r.shown;
}

bool redisplay_pending() {
  for (auto& [id, w] : state().windows)
    if ((w->redisplay && w->visible) || w->init_work || w->reshape_pending) return true;
  return false;
}

[[noreturn]] void finish() {
  std::fflush(stdout);
  std::exit(0);
}

// Every window is asked to redisplay, as a window manager does when it exposes them; a program
// that still shows nothing is stopped rather than left to spin.
void expose() {
  Run& r = run();
  r.turns_without_frame = 0;
  if (++r.exposes_without_frame > 3)
    error("no frame was shown in 3 exposures of the window (does the display callback of a "
          "double-buffered window call glutSwapBuffers? is the window hidden?)");
  for (auto& [id, w] : state().windows) w->redisplay = true;
}

// A busy turn (the idle callback ran, or the program drives the loop with glutMainLoopEvent) costs
// 1 ms; one that shows nothing for 1000 turns is exposed.
void busy_turn() {
  Run& r = run();
  ++r.now_ms;
  if (++r.turns_without_frame >= 1000) expose();
}

// Headless sleep: wait for the next thing that can happen.
void sleep_headless() {
  Run& r = run();
  State& s = state();
  if (redisplay_pending() || script_pending()) return;
  if (!s.timers.empty()) {
    r.now_ms = std::max(r.now_ms, s.timers.front().trigger_ms);
    return;
  }
  expose();  // nothing will ever happen by itself
}

}  // namespace

bool headless() { return run().headless; }
bool windowed() { return run().windowed; }

long long elapsed_ms() {
  if (run().headless) return run().now_ms;
  return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() - wall_start).count();
}

void reset_wall_clock() { wall_start = std::chrono::steady_clock::now(); }

void frame_shown(Window& w) {
  Run& r = run();
  const int index = w.frames++;
  if (!r.out.empty() || r.windowed) {
    std::vector<unsigned char> rgba(size_t(w.width) * w.height * 4);
    ffcompat_surface_read_rgba(w.surface, rgba.data());
    if (!r.out.empty()) write_frame(r.out, w.id, index, w.width, w.height, rgba.data());
    if (r.windowed && w.id == input_window()->id) windowed_show(w, rgba.data());
  }
  ++r.shown;
  r.turns_without_frame = 0, r.exposes_without_frame = 0;
  // The next frame waits for the next 60 Hz blank (see the top of this file).
  if (r.headless) r.now_ms = std::max(r.now_ms, (long long)r.shown * 1000 / 60);
}

void loop_turn() {
  Run& r = run();
  if (r.windowed) windowed_poll();
  else deliver_script();
  each_window([](Window& w) {
    if (w.init_work) init_work(w);
  });
  fire_timers();
  each_window(window_work);
  if ((r.headless || r.frames_given) && r.shown >= r.frames) finish();
}

}  // namespace ffc::glut

using namespace ffc::glut;

extern "C" {

// A program's own loop: one turn, then, headless, the time a busy turn takes (the program may be
// waiting for the clock to pass a time of its own).
void glutMainLoopEvent(void) {
  require_init("glutMainLoopEvent");
  loop_turn();
  if (!state().running && headless()) busy_turn();
}

void glutMainLoop(void) {
  require_init("glutMainLoop");
  State& s = state();
  if (s.windows.empty()) error(" ERROR:  glutMainLoop called with no windows created.");
  Run& r = run();
  s.running = true, s.leave = false;
  for (;;) {
    loop_turn();
    if (s.leave) break;
    if (s.windows.empty()) break;
    if (r.windowed && windowed_should_close()) {
      // The window manager closed the window: freeglut calls the close callback and ends.
      while (!s.windows.empty()) glutDestroyWindow(s.windows.begin()->first);
      break;
    }
    if (s.idle) {
      s.idle();
      if (r.headless) busy_turn();
    } else if (r.headless) {
      sleep_headless();
    } else if (!redisplay_pending()) {
      windowed_wait(s.timers.empty() ? -1 : s.timers.front().trigger_ms - elapsed_ms());
    }
  }
  s.running = false;
  const int action = s.action_on_window_close;
  while (!s.windows.empty()) glutDestroyWindow(s.windows.begin()->first);
  if (action == GLUT_ACTION_EXIT) finish();
}

void glutLeaveMainLoop(void) {
  require_init("glutLeaveMainLoop");
  state().leave = true;
}

}  // extern "C"
