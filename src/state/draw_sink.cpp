// The hand-over to a draw sink (draw_sink.h): the vertices as GL fetches them, and the state the
// sink draws with. Soft's vertex stage and rasterizer are not run for what a sink draws.
#include "state/draw_sink.h"

#include <cstdio>
#include <cstring>
#include <mutex>
#include <set>

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
  if (fog_) s.unsupported.push_back("fog");
  if (offset_fill_) s.unsupported.push_back("polygon offset");
  if (unfilled()) s.unsupported.push_back("glPolygonMode other than GL_FILL");
  if (frag_.alpha_test) s.unsupported.push_back("the alpha test");
  if (frag_.line_stipple) s.unsupported.push_back("line stipple");
  if (precision_ == Precision::Double) s.unsupported.push_back("double precision (the shaders are float)");
  return s;
}

void Context::sink_vertex(const glm::dvec4& obj) {
  sink_verts_.push_back({glm::vec4(obj), glm::vec3(normal_), glm::vec4(color_)});
}

void Context::sink_end() {
  if (!sink_verts_.empty()) sink_->draw(sink_state(), prim_mode_, sink_verts_.data(), sink_verts_.size(), nullptr, 0);
  sink_verts_.clear();
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

void Context::sink_read_back() {
  if (sink_) sink_->read_back(fb_.color.data(), fb_.width, fb_.height);
}

bool Context::sink_refuses(const char* what) {
  if (!sink_draws()) return false;
  error(GL_INVALID_OPERATION);
  static std::mutex m;
  static std::set<std::string> named;
  const std::lock_guard<std::mutex> lock(m);
  if (named.insert(what).second)
    std::fprintf(stderr, "ffcompat: %s is not supported by the GLSL backend: GL_INVALID_OPERATION, nothing drawn\n", what);
  return true;
}

}  // namespace ffc::state
