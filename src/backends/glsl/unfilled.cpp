#include "backends/glsl/unfilled.h"

namespace ffc::glsl {

bool polygon_passes(const state::SinkState& s, GLenum mode, const std::function<void(const state::SinkState&)>& draw) {
  if (!needs_polygon_passes(s, mode)) return false;
  // The faces culling leaves, then one pass per mode among them.
  const bool shown[2] = {!s.cull || s.cull_mode == GL_BACK, !s.cull || s.cull_mode == GL_FRONT};
  for (GLenum m : {GL_FILL, GL_LINE, GL_POINT}) {
    const unsigned faces = unsigned(shown[0] && s.polygon_mode[0] == m) | unsigned(shown[1] && s.polygon_mode[1] == m) << 1;
    if (!faces) continue;
    state::SinkState p = s;
    p.pass_mode = m, p.pass_faces = faces;
    // The fill pass culls what the others draw; the geometry shader picks its own faces.
    p.cull = m == GL_FILL && faces != 3;
    p.cull_mode = faces == 1 ? GL_BACK : GL_FRONT;
    draw(p);
  }
  return true;
}

void unfilled_key(ProgramKey& k, const state::SinkState& s) {
  if (!unfilled_pass(s)) return;
  k.unfilled = s.pass_mode, k.unfilled_faces = s.pass_faces, k.front_cw = s.front_face == GL_CW;
}

std::string unfilled_vertex_renames(const ProgramKey& k, const std::vector<std::string>& colours) {
  if (!k.unfilled) return "";
  std::string d;
  for (const std::string& c : colours) d += "#define " + c + " g" + c + "\n";
  if (k.fog) d += "#define v_fog gv_fog\n";
  return d;
}

std::string unfilled_geometry(const ProgramKey& k, const std::vector<std::string>& colours) {
  if (!k.unfilled) return "";
  const bool lines = k.unfilled == GL_LINE;
  const std::string q = k.flat ? "flat " : "";
  std::string g = "#version 330 core\n// ffcompat: glPolygonMode ";
  g += lines ? "GL_LINE" : "GL_POINT";
  g += std::string(" for the ") + (k.unfilled_faces == 3 ? "front and back" : k.unfilled_faces == 1 ? "front" : "back") + " faces\n";
  g += "layout(triangles) in;\n";
  g += lines ? "layout(line_strip, max_vertices = 6) out;\n" : "layout(points, max_vertices = 3) out;\n";
  for (const std::string& c : colours) g += q + "in vec4 g" + c + "[];\n" + q + "out vec4 " + c + ";\n";
  if (k.fog) g += "in float gv_fog[];\nout float v_fog;\n";
  g += "uniform usamplerBuffer u_edges;  // per triangle: bit i, the edge from vertex i is on the boundary\n";
  // The face shown picks the colours (a line has no facing of its own); GL_FLAT takes the
  // provoking vertex's, the triangle's last.
  g += "void emit(int i, bool front) {\n  gl_Position = gl_in[i].gl_Position;\n";
  g += std::string("  int c = ") + (k.flat ? "2" : "i") + ";\n";
  const bool two = k.two_side();
  for (const std::string& c : colours) {
    if (c.find("back") != std::string::npos) continue;
    std::string back = c;
    back.replace(back.find("front"), 5, "back");
    g += "  " + c + " = " + (two ? "front ? g" + c + "[c] : g" + back + "[c]" : "g" + c + "[c]") + ";\n";
    if (two) g += "  " + back + " = " + c + ";\n";
  }
  if (k.fog) g += "  v_fog = gv_fog[i];\n";
  g += "  EmitVertex();\n}\n";
  g += "void main() {\n";
  g += "  vec2 a = gl_in[0].gl_Position.xy / gl_in[0].gl_Position.w;\n";
  g += "  vec2 b = gl_in[1].gl_Position.xy / gl_in[1].gl_Position.w;\n";
  g += "  vec2 c = gl_in[2].gl_Position.xy / gl_in[2].gl_Position.w;\n";
  g += "  float area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);\n";
  // As Mesa's pipeline: a zero area counts as back-facing under GL_CCW, front-facing under GL_CW,
  // and shows the front colours either way.
  g += std::string("  bool front = ") + (k.front_cw ? "!(area > 0.0)" : "area > 0.0") + ";\n";
  if (k.unfilled_faces != 3) g += std::string("  if (") + (k.unfilled_faces == 1 ? "!front" : "front") + ") return;\n";
  g += "  bool front_colours = front || area == 0.0;\n";
  g += "  uint edges = texelFetch(u_edges, gl_PrimitiveIDIn).r;\n";
  // Mesa's unfilled stage draws the edge from the last vertex first (where lines overlap, the
  // later one shows): 2 to 0, 0 to 1, 1 to 2; points 0, 1, 2.
  g += std::string("  for (int k = 0; k < 3; ++k) {\n    int i = ") + (lines ? "(k + 2) % 3" : "k") + ";\n";
  g += "    if ((edges & (1u << i)) == 0u) continue;\n";
  g += lines ? "    emit(i, front_colours);\n    emit((i + 1) % 3, front_colours);\n" : "    emit(i, front_colours);\n";
  g += "    EndPrimitive();\n  }\n}\n";
  return g;
}

void EdgeStream::stream(const CoreGl& gl, const state::SinkState& s) {
  if (!unfilled_pass(s)) return;
  if (!buffer_) gl.GenBuffers(1, &buffer_), gl.GenTextures(1, &texture_);
  gl.BindBuffer(GL_TEXTURE_BUFFER, buffer_);
  gl.BufferData(GL_TEXTURE_BUFFER, GLsizeiptr(flags_.size()), flags_.data(), GL_STREAM_DRAW);
  gl.BindTexture(GL_TEXTURE_BUFFER, texture_);  // unit 0, which u_edges names by default
  gl.TexBuffer(GL_TEXTURE_BUFFER, GL_R8UI, buffer_);
}

void EdgeStream::destroy(const CoreGl& gl) {
  if (buffer_) gl.DeleteBuffers(1, &buffer_), gl.DeleteTextures(1, &texture_);
  buffer_ = texture_ = 0;
}

}  // namespace ffc::glsl
