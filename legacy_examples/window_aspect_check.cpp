// window_aspect_check SHOT.png W H: the screenshot of an example's window of W x H showing a
// sphere must be W x H, and the sphere round and centred: the examples draw a square picture
// (gluPerspective with aspect 1) and the window letterboxes it rather than stretching it.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>

#include "image/image.h"

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: window_aspect_check SHOT.png W H\n");
    return 1;
  }
  try {
    const ffc::image::Image img = ffc::image::read_png(argv[1]);
    const int w = std::atoi(argv[2]), h = std::atoi(argv[3]);
    if (img.width != w || img.height != h) {
      std::fprintf(stderr, "screenshot is %dx%d, not %dx%d\n", img.width, img.height, w, h);
      return 1;
    }
    int x0 = w, x1 = -1, y0 = h, y1 = -1;  // the lit pixels' box
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const uint8_t* p = img.at(x, y);
        if (p[0] + p[1] + p[2] > 0) x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
      }
    const int sw = x1 - x0 + 1, sh = y1 - y0 + 1;
    std::printf("sphere %dx%d at x %d..%d, y %d..%d in %dx%d\n", sw, sh, x0, x1, y0, y1, w, h);
    // Stretched to the window it would be 700/400 = 1.75 times wider than tall; a pixel of
    // rounding either way is allowed, and the box must sit in the middle within two pixels.
    const bool round = x1 >= 0 && std::abs(sw - sh) <= 2;
    const bool centred = std::abs((x0 + x1) - (w - 1)) <= 4;
    if (!round || !centred) {
      std::fprintf(stderr, "the sphere is %s\n", !round ? "not round: the picture was stretched" : "not centred");
      return 1;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "window_aspect_check: %s\n", e.what());
    return 1;
  }
  return 0;
}
