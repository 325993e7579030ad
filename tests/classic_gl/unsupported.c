/* A call soft does not implement: GL_INVALID_OPERATION each time, 0 from one that returns a
 * value, and exactly one line on stderr per name however often it is called. With no surface
 * current, calls do nothing (and say so once), and nothing crashes. */
#include "capture_stderr.h"
#include "classic_test.h"

int main(void) {
  require_ffcompat();
  /* No surface yet: nothing happens, nothing crashes, one line says so. */
  capture_begin();
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_TRIANGLES);
  glVertex3f(0, 0, 0);
  glEnd();
  const GLenum err_none = glGetError();
  const GLubyte* renderer_none = glGetString(GL_RENDERER);
  const GLboolean lit_none = glIsEnabled(GL_LIGHTING);
  capture_end();
  CHECK(err_none == 0 && renderer_none == NULL && lit_none == 0, "calls with no surface returned something");
  CHECK(lines_naming("no current GL surface") == 1, "stderr was: %s", captured);

  ffcompat_surface* s = surface_on("soft", 8, 8);
  CHECK(glGetError() == GL_NO_ERROR, "a fresh surface has an error");
  capture_begin();
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  const GLenum first = glGetError();
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  const GLenum second = glGetError();
  const GLboolean is_texture = glIsTexture(1);
  const GLenum third = glGetError();
  capture_end();
  CHECK(first == GL_INVALID_OPERATION && second == GL_INVALID_OPERATION, "errors %#x %#x", first, second);
  CHECK(is_texture == 0 && third == GL_INVALID_OPERATION, "glIsTexture gave %d, error %#x", is_texture, third);
  CHECK(lines_naming("glTexImage2D") == 1, "stderr was: %s", captured);
  CHECK(strstr(captured, "ffcompat: glTexImage2D is not implemented by the soft backend; it records "
                         "GL_INVALID_OPERATION\n") != NULL,
        "stderr was: %s", captured);
  CHECK(lines_naming("glIsTexture") == 1, "stderr was: %s", captured);

  /* A supported call reports nothing and records no error. */
  capture_begin();
  glEnable(GL_LIGHTING);
  capture_end();
  CHECK(captured[0] == 0 && glGetError() == GL_NO_ERROR, "stderr was: %s", captured);

  /* The current surface destroyed: none current, calls do nothing again. */
  ffcompat_surface_destroy(s);
  capture_begin();
  glEnable(GL_LIGHTING);
  const GLboolean lit_after = glIsEnabled(GL_LIGHTING);
  capture_end();
  CHECK(lit_after == 0, "a destroyed surface answered");
  CHECK(captured[0] == 0, "the no-surface line came twice: %s", captured);
  ffcompat_surface_make_current(NULL);
  ffcompat_surface_destroy(NULL);
  ffcompat_surface_read_rgba(NULL, NULL);

  /* An unknown backend: no surface, and a line listing the valid names. */
  capture_begin();
  setenv("FFCOMPAT_BACKEND", "no-such-backend", 1);
  ffcompat_surface* bad = ffcompat_surface_create(8, 8);
  capture_end();
  CHECK(bad == NULL, "a surface on an unknown backend");
  CHECK(strstr(captured, "unknown backend 'no-such-backend'") && strstr(captured, "soft") && strstr(captured, "mesa"),
        "stderr was: %s", captured);
  setenv("FFCOMPAT_BACKEND", "soft", 1);
  capture_begin();
  ffcompat_surface* empty = ffcompat_surface_create(0, 8);
  capture_end();
  CHECK(empty == NULL && strstr(captured, "0x8"), "a 0x8 surface; stderr was: %s", captured);
  return finish();
}
