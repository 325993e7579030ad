// The hand-over to a draw sink (draw_sink.h): the vertices as GL fetches them, and the state the
// sink draws with. Soft's vertex stage and rasterizer are not run for what a sink draws.
#include "state/draw_sink.h"

#include <algorithm>
#include <cstring>

#include "state/client_arrays.h"
#include "state/context.h"

namespace ffc::state {

SinkState Context::sink_state() {
  SinkState s;
  // Padding zeroed, so that equal states have equal bytes (the GLSL backend's uniform cache
  // compares them); every value is set below.
  std::memset(static_cast<void*>(static_cast<SinkValues*>(&s)), 0, sizeof(SinkValues));
  s.lighting = lighting_;
  s.key = lighting::Key{}, s.normal_inverse = glm::dmat3(1), s.rescale = 0;
  if (lighting_) {
    update_vertex_constants();  // the normal matrix as soft's stage takes it (and the same deviations noted)
    s.key = key();
    const glm::dmat3& inv = normal_matrix_;
    s.normal_inverse = inv;
    s.rescale = rescale_normal_ ? glm::length(glm::dvec3(inv[0][2], inv[1][2], inv[2][2])) : 0.0;
  }
  s.lights = lights_;
  s.materials = materials_;
  s.model = model_;
  s.model.color_material = cm_per_vertex();
  s.model.cm_mode = cm_mode_;
  s.modelview = modelview_f_.back().values();
  s.mvp = mvp_f_;
  s.flat = shade_model_ == GL_FLAT;
  s.cull = cull_face_, s.cull_mode = cull_mode_, s.front_face = front_face_;
  s.depth_test = depth_test_, s.depth_func = depth_func_;
  s.viewport = viewport_, s.depth_range = depth_range_;
  s.point_size = point_size_, s.line_width = line_width_;
  s.fragment = &frag_;
  s.clear_color = clear_color_, s.clear_depth = clear_depth_;
  raster::State rs;
  fog_raster_state(rs);
  s.fog = fog_, s.fog_mode = fog_mode_, s.fog_coord_src = fog_coord_src_;
  s.fog_params = glm::vec4(rs.fog_params[0], rs.fog_params[1], rs.fog_params[2], rs.fog_params[3]);
  s.fog_color = glm::vec3(fog_color_);
  s.offset_fill = offset_fill_;
  s.offset_line = enabled_state(GL_POLYGON_OFFSET_LINE) == 1, s.offset_point = enabled_state(GL_POLYGON_OFFSET_POINT) == 1;
  s.offset_factor = offset_factor_, s.offset_units = offset_units_;
  s.polygon_mode[0] = polygon_mode_[0], s.polygon_mode[1] = polygon_mode_[1];
  s.pass_mode = 0, s.pass_faces = 3;  // not split: the sink splits by mode itself
  s.vertex_materials = nullptr;        // sink_end sets it when glMaterial varied inside glBegin
  const bool line_or_point_offset = (polygon_mode_[0] == GL_LINE || polygon_mode_[1] == GL_LINE) && s.offset_line;
  if (line_or_point_offset || ((polygon_mode_[0] == GL_POINT || polygon_mode_[1] == GL_POINT) && s.offset_point))
    s.unsupported.push_back("polygon offset of GL_LINE or GL_POINT polygons");
  if (precision_ == Precision::Double) s.unsupported.push_back("double precision (the shaders are float)");
  return s;
}

void Context::sink_vertex(const glm::dvec4& obj) {
  sink_verts_.push_back({glm::vec4(obj), glm::vec3(normal_), glm::vec4(color_)});
  if (sink_material_varies_) sink_materials_.push_back(sink_material());
}

SinkMaterial Context::sink_material() const {
  SinkMaterial m;
  for (int f = 0; f < 2; ++f) {
    const lighting::MaterialParams& p = materials_[f];
    m.face[f][0] = glm::vec4(glm::vec3(p.ambient), float(p.shininess));
    m.face[f][1] = glm::vec4(p.diffuse), m.face[f][2] = glm::vec4(p.specular), m.face[f][3] = glm::vec4(p.emission);
  }
  return m;
}

// glMaterial between glBegin and glEnd while a sink draws: from here on each vertex carries the
// material as it stood at its glVertex (Mesa's vbo makes them per-vertex attributes too); the
// vertices before it, the material as it was.
void Context::sink_material_changes() {
  if (sink_material_varies_) return;
  sink_material_varies_ = true;
  sink_materials_.assign(sink_verts_.size(), sink_material());
}

void Context::sink_end() {
  if (!sink_verts_.empty()) {
    SinkState s = sink_state();
    if (sink_material_varies_) s.vertex_materials = &sink_materials_;
    sink_->draw(s, prim_mode_, sink_verts_.data(), sink_verts_.size(), nullptr, 0);
  }
  sink_verts_.clear();
  sink_materials_.clear();
  sink_material_varies_ = false;
}

namespace {

// Element i of `a`, n components (the others from `fill`), in float. Float arrays are read as
// floats: the general reader's widening to double and back gives the same values, at several
// times the cost on a large draw.
inline glm::vec4 fetch(const ClientArray& a, GLint i, int n, Fixed fixed, const glm::dvec4& fill) {
  if (a.type != GL_FLOAT || a.repeated) return glm::vec4(attribute(a, i, n, fixed, fill));
  const uint8_t* p = element(a, i);
  glm::vec4 v(fill);
  switch (n) {  // fixed sizes: copies to registers, not a library call
    case 4: std::memcpy(&v, p, 4 * sizeof(float)); break;
    case 3: std::memcpy(&v, p, 3 * sizeof(float)); break;
    case 2: std::memcpy(&v, p, 2 * sizeof(float)); break;
    default: std::memcpy(&v, p, sizeof(float)); break;
  }
  return v;
}

}  // namespace

// Array elements [first, first + count) as a draw reads them into sink_verts_: each attribute
// from its array when enabled, else the current value; the current values do not change.
void Context::sink_fetch(GLint first, GLsizei count) {
  sink_verts_.resize(size_t(count));
  const glm::vec3 normal(normal_);
  const glm::vec4 color(color_);
  for (GLsizei k = 0; k < count; ++k) {
    const GLint i = first + k;
    SinkVertex& v = sink_verts_[size_t(k)];
    v.position = fetch(vertex_array_, i, vertex_array_.size, Fixed::Raw, glm::dvec4(0, 0, 0, 1));
    v.normal = normal_array_.enabled ? glm::vec3(fetch(normal_array_, i, 3, draw_fixed(), glm::dvec4(0))) : normal;
    v.color = color_array_.enabled ? fetch(color_array_, i, color_array_.size, draw_fixed(), glm::dvec4(1)) : color;
  }
}

void Context::sink_arrays(GLenum mode, GLint first, GLsizei count) {
  sink_fetch(first, count);
  if (count > 0) sink_->draw(sink_state(), mode, sink_verts_.data(), sink_verts_.size(), nullptr, 0);
  sink_verts_.clear();
}

// The elements the indices name, fetched once each over the indices' range, and the indices
// made relative to its start.
void Context::sink_elements(GLenum mode, GLsizei count, GLenum type, const void* indices) {
  if (count == 0) return;
  const uint8_t* p = static_cast<const uint8_t*>(indices);
  elements_.resize(size_t(count));
  auto widen = [&](auto unit) {  // the unsigned types glDrawElements takes, copied as they are
    for (GLsizei i = 0; i < count; ++i) {
      decltype(unit) v;
      std::memcpy(&v, p + size_t(i) * sizeof v, sizeof v);
      elements_[size_t(i)] = v;
    }
  };
  if (type == GL_UNSIGNED_INT) std::memcpy(elements_.data(), p, size_t(count) * sizeof(uint32_t));
  else if (type == GL_UNSIGNED_SHORT) widen(uint16_t{});
  else if (type == GL_UNSIGNED_BYTE) widen(uint8_t{});
  else
    for (GLsizei i = 0; i < count; ++i) elements_[size_t(i)] = uint32_t(read_component(p, type, i, Fixed::Raw));
  uint32_t lo = 0, hi = 0;
  index_range(elements_.data(), elements_.size(), lo, hi);
  if (fits_in_memory(uint64_t(hi - lo) + 1)) {
    for (uint32_t& e : elements_) e -= lo;
    sink_fetch(GLint(lo), GLsizei(hi - lo + 1));
    sink_->draw(sink_state(), mode, sink_verts_.data(), sink_verts_.size(), elements_.data(), elements_.size());
  }
  sink_verts_.clear();
  elements_.clear();
}

// The sink hands its picture top row first; fb_ keeps GL's rows, the bottom one first.
void Context::sink_read_back() {
  if (!sink_) return;
  std::vector<uint8_t> top_first(fb_.color.size());
  sink_->read_back(top_first.data(), fb_.width, fb_.height);
  const size_t row = size_t(fb_.width) * 4;
  for (int y = 0; y < fb_.height; ++y)
    std::copy_n(&top_first[size_t(fb_.height - 1 - y) * row], row, &fb_.color[size_t(y) * row]);
}

Context::SinkPixels::SinkPixels(Context& c) : c_(c), on_(c.sink_draws()) {
  if (!on_) return;
  c.sink_read_back();
  c.sink_->read_depth(c.fb_.depth.data(), c.fb_.width, c.fb_.height);
}

Context::SinkPixels::~SinkPixels() {
  if (on_) c_.sink_->write_back(c_.fb_.color.data(), c_.fb_.depth.data(), c_.fb_.width, c_.fb_.height);
}

}  // namespace ffc::state
