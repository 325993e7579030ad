// The stress catalogue's positions with w cases (stress/cases.cpp says what the catalogue is).
#include "stress/case_kit.h"

namespace ffc::stress::kit {

void add_positions_w(std::vector<Case>& out) {
  auto add = [&](Case c) { out.push_back(std::move(c)); };
  {
    Case c;
    c.group = "position";
    c.name = "light_w_tiny";
    c.draw = lit_grid([] {
      const GLfloat p[] = {1, 1, 1, 1e-30f};
      glLightfv(GL_LIGHT0, GL_POSITION, p);
    });
    c.note = "A light position (1, 1, 1, 1e-30): a point light 1.7e30 away (2.14.1 divides by w). In "
             "float |P - V|^2 overflows to +inf and the unit vector VP becomes 0: the grid gets only "
             "ambient, where the double reference lights it as from a direction. Beyond the 2^32 range "
             "floats must cover (2.1.1).";
    c.float_limit = 1;
    c.float_reason = "|P - V|^2 overflows float; the double reference lights the grid";
    add(c);
  }
  {
    Case c;
    c.group = "position";
    c.name = "light_w_negative";
    c.draw = lit_grid([] {
      const GLfloat p[] = {-1, -1, -2, -1};
      glLightfv(GL_LIGHT0, GL_POSITION, p);
    });
    c.note = "A light position (-1, -1, -2, -1): the point (1, 1, 2) in front of the grid (w divides out, "
             "2.14.1).";
    add(c);
  }
  {
    Case c;
    c.group = "position";
    c.name = "vertex_w_tiny";
    c.draw = [] {
      scenes::standard();
      glTranslatef(0, 0, -4);
      scenes::draw_homogeneous(scenes::sphere(3), 1e-30, 1e-30f);
    };
    c.note = "Vertices (x, y, z, 1) * 1e-30 with w = 1e-30: the same projective points as the sphere, and "
             "clipping and the perspective divide make the same picture. For lighting, 2.14.1 takes VP "
             "between homogeneous points, that is between the positions divided by w (soft-spec lights "
             "the sphere as with w = 1). Mesa's fixed-function program (ffvertex_prog.c: SUB VPpli, Ppli, "
             "V; DP3) subtracts the eye-space x, y, z without dividing by w, so it lights every vertex as "
             "if it sat at the eye (1e-30 from the origin); ours by default too (docs/deviations.md).";
    c.mesa = MesaExpectation::Agree;
    add(c);
  }
  {
    Case c;
    c.group = "position";
    c.name = "vertex_w_denormal";
    c.draw = [] {
      scenes::standard();
      glTranslatef(0, 0, -4);
      scenes::draw_homogeneous(scenes::sphere(2), 1e-40, 1e-40f);
    };
    c.note = "Vertices (x, y, z, 1) * 1e-40: every coordinate a float denormal, the sphere's projective "
             "points again. Clip w is ~4e-40, so 1/w overflows float: the perspective divide and the "
             "rasterizer's 1/w planes are at their limits; the spec does not specify denormal precision. "
             "Ours drops a primitive with a w whose 1/w is not a normal float (below 2^-126 or above "
             "2^126): nothing is drawn or fed back. Mesa draws nothing either, but its feedback reports "
             "every triangle with NaN window positions.";
    c.mesa = MesaExpectation::Undefined;
    c.mesa_reason = "float denormals: llvmpipe flushes them to zero";
    c.float_limit = 1;
    c.float_reason = "the float path works with denormal clip coordinates";
    add(c);
  }
  {
    Case c;
    c.group = "position";
    c.name = "vertex_w_zero";
    c.draw = [] {
      scenes::standard();
      glMatrixMode(GL_PROJECTION);
      glLoadIdentity();  // clip = eye: the vertex (0, 0, 0, 0) stays (0, 0, 0, 0)
      glMatrixMode(GL_MODELVIEW);
      const GLfloat v[] = {-0.5f, -0.5f, 0, 1, 0.5f, -0.5f, 0, 1, 0, 0, 0, 0, 0.5f, 0.5f, 0, 1, -0.5f, 0.5f, 0, 1, 0, 0, 0, 0};
      const GLfloat n[] = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
      glEnableClientState(GL_VERTEX_ARRAY);
      glEnableClientState(GL_NORMAL_ARRAY);
      glVertexPointer(4, GL_FLOAT, 0, v);
      glNormalPointer(GL_FLOAT, 0, n);
      glDrawArrays(GL_TRIANGLES, 0, 6);
    };
    c.note = "Triangles with a vertex (0, 0, 0, 0) and an identity projection: its clip coordinates are all "
             "zero, which satisfies -w <= x, y, z <= w, yet the perspective divide is 0/0. The spec (2.11, "
             "2.12) gives it no window position. Ours drops a primitive with a vertex it cannot map (a w "
             "whose 1/w is not a float) after clipping: nothing drawn or fed back. Mesa draws nothing but "
             "feeds back both triangles, the vertex at a NaN window position.";
    c.mesa = MesaExpectation::Undefined;
    c.mesa_reason = "the perspective divide of (0, 0, 0, 0)";
    add(c);
  }
  {
    Case c;
    c.group = "position";
    c.name = "vertex_w_negative";
    c.draw = [] {
      scenes::standard();
      glTranslatef(0, 0, -4);
      scenes::draw_homogeneous(scenes::sphere(2), -1, -1);
    };
    c.note = "Every vertex (-x, -y, -z, -1): after the modelview and projection all clip w are negative, "
             "and -w_c <= x_c <= w_c has no solution: the view volume (2.12) holds none of it and nothing "
             "is drawn or fed back (checked), though the same points with w = 1 are visible.";
    c.check = expect_no_primitives;
    add(c);
  }
  {
    Case c;
    c.group = "position";
    c.name = "vertex_w_mixed_sign";
    c.draw = [] {
      scenes::standard();
      glTranslatef(0, 0, -3);
      // Triangles with one vertex of negative w: each edge to it passes through infinity.
      const GLfloat v[] = {-0.5f, -0.5f, 0, 1, 0.5f, -0.5f, 0, 1, 0.2f, 0.8f, 0, -1,
                           -0.8f, 0.1f, 0, 1, -0.1f, -0.7f, 0.5f, 1, 0.1f, 0.1f, -0.5f, -0.25f};
      const GLfloat n[] = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0.6f, 0, 0.8f, 0, 0.6f, 0.8f, 0, 0, 1};
      glEnableClientState(GL_VERTEX_ARRAY);
      glEnableClientState(GL_NORMAL_ARRAY);
      glVertexPointer(4, GL_FLOAT, 0, v);
      glNormalPointer(GL_FLOAT, 0, n);
      glDrawArrays(GL_TRIANGLES, 0, 6);
    };
    c.note = "Triangles with one vertex of negative w: their edges to it pass through infinity. 2.12: 'only "
             "the portion of the primitive that lies in the region of w_c > 0 need be produced by "
             "clipping'; ours and Mesa produce the same clipped polygons (Mesa's feedback reports each as a "
             "fan of triangles). The lighting of a vertex with w != 1 divides by w (2.14.1); Mesa does not "
             "(see vertex_w_tiny), nor does ours by default.";
    c.mesa = MesaExpectation::Agree;
    add(c);
  }
}

}  // namespace ffc::stress::kit
