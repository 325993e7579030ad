// For the probes built on our GLUT sources without libglut.so.3's glutSetOption: the switch that
// glutSetOption(GLUT_STROKE_FONT_DRAW_JOIN_DOTS, on) turns, callable from C.
#include "classic/glut/font.h"

extern "C" void probe_set_stroke_join_dots(int on) { ffc::glut::stroke_font_draw_join_dots = on != 0; }
