// Seed 001 ("8 - Lab - Lighting"): the handout's six GLSL 330 core programs as one program.
//   1 ambient only, Gouraud, face normals     4 all components, Phong shading, face normals
//   2 + diffuse, Gouraud, face normals        5 all components, Gouraud, averaged normals
//   3 + specular, Gouraud, face normals       6 all components, Phong, averaged normals
// Headless by default (an EGL core-profile pbuffer, a PNG out); --window opens a GLFW core-profile
// window. Keys: 1/3 turn the camera, 2/W raise/lower it (the seeds' keys); N next step and
// F the field of view (the handout's 45 radians or 45 degrees) are ours.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "harness.h"
#include "image/image.h"
#include "seed001_reference.h"
#include "seed001_renderer.h"

#ifdef FFCOMPAT_EXAMPLES_WITH_GLFW
#define GLFW_INCLUDE_NONE  // the GL names come from <GL/glcorearb.h> (seed001_gl.h)
#include <GLFW/glfw3.h>
#endif

namespace {

struct Options {
  int step = 3, size = 640, frames = 0;
  std::string out, keys;
  bool json = false, check = false, window = false, degrees = false, print_shaders = false;
};

std::string describe(int step, const seed001::View& v) {
  char b[160];
  std::snprintf(b, sizeof b, "step %d %s | camera %.0f deg, height %.1f | fovy 45 %s (%.1f deg)", step,
                seed001::step_name(step).c_str(), v.cam_ang * 180 / M_PI, v.cam_height,
                v.fovy_radians ? "rad" : "deg", seed001::fovy_degrees(v));
  return b;
}

nlohmann::ordered_json view_json(const seed001::View& v) {
  return {{"cam_angle_deg", v.cam_ang * 180 / M_PI},
          {"cam_height", v.cam_height},
          {"fovy_argument", 45},
          {"fovy_unit", v.fovy_radians ? "radians" : "degrees"},
          {"fovy_deg", seed001::fovy_degrees(v)}};
}

int run_headless(const Options& opt, const seed001::View& view) {
  const seed001::Lighting l = seed001::step_lighting(opt.step);
  seed001::Headless gl(opt.size, opt.size);
  const ffc::image::Image img = gl.render(l, view);
  if (!opt.out.empty()) ffc::image::write_png(opt.out, img);
  nlohmann::ordered_json j = {{"example", "seed001"}, {"step", opt.step}, {"name", seed001::step_name(opt.step)},
                              {"out", opt.out},       {"width", img.width}, {"height", img.height},
                              {"renderer", gl.gl_renderer()}, {"view", view_json(view)}};
  const uint8_t* centre = img.at(img.width / 2, img.height / 2);
  j["centre_pixel"] = {centre[0], centre[1], centre[2]};
  bool pass = true;
  if (opt.check) {
    const seed001::ReferenceCheck r = seed001::check_against_reference(img, l, view);
    // Float shaders against double: a step of rounding, two where pow(x, 32) meets a highlight.
    pass = r.pixels > 0 && r.max_diff <= 2 && r.background_wrong == 0;
    j["check"] = {{"pixels", r.pixels},   {"max_diff", r.max_diff},     {"mean_diff", r.mean_diff},
                  {"worst", {r.worst_x, r.worst_y}}, {"background", r.background},
                  {"background_wrong", r.background_wrong}, {"pass", pass}};
  }
  if (opt.json) {
    std::cout << j.dump() << std::endl;
  } else {
    std::cout << "seed001: " << describe(opt.step, view) << " -> " << (opt.out.empty() ? "(no --out)" : opt.out)
              << " on " << j["renderer"].get<std::string>() << "\n";
    if (opt.check)
      std::cout << "  against the handout's equation in double: " << j["check"]["pixels"] << " pixels, max "
                << j["check"]["max_diff"] << " steps, mean " << j["check"]["mean_diff"] << "; background "
                << j["check"]["background"] << " pixels, " << j["check"]["background_wrong"] << " not black"
                << (pass ? " PASS" : " FAIL") << "\n";
  }
  return pass ? 0 : 2;
}

struct WindowState {
  int step;
  seed001::View view;
};

#ifdef FFCOMPAT_EXAMPLES_WITH_GLFW

void on_key(GLFWwindow* window, int key, int, int action, int) {
  if (action != GLFW_PRESS && action != GLFW_REPEAT) return;
  auto* s = static_cast<WindowState*>(glfwGetWindowUserPointer(window));
  if (key == GLFW_KEY_ESCAPE) glfwSetWindowShouldClose(window, GLFW_TRUE);
  if (s->view.on_key(key)) return;
  if (key == 'N') s->step = s->step % seed001::kSteps + 1;
  if (key == 'F') s->view.fovy_radians = !s->view.fovy_radians;
}

void* glfw_proc(const char* name) { return reinterpret_cast<void*>(glfwGetProcAddress(name)); }

int run_window(const Options& opt, WindowState state) {
  glfwSetErrorCallback([](int, const char* what) { std::cerr << "glfw: " << what << "\n"; });
  if (!glfwInit()) {
    std::cerr << "seed001: glfwInit failed (no display? leave out --window for a PNG)\n";
    return 1;
  }
  // The handout's window: a core-profile 3.3 context (forward compatible, as macOS requires).
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  GLFWwindow* window = glfwCreateWindow(opt.size, opt.size, "seed001", nullptr, nullptr);
  if (!window) {
    glfwTerminate();
    std::cerr << "seed001: could not create a core-profile 3.3 window\n";
    return 1;
  }
  glfwMakeContextCurrent(window);
  int status = 0;
  {
    seed001::Gl33 gl;
    if (const auto missing = gl.load(glfw_proc); !missing.empty()) {
      glfwTerminate();
      std::cerr << "seed001: the window's context does not provide " << missing.front() << "\n";
      return 1;
    }
    seed001::Renderer renderer(gl);
    glfwSetWindowUserPointer(window, &state);
    glfwSetKeyCallback(window, on_key);
    glfwSwapInterval(1);
    std::string shown;
    const std::string renderer_name = reinterpret_cast<const char*>(gl.GetString(GL_RENDERER));
    try {
      for (int frame = 0; !glfwWindowShouldClose(window) && (opt.frames <= 0 || frame < opt.frames); ++frame) {
        glfwPollEvents();
        const std::string title = "seed001: " + describe(state.step, state.view) + " | " + renderer_name;
        if (title != shown) glfwSetWindowTitle(window, title.c_str()), shown = title;
        int fb_w = 0, fb_h = 0;
        glfwGetFramebufferSize(window, &fb_w, &fb_h);
        // The projection's aspect is 1: a square viewport, centred, whatever the window's shape.
        const ffc::examples::Viewport vp = ffc::examples::letterbox(fb_w, fb_h, 1, 1);
        if (vp.width > 0) {
          gl.Viewport(0, 0, fb_w, fb_h);
          gl.ClearColor(0, 0, 0, 1);
          gl.Clear(GL_COLOR_BUFFER_BIT);  // the bars
          gl.Viewport(vp.x, vp.y, vp.width, vp.height);
          renderer.draw(seed001::step_lighting(state.step), state.view);
        }
        glfwSwapBuffers(window);
      }
      if (opt.frames > 0) std::cout << "window title: " << shown << std::endl;
    } catch (const std::exception& e) {
      std::cerr << "seed001: " << e.what() << "\n";
      status = 1;
    }
  }  // the renderer's GL objects go before the context
  glfwTerminate();
  return status;
}
#else
int run_window(const Options&, const WindowState&) {
  std::cerr << "seed001: built without GLFW (FFCOMPAT_WITH_GLFW=OFF); only headless works\n";
  return 1;
}
#endif

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"seed001: the handout's six GLSL 330 core lighting programs (headless PNG, or --window)"};
  Options opt;
  app.add_option("--step", opt.step, "Which program: 1 ambient, 2 +diffuse, 3 all (Gouraud), 4 Phong, "
                                     "5 Gouraud and 6 Phong with averaged normals")
      ->check(CLI::Range(1, seed001::kSteps))
      ->capture_default_str();
  app.add_option("--out", opt.out, "PNG file to write (headless)");
  app.add_flag("--json", opt.json, "Print what was drawn (and --check's figures) as JSON");
  app.add_flag("--check", opt.check,
               "Hold the picture to the handout's equation evaluated in double on the CPU (exit 2 when a pixel "
               "is more than 2 steps off)");
  app.add_option("--size", opt.size, "Picture size (square)")->check(CLI::Range(16, 4096))->capture_default_str();
  app.add_option("--keys", opt.keys, "Space-separated keys pressed first, e.g. \"3 3 2\"");
  app.add_flag("--degrees", opt.degrees,
               "Use 45 degrees for glm.perspective's fovy (seed 000's camera); the handout passes 45, i.e. 45 radians");
  app.add_flag("--shaders", opt.print_shaders, "Print the step's vertex and fragment shaders and exit");
  auto* window = app.add_flag("--window", opt.window, "Open a GLFW core-profile window (N: next step, F: fovy)");
  app.add_option("--frames", opt.frames, "Close the window after N frames (0: when closed)")
      ->check(CLI::NonNegativeNumber)
      ->needs(window);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 1;
  }
  try {
    seed001::View view;
    view.fovy_radians = !opt.degrees;
    view.width = view.height = opt.size;
    std::istringstream names(opt.keys);
    for (std::string name; names >> name;) {
      const int k = ffc::examples::key_from_name(name);
      if (k < 0) {
        std::cerr << "seed001: unknown key \"" << name << "\" in --keys (use e.g. 1 3 2 W N F)\n";
        return 1;
      }
      if (view.on_key(k)) continue;
      if (k == 'N') opt.step = opt.step % seed001::kSteps + 1;
      if (k == 'F') view.fovy_radians = !view.fovy_radians;
    }
    if (opt.print_shaders) {
      const seed001::Lighting l = seed001::step_lighting(opt.step);
      const seed001::ShaderText t = seed001::shaders(l, l.light_pos, glm::normalize(seed001::eye_position(view)));
      std::cout << "// vertex shader\n" << t.vertex << "\n// fragment shader\n" << t.fragment;
      return 0;
    }
    if (opt.window) {
      if (opt.check || !opt.out.empty()) {
        std::cerr << "seed001: --check and --out are headless; leave out --window\n";
        return 1;
      }
      return run_window(opt, {opt.step, view});
    }
    return run_headless(opt, view);
  } catch (const std::exception& e) {
    std::cerr << "seed001: " << e.what() << "\n";
    return 1;
  }
}
