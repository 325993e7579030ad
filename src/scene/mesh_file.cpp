// OpenMesh's IO header before the mesh header, so its readers and the mesh's IO adapters are known.
#include <cerrno>
#include <cstdlib>
#include <OpenMesh/Core/IO/MeshIO.hh>

#include "scene/mesh_file.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <vector>

namespace ffc::scene {

namespace {

namespace fs = std::filesystem;

constexpr uintmax_t max_file_bytes = uintmax_t(512) << 20;  // 512 MiB
constexpr long long max_list_length = 1 << 16;             // vertices of one polygon

[[noreturn]] void corrupt(const std::string& what) { throw std::runtime_error(what); }

std::vector<std::string> tokens(const std::string& line) {
  std::vector<std::string> t;
  std::istringstream in(line);
  for (std::string w; in >> w;) t.push_back(w);
  return t;
}

bool parse_count(const std::string& s, long long& out) {
  if (s.empty() || s.size() > 18) return false;
  for (char c : s)
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  out = std::stoll(s);
  return true;
}

// --- OFF: the header's counts and every face's vertex count, before OpenMesh trusts them. Also
// what OpenMesh's OFF reader does not take (it would silently read nothing or drop faces): '#'
// comments before the end of the faces, counts on the OFF line, binary and 4D / nD variants.
void check_off(const std::string& data) {
  std::istringstream in(data);
  std::string line;
  int line_no = 0;
  auto next = [&](std::vector<std::string>& t) {  // the next line with content
    while (std::getline(in, line)) {
      ++line_no;
      t = tokens(line);
      if (t.empty()) continue;
      if (t[0][0] == '#')
        corrupt("line " + std::to_string(line_no) +
                ": a '#' comment before the end of the faces (OpenMesh's OFF reader does not take them there)");
      return true;
    }
    return false;
  };
  std::vector<std::string> t;
  if (!next(t)) corrupt("the file is empty");
  // OpenMesh reads a binary file when the header's raw characters have "BINARY" one character
  // after "OFF" ("OFFxBINARY" too), whatever the words: any "BINARY" on the first line is refused
  // (found by fuzz/: binary counts of billions).
  if (data.substr(0, data.find('\n')).find("BINARY") != std::string::npos)
    corrupt("binary OFF is not supported (use ASCII OFF, OBJ, PLY or STL)");
  const std::string& magic = t[0];
  // OpenMesh takes the header's options from the file's first characters, [ST][C][N][4][n]OFF:
  // read the same way here, so that both walk the same layout (found by fuzz/: "OFFCOFF", colours
  // here and none there).
  if (magic.size() < 3 || magic.compare(magic.size() - 3, 3, "OFF") != 0)
    corrupt("line " + std::to_string(line_no) + " is not an OFF header ('" + magic + "')");
  const std::string prefix = magic.substr(0, magic.size() - 3);
  if (prefix.find('4') != std::string::npos || prefix.find('n') != std::string::npos)
    corrupt("4D and n-dimensional OFF ('" + magic + "') are not supported");
  if (prefix.find("ST") != std::string::npos) corrupt("OFF with texture coordinates ('" + magic + "') is not supported");
  if (line_no != 1 || data.compare(0, magic.size(), magic) != 0 || (prefix != "" && prefix != "C" && prefix != "N" && prefix != "CN"))
    corrupt("line " + std::to_string(line_no) + " is not an OFF header ('" + magic + "': [C][N]OFF at the file's start)");
  if (t.size() > 1) corrupt("line " + std::to_string(line_no) + ": put the counts on the line after '" + magic + "'");
  if (!next(t)) corrupt("the OFF header has no vertex and face counts");
  long long nv = 0, nf = 0;
  if (t.size() < 2 || !parse_count(t[0], nv) || !parse_count(t[1], nf))
    corrupt("line " + std::to_string(line_no) + ": expected the vertex and face counts, got '" + line + "'");
  if (nv > (long long)data.size() || nf > (long long)data.size())
    corrupt("the header declares " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
            " faces, more than the file's " + std::to_string(data.size()) + " bytes can hold");
  for (long long i = 0; i < nv; ++i)
    if (!next(t)) corrupt("the file ends after " + std::to_string(i) + " of " + std::to_string(nv) + " vertices");
  for (long long i = 0; i < nf; ++i) {
    if (!next(t)) corrupt("the file ends after " + std::to_string(i) + " of " + std::to_string(nf) + " faces");
    long long n = 0;
    if (!parse_count(t[0], n) || n < 3 || n > nv || (long long)t.size() < n + 1)
      corrupt("line " + std::to_string(line_no) + ": face " + std::to_string(i) +
              " is not a vertex count of 3.." + std::to_string(nv) + " followed by that many indices");
    for (long long k = 1; k <= n; ++k) {
      long long idx = 0;
      if (!parse_count(t[size_t(k)], idx) || idx >= nv)
        corrupt("line " + std::to_string(line_no) + ": face " + std::to_string(i) + " has vertex index '" +
                t[size_t(k)] + "' (the file has " + std::to_string(nv) + " vertices)");
    }
  }
  // OpenMesh's ASCII reader is not line-based: it takes the three counts, each vertex's x y z (and
  // normal) and each face's size and indices as tokens (floats, unsigned ints: "-1" is 4294967295),
  // then the rest of a vertex's line (and a face's line, with colours). The same walk here, so no
  // count it reads can differ from what was checked (found by fuzz/: a 4-billion-entry face).
  std::istringstream walk(data);
  std::getline(walk, line);
  unsigned counts[3];
  if (!(walk >> counts[0] >> counts[1] >> counts[2])) corrupt("the counts are not three unsigned numbers");
  const bool normals = prefix.find('N') != std::string::npos, colours = prefix.find('C') != std::string::npos;
  for (unsigned i = 0; i < counts[0] && !walk.eof(); ++i) {
    float x[6];
    for (int k = 0; k < (normals ? 6 : 3); ++k)
      if (!(walk >> x[k])) corrupt("vertex " + std::to_string(i) + " does not start with its floats (as OpenMesh reads them)");
    std::getline(walk, line);
  }
  for (unsigned i = 0; i < counts[1]; ++i) {
    unsigned n = 0, idx = 0;
    if (!(walk >> n) || n < 3 || n > counts[0])
      corrupt("face " + std::to_string(i) + " has no vertex count of 3.." + std::to_string(counts[0]) + " where OpenMesh reads it");
    for (unsigned k = 0; k < n; ++k)
      if (!(walk >> idx) || idx >= counts[0])
        corrupt("face " + std::to_string(i) + " has a vertex index OpenMesh reads out of range");
    if (colours) std::getline(walk, line);
  }
}

// --- OBJ: OpenMesh's reader crashes when a malformed vertex line leaves it with fewer vertices than
// the faces and their normals refer to, so every v / vn / vt line must hold its numbers and every
// face must refer to elements already defined.
// A number as OpenMesh reads one (a float from a stream, which OpenMesh skips the line on failing):
// the whole token, no hex, nothing beyond float's range, no NUL inside (found by fuzz/).
bool is_number(const std::string& t) {
  std::istringstream in(t);
  float v;
  return in >> v && in.peek() == std::char_traits<char>::eof() && std::isfinite(v);
}

void check_obj(const std::string& data) {
  std::istringstream in(data);
  std::string line;
  long long counts[3] = {0, 0, 0};  // v, vt, vn
  for (int line_no = 1; std::getline(in, line); ++line_no) {
    // OpenMesh trims " \t\r\n" and skips a line that then starts with other white space (a
    // vertical tab, a form feed): the same here, so that both count the same vertices (found by
    // fuzz/: a "\vv" line counted here, not there, let a face name a vertex OpenMesh never made).
    const size_t first = line.find_first_not_of(" \t\r\n");
    if (first == std::string::npos || line[first] == '#' || std::isspace(static_cast<unsigned char>(line[first]))) continue;
    const auto t = tokens(line);
    const std::string where = "line " + std::to_string(line_no) + ": ";
    if (t.empty() || t[0][0] == '#') continue;
    const int kind = t[0] == "v" ? 0 : t[0] == "vt" ? 1 : t[0] == "vn" ? 2 : -1;
    if (kind >= 0) {
      const size_t need = kind == 1 ? 1 : 3;
      if (t.size() < need + 1) corrupt(where + "'" + t[0] + "' needs " + std::to_string(need) + " numbers");
      for (size_t k = 1; k < t.size() && k <= 3; ++k)  // (a fourth number, w or a colour, is left to OpenMesh)
        if (!is_number(t[k])) corrupt(where + "'" + t[k] + "' is not a finite number (a float, as OpenMesh reads it)");
      ++counts[kind];
      continue;
    }
    if (t[0] != "f") continue;  // groups, materials, smoothing, lines and points: not our concern
    if (t.size() < 4) corrupt(where + "a face needs at least 3 vertices");
    for (size_t k = 1; k < t.size(); ++k) {
      // v, v/vt, v//vn or v/vt/vn; 1-based, or negative counting back from the last one defined.
      const std::string& c = t[k];
      size_t start = 0;
      for (int part = 0; part < 3 && start <= c.size(); ++part) {
        const size_t slash = c.find('/', start);
        const std::string idx = c.substr(start, slash == std::string::npos ? std::string::npos : slash - start);
        const int which = part == 0 ? 0 : part == 1 ? 1 : 2;
        if (!(idx.empty() && part > 0)) {
          long long i = 0;
          const bool neg = !idx.empty() && idx[0] == '-';
          if (!parse_count(neg ? idx.substr(1) : idx, i) || i == 0 || i > counts[which])
            corrupt(where + "face corner '" + c + "' refers to " + (which == 0 ? "vertex" : which == 1 ? "texture coordinate" : "normal") +
                    " '" + idx + "' but " + std::to_string(counts[which]) + " are defined so far");
        }
        if (slash == std::string::npos) break;
        start = slash + 1;
      }
    }
  }
}

// --- OBJ per-corner normals. OpenMesh keeps one normal per vertex: where a face corner names
// another normal for a vertex than an earlier face did (`f v//vn` as Blender writes hard edges),
// the last face's wins for every face. To draw what the file says, the corners are read here and
// a vertex is split into one per distinct normal it has. Called on files check_obj accepted.
struct ObjCorners {
  std::vector<OpenMesh::Vec3d> normals;              // the vn lines, as floats (as OpenMesh reads them)
  std::vector<std::vector<std::pair<long long, long long>>> faces;  // per corner: v, vn (0-based; vn -1: none)
  long long vertices = 0;
};

ObjCorners read_obj_corners(const std::string& data) {
  ObjCorners out;
  std::istringstream in(data);
  std::string line;
  for (; std::getline(in, line);) {
    const size_t first = line.find_first_not_of(" \t\r\n");
    if (first == std::string::npos || line[first] == '#' || std::isspace(static_cast<unsigned char>(line[first]))) continue;
    const auto t = tokens(line);
    if (t.empty()) continue;
    if (t[0] == "v") ++out.vertices;
    if (t[0] == "vn") {
      float x = 0, y = 0, z = 0;  // missing components read as 0 (the triangle match catches a bad file)
      if (t.size() > 1) std::istringstream(t[1]) >> x;
      if (t.size() > 2) std::istringstream(t[2]) >> y;
      if (t.size() > 3) std::istringstream(t[3]) >> z;
      out.normals.push_back({x, y, z});
    }
    if (t[0] != "f") continue;
    std::vector<std::pair<long long, long long>> face;
    for (size_t k = 1; k < t.size(); ++k) {
      const std::string& c = t[k];
      auto index = [](const std::string& idx, long long defined) {  // 1-based or counting back
        // Not a number, or out of range (fuzz: "1///1" leaves "/1" here): no index, never a throw.
        errno = 0;
        char* end = nullptr;
        const long long i = std::strtoll(idx.c_str(), &end, 10);
        if (idx.empty() || end == idx.c_str() || errno == ERANGE) return -1LL;
        return i < 0 ? defined + i : i - 1;
      };
      const size_t s1 = c.find('/');
      const size_t s2 = s1 == std::string::npos ? std::string::npos : c.find('/', s1 + 1);
      const long long v = index(c.substr(0, s1), out.vertices);
      const long long vn = s2 == std::string::npos ? -1 : index(c.substr(s2 + 1), (long long)out.normals.size());
      face.push_back({v, vn});
    }
    out.faces.push_back(std::move(face));
  }
  return out;
}

// The file's faces as OpenMesh triangulated them (a fan from the first corner), each corner with
// the normal the file gives it; vertices split where they carry different normals. Empty when no
// vertex needs splitting (OpenMesh's per-vertex normals are then the file's) or a corner has no
// normal. Throws when OpenMesh's triangles cannot be matched to the file's faces.
std::optional<mesh::Layout> obj_corner_layout(const std::string& data, const mesh::Mesh& m, const std::string& name) {
  const ObjCorners c = read_obj_corners(data);
  std::vector<std::optional<OpenMesh::Vec3d>> first_normal(size_t(c.vertices));
  bool split = false;
  for (const auto& f : c.faces)
    for (const auto& [v, vn] : f) {
      if (vn < 0) return std::nullopt;  // a corner without a normal: the per-vertex normals stand
      auto& seen = first_normal[size_t(v)];
      if (!seen) seen = c.normals[size_t(vn)];
      split |= *seen != c.normals[size_t(vn)];
    }
  if (!split) return std::nullopt;
  auto mismatch = [&] {
    return std::runtime_error(name + ": its faces give a vertex several normals, and OpenMesh's triangles could not be "
                              "matched to the file's faces to keep them");
  };
  if ((long long)m.n_vertices() != c.vertices) throw mismatch();
  mesh::Layout l;
  std::map<std::pair<long long, std::array<double, 3>>, uint32_t> made;  // (vertex, normal) -> layout vertex
  auto vertex = [&](long long v, long long vn) {
    const OpenMesh::Vec3d& n = c.normals[size_t(vn)];
    const auto key = std::make_pair(v, std::array<double, 3>{n[0], n[1], n[2]});
    auto [it, fresh] = made.try_emplace(key, uint32_t(l.vertices.size()));
    if (fresh) {
      const auto p = m.point(mesh::Mesh::VertexHandle(int(v)));
      l.vertices.push_back({int(v), {p[0], p[1], p[2]}, {n[0], n[1], n[2]}});
    }
    return it->second;
  };
  size_t face_index = 0;
  for (const auto& f : c.faces)
    for (size_t i = 1; i + 1 < f.size(); ++i, ++face_index) {
      const std::pair<long long, long long> tri[3] = {f[0], f[i], f[i + 1]};
      if (face_index >= m.n_faces()) throw mismatch();
      // OpenMesh's face starts at one of its halfedges: the same triangle, maybe rotated.
      std::vector<int> fv;
      for (auto v : m.fv_range(m.face_handle(unsigned(face_index)))) fv.push_back(v.idx());
      if (fv.size() != 3) throw mismatch();
      int rot = -1;
      for (int r = 0; r < 3 && rot < 0; ++r)
        if (fv[size_t(r)] == tri[0].first && fv[size_t((r + 1) % 3)] == tri[1].first && fv[size_t((r + 2) % 3)] == tri[2].first) rot = r;
      if (rot < 0) throw mismatch();
      for (const auto& [v, vn] : tri) l.indices.push_back(vertex(v, vn));
    }
  if (face_index != m.n_faces()) throw mismatch();
  return l;
}

// --- PLY: walk the whole body as the header describes it, so no count can run past the file ---
struct PlyProperty {
  bool list = false;
  int count_size = 0, item_size = 0;  // bytes (binary)
  std::string count_type, item_type, name;
};
struct PlyElement {
  std::string name;
  long long count = 0;
  std::vector<PlyProperty> props;
};

int ply_type_size(const std::string& t) {
  static const std::map<std::string, int> sizes = {
      {"char", 1},  {"uchar", 1}, {"int8", 1},   {"uint8", 1},   {"short", 2},   {"ushort", 2},
      {"int16", 2}, {"uint16", 2}, {"int", 4},   {"uint", 4},    {"int32", 4},   {"uint32", 4},
      {"float", 4}, {"float32", 4}, {"double", 8}, {"float64", 8}};
  auto it = sizes.find(t);
  return it == sizes.end() ? 0 : it->second;
}

bool ply_is_float(const std::string& t) {
  return t == "float" || t == "float32" || t == "double" || t == "float64";
}

// A binary list count as a number; negative or fractional counts are corrupt.
long long ply_read_count(const unsigned char* p, const std::string& type, bool big_endian) {
  const int n = ply_type_size(type);
  unsigned char b[8] = {};
  for (int i = 0; i < n; ++i) b[i] = p[big_endian ? n - 1 - i : i];
  if (type == "char" || type == "int8") return int8_t(b[0]);
  if (type == "uchar" || type == "uint8") return b[0];
  if (type == "short" || type == "int16") return int16_t(uint16_t(b[0] | b[1] << 8));
  if (type == "ushort" || type == "uint16") return uint16_t(b[0] | b[1] << 8);
  const uint32_t u = uint32_t(b[0]) | uint32_t(b[1]) << 8 | uint32_t(b[2]) << 16 | uint32_t(b[3]) << 24;
  if (type == "int" || type == "int32") return int32_t(u);
  if (type == "uint" || type == "uint32") return u;
  return -1;  // a floating-point count
}

void check_ply(const std::string& data) {
  size_t pos = 0;
  auto header_line = [&](std::string& line) {
    const size_t end = data.find('\n', pos);
    if (end == std::string::npos) corrupt("the PLY header has no end_header line");
    line = data.substr(pos, end - pos);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    pos = end + 1;
  };
  std::string line;
  header_line(line);
  if (line != "ply") corrupt("it does not start with 'ply'");
  std::string format;
  std::vector<PlyElement> elements;
  for (int line_no = 2;; ++line_no) {
    header_line(line);
    const auto t = tokens(line);
    const std::string where = "header line " + std::to_string(line_no) + ": ";
    if (t.empty() || t[0] == "comment" || t[0] == "obj_info") continue;
    if (t[0] == "end_header") break;
    if (t[0] == "format") {
      if (t.size() != 3 || (t[1] != "ascii" && t[1] != "binary_little_endian" && t[1] != "binary_big_endian"))
        corrupt(where + "unknown format '" + line + "'");
      // OpenMesh reads the version as a float and, when it cannot, loops without end (a version
      // beyond float's range did that: found by fuzz/).
      if (!is_number(t[2])) corrupt(where + "the format version '" + t[2] + "' is not a number");
      format = t[1];
    } else if (t[0] == "element") {
      PlyElement e;
      if (t.size() != 3 || !parse_count(t[2], e.count)) corrupt(where + "bad element line '" + line + "'");
      e.name = t[1];
      elements.push_back(e);
    } else if (t[0] == "property") {
      if (elements.empty()) corrupt(where + "a property before any element");
      PlyProperty p;
      if (t.size() == 5 && t[1] == "list") {
        p.list = true;
        p.count_type = t[2], p.item_type = t[3], p.name = t[4];
        p.count_size = ply_type_size(p.count_type);
        p.item_size = ply_type_size(p.item_type);
        if (!p.count_size || !p.item_size) corrupt(where + "unknown type in '" + line + "'");
      } else if (t.size() == 3) {
        p.item_type = t[1], p.name = t[2];
        p.item_size = ply_type_size(p.item_type);
        if (!p.item_size) corrupt(where + "unknown type '" + t[1] + "'");
      } else {
        corrupt(where + "bad property line '" + line + "'");
      }
      elements.back().props.push_back(p);
    } else {
      corrupt(where + "unknown header keyword '" + t[0] + "'");
    }
  }
  if (format.empty()) corrupt("the PLY header has no format line");
  const size_t body = data.size() - pos;
  for (const auto& e : elements)
    if (e.count > (long long)body)
      corrupt("element '" + e.name + "' declares " + std::to_string(e.count) + " entries, more than the " +
              std::to_string(body) + " bytes of data can hold");
  if (format == "ascii") {
    // OpenMesh reads each value with operator>> of its type: a word that is not one whole number of
    // that type ("0H0", "1.5" for an int) leaves its stream failed or out of step, and it then reads
    // list counts it never wrote and grows a face's vertex list until memory runs out (found by
    // fuzz/ under AddressSanitizer: an index "0H0"; corpus ply_index_not_a_number.ply).
    const auto number = [](const std::string& w, const std::string& type) {
      const char* b = w.c_str();
      char* end = nullptr;
      // Decimal only: operator>> stops inside "nan", "inf" and hexadecimal floats that strtod takes.
      if (w.find_first_not_of("0123456789+-.eE") != std::string::npos) return false;
      if (ply_is_float(type)) (void)std::strtod(b, &end);
      else (void)std::strtoll(b, &end, 10);
      return end != b && *end == '\0';
    };
    std::istringstream in(data.substr(pos));
    std::string w;
    for (const auto& e : elements)
      for (long long i = 0; i < e.count; ++i)
        for (const auto& p : e.props) {
          const std::string where = "element '" + e.name + "' " + std::to_string(i) + " property '" + p.name + "'";
          if (!(in >> w)) corrupt("the data ends in " + where);
          if (!p.list) {
            if (!number(w, p.item_type)) corrupt(where + " is '" + w + "', not a " + p.item_type);
            continue;
          }
          long long n = 0;
          if (!parse_count(w, n) || n > max_list_length) corrupt(where + " has list length '" + w + "'");
          for (long long k = 0; k < n; ++k) {
            if (!(in >> w)) corrupt("the data ends in " + where);
            if (!number(w, p.item_type)) corrupt(where + " has item '" + w + "', not a " + p.item_type);
          }
        }
    return;
  }
  const bool big = format == "binary_big_endian";
  const auto* bytes = reinterpret_cast<const unsigned char*>(data.data());
  size_t at = pos;
  for (const auto& e : elements)
    for (long long i = 0; i < e.count; ++i)
      for (const auto& p : e.props) {
        const std::string where = "element '" + e.name + "' " + std::to_string(i) + " property '" + p.name + "'";
        if (!p.list) {
          if (data.size() - at < size_t(p.item_size)) corrupt("the data ends in " + where);
          at += size_t(p.item_size);
          continue;
        }
        if (ply_is_float(p.count_type)) corrupt(where + " has a floating-point list count type");
        if (data.size() - at < size_t(p.count_size)) corrupt("the data ends in " + where);
        const long long n = ply_read_count(bytes + at, p.count_type, big);
        at += size_t(p.count_size);
        if (n < 0 || n > max_list_length) corrupt(where + " has list length " + std::to_string(n));
        if ((data.size() - at) / size_t(p.item_size) < size_t(n)) corrupt("the data ends in " + where);
        at += size_t(n) * size_t(p.item_size);
      }
}

// Sends OpenMesh's log and error streams to a string while it reads, and back afterwards. They
// write to std::cerr, std::clog and std::cout, whose buffers are pointed at the string meanwhile:
// OpenMesh's own connect() / disconnect() would leak (disconnect does not delete the target
// connect allocated; found by fuzz/ under LeakSanitizer).
class CaptureOpenMeshOutput {
 public:
  CaptureOpenMeshOutput()
      : err_(std::cerr.rdbuf(captured_.rdbuf())), log_(std::clog.rdbuf(captured_.rdbuf())),
        out_(std::cout.rdbuf(captured_.rdbuf())) {}
  ~CaptureOpenMeshOutput() {
    flush();
    std::cerr.rdbuf(err_), std::clog.rdbuf(log_), std::cout.rdbuf(out_);
  }
  std::string text() {
    flush();
    return captured_.str();
  }

 private:
  static void flush() { omerr().flush(), omlog().flush(), omout().flush(); }
  std::ostringstream captured_;  // first: the buffers below point at it
  std::streambuf *err_, *log_, *out_;
};

std::string first_line(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find('\n', b) - b);
}

bool finite(const OpenMesh::Vec3d& v) {
  for (int k = 0; k < 3; ++k)
    if (!std::isfinite(float(v[k]))) return false;  // GL gets floats
  return true;
}

}  // namespace

MeshFile read_mesh_file(const std::string& path) {
  const std::string name = "mesh file '" + path + "'";
  std::error_code ec;
  const auto status = fs::status(path, ec);
  if (!fs::exists(status)) throw std::runtime_error(name + " does not exist");
  if (!fs::is_regular_file(status)) throw std::runtime_error(name + " is not a regular file");
  std::string ext = fs::path(path).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (ext != ".obj" && ext != ".off" && ext != ".ply" && ext != ".stl")
    throw std::runtime_error(name + ": unsupported format '" + ext + "' (.obj, .off, .ply or .stl)");
  const uintmax_t size = fs::file_size(path, ec);
  if (ec) throw std::runtime_error(name + " cannot be read: " + ec.message());
  if (size > max_file_bytes) throw std::runtime_error(name + " is larger than 512 MiB");
  std::string data;
  {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(name + " cannot be opened: " + std::strerror(errno));
    data.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    if (in.bad()) throw std::runtime_error(name + " cannot be read");
  }
  try {
    if (ext == ".obj") check_obj(data);
    if (ext == ".off") check_off(data);
    if (ext == ".ply") check_ply(data);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(name + " is corrupt: " + e.what());
  }

  MeshFile out;
  OpenMesh::IO::Options opt = OpenMesh::IO::Options::VertexNormal;
  bool ok = false;
  std::string log;
  {
    CaptureOpenMeshOutput capture;
    try {
      ok = OpenMesh::IO::read_mesh(out.mesh, path, opt);
    } catch (const std::exception& e) {  // std::bad_alloc and the like from a reader
      throw std::runtime_error(name + " cannot be read by OpenMesh: " + e.what());
    }
    log = capture.text();
  }
  const std::string said = first_line(log);
  if (!ok)
    throw std::runtime_error(name + " cannot be read by OpenMesh" + (said.empty() ? "" : ": " + said));
  // Faces OpenMesh dropped: a mesh that silently loses faces is worse than an error.
  if (log.find("invalid vertex index") != std::string::npos || log.find("could not be added") != std::string::npos)
    throw std::runtime_error(name + " is corrupt: OpenMesh dropped faces (" + said + ")");
  if (out.mesh.n_faces() == 0) throw std::runtime_error(name + " has no faces");
  for (auto v : out.mesh.vertices())
    if (!finite(out.mesh.point(v)))
      throw std::runtime_error(name + ": vertex " + std::to_string(v.idx()) + " has a coordinate that is not a finite float");
  out.has_normals = opt.check(OpenMesh::IO::Options::VertexNormal);
  for (auto v : out.mesh.vertices())
    if (out.has_normals && (!finite(out.mesh.normal(v)) || out.mesh.normal(v).sqrnorm() == 0)) out.has_normals = false;
  if (!out.has_normals)  // the property holds whatever the reader left there
    for (auto v : out.mesh.vertices()) out.mesh.set_normal(v, OpenMesh::Vec3d(0, 0, 0));
  if (out.has_normals && ext == ".obj") out.corner_normals = obj_corner_layout(data, out.mesh, name);
  return out;
}

}  // namespace ffc::scene
