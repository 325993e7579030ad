// Why the seeds insist on unit normals. GL lights with the normal transformed by the inverse
// transpose of the modelview's upper 3x3, and never normalizes it on its own. Rotations and
// translations keep lengths, but glScalef(s,s,s) multiplies every normal by 1/s, and a
// non-uniform glScalef(1,.2,1) (the seed's "try to uncomment") stretches each normal by a
// different amount depending on its direction (the top face's by 5, the front face's not at all).
// N.L and N.H then grow with the length: faces come out too bright, the highlight saturates.
//   GL_NORMALIZE       divides every transformed normal by its length: right for any scaling.
//   GL_RESCALE_NORMAL  multiplies by one factor read off the modelview (1/s for a uniform scale):
//                      cheaper, exact for uniform scaling if the normals were unit to begin
//                      with, and no help for a non-uniform one.
// The scene is the cube lab's with face normals, the cube scaled around its centre.
//   keys: K next of the 6 (mode x scale) combinations, 1/3/2/W move the camera
#include "harness.h"
#include "lab_scene.h"

static lab::Camera gCam;
static const char* const kModes[] = {"none", "normalize", "rescale"};
static const char* const kScales[] = {"uniform", "nonuniform"};
static int gMode = 0;   // index into kModes
static int gScale = 1;  // index into kScales: the seed's glScalef(1,.2,1) first

static void render(int, int) {
  lab::beginRender(gCam);  // turns GL_RESCALE_NORMAL on, as the seed does
  glDisable(GL_RESCALE_NORMAL);
  glDisable(GL_NORMALIZE);
  if (gMode == 1) glEnable(GL_NORMALIZE);
  if (gMode == 2) glEnable(GL_RESCALE_NORMAL);

  glPushMatrix();
  if (gScale == 0)
    glScalef(.5f, .5f, .5f);
  else
    glScalef(1.f, .2f, 1.f);
  lab::drawCube_glDrawArray();
  glPopMatrix();

  glDisable(GL_LIGHTING);
}

static void key_callback(int key) {
  if (gCam.on_key(key)) return;
  if (key == 'K') {  // modes first, then scales: none, normalize, rescale under one scale, ...
    const int next = (gScale * 3 + gMode + 1) % 6;
    gScale = next / 3;
    gMode = next % 3;
  }
}

static int index_of(const char* const* names, int n, const std::string& name) {
  for (int i = 0; i < n; ++i)
    if (name == names[i]) return i;
  return 0;
}

int main(int argc, char** argv) {
  ffc::examples::Example ex;
  ex.name = "normalize_rescale";
  ex.title = "normalize_rescale: GL_NORMALIZE vs GL_RESCALE_NORMAL under glScalef (K cycles)";
  ex.width = ex.height = 640;
  ex.draw = render;
  ex.on_key = key_callback;
  ex.state = [] {
    static const char* const fix[] = {"neither GL_NORMALIZE nor GL_RESCALE_NORMAL", "GL_NORMALIZE", "GL_RESCALE_NORMAL"};
    return std::string(fix[gMode]) + (gScale == 0 ? ", glScalef(.5,.5,.5)" : ", glScalef(1,.2,1)") +
           ", GL_SMOOTH, face normals, glDrawArrays, camera " + gCam.describe();
  };
  ex.add_options = [](CLI::App& app) {
    static std::string mode = kModes[gMode], scale = kScales[gScale];
    app.add_option("--mode", mode, "What fixes the normals' length: none, normalize or rescale")
        ->check(CLI::IsMember({"none", "normalize", "rescale"}))
        ->capture_default_str()
        ->each([](const std::string& m) { gMode = index_of(kModes, 3, m); });
    app.add_option("--scale", scale, "uniform: glScalef(.5,.5,.5); nonuniform: glScalef(1,.2,1)")
        ->check(CLI::IsMember({"uniform", "nonuniform"}))
        ->capture_default_str()
        ->each([](const std::string& s) { gScale = index_of(kScales, 2, s); });
  };
  return ffc::examples::run_example(argc, argv, ex);
}
