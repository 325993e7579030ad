/* FFCOMPAT_BACKEND=glsl as a program meets what it lacks: a call neither soft nor glsl implements
 * records GL_INVALID_OPERATION and is named once on stderr with the backend's name; fog, which the
 * GLSL backend may not draw yet, never crashes and is named at most once however many draws use
 * it; glsl and glsl-phong are among the names an unknown backend's line lists. */
#include "capture_stderr.h"
#include "classic_test.h"

static void fogged_triangle(void) {
  glBegin(GL_TRIANGLES);
  glColor3f(1, 1, 1);
  glVertex3f(-1, -1, -0.5f);
  glVertex3f(1, -1, -0.5f);
  glVertex3f(0, 1, -0.5f);
  glEnd();
}

int main(void) {
  require_ffcompat();
  ffcompat_surface* s = surface_on("glsl", 16, 16);
  CHECK(strcmp(ffcompat_surface_backend(s), "glsl") == 0, "backend %s", ffcompat_surface_backend(s));
  CHECK(glGetError() == GL_NO_ERROR, "a fresh surface has an error");

  /* The accumulation buffer: neither soft nor glsl has one. */
  GLenum errors[2];
  capture_begin();
  for (int i = 0; i < 2; ++i) {
    glAccum(GL_LOAD, 1.0f);
    errors[i] = glGetError();
  }
  capture_end();
  CHECK(errors[0] == GL_INVALID_OPERATION && errors[1] == GL_INVALID_OPERATION, "errors %#x %#x", errors[0], errors[1]);
  CHECK(lines_naming("ffcompat: glAccum is not implemented by the glsl backend; it records GL_INVALID_OPERATION\n") == 1,
        "stderr was: %s", captured);

  /* Fog on, three draws and a read: one line at most, and the fogless (or fogged) picture is there. */
  glEnable(GL_FOG);
  glClearColor(0, 0, 0, 1);
  capture_begin();
  for (int i = 0; i < 3; ++i) {
    glClear(GL_COLOR_BUFFER_BIT);
    fogged_triangle();
  }
  static unsigned char img[16 * 16 * 4];
  ffcompat_surface_read_rgba(s, img);
  capture_end();
  CHECK(glGetError() == GL_NO_ERROR, "fog recorded an error");
  CHECK(lines_naming("fog") <= 1, "stderr was: %s", captured);
  CHECK(captured[0] == 0 || lines_naming("ffcompat: the GLSL backend does not draw fog; drawn without it\n") == 1,
        "stderr was: %s", captured);
  const unsigned char* centre = img + ((size_t)8 * 16 + 8) * 4;
  CHECK(centre[0] > 0, "nothing drawn at the centre (%d %d %d)", centre[0], centre[1], centre[2]);
  ffcompat_surface_destroy(s);

  ffcompat_surface* phong = surface_on("glsl-phong", 8, 8);
  CHECK(strcmp(ffcompat_surface_backend(phong), "glsl-phong") == 0, "backend %s", ffcompat_surface_backend(phong));
  ffcompat_surface_destroy(phong);

  capture_begin();
  setenv("FFCOMPAT_BACKEND", "no-such-backend", 1);
  ffcompat_surface* bad = ffcompat_surface_create(8, 8);
  capture_end();
  CHECK(bad == NULL, "a surface on an unknown backend");
  CHECK(strstr(captured, ", glsl,") && strstr(captured, "glsl-phong"), "stderr was: %s", captured);
  return finish();
}
