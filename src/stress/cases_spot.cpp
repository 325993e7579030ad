// The stress catalogue's spot lights cases (stress/cases.cpp says what the catalogue is).
#include "stress/case_kit.h"

namespace ffc::stress::kit {

void add_spot(std::vector<Case>& out) {
  auto add = [&](Case c) { out.push_back(std::move(c)); };
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
}

}  // namespace ffc::stress::kit
