// GLUT's bitmap and stroke fonts as data (font_data.cpp, regenerated from the system's freeglut
// 3.4.0 by tests/classic_glu/dump_freeglut_data.c): the glyphs programs draw with glutBitmap* and
// glutStroke*.
#pragma once

#include <GL/gl.h>

namespace ffc::glut {

// Glyph c starts at glyphs[offsets[c]]: its width in pixels, then `height` rows of
// (width + 7) / 8 bytes, bottom row first, as glBitmap takes them.
struct BitmapFont {
  int height;
  GLfloat xorig, yorig;
  const GLubyte *glyphs;
  const unsigned short *offsets;
};

struct StrokeVertex {
  GLfloat x, y;
};
struct StrokeStrip {
  int count;  // vertices in this line strip
  int first;  // index of its first vertex in the font's vertex array
};
// Character: its advance, its strips (strip_count -1: no such character).
struct StrokeChar {
  GLfloat right;
  int strip_count;
  int first_strip;
};
struct StrokeFont {
  int char_count;
  GLfloat height;
  const StrokeChar *chars;
  const StrokeStrip *strips;
  const StrokeVertex *vertices;
};

// glutSetOption(GLUT_STROKE_FONT_DRAW_JOIN_DOTS, on) sets this (glutGet reads it): when on,
// glutStrokeCharacter also draws each strip's vertices as points, filling the joints of wide lines.
extern bool stroke_font_draw_join_dots;

extern const BitmapFont kFixed8x13, kFixed9x15, kHelvetica10, kHelvetica12, kHelvetica18, kTimesRoman10,
    kTimesRoman24;
extern const StrokeFont kStrokeRoman, kStrokeMonoRoman;

}  // namespace ffc::glut
