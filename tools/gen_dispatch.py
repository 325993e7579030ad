#!/usr/bin/env python3
"""Writes src/gl/gl_functions.inc: the one list of GL entry points that ffcompat's glad-style
dispatch loads. Edit FUNCS and rerun; the header's #defines and the X-macro come from it."""
import re, pathlib
FUNCS = """
void ArrayElement(GLint i)
void Begin(GLenum mode)
void CallList(GLuint list)
void CallLists(GLsizei n, GLenum type, const GLvoid *lists)
void Clear(GLbitfield mask)
void ClearColor(GLclampf red, GLclampf green, GLclampf blue, GLclampf alpha)
void ClearDepth(GLclampd depth)
void ColorMaterial(GLenum face, GLenum mode)
void ColorPointer(GLint size, GLenum type, GLsizei stride, const GLvoid *ptr)
void CullFace(GLenum mode)
void DeleteLists(GLuint list, GLsizei range)
void DepthFunc(GLenum func)
void DepthRange(GLclampd near_val, GLclampd far_val)
void Disable(GLenum cap)
void DisableClientState(GLenum cap)
void DrawArrays(GLenum mode, GLint first, GLsizei count)
void DrawElements(GLenum mode, GLsizei count, GLenum type, const GLvoid *indices)
void DrawPixels(GLsizei width, GLsizei height, GLenum format, GLenum type, const GLvoid *pixels)
void EdgeFlag(GLboolean flag)
void EdgeFlagv(const GLboolean *flag)
void Enable(GLenum cap)
void EnableClientState(GLenum cap)
void End(void)
void EndList(void)
void FeedbackBuffer(GLsizei size, GLenum type, GLfloat *buffer)
void Finish(void)
void Flush(void)
void Fogf(GLenum pname, GLfloat param)
void Fogfv(GLenum pname, const GLfloat *params)
void Fogi(GLenum pname, GLint param)
void Fogiv(GLenum pname, const GLint *params)
void FrontFace(GLenum mode)
void Frustum(GLdouble left, GLdouble right, GLdouble bottom, GLdouble top, GLdouble near_val, GLdouble far_val)
GLuint GenLists(GLsizei range)
void GetBooleanv(GLenum pname, GLboolean *params)
void GetDoublev(GLenum pname, GLdouble *params)
GLenum GetError(void)
void GetFloatv(GLenum pname, GLfloat *params)
void GetIntegerv(GLenum pname, GLint *params)
void GetLightfv(GLenum light, GLenum pname, GLfloat *params)
void GetMaterialfv(GLenum face, GLenum pname, GLfloat *params)
void GetPointerv(GLenum pname, GLvoid **params)
const GLubyte * GetString(GLenum name)
void Hint(GLenum target, GLenum mode)
void InitNames(void)
void InterleavedArrays(GLenum format, GLsizei stride, const GLvoid *pointer)
GLboolean IsEnabled(GLenum cap)
GLboolean IsList(GLuint list)
void LightModelf(GLenum pname, GLfloat param)
void LightModelfv(GLenum pname, const GLfloat *params)
void LightModeli(GLenum pname, GLint param)
void Lightf(GLenum light, GLenum pname, GLfloat param)
void Lightfv(GLenum light, GLenum pname, const GLfloat *params)
void Lighti(GLenum light, GLenum pname, GLint param)
void LineWidth(GLfloat width)
void ListBase(GLuint base)
void LoadIdentity(void)
void LoadMatrixd(const GLdouble *m)
void LoadMatrixf(const GLfloat *m)
void LoadName(GLuint name)
void Materialf(GLenum face, GLenum pname, GLfloat param)
void Materialfv(GLenum face, GLenum pname, const GLfloat *params)
void Materiali(GLenum face, GLenum pname, GLint param)
void MatrixMode(GLenum mode)
void MultMatrixd(const GLdouble *m)
void MultMatrixf(const GLfloat *m)
void NewList(GLuint list, GLenum mode)
void NormalPointer(GLenum type, GLsizei stride, const GLvoid *ptr)
void Ortho(GLdouble left, GLdouble right, GLdouble bottom, GLdouble top, GLdouble near_val, GLdouble far_val)
void PassThrough(GLfloat token)
void PixelStorei(GLenum pname, GLint param)
void PointSize(GLfloat size)
void PolygonOffset(GLfloat factor, GLfloat units)
void PopMatrix(void)
void PopName(void)
void PushMatrix(void)
void PushName(GLuint name)
void RasterPos2f(GLfloat x, GLfloat y)
void ReadPixels(GLint x, GLint y, GLsizei width, GLsizei height, GLenum format, GLenum type, GLvoid *pixels)
GLint RenderMode(GLenum mode)
void Rotated(GLdouble angle, GLdouble x, GLdouble y, GLdouble z)
void Rotatef(GLfloat angle, GLfloat x, GLfloat y, GLfloat z)
void Scaled(GLdouble x, GLdouble y, GLdouble z)
void Scalef(GLfloat x, GLfloat y, GLfloat z)
void SelectBuffer(GLsizei size, GLuint *buffer)
void ShadeModel(GLenum mode)
void TexCoordPointer(GLint size, GLenum type, GLsizei stride, const GLvoid *ptr)
void Translated(GLdouble x, GLdouble y, GLdouble z)
void Translatef(GLfloat x, GLfloat y, GLfloat z)
void VertexPointer(GLint size, GLenum type, GLsizei stride, const GLvoid *ptr)
void Viewport(GLint x, GLint y, GLsizei width, GLsizei height)
"""
# The immediate-mode families in every type (src/state/soft_gl_immediate.cpp defines them).
TYPES = {"b": "GLbyte", "s": "GLshort", "i": "GLint", "f": "GLfloat", "d": "GLdouble",
         "ub": "GLubyte", "us": "GLushort", "ui": "GLuint"}
def family(name, counts, suffixes, args):
    out = []
    for n in counts:
        for sfx in suffixes:
            t = TYPES[sfx]
            params = ", ".join(f"{t} {a}" for a in args[:n])
            out.append(f"void {name}{n}{sfx}({params})")
            out.append(f"void {name}{n}{sfx}v(const {t} *v)")
    return out
VARIANTS = (family("Vertex", [2, 3, 4], "sifd", "xyzw")
            + family("Normal", [3], "bsifd", ["nx", "ny", "nz"])
            + family("Color", [3, 4], ["b", "s", "i", "f", "d", "ub", "us", "ui"],
                     ["red", "green", "blue", "alpha"])
            + family("TexCoord", [1, 2, 3, 4], "sifd", "strq")
            + [f"void Rect{s}({TYPES[s]} x1, {TYPES[s]} y1, {TYPES[s]} x2, {TYPES[s]} y2)" for s in "sifd"]
            + [f"void Rect{s}v(const {TYPES[s]} *v1, const {TYPES[s]} *v2)" for s in "sifd"])
rows = []
for line in sorted(set(FUNCS.strip().splitlines()) | set(VARIANTS),
                   key=lambda l: re.match(r".+?\s*\b(\w+)\(", l).group(1)):
    m = re.match(r"(.+?)\s*\b(\w+)\((.*)\)$", line.strip())
    ret, name, params = m.group(1).strip(), m.group(2), m.group(3)
    rows.append((ret, name, params))
out = ["// Generated by tools/gen_dispatch.py: the GL 1.x entry points of ffcompat's dispatch.",
       "// FFC_GL_FUNCTION(return type, name without the gl prefix, (parameters))"]
for ret, name, params in rows:
    out.append(f"FFC_GL_FUNCTION({ret}, {name}, ({params}))")
pathlib.Path("src/gl/gl_functions.inc").write_text("\n".join(out) + "\n")
defs = ["// Generated by tools/gen_dispatch.py: plain gl* names resolve to the dispatch's pointers."]
defs += [f"#define gl{name} ffc_gl{name}" for _, name, _ in rows]
pathlib.Path("src/gl/gl_names.inc").write_text("\n".join(defs) + "\n")

