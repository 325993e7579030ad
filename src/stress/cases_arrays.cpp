// The stress catalogue's arrays cases (stress/cases.cpp says what the catalogue is).
#include "stress/case_kit.h"

namespace ffc::stress::kit {

void add_arrays(std::vector<Case>& out) {
  auto add = [&](Case c) { out.push_back(std::move(c)); };
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
}

}  // namespace ffc::stress::kit
