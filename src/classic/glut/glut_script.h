// Scripted input for headless runs: the text of FFCOMPAT_RUN_KEYS and FFCOMPAT_RUN_CLICKS (and of
// `ffcompat run --keys/--clicks`, which checks it with the same parser) turned into events.
// Header-only so that the command line can refuse a bad script before it starts the program.
//
// Keys: every character is one key press and release, delivered to glutKeyboardFunc and
// glutKeyboardUpFunc; a name in angle brackets is a special key (glutSpecialFunc/SpecialUpFunc)
// or a named character:
//   <up> <down> <left> <right> <pageup> <pagedown> <home> <end> <insert> <f1>..<f12>  special keys
//   <esc> <enter> <tab> <backspace> <delete> <space> <lt> (the character '<')    characters
//   <wait>                                                                      no key this turn
// with optional modifiers before the name: <shift+f1>, <ctrl+a> (delivers 1, as X does), <alt+x>.
// An upper-case letter is delivered with GLUT_ACTIVE_SHIFT, as a keyboard makes it.
// Clicks: items separated by spaces or ';', each one of
//   X,Y[,BUTTON]           press and release at (X,Y); BUTTON left (default), middle, right, 0-2,
//                          wheelup, wheeldown (buttons 3 and 4, as freeglut reports a wheel on X)
//   X,Y>X2,Y2[,BUTTON]     a drag: press at (X,Y), four motion events along the line, release at
//                          (X2,Y2)
//   X,Y,move               the pointer moves to (X,Y) with no button down (passive motion)
//   wait                   nothing this turn
// X and Y are window coordinates, origin at the top left, as GLUT gives them to callbacks.
// Timing: event i of each list is delivered after the program's frame i is shown (the first
// frame is drawn with no input), the key before the click of the same turn.
#pragma once
#include <GL/freeglut_std.h>

#include <cctype>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

namespace ffc::glut {

// One input event. A script gives whole presses (press and release together); a real window
// gives their halves (phase).
struct Event {
  enum Kind { None, Key, Special, Click, Drag, Move, Motion } kind = None;
  enum Phase { PressAndRelease, Press, Release } phase = PressAndRelease;
  int code = 0;       // the character (Key) or GLUT_KEY_* (Special)
  int modifiers = 0;  // GLUT_ACTIVE_*
  int x = 0, y = 0, x2 = 0, y2 = 0, button = GLUT_LEFT_BUTTON;
};

namespace script_detail {
struct Named {
  const char* name;
  Event::Kind kind;
  int code;
};
inline const std::vector<Named>& names() {
  static const std::vector<Named> list = {
      {"up", Event::Special, GLUT_KEY_UP},         {"down", Event::Special, GLUT_KEY_DOWN},
      {"left", Event::Special, GLUT_KEY_LEFT},     {"right", Event::Special, GLUT_KEY_RIGHT},
      {"pageup", Event::Special, GLUT_KEY_PAGE_UP}, {"pagedown", Event::Special, GLUT_KEY_PAGE_DOWN},
      {"home", Event::Special, GLUT_KEY_HOME},     {"end", Event::Special, GLUT_KEY_END},
      {"insert", Event::Special, GLUT_KEY_INSERT}, {"esc", Event::Key, 27},
      {"enter", Event::Key, 13},                   {"tab", Event::Key, 9},
      {"backspace", Event::Key, 8},                {"delete", Event::Key, 127},
      {"space", Event::Key, ' '},                  {"lt", Event::Key, '<'},
      {"wait", Event::None, 0}};
  return list;
}
inline int parse_int(const std::string& s, const std::string& item) {
  char* end = nullptr;
  const long v = std::strtol(s.c_str(), &end, 10);
  if (s.empty() || *end || v < -100000 || v > 100000)
    throw std::invalid_argument("'" + item + "': '" + s + "' is not a whole number");
  return int(v);
}
inline std::vector<std::string> split(const std::string& s, const std::string& seps) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : s) {
    if (seps.find(c) != std::string::npos) {
      if (!cur.empty()) out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  if (!cur.empty()) out.push_back(cur);
  return out;
}
}  // namespace script_detail

// Throws std::invalid_argument saying what is wrong and what is allowed.
inline std::vector<Event> parse_keys(const std::string& text) {
  using namespace script_detail;
  std::vector<Event> events;
  for (size_t i = 0; i < text.size(); ++i) {
    Event e;
    if (text[i] != '<') {
      e.kind = Event::Key;
      e.code = static_cast<unsigned char>(text[i]);
      if (std::isupper(e.code)) e.modifiers = GLUT_ACTIVE_SHIFT;
      events.push_back(e);
      continue;
    }
    const size_t close = text.find('>', i);
    if (close == std::string::npos)
      throw std::invalid_argument("keys: '<' at " + std::to_string(i) + " opens a name that no '>' closes (<lt> is '<')");
    std::string name = text.substr(i + 1, close - i - 1);
    i = close;
    for (;;) {  // modifiers
      const size_t plus = name.find('+');
      if (plus == std::string::npos || plus + 1 == name.size()) break;
      const std::string mod = name.substr(0, plus);
      if (mod == "shift") e.modifiers |= GLUT_ACTIVE_SHIFT;
      else if (mod == "ctrl") e.modifiers |= GLUT_ACTIVE_CTRL;
      else if (mod == "alt") e.modifiers |= GLUT_ACTIVE_ALT;
      else throw std::invalid_argument("keys: unknown modifier '" + mod + "' (shift, ctrl, alt)");
      name = name.substr(plus + 1);
    }
    bool found = false;
    for (const Named& n : names())
      if (name == n.name) e.kind = n.kind, e.code = n.code, found = true;
    if (!found && name.size() >= 2 && name[0] == 'f' && std::isdigit(static_cast<unsigned char>(name[1]))) {
      const int f = std::atoi(name.c_str() + 1);
      if (f >= 1 && f <= 12 && name == "f" + std::to_string(f)) e.kind = Event::Special, e.code = GLUT_KEY_F1 + f - 1, found = true;
    }
    if (!found && name.size() == 1) e.kind = Event::Key, e.code = static_cast<unsigned char>(name[0]), found = true;
    if (!found)
      throw std::invalid_argument("keys: unknown key name <" + name +
                                  "> (up down left right pageup pagedown home end insert f1-f12 esc enter tab "
                                  "backspace delete space lt wait)");
    // Ctrl with a letter gives the control character, as X's keyboard does for freeglut.
    if (e.kind == Event::Key && (e.modifiers & GLUT_ACTIVE_CTRL) && std::isalpha(e.code))
      e.code = std::toupper(e.code) - '@';
    events.push_back(e);
  }
  return events;
}

inline std::vector<Event> parse_clicks(const std::string& text) {
  using namespace script_detail;
  std::vector<Event> events;
  for (const std::string& item : split(text, " ;\t\n")) {
    Event e;
    if (item == "wait") {
      events.push_back(e);
      continue;
    }
    const size_t arrow = item.find('>');
    std::vector<std::string> parts = split(arrow == std::string::npos ? item : item.substr(0, arrow), ",");
    std::vector<std::string> to;
    if (arrow != std::string::npos) to = split(item.substr(arrow + 1), ",");
    std::string button = "left";
    std::vector<std::string>& last = arrow == std::string::npos ? parts : to;
    if (last.size() == 3) button = last[2], last.pop_back();
    if (parts.size() != 2 || (arrow != std::string::npos && to.size() != 2))
      throw std::invalid_argument("clicks: '" + item + "' is not X,Y[,BUTTON], X,Y>X2,Y2[,BUTTON], X,Y,move or wait");
    e.x = parse_int(parts[0], item), e.y = parse_int(parts[1], item);
    e.kind = arrow == std::string::npos ? Event::Click : Event::Drag;
    if (e.kind == Event::Drag) e.x2 = parse_int(to[0], item), e.y2 = parse_int(to[1], item);
    if (button == "move" && e.kind == Event::Click) e.kind = Event::Move;
    else if (button == "left" || button == "0") e.button = GLUT_LEFT_BUTTON;
    else if (button == "middle" || button == "1") e.button = GLUT_MIDDLE_BUTTON;
    else if (button == "right" || button == "2") e.button = GLUT_RIGHT_BUTTON;
    else if (button == "wheelup" || button == "3") e.button = 3;
    else if (button == "wheeldown" || button == "4") e.button = 4;
    else
      throw std::invalid_argument("clicks: '" + item + "': unknown button '" + button +
                                  "' (left, middle, right, 0-4, wheelup, wheeldown; move for no button)");
    events.push_back(e);
  }
  return events;
}

}  // namespace ffc::glut
