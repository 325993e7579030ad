// Display lists (GL 2.1 section 5.4): a list is a compact byte vector of recorded commands, each
// the address of a replay function followed by its arguments, packed by value.
//
// How an entry point becomes listable (the one rule): in src/state/soft_gl*.cpp, make the first
// statement of the C entry point (LISTABLE_VERTEX instead for a call of the vertex stream, which
// GL_COMPILE_AND_EXECUTE holds back: soft_gl_entries.h)
//
//     void APIENTRY Foo(GLenum a, GLfloat b) { LISTABLE(Foo, a, b); FWD(Foo(a, b)); }
//
// LISTABLE records `Foo` with its arguments while a list is being compiled (and returns at once in
// GL_COMPILE); replaying the list calls Foo(a, b) again, which then executes. The arguments must
// be plain values: an entry point that takes a pointer copies what it points to first and records
// a by-value twin (Color3fv calls Color3f; glMaterialfv records a Floats<4>). An entry point without
// LISTABLE executes immediately even while compiling, which is what section 5.4 says of the
// commands that are not compiled (glGenLists, glFeedbackBuffer, glRenderMode, glGet*, glFinish,
// client state, array pointers, glReadPixels, glPixelStore ...).
#pragma once
#include <GL/gl.h>

#include <cstring>
#include <glm/glm.hpp>
#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <tuple>
#include <type_traits>
#include <vector>

namespace ffc::state {

// Row 55 (docs/deviations.md): named, not modelled.
inline constexpr const char* kListStripWrap =
    "a display list's triangle strip whose vertex format grows (a glNormal, glColor ... first appearing) after an "
    "odd number of its vertices: Mesa's list wraps the strip and draws other triangles around the wrap "
    "(GL_COMPILE and GL_COMPILE_AND_EXECUTE alike); soft draws the strip as sent";

// Row 65 (docs/deviations.md): named, not modelled.
inline constexpr const char* kListLineLoopCurrent =
    "a display list's GL_LINE_LOOP whose vertex format grows after its first vertex: when the list runs, Mesa "
    "sets the current colour and normal (and a tracked material) to zeros, alpha 1 for a 3-component colour; soft "
    "to the last values sent";

// Row 66 (docs/deviations.md): named, not modelled.
// Row 71 (docs/deviations.md): named, not modelled (Context::note_node_primitive).
inline constexpr const char* kListTwoThenQuadCrash =
    "a display list's vertex list holding a GL_TRIANGLES, GL_TRIANGLE_FAN or GL_POLYGON of two vertices (sent, or "
    "the two a wrapped polygon copies) followed by a GL_QUADS of one vertex: Mesa 22.3 corrupts its heap compiling "
    "it (glibc aborts at that flush, a later call or the read-back); soft compiles it";

// Row 70 (docs/deviations.md): named, not modelled (Context::call_one_list).
inline constexpr const char* kListPaddedQuadDrawn =
    "a display list holding a GL_QUADS or GL_QUAD_STRIP of three vertices (a glBegin/glEnd or a compiled draw), "
    "called in GL_RENDER: Mesa's list playback pads the quad with its last vertex and draws the triangle of the "
    "three; soft draws nothing of it (GL: an incomplete quad is ignored)";

inline constexpr const char* kListIncompleteFedBack =
    "a display list holding a primitive with fewer vertices than its mode draws (a glBegin/glEnd or a compiled "
    "draw), called in GL_FEEDBACK or GL_SELECT: Mesa's list playback feeds back a primitive padded with its last "
    "vertex, reads vertices it never stored, or crashes in glCallList; soft draws nothing of it";

// Row 66 (docs/deviations.md), in GL_RENDER: named, not modelled.
inline constexpr const char* kListIncompleteUnfilled =
    "a display list holding a triangle too short to draw (a strip or GL_TRIANGLES of two vertices), called "
    "under glPolygonMode GL_LINE or GL_POINT: Mesa's list playback pads it with its last vertex and its unfilled "
    "stage draws the padded triangle's edges; soft draws nothing of it";

// Row 72 (docs/deviations.md): named, not modelled (Context::note_node_mode).
inline constexpr const char* kListModesFedBackFirst =
    "a display list's vertex list whose primitives (glBegin/glEnd or compiled draws, no state call between them) "
    "have more than one mode, called in GL_FEEDBACK or GL_SELECT: Mesa's list playback feeds back (or hits) only "
    "the primitives of its first mode, and crashes in glCallList where the mode changes twice; soft feeds back "
    "them all";

// Row 72 (docs/deviations.md), its crash: named, not modelled (Context::close_node_modes).
inline constexpr const char* kListModesCrash =
    "a display list's vertex list whose draws, after Mesa's merging, change mode after the second draw (GL_LINE_LOOP, "
    "GL_LINE_LOOP, GL_TRIANGLE_STRIP; GL_POINTS, GL_QUADS, GL_LINES), called in GL_FEEDBACK or GL_SELECT: Mesa 22.3 "
    "segfaults in glCallList; soft feeds back every primitive";

// Row 67 (docs/deviations.md): named, not modelled.
inline constexpr const char* kListLoopbackDeduplicated =
    "a display list replayed through immediate mode (a glBegin left open at glEndList, a wrap copying vertices "
    "while an attribute joins) holding a vertex list compiled before that with a vertex repeated: Mesa kept only "
    "its distinct vertices and replays the vertices by their first positions, so later ones are others or never "
    "sent (drawn, fed back, made current); soft replays the vertices sent";

// Row 68 (docs/deviations.md): named, not modelled.
inline constexpr const char* kListEmptyLoopCurrent =
    "a GL_LINE_LOOP last in a display list's vertex list and run through immediate mode, empty (a glBegin/glEnd or "
    "a compiled draw without a vertex; GL_COMPILE_AND_EXECUTE, or a list replayed so) or restarted there by a wrap "
    "(a list replayed so): Mesa closes the loop with a copy of a first vertex it never stored, or reads the copy "
    "past the vertices it kept, and sets the current values (and a tracked material) from that memory; soft "
    "leaves them as they were";

// Row 55 (docs/deviations.md): named, not modelled (Context::note_vertexless_node).
inline constexpr const char* kListVertexlessNode =
    "a display list's vertex list with an attribute in its format and no vertex (a primitive without a vertex, or "
    "an attribute first sent after a primitive's last vertex that wraps the store with nothing to copy, no vertex "
    "following before the flush): when the list is called, Mesa copies the current values from a slot of its "
    "vertex store that vertex list never wrote; soft leaves them as the vertices sent left them";

// Row 55 (docs/deviations.md): named, not modelled (Context::compile_elements).
inline constexpr const char* kListFillEmptyDraw =
    "a GL_COMPILE_AND_EXECUTE list's compiled draw too large for Mesa's vertex store that stores no vertex (no "
    "vertex array): where Mesa's executing side then raises GL_INVALID_OPERATION (at a later such draw, at the "
    "next flush, or nowhere) is not modelled; soft raises it at the next flush where the draw joins the "
    "restarted primitive";

// The fewest vertices a primitive of this mode draws anything with.
inline int fewest_vertices(GLenum mode) {
  switch (mode) {
    case GL_POINTS: return 1;
    case GL_LINES: case GL_LINE_STRIP: case GL_LINE_LOOP: return 2;
    case GL_QUADS: case GL_QUAD_STRIP: return 4;
    default: return 3;
  }
}

// N floats (or doubles) by value: a pointer argument's contents, recorded.
template <int N, typename T = GLfloat>
struct Floats {
  T v[N];
};

// Bytes a list keeps for one of its commands (a glBitmap's bits, unpacked when compiled): recorded
// by address, alive as long as the list.
struct PackedBits {
  const GLubyte* data;
};

class DisplayList {
 public:
  PackedBits keep(std::vector<GLubyte> bytes) {
    kept_.push_back(std::make_shared<std::vector<GLubyte>>(std::move(bytes)));
    return {kept_.back()->empty() ? nullptr : kept_.back()->data()};
  }
  template <auto Fn, typename... A>
  void record(const A&... a) {
    put(&Command<Fn>::replay);
    Command<Fn>::put(*this, a...);
  }
  void replay() const;
  void clear() {
    bytes_.clear(), kept_.clear(), incomplete = false, loopback = false, deduplicated = false, padded_quad = false;
    vertexless = false, mixed_modes = false, modes_crash = false, calls.clear();
  }
  bool incomplete = false;  // holds a primitive too short to draw (kListIncompleteFedBack)
  bool padded_quad = false;  // a GL_QUADS or GL_QUAD_STRIP of three vertices (kListPaddedQuadDrawn)
  // Notes a primitive of `mode` with `vertices` that compiled into the list.
  void note_primitive(GLenum mode, int vertices) {
    padded_quad |= (mode == GL_QUADS || mode == GL_QUAD_STRIP) && vertices == 3;
    if (vertices < fewest_vertices(mode)) incomplete = true;
  }
  // Mesa replays the list's vertex lists through immediate mode (vbo_save's UseLoopback: display_list.cpp,
  // Context::mark_loopback), where a compiled draw's values become current.
  bool loopback = false;
  bool deduplicated = false;  // a vertex list of it lost repeated vertices, compiled before any loopback mark
  bool vertexless = false;  // a vertex list of it has attributes and no vertex (kListVertexlessNode)
  bool mixed_modes = false;  // a vertex list of it draws primitives of two modes (kListModesFedBackFirst)
  bool modes_crash = false;  // ... and changes mode after its second draw (kListModesCrash)
  std::vector<GLuint> calls;  // the names its glCallList and glCallLists compiled (without the list base)
  bool empty() const { return bytes_.empty(); }

 private:
  using Replay = const unsigned char* (*)(const unsigned char*);
  template <typename T>
  void put(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    const size_t at = bytes_.size();
    bytes_.resize(at + sizeof(T));
    std::memcpy(bytes_.data() + at, &v, sizeof(T));
  }
  template <typename T>
  static T take(const unsigned char*& p) {
    T v;
    std::memcpy(&v, p, sizeof(T));
    p += sizeof(T);
    return v;
  }
  template <auto Fn>
  struct Command;
  template <typename R, typename... P, R (*Fn)(P...)>
  struct Command<Fn> {
    template <typename... A>
    static void put(DisplayList& l, const A&... a) {
      (l.put(std::decay_t<P>(a)), ...);
    }
    static const unsigned char* replay(const unsigned char* p) {
      // A braced list takes the arguments in order.
      const std::tuple<std::decay_t<P>...> args{take<std::decay_t<P>>(p)...};
      std::apply(Fn, args);
      return p;
    }
  };
  std::vector<unsigned char> bytes_;
  std::vector<std::shared_ptr<const std::vector<GLubyte>>> kept_;
};

// The lists of a context and the one being compiled (GL 2.1 table 6.39's state).
struct ListState {
  std::map<GLuint, DisplayList> lists;
  DisplayList compiling;
  DisplayList held_back;  // GL_COMPILE_AND_EXECUTE: vertex-stream calls recorded, not yet executed
  bool open = false;       // a glBegin compiled into the list, its glEnd not yet
  GLenum open_mode = 0;    // that glBegin's mode
  int vertices = 0;        // held back since the open glBegin
  int primitive_vertices = 0;  // compiled since the open glBegin (kListIncompleteFedBack)
  // Mesa's list vertex store and format (vbo_save): vertices stored since it last compiled them (a
  // flush or a wrap), whatever primitive they belong to, and the attributes in its format with the
  // sizes of the colour and the position, kept from one primitive to the next until a flush.
  int stored = 0;
  int prims = 0;  // primitives begun in the store since then (a wrap leaves the one it interrupted)
  int node_vertices = 0;  // the vertices of the open vertex list, a wrap's copies included (kListVertexlessNode)
  bool refill_error = false;  // a draw filled the store: the next flush raises an error (compile_elements)
  int attributes = 0;      // bits: normal, colour, texture, edge
  // Vertices of the open primitive a wrap copied into the next vertex list (Mesa's copied.nr), and
  // the attributes compiled outside the list's glBegin since glNewList or a compiled glCallList
  // (Mesa's ListState.ActiveAttribSize): bits as `attributes`.
  int wrap_copies = 0;
  int outside_attributes = 0;
  // The shade model the list last compiled (Mesa's ListState.Current.ShadeModel; 0 after glNewList
  // and a compiled glCallList): an equal glShadeModel is neither compiled nor a flush (soft_gl_entries.h).
  GLenum shade_model = 0;
  bool replaying_loopback = false;  // the list running is replayed through immediate mode (DisplayList::loopback)
  // GL_COMPILE_AND_EXECUTE: the store's last primitive is a GL_LINE_LOOP ended in it, and the values
  // of its first vertex as the held-back calls ran (display_list.cpp, Context::run_held_back).
  bool closing_loop = false;
  bool loop_restarted = false;  // compiling: a wrap restarted the open line loop in the store
  glm::dvec3 loop_first_normal{0, 0, 1};
  glm::dvec4 loop_first_color{1, 1, 1, 1};
  int color_size = 0, position_size = 0;
  GLuint index = 0;  // GL_LIST_INDEX: the list being compiled, 0 when none
  GLenum mode = 0;   // GL_LIST_MODE: GL_COMPILE or GL_COMPILE_AND_EXECUTE; 0 when none
  GLuint base = 0;   // GL_LIST_BASE
  int depth = 0;     // lists being executed, one inside another
  GLuint max_name = 0;  // the largest name the table has held (glGenLists gives out the next)
  // Compiling: a vertex list is open in the list (recorded Context::node_begins), and whether its
  // last primitive begun is a compiled draw (Mesa's no_current_update).
  bool node_open = false;
  bool node_draw = false;
  // The primitive before the open one in the open vertex list: its mode (0: none) and the vertices
  // it has there (kListTwoThenQuadCrash, Context::note_node_primitive).
  GLenum node_last_mode = 0;
  int node_last_count = 0;
  // GL_COMPILE_AND_EXECUTE: a primitive too short to draw is among the calls held back since the last
  // flush (run_held_back: Mesa's executing side feeds it back padded, kListIncompleteFedBack).
  bool held_incomplete = false;
  // The modes of the open vertex list's primitives with a vertex, in order (Context::note_node_mode,
  // close_node_modes).
  std::vector<GLenum> node_modes;
  // Replaying: whether Mesa's immediate mode was inside a primitive when the vertex list began, as the
  // vertex lists before it left it (Context::node_ends).
  bool node_inside = false;
  // Compiling: the vertices of the store since it was last compiled, as Mesa's compiler compares them
  // (the bits of the position, normal and colour as floats), whether one repeats, and whether a vertex
  // list with a repeat was compiled before the list was marked for loopback (kListLoopbackDeduplicated).
  std::set<std::array<uint32_t, 11>> store_vertices;
  bool store_repeats = false, deduplicated = false;
  glm::dvec3 store_normal{0, 0, 1};
  glm::dvec4 store_color{1, 1, 1, 1};
  // A glNormal or glColor a list runs outside its own glBegin/glEnd goes through Mesa's
  // immediate-mode vbo and stays pending there: a later primitive of the list writes its last values
  // to the state, and the next flush (a glGet, a glBegin) copies the pending ones over them
  // (display_list.cpp, Context::end_list_calls).
  bool calling = false;  // inside the outermost glCallList or glCallLists
  int pending = 0;       // bits: normal 1, colour 2
  // Running, Mesa's NeedFlush for them (Context::flush_pending): FLUSH_UPDATE_CURRENT and
  // FLUSH_STORED_VERTICES, and whether a vertex list's copy left Mesa inside glBegin/glEnd (a wrap).
  bool need_update = false, stored_bit = false, mesa_inside = false;
  bool compiling_draw = false;  // a glDrawArrays or glDrawElements being compiled
  glm::dvec3 pending_normal{0, 0, 1};
  glm::dvec4 pending_color{1, 1, 1, 1};
  // A glNormal or glColor after the last vertex of a list's own primitive never becomes current
  // (display_list.cpp, Context::list_trailing): compiling, whether the open primitive had a vertex
  // and which attributes followed its last one; running, the values that vertex took.
  bool had_vertex = false;
  int trailing = 0;  // bits: normal 1, colour 2
  bool held_element = false;  // a glArrayElement is being held back (Context::compile_element)
  glm::dvec3 before_join_normal{0, 0, 1};  // the values before an attribute joined (Context::list_before_joining)
  glm::dvec4 before_join_color{1, 1, 1, 1};
  glm::dvec3 last_vertex_normal{0, 0, 1};
  glm::dvec4 last_vertex_color{1, 1, 1, 1};
  // Mesa's vertex template keeps those trailing values: compiling, the attributes a later vertex of the
  // list before the next flush carries (Context::list_vertex_compiled); running, their values.
  int carry = 0;  // bits: normal 1, colour 2
  glm::dvec3 carried_normal{0, 0, 1};
  glm::dvec4 carried_color{1, 1, 1, 1};
  // GL_COMPILE_AND_EXECUTE: a wrap drew the list's primitive so far, but glGet reads the current
  // values from before it until the rest is flushed (display_list.cpp, Context::hold_back).
  bool shown = false;
  // A glCallList or glCallLists compiled inside the list's glBegin (Context::list_fallback): the rest of
  // that primitive compiles as calls executed at once, outside Mesa's vertex store.
  bool fallback = false;
  // Compiling, for the rest of a wrapped primitive (display_list.cpp, Context::list_loopback): whether
  // the open primitive wrapped, and the attributes in the format at its first vertex.
  bool wrapped = false;
  int first_format = 0;
  glm::dvec3 shown_normal{0, 0, 1};
  glm::dvec4 shown_color{1, 1, 1, 1};
  static constexpr double kStoreBytes = 256 * 1024;  // Mesa's VBO_SAVE_BUFFER_SIZE, as it compares it
  // Mesa's limit on glCallList inside lists being executed (GL_MAX_LIST_NESTING).
  static constexpr int kMaxNesting = 64;
};

}  // namespace ffc::state
