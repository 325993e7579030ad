// The stress catalogue's viewer cases (stress/cases.cpp says what the catalogue is).
#include "stress/case_kit.h"

namespace ffc::stress::kit {

void add_viewer(std::vector<Case>& out) {
  auto add = [&](Case c) { out.push_back(std::move(c)); };
  {
    Case c;
    c.group = "viewer";
    c.name = "local_viewer_eye_on_surface";
    c.draw = [] {
      scenes::standard();
      glMatrixMode(GL_PROJECTION);
      glLoadIdentity();
      glOrtho(-1, 1, -1, 1, -1, 1);  // the eye's plane z = 0 is inside the view volume
      glMatrixMode(GL_MODELVIEW);
      glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
      const GLfloat p[] = {0.5f, 0.5f, 1, 1};
      glLightfv(GL_LIGHT0, GL_POSITION, p);
      glRotatef(-30, 1, 0, 0);  // a grid through the eye, tilted, with a vertex at the eye
      scenes::draw(scenes::grid(8), 0.9);
    };
    c.note = "A local viewer (the eye at (0, 0, 0) of eye space) and a grid through the eye with a vertex "
             "exactly there: VP_e, the unit vector toward the eye (2.14.1), does not exist at that vertex. "
             "Ours takes it as zero, so h = VP_pli there. Mesa normalizes the zero vector to NaN (0 * "
             "RSQ(0)) and its specular term changes there: that vertex is 0.025 darker.";
    c.mesa = MesaExpectation::Undefined;
    c.mesa_reason = "the direction to the eye does not exist at the eye";
    add(c);
  }
}

}  // namespace ffc::stress::kit
