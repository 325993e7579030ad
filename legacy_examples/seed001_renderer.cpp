#include "seed001_renderer.h"

#include <glm/gtc/type_ptr.hpp>
#include <stdexcept>

#include "platform/egl_context.h"

namespace seed001 {

namespace {

void upload(const Gl33& gl, GLuint vao, GLuint vbo, const std::vector<Vertex>& vertices) {
  gl.BindVertexArray(vao);
  gl.BindBuffer(GL_ARRAY_BUFFER, vbo);
  gl.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(Vertex)), vertices.data(), GL_STATIC_DRAW);
  // location 0: position, 1: normal; 6 floats a vertex, as the handout's glm.array.
  gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, pos)));
  gl.EnableVertexAttribArray(0);
  gl.VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, normal)));
  gl.EnableVertexAttribArray(1);
}

// Empty when the shader's or program's status query says yes; else its info log, the object
// deleted.
template <class GetIv, class GetLog, class Delete>
std::string failure_log(GLuint object, GLenum status, GetIv get_iv, GetLog get_log, Delete del) {
  GLint ok = 0;
  get_iv(object, status, &ok);
  if (ok) return {};
  char log[2048] = {};
  get_log(object, sizeof log, nullptr, log);
  del(object);
  return log[0] ? log : "(no log)";
}

GLuint compile(const Gl33& gl, GLenum kind, const std::string& text) {
  const GLuint s = gl.CreateShader(kind);
  const char* src = text.c_str();
  gl.ShaderSource(s, 1, &src, nullptr);
  gl.CompileShader(s);
  if (const std::string log = failure_log(s, GL_COMPILE_STATUS, gl.GetShaderiv, gl.GetShaderInfoLog, gl.DeleteShader);
      !log.empty())
    throw std::runtime_error(std::string(kind == GL_VERTEX_SHADER ? "vertex" : "fragment") +
                             " shader does not compile: " + log);
  return s;
}

void check_error(const Gl33& gl, const char* what) {
  if (const GLenum e = gl.GetError(); e != GL_NO_ERROR) {
    char b[96];
    std::snprintf(b, sizeof b, "%s raised GL error 0x%04X", what, e);
    throw std::runtime_error(b);
  }
}

}  // namespace

Renderer::Renderer(const Gl33& gl) : gl_(gl) {
  gl_.GenVertexArrays(2, vao_);
  gl_.GenBuffers(2, vbo_);
  gl_.GenBuffers(1, &ebo_);
  upload(gl_, vao_[0], vbo_[0], face_normal_vertices());
  upload(gl_, vao_[1], vbo_[1], averaged_normal_vertices());
  const auto& idx = averaged_normal_indices();  // the element buffer is part of vao_[1]'s state
  gl_.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo_);
  gl_.BufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(idx.size() * sizeof(unsigned)), idx.data(), GL_STATIC_DRAW);
  gl_.BindVertexArray(0);
  check_error(gl_, "creating the cube's buffers");
}

Renderer::~Renderer() {
  for (auto& [text, p] : programs_) gl_.DeleteProgram(p);
  gl_.DeleteBuffers(1, &ebo_);
  gl_.DeleteBuffers(2, vbo_);
  gl_.DeleteVertexArrays(2, vao_);
}

unsigned Renderer::program(const Lighting& l, const View& v) {
  // In eye space the light's position is V times the world's; an infinite viewer looks along the
  // camera's axis, (0,0,1) in eye space, the column of V's inverse that maps it to the world.
  const glm::dmat4 V = view_matrix(v);
  const glm::dvec3 light = l.eye_space ? glm::dvec3(V * glm::dvec4(l.light_pos, 1)) : l.light_pos;
  const glm::dvec3 axis = l.eye_space ? glm::dvec3(0, 0, 1) : glm::dvec3(glm::inverse(V) * glm::dvec4(0, 0, 1, 0));
  const ShaderText text = shaders(l, light, axis);
  const std::string key = text.vertex + text.fragment;
  if (auto it = programs_.find(key); it != programs_.end()) return it->second;
  const GLuint vs = compile(gl_, GL_VERTEX_SHADER, text.vertex);
  GLuint fs = 0;
  try {
    fs = compile(gl_, GL_FRAGMENT_SHADER, text.fragment);
  } catch (...) {
    gl_.DeleteShader(vs);
    throw;
  }
  const GLuint p = gl_.CreateProgram();
  gl_.AttachShader(p, vs);
  gl_.AttachShader(p, fs);
  gl_.LinkProgram(p);
  gl_.DeleteShader(vs);  // flagged: freed with the program
  gl_.DeleteShader(fs);
  if (const std::string log = failure_log(p, GL_LINK_STATUS, gl_.GetProgramiv, gl_.GetProgramInfoLog, gl_.DeleteProgram);
      !log.empty())
    throw std::runtime_error("the program does not link: " + log);
  programs_.emplace(key, p);
  return p;
}

void Renderer::draw(const Lighting& l, const View& v) {
  const GLuint p = program(l, v);
  gl_.ClearColor(0, 0, 0, 1);
  gl_.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  gl_.Enable(GL_DEPTH_TEST);
  gl_.UseProgram(p);
  // The handout computes P, V and M with PyGLM in float32 and uploads them as they are; lighting
  // in eye space takes V as the "model" matrix (M is the identity) and the eye at the origin.
  const glm::dmat4 V = view_matrix(v);
  const glm::mat4 mvp(projection(v) * V);
  const glm::mat4 m = l.eye_space ? glm::mat4(V) : glm::mat4(1.0f);
  const glm::vec3 view_pos = l.eye_space ? glm::vec3(0) : glm::vec3(eye_position(v));
  gl_.UniformMatrix4fv(gl_.GetUniformLocation(p, "MVP"), 1, GL_FALSE, glm::value_ptr(mvp));
  gl_.UniformMatrix4fv(gl_.GetUniformLocation(p, "M"), 1, GL_FALSE, glm::value_ptr(m));
  gl_.Uniform3fv(gl_.GetUniformLocation(p, "view_pos"), 1, glm::value_ptr(view_pos));
  if (l.averaged_normals) {
    gl_.BindVertexArray(vao_[1]);
    gl_.DrawElements(GL_TRIANGLES, GLsizei(averaged_normal_indices().size()), GL_UNSIGNED_INT, nullptr);
  } else {
    gl_.BindVertexArray(vao_[0]);
    gl_.DrawArrays(GL_TRIANGLES, 0, GLsizei(face_normal_vertices().size()));
  }
  gl_.BindVertexArray(0);
  check_error(gl_, "drawing the cube");
}

Headless::Headless(int width, int height) : width_(width), height_(height) {
  if (width < 1 || height < 1 || width > 8192 || height > 8192)
    throw std::invalid_argument("picture size " + std::to_string(width) + "x" + std::to_string(height) +
                                " is not 1..8192 a side");
  std::string why;
  if (!ffc::platform::EglContext::available(&why)) throw std::runtime_error("no headless EGL context: " + why);
  ffc::platform::EglRequest r;
  r.profile = ffc::platform::Profile::Core;
  r.major = 3, r.minor = 3;
  r.width = width, r.height = height;
  context_ = std::make_unique<ffc::platform::EglContext>(r);
  context_->make_current();
  if (const auto missing = gl_.load(&ffc::platform::EglContext::proc_address); !missing.empty())
    throw std::runtime_error("the core-profile context does not provide " + missing.front());
  renderer_ = std::make_unique<Renderer>(gl_);
}

Headless::~Headless() {
  // The GL objects go while their context is current.
  if (context_ && !context_->is_current()) context_->make_current();
  renderer_.reset();
}

ffc::image::Image Headless::render(const Lighting& l, const View& v) {
  if (!context_->is_current()) context_->make_current();
  gl_.Viewport(0, 0, width_, height_);
  View sized = v;
  sized.width = width_, sized.height = height_;
  renderer_->draw(l, sized);
  ffc::image::Image img(width_, height_);
  gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl_.ReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba.data());
  check_error(gl_, "reading the picture back");
  // GL's rows come bottom first; the image's top first.
  for (int y = 0; y < height_ / 2; ++y)
    std::swap_ranges(img.at(0, y), img.at(0, y) + size_t(width_) * 4, img.at(0, height_ - 1 - y));
  return img;
}

std::string Headless::gl_renderer() const {
  const GLubyte* s = gl_.GetString(GL_RENDERER);
  return s ? reinterpret_cast<const char*>(s) : "";
}

}  // namespace seed001
