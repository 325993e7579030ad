// The stream's function table (read from gl_functions.inc's declarations, so a new entry point
// of the dispatch is fuzzed without an edit here), its text format and its C snippets.
#include "difftest/stream.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>
#include <stdexcept>

namespace ffc::difftest {

namespace {

std::string trim(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t"), b = s.find_last_not_of(" \t");
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

// "(GLenum light, const GLfloat *params)" -> the C types, and what each parameter is.
Function declare(const std::string& name, const std::string& ret, const std::string& params) {
  Function f;
  f.name = name;
  f.returns = trim(ret) != "void";
  std::string inner = params.substr(1, params.size() - 2);
  if (trim(inner) == "void") return f;
  std::stringstream ss(inner);
  std::string p;
  while (std::getline(ss, p, ',')) {
    p = trim(p);
    const size_t star = p.rfind('*');
    const std::string type = star != std::string::npos ? trim(p.substr(0, star + 1)) : trim(p.substr(0, p.rfind(' ')));
    Param k;
    if (star != std::string::npos) k = type.rfind("const", 0) == 0 ? Param::In : Param::Out;
    else if (type == "GLenum") k = Param::Enum;
    else if (type == "GLbitfield") k = Param::Bitfield;
    else if (type == "GLubyte") k = Param::UByte;
    else if (type == "GLfloat" || type == "GLclampf") k = Param::Float;
    else if (type == "GLdouble" || type == "GLclampd") k = Param::Double;
    else k = Param::Int;  // GLint, GLsizei
    f.params.push_back(k);
    f.ctypes.push_back(type);
  }
  return f;
}

std::string number(double v, Param p) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[40];
  if (p == Param::Float) std::snprintf(buf, sizeof buf, "%.9g", v);
  else std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

const char* type_word(GLenum t) {
  switch (t) {
    case GL_FLOAT: return "float";
    case GL_DOUBLE: return "double";
    case GL_INT: return "int";
    case GL_UNSIGNED_INT: return "uint";
    case GL_SHORT: return "short";
    case GL_UNSIGNED_SHORT: return "ushort";
    case GL_BYTE: return "byte";
    case GL_UNSIGNED_BYTE: return "ubyte";
  }
  throw std::invalid_argument("an owned array of type " + enum_name(t));
}
const char* c_type(GLenum t) {
  switch (t) {
    case GL_FLOAT: return "GLfloat";
    case GL_DOUBLE: return "GLdouble";
    case GL_INT: return "GLint";
    case GL_UNSIGNED_INT: return "GLuint";
    case GL_SHORT: return "GLshort";
    case GL_UNSIGNED_SHORT: return "GLushort";
    case GL_BYTE: return "GLbyte";
    default: return "GLubyte";
  }
}

// The clear bits by name (GL_COLOR_BUFFER_BIT shares its value with GL_LIGHT0).
const char* bit_name(GLbitfield b) {
  switch (b) {
    case GL_COLOR_BUFFER_BIT: return "GL_COLOR_BUFFER_BIT";
    case GL_DEPTH_BUFFER_BIT: return "GL_DEPTH_BUFFER_BIT";
    case GL_STENCIL_BUFFER_BIT: return "GL_STENCIL_BUFFER_BIT";
    default: return "GL_ACCUM_BUFFER_BIT";
  }
}

std::string bitfield_text(double v, const char* sep) {
  const GLbitfield b = GLbitfield(v);
  std::string s;
  GLbitfield rest = b;
  for (GLbitfield bit : {GLbitfield(GL_COLOR_BUFFER_BIT), GLbitfield(GL_DEPTH_BUFFER_BIT),
                         GLbitfield(GL_STENCIL_BUFFER_BIT), GLbitfield(GL_ACCUM_BUFFER_BIT)})
    if (b & bit) s += (s.empty() ? "" : sep) + std::string(bit_name(bit)), rest &= ~bit;
  if (rest || s.empty()) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "0x%X", rest);
    s += (s.empty() ? "" : sep) + std::string(buf);
  }
  return s;
}

// `exact`: every digit a double needs (the text format); otherwise a float's nine (C snippets).
std::string arg_text(const Arg& a, Param p, bool exact) {
  switch (a.kind) {
    case Arg::Kind::Null: return "null";
    case Arg::Kind::Out: return "out[" + std::to_string(long(a.num)) + "]";
    case Arg::Kind::Blob: {
      std::string s = std::string(type_word(a.type)) + "[";
      for (size_t i = 0; i < a.blob.size(); ++i)
        s += (i ? " " : "") + number(a.blob[i], a.type == GL_FLOAT && !exact ? Param::Float : Param::Double);
      return s + "]";
    }
    case Arg::Kind::Num: break;
  }
  if (p == Param::Enum && a.num >= 0 && a.num <= 4294967295.0 && a.num == std::floor(a.num))
    return enum_name(GLenum(a.num));
  if (p == Param::Bitfield && a.num >= 0 && a.num <= 4294967295.0) return bitfield_text(a.num, "|");
  return number(a.num, exact ? Param::Double : p);
}

double parse_number(const std::string& w) {
  if (w == "nan") return NAN;
  if (w == "inf") return INFINITY;
  if (w == "-inf") return -INFINITY;
  GLenum e;
  if (enum_value(w, e)) return double(e);
  char* end = nullptr;
  const double v = std::strtod(w.c_str(), &end);
  if (w.empty() || *end) throw std::invalid_argument("'" + w + "' is not a number or enum name");
  return v;
}

}  // namespace

bool Arg::operator==(const Arg& o) const {
  auto same = [](double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); };
  if (kind != o.kind || !same(num, o.num) || blob.size() != o.blob.size()) return false;
  if (kind == Kind::Blob && type != o.type) return false;
  for (size_t i = 0; i < blob.size(); ++i)
    if (!same(blob[i], o.blob[i])) return false;
  return true;
}

const std::vector<Function>& functions() {
  static const std::vector<Function> v = [] {
    std::vector<Function> f;
#define FFC_GL_FUNCTION(ret, name, params) f.push_back(declare("gl" #name, #ret, #params));
#include "gl/gl_functions.inc"
#undef FFC_GL_FUNCTION
    f.push_back(declare("glLightiv", "void", "(GLenum light, GLenum pname, const GLint *params)"));
    f.push_back(declare("glLightModeliv", "void", "(GLenum pname, const GLint *params)"));
    f.push_back(declare("glMaterialiv", "void", "(GLenum face, GLenum pname, const GLint *params)"));
    f.push_back(declare("checkpoint", "void", "(void)"));
    return f;
  }();
  return v;
}

int function_index(const std::string& name) {
  static const std::map<std::string, int> index = [] {
    std::map<std::string, int> m;
    for (size_t i = 0; i < functions().size(); ++i) m[functions()[i].name] = int(i);
    return m;
  }();
  auto it = index.find(name);
  return it == index.end() ? -1 : it->second;
}

int checkpoint_fn() {
  static const int i = function_index("checkpoint");
  return i;
}

Call make_call(const std::string& name, std::vector<Arg> args) {
  const int fn = function_index(name);
  if (fn < 0) throw std::invalid_argument("unknown function " + name);
  if (args.size() != functions()[size_t(fn)].params.size())
    throw std::invalid_argument(name + " takes " + std::to_string(functions()[size_t(fn)].params.size()) +
                                " arguments, not " + std::to_string(args.size()));
  return {fn, std::move(args)};
}

std::string to_text(const Stream& s) {
  std::string t = "# ffcompat difftest stream 1: one call a line (src/difftest/stream.h)\n";
  for (const Call& c : s) {
    const Function& f = functions()[size_t(c.fn)];
    t += f.name;
    for (size_t i = 0; i < c.args.size(); ++i) t += " " + arg_text(c.args[i], f.params[i], true);
    t += "\n";
  }
  return t;
}

Stream parse_text(const std::string& text) {
  Stream s;
  std::istringstream in(text);
  std::string line;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    try {
      if (const size_t hash = line.find('#'); hash != std::string::npos) line.resize(hash);
      // Words, with an array's brackets kept in one word ("float[1 2 3]").
      std::vector<std::string> words;
      std::string w;
      int depth = 0;
      for (char ch : line) {
        if (ch == '[') ++depth;
        if (ch == ']') --depth;
        if ((ch == ' ' || ch == '\t' || ch == '\r') && depth == 0) {
          if (!w.empty()) words.push_back(w), w.clear();
        } else {
          w += ch;
        }
      }
      if (depth != 0) throw std::invalid_argument("unbalanced [ ]");
      if (!w.empty()) words.push_back(w);
      if (words.empty()) continue;
      std::vector<Arg> args;
      for (size_t i = 1; i < words.size(); ++i) {
        const std::string& a = words[i];
        const size_t open = a.find('[');
        if (a == "null") {
          args.push_back(Arg::null());
        } else if (open != std::string::npos && a.back() == ']') {
          const std::string head = a.substr(0, open), body = a.substr(open + 1, a.size() - open - 2);
          std::vector<double> vals;
          std::istringstream vs(body);
          for (std::string v; vs >> v;) vals.push_back(parse_number(v));
          if (head == "out") {
            if (vals.size() != 1 || vals[0] < 0 || vals[0] > (1 << 24)) throw std::invalid_argument("out[N] needs one size");
            args.push_back(Arg::out(int(vals[0])));
            continue;
          }
          GLenum type = 0;
          for (GLenum t : {GL_FLOAT, GL_DOUBLE, GL_INT, GL_UNSIGNED_INT, GL_SHORT, GL_UNSIGNED_SHORT, GL_BYTE,
                           GL_UNSIGNED_BYTE})
            if (head == type_word(t)) type = t;
          if (!type) throw std::invalid_argument("unknown array type '" + head + "'");
          args.push_back(Arg::values(type, std::move(vals)));
        } else if (a.find('|') != std::string::npos) {
          double bits = 0;
          std::istringstream bs(a);
          for (std::string part; std::getline(bs, part, '|');) bits = double(GLbitfield(bits) | GLbitfield(parse_number(part)));
          args.push_back(Arg::number(bits));
        } else {
          args.push_back(Arg::number(parse_number(a)));
        }
      }
      s.push_back(make_call(words[0], std::move(args)));
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("line " + std::to_string(line_no) + ": " + e.what());
    }
  }
  return s;
}

std::string to_c(const Stream& s) {
  std::string out;
  int array_no = 0;
  for (const Call& c : s) {
    const Function& f = functions()[size_t(c.fn)];
    if (c.fn == checkpoint_fn()) {
      out += "/* checkpoint: every glGet value compared here */\n";
      continue;
    }
    std::string call = f.name + "(";
    for (size_t i = 0; i < c.args.size(); ++i) {
      const Arg& a = c.args[i];
      std::string text;
      if (a.kind == Arg::Kind::Blob || a.kind == Arg::Kind::Out) {
        const std::string var = "a" + std::to_string(array_no++);
        if (a.kind == Arg::Kind::Out) {
          // The pointee type without '*' ("GLfloat *" -> GLfloat); an untyped buffer gets 8 bytes an
          // element, as the runner allocates, whatever its pixel type.
          std::string t = f.ctypes[i].substr(0, f.ctypes[i].find_first_of(" *"));
          if (t == "GLvoid") t = "GLdouble";
          out += "static " + t + " " + var + "[" + std::to_string(long(a.num)) + "];\n";
        } else {
          out += "static const " + std::string(c_type(a.type)) + " " + var + "[] = {";
          for (size_t k = 0; k < a.blob.size(); ++k) {
            const double v = a.blob[k];
            std::string n = std::isnan(v) ? "NAN" : std::isinf(v) ? (v > 0 ? "INFINITY" : "-INFINITY")
                                                                  : number(v, a.type == GL_FLOAT ? Param::Float : Param::Double);
            out += (k ? ", " : "") + n;
          }
          out += "};\n";
        }
        text = var;
      } else if (a.kind == Arg::Kind::Null) {
        text = "NULL";
      } else if (f.params[i] == Param::Bitfield) {
        text = bitfield_text(a.num, " | ");
      } else if (std::isnan(a.num)) {
        text = "NAN";
      } else if (std::isinf(a.num)) {
        text = a.num > 0 ? "INFINITY" : "-INFINITY";
      } else {
        text = arg_text(a, f.params[i], false);
        if (f.params[i] == Param::Float && text.find_first_of(".e") == std::string::npos) text += ".0";
        if (f.params[i] == Param::Float) text += "f";
      }
      call += (i ? ", " : "") + text;
    }
    out += call + ");\n";
  }
  return out;
}

}  // namespace ffc::difftest
