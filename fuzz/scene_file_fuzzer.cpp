// libFuzzer target: the scene-file parser (src/scene/file.h) on arbitrary text. Its contract is
// that every problem is a scene::FileError; anything else escaping (another exception, a crash, a
// leak, an out-of-bounds access under AddressSanitizer) is a finding.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "scene/file.h"

#ifndef FFCOMPAT_FUZZ_SCENE_PATH
#error "FFCOMPAT_FUZZ_SCENE_PATH: where the text is said to come from (relative mesh paths resolve from its folder)"
#endif

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    // Named as a file in the shipped scenes' folder, so "meshes/plane.off" and the like resolve and
    // the mesh readers are reached from the scene parser too.
    (void)ffc::scene::parse_scene(text, FFCOMPAT_FUZZ_SCENE_PATH);
  } catch (const ffc::scene::FileError&) {
  }
  return 0;
}
