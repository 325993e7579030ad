// A differential test stream: GL calls as data. Each call names an entry point of the dispatch
// (src/gl/gl_functions.inc, plus glLightiv, glLightModeliv and glMaterialiv, which programs load
// by name) and holds its arguments: numbers, arrays the stream owns (so that a pointer handed to
// glVertexPointer reads the same values on both sides), or output buffers the runner allocates.
// A stream prints as a C snippet and round-trips through a small text format, one call a line,
// so a repro found by `ffcompat fuzz` can be kept as a file and replayed.
#pragma once
#include <GL/gl.h>

#include <string>
#include <vector>

namespace ffc::difftest {

struct Arg {
  enum class Kind : unsigned char { Num, Blob, Out, Null };
  Kind kind = Kind::Num;
  double num = 0;            // Num: the value; Out: the buffer's length in elements
  GLenum type = GL_FLOAT;    // Blob: the element type (GL_FLOAT, GL_DOUBLE, GL_INT, GL_SHORT, ...)
  std::vector<double> blob;  // Blob: the elements, converted to `type` when the stream runs

  static Arg number(double v) { return {Kind::Num, v, GL_FLOAT, {}}; }
  static Arg values(GLenum type, std::vector<double> v) { return {Kind::Blob, 0, type, std::move(v)}; }
  static Arg out(int elements) { return {Kind::Out, double(elements), GL_FLOAT, {}}; }
  static Arg null() { return {Kind::Null, 0, GL_FLOAT, {}}; }
  bool operator==(const Arg& o) const;
};

struct Call {
  int fn = 0;  // index into functions()
  std::vector<Arg> args;
  bool operator==(const Call& o) const { return fn == o.fn && args == o.args; }
};

using Stream = std::vector<Call>;

// What a parameter of an entry point is, read from its C type in gl_functions.inc.
enum class Param : unsigned char {
  Enum, Bitfield, Int, UByte, Float, Double,  // numbers
  In,                                         // const T*: an array the stream owns
  Out,                                        // T*: a buffer the runner allocates and compares
};

struct Function {
  std::string name;                 // "glLightfv"; "checkpoint" for the read-back pseudo-call
  std::vector<Param> params;
  std::vector<std::string> ctypes;  // the C types as declared ("const GLfloat *")
  bool returns = false;             // a value worth comparing (glRenderMode, glIsEnabled, ...)
};

// Every entry point a stream can call, then the pseudo-call "checkpoint" (read back every glGet
// value the tester knows and compare).
const std::vector<Function>& functions();
// Index of a function by name ("glBegin"); -1 when unknown.
int function_index(const std::string& name);
int checkpoint_fn();
inline const std::string& name_of(const Call& c) { return functions()[size_t(c.fn)].name; }

// Builds a call from a name and its arguments; throws std::invalid_argument on a wrong count.
Call make_call(const std::string& name, std::vector<Arg> args);

// The text format: a header line, then one call a line, "glName arg arg ...". Numbers are decimal
// (nan, inf, -inf allowed), enums by name (GL_LIGHT0) or number, bitfields as A|B, owned arrays as
// type[v v v] (float, double, int, uint, short, ushort, byte, ubyte), output buffers as out[N],
// a null pointer as null. '#' starts a comment.
std::string to_text(const Stream& s);
// Throws std::invalid_argument with "line N: what" on bad input.
Stream parse_text(const std::string& text);

// A C snippet doing the same calls through plain gl* names: arrays as static data before the call
// that takes them.
std::string to_c(const Stream& s);

// GL enum names for printing and parsing.
std::string enum_name(GLenum e);
// An error code's name (GL_NO_ERROR rather than GL_POINTS for 0).
std::string error_name(GLenum e);
bool enum_value(const std::string& name, GLenum& out);
// Every enum the name table knows (the generator draws invalid arguments from them too).
const std::vector<GLenum>& known_enums();
// Bytes of one element of an array type; 0 when the type is not one arrays may hold.
int type_size(GLenum type);

}  // namespace ffc::difftest
