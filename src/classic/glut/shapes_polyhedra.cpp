// The polyhedra of GLUT: cube, tetrahedron, octahedron, dodecahedron, icosahedron, rhombic
// dodecahedron and the Sierpinski sponge, with freeglut 3.4.0's vertex and normal tables (the
// numbers carry over; they define the shapes programs expect) and its way of drawing them: every
// face gets its own copies of its corners with the face normal; wire shapes are one line loop per
// face; solids with triangle faces are one glDrawArrays, the others are split into triangles (a
// quad as 0,1,2 0,2,3; a pentagon as 0,1,2 0,2,4 4,2,3) drawn by one glDrawElements.
#include "shapes.h"

#include <vector>

namespace {

struct Polyhedron {
  const GLfloat *vertices;  // corner positions, xyz
  const GLfloat *normals;   // one per face, xyz
  const GLubyte *faces;     // corner indices, edges_per_face per face, counter-clockwise
  int face_count;
  int edges_per_face;
};

// The drawable arrays of a polyhedron: corners repeated per face, and triangle indices for faces
// that are not triangles.
struct Mesh {
  std::vector<GLfloat> vertices, normals;
  std::vector<GLushort> triangles;
  int corner_count = 0;
};

Mesh expand(const Polyhedron &p) {
  static const GLubyte quad_split[] = {0, 1, 2, 0, 2, 3};
  static const GLubyte pentagon_split[] = {0, 1, 2, 0, 2, 4, 4, 2, 3};
  const GLubyte *split = p.edges_per_face == 4 ? quad_split : p.edges_per_face == 5 ? pentagon_split : nullptr;
  const int split_size = p.edges_per_face == 4 ? 6 : 9;
  Mesh m;
  m.corner_count = p.face_count * p.edges_per_face;
  for (int f = 0; f < p.face_count; ++f) {
    for (int c = 0; c < p.edges_per_face; ++c) {
      const GLfloat *v = p.vertices + 3 * p.faces[f * p.edges_per_face + c];
      m.vertices.insert(m.vertices.end(), v, v + 3);
      m.normals.insert(m.normals.end(), p.normals + 3 * f, p.normals + 3 * f + 3);
    }
    if (split != nullptr)
      for (int k = 0; k < split_size; ++k) m.triangles.push_back(GLushort(f * p.edges_per_face + split[k]));
  }
  return m;
}

void draw(const Mesh &m, const Polyhedron &p, bool wire, const GLfloat *vertices) {
  if (wire)
    ffc::glut::draw_wire(vertices, m.normals.data(), nullptr, p.face_count, p.edges_per_face, GL_LINE_LOOP);
  else
    ffc::glut::draw_solid(vertices, m.normals.data(), nullptr, m.corner_count,
                          m.triangles.empty() ? nullptr : m.triangles.data(), 1, GLsizei(m.triangles.size()));
}

// ---- cube: unit edge, centred
const GLfloat kCubeVertices[] = {.5f, .5f,  .5f,  -.5f, .5f,  .5f,  -.5f, -.5f, .5f,  .5f,  -.5f, .5f,
                                 .5f, -.5f, -.5f, .5f,  .5f,  -.5f, -.5f, .5f,  -.5f, -.5f, -.5f, -.5f};
const GLfloat kCubeNormals[] = {0, 0, 1, 1, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1, 0, 0, 0, -1};
const GLubyte kCubeFaces[] = {0, 1, 2, 3, 0, 3, 4, 5, 0, 5, 6, 1, 1, 6, 7, 2, 7, 4, 3, 2, 4, 7, 6, 5};
const Polyhedron kCube = {kCubeVertices, kCubeNormals, kCubeFaces, 6, 4};

// ---- dodecahedron: corners (+-1,+-1,+-1), (0,+-z,+-x), (+-x,0,+-z), (+-z,+-x,0) with x = 1/phi,
// z = phi; so about 1.7 across
constexpr GLfloat kPhi = 1.61803398875f, kPhiInv = 0.61803398875f;
const GLfloat kDodecahedronVertices[] = {
    0.0f,     kPhi,     kPhiInv,  -1.0f, 1.0f,  1.0f,  -kPhiInv, 0.0f,     kPhi,     kPhiInv,  0.0f,     kPhi,
    1.0f,     1.0f,     1.0f,     0.0f,  kPhi,  -kPhiInv, 1.0f,   1.0f,     -1.0f,    kPhiInv,  0.0f,     -kPhi,
    -kPhiInv, 0.0f,     -kPhi,    -1.0f, 1.0f,  -1.0f, 0.0f,     -kPhi,    kPhiInv,  1.0f,     -1.0f,    1.0f,
    -1.0f,    -1.0f,    1.0f,     0.0f,  -kPhi, -kPhiInv, -1.0f,  -1.0f,    -1.0f,    1.0f,     -1.0f,    -1.0f,
    kPhi,     -kPhiInv, 0.0f,     kPhi,  kPhiInv, 0.0f, -kPhi,   kPhiInv,  0.0f,     -kPhi,    -kPhiInv, 0.0f};
constexpr GLfloat kDodA = 0.525731112119f, kDodB = 0.850650808354f;
const GLfloat kDodecahedronNormals[] = {0.0f,  kDodA, kDodB, 0.0f,  kDodA, -kDodB, 0.0f,  -kDodA, kDodB,
                                        0.0f,  -kDodA, -kDodB, kDodB, 0.0f, kDodA, -kDodB, 0.0f, kDodA,
                                        kDodB, 0.0f,  -kDodA, -kDodB, 0.0f, -kDodA, kDodA, kDodB, 0.0f,
                                        kDodA, -kDodB, 0.0f,  -kDodA, kDodB, 0.0f,  -kDodA, -kDodB, 0.0f};
const GLubyte kDodecahedronFaces[] = {0,  1,  2,  3,  4,  5,  6,  7,  8,  9,  10, 11, 3,  2,  12,
                                      13, 14, 8,  7,  15, 3,  11, 16, 17, 4,  2,  1,  18, 19, 12,
                                      7,  6,  17, 16, 15, 8,  14, 19, 18, 9,  17, 6,  5,  0,  4,
                                      16, 11, 10, 13, 15, 18, 1,  0,  5,  9,  19, 14, 13, 10, 12};
const Polyhedron kDodecahedron = {kDodecahedronVertices, kDodecahedronNormals, kDodecahedronFaces, 12, 5};

// ---- icosahedron: unit circumradius, a vertex on +x
const GLfloat kIcosahedronVertices[] = {
    1.0f,           0.0f,            0.0f,           0.447213595500f,  0.894427191000f,  0.0f,
    0.447213595500f, 0.276393202252f, 0.850650808354f, 0.447213595500f, -0.723606797748f, 0.525731112119f,
    0.447213595500f, -0.723606797748f, -0.525731112119f, 0.447213595500f, 0.276393202252f, -0.850650808354f,
    -0.447213595500f, -0.894427191000f, 0.0f,         -0.447213595500f, -0.276393202252f, 0.850650808354f,
    -0.447213595500f, 0.723606797748f, 0.525731112119f, -0.447213595500f, 0.723606797748f, -0.525731112119f,
    -0.447213595500f, -0.276393202252f, -0.850650808354f, -1.0f,         0.0f,             0.0f};
const GLfloat kIcosahedronNormals[] = {
    0.760845213037948f,  0.470228201835026f,  0.341640786498800f,  0.760845213036861f,  -0.179611190632978f,
    0.552786404500000f,  0.760845213033849f,  -0.581234022404097f, 0.0f,                0.760845213036861f,
    -0.179611190632978f, -0.552786404500000f, 0.760845213037948f,  0.470228201835026f,  -0.341640786498800f,
    0.179611190628666f,  0.760845213037948f,  0.552786404498399f,  0.179611190634277f,  -0.290617011204044f,
    0.894427191000000f,  0.179611190633958f,  -0.940456403667806f, 0.0f,                0.179611190634278f,
    -0.290617011204044f, -0.894427191000000f, 0.179611190628666f,  0.760845213037948f,  -0.552786404498399f,
    -0.179611190633958f, 0.940456403667806f,  0.0f,                -0.179611190634277f, 0.290617011204044f,
    0.894427191000000f,  -0.179611190628666f, -0.760845213037948f, 0.552786404498399f,  -0.179611190628666f,
    -0.760845213037948f, -0.552786404498399f, -0.179611190634277f, 0.290617011204044f,  -0.894427191000000f,
    -0.760845213036861f, 0.179611190632978f,  -0.552786404500000f, -0.760845213033849f, 0.581234022404097f,
    0.0f,                -0.760845213036861f, 0.179611190632978f,  0.552786404500000f,  -0.760845213037948f,
    -0.470228201835026f, 0.341640786498800f,  -0.760845213037948f, -0.470228201835026f, -0.341640786498800f};
const GLubyte kIcosahedronFaces[] = {0, 1,  2, 0,  2, 3,  0,  3,  4,  0, 4,  5,  0, 5, 1,  1, 8, 2,  2,  7,
                                     3, 3,  6, 4,  4, 10, 5,  5,  9,  1, 1,  9,  8, 2, 8,  7, 3, 7,  6,  4,
                                     6, 10, 5, 10, 9, 11, 9,  10, 11, 8, 9,  11, 7, 8, 11, 6, 7, 11, 10, 6};
const Polyhedron kIcosahedron = {kIcosahedronVertices, kIcosahedronNormals, kIcosahedronFaces, 20, 3};

// ---- octahedron: unit circumradius, vertices on the axes
const GLfloat kOctahedronVertices[] = {1.f, 0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f,
                                       -1.f, 0.f, 0.f, 0.f, -1.f, 0.f, 0.f, 0.f, -1.f};
constexpr GLfloat kOctN = 0.577350269189f;  // sqrt(1/3)
const GLfloat kOctahedronNormals[] = {kOctN,  kOctN,  kOctN,  kOctN,  kOctN,  -kOctN, kOctN,  -kOctN,
                                      kOctN,  kOctN,  -kOctN, -kOctN, -kOctN, kOctN,  kOctN,  -kOctN,
                                      kOctN,  -kOctN, -kOctN, -kOctN, kOctN,  -kOctN, -kOctN, -kOctN};
const GLubyte kOctahedronFaces[] = {0, 1, 2, 0, 5, 1, 0, 2, 4, 0, 4, 5, 3, 2, 1, 3, 1, 5, 3, 4, 2, 3, 5, 4};
const Polyhedron kOctahedron = {kOctahedronVertices, kOctahedronNormals, kOctahedronFaces, 8, 3};

// ---- rhombic dodecahedron
constexpr GLfloat kR = 0.707106781187f, kRn = 0.353553390594f;
const GLfloat kRhombicVertices[] = {0.0f, 0.0f, 1.0f,  kR,   0.0f, 0.5f,  0.0f, kR,   0.5f,  -kR,  0.0f, 0.5f,
                                    0.0f, -kR,  0.5f,  kR,   kR,   0.0f,  -kR,  kR,   0.0f,  -kR,  -kR,  0.0f,
                                    kR,   -kR,  0.0f,  kR,   0.0f, -0.5f, 0.0f, kR,   -0.5f, -kR,  0.0f, -0.5f,
                                    0.0f, -kR,  -0.5f, 0.0f, 0.0f, -1.0f};
const GLfloat kRhombicNormals[] = {kRn,  kRn,  0.5f, -kRn, kRn,  0.5f, -kRn, -kRn, 0.5f, kRn,  -kRn, 0.5f,
                                   0.0f, 1.0f, 0.0f, -1.0f, 0.0f, 0.0f, 0.0f, -1.0f, 0.0f, 1.0f, 0.0f, 0.0f,
                                   kRn,  kRn,  -0.5f, -kRn, kRn,  -0.5f, -kRn, -kRn, -0.5f, kRn, -kRn, -0.5f};
const GLubyte kRhombicFaces[] = {0, 1,  5,  2, 0, 2,  6,  3, 0, 3,  7,  4, 0, 4,  8,  1, 5, 10, 6,  2, 6, 11, 7,  3,
                                 7, 12, 8,  4, 8, 9,  5,  1, 5, 9,  13, 10, 6, 10, 13, 11, 7, 11, 13, 12, 8, 12, 13, 9};
const Polyhedron kRhombicDodecahedron = {kRhombicVertices, kRhombicNormals, kRhombicFaces, 12, 4};

// ---- tetrahedron: unit circumradius, a vertex on +x; each face normal is minus the opposite vertex
constexpr GLfloat kTetX = 0.333333333333f, kTetY1 = 0.942809041582f, kTetY2 = 0.471404520791f,
                  kTetZ = 0.816496580928f;
const GLfloat kTetrahedronVertices[] = {1.0f, 0.0f, 0.0f, -kTetX, kTetY1, 0.0f,
                                        -kTetX, -kTetY2, kTetZ, -kTetX, -kTetY2, -kTetZ};
const GLfloat kTetrahedronNormals[] = {-1.0f, 0.0f, 0.0f, kTetX, -kTetY1, 0.0f,
                                       kTetX, kTetY2, -kTetZ, kTetX, kTetY2, kTetZ};
const GLubyte kTetrahedronFaces[] = {1, 3, 2, 0, 2, 3, 0, 3, 1, 0, 1, 2};
const Polyhedron kTetrahedron = {kTetrahedronVertices, kTetrahedronNormals, kTetrahedronFaces, 4, 3};

template <const Polyhedron &P>
void draw_cached(bool wire) {
  static const Mesh mesh = expand(P);
  draw(mesh, P, wire, mesh.vertices.data());
}

void cube(GLfloat size, bool wire) {
  static const Mesh mesh = expand(kCube);
  if (size == 1.f) return draw(mesh, kCube, wire, mesh.vertices.data());
  std::vector<GLfloat> scaled(mesh.vertices.size());
  for (size_t i = 0; i < scaled.size(); ++i) scaled[i] = size * mesh.vertices[i];
  draw(mesh, kCube, wire, scaled.data());
}

// The sponge at level n is four sponges of level n-1, half the size, centred halfway to the four
// corners of the tetrahedron; level 0 is the tetrahedron itself. Offsets stay in double until the
// level-0 corners, as in freeglut, so the rounding matches.
void sponge(int levels, const double offset[3], GLfloat scale, GLfloat *vertices, GLfloat *normals) {
  if (levels == 0) {
    for (int f = 0; f < 4; ++f)
      for (int c = 0; c < 3; ++c) {
        const GLfloat *v = kTetrahedronVertices + 3 * kTetrahedronFaces[f * 3 + c];
        const int out = 9 * f + 3 * c;
        for (int k = 0; k < 3; ++k) {
          vertices[out + k] = GLfloat(offset[k]) + scale * v[k];
          normals[out + k] = kTetrahedronNormals[3 * f + k];
        }
      }
    return;
  }
  int stride = 36;  // floats per level-0 tetrahedron
  for (int l = 1; l < levels; ++l) stride *= 4;
  scale /= 2.0;
  for (int corner = 0; corner < 4; ++corner) {
    double local[3];
    for (int k = 0; k < 3; ++k) local[k] = offset[k] + scale * kTetrahedronVertices[3 * corner + k];
    sponge(levels - 1, local, scale, vertices + corner * stride, normals + corner * stride);
  }
}

void sierpinski(int levels, double offset[3], GLfloat scale, bool wire) {
  if (levels < 0 || offset == nullptr) return;
  GLsizei tetrahedra = 1;
  for (int l = 0; l < levels; ++l) tetrahedra *= 4;
  const GLsizei corners = tetrahedra * 12;
  std::vector<GLfloat> vertices(size_t(corners) * 3), normals(size_t(corners) * 3);
  sponge(levels, offset, scale, vertices.data(), normals.data());
  if (wire)
    ffc::glut::draw_wire(vertices.data(), normals.data(), nullptr, tetrahedra * 4, 3, GL_LINE_LOOP);
  else
    ffc::glut::draw_solid(vertices.data(), normals.data(), nullptr, corners, nullptr, 1, 0);
}

}  // namespace

FFC_GLUT_EXPORT void FGAPIENTRY glutWireCube(double size) { cube(GLfloat(size), true); }
FFC_GLUT_EXPORT void FGAPIENTRY glutSolidCube(double size) { cube(GLfloat(size), false); }
FFC_GLUT_EXPORT void FGAPIENTRY glutWireTetrahedron(void) { draw_cached<kTetrahedron>(true); }
FFC_GLUT_EXPORT void FGAPIENTRY glutSolidTetrahedron(void) { draw_cached<kTetrahedron>(false); }
FFC_GLUT_EXPORT void FGAPIENTRY glutWireOctahedron(void) { draw_cached<kOctahedron>(true); }
FFC_GLUT_EXPORT void FGAPIENTRY glutSolidOctahedron(void) { draw_cached<kOctahedron>(false); }
FFC_GLUT_EXPORT void FGAPIENTRY glutWireDodecahedron(void) { draw_cached<kDodecahedron>(true); }
FFC_GLUT_EXPORT void FGAPIENTRY glutSolidDodecahedron(void) { draw_cached<kDodecahedron>(false); }
FFC_GLUT_EXPORT void FGAPIENTRY glutWireIcosahedron(void) { draw_cached<kIcosahedron>(true); }
FFC_GLUT_EXPORT void FGAPIENTRY glutSolidIcosahedron(void) { draw_cached<kIcosahedron>(false); }
FFC_GLUT_EXPORT void FGAPIENTRY glutWireRhombicDodecahedron(void) { draw_cached<kRhombicDodecahedron>(true); }
FFC_GLUT_EXPORT void FGAPIENTRY glutSolidRhombicDodecahedron(void) { draw_cached<kRhombicDodecahedron>(false); }
FFC_GLUT_EXPORT void FGAPIENTRY glutWireSierpinskiSponge(int num_levels, double offset[3], double scale) {
  sierpinski(num_levels, offset, GLfloat(scale), true);
}
FFC_GLUT_EXPORT void FGAPIENTRY glutSolidSierpinskiSponge(int num_levels, double offset[3], double scale) {
  sierpinski(num_levels, offset, GLfloat(scale), false);
}
