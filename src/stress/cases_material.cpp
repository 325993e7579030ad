// The stress catalogue's material and colours cases (stress/cases.cpp says what the catalogue is).
#include "stress/case_kit.h"

namespace ffc::stress::kit {

void add_material(std::vector<Case>& out) {
  auto add = [&](Case c) { out.push_back(std::move(c)); };
  {
    Case c;
    c.group = "material";
    c.name = "shininess_0";
    c.draw = [] {
      scenes::standard();
      glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 0);
      glTranslatef(0, 0, -4);
      scenes::draw(scenes::sphere(3));
    };
    c.note = "Shininess 0: (n.h)^0 = 1 wherever n.L > 0 (2.14.1 with 0^0 = 1, 2.1.1), so the full "
             "specular colour is added on the whole lit side. Mesa's LIT instruction takes pow(0, 0) as 0, "
             "which matters only where n.h is exactly 0 (not met here).";
    add(c);
  }
  {
    Case c;
    c.group = "material";
    c.name = "shininess_128";
    c.draw = [] {
      scenes::standard();
      glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 128);
      glTranslatef(0, 0, -4);
      scenes::draw(scenes::sphere(3));
    };
    c.note = "Shininess 128, the largest allowed: (n.h)^128 underflows float (to denormals, or to zero "
             "where denormals flush) away from the highlight; the differences are below 1e-30.";
    add(c);
  }
  {
    Case c;
    c.group = "material";
    c.name = "colours_out_of_range";
    c.draw = [] {
      scenes::standard();
      const GLfloat ld[] = {4, 3, -2, 1}, ls[] = {10, -5, 10, 1}, la[] = {-1, 2, 0.5f, 1};
      glLightfv(GL_LIGHT0, GL_DIFFUSE, ld);
      glLightfv(GL_LIGHT0, GL_SPECULAR, ls);
      glLightfv(GL_LIGHT0, GL_AMBIENT, la);
      const GLfloat e[] = {-0.5f, 0.25f, 1.5f, 1}, ga[] = {2, -1, 0.5f, 1}, md[] = {0.8f, 0.6f, 0.4f, 2.5f};
      glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, e);
      glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, md);
      glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ga);
      glTranslatef(0, 0, -4);
      scenes::draw(scenes::sphere(3));
    };
    c.note = "Light and material colours above 1 and below 0 (diffuse 4, specular 10 and -5, ambient -1, "
             "emission -0.5, global ambient 2, diffuse alpha 2.5). GL 2.1 takes them unclamped into the "
             "lighting equation (2.14.1) and clamps only the result to [0,1] (2.14.6), alpha included.";
    add(c);
  }
}

}  // namespace ffc::stress::kit
