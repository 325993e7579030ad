// Seed 000, "[Practice] OpenGL Lighting": a red cube lit by one point light, drawn either with
// glBegin/glNormal/glVertex (drawCube_glVertex) or from one interleaved array (drawCube_glDrawArray).
// The two paths feed GL the same vertices and normals, so they must give the same picture.
//   keys: 1/3 turn the camera, 2/W raise/lower it, V switch between the two drawing paths
#include "harness.h"
#include "lab_scene.h"

static lab::Camera gCam;
static bool gUseDrawArray = true;  // the seed's render() calls drawCube_glDrawArray()

// One glNormal3f per face: every vertex after it takes that normal, which is what makes the
// cube flat-shaded even under GL_SMOOTH.
static void drawCube_glVertex() {
  glBegin(GL_TRIANGLES);

  glNormal3f(0, 0, 1);  // v0, v2, v1, v0, v3, v2 normal
  glVertex3f(-1, 1, 1);   // v0 position
  glVertex3f(1, -1, 1);   // v2 position
  glVertex3f(1, 1, 1);    // v1 position

  glVertex3f(-1, 1, 1);   // v0 position
  glVertex3f(-1, -1, 1);  // v3 position
  glVertex3f(1, -1, 1);   // v2 position

  glNormal3f(0, 0, -1);
  glVertex3f(-1, 1, -1);   // v4
  glVertex3f(1, 1, -1);    // v5
  glVertex3f(1, -1, -1);   // v6

  glVertex3f(-1, 1, -1);   // v4
  glVertex3f(1, -1, -1);   // v6
  glVertex3f(-1, -1, -1);  // v7

  glNormal3f(0, 1, 0);
  glVertex3f(-1, 1, 1);   // v0
  glVertex3f(1, 1, 1);    // v1
  glVertex3f(1, 1, -1);   // v5

  glVertex3f(-1, 1, 1);   // v0
  glVertex3f(1, 1, -1);   // v5
  glVertex3f(-1, 1, -1);  // v4

  glNormal3f(0, -1, 0);
  glVertex3f(-1, -1, 1);  // v3
  glVertex3f(1, -1, -1);  // v6
  glVertex3f(1, -1, 1);   // v2

  glVertex3f(-1, -1, 1);   // v3
  glVertex3f(-1, -1, -1);  // v7
  glVertex3f(1, -1, -1);   // v6

  glNormal3f(1, 0, 0);
  glVertex3f(1, 1, 1);    // v1
  glVertex3f(1, -1, 1);   // v2
  glVertex3f(1, -1, -1);  // v6

  glVertex3f(1, 1, 1);    // v1
  glVertex3f(1, -1, -1);  // v6
  glVertex3f(1, 1, -1);   // v5

  glNormal3f(-1, 0, 0);
  glVertex3f(-1, 1, 1);    // v0
  glVertex3f(-1, -1, -1);  // v7
  glVertex3f(-1, -1, 1);   // v3

  glVertex3f(-1, 1, 1);    // v0
  glVertex3f(-1, 1, -1);   // v4
  glVertex3f(-1, -1, -1);  // v7
  glEnd();
}

static void render(int, int) {
  lab::beginRender(gCam);

  glPushMatrix();
  // glScalef(1., .2, 1.);  // try it: see normalize_rescale for what it does to the lighting
  glColor3ub(0, 0, 255);  // glColor*() is ignored while lighting is enabled
  if (gUseDrawArray)
    lab::drawCube_glDrawArray();
  else
    drawCube_glVertex();
  glPopMatrix();

  glDisable(GL_LIGHTING);
}

static void key_callback(int key) {
  if (gCam.on_key(key)) return;
  if (key == 'V') gUseDrawArray = !gUseDrawArray;
}

int main(int argc, char** argv) {
  ffc::examples::Example ex;
  ex.name = "cube_lab";
  ex.title = "cube_lab: OpenGL lighting practice (V: glVertex / glDrawArrays)";
  ex.width = ex.height = 640;
  ex.draw = render;
  ex.on_key = key_callback;
  ex.state = [] {
    return std::string("GL_SMOOTH, face normals, ") + (gUseDrawArray ? "glDrawArrays" : "glBegin/glVertex") +
           ", GL_RESCALE_NORMAL, camera " + gCam.describe();
  };
  ex.add_options = [](CLI::App& app) {
    static std::string path = "arrays";
    app.add_option("--path", path, "How the cube is drawn: vertex (glBegin) or arrays (glDrawArrays)")
        ->check(CLI::IsMember({"vertex", "arrays"}))
        ->capture_default_str()
        ->each([](const std::string& p) { gUseDrawArray = p == "arrays"; });
  };
  return ffc::examples::run_example(argc, argv, ex);
}
