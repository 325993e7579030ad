// Scene files: a Description in TOML (schema at the top of file.cpp and in scenes/README.md).
#pragma once
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

#include "scene/description.h"

namespace ffc::scene {

// Everything wrong with a scene file: TOML syntax, an unknown key, a wrong type, a value outside
// GL's range, an unknown name, a mesh file that is missing or cannot be read. what() is
// "path:line:column: message" (just "path: message" when there is no place in the file to point
// at, e.g. a scene file that cannot be opened).
class FileError : public std::runtime_error {
 public:
  FileError(const std::string& path, int line, int column, const std::string& message);
  const std::string& path() const { return path_; }
  int line() const { return line_; }      // 1-based; 0 when there is no place
  int column() const { return column_; }  // 1-based; 0 when there is no place
  const std::string& message() const { return message_; }

 private:
  std::string path_;
  int line_, column_;
  std::string message_;
};

// Reads and checks a scene file, and the mesh files it names (relative to its folder). Returns the
// Description only when everything is valid; throws FileError otherwise.
Description load_file(const std::string& path);
// The largest scene file load_file reads. Scene files are a page or two of TOML (the shipped ones
// are under 4 KiB); the limit only stops a runaway read (a huge or endless file).
constexpr uintmax_t kMaxSceneFileBytes = uintmax_t(4) << 20;

// The same for TOML text; `path` names it in messages and anchors relative mesh paths.
Description parse_scene(std::string_view toml, const std::string& path);

// Whether a --scene value names a scene file rather than a built-in scene (it ends in .toml).
bool is_scene_file(const std::string& name);

}  // namespace ffc::scene
