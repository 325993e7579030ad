// Our GL context: the fixed-function state with GL's defaults and errors (OpenGL 2.1
// compatibility, sections 2.6 to 2.14), the vertex stage that lights every vertex as it is
// submitted, and the hand-off to the rasterizer or to feedback.
//
// Entry points validate first and change nothing on error (they record the first error for
// glGetError), then apply. One dirty bit, `constants_dirty_` (a colour, position or enable changed):
// the constants are prepared again before the next vertex, and with them the lighting key (the
// pipeline's shape, lighting::make_key), which picks the kernel.
#pragma once
#include <GL/gl.h>

#include <array>
#include <atomic>
#include <cstdint>
#include <cstring>
#include <glm/glm.hpp>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "lighting/lighting.h"
#include "state/display_list.h"
#include "state/draw_sink.h"
#include "state/float_matrix.h"
#include "state/selection.h"
#include "state/fragment.h"
#include "state/vertex_stage.h"
#include "raster/raster.h"
#include "raster/triangle_list.h"

namespace ffc::state {

enum class Precision { Float, Double };

inline constexpr const char* kClipTempsUnwritten =
    "flat feedback of a clipped primitive reports a clip-made vertex's colours from a temporary "
    "Mesa's clipper allocated uninitialised and had not yet written";
inline constexpr const char* kLineSmooth =
    "GL_LINE_SMOOTH is not modelled: lines are drawn aliased, where llvmpipe draws them wider "
    "through its draw module's antialiasing stage (a zero-length one as a dot)";
inline constexpr const char* kPointSmooth =
    "GL_POINT_SMOOTH is not modelled: points are drawn aliased, where llvmpipe draws them through its "
    "draw module's antialiasing stage";
inline constexpr const char* kZeroNormal = "zero-length normal under GL_NORMALIZE: only ambient and emission remain";
// Not modelled, reported when met: what Mesa does there is not soft's picture or feedback.
inline constexpr const char* kNonfiniteDrawPixels =
    "glDrawPixels at a raster position that is not finite: soft draws nothing, Mesa draws at a place of its own";
inline constexpr const char* kColorShrinkInPrimitive =
    "a glColor3 inside glBegin/glEnd after a glColor4 (the colour's active size shrinking mid-primitive): "
    "Mesa reports alpha 1 for some vertices sent before it";
inline constexpr const char* kNonfiniteVertex =
    "a line, quad or polygon vertex with a NaN or infinite position or normal: undefined in GL; Mesa's clipper "
    "and lighting keep remnants soft does not reproduce";
inline constexpr const char* kZeroClipVertex =
    "a vertex at clip coordinates (0, 0, 0, 0) in a line, quad or polygon: inside every clip plane, but its window "
    "position is 0 / 0 (undefined in GL); Mesa's clipper and rasterizer place it where soft does not";
inline constexpr const char* kUnfilledClipped =
    "glPolygonMode GL_LINE or GL_POINT on a triangle the view volume clips: Mesa clips the triangle and draws the "
    "pieces of its edges that remain, zero-length ones too; soft clips each edge as a line";
inline constexpr const char* kClippedSliver =
    "a smooth triangle of a clipped polygon's fan with corners collinear up to float rounding that still covers "
    "pixels: its colour planes are rounding noise, llvmpipe's (float) and soft's (double) leave the vertices' "
    "range differently";
inline constexpr const char* kDrawPixelsFormat =
    "glDrawPixels with a format or type soft does not implement (depth, stencil, colour index, the integer and "
    "packed types): GL_INVALID_OPERATION and nothing drawn, where Mesa draws";
inline constexpr const char* kLineLoopWrap =
    "a glColor inside glBegin(GL_LINE_LOOP) that grows the colour attribute after the first vertex: Mesa's vbo "
    "wraps the primitive and loses the loop's closing segment";
inline constexpr const char* kTexCoordVarying =
    "texture coordinates that vary between the vertices of one draw, in feedback: soft reports the current ones "
    "for every vertex";
inline constexpr const char* kTexGen =
    "texture coordinate generation (GL_TEXTURE_GEN_*) is not modelled: fed-back texture coordinates are the current ones";

// How integer normals and colours map to [-1, 1] or [0, 1] (unsigned: c / (2^b - 1) in every rule).
//   Raw:      not at all (positions, indices);
//   Gl21:     signed (2c + 1) / (2^b - 1), GL 2.1's table 2.9;
//   Gl42:     signed max(c / (2^(b-1) - 1), -1), GL 4.2's rule, which Mesa 22.3's draws use;
//   MesaCall: GL 2.1's rule in float as Mesa's glNormal3b / glColor4s ... compute it (BYTE_TO_FLOAT
//             and friends in macros.h), which its glArrayElement goes through.
enum class Fixed : unsigned char { Raw, Gl21, Gl42, MesaCall };

struct ClientArray {
  bool enabled = false;
  GLint size = 4;
  GLenum type = GL_FLOAT;
  GLsizei stride = 0;
  const void* pointer = nullptr;
  bool repeated = false;  // every element is the first (a constant attribute, not a GL array)
};

class Context {
 public:
  Context(int width, int height, Precision precision = Precision::Float);
  ~Context();  // after immediate mode's early job in flight (it reads the context's lists)

  raster::Framebuffer& framebuffer() {  // as drawn: a pending glClear done first
    flush_clear();
    return fb_;
  }
  // The colour buffer, top row first (RGBA8), copied by the workers.
  void read_top_down(uint8_t* out);
  Precision precision() const { return precision_; }
  // The spec mode follows GL 2.1 to the letter where Mesa 22.3 departs from it (docs/deviations.md);
  // off (the default), the context reproduces Mesa's pictures, quirks included.
  void set_spec(bool on) { spec_ = on; }
  bool spec() const { return spec_; }
  // Off: every primitive takes the general path (vertex by vertex, then set-up triangles), which
  // the triangle-list path is tested against. The picture does not change.
  void set_triangle_lists(bool on) { triangle_lists_ = on; }
  void set_threads(int n) {
    early_join();
    threads_ = n < 1 ? 1 : n;
    bins_reserved_ = 0;
    workers_.reset();
  }  // the rasterizer's; the picture does not change
  // Immediate mode's early draws (immediate.cpp): a glBegin(GL_TRIANGLES) hands its complete
  // triangles to a thread of its own every `corners` corners sent (0: never; the default from
  // FFCOMPAT_EARLY_CORNERS, else kEarlyCorners). The picture does not change.
  void set_early_corners(size_t corners) { early_corners_ = corners; }
  // The job draws this many triangles between two looks at whether a join wants it to stop
  // (kEarlyChunk; tests take 1). The picture does not change.
  void set_early_chunk(size_t triangles) { early_chunk_ = triangles < 1 ? 1 : triangles; }
  // Joins that found the job in flight with triangles left and stopped it after its chunk.
  size_t early_stops() const { return early_.stops; }
  // Inline: every entry point reads it (a call per glVertex cost as much as the store it guards).
  static Context* current() { return current_; }
  static void make_current(Context* c);
  // What this context's draws counted since it was made (raster.h Counters): its own, whatever
  // other contexts draw on other threads meanwhile.
  const raster::Counters& counters() const { return counters_; }

  // Immediate mode's stores (soft_gl_immediate.cpp): inside a glBegin(GL_TRIANGLES) whose corners
  // are kept for the triangle list (immediate_list_), with no list compiling and no sink drawing,
  // a glNormal or glVertex only stores what Normal() and Vertex() would. False: nothing done, the
  // caller takes the full call.
  bool store_normal(double x, double y, double z) {
    if (!store_corners_ || !normal_in_format_ || lists_.mode != 0) return false;
    normal_ = {x, y, z};
    return true;
  }
  // A recent distinct corner of a glDrawArrays soup (soup.cpp): its floats' bits and its place.
  // Only once the format holds a position at least `size` wide: a position growing mid-primitive
  // wraps Mesa's vbo (position_size), which the full call does.
  bool store_vertex(float x, float y, float z, float w, int size) {
    if (!store_corners_ || lists_.mode != 0 || !format_has_position_ || size > position_size_) return false;
    if (!kept_repeat(x, y, z, w)) keep_list_vertex(x, y, z, w);
    return true;
  }

  // --- GL entry points (names as in GL, without the prefix) ---
  GLenum GetError();
  void Enable(GLenum cap) { set_enabled(cap, true); }
  void Disable(GLenum cap) { set_enabled(cap, false); }
  GLboolean IsEnabled(GLenum cap);
  void EnableClientState(GLenum a) { set_client_state(a, true); }
  void DisableClientState(GLenum a) { set_client_state(a, false); }

  void Lightfv(GLenum light, GLenum pname, const GLfloat* params);
  void Lightf(GLenum light, GLenum pname, GLfloat param);
  void Lightiv(GLenum light, GLenum pname, const GLint* params);
  void Lighti(GLenum light, GLenum pname, GLint param);
  void LightModelfv(GLenum pname, const GLfloat* params);
  void LightModelf(GLenum pname, GLfloat param);
  void LightModeli(GLenum pname, GLint param);
  void Materialfv(GLenum face, GLenum pname, const GLfloat* params);
  void Materialf(GLenum face, GLenum pname, GLfloat param);
  void Materiali(GLenum face, GLenum pname, GLint param);
  void ColorMaterial(GLenum face, GLenum mode);
  void ShadeModel(GLenum mode);
  void FrontFace(GLenum mode);
  void CullFace(GLenum mode);
  void DepthFunc(GLenum func);
  void GetLightfv(GLenum light, GLenum pname, GLfloat* params);
  void GetMaterialfv(GLenum face, GLenum pname, GLfloat* params);
  void GetDoublev(GLenum pname, GLdouble* params);
  void GetFloatv(GLenum pname, GLfloat* params);
  void GetIntegerv(GLenum pname, GLint* params);
  void GetBooleanv(GLenum pname, GLboolean* params);
  void GetPointerv(GLenum pname, void** params);

  void MatrixMode(GLenum mode);
  void LoadIdentity();
  void LoadMatrix(const glm::dmat4& m);
  void MultMatrix(const glm::dmat4& m);
  void PushMatrix();
  void PopMatrix();
  void Rotate(double angle_deg, double x, double y, double z);
  void Scale(double x, double y, double z);
  void Translate(double x, double y, double z);
  void Ortho(double l, double r, double b, double t, double n, double f);
  void Frustum(double l, double r, double b, double t, double n, double f);
  void Viewport(GLint x, GLint y, GLsizei w, GLsizei h);
  void DepthRange(double n, double f);
  void ClearColor(float r, float g, float b, float a);
  void ClearDepth(double d);
  void Clear(GLbitfield mask);
  void LineWidth(float w);
  void Finish();
  void Flush();
  void PointSize(float size);
  void Fogfv(GLenum pname, const GLfloat* params);  // fog.cpp, as PolygonOffset
  void PolygonOffset(GLfloat factor, GLfloat units);
  void PolygonMode(GLenum face, GLenum mode);  // polygon_mode.cpp

  void Begin(GLenum mode);
  void End();
  void Vertex(double x, double y, double z, double w, int size = 0);  // size: components sent (0: not known)
  void Normal(double x, double y, double z);
  void Color(double r, double g, double b, double a, int components = 4);  // glColor3*: 3
  void VertexPointer(GLint size, GLenum type, GLsizei stride, const void* p);
  void NormalPointer(GLenum type, GLsizei stride, const void* p);
  void ColorPointer(GLint size, GLenum type, GLsizei stride, const void* p);
  void DrawArrays(GLenum mode, GLint first, GLsizei count);
  void DrawElements(GLenum mode, GLsizei count, GLenum type, const void* indices);
  void ArrayElement(GLint i);

  void RasterPos(double x, double y, double z, double w);
  // packed: a list's copy (list_image), read whatever the GL_UNPACK_* state is then.
  void DrawPixels(GLsizei w, GLsizei h, GLenum format, GLenum type, const void* pixels, bool packed = false);
  std::vector<GLubyte> list_image(GLsizei w, GLsizei h, GLenum format, GLenum type, const void* pixels) const;
  void FeedbackBuffer(GLsizei size, GLenum type, GLfloat* buffer);
  GLint RenderMode(GLenum mode);
  void ReadPixels(GLint x, GLint y, GLsizei w, GLsizei h, GLenum format, GLenum type, void* pixels);
  void PixelStorei(GLenum pname, GLint param);
  const GLubyte* GetString(GLenum name);

  // Display lists (display_list.cpp; recording: display_list.h).
  GLuint GenLists(GLsizei range);
  void DeleteLists(GLuint list, GLsizei range);
  GLboolean IsList(GLuint list);
  void NewList(GLuint list, GLenum mode);
  void EndList();
  void CallList(GLuint list);
  void CallLists(GLsizei n, GLenum type, const void* lists);
  void call_one_list(GLuint list);
  void end_list_calls();  // the outermost glCallList(s) ends: a pending normal or colour reaches the state
  void ListBase(GLuint base);
  // Not GL: the list that calls are recorded into now (null when they only execute), and whether
  // a recorded call also executes (GL_COMPILE_AND_EXECUTE).
  DisplayList* list_recording();
  bool list_executes() const { return lists_.mode == GL_COMPILE_AND_EXECUTE; }
  DisplayList& list_held_back() { return lists_.held_back; }
  void run_held_back(bool new_format = true);  // executes the vertex-stream calls GL_COMPILE_AND_EXECUTE held back
  void note_list_primitive(GLenum mode, int vertices);  // a primitive compiled (DisplayList::note_primitive)
  void hold_back(int kind, int size = 0);  // a vertex-stream call is held back (kind: see compiled_only; size: components)
  void mark_list_attribute(DisplayList& l, int kind);  // a glNormal (1) or glColor (2) compiled outside the list's glBegin/glEnd
  void keep_pending(int kind);  // such a call has run from a list: its value waits for a flush
  void list_loopback(int kinds, int kind, bool first_format);  // run from a list: a wrapped primitive's rest replays these attributes over the pending ones
  bool store_fills(GLsizei count) const;  // a compiled draw overfills the list's vertex store
  void list_before_joining(DisplayList& l, int kind);  // an attribute about to join the list's format
  void value_before_joining();  // run from a list: the values before such an attribute
  void list_trailing(DisplayList& l, int kind);  // an attribute compiled after a vertex of the list's primitive
  void list_primitive_end(DisplayList& l, int trailing);  // its glEnd was compiled: the trailing values dropped
  void show_current();  // the current values Mesa's executing side shows inside the list's glBegin (ListState::shown)
  void list_fallback();  // a glCallList(s) compiles inside the list's glBegin (Mesa's dlist_fallback)
  void fallen_back_run();  // ... and in GL_COMPILE_AND_EXECUTE, after the held-back calls ran: inside the glBegin
  void mark_loopback();  // the list compiling is replayed through immediate mode (DisplayList::loopback)
  void mark_called_loopback(const DisplayList& l);  // ... and so are the lists it calls, for good
  void note_loop_first_vertex(DisplayList& l);  // after a compiled vertex: a line loop's first keeps its values
  void loop_first_vertex();  // run from the held-back calls: a line loop's first vertex's values
  void copied_vertex_values(int kind, const glm::dvec4& v);  // a wrap's copies take the compiler's value
  void snapshot_last_vertex();  // run from a list: the normal and colour its last vertex took
  void drop_trailing(int kind);  // run from a list after its glEnd: those values back
  void list_vertex_compiled(DisplayList& l, int own, bool last);  // a vertex compiles in a primitive of the list: it carries the trailing values
  void carry_trailing(int kind);  // run from a list before such a vertex: the trailing values again
  ListState& list_state() { return lists_; }
  bool inside_begin() const { return in_begin_; }  // GL_COMPILE_AND_EXECUTE: the executing side too (a wrap)
  // glCallList draws the list's vertex lists as indexed draws (not replayed through immediate mode).
  bool list_indexed() const { return lists_.calling && !lists_.replaying_loopback; }
  void compile_error(DisplayList& l, GLenum e);  // a compiled draw's error (display_list.cpp)
  void record_list_error(GLenum e);  // a compile error: recorded, and raised now in GL_COMPILE_AND_EXECUTE
  // Vertex-array draws while compiling, dereferenced (indices null: first .. first + count - 1).
  void compile_elements(DisplayList& l, GLenum mode, GLsizei count, const GLuint* indices, GLint first);
  void compile_draw_elements(DisplayList& l, GLenum mode, GLsizei count, GLenum type, const void* indices);
  void compile_element(DisplayList& l, GLint i);
  bool forms_format(const DisplayList& l) const;  // whether recording into l stands for Mesa's vertex store
  // Mesa's vertex lists as the compiled list records them (display_list.cpp, Context::start_list_node).
  void start_list_node(bool draw);  // a primitive begins in the list's vertex store (a compiled draw or not)
  void end_list_node();             // the store is compiled into a vertex list (a flush)
  void split_list_node(int joining = 0);           // ... and its open primitive goes on in the next (a wrap)
  void note_vertexless_node();  // a vertex list ends: one with attributes and no vertex (kListVertexlessNode)
  void note_node_primitive(bool open);  // the open primitive ends, or a flush cuts it (kListTwoThenQuadCrash)
  void note_node_mode(GLenum mode, int vertices);  // a primitive's vertices in the open vertex list (kListModesFedBackFirst)
  void close_node_modes();  // the open vertex list's draws as Mesa merges them (kListModesFedBackFirst, kListModesCrash)
  void node_begins();               // run from a list: a vertex list starts
  void node_ends(bool draw, int loop, bool copy);  // run from a list: it ends; a last primitive drawn from arrays copies
                                        // nothing, a closed line loop (loop: the attributes) replays its first vertex
  void node_splits(bool draw, int copy, int joining);  // run from a list: a wrap ends it inside a primitive (copy: Context::split_list_node)
  // Mesa's immediate-mode flushes of the values a list left pending (display_list.cpp, Context::flush_pending).
  void begin_list_calls();        // the outermost glCallList(s) begins (its FLUSH_CURRENT)
  void flush_pending(bool draw, int joining = 0);  // a vertex list starts (FLUSH_FOR_DRAW) or a state call flushes (FLUSH_VERTICES)
  void apply_pending();           // the pending values reach the state
  void store_vertex(int kind, const glm::dvec4& v);  // a value entering the list's store: a vertex (-1), a normal (1), a colour (2)
  void close_store();               // the store is compiled into a vertex list: its repeats counted
  void stray_end();                 // run from a list: the glEnd of a draw joined to a restarted primitive
  void drop_open_primitive(bool keep_open, int drop);  // run from a list: a compiled draw inside the list's own glBegin
  void call_list_offset(GLuint offset);  // a compiled glCallLists name: the list base read now

  // Texture coordinates, the edge flag, glRect, glHint, glInterleavedArrays (attributes.cpp).
  void TexCoord(float s, float t, float r, float q);
  void EdgeFlag(GLboolean flag);
  void Rect(float x1, float y1, float x2, float y2);
  void Hint(GLenum target, GLenum mode);
  void TexCoordPointer(GLint size, GLenum type, GLsizei stride, const void* p);
  void InterleavedArrays(GLenum format, GLsizei stride, const void* p);

  // Selection (selection.cpp) and glPassThrough (feedback.cpp).
  void SelectBuffer(GLsizei size, GLuint* buffer);
  void InitNames();
  void LoadName(GLuint name);
  void PushName(GLuint name);
  void PopName();
  void PassThrough(GLfloat token);

  // Not GL: records `e` as a GL call would (the first error stays until glGetError). The C ABI
  // (src/classic/gl) uses it for an entry point soft does not implement: GL_INVALID_OPERATION.
  void record_error(GLenum e) { error(e); }

  // Not GL: a sink that draws instead of the vertex stage and rasterizer while rendering
  // (draw_sink.h; the GLSL backend's), and the state it reads (draw_sink.cpp).
  void set_draw_sink(DrawSink* s) { sink_ = s, store_corners_ = false; }
  SinkState sink_state();

  // Not GL: what the checker and tests read.
  lighting::Key key() const;
  const lighting::LightParams& light(int i) const { return lights_[i]; }
  const lighting::MaterialParams& material(int face) const { return materials_[face]; }
  // Places where Mesa 22.3 is known to depart from the spec, met while drawing (the checker reports
  // them instead of calling their differences passes or failures).
  const std::set<std::string>& deviations() const { return deviations_; }

 private:
  void error(GLenum e) {
    if (error_ == GL_NO_ERROR) error_ = e;
  }
  bool outside_begin_end();
  bool query_allowed();  // a query's check (outside_begin_end_keeping_vertices)
  bool outside_begin_end_or_compiling();  // outside_begin_end, but taken while a list compiles
  bool outside_exec_primitive();  // outside_begin_end, and refused where a list left Mesa inside (exec_inside_)
  bool outside_begin_end_keeping_vertices();  // records INVALID_OPERATION inside glBegin/glEnd, flushes nothing  // records INVALID_OPERATION inside glBegin/glEnd
  void set_enabled(GLenum cap, bool on);
  void set_client_state(GLenum array, bool on);
  bool* capability(GLenum cap);
  int enabled_state(GLenum cap);  // 1 or 0 for a capability or client array GL knows; -1 otherwise
  // glGet's list: the values and their count (0 after an error), and how glGetIntegerv converts them.
  enum { kRound, kFromFloat, kFromDouble };
  int get_values(GLenum pname, GLdouble* out, int& normalized);
  // The rest of the list (get_table.cpp): state not modelled, at Mesa's defaults; 0 for a name
  // it does not know (no error recorded).
  int get_table_values(GLenum pname, GLdouble* out, int& normalized);
  int fog_values(GLenum pname, GLdouble* out, int& normalized);
  int list_values(GLenum pname, GLdouble* out);  // display_list.cpp; 0 otherwise
  int select_values(GLenum pname, GLdouble* out);  // selection.cpp; 0 otherwise
  int attribute_values(GLenum pname, GLdouble* out);  // attributes.cpp; 0 otherwise
  void fetch_texcoord(GLint i);
  bool name_stack_call();
  void select_put(GLuint v);
  void select_hit(double window_z);
  void write_hit();
  GLint leave_select();  // glRenderMode's result on leaving GL_SELECT  // fog.cpp: fog and polygon offset; 0 otherwise
  std::vector<glm::dmat4>& stack();
  // The modelview as this context's precision keeps it: lights, normals and glGet read this one.
  glm::dmat4 modelview() const;
  glm::dmat4 projection() const;
  glm::dmat4 texture() const;
  glm::dvec3 direction_to_eye(const double* v);
  glm::dvec4 to_eye(const double* v, double w) const;
  std::vector<fmat::Matrix>& stack_f();
  // What Mesa's state validation does to the matrices (draws, glRasterPos, glReadPixels,
  // glDrawPixels): the modelview and texture matrices analysed, the float MVP recomputed.
  void validate_matrices();
  void set_light(int i, GLenum pname, const double* v);
  bool set_material(GLenum face, GLenum pname, const double* v);  // false: error recorded
  void fetch_vertex(GLint i, Fixed f);  // from the enabled client arrays, as glArrayElement
  // Integer normals and colours: as Mesa's draws and its glArrayElement convert them, or GL 2.1's rule.
  Fixed draw_fixed() const { return spec_ ? Fixed::Gl21 : Fixed::Gl42; }
  Fixed element_fixed() const { return spec_ ? Fixed::Gl21 : Fixed::MesaCall; }
  // The vertex stage (vertex_stage.cpp): a vertex kept for its batch (its place in verts_ taken
  // now, lit by light_pending) or for the triangle list.
  void process_vertex(const glm::dvec4& obj);
  // The kept vertices lit into their places in verts_: before anything reads verts_ (assembly,
  // Mesa's vbo wrap) and before anything the stage reads changes (a colour that changes the
  // lighting key, a material inside glBegin/glEnd, spec mode's colour material).
  void light_pending();
  glm::dvec4 mesa_raster_color(const float obj[4]);  // raster_pos.cpp
  void raster_pos_spec(double x, double y, double z, double w);
  void set_raster_pos(double x, double y, double z, double w);  // glRasterPos but for selection
  void leave_triangle_list();  // the vertices kept for glEnd's triangle list: lit now, one by one
  void update_vertex_constants();  // lighting constants and the normal matrix, before vertex()
  raster::Vertex vertex(const glm::dvec4& obj, const glm::dvec3& normal, const glm::dvec4& color,
                        bool* zero_normal) const;  // one vertex through the stage
  VertexIn array_vertex(GLint i) const;
  bool float_arrays() const;  // every array array_vertex reads holds GL_FLOAT
  template <class Batches>
  void run_stage(GLint first, GLint count, const Batches& batches);
  void arrays_to_vertices(GLint first, GLint count);  // the general path's large draws, into verts_
  template <typename T>
  friend class VertexStage;
  bool fits_in_memory(uint64_t vertices);  // false: GL_OUT_OF_MEMORY recorded
  bool arrays_readable();                  // false: GL_INVALID_OPERATION recorded
  // The triangle-list path (glDrawArrays / glDrawElements with GL_TRIANGLES, rendering, float):
  // array elements [first, first + count) lit into list_vertices_, then drawn from shared vertices.
  bool triangle_list_path(GLenum mode) const;
  // Vertices fetch(first + o), o in [0, count), lit and mapped into list_vertices_[at + o]
  // (list_vertices_ holds at + count after it); from_arrays: fetch is array_vertex.
  template <class Fetch>
  void stage_to_list(const Fetch& fetch, GLint first, GLint count, bool from_arrays, size_t at = 0);
  // One thread's part of it: vertices [lo, hi) of the same numbering; `zero` set by a zero normal.
  template <class Fetch>
  void stage_list_part(const Fetch& fetch, GLint first, GLint lo, GLint hi, bool from_arrays, size_t at,
                       const raster::State& rs, bool* zero);
  void arrays_to_list(GLint first, GLint count);  // array elements [first, first + count)
  void immediate_to_list();                       // immediate mode's vertices kept for the list
  void draw_triangle_list(const uint32_t* indices, size_t triangles);
  raster::State raster_state() const;
  pool::Workers& workers();
  void prepare_lighting();
  // Colour material as Mesa tracks it (light.cpp).
  void update_color_material();
  void copy_pending();
  void flush_current();
  void flush_stored();
  void flush_stored_keeping_format(bool begin = false);
  void flush_vertices();  // Mesa's FLUSH_VERTICES: a flush of stored vertices when one is asked for
  // Mesa's setters compare first and run FLUSH_VERTICES only when the call changes the state
  // (docs/fidelity.md): `changes` flushes when `differs`, `assign` sets a value that differs.
  bool changes(bool differs) { return differs && (flush_vertices(), true); }
  template <class T> void assign(T& field, const T& value) {
    if (changes(!(field == value))) field = value;
  }
  void stray_vertex();
  void begin_draw();
  void feedback_offset(const raster::WindowVertex* const* v, const raster::State& rs, float* z) const;
  void feedback_primitive(GLenum kind, const raster::WindowVertex* w, size_t count, bool clipped,
                          const raster::State& rs, bool offset_stage);
  template <class Draw>
  void with_positions(Draw draw);  // the vertex array, or Mesa's stand-in (no std::function: no allocation)
  void draw_arrays(GLenum mode, GLint first, GLsizei count);
  void draw_elements(GLenum mode, GLsizei count, GLenum type, const void* indices);
  void set_color_varies(bool v);
  void vbo_wrap(bool alpha_one);
  void position_size(int size);  // immediate.cpp: a position's components join Mesa's vbo format  // immediate.cpp: an attribute joins Mesa's vbo format mid-primitive
  bool cm_per_vertex() const { return color_material_ && (spec_ || color_varies_); }
  void flush_primitive();  // primitive.cpp, through its Assembly
  friend class Assembly;

  DrawSink* sink_ = nullptr;  // draw_sink.cpp: the hand-over to a sink
  std::vector<SinkVertex> sink_verts_;
  bool sink_draws() const { return sink_ && render_mode_ == GL_RENDER; }
  void sink_vertex(const glm::dvec4& obj);
  void sink_end();
  std::vector<SinkMaterial> sink_materials_;  // per vertex, once glMaterial changed inside glBegin
  bool sink_material_varies_ = false;
  SinkMaterial sink_material() const;
  void sink_material_changes();  // glMaterial inside glBegin/glEnd (draw_sink.cpp)
  void sink_fetch(GLint first, GLsizei count);  // array elements into sink_verts_
  void sink_arrays(GLenum mode, GLint first, GLsizei count);
  void sink_elements(GLenum mode, GLsizei count, GLenum type, const void* indices);
  void sink_read_back();  // the sink's picture into fb_, before soft reads or writes it
  // glDrawPixels and glBitmap while a sink draws: the sink's picture into fb_ for the call's
  // life, and back to the sink after it (draw_sink.cpp).
  class SinkPixels {
   public:
    explicit SinkPixels(Context& c);
    ~SinkPixels();

   private:
    Context& c_;
    bool on_;
  };
  raster::Framebuffer fb_;
  // glClear waits here until something draws or reads: a triangle list clears band by band, on
  // the threads that draw the bands; anything else calls flush_clear() first.
  raster::ClearRequest pending_clear_;
  void flush_clear();
  Precision precision_;
  bool spec_ = false;
  GLenum error_ = GL_NO_ERROR;

  // Enables
  bool lighting_ = false, normalize_ = false, rescale_normal_ = false, color_material_ = false;
  bool depth_test_ = false, cull_face_ = false;
  bool fog_ = false, offset_fill_ = false;
  // Capabilities and client arrays GL knows that the pipeline does not model, by name; missing
  // ones have their default (enable.cpp's table).
  std::map<GLenum, bool> other_enables_;
  GLenum shade_model_ = GL_SMOOTH, front_face_ = GL_CCW, cull_mode_ = GL_BACK, depth_func_ = GL_LESS;
  GLenum cm_face_ = GL_FRONT_AND_BACK, cm_mode_ = GL_AMBIENT_AND_DIFFUSE;
  lighting::LightParams lights_[8];
  lighting::MaterialParams materials_[2];
  glm::dvec3 color_indexes_[2] = {{0, 1, 1}, {0, 1, 1}};  // GL_COLOR_INDEXES: stored and reported only
  lighting::ModelParams model_;
  float line_width_ = 1;
  float point_size_ = 1;
  // Fog and polygon offset (fog.cpp), with GL 2.1's defaults (table 6.9, 6.14). The colour is kept
  // clamped to [0, 1], as Mesa keeps and reports it for a fixed-point colour buffer.
  GLenum fog_mode_ = GL_EXP, fog_coord_src_ = GL_FRAGMENT_DEPTH;
  float fog_density_ = 1, fog_start_ = 0, fog_end_ = 1, fog_index_ = 0;
  glm::vec4 fog_color_{0, 0, 0, 0};
  float offset_factor_ = 0, offset_units_ = 0;
  // glPolygonMode: how front- and back-facing polygons are drawn (polygon_mode.cpp, primitive.cpp).
  GLenum polygon_mode_[2] = {GL_FILL, GL_FILL};
  bool unfilled() const { return polygon_mode_[0] != GL_FILL || polygon_mode_[1] != GL_FILL; }
  void fog_raster_state(raster::State& rs) const;

  // Transform
  GLenum matrix_mode_ = GL_MODELVIEW;
  std::vector<glm::dmat4> modelview_{glm::dmat4(1)}, projection_{glm::dmat4(1)};
  // The same stacks in float, computed as Mesa computes them (see float_matrix.h).
  // Each entry keeps Mesa's flags, type and inverse beside its values (fmat::Matrix).
  std::vector<fmat::Matrix> modelview_f_{fmat::Matrix()}, projection_f_{fmat::Matrix()};
  glm::mat4 mvp_f_{1.0f};  // projection x modelview in float, refreshed as each primitive begins
  static constexpr GLint kMaxViewport = 16384;  // GL_MAX_VIEWPORT_DIMS, as llvmpipe's
  static constexpr size_t kMaxStackDepth = 32;  // Mesa's, for the modelview and projection stacks
  static constexpr size_t kMaxTextureStackDepth = 10;
  std::vector<glm::dmat4> texture_{glm::dmat4(1)};
  std::vector<fmat::Matrix> texture_f_{fmat::Matrix()};
  glm::ivec4 viewport_;
  glm::dvec2 depth_range_{0, 1};
  glm::vec4 clear_color_{0, 0, 0, 0};
  double clear_depth_ = 1;

  // Current values and arrays
  glm::dvec3 normal_{0, 0, 1};
  glm::dvec4 color_{1, 1, 1, 1};
  glm::dvec4 flushed_color_{1, 1, 1, 1};  // the colour as last copied to the state (Mesa's ctx->Current)
  // Mesa's ctx->Current normal and colour: normal_ and color_ are its vbo's values, copied there at
  // FLUSH_CURRENT, at a flush of stored vertices and at a glBegin whose vbo format holds attributes
  // and no position, never at glEnd (copy_pending, flush_stored_keeping_format). Read only where a
  // GL_COMPILE_AND_EXECUTE list leaves Mesa inside a glBegin (display_list.cpp, Context::hold_back).
  glm::dvec3 mesa_normal_{0, 0, 1};
  glm::dvec4 mesa_color_{1, 1, 1, 1};
  // Mesa's ctx->Light.Material, kept as mesa_normal_ is: its vbo's material values and the colour
  // material tracking reach it only where the current values are copied (copy_pending), and
  // glEnable(GL_COLOR_MATERIAL), glColorMaterial and glPopAttrib write it directly. glGetMaterial
  // reads it while a list's wrap leaves Mesa's executing side inside the glBegin (ListState::shown).
  lighting::MaterialParams mesa_materials_[2];
  void note_materials_flushed() { mesa_materials_[0] = materials_[0], mesa_materials_[1] = materials_[1]; }
  bool color_varies_ = false;             // this draw's colour comes per vertex
  int color_size_ = 0, color_active_ = 0;  // Mesa's vbo colour attribute: its size and active size
  bool normal_in_format_ = false;          // Mesa's vbo format holds the normal
  bool vertices_kept_ = false;  // Mesa's NeedFlush asks for a flush of stored vertices (a glEnd that stored some, or a FLUSH_CURRENT)
  // The open primitive's vertices that Mesa's last wrap drew and dropped (vbo_wrap): the rest is
  // what its glEnd finds stored.
  size_t wrap_start_ = 0;
  bool format_has_position_ = false;      // Mesa's vbo format holds the position (a glVertex since its reset)
  int position_size_ = 0;                 // and its size then (position_size)
  // glDrawArrays and glDrawElements leave the current normal and colour as they were (Mesa; GL 2.1
  // section 2.8 leaves them indeterminate), though the elements go through glArrayElement's path.
  struct CurrentValues {
    glm::dvec3 normal;
    glm::dvec4 color;
    glm::vec4 texcoord;
  };
  CurrentValues current_values() const { return {normal_, color_, texcoord_}; }
  CurrentValues node_values_{{0, 0, 1}, {1, 1, 1, 1}, {0, 0, 0, 1}};  // before a list's vertex list ran
  // With them, the materials and the colour colour material last tracked (a compiled draw's colours
  // are tracked in soft as it replays them; Mesa's vertex list of the draw copies nothing).
  lighting::MaterialParams node_materials_[2];
  glm::dvec4 node_flushed_color_{1, 1, 1, 1};
  void keep_node_values() {
    node_values_ = current_values();
    node_materials_[0] = materials_[0], node_materials_[1] = materials_[1], node_flushed_color_ = flushed_color_;
  }
  void restore(const CurrentValues& v) {  // and the vbo format is empty after a draw, as at its start
    normal_ = v.normal, color_ = v.color, texcoord_ = v.texcoord;
    color_size_ = color_active_ = 0, normal_in_format_ = false, material_attrs_ = 0;
  }
  struct PendingMaterial {
    glm::dvec4* dst;
    glm::dvec4 value;
  };
  std::vector<PendingMaterial> pending_materials_;  // glMaterial values copied again at each flush
  bool material_in_format_ = false;  // a glMaterial outside glBegin since the format's reset, shininess too (mesa_materials_)
  uint32_t material_attrs_ = 0;      // the material parameters in Mesa's vbo format, 8 bits a face (set_material)
  ClientArray vertex_array_{false, 4, GL_FLOAT, 0, nullptr}, normal_array_{false, 3, GL_FLOAT, 0, nullptr},
      color_array_{false, 4, GL_FLOAT, 0, nullptr};

  // Lighting constants, rebuilt lazily
  bool constants_dirty_ = true;
  lighting::Prepared<float> prepared_f_;
  lighting::Prepared<double> prepared_d_;
  lighting::Kernel<float> kernel_f_ = nullptr;
  lighting::Kernel<double> kernel_d_ = nullptr;
  glm::dmat4 normal_matrix_of_{0.0};  // the modelview normal_matrix_ was computed for
  glm::dmat3 normal_matrix_{1.0};

  // The primitive being assembled
  GLenum prim_mode_ = 0;
  bool in_begin_ = false;
  // Mesa's CurrentExecPrimitive left set by a list's vertex list without its glBegin/glEnd dispatch
  // (display_list.cpp, Context::node_ends): soft is outside glBegin/glEnd, and only the calls that
  // test CurrentExecPrimitive themselves see a primitive (outside_exec_primitive); glEnd ends it.
  bool exec_inside_ = false;
  bool color_in_begin_format_ = false;  // Mesa stores the colour with each vertex of this glBegin (Begin)
  // What glGet reads meanwhile: Mesa's flushes return at once while CurrentExecPrimitive is set, so
  // a glNormal, glColor or glMaterial then waits in its vbo until glEnd ends the primitive; these
  // are the values of the moment it was set (Context::node_ends).
  CurrentValues inside_values_{{0, 0, 1}, {1, 1, 1, 1}, {0, 0, 0, 1}};
  lighting::MaterialParams inside_materials_[2];
  // A list's vertex list whose glBegin that refused: Mesa skips it whole (Context::Begin, node_ends).
  bool refused_node_ = false;
  std::vector<raster::Vertex> verts_;
  // The batch process_vertex keeps: the last pending_slot_.size() entries of verts_ wait for
  // their colours; slot k takes pending_in_[pending_slot_[k]] (identical consecutive vertices
  // share one entry, lit once).
  std::vector<VertexIn> pending_in_;
  std::vector<uint32_t> pending_slot_;
  std::vector<uint32_t> elements_;            // glDrawElements: indices into verts_
  std::vector<raster::Triangle> triangles_;   // set up, waiting for the rasterizer
  std::vector<std::vector<raster::Triangle>> tri_parts_;  // the other threads' shares of a draw
  std::vector<unsigned> outside_;             // per vertex: the view-volume planes it is outside
  std::vector<raster::WindowVertex> window_;  // per vertex inside: its window position
  int threads_ = 2;
  std::unique_ptr<pool::Workers> workers_;  // started on the first draw that uses them
  // The triangle-list path: GL_TRIANGLES while rendering in float, lit in batches into compact
  // records the rasterizer reads in place (raster/triangle_list.h's ListVertices).
  raster::ListVertices list_vertices_;
  bool triangle_lists_ = true;
  bool immediate_list_ = false;  // glBegin(GL_TRIANGLES) on the list: vertices kept as sent, lit at glEnd
  bool store_corners_ = false;    // immediate_list_, not spec, no sink: store_normal/store_vertex apply
  // One entry per distinct vertex sent (position, and the normal and colour where the lighting
  // reads them); list_corner_ names each glVertex's entry, the triangles' indices. A vertex equal
  // to a recent one (found in corner_slots_) is that entry again: lit once (immediate.cpp).
  std::vector<glm::vec4> list_pos_;
  std::vector<glm::dvec3> list_normal_;
  std::vector<glm::dvec4> list_color_;
  std::vector<uint32_t> list_corner_;
  // A direct-mapped cache of recent entries by a hash of position and normal. Each slot holds the
  // key's bits beside the entry, so a repeat is found reading the slot alone (list_pos_ and
  // list_normal_ outgrow the caches); a slot of an older glBegin has another generation.
  struct alignas(64) CornerSlot {
    uint64_t pos[2], normal[3];
    uint32_t entry, generation;
  };
  // A slot a cache line (48 bytes of it used): one that straddled two lines waited on both, which
  // made immediate-mode frames 1-3 % slower at depths 5 and 7. 256 KiB (in L2): at depth 7 the
  // icosphere's 983,040 corners make 178,500 entries for its 163,842 vertices, against 202,289
  // with 512 slots (in L1), and each entry saved is a lookup missed and a vertex lit; frames 3-4 %
  // faster at depths 5 and 7 (docs/performance.md).
  static constexpr int kCornerSlotBits = 12;
  std::array<CornerSlot, size_t(1) << kCornerSlotBits> corner_slots_{};
  uint32_t corner_generation_ = 0;
  void keep_list_vertex(float x, float y, float z, float w);
  // The hash keep_list_vertex files a corner under: positions as float bits, the normal's doubles.
  static uint64_t corner_hash(const uint64_t (&p)[2], const uint64_t (&n)[3]) {
    // Independent products summed (a chain of multiplies would wait on each other): the top bits
    // depend on every bit. The normal is hashed even where it is not compared: only the slot
    // chosen depends on it.
    return p[0] * 0x9E3779B97F4A7C15ull + p[1] * 0xC2B2AE3D27D4EB4Full + (n[0] ^ n[1] ^ n[2]) * 0x165667B19E3779F9ull;
  }
  static uint64_t float_bits(float lo, float hi) {  // from registers: the floats never pass through memory
    uint32_t a, b;
    std::memcpy(&a, &lo, sizeof a);
    std::memcpy(&b, &hi, sizeof b);
    return a | uint64_t(b) << 32;
  }
  static uint64_t double_bits(double d) {
    uint64_t u;
    std::memcpy(&u, &d, sizeof u);
    return u;
  }
  // keep_list_vertex's commonest case inline in glVertex: lit without colour material, a repeat
  // of the corner its slot holds, and room in list_corner_ (the early job may be reading it). False:
  // nothing done, keep_list_vertex decides.
  bool kept_repeat(float x, float y, float z, float w) {
    if (!lighting_ || color_material_) return false;
    const uint64_t p[2] = {float_bits(x, y), float_bits(z, w)};
    const uint64_t n[3] = {double_bits(normal_.x), double_bits(normal_.y), double_bits(normal_.z)};
    const CornerSlot& s = corner_slots_[corner_hash(p, n) >> (64 - kCornerSlotBits)];
    const bool same = (s.generation == corner_generation_) & (s.pos[0] == p[0]) & (s.pos[1] == p[1]) &
                      (s.normal[0] == n[0]) & (s.normal[1] == n[1]) & (s.normal[2] == n[2]);
    if (!same || list_corner_.size() == list_corner_.capacity()) return false;
    list_corner_.push_back(s.entry);
    return true;
  }
  // Early draws: inside a long glBegin(GL_TRIANGLES) on the triangle list the complete triangles
  // are lit and drawn on a worker thread (pool::Workers::post) while the application sends the next corners; glEnd lights
  // and draws the rest on the workers, after them, so every pixel sees the triangles in order.
  // While a job is in flight the application's thread changes nothing it reads: the entries and
  // corners it reads are complete and never rewritten (a wrap rewrites only the unfinished
  // triangle's corners), the lists do not grow past their capacity (early_join first), and every
  // call that could change the lighting's constants or the matrices joins first (vbo_wrap,
  // leave_triangle_list, validate_matrices, End). Only where the lighting's constants stay those
  // of glEnd: not for colour material before a glColor inside the glBegin (cm_per_vertex()
  // would change with it).
  static constexpr size_t kEarlyCorners = 3072;
  size_t early_corners_ = kEarlyCorners;
  struct EarlyDraw {  // the application's thread's own
    size_t next = SIZE_MAX;  // list_corner_.size() at which to try a handoff
    size_t lit = 0;          // entries lit and mapped into list_vertices_ (or by the job in flight)
    size_t drawn = 0;        // triangles drawn (or by the job in flight)
    bool in_flight = false;  // a job posted and not yet joined
    size_t stops = 0;        // early_stops()
  } early_;
  // The job: written by early_handoff before it posts, read by the job only (entries [first, lit)
  // and triangles [tri_first, drawn), through pointers that stay valid while it runs); what it
  // found is read after the join. It draws its triangles kEarlyChunk at a time and stops after
  // the chunk it is in when `stop` is set (early_wait): `reached` says how far it got, and the
  // caller draws the rest, so a join waits for a chunk rather than for the whole job.
  static constexpr size_t kEarlyChunk = 512;
  size_t early_chunk_ = kEarlyChunk;
  struct EarlyJob {
    size_t first = 0, lit = 0, tri_first = 0, drawn = 0, chunk = kEarlyChunk;
    size_t reached = 0;  // triangles drawn, [tri_first, reached): written by the job
    std::atomic<bool> stop{false};
    const glm::vec4* pos = nullptr;
    const glm::dvec3* normal = nullptr;  // null: cur_normal for every entry
    const glm::dvec4* color = nullptr;   // null: cur_color
    const uint32_t* corners = nullptr;
    glm::dvec3 cur_normal{0};
    glm::dvec4 cur_color{0};
    raster::State rs;
    raster::ClearRequest clear;
    bool zero_normal = false, sliver = false;
  } early_job_;
  // Whether corners drawn early lay after the last wrap (End's "stored"), once leave_triangle_list
  // has dropped them from the primitive.
  bool early_after_wrap_ = false;
  pool::Workers early_workers_{1};  // the job's draw: one share, on its own thread
  raster::TriangleBins early_bins_;
  size_t bins_reserved_ = 0;  // triangles bins_ and early_bins_ have room for
  void early_handoff();
  void early_job();
  void early_join() {
    if (early_.in_flight) early_wait();
  }
  void early_wait();
  // glDrawArrays(GL_TRIANGLES) of a soup (soup.cpp): its repeated corners lit once, drawn from
  // indices. False: not taken (small, or arrays the stage does not read as floats).
  bool draw_soup(GLint first, GLsizei count);
  std::vector<uint64_t> soup_slots_;  // a cache per share (state/soup.cpp lays out its slots)
  uint32_t soup_generation_ = 0;
  std::vector<uint32_t> soup_index_;                // per corner: its distinct corner
  std::vector<float> soup_staged_, soup_compact_;  // the distinct corners, per share and laid out
  // Defined here, constant: a thread_local defined elsewhere is read through a wrapper call.
  // Initial-exec, as the classic libGL's table (src/classic/gl/table.h): in that shared library
  // the default model calls __tls_get_addr on every read.
  static inline thread_local Context* current_ __attribute__((tls_model("initial-exec"))) = nullptr;
  raster::TriangleBins bins_;

  // The current raster position (glRasterPos): window position and clip w, its colour.
  struct RasterPosition {
    bool valid = true;
    glm::dvec4 window{0, 0, 0, 1};
    glm::dvec4 color{1, 1, 1, 1};
    double distance = 0;  // from the eye
  } raster_pos_;

  // Feedback
  GLenum render_mode_ = GL_RENDER;
  GLfloat* feedback_ = nullptr;
  GLsizei feedback_size_ = 0, feedback_count_ = 0;
  GLenum feedback_type_ = GL_2D;
  bool feedback_overflow_ = false;
  void feedback_put(double x);  // the next value, or the overflow noted
  void note_texgen_in_feedback();  // names kTexGen when it changes what feedback would hold
  raster::ClipTemps clip_temps_;  // Mesa's clipper's temporaries, as feedback sees them
  GLint pack_alignment_ = 4, unpack_alignment_ = 4;
  std::map<GLenum, GLint> pixel_store_;  // the other glPixelStorei values, recorded and reported (0 by default)
  std::set<std::string> deviations_;
  ListState lists_;  // display lists (display_list.h)
  SelectState select_;  // selection (selection.h)
  // attributes.cpp: the current texture coordinates and edge flag, the hints set, the array.
  glm::vec4 texcoord_{0, 0, 0, 1};
  bool texcoord_varies_ = false;  // since glBegin or the draw's start: per-vertex texture coordinates
  bool edge_flag_ = true;
  std::map<GLenum, GLenum> hints_;
  ClientArray texcoord_array_{false, 4, GL_FLOAT, 0, nullptr};

  // --- Per-fragment operations, glBitmap and the attribute stacks (the fragment helper's block) ---
  // fragment.cpp: scissor, alpha test, blending, the write masks and what raster::State gets of
  // them; bitmap.cpp: glBitmap; attrib.cpp: glPushAttrib / glPopAttrib and the client's.
 public:
  void AlphaFunc(GLenum func, GLfloat ref);
  void BlendFuncSeparate(GLenum src_rgb, GLenum dst_rgb, GLenum src_alpha, GLenum dst_alpha);
  void BlendEquationSeparate(GLenum rgb, GLenum alpha);
  void BlendColor(float r, float g, float b, float a);
  void ColorMask(bool r, bool g, bool b, bool a);
  void DepthMask(bool on);
  void Scissor(GLint x, GLint y, GLsizei w, GLsizei h);
  void LineStipple(GLint factor, GLushort pattern);
  // packed: rows of whole bytes, most significant bit first, as pack_bitmap makes them (a display
  // list's copy), whatever the GL_UNPACK_* state; otherwise unpacked by that state.
  void Bitmap(GLsizei w, GLsizei h, float xorig, float yorig, float xmove, float ymove, const GLubyte* bits,
              bool packed = false);
  std::vector<GLubyte> pack_bitmap(GLsizei w, GLsizei h, const GLubyte* bits) const;

 private:
  struct PixelRows {  // raster_pos.cpp: where glDrawPixels finds its pixels
    size_t row = 0, pixel = 0, skip = 0;  // bytes a row, a pixel, before the first
  };
  bool pixel_rows(GLsizei w, GLenum format, GLenum type, bool packed, PixelRows& out) const;
  struct BitmapLayout {  // bitmap.cpp
    size_t row, skip_rows, skip_bits;
    bool lsb_first;
    bool bit(const GLubyte* bits, GLsizei i, GLsizei j) const;  // bit i of row j
  };
  BitmapLayout bitmap_layout(GLsizei w, bool packed) const;

 public:
  void PushAttrib(GLbitfield mask);
  void PopAttrib();
  void PushClientAttrib(GLbitfield mask);
  void PopClientAttrib();

 private:
  FragmentState frag_;
  mutable int stipple_counter_ = 0;  // the line stipple's position, run on along a strip (raster.h)
  mutable raster::Counters counters_;  // every raster::State of this context counts here (raster_state)
  bool* fragment_capability(GLenum cap);  // GL_SCISSOR_TEST, GL_ALPHA_TEST, GL_BLEND, GL_LINE_STIPPLE; else null
  int fragment_values(GLenum pname, GLdouble* out, int& normalized);  // 0 for a name not its own
  void fragment_raster_state(raster::State& rs) const;
  bool fragment_ops_default() const;  // none of frag_'s operations changes a fragment: fast paths allowed
  bool clear_with_fragment_ops(GLbitfield mask);  // glClear now, under masks and scissor; false: none apply
  glm::ivec4 scissor_box() const;
  struct AttribEntry;  // attrib.cpp
  struct ClientAttribEntry;
  std::vector<std::shared_ptr<AttribEntry>> attrib_stack_;
  std::vector<std::shared_ptr<ClientAttribEntry>> client_attrib_stack_;
  static constexpr size_t kMaxAttribStackDepth = 16;  // Mesa's MAX_ATTRIB_STACK_DEPTH and client's
  // Mesa's bitmap cache (st_cb_bitmap.c): consecutive glBitmaps of one colour and depth are ORed
  // into one 512 x 32 bitmap drawn once, so a pixel two glyphs share is one fragment (bitmap.cpp).
  struct BitmapRun {
    bool active = false;
    uint64_t writes = 0;  // the framebuffer's count when the run last drew
    glm::dvec4 color{0};
    double z = 0;
    raster::State::Ops ops;
    bool depth_test = false;
    GLenum depth_func = GL_LESS;
    int xpos = 0, ypos = 0;      // the cache's lower-left corner in the window
    std::vector<uint8_t> drawn;  // 512 x 32: set where the run has made a fragment
  } bitmap_run_;
  uint8_t* bitmap_cache(int x0, int y0, int w, int h, const raster::State& rs);
  void feedback_raster_position(GLenum token);  // GL_BITMAP_TOKEN or GL_DRAW_PIXEL_TOKEN and the position
};

}  // namespace ffc::state
