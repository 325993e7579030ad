/* Prints every GL call that GLUT makes for its shapes and text (through gl_recorder.c), and the
 * text metrics, in exact hexadecimal. Built twice: on the system's freeglut (which needs glutInit,
 * hence an X display: the test runs it under xvfb-run) and on ffcompat's shapes and fonts; the
 * two outputs must be identical. */
#include <GL/freeglut.h>
#include <stdio.h>

#ifndef PROBE_GLUT_INIT
void probe_set_stroke_join_dots(int on); /* stroke_join_dots.cpp */
#endif

static void round_shapes(void) {
  static const struct { double a, b; int n, m; } p[] = {{1.0, 2.0, 12, 8}, {0.5, 1.5, 5, 2}, {2.0, 0.75, 3, 1},
                                                       {1.25, 1.0, 30, 20}, {1.0, 1.0, 0, 4}, {1.0, 1.0, 4, 0}};
  for (int i = 0; i < 6; ++i) {
    printf("# sphere %g %d %d\n", p[i].a, p[i].n, p[i].m);
    glutSolidSphere(p[i].a, p[i].n, p[i].m);
    glutWireSphere(p[i].a, p[i].n, p[i].m);
    printf("# cone %g %g %d %d\n", p[i].a, p[i].b, p[i].n, p[i].m);
    glutSolidCone(p[i].a, p[i].b, p[i].n, p[i].m);
    glutWireCone(p[i].a, p[i].b, p[i].n, p[i].m);
    printf("# cylinder %g %g %d %d\n", p[i].a, p[i].b, p[i].n, p[i].m);
    glutSolidCylinder(p[i].a, p[i].b, p[i].n, p[i].m);
    glutWireCylinder(p[i].a, p[i].b, p[i].n, p[i].m);
    printf("# torus %g %g %d %d\n", p[i].a * 0.3, p[i].b, p[i].n, p[i].m);
    glutSolidTorus(p[i].a * 0.3, p[i].b, p[i].n, p[i].m);
    glutWireTorus(p[i].a * 0.3, p[i].b, p[i].n, p[i].m);
  }
}

static void polyhedra(void) {
  static const double sizes[] = {1.0, 2.5, 0.3};
  for (int i = 0; i < 3; ++i) {
    printf("# cube %g\n", sizes[i]);
    glutSolidCube(sizes[i]);
    glutWireCube(sizes[i]);
  }
  printf("# tetrahedron\n");
  glutSolidTetrahedron();
  glutWireTetrahedron();
  printf("# octahedron\n");
  glutSolidOctahedron();
  glutWireOctahedron();
  printf("# dodecahedron\n");
  glutSolidDodecahedron();
  glutWireDodecahedron();
  printf("# icosahedron\n");
  glutSolidIcosahedron();
  glutWireIcosahedron();
  printf("# rhombic dodecahedron\n");
  glutSolidRhombicDodecahedron();
  glutWireRhombicDodecahedron();
  double offset[3] = {0.25, -0.5, 1.0};
  for (int levels = -1; levels <= 3; ++levels) {
    printf("# sierpinski %d\n", levels);
    glutSolidSierpinskiSponge(levels, offset, 1.5);
    glutWireSierpinskiSponge(levels, offset, 1.5);
  }
}

/* Each object keeps its arrays between calls, its normals from the first size: the order of
 * sizes is part of what is compared. */
static void teaset(void) {
  static const double sizes[] = {1.0, 0.5, 0.5, 2.0};
  for (int i = 0; i < 4; ++i) {
    printf("# teapot %g\n", sizes[i]);
    glutSolidTeapot(sizes[i]);
    glutWireTeapot(sizes[i] * 1.5);
    printf("# teacup %g\n", sizes[i]);
    glutSolidTeacup(sizes[i]);
    glutWireTeacup(sizes[i]);
    printf("# teaspoon %g\n", sizes[i]);
    glutSolidTeaspoon(sizes[i]);
    glutWireTeaspoon(sizes[i]);
  }
}

static void text(void) {
  void *bitmaps[] = {GLUT_BITMAP_8_BY_13, GLUT_BITMAP_9_BY_15, GLUT_BITMAP_TIMES_ROMAN_10, GLUT_BITMAP_TIMES_ROMAN_24,
                     GLUT_BITMAP_HELVETICA_10, GLUT_BITMAP_HELVETICA_12, GLUT_BITMAP_HELVETICA_18};
  const unsigned char sample[] = "Lit sphere\nflat: 1, smooth: 2\n\xe9t\xe9";
  for (int f = 0; f < 7; ++f) {
    printf("# bitmap font %d: height %d length %d\n", f, glutBitmapHeight(bitmaps[f]),
           glutBitmapLength(bitmaps[f], sample));
    for (int c = -1; c <= 256; ++c) {
      printf("width %d %d\n", c, glutBitmapWidth(bitmaps[f], c));
      glutBitmapCharacter(bitmaps[f], c);
    }
    glutBitmapString(bitmaps[f], sample);
  }
  void *strokes[] = {GLUT_STROKE_ROMAN, GLUT_STROKE_MONO_ROMAN};
  for (int f = 0; f < 2; ++f) {
    printf("# stroke font %d: height %a length %d %a\n", f, glutStrokeHeight(strokes[f]),
           glutStrokeLength(strokes[f], sample), glutStrokeLengthf(strokes[f], sample));
    for (int c = -1; c <= 256; ++c) {
      printf("width %d %d %a\n", c, glutStrokeWidth(strokes[f], c), glutStrokeWidthf(strokes[f], c));
      glutStrokeCharacter(strokes[f], c);
    }
    glutStrokeString(strokes[f], sample);
  }
  /* Join dots: glutStrokeCharacter then also draws each strip's vertices as points. */
#ifdef PROBE_GLUT_INIT
  glutSetOption(GLUT_STROKE_FONT_DRAW_JOIN_DOTS, GL_TRUE);
#else
  probe_set_stroke_join_dots(1);
#endif
  printf("# join dots\n");
  glutStrokeCharacter(GLUT_STROKE_ROMAN, 'B');
  glutStrokeString(GLUT_STROKE_MONO_ROMAN, sample);
#ifdef PROBE_GLUT_INIT
  glutSetOption(GLUT_STROKE_FONT_DRAW_JOIN_DOTS, GL_FALSE);
#else
  probe_set_stroke_join_dots(0);
#endif
  /* A font of the other kind draws nothing and measures 0 (both libraries warn on stderr). */
  printf("# wrong kind of font: %d %d %d %d %a\n", glutBitmapWidth(GLUT_STROKE_ROMAN, 'a'),
         glutBitmapHeight(GLUT_STROKE_ROMAN), glutStrokeWidth(GLUT_BITMAP_8_BY_13, 'a'),
         glutStrokeLength(GLUT_BITMAP_9_BY_15, sample), glutStrokeHeight(GLUT_BITMAP_8_BY_13));
  glutBitmapCharacter(GLUT_STROKE_ROMAN, 'a');
  glutBitmapString(GLUT_STROKE_MONO_ROMAN, sample);
  glutStrokeCharacter(GLUT_BITMAP_8_BY_13, 'a');
  glutStrokeString(GLUT_BITMAP_HELVETICA_12, sample);
  glutBitmapString(GLUT_BITMAP_8_BY_13, (const unsigned char *)"");
  glutStrokeString(GLUT_STROKE_ROMAN, (const unsigned char *)"");
  printf("empty %d %d\n", glutBitmapLength(GLUT_BITMAP_8_BY_13, (const unsigned char *)""),
         glutStrokeLength(GLUT_STROKE_ROMAN, (const unsigned char *)""));
}

/* feedback_harness.c runs the probe under its own main. */
#ifndef PROBE_MAIN
#define PROBE_MAIN main
#endif
int PROBE_MAIN(int argc, char **argv) {
#ifdef PROBE_GLUT_INIT
  glutInit(&argc, argv);
#else
  (void)argc;
  (void)argv;
#endif
  round_shapes();
  polyhedra();
  teaset();
  text();
  return 0;
}
