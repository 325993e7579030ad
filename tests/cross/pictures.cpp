// Pictures for scripts/cross-check-aarch64: built for AArch64 (run under qemu-user) and for this
// machine, the two must write the same bytes. Eight pictures on "soft" through the public header:
// a lit sphere (specular, ambient) of many small triangles and of a few large ones, by
// glDrawElements (the triangle-list path), immediate mode and triangle strips (the general path),
// smooth and flat, with and without depth test, once with fog; over it random triangles with
// colours and perspective (w from 0.5 to 3), small and large, across the framebuffer's edges.
// Writes the pictures' RGBA8 bytes, one after the other, to argv[1].
#include <ffcompat/ffcompat.h>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

namespace {

// A sphere of radius 1 from the six faces of a cube, each an n x n grid of quads (two triangles
// each), its points pushed out to the sphere; normals = positions. Only arithmetic and sqrt
// (rounded exactly everywhere), so both machines draw the same input.
void sphere(int n, std::vector<float>& v, std::vector<float>& normals, std::vector<unsigned>& idx) {
  for (int face = 0; face < 6; ++face) {
    const unsigned first = unsigned(v.size() / 3);
    const int axis = face / 2;
    const float sign = face % 2 ? -1.0f : 1.0f;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j) {
        float p[3];
        p[axis] = sign, p[(axis + 1) % 3] = sign * (2.0f * i / n - 1), p[(axis + 2) % 3] = 2.0f * j / n - 1;
        const float len = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        for (float c : p) v.push_back(c / len), normals.push_back(c / len);
      }
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const unsigned a = first + unsigned(i * (n + 1) + j), b = a + unsigned(n + 1);
        idx.insert(idx.end(), {a, b, a + 1, a + 1, b, b + 1});
      }
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) return std::fprintf(stderr, "usage: %s OUT\n", argv[0]), 2;
  std::FILE* out = std::fopen(argv[1], "wb");
  if (!out) return std::perror(argv[1]), 1;
  for (int variant = 0; variant < 8; ++variant) {
    ffcompat::Context ctx("soft", 301, 257);
    glClearColor(0.1f, 0.2f, 0.3f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (variant & 1) glEnable(GL_DEPTH_TEST);
    glShadeModel(variant & 2 ? GL_FLAT : GL_SMOOTH);
    glMatrixMode(GL_PROJECTION);
    glFrustum(-0.6, 0.6, -0.5, 0.5, 1, 10);
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(0.1f, -0.05f, -3.3f);
    glRotatef(23.0f * variant + 7, 0.3f, 1, 0.2f);
    const GLfloat pos[] = {1, 2, 3, 0}, spec[] = {1, 1, 1, 1}, amb[] = {0.3f, 0.1f, 0.2f, 1};
    glEnable(GL_LIGHTING); glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, amb);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 20);
    if (variant == 6) { glEnable(GL_FOG); glFogf(GL_FOG_DENSITY, 0.3f); }
    std::vector<float> v, n; std::vector<unsigned> idx;
    sphere(variant < 4 ? 60 : 5, v, n, idx);
    glEnableClientState(GL_VERTEX_ARRAY); glEnableClientState(GL_NORMAL_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, v.data()); glNormalPointer(GL_FLOAT, 0, n.data());
    if (variant % 3 == 0) {
      glDrawElements(GL_TRIANGLES, GLsizei(idx.size()), GL_UNSIGNED_INT, idx.data());
    } else if (variant % 3 == 1) {
      glBegin(GL_TRIANGLES);
      for (unsigned i : idx) { glNormal3fv(&n[3 * i]); glVertex3fv(&v[3 * i]); }
      glEnd();
    } else {
      glDrawElements(GL_TRIANGLE_STRIP, GLsizei(idx.size()), GL_UNSIGNED_INT, idx.data());  // general path
    }
    // Random big and small triangles with colours, no lighting, across the framebuffer's edges.
    glDisable(GL_LIGHTING); glDisable(GL_FOG);
    glLoadIdentity();
    std::mt19937 rng(variant);
    std::uniform_real_distribution<float> u(-1.3f, 1.3f), c(0, 1);
    std::vector<float> xyzw, rgba4;
    for (int i = 0; i < 300; ++i) {
      const float cx = u(rng), cy = u(rng), s = i % 10 == 0 ? 1.5f : 0.05f;
      for (int k = 0; k < 3; ++k) {
        const float w = 2 + c(rng) - 1.5f * (k == 1);
        xyzw.insert(xyzw.end(), {(cx + s * u(rng)) * w, (cy + s * u(rng)) * w, u(rng) * 0.7f * w, w});
        rgba4.insert(rgba4.end(), {c(rng), c(rng), c(rng), 1});
      }
    }
    glDisableClientState(GL_NORMAL_ARRAY); glEnableClientState(GL_COLOR_ARRAY);
    glMatrixMode(GL_PROJECTION); glLoadIdentity();
    glVertexPointer(4, GL_FLOAT, 0, xyzw.data()); glColorPointer(4, GL_FLOAT, 0, rgba4.data());
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(xyzw.size() / 4));
    const std::vector<std::uint8_t> rgba = ctx.read_pixels();
    std::fwrite(rgba.data(), 1, rgba.size(), out);
  }
  return std::fclose(out) == 0 ? 0 : 1;
}
