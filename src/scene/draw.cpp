// A Description's GL calls, through the dispatch, from GL's default state.
#include <optional>
#include <stdexcept>

#include "gl/glu.h"
#include "scene/description.h"
#include "scene/scene.h"

namespace ffc::scene {

namespace {

GLenum gl_face(Face f) {
  switch (f) {
    case Face::Front: return GL_FRONT;
    case Face::Back: return GL_BACK;
    case Face::FrontAndBack: return GL_FRONT_AND_BACK;
  }
  return GL_FRONT_AND_BACK;
}

GLenum gl_color_mode(ColorMode m) {
  switch (m) {
    case ColorMode::Ambient: return GL_AMBIENT;
    case ColorMode::Diffuse: return GL_DIFFUSE;
    case ColorMode::Specular: return GL_SPECULAR;
    case ColorMode::Emission: return GL_EMISSION;
    case ColorMode::AmbientAndDiffuse: return GL_AMBIENT_AND_DIFFUSE;
  }
  return GL_AMBIENT_AND_DIFFUSE;
}

// Seed 000's drawFrame: the unit axes, red x, green y, blue z.
void draw_axes() {
  glBegin(GL_LINES);
  glColor3ub(255, 0, 0);
  glVertex3f(0, 0, 0);
  glVertex3f(1, 0, 0);
  glColor3ub(0, 255, 0);
  glVertex3f(0, 0, 0);
  glVertex3f(0, 1, 0);
  glColor3ub(0, 0, 255);
  glVertex3f(0, 0, 0);
  glVertex3f(0, 0, 1);
  glEnd();
}

void apply(const Transform& t) {
  switch (t.kind) {
    case Transform::Kind::Translate: glTranslated(t.v[0], t.v[1], t.v[2]); break;
    case Transform::Kind::Rotate: glRotated(t.angle_deg, t.v[0], t.v[1], t.v[2]); break;
    case Transform::Kind::Scale: glScaled(t.v[0], t.v[1], t.v[2]); break;
  }
}

// The position and spot direction: their meaning depends on the modelview current when set, so a
// world-space light sets its position even when it equals GL's default (which is in eye space).
// The spot direction matters only to a spot (cutoff other than 180): a world-space light that is
// no spot and keeps the default direction leaves it alone, as the seeds do.
void set_light_placement(int i, const Light& l) {
  const Light def = default_light(i);
  const GLenum light = GLenum(GL_LIGHT0 + i);
  const bool world = l.space == Space::World;
  if (world || l.position != def.position) glLightfv(light, GL_POSITION, l.position.data());
  if (l.spot_direction != def.spot_direction || (world && l.spot_cutoff != def.spot_cutoff))
    glLightfv(light, GL_SPOT_DIRECTION, l.spot_direction.data());
}

void set_light_parameters(int i, const Light& l) {
  const Light def = default_light(i);
  const GLenum light = GLenum(GL_LIGHT0 + i);
  if (l.enabled) glEnable(light);
  if (l.ambient != def.ambient) glLightfv(light, GL_AMBIENT, l.ambient.data());
  if (l.diffuse != def.diffuse) glLightfv(light, GL_DIFFUSE, l.diffuse.data());
  if (l.specular != def.specular) glLightfv(light, GL_SPECULAR, l.specular.data());
  if (l.spot_exponent != def.spot_exponent) glLightf(light, GL_SPOT_EXPONENT, l.spot_exponent);
  if (l.spot_cutoff != def.spot_cutoff) glLightf(light, GL_SPOT_CUTOFF, l.spot_cutoff);
  if (l.constant_attenuation != def.constant_attenuation)
    glLightf(light, GL_CONSTANT_ATTENUATION, l.constant_attenuation);
  if (l.linear_attenuation != def.linear_attenuation) glLightf(light, GL_LINEAR_ATTENUATION, l.linear_attenuation);
  if (l.quadratic_attenuation != def.quadratic_attenuation)
    glLightf(light, GL_QUADRATIC_ATTENUATION, l.quadratic_attenuation);
}

// glMaterial calls from the materials GL holds (`cur`) to the wanted ones: only what differs, one
// GL_FRONT_AND_BACK call where both faces take the same value, GL_AMBIENT_AND_DIFFUSE where a
// face's ambient and diffuse are set together to one colour.
class MaterialState {
 public:
  void set(const Material& front, const Material& back) {
    struct Need {
      bool f, b;
      bool any() const { return f || b; }
      bool operator==(const Need& o) const { return f == o.f && b == o.b; }
    };
    auto need = [&](auto field) { return Need{cur_front_.*field != front.*field, cur_back_.*field != back.*field}; };
    auto emit = [&](GLenum pname, Need n, auto field) {
      auto put = [&](GLenum face, const Material& m) {
        if constexpr (std::is_same_v<std::decay_t<decltype(m.*field)>, float>)
          glMaterialf(face, pname, m.*field);
        else
          glMaterialfv(face, pname, (m.*field).data());
      };
      if (n.f && n.b && front.*field == back.*field)
        put(GL_FRONT_AND_BACK, front);
      else {
        if (n.f) put(GL_FRONT, front);
        if (n.b) put(GL_BACK, back);
      }
    };
    const Need na = need(&Material::ambient), nd = need(&Material::diffuse);
    if (na.any() && na == nd && (!na.f || front.ambient == front.diffuse) && (!na.b || back.ambient == back.diffuse))
      emit(GL_AMBIENT_AND_DIFFUSE, na, &Material::ambient);
    else {
      emit(GL_AMBIENT, na, &Material::ambient);
      emit(GL_DIFFUSE, nd, &Material::diffuse);
    }
    emit(GL_SPECULAR, need(&Material::specular), &Material::specular);
    emit(GL_EMISSION, need(&Material::emission), &Material::emission);
    emit(GL_SHININESS, need(&Material::shininess), &Material::shininess);
    cur_front_ = front;
    cur_back_ = back;
  }

 private:
  Material cur_front_, cur_back_;  // GL's defaults
};

// An object's client arrays, built before any GL call. Arrays draw unshared corners (an indexed
// layout is expanded); elements and immediate mode keep the layout's vertices and walk its indices
// (0, 1, 2, ... for unshared corners).
struct Prepared {
  DrawPath path = DrawPath::Arrays;
  std::vector<float> positions, normals, colors;  // xyz, xyz, rgba per vertex
  std::vector<uint32_t> indices;                  // elements and immediate mode
  std::optional<Color> constant_color;
};

Prepared prepare(const Object& o) {
  const mesh::Layout l = layout(o);
  const std::vector<Color> colors = vertex_colors(o, l);
  Prepared p;
  p.path = resolved_draw_path(o);
  if (o.color.kind == ColorSource::Kind::Constant) p.constant_color = o.color.constant;
  std::vector<uint32_t> all(l.vertices.size());
  for (size_t v = 0; v < all.size(); ++v) all[v] = uint32_t(v);
  const std::vector<uint32_t>& sent = p.path == DrawPath::Arrays && !l.indices.empty() ? l.indices : all;
  if (p.path != DrawPath::Arrays) p.indices = l.indices.empty() ? all : l.indices;
  p.positions.reserve(sent.size() * 3);
  p.normals.reserve(sent.size() * 3);
  for (uint32_t v : sent) {
    for (int k = 0; k < 3; ++k) {
      p.positions.push_back(float(l.vertices[v].position[k]));
      p.normals.push_back(float(l.vertices[v].normal[k]));
    }
    if (!colors.empty()) p.colors.insert(p.colors.end(), colors[v].begin(), colors[v].end());
  }
  return p;
}

std::vector<Prepared> prepare(const Description& d) {
  std::vector<Prepared> all;
  all.reserve(d.objects.size());
  for (const Object& o : d.objects) all.push_back(prepare(o));
  return all;
}

void draw_object(const Prepared& p) {
  if (p.constant_color) glColor4fv(p.constant_color->data());
  const bool colors = !p.colors.empty();
  if (p.path == DrawPath::Immediate) {
    glBegin(GL_TRIANGLES);
    auto corner = [&](size_t v) {
      if (colors) glColor4fv(&p.colors[4 * v]);
      glNormal3f(p.normals[3 * v], p.normals[3 * v + 1], p.normals[3 * v + 2]);
      glVertex3f(p.positions[3 * v], p.positions[3 * v + 1], p.positions[3 * v + 2]);
    };
    if (p.indices.empty())
      for (size_t v = 0; v < p.positions.size() / 3; ++v) corner(v);
    else
      for (uint32_t v : p.indices) corner(v);
    glEnd();
    return;
  }
  // Client vertex arrays as the seeds draw them.
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  if (colors) glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, p.positions.data());
  glNormalPointer(GL_FLOAT, 0, p.normals.data());
  if (colors) glColorPointer(4, GL_FLOAT, 0, p.colors.data());
  if (p.path == DrawPath::Elements)
    glDrawElements(GL_TRIANGLES, GLsizei(p.indices.size()), GL_UNSIGNED_INT, p.indices.data());
  else
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(p.positions.size() / 3));
  if (colors) glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
}

void issue(const Description& d, const std::vector<Prepared>& prepared) {
  if (prepared.size() != d.objects.size()) throw std::logic_error("scene::issue: one Prepared per object");
  if (d.background != Color{0, 0, 0, 0})
    glClearColor(d.background[0], d.background[1], d.background[2], d.background[3]);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (d.depth_test) glEnable(GL_DEPTH_TEST);

  const Camera& c = d.camera;
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  switch (c.projection) {
    case Camera::Projection::Perspective:
      gluPerspective(c.fovy_deg, c.aspect > 0 ? c.aspect : double(d.width) / d.height, c.z_near, c.z_far);
      break;
    case Camera::Projection::Frustum: glFrustum(c.left, c.right, c.bottom, c.top, c.z_near, c.z_far); break;
    case Camera::Projection::Ortho: glOrtho(c.left, c.right, c.bottom, c.top, c.z_near, c.z_far); break;
  }
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  // Lights given in eye space are placed under the identity, before the camera.
  for (int i = 0; i < max_lights; ++i)
    if (d.lights[size_t(i)].space == Space::Eye) set_light_placement(i, d.lights[size_t(i)]);
  gluLookAt(c.eye[0], c.eye[1], c.eye[2], c.center[0], c.center[1], c.center[2], c.up[0], c.up[1], c.up[2]);
  if (d.axes) draw_axes();  // before lighting is enabled: unlit
  // Lights given in the world are placed under the camera, before the object transforms.
  for (int i = 0; i < max_lights; ++i) {
    const Light& l = d.lights[size_t(i)];
    if (l.space == Space::World && l != default_light(i)) set_light_placement(i, l);
  }

  if (d.lighting) glEnable(GL_LIGHTING);
  for (int i = 0; i < max_lights; ++i) set_light_parameters(i, d.lights[size_t(i)]);
  const LightModel lm;
  if (d.light_model.ambient != lm.ambient) glLightModelfv(GL_LIGHT_MODEL_AMBIENT, d.light_model.ambient.data());
  if (d.light_model.local_viewer) glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
  if (d.light_model.two_sided) glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  if (d.light_model.separate_specular) glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
  if (d.normalize) glEnable(GL_NORMALIZE);
  if (d.rescale_normal) glEnable(GL_RESCALE_NORMAL);
  if (d.shade == Shade::Flat) glShadeModel(GL_FLAT);
  if (d.cull_face) glEnable(GL_CULL_FACE);
  if (d.cull_mode != Face::Back) glCullFace(gl_face(d.cull_mode));
  if (d.front_face_cw) glFrontFace(GL_CW);

  MaterialState materials;
  materials.set(d.front, d.back);
  const ColorMaterial cm;
  if (d.color_material.face != cm.face || d.color_material.mode != cm.mode)
    glColorMaterial(gl_face(d.color_material.face), gl_color_mode(d.color_material.mode));
  if (d.color_material.enabled) glEnable(GL_COLOR_MATERIAL);

  for (const Transform& t : d.transforms) apply(t);
  for (size_t i = 0; i < d.objects.size(); ++i) {
    const Object& o = d.objects[i];
    glPushMatrix();
    for (const Transform& t : o.transforms) apply(t);
    materials.set(o.front.value_or(d.front), o.back.value_or(d.back));
    draw_object(prepared[i]);
    glPopMatrix();
  }
}

}  // namespace

void draw(const Description& d) { issue(d, prepare(d)); }

std::function<void()> frame(const Description& d) {
  return [d, prepared = prepare(d)] { issue(d, prepared); };
}

image::Image render(const Description& d, backends::Backend& backend) {
  const std::vector<Prepared> prepared = prepare(d);  // a mesh that cannot be built throws here
  backend.begin(d.width, d.height);
  issue(d, prepared);
  return backend.read();
}

}  // namespace ffc::scene
