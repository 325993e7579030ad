// A 16x16 raster State whose draws count in `counts`, as a context's own (raster::Counters).
#pragma once
#include "raster/raster.h"

namespace ffc::test {

inline raster::State counted_state(raster::Counters& counts) {
  raster::State s;
  s.counters = &counts;
  s.viewport = {0, 0, 16, 16};
  s.fb_height = 16;
  return s;
}

}  // namespace ffc::test
