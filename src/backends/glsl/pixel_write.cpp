#include "backends/glsl/pixel_write.h"

#include <string>
#include <vector>

namespace ffc::glsl {

void read_depth(const CoreGl& gl, uint32_t* depth, int width, int height) {
  std::vector<uint32_t> rows(size_t(width) * size_t(height));
  gl.PixelStorei(GL_PACK_ALIGNMENT, 4);
  gl.ReadPixels(0, 0, width, height, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, rows.data());
  for (size_t i = 0; i < rows.size(); ++i) depth[i] = rows[i] >> 8;  // the 24 bits are the high ones
}

namespace {

const char* const kVertex =
    "#version 330 core\n"
    "void main() {  // one triangle over the window: (-1, -1), (3, -1), (-1, 3)\n"
    "  gl_Position = vec4(float((gl_VertexID & 1) * 4 - 1), float((gl_VertexID >> 1) * 4 - 1), 0.0, 1.0);\n"
    "}\n";
const char* const kFragment =
    "#version 330 core\n"
    "uniform sampler2D u_color;\nuniform sampler2D u_depth;\nout vec4 o_color;\n"
    "void main() {\n"
    "  ivec2 p = ivec2(gl_FragCoord.xy);\n"
    "  o_color = texelFetch(u_color, p, 0);\n"
    "  gl_FragDepth = texelFetch(u_depth, p, 0).r;\n"
    "}\n";

}  // namespace

void PixelWriter::write(const CoreGl& gl, const uint8_t* rgba, const uint32_t* depth, int width, int height) {
  if (!program_) {
    program_ = gl.CreateProgram();
    const GLuint vs = compile_shader(gl, GL_VERTEX_SHADER, kVertex, "the pixel copy shader"),
                 fs = compile_shader(gl, GL_FRAGMENT_SHADER, kFragment, "the pixel copy shader");
    gl.AttachShader(program_, vs), gl.AttachShader(program_, fs);
    gl.DeleteShader(vs), gl.DeleteShader(fs);  // kept by the program until it is deleted
    link_program(gl, program_, "the pixel copy program");
    gl.UseProgram(program_);
    gl.Uniform1i(gl.GetUniformLocation(program_, "u_color"), 1);
    gl.Uniform1i(gl.GetUniformLocation(program_, "u_depth"), 2);
    gl.GenVertexArrays(1, &vao_);
    gl.GenTextures(2, textures_);
  }
  // The depth as the float the 24-bit value stands for (rows as GL's textures keep them).
  std::vector<float> z(size_t(width) * size_t(height));
  for (size_t i = 0; i < z.size(); ++i) z[i] = float(double(depth[i]) / 16777215.0);
  gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
  const struct {
    GLenum unit;
    GLint internal;
    GLenum format, type;
    const void* data;
  } planes[2] = {{GL_TEXTURE1, GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, rgba}, {GL_TEXTURE2, GL_R32F, GL_RED, GL_FLOAT, z.data()}};
  for (int i = 0; i < 2; ++i) {
    gl.ActiveTexture(planes[i].unit);
    gl.BindTexture(GL_TEXTURE_2D, textures_[i]);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl.TexImage2D(GL_TEXTURE_2D, 0, planes[i].internal, width, height, 0, planes[i].format, planes[i].type, planes[i].data);
  }
  gl.ActiveTexture(GL_TEXTURE0);
  GLint vao = 0;
  gl.GetIntegerv(GL_VERTEX_ARRAY_BINDING, &vao);
  gl.UseProgram(program_);
  gl.BindVertexArray(vao_);
  gl.Viewport(0, 0, width, height);
  for (GLenum cap : {GL_BLEND, GL_SCISSOR_TEST, GL_CULL_FACE, GL_POLYGON_OFFSET_FILL}) gl.Disable(cap);
  gl.Enable(GL_DEPTH_TEST);
  gl.DepthFunc(GL_ALWAYS);
  gl.DepthMask(GL_TRUE);
  gl.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  gl.DrawArrays(GL_TRIANGLES, 0, 3);
  gl.BindVertexArray(GLuint(vao));
}

void PixelWriter::destroy(const CoreGl& gl) {
  if (!program_) return;
  gl.DeleteProgram(program_);
  gl.DeleteVertexArrays(1, &vao_);
  gl.DeleteTextures(2, textures_);
  program_ = 0;
}

}  // namespace ffc::glsl
