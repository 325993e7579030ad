/* Prints every GL call that GLU makes for a set of quadrics and matrix helpers (through
 * gl_recorder.c), and the results of GLU's pure functions, in exact hexadecimal. Built twice: with
 * the system libGLU and with ffcompat's; the two outputs must be identical. */
#include <GL/glu.h>
#include <stdio.h>

static void GLAPIENTRY on_error(GLenum error) { printf("QuadricError %u\n", error); }

enum shape { SPHERE, CYLINDER, DISK, PARTIAL_DISK };

static void draw(GLUquadric *q, enum shape shape, int set) {
  switch (shape) {
    case SPHERE: {
      static const struct { double r; int slices, stacks; } p[] = {
          {1.5, 12, 8}, {2.0, 5, 3}, {1.0, 3, 2}, {0.75, 245, 3}, {1.0, 6, 1}, {1.0, 1, 4}, {-1.0, 8, 4}};
      if (set >= 7) return;
      printf("# gluSphere %g %d %d\n", p[set].r, p[set].slices, p[set].stacks);
      gluSphere(q, p[set].r, p[set].slices, p[set].stacks);
      return;
    }
    case CYLINDER: {
      static const struct { double base, top, height; int slices, stacks; } p[] = {
          {1.0, 0.5, 2.0, 10, 3}, {0.7, 0.7, 1.5, 7, 1}, {1.0, 0.0, 2.0, 8, 4}, {0.0, 1.0, 1.0, 6, 2},
          {1.0, 1.0, 0.0, 5, 2}, {1.0, 1.0, 1.0, 250, 2}, {1.0, 1.0, 0.0, 1, 2}, {0.0, 0.0, 0.0, 5, 2}};
      if (set >= 8) return;
      printf("# gluCylinder %g %g %g %d %d\n", p[set].base, p[set].top, p[set].height, p[set].slices, p[set].stacks);
      gluCylinder(q, p[set].base, p[set].top, p[set].height, p[set].slices, p[set].stacks);
      return;
    }
    case DISK: {
      static const struct { double inner, outer; int slices, loops; } p[] = {
          {0.0, 1.0, 10, 3}, {0.3, 1.0, 8, 2}, {1.0, 1.0, 6, 2}, {0.0, 2.0, 4, 1}, {0.5, 0.2, 6, 2}};
      if (set >= 5) return;
      printf("# gluDisk %g %g %d %d\n", p[set].inner, p[set].outer, p[set].slices, p[set].loops);
      gluDisk(q, p[set].inner, p[set].outer, p[set].slices, p[set].loops);
      return;
    }
    case PARTIAL_DISK: {
      static const struct { double inner, outer; int slices, loops; double start, sweep; } p[] = {
          {0.2, 1.0, 9, 3, 30.0, 120.0}, {0.0, 1.0, 5, 2, 10.0, -90.0}, {0.5, 1.0, 6, 2, 0.0, 400.0},
          {0.0, 1.0, 4, 1, 45.0, -500.0}, {0.4, 0.4, 7, 2, 20.0, 200.0}};
      if (set >= 5) return;
      printf("# gluPartialDisk %g %g %d %d %g %g\n", p[set].inner, p[set].outer, p[set].slices, p[set].loops,
             p[set].start, p[set].sweep);
      gluPartialDisk(q, p[set].inner, p[set].outer, p[set].slices, p[set].loops, p[set].start, p[set].sweep);
      return;
    }
  }
}

/* SGI's GLU reads tables it never filled for these (its output there is undefined): left out. */
static int defined_in_glu(enum shape shape, GLenum style, GLenum normals) {
  if (shape != SPHERE && shape != CYLINDER) return 1;
  return !(normals == GLU_FLAT && (style == GLU_POINT || style == GLU_SILHOUETTE));
}

static void quadrics(void) {
  static const GLenum styles[] = {GLU_FILL, GLU_LINE, GLU_SILHOUETTE, GLU_POINT};
  static const GLenum normals[] = {GLU_NONE, GLU_FLAT, GLU_SMOOTH};
  static const GLenum orientations[] = {GLU_OUTSIDE, GLU_INSIDE};
  GLUquadric *q = gluNewQuadric();
  gluQuadricCallback(q, GLU_ERROR, (_GLUfuncptr)on_error);
  for (int shape = SPHERE; shape <= PARTIAL_DISK; ++shape)
    for (int s = 0; s < 4; ++s)
      for (int n = 0; n < 3; ++n)
        for (int o = 0; o < 2; ++o)
          for (int t = 0; t < 2; ++t) {
            if (!defined_in_glu((enum shape)shape, styles[s], normals[n])) continue;
            gluQuadricDrawStyle(q, styles[s]);
            gluQuadricNormals(q, normals[n]);
            gluQuadricOrientation(q, orientations[o]);
            gluQuadricTexture(q, (GLboolean)t);
            printf("## style 0x%x normals 0x%x orientation 0x%x texture %d\n", styles[s], normals[n], orientations[o], t);
            for (int set = 0; set < 8; ++set) draw(q, (enum shape)shape, set);
          }
  /* Bad settings: reported through the callback, the quadric keeps its state. */
  gluQuadricDrawStyle(q, GL_TRIANGLES);
  gluQuadricNormals(q, GL_TRIANGLES);
  gluQuadricOrientation(q, GL_TRIANGLES);
  gluQuadricCallback(q, GL_TRIANGLES, (_GLUfuncptr)on_error);
  printf("# after bad settings\n");
  draw(q, DISK, 1);
  gluDeleteQuadric(q);
}

static void matrices(void) {
  static const double persp[][4] = {{60, 1.333, 0.1, 100}, {45, 1, 1, 10}, {90, 0.5, 2, 3}, {30, 1, 5, 5}, {0, 1, 1, 2}, {60, 0, 1, 2}};
  for (int i = 0; i < 6; ++i) {
    printf("# gluPerspective %g %g %g %g\n", persp[i][0], persp[i][1], persp[i][2], persp[i][3]);
    gluPerspective(persp[i][0], persp[i][1], persp[i][2], persp[i][3]);
  }
  static const double look[][9] = {{0, 0, 5, 0, 0, 0, 0, 1, 0}, {3, 4, 5, -1, 0.5, 2, 0.1, 1, 0.2},
                                   {1, 1, 1, 1, 1, 1, 0, 1, 0}, {0, 5, 0, 0, 0, 0, 0, 1, 0}, {-2.5, 0.3, 7, 1, 1, 1, 0, 0, 1}};
  for (int i = 0; i < 5; ++i) {
    const double *l = look[i];
    printf("# gluLookAt %d\n", i);
    gluLookAt(l[0], l[1], l[2], l[3], l[4], l[5], l[6], l[7], l[8]);
  }
  printf("# gluOrtho2D\n");
  gluOrtho2D(-1.5, 2.5, -3, 4);
  GLint viewport[4] = {10, 20, 640, 480};
  static const double pick[][4] = {{100, 200, 5, 5}, {10.5, 470.25, 3, 7}, {0, 0, 0, 5}, {50, 50, 4, -1}};
  for (int i = 0; i < 4; ++i) {
    printf("# gluPickMatrix %d\n", i);
    gluPickMatrix(pick[i][0], pick[i][1], pick[i][2], pick[i][3], viewport);
  }
}

static void print_matrix(const char *name, const GLdouble m[16]) {
  printf("%s", name);
  for (int i = 0; i < 16; ++i) printf(" %a", m[i]);
  printf("\n");
}

static void projections(void) {
  const GLdouble model[16] = {0.8, 0.1, -0.3, 0, -0.2, 0.9, 0.4, 0, 0.35, -0.25, 0.85, 0, 0.5, -1.25, -6, 1};
  const GLdouble proj[16] = {1.299, 0, 0, 0, 0, 1.732, 0, 0, 0, 0, -1.002, -1, 0, 0, -0.2002, 0};
  const GLdouble singular[16] = {1, 2, 3, 4, 2, 4, 6, 8, 0, 0, 1, 0, 0, 0, 0, 1};
  const GLint view[4] = {0, 0, 640, 480};
  print_matrix("# model", model);
  static const double points[][3] = {{0, 0, 0}, {1, 2, -3}, {-0.5, 0.25, 4}, {10, -7, 2.5}};
  for (int i = 0; i < 4; ++i) {
    GLdouble wx = 0, wy = 0, wz = 0, ox = 0, oy = 0, oz = 0, ow = 0;
    GLint r = gluProject(points[i][0], points[i][1], points[i][2], model, proj, view, &wx, &wy, &wz);
    printf("gluProject %d -> %d %a %a %a\n", i, r, wx, wy, wz);
    r = gluUnProject(wx, wy, wz, model, proj, view, &ox, &oy, &oz);
    printf("gluUnProject %d -> %d %a %a %a\n", i, r, ox, oy, oz);
    r = gluUnProject4(wx, wy, wz, 0.7, model, proj, view, 0.1, 0.9, &ox, &oy, &oz, &ow);
    printf("gluUnProject4 %d -> %d %a %a %a %a\n", i, r, ox, oy, oz, ow);
  }
  GLdouble x = 0, y = 0, z = 0, w = 0;
  printf("singular %d %d\n", gluUnProject(1, 2, 0.5, singular, proj, view, &x, &y, &z),
         gluUnProject4(1, 2, 0.5, 1, singular, proj, view, 0, 1, &x, &y, &z, &w));
  const GLdouble flat_w[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0};
  printf("w zero %d\n", gluProject(1, 2, 3, flat_w, flat_w, view, &x, &y, &z));
}

static void strings(void) {
  for (GLenum e = 0; e < 0x510; ++e) {
    const GLubyte *s = gluErrorString(e);
    if (s) printf("error 0x%x %s\n", e, s);
  }
  for (GLenum e = 100000; e < 101000; ++e) {
    const GLubyte *s = gluErrorString(e);
    if (s) printf("error %u %s\n", e, s);
  }
  printf("version [%s] extensions [%s] other %d\n", gluGetString(GLU_VERSION), gluGetString(GLU_EXTENSIONS),
         gluGetString(GL_VENDOR) == NULL);
  static const char *cases[][2] = {{"a", "a b"}, {"b", "ab b"}, {"a", "ab"}, {"", "a  b"}, {"b", "a b "},
                                   {"a b", "a b"}, {"GLU_EXT_nurbs_tessellator", "GLU_EXT_nurbs_tessellator"},
                                   {"x", ""}, {"ab", "a"}};
  for (int i = 0; i < 9; ++i)
    printf("check [%s] in [%s]: %d\n", cases[i][0], cases[i][1],
           gluCheckExtension((const GLubyte *)cases[i][0], (const GLubyte *)cases[i][1]));
}

/* feedback_harness.c runs the probe under its own main. */
#ifndef PROBE_MAIN
#define PROBE_MAIN main
#endif
int PROBE_MAIN(int argc, char **argv) {
  (void)argc;
  (void)argv;
  quadrics();
  matrices();
  projections();
  strings();
  return 0;
}
