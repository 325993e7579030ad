#include "harness.h"

#include <cctype>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "backends/backend.h"
#include "check/vertex_check.h"
#include "image/compare.h"
#include "gl/dispatch.h"
#include "image/image.h"
#ifdef FFCOMPAT_WITH_GLSL
#include "backends/glsl/vertex_compare.h"
#endif

#ifdef FFCOMPAT_EXAMPLES_WITH_GLFW
#define GLFW_INCLUDE_NONE  // the GL names come from the dispatch
#include <GLFW/glfw3.h>
static_assert(GLFW_KEY_1 == '1' && GLFW_KEY_W == 'W' && GLFW_KEY_SPACE == ' ');
static_assert(GLFW_KEY_MINUS == ffc::examples::key::kMinus && GLFW_KEY_EQUAL == ffc::examples::key::kEqual &&
              GLFW_KEY_ESCAPE == ffc::examples::key::kEscape &&
              GLFW_KEY_KP_SUBTRACT == ffc::examples::key::kKpSubtract &&
              GLFW_KEY_KP_ADD == ffc::examples::key::kKpAdd);
#endif

namespace ffc::examples {

int key_from_name(const std::string& name) {
  if (name.size() == 1) {
    const unsigned char c = static_cast<unsigned char>(name[0]);
    if (std::isdigit(c) || std::isalpha(c)) return std::toupper(c);
  }
  static const std::map<std::string, int> named = {
      {"+", key::kKpAdd},      {"plus", key::kKpAdd},  {"kp+", key::kKpAdd},
      {"-", key::kMinus},      {"minus", key::kMinus}, {"kp-", key::kKpSubtract},
      {"=", key::kEqual},      {"space", ' '},         {"esc", key::kEscape},
      {"escape", key::kEscape}};
  std::string lower;
  for (char c : name) lower += char(std::tolower(static_cast<unsigned char>(c)));
  const auto it = named.find(lower);
  return it == named.end() ? -1 : it->second;
}

Viewport letterbox(int fb_w, int fb_h, int pic_w, int pic_h) {
  Viewport v;
  if (fb_w <= 0 || fb_h <= 0 || pic_w <= 0 || pic_h <= 0) return v;
  // Full width if the framebuffer is relatively taller than the picture, else full height.
  if (int64_t(fb_w) * pic_h <= int64_t(fb_h) * pic_w)
    v.width = fb_w, v.height = int(int64_t(fb_w) * pic_h / pic_w);
  else
    v.height = fb_h, v.width = int(int64_t(fb_h) * pic_w / pic_h);
  v.x = (fb_w - v.width) / 2, v.y = (fb_h - v.height) / 2;
  return v;
}

std::string window_title(const Example& ex, const std::string& backend) {
  std::string t = ex.title;
  if (ex.state) t += " | " + ex.state();
  return t + " | backend " + backend;
}

namespace {

struct Options {
  bool headless = false, json = false, check = false;
  std::string out, keys, backend = "mesa", screenshot;
  int frames = 0, window_w = 0, window_h = 0;
};

// The example's frame on Mesa and on `ours`, the picture: no pixel more than one 8-bit step apart.
image::Diff compare_pictures(const Example& ex, const std::string& ours) {
  image::Image pictures[2];
  const std::string names[2] = {"mesa", ours};
  for (int i = 0; i < 2; ++i) {
    auto backend = backends::make(names[i]);
    backend->begin(ex.width, ex.height);
    ex.draw(ex.width, ex.height);
    pictures[i] = backend->read();
  }
  return image::compare(pictures[0], pictures[1]);
}

// --check --backend glsl: the lit colours and positions the generated vertex shaders compute
// (transform feedback) against Mesa's feedback, as `ffcompat check --backend glsl --level vertex`
// does for a scene, then the pictures.
int check_glsl(const Example& ex, const Options& opt) {
#ifndef FFCOMPAT_WITH_GLSL
  (void)opt;
  std::cerr << ex.name << ": the GLSL backend is not built here (no EGL at configure time)\n";
  return 1;
#else
  const glsl::VertexComparison r = glsl::compare_with_mesa(ex.width, ex.height, [&] { ex.draw(ex.width, ex.height); });
  const image::Diff d = compare_pictures(ex, "glsl");
  // Every primitive Mesa reports paired with one of ours (or holding a vertex the clipper made),
  // at least one compared, every compared colour within 1e-5 (or a deviation of Mesa's named).
  const bool vertices_ok = r.unpaired == 0 && r.compared > 0 && (r.max_abs <= 1e-5 || !r.known_mesa_deviations.empty());
  const bool pass = vertices_ok && d.max_diff <= 1;
  if (opt.json)
    std::cout << nlohmann::ordered_json{{"example", ex.name},          {"backend", "glsl"},
                                        {"mesa_primitives", r.mesa_primitives}, {"compared", r.compared},
                                        {"clipped", r.clipped},         {"unpaired", r.unpaired},
                                        {"vertices", r.vertices},       {"max_abs", r.max_abs},
                                        {"rms", r.rms},                 {"max_position_px", r.max_position},
                                        {"known_mesa_deviations", r.known_mesa_deviations},
                                        {"programs", {{"compiles", r.compiles}, {"cache_hits", r.cache_hits}}},
                                        {"pixel_max_diff", d.max_diff}, {"pixel_differing_share", d.differing_share},
                                        {"pass", pass}}
                     .dump()
              << std::endl;
  else
    std::cout << ex.name << ": glsl " << r.compared << " of " << r.mesa_primitives << " primitives compared ("
              << r.clipped << " clipped, " << r.unpaired << " unpaired), " << r.vertices << " vertices, colour vs Mesa max "
              << r.max_abs << ", positions within " << r.max_position << " px; pixels max " << d.max_diff << " steps on "
              << 100 * d.differing_share << "%" << (pass ? " PASS" : " FAIL") << std::endl;
  return pass ? 0 : 2;
#endif
}

// The example's frame through Mesa's feedback and ours, vertex by vertex (ffcompat check's
// vertex level, for a program that is not a scene).
int check_vertices(const Example& ex, const Options& opt) {
  if (opt.backend == "glsl") return check_glsl(ex, opt);
  if (opt.backend != "mesa" && opt.backend != "soft")
    throw std::invalid_argument("--check compares soft (the default) or glsl with Mesa, not '" + opt.backend + "'");
  const check::VertexReport r = check::compare_vertices(ex.width, ex.height, [&] { ex.draw(ex.width, ex.height); });
  const image::Diff d = compare_pictures(ex, "soft");
  const bool pass = (r.max_abs <= 1e-5 || !r.known_mesa_deviations.empty()) && d.max_diff <= 1;
  if (opt.json)
    std::cout << nlohmann::ordered_json{{"example", ex.name}, {"vertices", r.vertices},      {"max_abs", r.max_abs},
                                        {"rms", r.rms},       {"max_abs_double", r.max_abs_double},
                                        {"max_position_px", r.max_position},
                                        {"known_mesa_deviations", r.known_mesa_deviations},
                                        {"pixel_max_diff", d.max_diff}, {"pixel_differing_share", d.differing_share},
                                        {"pass", pass}}
                     .dump()
              << std::endl;
  else
    std::cout << ex.name << ": " << r.vertices << " vertices, float vs Mesa max " << r.max_abs << ", double vs Mesa max "
              << r.max_abs_double << "; pixels max " << d.max_diff << " steps on " << 100 * d.differing_share << "%"
              << (pass ? " PASS" : " FAIL") << std::endl;
  return pass ? 0 : 2;
}

int render_headless(const Example& ex, const Options& opt) {
  auto backend = backends::make(opt.backend);  // throws for an unknown name
  backend->begin(ex.width, ex.height);         // sets the viewport
  ex.draw(ex.width, ex.height);
  const image::Image img = backend->read();
  image::write_png(opt.out, img);
  if (opt.json)
    std::cout << nlohmann::ordered_json{{"example", ex.name}, {"out", opt.out}, {"width", img.width},
                                {"height", img.height}, {"backend", backend->name()}}
                     .dump()
              << std::endl;
  return 0;
}

#ifdef FFCOMPAT_EXAMPLES_WITH_GLFW
void* glfw_loader(const char* name) { return reinterpret_cast<void*>(glfwGetProcAddress(name)); }

void on_glfw_key(GLFWwindow* window, int key, int /*scancode*/, int action, int /*mods*/) {
  if (action != GLFW_PRESS && action != GLFW_REPEAT) return;
  if (key == GLFW_KEY_ESCAPE) glfwSetWindowShouldClose(window, GLFW_TRUE);
  const auto* ex = static_cast<const Example*>(glfwGetWindowUserPointer(window));
  if (ex->on_key) ex->on_key(key);
}

int run_window(const Example& ex, const Options& opt) {
  glfwSetErrorCallback([](int, const char* what) { std::cerr << "glfw: " << what << "\n"; });
  if (!glfwInit()) {
    std::cerr << ex.name << ": glfwInit failed (no display? try --headless --out F.png)\n";
    return 1;
  }
  // No profile hint: a compatibility context, where the fixed-function pipeline lives.
  GLFWwindow* window = glfwCreateWindow(opt.window_w > 0 ? opt.window_w : ex.width,
                                        opt.window_h > 0 ? opt.window_h : ex.height, ex.title.c_str(), nullptr, nullptr);
  if (!window) {
    glfwTerminate();
    std::cerr << ex.name << ": could not create a GLFW window\n";
    return 1;
  }
  glfwMakeContextCurrent(window);
  // --backend soft: frames come from our renderer and are shown with glDrawPixels.
  std::unique_ptr<backends::Backend> soft;
  if (opt.backend != "mesa") soft = backends::make(opt.backend);
  if (const auto missing = gl::load(glfw_loader); !missing.empty()) {
    glfwTerminate();
    std::cerr << ex.name << ": the window's GL context does not provide " << missing.front() << "\n";
    return 1;
  }
  glfwSetWindowUserPointer(window, const_cast<Example*>(&ex));
  glfwSetKeyCallback(window, on_glfw_key);
  glfwSwapInterval(1);
  // The window keeps the picture's aspect when the window manager honours the hint; the
  // letterbox below keeps it when one does not (or under a bare X server).
  glfwSetWindowAspectRatio(window, ex.width, ex.height);
  const std::string backend_name = soft ? soft->name() : "mesa (the window's GL)";
  std::string shown_title;
  try {
    for (int frame = 0; !glfwWindowShouldClose(window) && (opt.frames <= 0 || frame < opt.frames); ++frame) {
      glfwPollEvents();
      if (const std::string t = window_title(ex, backend_name); t != shown_title) {
        glfwSetWindowTitle(window, t.c_str());
        shown_title = t;
      }
      int fb_w = 0, fb_h = 0;
      glfwGetFramebufferSize(window, &fb_w, &fb_h);
      const Viewport v = letterbox(fb_w, fb_h, ex.width, ex.height);
      if (v.width <= 0 || v.height <= 0) {  // minimised
        glfwSwapBuffers(window);
        continue;
      }
      if (soft) {
        // Our renderer draws the frame; the window's GL only shows the picture.
        soft->begin(v.width, v.height);
        ex.draw(v.width, v.height);
        image::Image img = soft->read();
        for (int y = 0; y < v.height / 2; ++y)  // glDrawPixels wants the bottom row first
          std::swap_ranges(img.at(0, y), img.at(0, y) + size_t(v.width) * 4, img.at(0, v.height - 1 - y));
        gl::load(glfw_loader);
        glViewport(0, 0, fb_w, fb_h);
        glClearColor(0, 0, 0, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        glViewport(v.x, v.y, v.width, v.height);  // glRasterPos2f(-1, -1) lands on its corner
        glMatrixMode(GL_PROJECTION), glLoadIdentity();
        glMatrixMode(GL_MODELVIEW), glLoadIdentity();
        glDisable(GL_DEPTH_TEST), glDisable(GL_LIGHTING);
        glRasterPos2f(-1, -1);
        glDrawPixels(v.width, v.height, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba.data());
      } else {
        // The examples' glClear clears the whole window, bars included; they draw in the box.
        glViewport(v.x, v.y, v.width, v.height);
        ex.draw(v.width, v.height);
      }
      if (!opt.screenshot.empty() && frame + 1 == opt.frames) {
        // What the window shows, read back from its own GL before the swap: bars included.
        image::Image shot(fb_w, fb_h);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, fb_w, fb_h, GL_RGBA, GL_UNSIGNED_BYTE, shot.rgba.data());
        for (int y = 0; y < fb_h / 2; ++y)  // bottom row first, as glReadPixels gives it
          std::swap_ranges(shot.at(0, y), shot.at(0, y) + size_t(fb_w) * 4, shot.at(0, fb_h - 1 - y));
        image::write_png(opt.screenshot, shot);
      }
      glfwSwapBuffers(window);
    }
    // With --frames (the tests), the title last shown: what a person would have read.
    if (opt.frames > 0) std::cout << "window title: " << shown_title << std::endl;
  } catch (...) {
    glfwTerminate();  // close the window before run_example reports the error
    throw;
  }
  glfwTerminate();
  return 0;
}
#else
int run_window(const Example& ex, const Options&) {
  std::cerr << ex.name << ": built without GLFW (FFCOMPAT_WITH_GLFW=OFF); only --headless --out F.png works\n";
  return 1;
}
#endif

}  // namespace

int run_example(int argc, char** argv, const Example& ex) {
  CLI::App app{ex.title};
  Options opt;
  auto* headless = app.add_flag("--headless", opt.headless, "Render one frame offscreen and write --out");
  app.add_option("--out", opt.out, "PNG file written by --headless")->needs(headless);
  app.add_option("--backend", opt.backend,
                 "Renderer: mesa (in a window: the window's GL), soft or glsl; with --check, the one checked (soft unless glsl)")
      ->capture_default_str();
  app.add_option("--keys", opt.keys, "Space-separated keys pressed before drawing, e.g. \"3 3 2\"");
  auto* check = app.add_flag("--check", opt.check, "Compare our lit vertices (feedback) and pixels with Mesa's")
                    ->excludes(headless);
  app.add_flag("--json", opt.json, "Print what --headless wrote (or --check found) as JSON");
  app.add_option("--frames", opt.frames, "Close the window after N frames (0: when closed)")
      ->check(CLI::NonNegativeNumber)
      ->excludes(headless)
      ->excludes(check);
  app.add_option_function<std::string>(
         "--window-size",
         [&opt](const std::string& s) {
           char x = 0;
           if (std::sscanf(s.c_str(), "%d%c%d", &opt.window_w, &x, &opt.window_h) != 3 || x != 'x' ||
               opt.window_w < 1 || opt.window_h < 1 || opt.window_w > 8192 || opt.window_h > 8192)
             throw CLI::ValidationError("--window-size", "'" + s + "' is not WxH (1..8192)");
         },
         "Window size WxH at start (default: the picture's size); the picture keeps its aspect, centred")
      ->excludes(headless)
      ->excludes(check);
  app.add_option("--screenshot", opt.screenshot, "Write the window's last frame (read back with glReadPixels) to a PNG")
      ->excludes(headless)
      ->excludes(check);
  if (ex.add_options) ex.add_options(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 1;  // --help is not an error
  }

  try {
    // Every key name is checked before the first one is pressed.
    std::vector<int> keys;
    std::istringstream names(opt.keys);
    for (std::string name; names >> name;) {
      const int k = key_from_name(name);
      if (k < 0) {
        std::cerr << ex.name << ": unknown key \"" << name << "\" in --keys (use e.g. 1 W + - =)\n";
        return 1;
      }
      keys.push_back(k);
    }
    if (ex.on_key)
      for (int k : keys) ex.on_key(k);

    if (opt.check) return check_vertices(ex, opt);
    if (opt.json && !opt.headless) {
      std::cerr << ex.name << ": --json goes with --headless or --check\n";
      return 1;
    }
    if (!opt.screenshot.empty() && opt.frames <= 0) {
      std::cerr << ex.name << ": --screenshot needs --frames N (the last frame is written)\n";
      return 1;
    }
    if (!opt.headless) return run_window(ex, opt);
    if (opt.out.empty()) {
      std::cerr << ex.name << ": --headless needs --out F.png\n";
      return 1;
    }
    return render_headless(ex, opt);
  } catch (const std::exception& e) {
    std::cerr << ex.name << ": " << e.what() << "\n";
    return 1;
  }
}

}  // namespace ffc::examples
