#include "difftest/generator.h"

#include <cmath>
#include <random>
#include <stdexcept>

namespace ffc::difftest {

const std::vector<Category>& categories() {
  static const std::vector<Category> v = {
      {"state", "enables of the modelled capabilities, shade model, front and cull face, depth function, clear values, line width"},
      {"lighting", "glLight*, glLightModel*, glMaterial*, float forms and integer forms of small values"},
      {"colormaterial", "glColorMaterial and GL_COLOR_MATERIAL"},
      {"extreme", "the integer forms (glLightiv, glMaterialiv, glLightModeliv) with values near 2^31"},
      {"camera", "a random projection (glOrtho or glFrustum) and modelview (translate, rotate) to start with"},
      {"matrix", "matrix mode, load, multiply, rotate, scale, translate, ortho, frustum at any time"},
      {"stack", "glPushMatrix / glPopMatrix, past the stacks' ends too"},
      {"viewport", "glViewport and glDepthRange inside the framebuffer's scale"},
      {"immediate", "glBegin/glEnd with every glVertex, glNormal and glColor form"},
      {"trailing", "glColor / glNormal after the last glVertex of a glBegin/glEnd"},
      {"arrays", "client arrays of every type, size and stride; glDrawArrays, glDrawElements, glArrayElement"},
      {"points", "GL_POINTS"},
      {"lines", "GL_LINES, GL_LINE_STRIP, GL_LINE_LOOP"},
      {"triangles", "GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN"},
      {"quads", "GL_QUADS, GL_QUAD_STRIP"},
      {"polygons", "GL_POLYGON"},
      {"feedback", "glFeedbackBuffer of each type, glRenderMode in and out of GL_FEEDBACK"},
      {"readpixels", "glReadPixels of every format and type, glPixelStorei"},
      {"get", "glGet*, glGetLight/Material, glIsEnabled, glGetString of any name, read back into buffers"},
      {"clear", "glClear, glFinish, glFlush"},
      {"fog", "capabilities that change pictures but are not modelled: fog, polygon offset, blending, scissor, smoothing"},
      {"invalid", "invalid enums and values, calls inside glBegin/glEnd that GL forbids there"},
      {"nonfinite", "NaN and infinities in float and double arguments and arrays"},
      {"rasterpos", "glRasterPos2f and glDrawPixels"},
      {"huge", "viewports of tens of thousands of pixels and draws of millions of vertices"},
      {"lists", "display lists: glNewList (both modes) around the other calls, glEndList, glCallList, glCallLists of every type, glListBase, glGenLists, glDeleteLists, glIsList"},
      {"selection", "glSelectBuffer, glRenderMode(GL_SELECT), the name stack (past its ends too), glPassThrough"},
      {"polygonmode", "glPolygonMode: faces drawn as lines or points"},
  };
  return v;
}

std::set<std::string> select_categories(const std::vector<std::string>& only, const std::vector<std::string>& exclude) {
  auto known = [](const std::string& n) {
    for (const auto& c : categories())
      if (c.name == n) return;
    throw std::invalid_argument("unknown category '" + n + "'");
  };
  std::set<std::string> s;
  for (const auto& n : only) known(n), s.insert(n);
  if (s.empty())
    for (const auto& c : categories()) s.insert(c.name);
  for (const auto& n : exclude) known(n), s.erase(n);
  if (s.empty()) throw std::invalid_argument("no category left");
  return s;
}

uint64_t stream_seed(uint64_t seed, uint64_t index) {
  // splitmix64 of the pair: neighbouring seeds and indices give unrelated streams.
  uint64_t z = seed * 0x9E3779B97F4A7C15ull + index + 0x632BE59BD9B4E019ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

namespace {

constexpr int kArrayVertices = 12;  // every client array holds this many vertices

class Gen {
 public:
  Gen(uint64_t seed, const GenOptions& o) : rng_(seed), o_(o) {}

  Stream run() {
    camera();
    if (o_.has("lighting")) lighting_setup();
    int since_checkpoint = 0;
    while (counted_ < o_.calls) {
      const int before = counted_;
      step();
      since_checkpoint += counted_ - before;
      if (since_checkpoint >= 8 && !in_begin_) {
        checkpoint();
        since_checkpoint = 0;
      }
    }
    if (in_begin_) emit("glEnd", {});
    if (compiling_) {
      emit("glEndList", {});
      emit("glCallList", {num(list_name_)});
    }
    if (in_feedback_ || in_select_) emit("glRenderMode", {num(GL_RENDER)});
    checkpoint();
    return std::move(s_);
  }

 private:
  std::mt19937_64 rng_;
  const GenOptions& o_;
  Stream s_;
  int counted_ = 0;
  int calls_in_list_ = 0;  // glCallList(s) recorded into the list being compiled
  bool in_begin_ = false, in_feedback_ = false, arrays_set_ = false;
  bool compiling_ = false, in_select_ = false;  // inside glNewList; in GL_SELECT
  int list_name_ = 0;
  bool keep_valid_ = false;  // no invalid value in the calls emitted meanwhile

  // ------------------------------------------------------------ random values
  double uni(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng_); }
  int pick(int n) { return int(std::uniform_int_distribution<int>(0, n - 1)(rng_)); }
  bool chance(double p) { return uni(0, 1) < p; }
  template <class T>
  T one_of(std::initializer_list<T> l) { return *(l.begin() + pick(int(l.size()))); }
  static Arg num(double v) { return Arg::number(v); }
  double coord() { return std::round(uni(-1.5, 1.5) * 64) / 64; }  // on a 1/64 grid: ties appear
  double colour() { return chance(0.9) ? std::round(uni(0, 1) * 32) / 32 : uni(-0.5, 1.5); }
  GLenum light() { return GL_LIGHT0 + GLenum(pick(8)); }

  // ------------------------------------------------------------ emitting
  // Appends a call after the categories' mutations: an invalid value in place of one argument,
  // NaN/Inf in place of a number.
  void emit(const std::string& name, std::vector<Arg> args) {
    Call c = make_call(name, std::move(args));
    const auto& params = functions()[size_t(c.fn)].params;
    // Invalid values that GL must reject before touching memory: negative counts and sizes (a
    // large one would read or write past the stream's arrays, which no GL checks), other enums
    // but not for an array's type (a wider type would read past the array as well).
    const bool typed_memory = name == "glVertexPointer" || name == "glNormalPointer" || name == "glColorPointer" ||
                              name == "glDrawElements";
    // Left valid: an array's size while no array has been given a pointer (the call would fail,
    // leaving the array without one, and Mesa's draw would read address 0), and glDrawArrays'
    // first (a negative one is no error in GL 2.1 and Mesa reads before the arrays).
    auto undefined_if_invalid = [&](size_t k) {
      return (k == 0 && (name == "glVertexPointer" || name == "glColorPointer") && !arrays_set_) ||
             (k == 1 && name == "glDrawArrays");
    };
    if (o_.has("invalid") && !keep_valid_ && !c.args.empty() && chance(0.08)) {
      const size_t k = size_t(pick(int(c.args.size())));
      Arg& a = c.args[k];
      if (a.kind == Arg::Kind::Num && !undefined_if_invalid(k)) {
        if (params[k] == Param::Enum && !typed_memory) {
          a.num = chance(0.8) ? known_enums()[size_t(pick(int(known_enums().size())))] : one_of({0.0, double(0x1234), 4294967295.0});
          // Never a client array the stream gives no pointer: Mesa's glEnable takes them and its
          // glArrayElement then reads address 0.
          const GLenum e = GLenum(a.num);
          if ((name == "glEnable" || name == "glEnableClientState") &&
              (e == GL_EDGE_FLAG_ARRAY || e == GL_TEXTURE_COORD_ARRAY || e == GL_INDEX_ARRAY ||
               e == GL_FOG_COORD_ARRAY || e == GL_SECONDARY_COLOR_ARRAY))
            a.num = double(0x1234);
        }
        else if (params[k] == Param::Int) a.num = name == "glArrayElement" ? -1.0 : one_of({-1.0, -100.0});
        else if (params[k] == Param::Bitfield) a.num = one_of({1.0, 2147483648.0, double(GL_COLOR_BUFFER_BIT | 0x2)});
        else if (params[k] == Param::Float || params[k] == Param::Double) a.num = one_of({-1.0, -0.5, 2.0, 1e6, 200.0});
      }
    }
    if (o_.has("nonfinite"))
      for (size_t k = 0; k < c.args.size(); ++k) {
        Arg& a = c.args[k];
        const bool real = params[k] == Param::Float || params[k] == Param::Double;
        if (a.kind == Arg::Kind::Num && real && chance(0.04)) a.num = one_of({double(NAN), double(INFINITY), -double(INFINITY)});
        if (a.kind == Arg::Kind::Blob && (a.type == GL_FLOAT || a.type == GL_DOUBLE) && !a.blob.empty() && chance(0.1))
          a.blob[size_t(pick(int(a.blob.size())))] = one_of({double(NAN), double(INFINITY), -double(INFINITY)});
      }
    s_.push_back(std::move(c));
    ++counted_;
  }
  void checkpoint() { s_.push_back(make_call("checkpoint", {})); }
  Arg floats(std::vector<double> v) { return Arg::values(GL_FLOAT, std::move(v)); }
  Arg ints(std::vector<double> v) { return Arg::values(GL_INT, std::move(v)); }

  // ------------------------------------------------------------ the prologue
  void camera() {
    if (!o_.has("camera")) return;
    emit("glMatrixMode", {num(GL_PROJECTION)});
    emit("glLoadIdentity", {});
    if (chance(0.5)) {
      const double s = uni(1, 3);
      emit("glOrtho", {num(-s), num(s), num(-s), num(s), num(-uni(2, 10)), num(uni(2, 10))});
    } else {
      const double n = uni(0.5, 2), s = n * uni(0.3, 1);
      emit("glFrustum", {num(-s), num(s), num(-s), num(s), num(n), num(uni(6, 20))});
    }
    emit("glMatrixMode", {num(GL_MODELVIEW)});
    emit("glLoadIdentity", {});
    emit("glTranslatef", {num(0), num(0), num(-uni(3, 5))});
    emit("glRotatef", {num(uni(-180, 180)), num(uni(-1, 1)), num(uni(-1, 1)), num(uni(-1, 1))});
  }

  void lighting_setup() {
    emit("glEnable", {num(GL_LIGHTING)});
    const int n = 1 + pick(3);
    for (int i = 0; i < n; ++i) {
      const GLenum l = i == 0 ? GL_LIGHT0 : light();
      emit("glEnable", {num(l)});
      emit("glLightfv", {num(l), num(GL_POSITION), floats({coord() * 3, coord() * 3, coord() * 3, double(pick(2))})});
      emit("glLightfv", {num(l), num(GL_DIFFUSE), floats({colour(), colour(), colour(), 1})});
    }
  }

  // ------------------------------------------------------------ one random action
  void step() {
    struct Action {
      const char* category;
      void (Gen::*act)();
      int weight;
    };
    static const Action actions[] = {
        {"state", &Gen::state_call, 3},     {"lighting", &Gen::lighting_call, 4}, {"matrix", &Gen::matrix_call, 2},
        {"stack", &Gen::stack_call, 1},     {"viewport", &Gen::viewport_call, 1}, {"immediate", &Gen::immediate_draw, 4},
        {"arrays", &Gen::array_draw, 4},    {"feedback", &Gen::feedback_call, 2}, {"readpixels", &Gen::readpixels_call, 1},
        {"get", &Gen::get_call, 2},         {"clear", &Gen::clear_call, 1},       {"fog", &Gen::fog_call, 1},
        {"rasterpos", &Gen::rasterpos_call, 1}, {"huge", &Gen::huge_call, 1},
        {"lists", &Gen::list_call, 2},      {"selection", &Gen::selection_call, 2},
        {"polygonmode", &Gen::polygon_mode_call, 1},
    };
    int total = 0;
    for (const auto& a : actions)
      if (o_.has(a.category)) total += a.weight;
    if (total == 0) throw std::invalid_argument("the categories leave no call to make");
    int r = pick(total);
    for (const auto& a : actions) {
      if (!o_.has(a.category)) continue;
      if ((r -= a.weight) < 0) return (this->*a.act)();
    }
  }

  void state_call() {
    static const GLenum caps[] = {GL_LIGHTING, GL_NORMALIZE, GL_RESCALE_NORMAL, GL_DEPTH_TEST, GL_CULL_FACE, GL_LIGHT0,
                                  GL_LIGHT1, GL_LIGHT7};
    switch (pick(7)) {
      case 0: emit(chance(0.6) ? "glEnable" : "glDisable", {num(caps[pick(8)])}); break;
      case 1: emit("glShadeModel", {num(one_of({GL_SMOOTH, GL_FLAT}))}); break;
      case 2: emit("glFrontFace", {num(one_of({GL_CW, GL_CCW}))}); break;
      case 3: emit("glCullFace", {num(one_of({GL_FRONT, GL_BACK, GL_FRONT_AND_BACK}))}); break;
      case 4: emit("glDepthFunc", {num(GLenum(GL_NEVER + pick(8)))}); break;
      case 5:
        if (chance(0.5)) emit("glClearColor", {num(colour()), num(colour()), num(colour()), num(colour())});
        else emit("glClearDepth", {num(uni(0, 1))});
        break;
      default: emit("glLineWidth", {num(one_of({1.0, 1.0, 2.0, 3.5}))}); break;
    }
  }

  void lighting_call() {
    const GLenum light_pnames[] = {GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_POSITION, GL_SPOT_DIRECTION,
                                   GL_SPOT_EXPONENT, GL_SPOT_CUTOFF, GL_CONSTANT_ATTENUATION, GL_LINEAR_ATTENUATION,
                                   GL_QUADRATIC_ATTENUATION};
    const GLenum faces[] = {GL_FRONT, GL_BACK, GL_FRONT_AND_BACK};
    auto scalar_light = [&](GLenum p) {
      switch (p) {
        case GL_SPOT_EXPONENT: return double(pick(129));
        case GL_SPOT_CUTOFF: return chance(0.3) ? 180.0 : double(pick(91));
        default: return std::round(uni(0, 2) * 8) / 8;
      }
    };
    switch (pick(9)) {
      case 0: case 1: {
        const GLenum p = light_pnames[pick(10)];
        std::vector<double> v = {colour(), colour(), colour(), colour()};
        if (p == GL_POSITION) v = {coord() * 3, coord() * 3, coord() * 3, double(pick(2))};
        if (p == GL_SPOT_DIRECTION) v = {coord(), coord(), coord(), 0};
        if (p >= GL_SPOT_EXPONENT) v = {scalar_light(p), 0, 0, 0};
        emit("glLightfv", {num(light()), num(p), floats(v)});
        break;
      }
      case 2: {
        const GLenum p = light_pnames[5 + pick(5)];
        if (chance(0.5)) emit("glLightf", {num(light()), num(p), num(scalar_light(p))});
        else emit("glLighti", {num(light()), num(p), num(std::round(scalar_light(p)))});
        break;
      }
      case 3: {
        const GLenum p = light_pnames[pick(10)];
        if (o_.has("extreme"))
          emit("glLightiv", {num(light()), num(p), ints({double(pick(2000) - 1000) * 1e6, double(pick(90)), 2147483647, double(pick(3))})});
        else
          emit("glLightiv", {num(light()), num(p), ints({double(pick(5) - 2), double(pick(90)), double(pick(3)), double(pick(2))})});
        break;
      }
      case 4: {
        const GLenum p = one_of({GL_LIGHT_MODEL_AMBIENT, GL_LIGHT_MODEL_LOCAL_VIEWER, GL_LIGHT_MODEL_TWO_SIDE,
                                 GL_LIGHT_MODEL_COLOR_CONTROL});
        const double scalar = p == GL_LIGHT_MODEL_COLOR_CONTROL ? double(one_of({GL_SINGLE_COLOR, GL_SEPARATE_SPECULAR_COLOR})) : double(pick(2));
        switch (pick(4)) {
          case 0: emit("glLightModelfv", {num(p), floats(p == GL_LIGHT_MODEL_AMBIENT ? std::vector<double>{colour(), colour(), colour(), 1} : std::vector<double>{scalar, 0, 0, 0})}); break;
          case 1: emit("glLightModelf", {num(p), num(scalar)}); break;
          case 2: emit("glLightModeli", {num(p), num(scalar)}); break;
          default:
            if (o_.has("extreme") || p != GL_LIGHT_MODEL_AMBIENT) emit("glLightModeliv", {num(p), ints({p == GL_LIGHT_MODEL_AMBIENT ? 1e9 : scalar, 5e8, 0, 2147483647})});
            break;
        }
        break;
      }
      case 5: case 6: {
        const GLenum p = one_of({GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION, GL_SHININESS, GL_AMBIENT_AND_DIFFUSE});
        const GLenum f = faces[pick(3)];
        std::vector<double> v = {colour(), colour(), colour(), colour()};
        if (p == GL_SHININESS) v = {double(pick(129)), 0, 0, 0};
        if (chance(0.7)) emit("glMaterialfv", {num(f), num(p), floats(v)});
        else if (chance(0.5) && (o_.has("extreme") || p == GL_SHININESS)) emit("glMaterialiv", {num(f), num(p), ints({1e9, -5e8, 2147483647, double(pick(129))})});
        else emit(chance(0.5) ? "glMaterialf" : "glMateriali", {num(f), num(GL_SHININESS), num(double(pick(129)))});
        break;
      }
      case 7:
        if (!o_.has("colormaterial")) return lighting_call();
        emit("glColorMaterial", {num(faces[pick(3)]), num(one_of({GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION, GL_AMBIENT_AND_DIFFUSE}))});
        break;
      default:
        if (!o_.has("colormaterial")) return lighting_call();
        emit(chance(0.6) ? "glEnable" : "glDisable", {num(GL_COLOR_MATERIAL)});
        break;
    }
  }

  std::vector<double> matrix16() {
    std::vector<double> m(16);
    for (int i = 0; i < 16; ++i) m[size_t(i)] = (i % 5 == 0 ? 1 : 0) + (chance(0.5) ? uni(-0.5, 0.5) : 0);
    return m;
  }
  void matrix_call() {
    switch (pick(9)) {
      case 0: emit("glMatrixMode", {num(one_of({GL_MODELVIEW, GL_MODELVIEW, GL_PROJECTION}))}); break;
      case 1: emit(chance(0.5) ? "glRotatef" : "glRotated", {num(uni(-180, 180)), num(uni(-1, 1)), num(uni(-1, 1)), num(uni(-1, 1))}); break;
      case 2: emit(chance(0.5) ? "glScalef" : "glScaled", {num(uni(0.3, 2)), num(uni(0.3, 2)), num(uni(0.3, 2))}); break;
      case 3: emit(chance(0.5) ? "glTranslatef" : "glTranslated", {num(uni(-1, 1)), num(uni(-1, 1)), num(uni(-1, 1))}); break;
      case 4: emit("glLoadMatrixf", {floats(matrix16())}); break;
      case 5: emit("glLoadMatrixd", {Arg::values(GL_DOUBLE, matrix16())}); break;
      case 6:
        if (chance(0.5)) emit("glMultMatrixf", {floats(matrix16())});
        else emit("glMultMatrixd", {Arg::values(GL_DOUBLE, matrix16())});
        break;
      case 7: emit("glLoadIdentity", {}); break;
      default: {
        const double s = uni(0.5, 3);
        emit(chance(0.5) ? "glOrtho" : "glFrustum", {num(-s), num(s), num(-s), num(s), num(uni(0.5, 1)), num(uni(2, 20))});
      }
    }
  }
  void stack_call() {
    const int n = chance(0.1) ? 40 : 1 + pick(2);  // 40: past the projection stack's 32
    const bool push = chance(0.55);
    for (int i = 0; i < n; ++i) emit(push ? "glPushMatrix" : "glPopMatrix", {});
  }
  void viewport_call() {
    if (chance(0.6)) emit("glViewport", {num(pick(16) - 4), num(pick(16) - 4), num(8 + pick(40)), num(8 + pick(40))});
    else emit("glDepthRange", {num(std::round(uni(0, 1) * 8) / 8), num(std::round(uni(0, 1) * 8) / 8)});
  }

  // ------------------------------------------------------------ drawing
  GLenum mode() {
    std::vector<GLenum> m;
    if (o_.has("points")) m.push_back(GL_POINTS);
    if (o_.has("lines")) m.insert(m.end(), {GL_LINES, GL_LINE_STRIP, GL_LINE_LOOP});
    if (o_.has("triangles")) m.insert(m.end(), {GL_TRIANGLES, GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN});
    if (o_.has("quads")) m.insert(m.end(), {GL_QUADS, GL_QUAD_STRIP});
    if (o_.has("polygons")) m.push_back(GL_POLYGON);
    return m.empty() ? GLenum(0xFFFF) : m[size_t(pick(int(m.size())))];
  }
  bool can_draw() { return mode() != 0xFFFF; }

  void attribute() {
    if (chance(0.5)) {
      const double x = uni(-1, 1), y = uni(-1, 1), z = uni(-1, 1);
      switch (pick(4)) {
        case 0: emit("glNormal3f", {num(x), num(y), num(z)}); break;
        case 1: emit("glNormal3fv", {floats({x, y, z})}); break;
        case 2: emit("glNormal3d", {num(x), num(y), num(z)}); break;
        default: emit("glNormal3dv", {Arg::values(GL_DOUBLE, {x, y, z})}); break;
      }
    } else {
      switch (pick(5)) {
        case 0: emit("glColor3f", {num(colour()), num(colour()), num(colour())}); break;
        case 1: emit("glColor3fv", {floats({colour(), colour(), colour()})}); break;
        case 2: emit("glColor3ub", {num(pick(256)), num(pick(256)), num(pick(256))}); break;
        case 3: emit("glColor4f", {num(colour()), num(colour()), num(colour()), num(colour())}); break;
        default: emit("glColor4fv", {floats({colour(), colour(), colour(), colour()})}); break;
      }
    }
  }
  void vertex() {
    const double x = coord(), y = coord(), z = coord();
    if (arrays_set_ && chance(0.15)) return emit("glArrayElement", {num(pick(kArrayVertices))});
    switch (pick(5)) {
      case 0: emit("glVertex2f", {num(x), num(y)}); break;
      case 1: emit("glVertex3f", {num(x), num(y), num(z)}); break;
      case 2: emit("glVertex3fv", {floats({x, y, z})}); break;
      case 3: emit("glVertex3d", {num(x), num(y), num(z)}); break;
      default: emit("glVertex3dv", {Arg::values(GL_DOUBLE, {x, y, z})}); break;
    }
  }
  // A call GL forbids between glBegin and glEnd.
  void misplaced() {
    switch (pick(5)) {
      case 0: emit("glFinish", {}); break;
      case 1: emit("glEnable", {num(GL_LIGHTING)}); break;
      case 2: emit("glLoadIdentity", {}); break;
      case 3: emit("glBegin", {num(GL_TRIANGLES)}); break;
      default: emit("glViewport", {num(0), num(0), num(16), num(16)}); break;
    }
  }
  void immediate_draw() {
    if (!can_draw()) return state_call();
    emit("glBegin", {num(mode())});
    in_begin_ = true;
    const int n = 1 + pick(9);
    for (int i = 0; i < n; ++i) {
      while (chance(0.5)) attribute();
      if (o_.has("invalid") && chance(0.05)) misplaced();
      vertex();
    }
    if (o_.has("trailing") && chance(0.5)) attribute();
    emit("glEnd", {});
    in_begin_ = false;
  }

  // An array of kArrayVertices elements of `size` components of `type`, `pad` elements apart
  // beyond them (the stride), values from `value`.
  template <class F>
  Arg array(GLenum type, int size, int pad, F value) {
    std::vector<double> v;
    for (int i = 0; i < kArrayVertices; ++i) {
      for (int c = 0; c < size; ++c) v.push_back(value(c));
      for (int p = 0; p < pad; ++p) v.push_back(0);
    }
    return Arg::values(type, std::move(v));
  }
  // A stride in bytes that is the packed one (0 or explicit) or a padded one.
  int stride(GLenum type, int size, int& pad) {
    pad = chance(0.6) ? 0 : 1 + pick(3);
    if (pad == 0 && chance(0.5)) return 0;
    return (size + pad) * type_size(type);
  }
  void set_arrays() {
    {  // positions: integers for the integer types, on the coordinate grid for the others
      const GLenum type = one_of({GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE});
      const int size = 2 + pick(3);
      int pad;
      const int st = stride(type, size, pad);
      const bool whole = type == GL_SHORT || type == GL_INT;
      emit("glVertexPointer", {num(size), num(type), num(st), array(type, size, pad, [&](int c) {
             return c == 3 ? (whole ? 1.0 + pick(2) : uni(0.5, 2)) : whole ? double(pick(5) - 2) : coord();
           })});
    }
    {
      const GLenum type = one_of({GL_BYTE, GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE});
      int pad;
      const int st = stride(type, 3, pad);
      const double range = type == GL_BYTE ? 127 : type == GL_SHORT ? 32767 : type == GL_INT ? 2147483647.0 : 1;
      emit("glNormalPointer", {num(type), num(st), array(type, 3, pad, [&](int) { return range == 1 ? std::round(uni(-1, 1) * 64) / 64 : std::round(uni(-1, 1) * range); })});
    }
    {
      const GLenum type = one_of({GL_BYTE, GL_UNSIGNED_BYTE, GL_SHORT, GL_UNSIGNED_SHORT, GL_INT, GL_UNSIGNED_INT, GL_FLOAT, GL_DOUBLE});
      const int size = 3 + pick(2);
      int pad;
      const int st = stride(type, size, pad);
      const double top = type == GL_BYTE ? 127 : type == GL_UNSIGNED_BYTE ? 255 : type == GL_SHORT ? 32767
                       : type == GL_UNSIGNED_SHORT ? 65535 : type == GL_INT ? 2147483647.0 : type == GL_UNSIGNED_INT ? 4294967295.0 : 1;
      emit("glColorPointer", {num(size), num(type), num(st), array(type, size, pad, [&](int) {
             return type == GL_FLOAT || type == GL_DOUBLE ? colour() : std::round(std::round(uni(0, 1) * 8) / 8 * top);
           })});
    }
    emit("glEnableClientState", {num(GL_VERTEX_ARRAY)});
    for (GLenum a : {GL_NORMAL_ARRAY, GL_COLOR_ARRAY})
      emit(chance(0.7) ? "glEnableClientState" : "glDisableClientState", {num(a)});
    arrays_set_ = true;
  }
  void array_draw() {
    if (!arrays_set_ || chance(0.2)) set_arrays();
    if (!can_draw()) return;
    const int first = pick(kArrayVertices / 2), count = 1 + pick(kArrayVertices - first);
    switch (pick(3)) {
      case 0: emit("glDrawArrays", {num(mode()), num(first), num(count)}); break;
      case 1: {
        const GLenum type = one_of({GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT, GL_UNSIGNED_INT});
        std::vector<double> idx(static_cast<size_t>(count));
        for (double& i : idx) i = pick(kArrayVertices);
        emit("glDrawElements", {num(mode()), num(count), num(type), Arg::values(type, idx)});
        break;
      }
      default:
        emit("glBegin", {num(mode())});
        in_begin_ = true;
        for (int i = 0; i < count; ++i) emit("glArrayElement", {num(first + i)});
        emit("glEnd", {});
        in_begin_ = false;
    }
  }

  void feedback_call() {
    if (in_feedback_) {
      emit("glRenderMode", {num(GL_RENDER)});
      in_feedback_ = false;
      return;
    }
    const int size = one_of({16, 256, 2048});
    emit("glFeedbackBuffer", {num(size), num(one_of({GL_2D, GL_3D, GL_3D_COLOR, GL_3D_COLOR, GL_3D_COLOR_TEXTURE, GL_4D_COLOR_TEXTURE})), Arg::out(size)});
    emit("glRenderMode", {num(GL_FEEDBACK)});
    in_feedback_ = true, in_select_ = false;
  }

  // Lists 1 to 6 (and 7, never compiled): calls made while one compiles are recorded.
  void list_call() {
    if (compiling_ && chance(0.5)) {
      emit("glEndList", {});
      compiling_ = false;
      return;
    }
    switch (pick(8)) {
      case 0: case 1: {
        const int name = 1 + pick(6);
        emit("glNewList", {num(name), num(chance(0.7) ? GL_COMPILE : GL_COMPILE_AND_EXECUTE)});
        if (!compiling_) list_name_ = name, calls_in_list_ = 0;  // a second glNewList is an error and changes nothing
        compiling_ = true;
        break;
      }
      case 2: case 3: case 4: {
        // A list calls at most one list: lists calling each other twice or more would run 2^64
        // times through the nesting limit (Mesa and soft alike never return).
        if (compiling_ && calls_in_list_++ > 0) return emit("glListBase", {num(pick(3))});
        if (pick(3) < 2) return emit("glCallList", {num(1 + pick(7))});
        const GLenum type = GLenum(GL_BYTE + pick(10));
        const int bytes = type == GL_2_BYTES ? 2 : type == GL_3_BYTES ? 3 : type == GL_4_BYTES ? 4 : 1;
        const int n = compiling_ ? 1 : 1 + pick(4);
        std::vector<double> names;
        for (int k = 0; k < n * bytes; ++k) names.push_back(bytes > 1 && k % bytes != bytes - 1 ? 0 : pick(8) - 1);
        emit("glCallLists", {num(n), num(type), Arg::values(bytes > 1 ? GLenum(GL_UNSIGNED_BYTE) : type, names)});
        break;
      }
      case 5: emit("glListBase", {num(pick(3))}); break;
      case 6: emit(chance(0.5) ? "glGenLists" : "glIsList", {num(pick(4))}); break;
      case 7: emit("glDeleteLists", {num(1 + pick(6)), num(pick(3))}); break;
    }
  }

  void selection_call() {
    if (!in_select_) {
      if (chance(0.6)) {
        const int size = one_of({4, 64, 512});
        emit("glSelectBuffer", {num(size), Arg::out(size)});
        emit("glRenderMode", {num(GL_SELECT)});
        in_select_ = true, in_feedback_ = false;
      } else {
        emit("glPassThrough", {num(uni(-10, 10))});
      }
      return;
    }
    switch (pick(8)) {
      case 0: emit("glRenderMode", {num(GL_RENDER)}); in_select_ = false; break;
      case 1: emit("glInitNames", {}); break;
      case 2: case 3: emit("glPushName", {num(pick(100))}); break;
      case 4: emit("glPopName", {}); break;
      case 5: case 6: emit("glLoadName", {num(pick(100))}); break;
      case 7: emit("glPassThrough", {num(uni(-10, 10))}); break;
    }
  }

  void readpixels_call() {
    if (chance(0.3)) {
      const GLenum p = one_of({GL_PACK_ALIGNMENT, GL_PACK_ROW_LENGTH, GL_PACK_SKIP_ROWS, GL_PACK_SKIP_PIXELS, GL_PACK_SWAP_BYTES, GL_PACK_LSB_FIRST});
      emit("glPixelStorei", {num(p), num(p == GL_PACK_ALIGNMENT ? one_of({1, 2, 4, 8}) : p == GL_PACK_ROW_LENGTH ? one_of({0, 20, 40}) : pick(4))});
      return;
    }
    const int w = 1 + pick(16), h = 1 + pick(16);
    // Room for any format and type and the pack settings above: 8 bytes an element.
    const int room = (40 + 8) * (h + 4) * 4 / 2 + 64;
    emit("glReadPixels", {num(pick(20)), num(pick(20)), num(w), num(h),
                          num(one_of({GL_RGBA, GL_RGBA, GL_RGB, GL_RED, GL_GREEN, GL_BLUE, GL_ALPHA, GL_LUMINANCE, GL_LUMINANCE_ALPHA, GL_BGRA, GL_DEPTH_COMPONENT})),
                          num(one_of({GL_UNSIGNED_BYTE, GL_UNSIGNED_BYTE, GL_FLOAT, GL_UNSIGNED_SHORT, GL_SHORT, GL_INT, GL_UNSIGNED_INT, GL_BYTE})),
                          Arg::out(room)});
  }

  void get_call() {
    const auto& e = known_enums();
    const GLenum any = e[size_t(pick(int(e.size())))];
    switch (pick(7)) {
      case 6: emit("glGetError", {}); break;
      case 0: emit("glGetFloatv", {num(any), Arg::out(16)}); break;
      case 1: emit("glGetDoublev", {num(any), Arg::out(16)}); break;
      case 2: emit("glGetIntegerv", {num(any), Arg::out(16)}); break;
      case 3: emit("glIsEnabled", {num(any)}); break;
      case 4: emit("glGetString", {num(one_of<GLenum>({GL_VENDOR, GL_RENDERER, GL_VERSION, GL_EXTENSIONS, any}))}); break;
      default:
        if (chance(0.5)) emit("glGetLightfv", {num(light()), num(chance(0.8) ? GLenum(GL_AMBIENT + pick(10)) : any), Arg::out(4)});
        else emit("glGetMaterialfv", {num(one_of({GL_FRONT, GL_BACK})), num(one_of<GLenum>({GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION, GL_SHININESS, GL_COLOR_INDEXES, any})), Arg::out(4)});
    }
  }

  void clear_call() {
    switch (pick(3)) {
      case 0: emit("glClear", {num(one_of({GL_COLOR_BUFFER_BIT, GL_DEPTH_BUFFER_BIT, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT}))}); break;
      case 1: emit("glFinish", {}); break;
      default: emit("glFlush", {}); break;
    }
  }

  void fog_call() {
    emit(chance(0.7) ? "glEnable" : "glDisable",
         {num(one_of({GL_FOG, GL_POLYGON_OFFSET_FILL, GL_POLYGON_OFFSET_LINE, GL_BLEND, GL_SCISSOR_TEST, GL_ALPHA_TEST,
                      GL_LINE_SMOOTH, GL_POINT_SMOOTH, GL_POLYGON_SMOOTH, GL_LINE_STIPPLE, GL_DITHER}))});
  }

  void polygon_mode_call() {
    emit("glPolygonMode", {num(one_of({GL_FRONT, GL_BACK, GL_FRONT_AND_BACK, GL_FRONT_AND_BACK})),
                           num(one_of({GL_POINT, GL_LINE, GL_LINE, GL_FILL}))});
  }

  void rasterpos_call() {
    if (chance(0.5)) return emit("glRasterPos2f", {num(coord()), num(coord())});
    const int w = 1 + pick(4), h = 1 + pick(4);
    std::vector<double> px(size_t(w * h * 4));
    for (double& p : px) p = pick(256);
    emit("glDrawPixels", {num(w), num(h), num(GL_RGBA), num(GL_UNSIGNED_BYTE), Arg::values(GL_UNSIGNED_BYTE, px)});
  }

  void huge_call() {
    if (chance(0.5)) {
      const double big = one_of({16384.0, 32768.0, 1e6});
      emit("glViewport", {num(-big / 2), num(-big / 2), num(big), num(big)});
    } else {
      // Vertex array off: Mesa draws all the same, every vertex at the origin (soft too:
      // Context::with_positions), so the count is what it costs: 2^16 and 2^20 vertices take
      // either side a fraction of a second. 2^28 took Mesa seconds (past the fuzzer's timeout
      // when the origin lies outside the view volume and every triangle is clipped), 2^24 lit
      // took soft seconds. Soft's GL_OUT_OF_MEMORY (a draw past half the machine's memory) is
      // left to Issue10Soft.HugeDrawsAreOutOfMemory; the known deviation soft-out-of-memory
      // names it should a small machine meet it here.
      // The other arrays off too: each holds kArrayVertices elements, and both sides would read
      // past them.
      keep_valid_ = true;
      for (GLenum a : {GL_VERTEX_ARRAY, GL_NORMAL_ARRAY, GL_COLOR_ARRAY}) emit("glDisableClientState", {num(a)});
      keep_valid_ = false;
      arrays_set_ = false;
      const int count = one_of({1 << 16, 1 << 20});
      emit("glDrawArrays", {num(GL_TRIANGLES), num(0), num(count)});
    }
  }
};

}  // namespace

Stream generate(uint64_t seed, const GenOptions& o) { return Gen(seed, o).run(); }

}  // namespace ffc::difftest
