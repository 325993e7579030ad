// The stress catalogue's attenuation cases (stress/cases.cpp says what the catalogue is).
#include "stress/case_kit.h"

namespace ffc::stress::kit {

void add_attenuation(std::vector<Case>& out) {
  auto add = [&](Case c) { out.push_back(std::move(c)); };
  {
    Case c;
    c.group = "attenuation";
    c.name = "attenuation_zero";
    c.draw = lit_grid([] {
      const GLfloat p[] = {0, 0, 0, 1};
      glLightfv(GL_LIGHT0, GL_POSITION, p);
      glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, 0);
    });
    c.note = "Constant, linear and quadratic attenuation all 0 (each is allowed: >= 0): the attenuation "
             "1/(k0 + k1 d + k2 d^2) divides by zero, unspecified (2.1.1). In IEEE it is +inf: channels "
             "with a positive sum go to +inf and clamp to 1 (here every channel: the light's ambient is "
             "0.1); a channel whose sum is 0 would be inf * 0 = NaN (see attenuation_zero_dark_channel).";
    c.mesa = MesaExpectation::Undefined;
    c.mesa_reason = "attenuation 1/0";
    add(c);
  }
  {
    Case c;
    c.group = "attenuation";
    c.name = "attenuation_zero_dark_channel";
    c.draw = lit_grid([] {
      const GLfloat p[] = {0, 0, 0, 1}, d[] = {1, 0.5f, 0, 1}, zero[] = {0, 0, 0, 1};
      glLightfv(GL_LIGHT0, GL_POSITION, p);
      glLightfv(GL_LIGHT0, GL_DIFFUSE, d);
      glLightfv(GL_LIGHT0, GL_SPECULAR, zero);
      glLightfv(GL_LIGHT0, GL_AMBIENT, zero);
      glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, 0);
    });
    c.note = "Attenuation all 0 with a light whose blue is 0 (diffuse (1, 0.5, 0), no ambient or "
             "specular): red and green are +inf and clamp to 1; blue is +inf * 0 = NaN, unspecified "
             "(2.1.1). Mesa's clamp, min(max(x, 0), 1) with a max that keeps a NaN and a min that drops "
             "it, makes it 1; ours does the same at the end of lighting, so no NaN reaches the raster.";
    c.mesa = MesaExpectation::Undefined;
    c.mesa_reason = "attenuation 1/0";
    add(c);
  }
  {
    Case c;
    c.group = "attenuation";
    c.name = "attenuation_huge_quadratic";
    c.draw = lit_grid([] {
      const GLfloat p[] = {0, 0, 0, 1};
      glLightfv(GL_LIGHT0, GL_POSITION, p);
      glLightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, 1e38f);
    });
    c.note = "Quadratic attenuation 1e38: k2 d^2 overflows float to +inf for d > 1.8, and the attenuation "
             "is 0 (exactly 1/inf) or 1e-38: the light vanishes, well defined.";
    add(c);
  }
  {
    Case c;
    c.group = "attenuation";
    c.name = "light_at_vertex";
    c.draw = lit_grid([] {
      const GLfloat p[] = {0, 0, -3, 1};  // the grid's centre vertex
      glLightfv(GL_LIGHT0, GL_POSITION, p);
      glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 1);
    });
    c.note = "A point light exactly at a vertex (the grid's centre): VP, the unit vector from the vertex "
             "to the light (2.14.1), does not exist there. Ours takes it as zero (n.L = 0: ambient only at "
             "that vertex; attenuation 1/(1 + 0) = 1). Mesa normalizes it as 0 * RSQ(0) = 0 * inf = NaN, "
             "which comes out of its lighting as 1: that vertex is white.";
    c.mesa = MesaExpectation::Undefined;
    c.mesa_reason = "the direction to a light at the vertex does not exist";
    add(c);
  }
}

}  // namespace ffc::stress::kit
