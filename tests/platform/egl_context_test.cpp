// The headless EGL platform: compatibility and core-profile contexts on Mesa's EGL, drawn into
// and read back. Skipped (with the reason) where no EGL display with desktop GL exists.
#include "platform/egl_context.h"

#include <GL/gl.h>
#include <gtest/gtest.h>

#include <cstring>
#include <string>

namespace ffc::platform {
namespace {

template <class F>
F fn(const char* name) {
  return reinterpret_cast<F>(EglContext::proc_address(name));
}

void require_egl() {
  std::string why;
  if (!EglContext::available(&why)) GTEST_SKIP() << why;
}

TEST(EglContext, CompatibilityContextClearsAndReadsBack) {
  require_egl();
  EglRequest r;
  r.width = 17, r.height = 9;
  EglContext ctx(r);
  auto get_string = fn<const GLubyte* (*)(GLenum)>("glGetString");
  const std::string version = reinterpret_cast<const char*>(get_string(GL_VERSION));
  EXPECT_NE(version.find("Compatibility"), std::string::npos) << version;
  fn<void (*)(GLfloat, GLfloat, GLfloat, GLfloat)>("glClearColor")(1.0f, 0.5f, 0.0f, 1.0f);
  fn<void (*)(GLbitfield)>("glClear")(GL_COLOR_BUFFER_BIT);
  GLubyte px[4] = {};
  // The pbuffer's far corner: it has the requested size.
  fn<void (*)(GLint, GLint, GLsizei, GLsizei, GLenum, GLenum, void*)>("glReadPixels")(16, 8, 1, 1, GL_RGBA,
                                                                                     GL_UNSIGNED_BYTE, px);
  EXPECT_EQ(px[0], 255);
  EXPECT_EQ(px[1], 128);  // 0.5 * 255 = 127.5 rounds to 128
  EXPECT_EQ(px[2], 0);
  EXPECT_EQ(px[3], 255);
  // Fixed function is there: feedback of one vertex at the viewport's centre.
  GLfloat buf[8] = {};
  fn<void (*)(GLsizei, GLenum, GLfloat*)>("glFeedbackBuffer")(8, GL_2D, buf);
  fn<GLint (*)(GLenum)>("glRenderMode")(GL_FEEDBACK);
  fn<void (*)(GLenum)>("glBegin")(GL_POINTS);
  fn<void (*)(GLfloat, GLfloat)>("glVertex2f")(0.0f, 0.0f);
  fn<void (*)()>("glEnd")();
  EXPECT_EQ(fn<GLint (*)(GLenum)>("glRenderMode")(GL_RENDER), 3);
  EXPECT_EQ(buf[0], GLfloat(GL_POINT_TOKEN));
  EXPECT_EQ(buf[1], 8.5f);
  EXPECT_EQ(buf[2], 4.5f);
}

TEST(EglContext, CoreProfileContext) {
  require_egl();
  EglRequest r;
  r.profile = Profile::Core, r.major = 3, r.minor = 3;
  EglContext ctx(r);
  EXPECT_TRUE(ctx.is_current());
  GLint mask = 0;
  fn<void (*)(GLenum, GLint*)>("glGetIntegerv")(0x9126 /* GL_CONTEXT_PROFILE_MASK */, &mask);
  EXPECT_EQ(mask & 1, 1);  // GL_CONTEXT_CORE_PROFILE_BIT
  // Fixed function is gone: glBegin is an invalid operation in a core context.
  fn<void (*)(GLenum)>("glBegin")(GL_TRIANGLES);
  EXPECT_EQ(fn<GLenum (*)()>("glGetError")(), GLenum(GL_INVALID_OPERATION));
  EXPECT_NE(ctx.description().find("EGL"), std::string::npos);
}

TEST(EglContext, TwoContextsKeepTheirOwnPictures) {
  require_egl();
  EglRequest r;
  r.width = 4, r.height = 4;
  EglContext a(r), b(r);
  auto clear_color = fn<void (*)(GLfloat, GLfloat, GLfloat, GLfloat)>("glClearColor");
  auto clear = fn<void (*)(GLbitfield)>("glClear");
  auto read = fn<void (*)(GLint, GLint, GLsizei, GLsizei, GLenum, GLenum, void*)>("glReadPixels");
  a.make_current();
  clear_color(1, 0, 0, 1), clear(GL_COLOR_BUFFER_BIT);
  b.make_current();
  clear_color(0, 0, 1, 1), clear(GL_COLOR_BUFFER_BIT);
  GLubyte px[4];
  a.make_current();
  read(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_EQ(px[0], 255);
  EXPECT_EQ(px[2], 0);
  b.make_current();
  read(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_EQ(px[0], 0);
  EXPECT_EQ(px[2], 255);
}

TEST(EglContext, BadSizeIsRefused) {
  EglRequest r;
  r.width = 0;
  EXPECT_THROW(EglContext{r}, std::runtime_error);
}

}  // namespace
}  // namespace ffc::platform
