// The stress catalogue's normals cases (stress/cases.cpp says what the catalogue is).
#include "stress/case_kit.h"

namespace ffc::stress::kit {

void add_normals(std::vector<Case>& out) {
  auto add = [&](Case c) { out.push_back(std::move(c)); };
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
}

}  // namespace ffc::stress::kit
