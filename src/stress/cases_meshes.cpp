// The stress catalogue's meshes cases (stress/cases.cpp says what the catalogue is).
#include "stress/case_kit.h"

namespace ffc::stress::kit {

void add_meshes(std::vector<Case>& out) {
  auto add = [&](Case c) { out.push_back(std::move(c)); };
  {
    Case c;
    c.group = "mesh";
    c.name = "mesh_slivers";
    c.draw = mesh_scene(scenes::slivers, Normals::Plain);
    c.note = "A fan of triangles whose apex angles go from 0.5 down to 1e-7 radians (far thinner than a "
             "pixel), with face normals from src/mesh (OpenMesh, double). Slivers are drawn by the "
             "rasterization rules like any triangle (3.5.1): a pixel whose centre lies inside; feedback "
             "reports them whole.";
    add(c);
  }
  {
    Case c;
    c.group = "mesh";
    c.name = "mesh_needles";
    c.draw = mesh_scene(scenes::needles, Normals::Normalize);
    c.note = "Triangles 2.4 long and 1e-4 to 1e-7 wide across the view, tilted: their face normals come "
             "from cross products of nearly parallel edges (computed in double by src/mesh, exact to "
             "rounding), their pixels from the rasterization rules.";
    add(c);
  }
  {
    Case c;
    c.group = "mesh";
    c.name = "mesh_near_duplicates";
    c.draw = mesh_scene(scenes::near_duplicates, Normals::Plain);
    c.note = "A bumped grid whose odd columns are doubled by a vertex one float ulp to the right, joined "
             "by triangles of almost no area. Their face normals are computed in double from coordinates "
             "that differ in the last float bit: direction defined, length 1 (src/mesh normalizes; a "
             "triangle of exactly zero area would get the zero normal and ambient only).";
    add(c);
  }
  {
    Case c;
    c.group = "mesh";
    c.name = "mesh_degenerate_triangles";
    c.draw = [] {
      scenes::standard();
      glEnable(GL_NORMALIZE);
      glTranslatef(0, 0, -3);
      // Zero-area triangles: a repeated vertex, three collinear vertices, one point three times,
      // with the zero face normal a cross product gives them; then a proper triangle.
      const GLfloat v[] = {-0.8f, -0.8f, 0, 0.8f, -0.8f, 0, 0.8f, -0.8f, 0,   -0.8f, 0, 0, 0, 0, 0, 0.8f, 0, 0,
                           0.3f, 0.5f, 0, 0.3f, 0.5f, 0, 0.3f, 0.5f, 0,       -0.5f, 0.2f, 0, 0.5f, 0.2f, 0, 0, 0.9f, 0};
      const GLfloat n[] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
                           0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 1, 0, 0, 1};
      glEnableClientState(GL_VERTEX_ARRAY);
      glEnableClientState(GL_NORMAL_ARRAY);
      glVertexPointer(3, GL_FLOAT, 0, v);
      glNormalPointer(GL_FLOAT, 0, n);
      glDrawArrays(GL_TRIANGLES, 0, 12);
    };
    c.note = "Triangles of zero area (a repeated vertex, collinear vertices, a point), carrying the zero "
             "normal their cross product gives, under GL_NORMALIZE (undefined for a zero normal: ambient "
             "only on both). They cover no pixel; with culling off feedback still reports them (feedback "
             "comes after clipping and culling, before rasterization).";
    c.mesa = MesaExpectation::Undefined;
    c.mesa_reason = "normalizing a zero normal";
    add(c);
  }
  {
    Case c;
    c.group = "mesh";
    c.name = "mesh_coords_1e20";
    c.draw = [] {
      scenes::standard();
      glMatrixMode(GL_PROJECTION);
      glLoadIdentity();
      glOrtho(-1.5e20, 1.5e20, -1.5e20, 1.5e20, -3e20, 3e20);
      glMatrixMode(GL_MODELVIEW);
      const GLfloat p[] = {2e20f, 2e20f, 3e20f, 1};
      glLightfv(GL_LIGHT0, GL_POSITION, p);
      static const Geometry g = [] {
        Geometry s = scenes::sphere(2);
        for (auto& v : s.positions)
          for (double& x : v) x *= 1e20;
        return s;
      }();
      scenes::draw(g);
    };
    c.note = "The sphere at radius 1e20 (eye coordinates, glOrtho 1.5e20 wide), a point light 4e20 away. "
             "Beyond the 2^32 magnitude floats must hold (2.1.1): unspecified. In float |P - V|^2 ~ 1e41 "
             "overflows to +inf and the unit vector to the light becomes 0 (Mesa: DP3, RSQ(inf) = 0): only "
             "ambient remains. Our double reference lights the sphere.";
    c.float_limit = 1;
    c.float_reason = "|P - V|^2 overflows float; the double reference lights the sphere";
    add(c);
  }
  {
    Case c;
    c.group = "mesh";
    c.name = "mesh_coords_1e-20";
    c.draw = [] {
      scenes::standard();
      glMatrixMode(GL_PROJECTION);
      glLoadIdentity();
      glOrtho(-1.5e-20, 1.5e-20, -1.5e-20, 1.5e-20, -3e-20, 3e-20);
      glMatrixMode(GL_MODELVIEW);
      const GLfloat p[] = {2e-20f, 2e-20f, 3e-20f, 1};
      glLightfv(GL_LIGHT0, GL_POSITION, p);
      static const Geometry g = [] {
        Geometry s = scenes::sphere(2);
        for (auto& v : s.positions)
          for (double& x : v) x *= 1e-20;
        return s;
      }();
      scenes::draw(g);
    };
    c.note = "The sphere at radius 1e-20, a point light 4e-20 away: |P - V|^2 ~ 1e-40 is a float "
             "denormal. llvmpipe flushes it to zero, then RSQ(0) = inf and VP = 0 * inf = NaN: Mesa's "
             "sphere gets ambient only (or 1 where the NaN reaches its clamp). Ours keeps the denormal and "
             "lights the sphere like the double reference (within 1e-6). Small magnitudes are allowed "
             "(2.1.1 bounds only the largest), but the precision of denormals is not specified.";
    c.float_limit = 1e-2;
    c.float_reason = "|P - V|^2 is a float denormal";
    c.mesa = MesaExpectation::Undefined;
    c.mesa_reason = "float denormals: llvmpipe flushes them to zero, ours keeps them";
    add(c);
  }
  {
    Case c;
    c.group = "mesh";
    c.name = "icosphere_patch_depth9";
    c.width = c.height = 128;
    c.draw = [] {
      static const Geometry g = scenes::icosphere_patch(9);  // built once per process
      draw_patch_face_on(g);
    };
    c.feedback_hint = size_t(23) << 18;
    c.note = "One face of the icosahedron subdivided 9 times as src/mesh's icosphere does (262144 "
             "triangles, 131841 vertices, midpoints normalized in double), seen face on at 128x128: "
             "most triangles are smaller than a pixel and many cover no pixel centre at all.";
    add(c);
  }
  {
    Case c;
    c.group = "mesh";
    c.name = "icosphere_patch_depth10";
    c.slow = true;
    c.width = c.height = 128;
    c.draw = [] {
      static const Geometry g = scenes::icosphere_patch(10);  // built once per process
      draw_patch_face_on(g);
    };
    c.feedback_hint = size_t(23) << 20;
    c.note = "The same face subdivided 10 times: 1048576 triangles, 525825 vertices (a twentieth of the "
             "depth-10 icosphere's 20M faces, which would need gigabytes through OpenMesh). Slow: "
             "skipped by the CI test.";
    add(c);
  }
  {
    Case c;
    c.group = "mesh";
    c.name = "icosphere_float_collision";
    c.draw = [] {
      static const Geometry g = scenes::icosphere_deep_patch(24, 4);
      scenes::standard();
      const auto ctr = scenes::centroid(g);
      glMatrixMode(GL_PROJECTION);
      glLoadIdentity();
      glOrtho(-1, 1, -1, 1, -3, 3);
      glMatrixMode(GL_MODELVIEW);
      gluLookAtLike(ctr);
      glScaled(1.5e7, 1.5e7, 1.5e7);
      glTranslated(-ctr[0], -ctr[1], -ctr[2]);
      scenes::draw_double(g);
    };
    c.check = [](const Observed& o) -> std::string {
      // The float path's window triangles collapse (zero area); the double reference's do not.
      auto collapsed = [](const Run& r) {
        int n = 0;
        for (const auto& p : r.feedback) {
          const auto &a = p.vertices[0].position, &b = p.vertices[1].position, &c = p.vertices[2].position;
          n += (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y) == 0;
        }
        return n;
      };
      const int f = collapsed(o.soft), d = collapsed(o.dbl);
      if (f == 0) return "no triangle collapsed in float: the patch is not below float's spacing";
      if (d != 0) return std::to_string(d) + " triangles collapsed in the double reference";
      return "";
    };
    c.note = "The icosphere's face 0 followed down 24 levels (edges ~7e-8, below float's spacing of "
             "6e-8 to 1.2e-7 near radius 1) and subdivided 4 more: depth 28, far beyond src/mesh's limit "
             "of 12. Drawn from GL_DOUBLE arrays magnified 1.5e7 times: in float (ours and Mesa) the "
             "midpoints collide and the patch becomes a lattice of float steps with collapsed "
             "triangles; our double reference keeps them apart. Colours come from the sphere normals, "
             "which stay unit, so they agree; the positions do not (float against double: see "
             "max_position_vs_double_px; checked: triangles collapse to zero area in float, none in "
             "double).";
    add(c);
  }
}

}  // namespace ffc::stress::kit
