// The little main() every legacy example shares: a GLFW window like the handouts' programs, or one
// headless frame through an ffcompat backend (--headless --out F.png), with the key presses of
// --keys replayed first so the interaction can be tested without a window.
#pragma once
#include <CLI/CLI.hpp>
#include <functional>
#include <string>

namespace ffc::examples {

// GLFW key codes, so the examples need no GLFW header (and build when GLFW is off). Printable
// keys are their uppercase ASCII code (GLFW_KEY_1 == '1', GLFW_KEY_W == 'W'); harness.cpp checks
// these against GLFW's values when GLFW is available.
namespace key {
constexpr int kMinus = 45;         // GLFW_KEY_MINUS
constexpr int kEqual = 61;         // GLFW_KEY_EQUAL (the '+' key of a US layout, unshifted)
constexpr int kEscape = 256;       // GLFW_KEY_ESCAPE
constexpr int kKpSubtract = 333;   // GLFW_KEY_KP_SUBTRACT
constexpr int kKpAdd = 334;        // GLFW_KEY_KP_ADD
inline bool is_plus(int k) { return k == kKpAdd || k == kEqual; }
inline bool is_minus(int k) { return k == kMinus || k == kKpSubtract; }
}  // namespace key

// A key name of --keys to its GLFW code, or -1: "1", "w"/"W" (letters and digits), "+" (keypad
// add), "=", "-", "kp-", "plus", "minus", "space", "esc".
int key_from_name(const std::string& name);

struct Example {
  std::string name;   // "cube_lab": the "example" field of --json
  std::string title;  // window title: the program and its keys
  int width = 640, height = 640;
  std::function<void(int w, int h)> draw;  // one frame, the viewport already set to w x h
  std::function<void(int key)> on_key;     // a GLFW key code, on press and repeat
  // The state a person changes with the keys, in words (shade model, normals, drawing path,
  // GL_NORMALIZE / GL_RESCALE_NORMAL): shown in the window title with the backend, so a
  // screenshot says what it shows.
  std::function<std::string()> state;
  // Registers the example's own options (--path, --depth, ...); they are parsed before any key
  // is replayed or any frame drawn.
  std::function<void(CLI::App& app)> add_options;
};

// The viewport that shows a picture of aspect pic_w:pic_h as large as it fits in a fb_w x fb_h
// framebuffer, centred (black bars on the other sides): the examples keep their aspect when the
// window is resized, as their projections (gluPerspective with aspect 1) assume.
struct Viewport {
  int x = 0, y = 0, width = 0, height = 0;
};
Viewport letterbox(int fb_w, int fb_h, int pic_w, int pic_h);

// "<title> | <state> | backend <name>": what the window shows in its title bar.
std::string window_title(const Example& ex, const std::string& backend);

// Parses the command line and runs the example; returns the process exit code (0, or 1 after
// printing the error to stderr).
int run_example(int argc, char** argv, const Example& ex);

}  // namespace ffc::examples
