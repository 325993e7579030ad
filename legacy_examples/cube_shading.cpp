// Seed 001: the same cube flat and "smooth". Shading follows the normals you give, not the
// geometry: 36 vertices, each carrying its face's normal, make a flat cube; 8 shared vertices,
// each with one averaged normal, make the lighting blend across the edges.
//   keys: S flat/smooth cube, G glShadeModel GL_SMOOTH/GL_FLAT, 1/3/2/W move the camera
#include "harness.h"
#include "lab_scene.h"

static lab::Camera gCam;
static bool gSmoothCube = false;
static bool gShadeSmooth = true;  // GL's default, as in the seed

// prepare_vao_cube(), flat: position then normal (seed 001's layout), 12 triangles.
static const GLfloat gFlatVertices[36 * 6] = {
    -1, 1, 1,    0, 0, 1,   // v0
    1, -1, 1,    0, 0, 1,   // v2
    1, 1, 1,     0, 0, 1,   // v1
    -1, 1, 1,    0, 0, 1,   // v0
    -1, -1, 1,   0, 0, 1,   // v3
    1, -1, 1,    0, 0, 1,   // v2
    -1, 1, -1,   0, 0, -1,  // v4
    1, 1, -1,    0, 0, -1,  // v5
    1, -1, -1,   0, 0, -1,  // v6
    -1, 1, -1,   0, 0, -1,  // v4
    1, -1, -1,   0, 0, -1,  // v6
    -1, -1, -1,  0, 0, -1,  // v7
    -1, 1, 1,    0, 1, 0,   // v0
    1, 1, 1,     0, 1, 0,   // v1
    1, 1, -1,    0, 1, 0,   // v5
    -1, 1, 1,    0, 1, 0,   // v0
    1, 1, -1,    0, 1, 0,   // v5
    -1, 1, -1,   0, 1, 0,   // v4
    -1, -1, 1,   0, -1, 0,  // v3
    1, -1, -1,   0, -1, 0,  // v6
    1, -1, 1,    0, -1, 0,  // v2
    -1, -1, 1,   0, -1, 0,  // v3
    -1, -1, -1,  0, -1, 0,  // v7
    1, -1, -1,   0, -1, 0,  // v6
    1, 1, 1,     1, 0, 0,   // v1
    1, -1, 1,    1, 0, 0,   // v2
    1, -1, -1,   1, 0, 0,   // v6
    1, 1, 1,     1, 0, 0,   // v1
    1, -1, -1,   1, 0, 0,   // v6
    1, 1, -1,    1, 0, 0,   // v5
    -1, 1, 1,    -1, 0, 0,  // v0
    -1, -1, -1,  -1, 0, 0,  // v7
    -1, -1, 1,   -1, 0, 0,  // v3
    -1, 1, 1,    -1, 0, 0,  // v0
    -1, 1, -1,   -1, 0, 0,  // v4
    -1, -1, -1,  -1, 0, 0,  // v7
};

// The handout's smooth normal table. Each is the average of the normals of the *triangles* at
// that corner, not of the three faces: v1 sits in two right-face triangles but one front and one
// top, hence (2,1,1)/sqrt(6). Only v0 and v6, in one triangle per face, get (1,1,1)/sqrt(3).
static const GLfloat gSmoothVertices[8 * 6] = {
    -1, 1, 1,    -0.5773502691896258f, 0.5773502691896258f, 0.5773502691896258f,    // v0
    1, 1, 1,     0.8164965809277261f, 0.4082482904638631f, 0.4082482904638631f,     // v1
    1, -1, 1,    0.4082482904638631f, -0.4082482904638631f, 0.8164965809277261f,    // v2
    -1, -1, 1,   -0.4082482904638631f, -0.8164965809277261f, 0.4082482904638631f,   // v3
    -1, 1, -1,   -0.4082482904638631f, 0.4082482904638631f, -0.8164965809277261f,   // v4
    1, 1, -1,    0.4082482904638631f, 0.8164965809277261f, -0.4082482904638631f,    // v5
    1, -1, -1,   0.5773502691896258f, -0.5773502691896258f, -0.5773502691896258f,   // v6
    -1, -1, -1,  -0.8164965809277261f, -0.4082482904638631f, -0.4082482904638631f,  // v7
};
static const GLuint gIndices[12 * 3] = {
    0, 2, 1,  0, 3, 2,  4, 5, 6,  4, 6, 7,  0, 1, 5,  0, 5, 4,
    3, 6, 2,  3, 7, 6,  1, 2, 6,  1, 6, 5,  0, 7, 3,  0, 4, 7,
};

static void drawCube(const GLfloat* varr, GLsizei count, const GLuint* indices) {
  const GLsizei stride = 6 * sizeof(GLfloat);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glVertexPointer(3, GL_FLOAT, stride, varr);
  glNormalPointer(GL_FLOAT, stride, varr + 3);
  if (indices)
    glDrawElements(GL_TRIANGLES, count, GL_UNSIGNED_INT, indices);
  else
    glDrawArrays(GL_TRIANGLES, 0, count);
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
}

static void render(int, int) {
  lab::beginRender(gCam);
  // GL_FLAT lights each vertex all the same and then paints the triangle with the colour of its
  // last vertex; GL_SMOOTH interpolates the three colours (Gouraud).
  glShadeModel(gShadeSmooth ? GL_SMOOTH : GL_FLAT);

  glColor3ub(0, 0, 255);  // ignored under lighting
  if (gSmoothCube)
    drawCube(gSmoothVertices, 36, gIndices);
  else
    drawCube(gFlatVertices, 36, nullptr);

  glDisable(GL_LIGHTING);
}

static void key_callback(int key) {
  if (gCam.on_key(key)) return;
  if (key == 'S') gSmoothCube = !gSmoothCube;
  if (key == 'G') gShadeSmooth = !gShadeSmooth;
}

int main(int argc, char** argv) {
  ffc::examples::Example ex;
  ex.name = "cube_shading";
  ex.title = "cube_shading: face normals vs averaged normals (S cube, G shade model)";
  ex.width = ex.height = 640;
  ex.draw = render;
  ex.on_key = key_callback;
  ex.state = [] {
    return std::string(gShadeSmooth ? "GL_SMOOTH" : "GL_FLAT") +
           (gSmoothCube ? ", averaged normals (8 vertices, glDrawElements)" : ", face normals (36 vertices, glDrawArrays)") +
           ", GL_RESCALE_NORMAL, camera " + gCam.describe();
  };
  ex.add_options = [](CLI::App& app) {
    static std::string mode = "flat";
    app.add_option("--mode", mode, "flat: 36 vertices with face normals; smooth: 8 with averaged normals")
        ->check(CLI::IsMember({"flat", "smooth"}))
        ->capture_default_str()
        ->each([](const std::string& m) { gSmoothCube = m == "smooth"; });
  };
  return ffc::examples::run_example(argc, argv, ex);
}
