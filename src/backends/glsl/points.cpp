#include "backends/glsl/points.h"

#include <algorithm>
#include <cmath>

#include "backends/glsl/unfilled.h"

namespace ffc::glsl {

int point_width(float point_size) {
  const float size = std::min(point_size, 255.0f);  // NaN or not positive: 1 below
  const float snapped = std::floor((size > 0 ? size : 1.0f) * 256.0f + 0.5f);
  return std::max(1, int((snapped + 127.0f) / 256.0f));
}

void point_uniforms(const ProgramKey& k, const state::SinkState* s, std::vector<Uniform>& out) {
  if (!k.points) return;
  Uniform vp{"u_point_viewport", "vec4", 4, {}}, w{"u_point_width", "float", 1, {}};
  if (s) {
    for (int i = 0; i < 4; ++i) vp.value[size_t(i)] = float(s->viewport[i]);
    w.value[0] = float(point_width(s->point_size));
  }
  out.push_back(vp), out.push_back(w);
}

std::string point_vertex_renames(const ProgramKey& k, const std::vector<std::string>& colours) {
  if (!k.points) return "";
  ProgramKey u = k;  // the same renames as glPolygonMode's geometry shader reads
  u.unfilled = GL_POINT;
  return unfilled_vertex_renames(u, colours);
}

std::string point_geometry(const ProgramKey& k, const std::vector<std::string>& colours) {
  if (!k.points) return "";
  const std::string q = k.flat ? "flat " : "";
  std::string g = "#version 330 core\n// ffcompat: GL_POINTS as squares of whole pixels\n";
  g += "layout(points) in;\nlayout(triangle_strip, max_vertices = 4) out;\n";
  g += "uniform vec4 u_point_viewport;  // x, y, width, height\nuniform float u_point_width;\n";
  for (const std::string& c : colours) g += q + "in vec4 g" + c + "[];\n" + q + "out vec4 " + c + ";\n";
  if (k.fog) g += "in float gv_fog[];\nout float v_fog;\n";
  g += "void corner(vec2 px, float z) {\n";
  g += "  gl_Position = vec4((px - u_point_viewport.xy) / u_point_viewport.zw * 2.0 - 1.0, z, 1.0);\n";
  // A point has no back: its square shows the front colours whatever the strip's winding.
  for (std::string c : colours) {
    const std::string out = c;
    if (const size_t at = c.find("back"); at != std::string::npos) c.replace(at, 4, "front");
    g += "  " + out + " = g" + c + "[0];\n";
  }
  if (k.fog) g += "  v_fog = gv_fog[0];\n";
  g += "  EmitVertex();\n}\n";
  // A point whose centre is outside the view volume is not drawn (GL 2.1 section 2.12).
  g += "void main() {\n  vec4 p = gl_in[0].gl_Position;\n";
  g += "  if (any(greaterThan(abs(p.xyz), vec3(p.w)))) return;\n";
  g += "  vec3 n = p.xyz / p.w;\n";
  g += "  vec2 half_size = u_point_viewport.zw * 0.5;\n";
  g += "  vec2 win = n.xy * half_size + (u_point_viewport.xy + half_size);\n";
  // llvmpipe snaps the centre to 1/256 pixel (half away from zero), counts rows downwards and
  // moves them one step lower; in rows counted upwards that makes the square's top row boundary
  // ceil((sy + 1) / 256) + (w - 1) / 2 for an odd width, ceil((sy - 127) / 256) + w / 2 for an
  // even one (raster::draw_point's rule with the window height cancelled).
  g += "  vec2 s = sign(win) * floor(abs(win) * 256.0 + 0.5);\n";
  g += "  float w = u_point_width;\n";
  g += "  bool odd = mod(w, 2.0) == 1.0;\n";
  g += "  float x0 = odd ? floor(s.x / 256.0) - (w - 1.0) * 0.5 : floor((s.x + 128.0) / 256.0) - w * 0.5;\n";
  g += "  float top = odd ? ceil((s.y + 1.0) / 256.0) + (w - 1.0) * 0.5 : ceil((s.y - 127.0) / 256.0) + w * 0.5;\n";
  g += "  corner(vec2(x0, top - w), n.z);\n  corner(vec2(x0 + w, top - w), n.z);\n";
  g += "  corner(vec2(x0, top), n.z);\n  corner(vec2(x0 + w, top), n.z);\n  EndPrimitive();\n}\n";
  return g;
}

}  // namespace ffc::glsl
