// GLUT text: glutBitmap* draw glyphs with glBitmap at the raster position, glutStroke* draw them
// as line strips in model space and move along x; the fonts are named by the addresses of the
// data symbols below (GLUT_BITMAP_8_BY_13 is &glutBitmap8By13 on Linux), which keep the names and
// sizes of freeglut's so that programs' copy relocations fit. Behaviour follows freeglut 3.4.0.
#include "font.h"
#include "shapes.h"

#include <cstdio>
#include <initializer_list>

// Declared extern "C" by <GL/freeglut_std.h>; defined here, visible outside the library.
#define FFC_GLUT_DATA __attribute__((visibility("default")))

// Only their addresses matter.
FFC_GLUT_DATA void *glutStrokeRoman = nullptr;
FFC_GLUT_DATA void *glutStrokeMonoRoman = nullptr;
FFC_GLUT_DATA void *glutBitmap9By15 = nullptr;
FFC_GLUT_DATA void *glutBitmap8By13 = nullptr;
FFC_GLUT_DATA void *glutBitmapTimesRoman10 = nullptr;
FFC_GLUT_DATA void *glutBitmapTimesRoman24 = nullptr;
FFC_GLUT_DATA void *glutBitmapHelvetica10 = nullptr;
FFC_GLUT_DATA void *glutBitmapHelvetica12 = nullptr;
FFC_GLUT_DATA void *glutBitmapHelvetica18 = nullptr;

namespace ffc::glut {
bool stroke_font_draw_join_dots = false;  // freeglut's default
}  // namespace ffc::glut

namespace {

using ffc::glut::BitmapFont;
using ffc::glut::StrokeChar;
using ffc::glut::StrokeFont;

const BitmapFont *bitmap_font(void *id, const char *caller) {
  if (id == GLUT_BITMAP_8_BY_13) return &ffc::glut::kFixed8x13;
  if (id == GLUT_BITMAP_9_BY_15) return &ffc::glut::kFixed9x15;
  if (id == GLUT_BITMAP_HELVETICA_10) return &ffc::glut::kHelvetica10;
  if (id == GLUT_BITMAP_HELVETICA_12) return &ffc::glut::kHelvetica12;
  if (id == GLUT_BITMAP_HELVETICA_18) return &ffc::glut::kHelvetica18;
  if (id == GLUT_BITMAP_TIMES_ROMAN_10) return &ffc::glut::kTimesRoman10;
  if (id == GLUT_BITMAP_TIMES_ROMAN_24) return &ffc::glut::kTimesRoman24;
  std::fprintf(stderr, "ffcompat: %s: %p is not a GLUT bitmap font (a stroke font?); nothing drawn\n", caller, id);
  return nullptr;
}

const StrokeFont *stroke_font(void *id, const char *caller) {
  if (id == GLUT_STROKE_ROMAN) return &ffc::glut::kStrokeRoman;
  if (id == GLUT_STROKE_MONO_ROMAN) return &ffc::glut::kStrokeMonoRoman;
  std::fprintf(stderr, "ffcompat: %s: %p is not a GLUT stroke font (a bitmap font?); nothing drawn\n", caller, id);
  return nullptr;
}

const GLubyte *glyph(const BitmapFont &font, unsigned char c) { return font.glyphs + font.offsets[c]; }

void draw_glyph(const BitmapFont &font, unsigned char c) {
  const GLubyte *g = glyph(font, c);
  glBitmap(g[0], font.height, font.xorig, font.yorig, GLfloat(g[0]), 0.0, g + 1);
}

// Glyph rows are byte-aligned, most significant bit first: the unpack state is set for that
// around the draw and put back after (freeglut's path for GLs without a client attribute stack;
// it needs only glGet and glPixelStore).
class GlyphUnpack {
 public:
  GlyphUnpack() {
    for (int i = 0; i < kCount; ++i) glGetIntegerv(kNames[i], &saved_[i]);
    static const GLint kGlyph[kCount] = {GL_FALSE, GL_FALSE, 0, 0, 0, 1};
    for (int i = 0; i < kCount; ++i) glPixelStorei(kNames[i], kGlyph[i]);
  }
  ~GlyphUnpack() {
    for (int i = 0; i < kCount; ++i) glPixelStorei(kNames[i], saved_[i]);
  }
  GlyphUnpack(const GlyphUnpack &) = delete;
  GlyphUnpack &operator=(const GlyphUnpack &) = delete;

 private:
  static constexpr int kCount = 6;
  static constexpr GLenum kNames[kCount] = {GL_UNPACK_SWAP_BYTES, GL_UNPACK_LSB_FIRST,  GL_UNPACK_ROW_LENGTH,
                                            GL_UNPACK_SKIP_ROWS,  GL_UNPACK_SKIP_PIXELS, GL_UNPACK_ALIGNMENT};
  GLint saved_[kCount] = {};
};

const StrokeChar *stroke_char(const StrokeFont &font, int c) {
  if (c < 0 || c >= font.char_count || font.chars[c].strip_count < 0) return nullptr;
  return &font.chars[c];
}

// Each strip as a line strip, followed (with join dots, which only glutStrokeCharacter draws, as
// in freeglut) by its vertices as points.
void draw_strokes(const StrokeFont &font, const StrokeChar &ch, bool join_dots) {
  for (int s = 0; s < ch.strip_count; ++s) {
    const ffc::glut::StrokeStrip &strip = font.strips[ch.first_strip + s];
    for (GLenum mode : {GL_LINE_STRIP, GL_POINTS}) {
      if (mode == GL_POINTS && !join_dots) break;
      glBegin(mode);
      for (int v = 0; v < strip.count; ++v) glVertex2f(font.vertices[strip.first + v].x, font.vertices[strip.first + v].y);
      glEnd();
    }
  }
}

}  // namespace

FFC_GLUT_EXPORT void FGAPIENTRY glutBitmapCharacter(void *font, int character) {
  const BitmapFont *f = bitmap_font(font, "glutBitmapCharacter");
  if (f == nullptr || character < 1 || character > 255) return;
  GlyphUnpack unpack;
  draw_glyph(*f, static_cast<unsigned char>(character));
}

FFC_GLUT_EXPORT void FGAPIENTRY glutBitmapString(void *font, const unsigned char *string) {
  const BitmapFont *f = bitmap_font(font, "glutBitmapString");
  if (f == nullptr || string == nullptr || *string == '\0') return;
  GlyphUnpack unpack;
  GLfloat x = 0.0f;
  for (; *string != '\0'; ++string) {
    if (*string == '\n') {
      // Back to the line's start and one line down: a glBitmap that draws nothing and moves.
      glBitmap(0, 0, 0, 0, -x, GLfloat(-f->height), nullptr);
      x = 0.0f;
    } else {
      draw_glyph(*f, *string);
      x += GLfloat(glyph(*f, *string)[0]);
    }
  }
}

FFC_GLUT_EXPORT int FGAPIENTRY glutBitmapWidth(void *font, int character) {
  if (character <= 0 || character > 255) return 0;
  const BitmapFont *f = bitmap_font(font, "glutBitmapWidth");
  return f == nullptr ? 0 : glyph(*f, static_cast<unsigned char>(character))[0];
}

// The widest line of the string, in pixels.
FFC_GLUT_EXPORT int FGAPIENTRY glutBitmapLength(void *font, const unsigned char *string) {
  const BitmapFont *f = bitmap_font(font, "glutBitmapLength");
  if (f == nullptr || string == nullptr) return 0;
  int widest = 0, line = 0;
  for (; *string != '\0'; ++string) {
    if (*string == '\n') {
      if (line > widest) widest = line;
      line = 0;
    } else {
      line += glyph(*f, *string)[0];
    }
  }
  return line > widest ? line : widest;
}

FFC_GLUT_EXPORT int FGAPIENTRY glutBitmapHeight(void *font) {
  const BitmapFont *f = bitmap_font(font, "glutBitmapHeight");
  return f == nullptr ? 0 : f->height;
}

FFC_GLUT_EXPORT void FGAPIENTRY glutStrokeCharacter(void *font, int character) {
  const StrokeFont *f = stroke_font(font, "glutStrokeCharacter");
  const StrokeChar *ch = f == nullptr ? nullptr : stroke_char(*f, character);
  if (ch == nullptr) return;
  draw_strokes(*f, *ch, ffc::glut::stroke_font_draw_join_dots);
  glTranslatef(ch->right, 0.0, 0.0);
}

FFC_GLUT_EXPORT void FGAPIENTRY glutStrokeString(void *font, const unsigned char *string) {
  const StrokeFont *f = stroke_font(font, "glutStrokeString");
  if (f == nullptr || string == nullptr) return;
  GLfloat x = 0.0f;
  for (; *string != '\0'; ++string) {
    if (*string >= f->char_count) continue;
    if (*string == '\n') {
      glTranslatef(-x, -f->height, 0.0);
      x = 0.0f;
    } else if (const StrokeChar *ch = stroke_char(*f, *string)) {
      draw_strokes(*f, *ch, false);
      x += ch->right;
      glTranslatef(ch->right, 0.0, 0.0);
    }
  }
}

FFC_GLUT_EXPORT GLfloat FGAPIENTRY glutStrokeWidthf(void *font, int character) {
  const StrokeFont *f = stroke_font(font, "glutStrokeWidth");
  const StrokeChar *ch = f == nullptr ? nullptr : stroke_char(*f, character);
  return ch == nullptr ? 0.0f : ch->right;
}

FFC_GLUT_EXPORT int FGAPIENTRY glutStrokeWidth(void *font, int character) {
  return int(glutStrokeWidthf(font, character) + 0.5f);
}

FFC_GLUT_EXPORT GLfloat FGAPIENTRY glutStrokeLengthf(void *font, const unsigned char *string) {
  const StrokeFont *f = stroke_font(font, "glutStrokeLength");
  if (f == nullptr || string == nullptr) return 0.0f;
  GLfloat widest = 0.0f, line = 0.0f;
  for (; *string != '\0'; ++string) {
    if (*string >= f->char_count) continue;
    if (*string == '\n') {
      if (line > widest) widest = line;
      line = 0.0f;
    } else if (const StrokeChar *ch = stroke_char(*f, *string)) {
      line += ch->right;
    }
  }
  return line > widest ? line : widest;
}

FFC_GLUT_EXPORT int FGAPIENTRY glutStrokeLength(void *font, const unsigned char *string) {
  return int(glutStrokeLengthf(font, string) + 0.5f);
}

FFC_GLUT_EXPORT GLfloat FGAPIENTRY glutStrokeHeight(void *font) {
  const StrokeFont *f = stroke_font(font, "glutStrokeHeight");
  return f == nullptr ? 0.0f : f->height;
}
