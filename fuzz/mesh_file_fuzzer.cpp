// libFuzzer target: a mesh reader (src/scene/mesh_file.h) on arbitrary bytes, written to a file
// with the extension FFCOMPAT_FUZZ_MESH_EXT (one target per format: .obj, .off, .ply, .stl). The
// reader's contract is that every problem is a std::runtime_error naming the file; anything else
// (another exception, a crash, a hang, gigabytes allocated, an out-of-bounds access under
// AddressSanitizer) is a finding.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "scene/mesh_file.h"

#ifndef FFCOMPAT_FUZZ_MESH_EXT
#error "FFCOMPAT_FUZZ_MESH_EXT: the extension the bytes are read as (\".obj\", \".off\", \".ply\" or \".stl\")"
#endif

namespace {

// One file per process (libFuzzer's -jobs/-workers run several), in the temporary directory.
const std::string& scratch_path() {
  static const std::string path = [] {
    const char* dir = std::getenv("TMPDIR");
    return std::string(dir && *dir ? dir : "/tmp") + "/ffcompat-fuzz-" + std::to_string(getpid()) +
           FFCOMPAT_FUZZ_MESH_EXT;
  }();
  return path;
}

struct RemoveAtExit {
  ~RemoveAtExit() { std::remove(scratch_path().c_str()); }
} remove_at_exit;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string& path = scratch_path();
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return 0;
  const bool written = std::fwrite(data, 1, size, f) == size;
  std::fclose(f);
  if (!written) return 0;
  try {
    (void)ffc::scene::read_mesh_file(path);
  } catch (const std::runtime_error&) {
  }
  return 0;
}
