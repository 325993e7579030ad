// The stress catalogue: stiff and extreme inputs to the fixed-function pipeline, each a small GL
// program, with what OpenGL 2.1 (compatibility profile) says about it and what Mesa 22.3
// (llvmpipe, through OSMesa) does. Section numbers are OpenGL 2.1's. Facts about Mesa quote its
// source: src/mesa/math/m_matrix.c (the float inverse of the modelview), src/mesa/main/light.c
// (light constants), src/mesa/main/state.c (the rescale factor), src/mesa/main/ffvertex_prog.c
// (the fixed-function vertex program llvmpipe runs).
#include <cmath>
#include <limits>
#include <sstream>

#include <cstring>
#include <memory>

#include "gl/dispatch.h"
#include "gl/glu.h"
#include "stress/scenes.h"
#include "stress/stress.h"

namespace ffc::stress {

namespace {

using scenes::Geometry;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

enum class Normals { Plain, Normalize, Rescale };

void enable(Normals m) {
  if (m == Normals::Normalize) glEnable(GL_NORMALIZE);
  if (m == Normals::Rescale) glEnable(GL_RESCALE_NORMAL);
}

const char* suffix(Normals m) {
  return m == Normals::Normalize ? "normalize" : m == Normals::Rescale ? "rescale" : "plain";
}

std::string num(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

// --- hand-derived checks

// Every feedback vertex of our two backends has colour `want` (within `tol`).
std::function<std::string(const Observed&)> all_vertices_are(glm::dvec4 want, double tol = 1e-5) {
  return [=](const Observed& o) -> std::string {
    for (const Run* r : {&o.soft, &o.dbl}) {
      if (r->feedback.empty()) return "no primitives in our feedback";
      for (const auto& p : r->feedback)
        for (const auto& v : p.vertices)
          for (int k = 0; k < 4; ++k)
            if (!(std::abs(v.color[k] - want[k]) <= tol)) {
              std::ostringstream s;
              s << (r == &o.soft ? "float" : "double") << " vertex colour (" << v.color.r << ", " << v.color.g << ", "
                << v.color.b << ", " << v.color.a << ") where the hand-derived colour is (" << want.r << ", "
                << want.g << ", " << want.b << ", " << want.a << ")";
              return s.str();
            }
    }
    return "";
  };
}

std::string expect_no_primitives(const Observed& o) {
  if (!o.soft.feedback.empty() || !o.dbl.feedback.empty())
    return "our feedback has " + std::to_string(o.soft.feedback.size()) + " primitives where the spec clips all";
  return "";
}

// --- scenes

// The standard sphere (icosphere depth 3) behind translate(0, 0, -4), rotate(30, 1, 1, 0) and
// scale(s); its positions are multiplied by 1/s so the picture stays the same when the inverse
// transpose of the modelview does its job.
std::function<void()> scaled_sphere(glm::dvec3 s, Normals m, bool rotate = true) {
  return [=] {
    scenes::standard();
    enable(m);
    // A flattened sphere's front and back lie at one depth: only the front is drawn. (A sphere
    // scaled to a point has no pixels: its triangles stay, for feedback.)
    const int zeros = (s.x == 0) + (s.y == 0) + (s.z == 0);
    if (zeros == 1 || zeros == 2) glEnable(GL_CULL_FACE);
    glTranslatef(0, 0, -4);
    if (rotate) glRotatef(30, 1, 1, 0);
    glScaled(s.x, s.y, s.z);
    auto inv = [](double x) { return x != 0 ? 1 / x : 1.0; };
    scenes::draw(scenes::sphere(3), {inv(s.x), inv(s.y), inv(s.z)});
  };
}

// The standard sphere at (0, 0, -4) with its normals multiplied by `k`.
std::function<void()> sphere_normals_times(double k, Normals m) {
  return [=] {
    scenes::standard();
    enable(m);
    const GLfloat e[] = {0.1f, 0.05f, 0, 1};
    glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, e);
    glTranslatef(0, 0, -4);
    scenes::draw(scenes::sphere(3), 1, k);
  };
}

// A 16x16 grid facing the viewer at z = -3 (its centre is a grid vertex, on the optical axis,
// window (32, 32)), lit by GL_LIGHT0 set up by `light` (in eye space), no other light.
std::function<void()> lit_grid(std::function<void()> light, int n = 16) {
  return [=] {
    scenes::standard();
    light();
    glTranslatef(0, 0, -3);
    scenes::draw(scenes::grid(n), 0.9);
  };
}

void spot(glm::vec4 pos, glm::vec3 dir, float cutoff, float exponent) {
  const GLfloat p[] = {pos.x, pos.y, pos.z, pos.w}, d[] = {dir.x, dir.y, dir.z};
  glLightfv(GL_LIGHT0, GL_POSITION, p);
  glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, d);
  glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, cutoff);
  glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, exponent);
}

// A grid of quads drawn from a float array with one poisoned value (at vertex `at`, component
// `k`: 0-2 position, 3-5 normal).
std::function<void()> poisoned_grid(int at, int k, double value) {
  return [=] {
    scenes::standard();
    glTranslatef(0, 0, -3);
    const Geometry g = scenes::grid(8);
    std::vector<float> v;
    for (size_t i = 0; i < g.positions.size(); ++i) {
      for (int c = 0; c < 3; ++c) v.push_back(float(g.positions[i][c] * 0.9));
      for (int c = 0; c < 3; ++c) v.push_back(float(g.normals[i][c]));
    }
    v[size_t(at) * 6 + size_t(k)] = float(value);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glVertexPointer(3, GL_FLOAT, 6 * sizeof(float), v.data());
    glNormalPointer(GL_FLOAT, 6 * sizeof(float), v.data() + 3);
    glDrawElements(GL_TRIANGLES, GLsizei(g.indices.size()), GL_UNSIGNED_INT, g.indices.data());
  };
}

// The sphere with its normals in an integer type (GL 2.1 table 2.9 maps them to [-1, 1]), the
// extremes included: each normal scaled to the type's range, and every 7th vertex's normal
// replaced by the most negative value on every axis.
template <typename T>
std::function<void()> integer_normals(GLenum type, bool normalize) {
  return [=] {
    scenes::standard();
    if (normalize) glEnable(GL_NORMALIZE);
    glTranslatef(0, 0, -4);
    const Geometry& g = scenes::sphere(3);
    std::vector<float> p;
    std::vector<T> n;
    const double range = double(std::numeric_limits<T>::max());
    for (size_t i = 0; i < g.positions.size(); ++i)
      for (int c = 0; c < 3; ++c) {
        p.push_back(float(g.positions[i][c]));
        n.push_back(i % 7 == 3 ? std::numeric_limits<T>::min() : T(std::lround(g.normals[i][c] * range)));
      }
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, p.data());
    glNormalPointer(type, 0, n.data());
    glDrawElements(GL_TRIANGLES, GLsizei(g.indices.size()), GL_UNSIGNED_INT, g.indices.data());
  };
}

// Geometry drawn with face normals under a directional light, fitted to the view by glOrtho.
std::function<void()> mesh_scene(std::function<Geometry()> make, Normals m, double extent = 1.3) {
  auto g = std::make_shared<Geometry>();
  auto made = std::make_shared<bool>(false);
  return [=] {
    if (!*made) *g = make(), *made = true;
    scenes::standard();
    enable(m);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-extent, extent, -extent, extent, -10, 10);
    glMatrixMode(GL_MODELVIEW);
    const GLfloat dir[] = {0.3f, 0.4f, 1, 0};
    glLightfv(GL_LIGHT0, GL_POSITION, dir);
    glRotatef(-20, 1, 0, 0);
    scenes::draw(*g);
  };
}

// A modelview looking at `target` (a point near the unit sphere) from outside along its direction.
void gluLookAtLike(const std::array<double, 3>& target) {
  const double len = std::sqrt(target[0] * target[0] + target[1] * target[1] + target[2] * target[2]);
  const double e[3] = {target[0] / len * 2, target[1] / len * 2, target[2] / len * 2};
  gluLookAt(e[0], e[1], e[2], target[0], target[1], target[2], 0, 1, 0);
}

// A patch of the icosphere seen face on from outside, its centroid in the middle, 1.2 wide.
void draw_patch_face_on(const Geometry& g) {
  scenes::standard();
  const auto ctr = scenes::centroid(g);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-0.6, 0.6, -0.6, 0.6, -3, 3);
  glMatrixMode(GL_MODELVIEW);
  gluLookAtLike(ctr);
  scenes::draw(g);
}

std::vector<Case> build() {
  std::vector<Case> out;
  auto add = [&](Case c) { out.push_back(std::move(c)); };
  const std::string kMesaInverse =
      " Mesa inverts the modelview in float by its kind (m_matrix.c): a uniform scale with rotation "
      "takes 1/(sum of squares of a row), a scale without rotation 1/s per axis, anything else "
      "the 3x3 adjugate, refused when |det| < 1e-25; a refused matrix is 'singular' and its inverse "
      "is the identity.";

  // ------------------------------------------------------------------ scale
  for (Normals m : {Normals::Normalize, Normals::Rescale, Normals::Plain}) {
    const std::string s = suffix(m);
    Case c;
    c.group = "scale";
    c.name = "scale_1e-6_" + s;
    c.draw = scaled_sphere({1e-6, 1e-6, 1e-6}, m);
    c.note = "glScalef(1e-6) under a rotation, the sphere's coordinates multiplied by 1e6. Normals "
             "transform by the inverse transpose (2.11.3): they come out 1e6 long. " +
             std::string(m == Normals::Normalize ? "GL_NORMALIZE brings them back to unit length: the picture is the unscaled sphere's."
                         : m == Normals::Rescale ? "GL_RESCALE_NORMAL divides by the length of M^-1's third row (1e6): exactly unit for a uniform scale, so this equals GL_NORMALIZE (the test compares them)."
                                                 : "Neither: n.L is 1e6 times too large and the diffuse and specular terms saturate where n.L > 0; the clamp to [0,1] (2.14.6) keeps the colours in range.");
    add(c);
  }
  for (Normals m : {Normals::Normalize, Normals::Rescale, Normals::Plain}) {
    const std::string s = suffix(m);
    Case c;
    c.group = "scale";
    c.name = "scale_1e6_" + s;
    c.draw = scaled_sphere({1e6, 1e6, 1e6}, m);
    c.note = "glScalef(1e6) under a rotation, coordinates multiplied by 1e-6: the normals come out 1e-6 long. " +
             std::string(m == Normals::Normalize ? "GL_NORMALIZE restores them."
                         : m == Normals::Rescale ? "GL_RESCALE_NORMAL multiplies by 1e6 (1 / the length of M^-1's third row)."
                                                 : "Neither: the diffuse and specular terms are a millionth of their size; only ambient and emission remain visible.");
    if (m == Normals::Rescale) {
      c.note += " Mesa computes the rescale factor from its float inverse as 1/sqrt(f), f = m[2]^2 + m[6]^2 + m[10]^2, "
                "but takes f = 1 when f < 1e-12 (state.c, update_modelview_scale): at a scale of 1e6, f is 1e-12 within float rounding.";
    }
    add(c);
  }
  {
    Case c;
    c.group = "scale";
    c.name = "scale_1e7_rescale";
    c.draw = scaled_sphere({1e7, 1e7, 1e7}, Normals::Rescale);
    c.note = "glScalef(1e7) under a rotation with GL_RESCALE_NORMAL: the spec's factor (2.11.3) is 1e7 and "
             "makes the 1e-7-long normals unit. Mesa takes f = 1 when f = m[2]^2 + m[6]^2 + m[10]^2 of its "
             "inverse is below 1e-12 (state.c, update_modelview_scale), here 1e-14: it does not rescale, "
             "the normals stay 1e-7 long and only ambient remains.";
    c.mesa = MesaExpectation::Deviation;
    c.mesa_reason = "Mesa skips GL_RESCALE_NORMAL when its factor's f is below 1e-12 (uniform scales above 1e6)";
    add(c);
  }
  for (Normals m : {Normals::Normalize, Normals::Rescale, Normals::Plain}) {
    Case c;
    c.group = "scale";
    c.name = std::string("scale_1e-30_") + suffix(m);
    c.draw = scaled_sphere({1e-30, 1e-30, 1e-30}, m);
    c.note = "glScalef(1e-30) under a rotation, coordinates multiplied by 1e30 (still finite in float). "
             "Well conditioned but with a determinant of 1e-90: the spec cannot specify behaviour for a "
             "poorly conditioned or nearly singular modelview (2.11.3)." + kMesaInverse +
             " Here the row's sum of squares, 1e-60, underflows float: Mesa calls the matrix singular and "
             "transforms normals by the identity, so they are not rotated with the sphere. Ours inverts in "
             "double (exactly 1e30 times the rotation).";
    c.mesa = MesaExpectation::Undefined;
    c.mesa_reason = "nearly singular modelview: Mesa's float inverse underflows and it uses the identity";
    add(c);
  }
  for (Normals m : {Normals::Normalize, Normals::Plain}) {
    Case c;
    c.group = "scale";
    c.name = std::string("scale_1e30_") + suffix(m);
    c.draw = scaled_sphere({1e30, 1e30, 1e30}, m);
    c.note = "glScalef(1e30) under a rotation, coordinates multiplied by 1e-30: beyond the 2^32 that "
             "floating-point values must reach (2.1.1), so unspecified." + kMesaInverse +
             " Here the row's sum of squares, 1e60, overflows float to infinity and Mesa's inverse is 1/inf = 0: "
             "every normal becomes zero" +
             std::string(m == Normals::Normalize ? " (GL_NORMALIZE then makes NaN, which Mesa's lighting drops: ambient only)"
                                                 : ", and ours are 1e-30 long: ambient only on both") +
             ". Ours inverts in double.";
    c.mesa = MesaExpectation::Undefined;
    c.mesa_reason = "beyond float range: Mesa's float inverse overflows to a zero normal matrix";
    add(c);
  }
  for (Normals m : {Normals::Normalize, Normals::Rescale, Normals::Plain}) {
    Case c;
    c.group = "scale";
    c.name = std::string("scale_0_z_") + suffix(m);
    c.draw = scaled_sphere({1, 1, 0}, m);
    c.note = "glScalef(1, 1, 0) under a rotation flattens the sphere: the modelview is singular. 2.11.3: "
             "'In case of an exactly singular matrix, the transformed normal is undefined. If the GL "
             "implementation determines that the model-view matrix is uninvertible, then the entries in the "
             "inverted matrix are arbitrary.' It must not interrupt the GL." + kMesaInverse +
             " Here the determinant is exactly 0 and Mesa uses the identity; so does ours (a singular "
             "modelview, see modelview_singular_rank2, gives the identity). Back faces are culled: the "
             "flattened sphere's front and back share one depth.";
    c.mesa = MesaExpectation::Undefined;
    c.mesa_reason = "singular modelview: the transformed normal is undefined";
    add(c);
  }
  {
    Case c;
    c.group = "scale";
    c.name = "scale_0_all_normalize";
    c.draw = scaled_sphere({0, 0, 0}, Normals::Normalize);
    c.note = "glScalef(0, 0, 0): every vertex lands on one point and every normal is undefined (2.11.3). "
             "The triangles have no area: nothing is drawn, but feedback reports each one (feedback is "
             "after clipping, before rasterization; culling is off), with the colour the identity normal "
             "matrix gives (Mesa's choice for a singular modelview, and ours).";
    c.mesa = MesaExpectation::Undefined;
    c.mesa_reason = "singular modelview: the transformed normal is undefined";
    add(c);
  }
  for (Normals m : {Normals::Normalize, Normals::Rescale}) {
    Case c;
    c.group = "scale";
    c.name = std::string("scale_nonuniform_1e-6_") + suffix(m);
    c.draw = scaled_sphere({1e-6, 1, 1}, m);
    c.note = "glScalef(1e-6, 1, 1) under a rotation, x coordinates multiplied by 1e6: non-singular "
             "(det 1e-6), so the inverse transpose is defined and Mesa's adjugate inverse takes it. " +
             std::string(m == Normals::Normalize ? "GL_NORMALIZE: the picture is the unscaled sphere's."
                                                 : "GL_RESCALE_NORMAL's factor is defined for any matrix (2.11.3) but makes unit normals only for a uniform scale: the normals here are up to 1e6 long and the lighting saturates.");
    add(c);
  }
  {
    Case c;
    c.group = "scale";
    c.name = "modelview_singular_rank2";
    c.draw = [] {
      scenes::standard();
      glEnable(GL_NORMALIZE);
      glTranslatef(0, 0, -4);
      // I - n n^T with n = (1, 1, 1)/sqrt(3): the projection onto a tilted plane, rank 2.
      const double t = 1.0 / 3;
      const GLdouble mtx[16] = {1 - t, -t, -t, 0, -t, 1 - t, -t, 0, -t, -t, 1 - t, 0, 0, 0, 0, 1};
      glMultMatrixd(mtx);
      glEnable(GL_CULL_FACE);  // the flattened sphere's front and back lie at one depth
      scenes::draw(scenes::sphere(3));
    };
    c.note = "A rank-2 modelview (the projection onto the plane through the origin normal to (1,1,1), as "
             "a planar-shadow matrix is): singular, so the transformed normal is undefined (2.11.3) and may "
             "be anything but must not stop the GL. Rounding hides the singularity: Mesa's float "
             "determinant is exactly 0 and it uses the identity; ours, in double, gets 8e-17, whose "
             "inverse would be rounding noise times 1e16, so ours calls a matrix singular when |det| is "
             "below 1e-14 of the Hadamard bound (the product of its row or column lengths) and uses the "
             "identity too. Back faces are culled (front and back of the flattened sphere share a depth).";
    c.mesa = MesaExpectation::Undefined;
    c.mesa_reason = "singular modelview: the transformed normal is undefined";
    add(c);
  }
  {
    Case c;
    c.group = "scale";
    c.name = "modelview_near_singular";
    c.draw = scaled_sphere({1e-13, 1e-13, 1}, Normals::Normalize);
    c.note = "glRotatef(30, 1, 1, 0) then glScalef(1e-13, 1e-13, 1), coordinates multiplied back: "
             "determinant 1e-26, perfectly invertible in double. The spec does not specify poorly "
             "conditioned or nearly singular modelviews (2.11.3)." + kMesaInverse +
             " With |det| < 1e-25 Mesa calls it singular and uses the identity: its normals are not "
             "rotated; ours are.";
    c.mesa = MesaExpectation::Undefined;
    c.mesa_reason = "nearly singular modelview: Mesa refuses |det| < 1e-25 and uses the identity";
    add(c);
  }

  // ------------------------------------------------------------------ normals
  for (double k : {1e-3, 1e3}) {
    for (Normals m : {Normals::Plain, Normals::Normalize}) {
      Case c;
      c.group = "normals";
      c.name = std::string("normal_length_") + (k < 1 ? "1e-3_" : "1e3_") + suffix(m);
      c.draw = sphere_normals_times(k, m);
      c.note = "Normals " + num(k) + " long, identity modelview. " +
               std::string(m == Normals::Normalize ? "GL_NORMALIZE makes them unit: the picture is the unit-normal sphere's."
                           : k < 1 ? "Not normalized, n.L and n.h are a thousandth of their size (2.14.1 uses n as given): diffuse a thousandth, specular (n.h)^32 vanishes."
                                   : "Not normalized, n.L is up to 1000 and (n.h)^32 up to 1e96: everything lit saturates at the clamp to [0,1] (2.14.6); where n.L <= 0 only ambient remains.");
      add(c);
    }
  }
  for (Normals m : {Normals::Normalize, Normals::Rescale, Normals::Plain}) {
    Case c;
    c.group = "normals";
    c.name = std::string("normal_zero_") + suffix(m);
    c.draw = sphere_normals_times(0, m);
    // Hand-derived: n = 0 leaves n.L = 0 and no specular (f_i = 0 when n.L = 0), so each vertex is
    // e + a_cm * a_cs + a_cm * a_cl = (0.1, 0.05, 0) + 0.2 * 0.2 + 0.2 * 0.1 = (0.16, 0.11, 0.06),
    // alpha the diffuse alpha, 1.
    c.check = all_vertices_are({0.16, 0.11, 0.06, 1});
    c.note = "Zero-length normals. Without GL_NORMALIZE the lighting equation (2.14.1) is defined: n.L = 0 "
             "and f_i = 0, so only emission and the ambient terms remain: (0.1, 0.05, 0) + 0.2*0.2 + "
             "0.2*0.1 = (0.16, 0.11, 0.06) at every vertex (checked). GL_RESCALE_NORMAL scales zero to "
             "zero: the same. GL_NORMALIZE divides by zero: unspecified (2.1.1); ours keeps the zero "
             "normal, so the same colour; Mesa normalizes it to NaN (0 * RSQ(0)), which its lighting "
             "drops at max(n.L, 0): the same colour too.";
    if (m == Normals::Normalize) {
      c.mesa = MesaExpectation::Undefined;
      c.mesa_reason = "normalizing a zero-length normal divides by zero";
    }
    add(c);
  }

  // ------------------------------------------------------------------ material and colours
  {
    Case c;
    c.group = "material";
    c.name = "shininess_0";
    c.draw = [] {
      scenes::standard();
      glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 0);
      glTranslatef(0, 0, -4);
      scenes::draw(scenes::sphere(3));
    };
    c.note = "Shininess 0: (n.h)^0 = 1 wherever n.L > 0 (2.14.1 with 0^0 = 1, 2.1.1), so the full "
             "specular colour is added on the whole lit side. Mesa's LIT instruction takes pow(0, 0) as 0, "
             "which matters only where n.h is exactly 0 (not met here).";
    add(c);
  }
  {
    Case c;
    c.group = "material";
    c.name = "shininess_128";
    c.draw = [] {
      scenes::standard();
      glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 128);
      glTranslatef(0, 0, -4);
      scenes::draw(scenes::sphere(3));
    };
    c.note = "Shininess 128, the largest allowed: (n.h)^128 underflows float (to denormals, or to zero "
             "where denormals flush) away from the highlight; the differences are below 1e-30.";
    add(c);
  }
  {
    Case c;
    c.group = "material";
    c.name = "colours_out_of_range";
    c.draw = [] {
      scenes::standard();
      const GLfloat ld[] = {4, 3, -2, 1}, ls[] = {10, -5, 10, 1}, la[] = {-1, 2, 0.5f, 1};
      glLightfv(GL_LIGHT0, GL_DIFFUSE, ld);
      glLightfv(GL_LIGHT0, GL_SPECULAR, ls);
      glLightfv(GL_LIGHT0, GL_AMBIENT, la);
      const GLfloat e[] = {-0.5f, 0.25f, 1.5f, 1}, ga[] = {2, -1, 0.5f, 1}, md[] = {0.8f, 0.6f, 0.4f, 2.5f};
      glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, e);
      glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, md);
      glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ga);
      glTranslatef(0, 0, -4);
      scenes::draw(scenes::sphere(3));
    };
    c.note = "Light and material colours above 1 and below 0 (diffuse 4, specular 10 and -5, ambient -1, "
             "emission -0.5, global ambient 2, diffuse alpha 2.5). GL 2.1 takes them unclamped into the "
             "lighting equation (2.14.1) and clamps only the result to [0,1] (2.14.6), alpha included.";
    add(c);
  }

  // ------------------------------------------------------------------ spot lights
  {
    Case c;
    c.group = "spot";
    c.name = "spot_exponent_128";
    c.draw = lit_grid([] { spot({0, 0, 0, 1}, {0, 0, -1}, 30, 128); });
    c.note = "A spot light at the eye looking down the axis, cutoff 30, exponent 128 (the largest): "
             "(cos)^128 falls from 1 to 1e-8 across the cone (2.14.1); below about 1e-38 it underflows.";
    add(c);
  }
  {
    Case c;
    c.group = "spot";
    c.name = "spot_cutoff_0";
    c.draw = lit_grid([] { spot({0, 0, 0, 1}, {0, 0, -1}, 0, 0); });
    c.note = "Cutoff 0 (allowed: [0, 90] and 180): a vertex is lit only when the direction from the light "
             "makes cos >= cos(0) = 1 with the spot axis (2.14.1), so only the grid's centre vertex, exactly "
             "on the axis, is lit (checked; VP is exactly (0, 0, -1) there): every other vertex has the "
             "global ambient only, 0.2*0.2 = 0.04 (a spot light outside its cone contributes nothing, its "
             "ambient included). Mesa lights nothing: its spot test is strict (ffvertex_prog.c: SLT, lit "
             "when cos > cos cutoff), and no cos exceeds 1.";
    c.check = [](const Observed& o) -> std::string {
      for (const Run* r : {&o.soft, &o.dbl}) {
        int lit_at_axis = 0;
        for (const auto& p : r->feedback)
          for (const auto& v : p.vertices) {
            const bool axis = std::abs(v.position.x - 32) < 1e-3 && std::abs(v.position.y - 32) < 1e-3;
            const bool ambient_only = std::abs(v.color.r - 0.04) < 1e-6 && std::abs(v.color.g - 0.04) < 1e-6 &&
                                      std::abs(v.color.b - 0.04) < 1e-6;
            if (axis) lit_at_axis += !ambient_only;
            else if (!ambient_only)
              return "a vertex off the axis, at (" + num(v.position.x) + ", " + num(v.position.y) + "), is lit";
          }
        if (lit_at_axis == 0) return std::string(r == &o.soft ? "float" : "double") + ": the axis vertex is not lit";
      }
      return "";
    };
    c.mesa = MesaExpectation::Deviation;
    c.mesa_reason = "Mesa's spot test is strict (SLT: lit when cos > cos cutoff), 2.14.1's is cos >= cos cutoff";
    add(c);
  }
  {
    Case c;
    c.group = "spot";
    c.name = "spot_cutoff_90_boundary";
    c.draw = lit_grid([] { spot({0, 0, -2, 1}, {1, 0, 0}, 90, 0); });
    c.note = "Cutoff 90, exponent 0, the light 1 unit in front of the grid pointing along +x: the grid's "
             "column x = 0 is exactly on the cone's boundary (cos = 0 = cos 90). 2.14.1 lights it (cos >= "
             "cos(cutoff)) with spot factor 0^0 = 1 (2.1.1): the column is lit (checked), the half x < 0 "
             "has the global ambient only. Ours takes cos 90 as exactly 0 (cos(pi/2) rounds to 6e-17, "
             "which left the column dark before). Mesa leaves it dark: its spot test is strict (SLT in "
             "ffvertex_prog.c) and its cos 90 is 6e-17 (light.c).";
    c.check = [](const Observed& o) -> std::string {
      for (const Run* r : {&o.soft, &o.dbl}) {
        int column = 0;
        for (const auto& p : r->feedback)
          for (const auto& v : p.vertices) {
            if (std::abs(v.position.x - 32) > 1e-3) continue;
            ++column;
            if (v.color.r < 0.2) return "a vertex on the cone's boundary, at y = " + num(v.position.y) + ", is dark";
          }
        if (column == 0) return "no vertex on the boundary column";
      }
      return "";
    };
    c.mesa = MesaExpectation::Deviation;
    c.mesa_reason = "Mesa's spot test is strict (SLT: lit when cos > cos cutoff), 2.14.1's is cos >= cos cutoff";
    add(c);
  }
  {
    Case c;
    c.group = "spot";
    c.name = "spot_cutoff_180_exponent_128";
    c.draw = lit_grid([] { spot({0, 0, 0, 1}, {1, 0, 0}, 180, 128); });
    c.note = "Cutoff 180 is no spot light at all: the spot factor is 1 whatever the direction and "
             "exponent (2.14.1), here a direction pointing away from the grid and exponent 128.";
    add(c);
  }
  {
    Case c;
    c.group = "spot";
    c.name = "spot_direction_zero";
    c.draw = lit_grid([] { spot({0, 0, 0, 1}, {0, 0, 0}, 60, 2); });
    c.note = "A zero spot direction, cutoff 60: the spot factor uses the unit spot direction (2.14.1), "
             "and normalizing zero is a division by zero: unspecified (2.1.1). Ours and Mesa "
             "(light.c normalizes with a guard) keep it zero, so cos = 0 < cos 60 and the light "
             "contributes nothing.";
    c.mesa = MesaExpectation::Undefined;
    c.mesa_reason = "a zero spot direction has no unit vector";
    add(c);
  }

  // ------------------------------------------------------------------ attenuation
  {
    Case c;
    c.group = "attenuation";
    c.name = "attenuation_zero";
    c.draw = lit_grid([] {
      const GLfloat p[] = {0, 0, 0, 1};
      glLightfv(GL_LIGHT0, GL_POSITION, p);
      glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, 0);
    });
    c.note = "Constant, linear and quadratic attenuation all 0 (each is allowed: >= 0): the attenuation "
             "1/(k0 + k1 d + k2 d^2) divides by zero, unspecified (2.1.1). In IEEE it is +inf: channels "
             "with a positive sum go to +inf and clamp to 1 (here every channel: the light's ambient is "
             "0.1); a channel whose sum is 0 would be inf * 0 = NaN (see attenuation_zero_dark_channel).";
    c.mesa = MesaExpectation::Undefined;
    c.mesa_reason = "attenuation 1/0";
    add(c);
  }
  {
    Case c;
    c.group = "attenuation";
    c.name = "attenuation_zero_dark_channel";
    c.draw = lit_grid([] {
      const GLfloat p[] = {0, 0, 0, 1}, d[] = {1, 0.5f, 0, 1}, zero[] = {0, 0, 0, 1};
      glLightfv(GL_LIGHT0, GL_POSITION, p);
      glLightfv(GL_LIGHT0, GL_DIFFUSE, d);
      glLightfv(GL_LIGHT0, GL_SPECULAR, zero);
      glLightfv(GL_LIGHT0, GL_AMBIENT, zero);
      glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, 0);
    });
    c.note = "Attenuation all 0 with a light whose blue is 0 (diffuse (1, 0.5, 0), no ambient or "
             "specular): red and green are +inf and clamp to 1; blue is +inf * 0 = NaN, unspecified "
             "(2.1.1). Mesa's clamp, min(max(x, 0), 1) with a max that keeps a NaN and a min that drops "
             "it, makes it 1; ours does the same at the end of lighting, so no NaN reaches the raster.";
    c.mesa = MesaExpectation::Undefined;
    c.mesa_reason = "attenuation 1/0";
    add(c);
  }
  {
    Case c;
    c.group = "attenuation";
    c.name = "attenuation_huge_quadratic";
    c.draw = lit_grid([] {
      const GLfloat p[] = {0, 0, 0, 1};
      glLightfv(GL_LIGHT0, GL_POSITION, p);
      glLightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, 1e38f);
    });
    c.note = "Quadratic attenuation 1e38: k2 d^2 overflows float to +inf for d > 1.8, and the attenuation "
             "is 0 (exactly 1/inf) or 1e-38: the light vanishes, well defined.";
    add(c);
  }
  {
    Case c;
    c.group = "attenuation";
    c.name = "light_at_vertex";
    c.draw = lit_grid([] {
      const GLfloat p[] = {0, 0, -3, 1};  // the grid's centre vertex
      glLightfv(GL_LIGHT0, GL_POSITION, p);
      glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 1);
    });
    c.note = "A point light exactly at a vertex (the grid's centre): VP, the unit vector from the vertex "
             "to the light (2.14.1), does not exist there. Ours takes it as zero (n.L = 0: ambient only at "
             "that vertex; attenuation 1/(1 + 0) = 1). Mesa normalizes it as 0 * RSQ(0) = 0 * inf = NaN, "
             "which comes out of its lighting as 1: that vertex is white.";
    c.mesa = MesaExpectation::Undefined;
    c.mesa_reason = "the direction to a light at the vertex does not exist";
    add(c);
  }

  // ------------------------------------------------------------------ positions with w
  {
    Case c;
    c.group = "position";
    c.name = "light_w_tiny";
    c.draw = lit_grid([] {
      const GLfloat p[] = {1, 1, 1, 1e-30f};
      glLightfv(GL_LIGHT0, GL_POSITION, p);
    });
    c.note = "A light position (1, 1, 1, 1e-30): a point light 1.7e30 away (2.14.1 divides by w). In "
             "float |P - V|^2 overflows to +inf and the unit vector VP becomes 0: the grid gets only "
             "ambient, where the double reference lights it as from a direction. Beyond the 2^32 range "
             "floats must cover (2.1.1).";
    c.float_limit = 1;
    c.float_reason = "|P - V|^2 overflows float; the double reference lights the grid";
    add(c);
  }
  {
    Case c;
    c.group = "position";
    c.name = "light_w_negative";
    c.draw = lit_grid([] {
      const GLfloat p[] = {-1, -1, -2, -1};
      glLightfv(GL_LIGHT0, GL_POSITION, p);
    });
    c.note = "A light position (-1, -1, -2, -1): the point (1, 1, 2) in front of the grid (w divides out, "
             "2.14.1).";
    add(c);
  }
  {
    Case c;
    c.group = "position";
    c.name = "vertex_w_tiny";
    c.draw = [] {
      scenes::standard();
      glTranslatef(0, 0, -4);
      scenes::draw_homogeneous(scenes::sphere(3), 1e-30, 1e-30f);
    };
    c.note = "Vertices (x, y, z, 1) * 1e-30 with w = 1e-30: the same projective points as the sphere, and "
             "clipping and the perspective divide make the same picture. For lighting, 2.14.1 takes VP "
             "between homogeneous points, that is between the positions divided by w (soft-spec lights "
             "the sphere as with w = 1). Mesa's fixed-function program (ffvertex_prog.c: SUB VPpli, Ppli, "
             "V; DP3) subtracts the eye-space x, y, z without dividing by w, so it lights every vertex as "
             "if it sat at the eye (1e-30 from the origin); ours by default too (docs/deviations.md).";
    c.mesa = MesaExpectation::Agree;
    add(c);
  }
  {
    Case c;
    c.group = "position";
    c.name = "vertex_w_denormal";
    c.draw = [] {
      scenes::standard();
      glTranslatef(0, 0, -4);
      scenes::draw_homogeneous(scenes::sphere(2), 1e-40, 1e-40f);
    };
    c.note = "Vertices (x, y, z, 1) * 1e-40: every coordinate a float denormal, the sphere's projective "
             "points again. Clip w is ~4e-40, so 1/w overflows float: the perspective divide and the "
             "rasterizer's 1/w planes are at their limits; the spec does not specify denormal precision. "
             "Ours drops a primitive with a w whose 1/w is not a normal float (below 2^-126 or above "
             "2^126): nothing is drawn or fed back. Mesa draws nothing either, but its feedback reports "
             "every triangle with NaN window positions.";
    c.mesa = MesaExpectation::Undefined;
    c.mesa_reason = "float denormals: llvmpipe flushes them to zero";
    c.float_limit = 1;
    c.float_reason = "the float path works with denormal clip coordinates";
    add(c);
  }
  {
    Case c;
    c.group = "position";
    c.name = "vertex_w_zero";
    c.draw = [] {
      scenes::standard();
      glMatrixMode(GL_PROJECTION);
      glLoadIdentity();  // clip = eye: the vertex (0, 0, 0, 0) stays (0, 0, 0, 0)
      glMatrixMode(GL_MODELVIEW);
      const GLfloat v[] = {-0.5f, -0.5f, 0, 1, 0.5f, -0.5f, 0, 1, 0, 0, 0, 0, 0.5f, 0.5f, 0, 1, -0.5f, 0.5f, 0, 1, 0, 0, 0, 0};
      const GLfloat n[] = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
      glEnableClientState(GL_VERTEX_ARRAY);
      glEnableClientState(GL_NORMAL_ARRAY);
      glVertexPointer(4, GL_FLOAT, 0, v);
      glNormalPointer(GL_FLOAT, 0, n);
      glDrawArrays(GL_TRIANGLES, 0, 6);
    };
    c.note = "Triangles with a vertex (0, 0, 0, 0) and an identity projection: its clip coordinates are all "
             "zero, which satisfies -w <= x, y, z <= w, yet the perspective divide is 0/0. The spec (2.11, "
             "2.12) gives it no window position. Ours drops a primitive with a vertex it cannot map (a w "
             "whose 1/w is not a float) after clipping: nothing drawn or fed back. Mesa draws nothing but "
             "feeds back both triangles, the vertex at a NaN window position.";
    c.mesa = MesaExpectation::Undefined;
    c.mesa_reason = "the perspective divide of (0, 0, 0, 0)";
    add(c);
  }
  {
    Case c;
    c.group = "position";
    c.name = "vertex_w_negative";
    c.draw = [] {
      scenes::standard();
      glTranslatef(0, 0, -4);
      scenes::draw_homogeneous(scenes::sphere(2), -1, -1);
    };
    c.note = "Every vertex (-x, -y, -z, -1): after the modelview and projection all clip w are negative, "
             "and -w_c <= x_c <= w_c has no solution: the view volume (2.12) holds none of it and nothing "
             "is drawn or fed back (checked), though the same points with w = 1 are visible.";
    c.check = expect_no_primitives;
    add(c);
  }
  {
    Case c;
    c.group = "position";
    c.name = "vertex_w_mixed_sign";
    c.draw = [] {
      scenes::standard();
      glTranslatef(0, 0, -3);
      // Triangles with one vertex of negative w: each edge to it passes through infinity.
      const GLfloat v[] = {-0.5f, -0.5f, 0, 1, 0.5f, -0.5f, 0, 1, 0.2f, 0.8f, 0, -1,
                           -0.8f, 0.1f, 0, 1, -0.1f, -0.7f, 0.5f, 1, 0.1f, 0.1f, -0.5f, -0.25f};
      const GLfloat n[] = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0.6f, 0, 0.8f, 0, 0.6f, 0.8f, 0, 0, 1};
      glEnableClientState(GL_VERTEX_ARRAY);
      glEnableClientState(GL_NORMAL_ARRAY);
      glVertexPointer(4, GL_FLOAT, 0, v);
      glNormalPointer(GL_FLOAT, 0, n);
      glDrawArrays(GL_TRIANGLES, 0, 6);
    };
    c.note = "Triangles with one vertex of negative w: their edges to it pass through infinity. 2.12: 'only "
             "the portion of the primitive that lies in the region of w_c > 0 need be produced by "
             "clipping'; ours and Mesa produce the same clipped polygons (Mesa's feedback reports each as a "
             "fan of triangles). The lighting of a vertex with w != 1 divides by w (2.14.1); Mesa does not "
             "(see vertex_w_tiny), nor does ours by default.";
    c.mesa = MesaExpectation::Agree;
    add(c);
  }

  // ------------------------------------------------------------------ viewer
  {
    Case c;
    c.group = "viewer";
    c.name = "local_viewer_eye_on_surface";
    c.draw = [] {
      scenes::standard();
      glMatrixMode(GL_PROJECTION);
      glLoadIdentity();
      glOrtho(-1, 1, -1, 1, -1, 1);  // the eye's plane z = 0 is inside the view volume
      glMatrixMode(GL_MODELVIEW);
      glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
      const GLfloat p[] = {0.5f, 0.5f, 1, 1};
      glLightfv(GL_LIGHT0, GL_POSITION, p);
      glRotatef(-30, 1, 0, 0);  // a grid through the eye, tilted, with a vertex at the eye
      scenes::draw(scenes::grid(8), 0.9);
    };
    c.note = "A local viewer (the eye at (0, 0, 0) of eye space) and a grid through the eye with a vertex "
             "exactly there: VP_e, the unit vector toward the eye (2.14.1), does not exist at that vertex. "
             "Ours takes it as zero, so h = VP_pli there. Mesa normalizes the zero vector to NaN (0 * "
             "RSQ(0)) and its specular term changes there: that vertex is 0.025 darker.";
    c.mesa = MesaExpectation::Undefined;
    c.mesa_reason = "the direction to the eye does not exist at the eye";
    add(c);
  }

  // ------------------------------------------------------------------ meshes
  {
    Case c;
    c.group = "mesh";
    c.name = "mesh_slivers";
    c.draw = mesh_scene(scenes::slivers, Normals::Plain);
    c.note = "A fan of triangles whose apex angles go from 0.5 down to 1e-7 radians (far thinner than a "
             "pixel), with face normals from src/mesh (OpenMesh, double). Slivers are drawn by the "
             "rasterization rules like any triangle (3.5.1): a pixel whose centre lies inside; feedback "
             "reports them whole.";
    add(c);
  }
  {
    Case c;
    c.group = "mesh";
    c.name = "mesh_needles";
    c.draw = mesh_scene(scenes::needles, Normals::Normalize);
    c.note = "Triangles 2.4 long and 1e-4 to 1e-7 wide across the view, tilted: their face normals come "
             "from cross products of nearly parallel edges (computed in double by src/mesh, exact to "
             "rounding), their pixels from the rasterization rules.";
    add(c);
  }
  {
    Case c;
    c.group = "mesh";
    c.name = "mesh_near_duplicates";
    c.draw = mesh_scene(scenes::near_duplicates, Normals::Plain);
    c.note = "A bumped grid whose odd columns are doubled by a vertex one float ulp to the right, joined "
             "by triangles of almost no area. Their face normals are computed in double from coordinates "
             "that differ in the last float bit: direction defined, length 1 (src/mesh normalizes; a "
             "triangle of exactly zero area would get the zero normal and ambient only).";
    add(c);
  }
  {
    Case c;
    c.group = "mesh";
    c.name = "mesh_degenerate_triangles";
    c.draw = [] {
      scenes::standard();
      glEnable(GL_NORMALIZE);
      glTranslatef(0, 0, -3);
      // Zero-area triangles: a repeated vertex, three collinear vertices, one point three times,
      // with the zero face normal a cross product gives them; then a proper triangle.
      const GLfloat v[] = {-0.8f, -0.8f, 0, 0.8f, -0.8f, 0, 0.8f, -0.8f, 0,   -0.8f, 0, 0, 0, 0, 0, 0.8f, 0, 0,
                           0.3f, 0.5f, 0, 0.3f, 0.5f, 0, 0.3f, 0.5f, 0,       -0.5f, 0.2f, 0, 0.5f, 0.2f, 0, 0, 0.9f, 0};
      const GLfloat n[] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
                           0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 1, 0, 0, 1};
      glEnableClientState(GL_VERTEX_ARRAY);
      glEnableClientState(GL_NORMAL_ARRAY);
      glVertexPointer(3, GL_FLOAT, 0, v);
      glNormalPointer(GL_FLOAT, 0, n);
      glDrawArrays(GL_TRIANGLES, 0, 12);
    };
    c.note = "Triangles of zero area (a repeated vertex, collinear vertices, a point), carrying the zero "
             "normal their cross product gives, under GL_NORMALIZE (undefined for a zero normal: ambient "
             "only on both). They cover no pixel; with culling off feedback still reports them (feedback "
             "comes after clipping and culling, before rasterization).";
    c.mesa = MesaExpectation::Undefined;
    c.mesa_reason = "normalizing a zero normal";
    add(c);
  }
  {
    Case c;
    c.group = "mesh";
    c.name = "mesh_coords_1e20";
    c.draw = [] {
      scenes::standard();
      glMatrixMode(GL_PROJECTION);
      glLoadIdentity();
      glOrtho(-1.5e20, 1.5e20, -1.5e20, 1.5e20, -3e20, 3e20);
      glMatrixMode(GL_MODELVIEW);
      const GLfloat p[] = {2e20f, 2e20f, 3e20f, 1};
      glLightfv(GL_LIGHT0, GL_POSITION, p);
      static const Geometry g = [] {
        Geometry s = scenes::sphere(2);
        for (auto& v : s.positions)
          for (double& x : v) x *= 1e20;
        return s;
      }();
      scenes::draw(g);
    };
    c.note = "The sphere at radius 1e20 (eye coordinates, glOrtho 1.5e20 wide), a point light 4e20 away. "
             "Beyond the 2^32 magnitude floats must hold (2.1.1): unspecified. In float |P - V|^2 ~ 1e41 "
             "overflows to +inf and the unit vector to the light becomes 0 (Mesa: DP3, RSQ(inf) = 0): only "
             "ambient remains. Our double reference lights the sphere.";
    c.float_limit = 1;
    c.float_reason = "|P - V|^2 overflows float; the double reference lights the sphere";
    add(c);
  }
  {
    Case c;
    c.group = "mesh";
    c.name = "mesh_coords_1e-20";
    c.draw = [] {
      scenes::standard();
      glMatrixMode(GL_PROJECTION);
      glLoadIdentity();
      glOrtho(-1.5e-20, 1.5e-20, -1.5e-20, 1.5e-20, -3e-20, 3e-20);
      glMatrixMode(GL_MODELVIEW);
      const GLfloat p[] = {2e-20f, 2e-20f, 3e-20f, 1};
      glLightfv(GL_LIGHT0, GL_POSITION, p);
      static const Geometry g = [] {
        Geometry s = scenes::sphere(2);
        for (auto& v : s.positions)
          for (double& x : v) x *= 1e-20;
        return s;
      }();
      scenes::draw(g);
    };
    c.note = "The sphere at radius 1e-20, a point light 4e-20 away: |P - V|^2 ~ 1e-40 is a float "
             "denormal. llvmpipe flushes it to zero, then RSQ(0) = inf and VP = 0 * inf = NaN: Mesa's "
             "sphere gets ambient only (or 1 where the NaN reaches its clamp). Ours keeps the denormal and "
             "lights the sphere like the double reference (within 1e-6). Small magnitudes are allowed "
             "(2.1.1 bounds only the largest), but the precision of denormals is not specified.";
    c.float_limit = 1e-2;
    c.float_reason = "|P - V|^2 is a float denormal";
    c.mesa = MesaExpectation::Undefined;
    c.mesa_reason = "float denormals: llvmpipe flushes them to zero, ours keeps them";
    add(c);
  }
  {
    Case c;
    c.group = "mesh";
    c.name = "icosphere_patch_depth9";
    c.width = c.height = 128;
    c.draw = [] {
      static const Geometry g = scenes::icosphere_patch(9);  // built once per process
      draw_patch_face_on(g);
    };
    c.feedback_hint = size_t(23) << 18;
    c.note = "One face of the icosahedron subdivided 9 times as src/mesh's icosphere does (262144 "
             "triangles, 131841 vertices, midpoints normalized in double), seen face on at 128x128: "
             "most triangles are smaller than a pixel and many cover no pixel centre at all.";
    add(c);
  }
  {
    Case c;
    c.group = "mesh";
    c.name = "icosphere_patch_depth10";
    c.slow = true;
    c.width = c.height = 128;
    c.draw = [] {
      static const Geometry g = scenes::icosphere_patch(10);  // built once per process
      draw_patch_face_on(g);
    };
    c.feedback_hint = size_t(23) << 20;
    c.note = "The same face subdivided 10 times: 1048576 triangles, 525825 vertices (a twentieth of the "
             "depth-10 icosphere's 20M faces, which would need gigabytes through OpenMesh). Slow: "
             "skipped by the CI test.";
    add(c);
  }
  {
    Case c;
    c.group = "mesh";
    c.name = "icosphere_float_collision";
    c.draw = [] {
      static const Geometry g = scenes::icosphere_deep_patch(24, 4);
      scenes::standard();
      const auto ctr = scenes::centroid(g);
      glMatrixMode(GL_PROJECTION);
      glLoadIdentity();
      glOrtho(-1, 1, -1, 1, -3, 3);
      glMatrixMode(GL_MODELVIEW);
      gluLookAtLike(ctr);
      glScaled(1.5e7, 1.5e7, 1.5e7);
      glTranslated(-ctr[0], -ctr[1], -ctr[2]);
      scenes::draw_double(g);
    };
    c.check = [](const Observed& o) -> std::string {
      // The float path's window triangles collapse (zero area); the double reference's do not.
      auto collapsed = [](const Run& r) {
        int n = 0;
        for (const auto& p : r.feedback) {
          const auto &a = p.vertices[0].position, &b = p.vertices[1].position, &c = p.vertices[2].position;
          n += (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y) == 0;
        }
        return n;
      };
      const int f = collapsed(o.soft), d = collapsed(o.dbl);
      if (f == 0) return "no triangle collapsed in float: the patch is not below float's spacing";
      if (d != 0) return std::to_string(d) + " triangles collapsed in the double reference";
      return "";
    };
    c.note = "The icosphere's face 0 followed down 24 levels (edges ~7e-8, below float's spacing of "
             "6e-8 to 1.2e-7 near radius 1) and subdivided 4 more: depth 28, far beyond src/mesh's limit "
             "of 12. Drawn from GL_DOUBLE arrays magnified 1.5e7 times: in float (ours and Mesa) the "
             "midpoints collide and the patch becomes a lattice of float steps with collapsed "
             "triangles; our double reference keeps them apart. Colours come from the sphere normals, "
             "which stay unit, so they agree; the positions do not (float against double: see "
             "max_position_vs_double_px; checked: triangles collapse to zero area in float, none in "
             "double).";
    add(c);
  }

  // ------------------------------------------------------------------ viewports
  {
    Case c;
    c.group = "viewport";
    c.name = "viewport_1x1";
    c.draw = [] {
      scenes::standard();
      glViewport(20, 30, 1, 1);
      glTranslatef(0, 0, -4);
      scenes::draw(scenes::sphere(3));
    };
    c.note = "glViewport(20, 30, 1, 1): the whole sphere maps into one pixel (2.11.1). Window positions "
             "are within [20, 21] x [30, 31]; only triangles covering the pixel's centre draw it.";
    add(c);
  }
  {
    Case c;
    c.group = "viewport";
    c.name = "framebuffer_1x1";
    c.width = c.height = 1;
    c.draw = [] {
      scenes::standard();
      glTranslatef(0, 0, -4);
      scenes::draw(scenes::sphere(3));
    };
    c.note = "A 1x1 framebuffer (and viewport): as viewport_1x1, with the pixel at the origin.";
    add(c);
  }
  {
    Case c;
    c.group = "viewport";
    c.name = "viewport_8192";
    c.draw = [] {
      scenes::standard();
      glViewport(-4064, -4064, 8192, 8192);
      glTranslatef(0, 0, -4);
      scenes::draw(scenes::sphere(4));
    };
    c.note = "glViewport(-4064, -4064, 8192, 8192) on a 64x64 framebuffer: window coordinates up to "
             "+-4096, of which the framebuffer shows the middle 64x64 pixels (the sphere's centre, 1/128 "
             "of it across). 8192 is within GL_MAX_VIEWPORT_DIMS (16384 on llvmpipe).";
    add(c);
  }
  {
    Case c;
    c.group = "viewport";
    c.name = "viewport_beyond_max";
    c.draw = [] {
      scenes::standard();
      glViewport(-50000, -50000, 100000, 100000);
      glTranslatef(0, 0, -4);
      scenes::draw(scenes::sphere(3));
    };
    c.note = "glViewport(-50000, -50000, 100000, 100000): 'the viewport's width and height are clamped to "
             "implementation-dependent maximums' (2.11.1, GL_MAX_VIEWPORT_DIMS: 16384 in llvmpipe and "
             "ours), the origin is not: the framebuffer sees a corner of the clamped viewport, far off "
             "the sphere.";
    add(c);
  }
  {
    Case c;
    c.group = "viewport";
    c.name = "framebuffer_8192";
    c.slow = true;
    c.width = c.height = 8192;
    c.draw = [] {
      scenes::standard();
      glTranslatef(0, 0, -3);
      scenes::draw(scenes::grid(2), 0.9);
    };
    c.note = "An 8192x8192 framebuffer (256 MB of colour) with trivial geometry: 8 lit triangles. Slow "
             "and large: skipped by the CI test.";
    add(c);
  }

  // ------------------------------------------------------------------ arrays
  {
    Case c;
    c.group = "arrays";
    c.name = "nan_vertex_position";
    c.draw = poisoned_grid(40, 0, kNaN);
    c.note = "One vertex of a lit grid has x = NaN. 'Providing a NaN or an infinity yields unspecified "
             "results, but must not lead to GL interruption or termination' (2.1.1). Ours drops every "
             "primitive with a non-finite clip coordinate: nothing else sensible can be drawn or fed back.";
    c.mesa = MesaExpectation::Undefined;
    c.mesa_reason = "a NaN coordinate";
    add(c);
  }
  {
    Case c;
    c.group = "arrays";
    c.name = "inf_vertex_position";
    c.draw = poisoned_grid(40, 1, kInf);
    c.note = "One vertex of a lit grid has y = +inf: unspecified, must not stop the GL (2.1.1). Its clip "
             "coordinates are infinite or NaN (inf * 0); ours drops the primitives that use it.";
    c.mesa = MesaExpectation::Undefined;
    c.mesa_reason = "an infinite coordinate";
    add(c);
  }
  {
    Case c;
    c.group = "arrays";
    c.name = "nan_normal";
    c.draw = poisoned_grid(40, 4, kNaN);
    c.note = "One vertex's normal has y = NaN: n.L and n.h are NaN there (unspecified, 2.1.1). Mesa drops "
             "them at max(n.L, 0) (its MAX / LIT return the other operand for a NaN): the vertex keeps its "
             "ambient terms. Ours takes max(0, n.L) the same way, and would turn a NaN left at the end of "
             "lighting into 1 as Mesa's clamp does.";
    c.mesa = MesaExpectation::Undefined;
    c.mesa_reason = "a NaN normal";
    add(c);
  }
  {
    Case c;
    c.group = "arrays";
    c.name = "nan_colour_unlit";
    c.draw = [] {
      scenes::standard(false);
      glTranslatef(0, 0, -3);
      const Geometry g = scenes::grid(4);
      std::vector<float> p, col;
      for (size_t i = 0; i < g.positions.size(); ++i) {
        for (int k = 0; k < 3; ++k) p.push_back(float(g.positions[i][k] * 0.9));
        const float x = float(i) / float(g.positions.size());
        col.insert(col.end(), {i == 7 ? float(kNaN) : x, i == 12 ? float(kInf) : 1 - x, i == 3 ? -float(kInf) : 0.5f, 1});
      }
      glEnableClientState(GL_VERTEX_ARRAY);
      glEnableClientState(GL_COLOR_ARRAY);
      glVertexPointer(3, GL_FLOAT, 0, p.data());
      glColorPointer(4, GL_FLOAT, 0, col.data());
      glDrawElements(GL_TRIANGLES, GLsizei(g.indices.size()), GL_UNSIGNED_INT, g.indices.data());
    };
    c.note = "Lighting off, a colour array with NaN, +inf and -inf in it: unspecified (2.1.1). The "
             "colour is clamped to [0,1] (2.14.6; +-inf to 1 and 0); Mesa's clamp makes a NaN 1, and "
             "so does ours (before, it reached our rasterizer as NaN).";
    c.mesa = MesaExpectation::Undefined;
    c.mesa_reason = "a NaN colour";
    add(c);
  }
  {
    Case c;
    c.group = "arrays";
    c.name = "odd_strides";
    c.draw = [] {
      scenes::standard();
      glEnable(GL_NORMALIZE);
      glTranslatef(0, 0, -4);
      const Geometry& g = scenes::sphere(3);
      // Positions every 13 bytes and GL_SHORT normals every 7 bytes, both unaligned, in one buffer.
      const size_t n = g.positions.size();
      std::vector<uint8_t> buf(n * 13 + n * 7 + 16);
      uint8_t* pos = buf.data() + 1;
      uint8_t* nrm = buf.data() + 3 + n * 13;
      for (size_t i = 0; i < n; ++i) {
        for (int k = 0; k < 3; ++k) {
          const float f = float(g.positions[i][k]);
          std::memcpy(pos + i * 13 + size_t(k) * 4, &f, 4);
          const int16_t s = int16_t(std::lround(g.normals[i][k] * 32767));
          std::memcpy(nrm + i * 7 + size_t(k) * 2, &s, 2);
        }
      }
      glEnableClientState(GL_VERTEX_ARRAY);
      glEnableClientState(GL_NORMAL_ARRAY);
      glVertexPointer(3, GL_FLOAT, 13, pos);
      glNormalPointer(GL_SHORT, 7, nrm);
      glDrawElements(GL_TRIANGLES, GLsizei(g.indices.size()), GL_UNSIGNED_INT, g.indices.data());
    };
    c.note = "Positions every 13 bytes and GL_SHORT normals every 7, both misaligned (odd addresses): any "
             "stride is allowed (2.8) and GL 2.1 asks for no alignment. Both read every element where it is.";
    add(c);
  }
  for (bool normalize : {false, true}) {
    const std::string s = normalize ? "_normalize" : "";
    {
      Case c;
      c.group = "arrays";
      c.name = "normals_byte" + s;
      c.draw = integer_normals<int8_t>(GL_BYTE, normalize);
      c.note = "GL_BYTE normals, scaled to +-127, every 7th one (-128, -128, -128). GL 2.1 table 2.9 "
               "converts a signed byte c to (2c + 1)/255 (so 0 is 1/255, 64 is 0.50588, -128 is -1). Mesa "
               "22.3's draws fetch them as a signed-normalized format, max(c/127, -1) (the GL 4.2 rule: 0 "
               "is 0, 64 is 0.50394), and so do ours by default (soft-spec keeps GL 2.1's rule): "
               "docs/deviations.md.";
      c.mesa = MesaExpectation::Agree;
      add(c);
    }
    {
      Case c;
      c.group = "arrays";
      c.name = "normals_short" + s;
      c.draw = integer_normals<int16_t>(GL_SHORT, normalize);
      c.note = "GL_SHORT normals, scaled to +-32767, every 7th one -32768 on every axis: (2c + 1)/65535 "
               "(table 2.9).";
      add(c);
    }
    {
      Case c;
      c.group = "arrays";
      c.name = "normals_int" + s;
      c.draw = integer_normals<int32_t>(GL_INT, normalize);
      c.note = "GL_INT normals, scaled to +-(2^31 - 1), every 7th one INT_MIN on every axis: (2c + 1)/(2^32 "
               "- 1) (table 2.9), beyond float's 24 bits: the conversion rounds.";
      add(c);
    }
  }

  return out;
}

}  // namespace

const std::vector<Case>& catalogue() {
  static const std::vector<Case> cases = build();
  return cases;
}

}  // namespace ffc::stress
