#include "difftest/known.h"

#include <set>

#include "state/context.h"
#include "state/display_list.h"

namespace ffc::difftest {

namespace {

// Whether a call before or at `upto` (the whole stream for -1) matches `pred`.
template <class Pred>
bool any_call(const Stream& s, int upto, Pred pred) {
  const size_t end = upto < 0 ? s.size() : std::min(s.size(), size_t(upto) + 1);
  for (size_t i = 0; i < end; ++i)
    if (pred(s[i], i)) return true;
  return false;
}

bool is(const Call& c, const char* name) { return name_of(c) == name; }
bool starts(const std::string& n, const char* prefix) { return n.rfind(prefix, 0) == 0; }

// The client arrays on, as the glEnableClientState / glDisableClientState calls soft took (ok: no
// error) left them.
struct ArraysOn {
  bool vertex = false, normal = false, color = false;
  void follow(const std::string& n, const Call& c, bool ok) {
    if ((n != "glEnableClientState" && n != "glDisableClientState") || !ok) return;
    const auto a = GLenum(c.args[0].num);
    const bool on = n == "glEnableClientState";
    if (a == GL_VERTEX_ARRAY) vertex = on;
    if (a == GL_NORMAL_ARRAY) normal = on;
    if (a == GL_COLOR_ARRAY) color = on;
  }
};



// The last call that can have caused m: a feedback buffer is written until the next
// glFeedbackBuffer replaces it (-1: the end; one Mesa refused replaces nothing), other kinds show
// at their call.
int reach(const Stream& s, const Mismatch& m, const SideResult& mesa) {
  // A feedback or selection buffer is named by the call that set it, and written until the next.
  const bool selection = m.kind == "output" && m.call >= 0 && is(s[size_t(m.call)], "glSelectBuffer");
  if ((m.kind != "feedback" && !selection) || m.call < 0) return m.call;
  const char* setter = selection ? "glSelectBuffer" : "glFeedbackBuffer";
  for (size_t i = size_t(m.call) + 1; i < s.size(); ++i)
    if (is(s[i], setter) && !(i < mesa.errors.size() && mesa.errors[i] != GL_NO_ERROR)) return int(i) - 1;
  return -1;
}

// Mesa records an error and applies the call anyway: everything after it may differ, but not the
// error of the call itself, which both sides must raise alike.
// `hidden`: also where neither side shows the call's error, a call soft refuses with an error
// whatever the state (a glGetError inside the executing side's glBegin of GL_COMPILE_AND_EXECUTE
// returns none and records GL_INVALID_OPERATION instead: Context::GetError).
bool after_mesa_applied(const Stream& s, const Mismatch& m, const SideResult& mesa,
                        bool (*call_matches)(const Call&), const SideResult* hidden = nullptr) {
  return any_call(s, reach(s, m, mesa), [&](const Call& c, size_t i) {
    if (!call_matches(c) || i >= mesa.errors.size() || (m.kind == "error" && int(i) == m.call)) return false;
    return mesa.errors[i] != GL_NO_ERROR ||
           (hidden && i < hidden->errors.size() && hidden->errors[i] == GL_NO_ERROR);
  });
}

// Whether the glEndList at `end_list` closes a list that compiled a glCallList(s) and also met what
// makes Mesa copy or flush vertices of its list's vertex store: the call itself inside the list's
// open glBegin, a glBegin still open at the glEndList, or a wrap that keeps vertices (an attribute
// first sent after a vertex, with an unfinished primitive: one vertex of a triangle, any of a
// strip, fan, loop or polygon), before or after the call. Measured: each crashes Mesa at the
// glEndList, in both list modes, for any list name (0 and names never defined too); a wrap after a
// whole triangle does not, nor any of them without the glCallList. Which calls took effect is read
// from soft's errors (Mesa's side crashed): a glNewList soft refused opened nothing.
bool call_list_and_wrap(const Stream& s, const SideResult& soft, size_t end_list) {
  bool compiling = false, open = false, called = false, wrapped = false;
  ArraysOn arrays;
  int array_color_size = 4;    // glColorPointer's size
  int vertices = 0, seen = 0;  // in the open primitive: its vertices, the attributes sent (bits)
  int color_size = 0;          // the colour's components in the open primitive (0: none sent)
  GLenum mode = 0;
  for (size_t i = 0; i < end_list && i < s.size(); ++i) {
    const bool ok = i < soft.errors.size() && soft.errors[i] == GL_NO_ERROR;
    const std::string& n = name_of(s[i]);
    arrays.follow(n, s[i], ok);
    if (n == "glColorPointer" && ok) array_color_size = int(s[i].args[0].num);
    if (n == "glNewList" && ok && !compiling) compiling = true, open = called = wrapped = false;
    if (!compiling) continue;
    const bool element = n == "glArrayElement";
    // glArrayElement sends the enabled arrays' attributes before its vertex (seed 271828 stream 1135: a
    // glArrayElement with the colour array on after three glVertex in a GL_LINES wraps, the colour new).
    const int attribute = element ? (arrays.normal ? 1 : 0) | (arrays.color ? 2 : 0)
                          : starts(n, "glNormal3") ? 1 : starts(n, "glColor3") || starts(n, "glColor4") ? 2
                          : starts(n, "glTexCoord") ? 4 : starts(n, "glEdgeFlag") ? 8 : 0;
    // A colour growing from 3 to 4 components after a vertex wraps the store too (row 64's kind; measured,
    // seed 271828 stream 868: glColor3fv, glVertex2f, glColor4f in a GL_POLYGON). A position growing does
    // not crash (measured: glVertex2f then glVertex3f in a GL_POLYGON).
    // Mesa's vbo takes every glColor3 but glColor3f/fv as four components, alpha 1 (seed 577215:
    // glColor3fv, a vertex, glColor3ub grows the colour; repro list_colour3ub_grows_wrap_crash).
    const bool three = n == "glColor3f" || n == "glColor3fv";
    const int size = attribute & 2 ? (element ? array_color_size : three ? 3 : 4) : 0;
    const bool grows = (attribute & 2) && color_size > 0 && size > color_size;
    if (attribute & 2) color_size = std::max(color_size, size);
    if (n == "glBegin") open = true, vertices = seen = color_size = 0, mode = GLenum(s[i].args[0].num);
    else if (n == "glEnd") open = false;
    else if (n == "glCallList" || n == "glCallLists") called = true, wrapped |= open;
    else if (open && (attribute || element || starts(n, "glVertex2") || starts(n, "glVertex3") || starts(n, "glVertex4"))) {
      if (attribute && vertices > 0 && ((attribute & ~seen) || grows)) {
        const int unfinished = mode == GL_LINES ? vertices % 2 : mode == GL_TRIANGLES ? vertices % 3
                               : mode == GL_QUADS ? vertices % 4 : mode == GL_POINTS ? 0 : 1;
        wrapped |= unfinished > 0;
      }
      seen |= attribute;
      // A glVertex sends a vertex; a glArrayElement only with the vertex array on.
      if (element ? arrays.vertex : !attribute) ++vertices;
    }
  }
  return compiling && called && (wrapped || open);
}

// The first call after which a display list holds a primitive with attributes but no vertex: a
// compiled glBegin/glEnd with glNormal, glColor, glTexCoord or glArrayElement and no glVertex (nor a
// vertex array for the elements), or a compiled glDrawArrays / glDrawElements with the vertex array
// off and the normal or colour array on; -1 if none. Which client-state calls took effect is read
// from soft's errors.
int vertexless_list_primitive(const Stream& s, const SideResult& soft, bool* material = nullptr) {
  bool compiling = false, open = false;
  ArraysOn arrays;
  bool attribute = false, vertex = false, materials = false;
  // A glMaterial first sent (its face and pname) after the last vertex of a GL_POINTS: it wraps the
  // store with nothing to copy, and the vertex list after the wrap holds the material and no vertex
  // (measured, seed 161803 stream 2269: glBegin(GL_POINTS), a vertex, glMaterialf(GL_FRONT,
  // GL_SHININESS, 1), glEnd, called: the shininess reads back 0; repro
  // list_material_after_last_point.txt). Soft's store model counts no material (Context::hold_back).
  std::set<std::pair<double, double>> sent;
  bool trailing_material = false;
  GLenum mode = 0;
  for (size_t i = 0; i < s.size(); ++i) {
    const bool ok = i < soft.errors.size() && soft.errors[i] == GL_NO_ERROR;
    const std::string& n = name_of(s[i]);
    arrays.follow(n, s[i], ok);
    if (n == "glNewList" && ok && !compiling) compiling = true, open = false;
    if (n == "glEndList") compiling = false;
    if (!compiling) continue;
    const bool element_attributes = arrays.normal || arrays.color;
    // A glBegin inside the list's glBegin is a compile error and begins nothing.
    if (n == "glBegin" && !open) {
      open = true, attribute = vertex = materials = trailing_material = false;
      mode = GLenum(s[i].args[0].num), sent.clear();
    } else if (n == "glEnd" && open) {
      open = false;
      if ((attribute && !vertex) || trailing_material) {
        if (material) *material = materials || trailing_material;
        return int(i);
      }
    } else if (open && starts(n, "glVertex") && n != "glVertexPointer") vertex = true, trailing_material = false;  // the pointer is client state
    else if (open && n == "glArrayElement") attribute |= element_attributes, vertex |= arrays.vertex;
    else if (open && (starts(n, "glNormal3") || starts(n, "glColor") || starts(n, "glTexCoord"))) attribute = true;
    // A glMaterial there too (measured, seed 161803 stream 2269: glMaterialf(GL_FRONT, GL_SHININESS, 0)
    // alone in a list's GL_POINTS reads back 1.5e16; repro list_materialf_inside_begin.txt).
    else if (open && starts(n, "glMaterial")) {
      if (vertex && mode == GL_POINTS && ok && sent.insert({s[i].args[0].num, s[i].args[1].num}).second)
        trailing_material = true;
      else sent.insert({s[i].args[0].num, s[i].args[1].num});
      if (!vertex) attribute = materials = true;
    }
    else if (!open && (n == "glDrawArrays" || n == "glDrawElements") && !arrays.vertex && element_attributes &&
             s[i].args[n == "glDrawArrays" ? 2 : 1].num > 0)
      return int(i);
  }
  return -1;
}

// A mismatch of the current values: the current normal, colour or texture coordinates, or a
// material where colour material tracks the colour (glEnable(GL_COLOR_MATERIAL) before m), read at
// a checkpoint or by the stream's own glGet (an output: seed 577215 stream 5988082728378332109,
// a GL_COMPILE_AND_EXECUTE list's wrapped line loop read by glGetFloatv(GL_CURRENT_COLOR), repro
// list_line_loop_wrap_current_get.txt).
bool current_values(const Stream& s, const Mismatch& m) {
  if (m.kind != "state" && m.kind != "output") return false;
  if (m.key.find("GL_CURRENT_") != std::string::npos) return true;
  return m.key.find("glGetMaterialfv") != std::string::npos && any_call(s, m.call, [](const Call& c, size_t) {
           return is(c, "glEnable") && GLenum(c.args[0].num) == GL_COLOR_MATERIAL;
         });
}

// Whether a glRenderMode(GL_FEEDBACK or GL_SELECT) comes before call `at` with no glRenderMode(GL_RENDER)
// after it (taken or not: Mesa takes some that soft refuses).
bool fed_back_at(const Stream& s, size_t at) {
  bool fed = false;
  for (size_t i = 0; i < at && i < s.size(); ++i)
    if (is(s[i], "glRenderMode")) fed = GLenum(s[i].args[0].num) != GL_RENDER;
  return fed;
}

// Whether a list compiled before call `at` holds a primitive with fewer vertices than its mode
// draws: a glBegin/glEnd (glVertex, or glArrayElement with the vertex array on) or a compiled
// glDrawArrays (its count, or no vertex array).
bool incomplete_list_primitive(const Stream& s, const SideResult& soft, size_t at) {
  bool compiling = false, open = false;
  ArraysOn arrays;
  GLenum mode = 0;
  int vertices = 0;
  for (size_t i = 0; i < at && i < s.size(); ++i) {
    const bool ok = i < soft.errors.size() && soft.errors[i] == GL_NO_ERROR;
    const std::string& n = name_of(s[i]);
    arrays.follow(n, s[i], ok);
    if (n == "glNewList" && ok && !compiling) compiling = true, open = false;
    if (n == "glEndList") compiling = false;
    if (!compiling) continue;
    if (n == "glBegin" && ok && !open) open = true, mode = GLenum(s[i].args[0].num), vertices = 0;
    else if (n == "glEnd" && open) {
      open = false;
      if (vertices < state::fewest_vertices(mode)) return true;
    } else if (open && (starts(n, "glVertex") || (n == "glArrayElement" && arrays.vertex))) ++vertices;
    else if (!open && n == "glDrawArrays" && ok &&
             (!arrays.vertex || s[i].args[2].num < state::fewest_vertices(GLenum(s[i].args[0].num))))
      return true;
  }
  return false;
}

// Whether a list compiled before call `at` changes primitive mode at least twice from one primitive
// to the next (glBegin/glEnd, or a compiled glDrawArrays or glDrawElements): measured, Mesa feeds
// back only the first mode's primitives of such a list and segfaults in glCallList at the second
// change (GL_POINTS, GL_QUADS, GL_LINES; seed 555 stream 303, repro
// list_modes_fed_back_crash.txt). Calls between the primitives were not varied.
bool list_modes_change_twice(const Stream& s, const SideResult& soft, size_t at) {
  bool compiling = false, open = false;
  GLenum last = 0;
  int changes = 0, primitives = 0;
  for (size_t i = 0; i < at && i < s.size(); ++i) {
    const bool ok = i < soft.errors.size() && soft.errors[i] == GL_NO_ERROR;
    const std::string& n = name_of(s[i]);
    if (n == "glNewList" && ok && !compiling) compiling = true, open = false, changes = primitives = 0;
    if (n == "glEndList") compiling = false;
    if (!compiling) continue;
    const bool begins = n == "glBegin" && ok && !open;
    if (begins) open = true;
    else if (n == "glEnd") open = false;
    if (begins || (!open && (n == "glDrawArrays" || n == "glDrawElements") && ok)) {
      const GLenum mode = GLenum(s[i].args[0].num);
      if (primitives++ > 0 && mode != last) ++changes;
      last = mode;
      if (changes >= 2) return true;
    }
  }
  return false;
}

// Whether m can show a glMaterialf or glMateriali with a colour's pname (four values) compiled into a
// display list before it (taken by soft: no error): Mesa's list keeps four floats read from the one
// parameter, three of them memory it never wrote, and sets the material from them when the list
// runs (measured, seed 577215 stream 16382461972266344557: glMaterialf(GL_FRONT,
// GL_AMBIENT_AND_DIFFUSE, 76) in a GL_COMPILE list reads back green, blue and alpha as -6.4, -20414
// or 0 from one run to the next; glMateriali(GL_BACK, GL_SPECULAR) too; the same call outside a list
// read back (76, 0, 0, 0) every time). GL 2.1 makes the call GL_INVALID_ENUM; soft sets (v, 0, 0, 0),
// as Context::Materialf. Explains that material's reads (a face the call set) and what was drawn.
bool list_materialf_colour(const Stream& s, const Mismatch& m, const SideResult& soft) {
  if (m.call < 0) return false;
  const bool drawing = m.kind == "feedback" || m.kind == "pixels" || m.kind == "readpixels";
  const bool material = m.kind == "state" && m.key.find("glGetMaterialfv") != std::string::npos;
  if (!drawing && !material) return false;
  bool compiling = false;
  for (size_t i = 0; i < size_t(m.call) && i < s.size(); ++i) {
    const bool ok = i < soft.errors.size() && soft.errors[i] == GL_NO_ERROR;
    const std::string& n = name_of(s[i]);
    if (n == "glNewList" && ok) compiling = true;
    if (n == "glEndList") compiling = false;
    if (!compiling || !ok || (n != "glMaterialf" && n != "glMateriali")) continue;
    const auto face = GLenum(s[i].args[0].num), pname = GLenum(s[i].args[1].num);
    const bool colour = pname == GL_AMBIENT || pname == GL_DIFFUSE || pname == GL_SPECULAR || pname == GL_EMISSION ||
                        pname == GL_AMBIENT_AND_DIFFUSE;
    if (!colour) continue;
    if (drawing) return true;
    auto reads = [&](GLenum e) { return m.key.find(enum_name(e) + ")") != std::string::npos; };
    const bool face_read = face == GL_FRONT_AND_BACK || m.key.find("(" + enum_name(face) + ",") != std::string::npos;
    const bool pname_read = pname == GL_AMBIENT_AND_DIFFUSE ? reads(GL_AMBIENT) || reads(GL_DIFFUSE) : reads(pname);
    if (face_read && pname_read) return true;
  }
  return false;
}

// A deviation soft reported while drawing, which can only change what was drawn.
// A deviation soft names when it draws: it explains what drawing shows (pictures, feedback, the
// selection buffer's hit records and the count glRenderMode returns) in a stream where soft named it.
KnownDeviation drawn(std::string name, const char* soft_says) {
  return {std::move(name), soft_says, [soft_says](const Stream& s, const Mismatch& m, const SideResult&, const SideResult& soft) {
            auto call_is = [&](const char* f) { return m.call >= 0 && name_of(s[size_t(m.call)]) == f; };
            const bool drawing = m.kind == "feedback" || m.kind == "pixels" || m.kind == "readpixels" ||
                                 (m.kind == "return" && call_is("glRenderMode")) ||
                                 (m.kind == "output" && call_is("glSelectBuffer"));
            return drawing && std::find(soft.deviations.begin(), soft.deviations.end(), soft_says) != soft.deviations.end();
          }};
}

}  // namespace

namespace {
// Whether call `at` is a draw of at least one vertex that reads an array enabled but never given
// a pointer (a pointer call soft took, not null): Mesa reads address 0 there. Outside lists soft
// refuses the draw with GL_INVALID_OPERATION (`refused`: required); a list compiling it records
// nothing.
bool null_array_draw(const Stream& s, size_t at, const SideResult& soft, bool refused) {
  if (at >= soft.errors.size() || (refused && soft.errors[at] != GL_INVALID_OPERATION)) return false;
  const Call& draw = s[at];
  const std::string& n = name_of(draw);
  if (n == "glDrawArrays" ? draw.args[2].num < 1 : n == "glDrawElements" ? draw.args[1].num < 1 : n != "glArrayElement") return false;
  const std::pair<GLenum, const char*> arrays[] = {
      {GL_VERTEX_ARRAY, "glVertexPointer"}, {GL_NORMAL_ARRAY, "glNormalPointer"}, {GL_COLOR_ARRAY, "glColorPointer"}};
  for (const auto& [array, pointer] : arrays) {
    const bool enabled = any_call(s, int(at), [&](const Call& c, size_t) {
      return (is(c, "glEnableClientState") || is(c, "glEnable")) && GLenum(c.args[0].num) == array;
    });
    const bool given = any_call(s, int(at), [&](const Call& c, size_t i) {
      return is(c, pointer) && i < soft.errors.size() && soft.errors[i] == GL_NO_ERROR && c.args.back().kind != Arg::Kind::Null;
    });
    if (enabled && !given) return true;
  }
  return false;
}
}  // namespace

const std::vector<KnownDeviation>& known_deviations() {
  static const std::vector<KnownDeviation> v = {
      {"mesa-negative-stride-applied",
       "Mesa records GL_INVALID_VALUE for a negative stride in gl*Pointer and sets the array all the same (varray.c); GL ignores the call",
       // Its error hidden too (both sides read none): while GL_COMPILE_AND_EXECUTE's executing
       // side is inside the list's glBegin (a wrap), a gl*Pointer is not compiled and runs as
       // outside glBegin/glEnd, on Mesa as on soft; Mesa sets the array with its negative stride
       // there as well (measured: seed 577215 stream 11801004284260778288, repro
       // list_executing_negative_stride.txt).
       [](const Stream& s, const Mismatch& m, const SideResult& mesa, const SideResult& soft) {
         return after_mesa_applied(
             s, m, mesa,
             [](const Call& c) {
               return (is(c, "glVertexPointer") || is(c, "glColorPointer")) ? c.args[2].num < 0
                      : is(c, "glNormalPointer")                            ? c.args[1].num < 0
                                                                            : false;
             },
             &soft);
       }},
      {"mesa-render-mode-applied",
       "Mesa records GL_INVALID_OPERATION for glRenderMode(GL_FEEDBACK/GL_SELECT) without a buffer and switches the mode all the same, and GL_INVALID_ENUM for a bad mode after emptying the feedback buffer (feedback.c)",
       [](const Stream& s, const Mismatch& m, const SideResult& mesa, const SideResult&) {
         return after_mesa_applied(s, m, mesa, [](const Call& c) { return is(c, "glRenderMode"); });
       }},
      {"mesa-feedback-null-buffer",
       "Mesa records GL_INVALID_VALUE for glFeedbackBuffer with a null buffer and sets the buffer's size to 0 all the same (feedback.c)",
       [](const Stream& s, const Mismatch& m, const SideResult& mesa, const SideResult&) {
         return after_mesa_applied(s, m, mesa, [](const Call& c) {
           return is(c, "glFeedbackBuffer") && c.args[2].kind == Arg::Kind::Null;
         });
       }},
      {"mesa-array-element-out-of-range",
       "Mesa reads outside the client arrays for glArrayElement with an index they do not hold (no error is defined); the values it passes on are garbage",
       [](const Stream& s, const Mismatch& m, const SideResult& mesa, const SideResult&) {
         return any_call(s, reach(s, m, mesa), [](const Call& c, size_t) { return is(c, "glArrayElement") && c.args[0].num < 0; });
       }},
      {"soft-null-array-pointer",
       "an enabled array that was never given a pointer: Mesa reads address 0 (garbage or a crash), soft reads nothing and records GL_INVALID_OPERATION",
       [](const Stream& s, const Mismatch& m, const SideResult&, const SideResult& soft) {
         return m.call >= 0 && null_array_draw(s, size_t(m.call), soft, true);
       }},
      // The same read of address 0 crashing Mesa, at the draw or, its heap corrupted, later wherever
      // malloc next looks. Measured: glEnableClientState(GL_VERTEX_ARRAY), then a
      // GL_COMPILE_AND_EXECUTE list's glDrawArrays(GL_TRIANGLE_STRIP, 0, 2) segfaults there (repro
      // null_vertex_array_list_crash; found by shrinking seed 299792 stream 2831664394777852868's
      // crash as any Mesa crash: that stream's own, an abort in malloc, has another cause).
      {"soft-null-array-pointer-crash",
       "Mesa crashes at or after a draw that read an enabled array never given a pointer (address 0; its heap corrupted, "
       "the crash where malloc next notices); soft reads nothing",
       [](const Stream& s, const Mismatch& m, const SideResult&, const SideResult& soft) {
         if (m.kind != "crash" || m.key.rfind("crash mesa", 0) != 0) return false;
         const size_t upto = m.call < 0 ? s.size() : std::min(size_t(m.call) + 1, s.size());
         for (size_t i = 0; i < upto; ++i)
           if (null_array_draw(s, i, soft, false)) return true;
         return false;
       },
       true},
      {"soft-out-of-memory",
       "a draw of more vertices than half the machine's memory holds: soft records GL_OUT_OF_MEMORY before allocating (GL 2.1 allows it), Mesa draws",
       [](const Stream& s, const Mismatch& m, const SideResult& mesa, const SideResult& soft) {
         if (m.kind != "error" || m.call < 0 || size_t(m.call) >= soft.errors.size()) return false;
         const std::string& n = name_of(s[size_t(m.call)]);
         return (n == "glDrawArrays" || n == "glDrawElements") && soft.errors[size_t(m.call)] == GL_OUT_OF_MEMORY &&
                mesa.errors[size_t(m.call)] == GL_NO_ERROR;
       }},
      {"current-undefined-after-draw",
       "GL 2.1 section 2.8: with the normal or colour array enabled, the current normal or colour is indeterminate after glDrawArrays / glDrawElements",
       [](const Stream& s, const Mismatch& m, const SideResult&, const SideResult& soft) {
         const bool normal = m.key.find("GL_CURRENT_NORMAL") != std::string::npos;
         const bool colour = m.key.find("GL_CURRENT_COLOR") != std::string::npos;
         if (m.kind != "state" || !(normal || colour) || m.call < 0) return false;
         // Whether the last call before the checkpoint that sets the attribute is a draw with its
         // array on: a draw without it leaves the value defined (seed 299792 stream
         // 6292637399379987596 hid a real difference here while any draw counted).
         ArraysOn on;
         bool undefined = false;
         for (size_t i = 0; i < size_t(m.call) && i < s.size(); ++i) {
           const std::string& n = name_of(s[i]);
           on.follow(n, s[i], i < soft.errors.size() && soft.errors[i] == GL_NO_ERROR);
           if (n == "glDrawArrays" || n == "glDrawElements") undefined = undefined || (normal ? on.normal : on.color);
           if (n == "glArrayElement" || starts(n, normal ? "glNormal3" : "glColor3") || (colour && starts(n, "glColor4")))
             undefined = false;
         }
         return undefined;
       }},
      drawn("mesa-separate-specular-feedback",
            "feedback reports only the primary colour under GL_SEPARATE_SPECULAR_COLOR"),
      drawn("mesa-two-side-back-color-material",
            "two-sided lighting with a GL_BACK colour material is broken in Mesa 22.3"),
      drawn("mesa-shininess-zero-pow",
            "shininess 0: Mesa's LIT path takes pow(0, 0) as 0 where the spec gives 1"),
      drawn("mesa-shininess-zero-attenuated",
            "shininess 0 with an attenuated or spot light: Mesa's LIT path raises n.L to the power n.L "
            "for the specular factor where the spec gives 1"),
      drawn("zero-normal-normalize", state::kZeroNormal),
      drawn("soft-drawpixels-nonfinite-position", state::kNonfiniteDrawPixels),
      drawn("soft-texgen-not-modelled", state::kTexGen),
      drawn("mesa-clip-temps-uninitialised", state::kClipTempsUnwritten),
      drawn("soft-line-smooth-not-modelled", state::kLineSmooth),
      drawn("soft-point-smooth-not-modelled", state::kPointSmooth),
      drawn("mesa-line-loop-wrap", state::kLineLoopWrap),
      drawn("soft-texcoord-varying-not-modelled", state::kTexCoordVarying),
      // Row 44: the alpha of vertices sent before the glColor3, and so of the current colour too.
      {"mesa-color3-shrink-in-primitive", state::kColorShrinkInPrimitive,
       [](const Stream&, const Mismatch& m, const SideResult&, const SideResult& soft) {
         const bool kind = m.kind == "feedback" || m.kind == "pixels" || m.kind == "readpixels" ||
                           (m.kind == "state" && m.key.find("GL_CURRENT_COLOR") != std::string::npos);
         return kind && std::find(soft.deviations.begin(), soft.deviations.end(), state::kColorShrinkInPrimitive) !=
                            soft.deviations.end();
       }},
      // Row 47: the call's own error, and what was not drawn. Compiled into a list, the error is the
      // glCallList's (seed 662607 stream 3910108319701054866, repro list_draw_pixels_format.txt):
      // soft's GL_INVALID_OPERATION where Mesa's is none.
      {"soft-drawpixels-format-not-implemented", state::kDrawPixelsFormat,
       [](const Stream& s, const Mismatch& m, const SideResult& mesa, const SideResult& soft) {
         const auto call_is = [&](const char* f) { return m.call >= 0 && name_of(s[size_t(m.call)]) == f; };
         const bool called = (call_is("glCallList") || call_is("glCallLists")) && size_t(m.call) < soft.errors.size() &&
                             soft.errors[size_t(m.call)] == GL_INVALID_OPERATION &&
                             mesa.errors[size_t(m.call)] == GL_NO_ERROR &&
                             any_call(s, m.call, [](const Call& c, size_t) { return is(c, "glDrawPixels"); });
         const bool kind = m.kind == "pixels" || m.kind == "readpixels" ||
                           (m.kind == "error" && (call_is("glDrawPixels") || called));
         return kind && std::find(soft.deviations.begin(), soft.deviations.end(), state::kDrawPixelsFormat) !=
                            soft.deviations.end();
       }},
      // Row 55: see call_list_and_wrap.
      {"mesa-list-call-then-wrap-crash",
       "Mesa 22.3 segfaults in glEndList when a list compiled a glCallList or glCallLists and its vertex store "
       "wraps keeping vertices, or flushes inside a glBegin of the list (GL: compiled like any other call); soft compiles it",
       [](const Stream& s, const Mismatch& m, const SideResult&, const SideResult& soft) {
         if (m.kind != "crash" || m.key != "crash mesa glEndList" || m.call < 0) return false;
         return call_list_and_wrap(s, soft, size_t(m.call));
       },
       true},
      drawn("mesa-list-strip-wrap", state::kListStripWrap),  // row 55
      // Row 55, the values it leaves: the wrapped strip's vertices Mesa copies are others than sent, so
      // the current values after the list come from another vertex (measured, seed 271828 stream 494:
      // a strip of three with normals (.5, 0, 0), (0, .5, 0), (0, 0, .5) wrapped by a first glColor
      // reads back the second's normal; of one, the normal from before the list; repro
      // list_strip_wrap_current.txt).
      // Row 55: the executing side's errors after a store fill by draws of no vertex (Context::compile_elements).
      {"mesa-list-fill-empty-draw-error", state::kListFillEmptyDraw,
       [](const Stream&, const Mismatch& m, const SideResult&, const SideResult& soft) {
         return m.kind == "error" && std::find(soft.deviations.begin(), soft.deviations.end(),
                                               state::kListFillEmptyDraw) != soft.deviations.end();
       }},
      {"mesa-list-strip-wrap-current", state::kListStripWrap,
       [](const Stream& s, const Mismatch& m, const SideResult&, const SideResult& soft) {
         return current_values(s, m) && std::find(soft.deviations.begin(), soft.deviations.end(),
                                                  state::kListStripWrap) != soft.deviations.end();
       }},
      drawn("mesa-list-incomplete-fed-back", state::kListIncompleteFedBack),  // row 66
      drawn("mesa-list-incomplete-unfilled", state::kListIncompleteUnfilled),  // row 66, GL_RENDER
      drawn("mesa-list-padded-quad-drawn", state::kListPaddedQuadDrawn),      // row 70
      drawn("mesa-list-modes-fed-back-first", state::kListModesFedBackFirst),  // row 72
      // Row 72: the crash, from soft's model of Mesa's merged draws (Context::close_node_modes).
      {"mesa-list-modes-crash", state::kListModesCrash,
       [](const Stream&, const Mismatch& m, const SideResult&, const SideResult& soft) {
         return m.kind == "crash" && m.key == "crash mesa glCallList" &&
                std::find(soft.deviations.begin(), soft.deviations.end(), state::kListModesCrash) != soft.deviations.end();
       },
       true},
      // Row 71: heap corruption compiling a vertex list (Context::note_node_primitive); glibc aborts at
      // that flush or at any later call, the read-back included.
      {"mesa-list-two-then-quad-crash", state::kListTwoThenQuadCrash,
       [](const Stream&, const Mismatch& m, const SideResult&, const SideResult& soft) {
         return m.kind == "crash" && m.key.rfind("crash mesa", 0) == 0 &&
                std::find(soft.deviations.begin(), soft.deviations.end(), state::kListTwoThenQuadCrash) !=
                    soft.deviations.end();
       },
       true},
      // Row 66: the crash, read from the stream (Mesa takes a glRenderMode(GL_SELECT) soft refuses
      // without a buffer, so soft may be drawing where Mesa feeds back).
      {"mesa-list-incomplete-fed-back-crash",
       "Mesa 22.3 segfaults in glCallList of a list holding a primitive too short to draw, or changing "
       "primitive mode twice, in GL_FEEDBACK or GL_SELECT (GL: each drawn or, too short, not); soft draws them",
       [](const Stream& s, const Mismatch& m, const SideResult&, const SideResult& soft) {
         if (m.kind != "crash" || m.key != "crash mesa glCallList" || m.call < 0) return false;
         return fed_back_at(s, size_t(m.call)) && (incomplete_list_primitive(s, soft, size_t(m.call)) ||
                                                  list_modes_change_twice(s, soft, size_t(m.call)));
       },
       true},
      // Row 55: its vertex list has no vertex, and running the list (GL_COMPILE_AND_EXECUTE or
      // glCallList) copies its attribute slots, never written, to the current values: garbage
      // such as 9.78e35 or -3.7e10 (measured), so only those values are explained.
      {"mesa-list-primitive-without-vertex",
       "a display list's primitive with attributes but no vertex: Mesa sets the current normal, colour and "
       "texture coordinates (and a tracked material) from memory it never wrote when the list runs; soft from the "
       "attributes sent",
       [](const Stream& s, const Mismatch& m, const SideResult&, const SideResult& soft) {
         bool material = false;
         const int at = vertexless_list_primitive(s, soft, &material);
         const bool material_read = material && m.kind == "state" && m.key.find("glGetMaterialfv") != std::string::npos;
         // What is drawn with those values afterwards differs too (seed 173205 stream
         // 9957378043699921596: a triangle drawn without a colour array after the list, in Mesa's
         // unwritten colour; repro list_vertexless_colour_drawn.txt).
         const bool drawing = m.kind == "pixels" || m.kind == "readpixels" || m.kind == "feedback" ||
                              (m.kind == "return" && m.call >= 0 && is(s[size_t(m.call)], "glRenderMode"));
         if (!current_values(s, m) && !material_read && !drawing) return false;
         // Soft's model names the wider case too (a wrap with nothing to copy: 2026 stream 972).
         return (at >= 0 && (m.call < 0 || m.call > at)) ||
                std::find(soft.deviations.begin(), soft.deviations.end(), state::kListVertexlessNode) != soft.deviations.end();
       }},
      // Row 65: measured, glBegin(GL_LINE_LOOP), glVertex, glColor3f(.5, .25, 1), glVertex, glEnd in a
      // list reads back (0, 0, 0, 1) after glCallList (and in GL_COMPILE_AND_EXECUTE after the next
      // flush), with a colour at the first vertex too; immediate mode agrees.
      {"mesa-list-line-loop-wrap-current", state::kListLineLoopCurrent,
       [](const Stream& s, const Mismatch& m, const SideResult&, const SideResult& soft) {
         return current_values(s, m) && std::find(soft.deviations.begin(), soft.deviations.end(),
                                                  state::kListLineLoopCurrent) != soft.deviations.end();
       }},
      // Row 67: the vertices Mesa replays are others than sent: what they draw, and the current values
      // (and a tracked material) they leave.
      {"mesa-list-loopback-deduplicated", state::kListLoopbackDeduplicated,
       [](const Stream& s, const Mismatch& m, const SideResult& mesa, const SideResult& soft) {
         static const KnownDeviation shown = drawn("", state::kListLoopbackDeduplicated);
         return shown.explains(s, m, mesa, soft) ||
                (current_values(s, m) && std::find(soft.deviations.begin(), soft.deviations.end(),
                                                   state::kListLoopbackDeduplicated) != soft.deviations.end());
       }},
      // Row 68: the current values (and a tracked material) set from the never-stored vertex.
      {"mesa-list-empty-line-loop-current", state::kListEmptyLoopCurrent,
       [](const Stream& s, const Mismatch& m, const SideResult&, const SideResult& soft) {
         return current_values(s, m) && std::find(soft.deviations.begin(), soft.deviations.end(),
                                                  state::kListEmptyLoopCurrent) != soft.deviations.end();
       }},
      {"mesa-list-materialf-colour-unwritten",
       "glMaterialf or glMateriali with a colour's pname (GL_INVALID_ENUM in GL 2.1) compiled into a display list: "
       "Mesa's list keeps four values read from the one parameter, three of them memory it never wrote, and sets "
       "the material from them when the list runs; soft sets (v, 0, 0, 0)",
       [](const Stream& s, const Mismatch& m, const SideResult&, const SideResult& soft) {
         return list_materialf_colour(s, m, soft);
       }},
      drawn("nonfinite-vertex", state::kNonfiniteVertex),     // row 46
      drawn("unfilled-clipped", state::kUnfilledClipped),     // row 62
      drawn("zero-clip-vertex", state::kZeroClipVertex),      // row 56
      drawn("clipped-sliver-planes", state::kClippedSliver),  // row 63
  };
  return v;
}

const KnownDeviation* explain(const Stream& s, const Mismatch& m, const SideResult& mesa, const SideResult& soft) {
  if (m.kind == "hang") return nullptr;  // never explained away
  const bool crash = m.kind == "crash";
  for (const KnownDeviation& d : known_deviations())
    if ((!crash || d.mesa_crash) && d.explains(s, m, mesa, soft)) return &d;
  return nullptr;
}

}  // namespace ffc::difftest
