// Mesa (llvmpipe) and soft side by side for picture tests: one context of each, kept for the
// process, and the comparison of two pictures channel by channel.
#pragma once
#include <gtest/gtest.h>

#include <cstdlib>
#include <functional>
#include <memory>
#include <string>

#include "backends/backend.h"
#include "gl/dispatch.h"

namespace ffc::picture_test {

struct Pair {
  std::unique_ptr<backends::Backend> mesa = backends::make("mesa"), soft = backends::make("soft");
  int size;
  explicit Pair(int s) : size(s) { mesa->begin(s, s), soft->begin(s, s); }
};
inline Pair& pair(int size) {
  static Pair* p = new Pair(size);  // never destroyed: Mesa's exit handlers stop llvmpipe first
  return *p;
}

// How far two pictures are apart: pixels with a channel more than one step off, pixels not
// identical, pixels drawn (not black) in Mesa's; the first far pixel described.
struct Difference {
  int far = 0, inexact = 0, drawn = 0;
  std::string first;
};
inline Difference compare(const image::Image& m, const image::Image& s, const std::string& label) {
  Difference d;
  for (int y = 0; y < m.height; ++y)
    for (int x = 0; x < m.width; ++x) {
      const uint8_t *p = m.at(x, y), *q = s.at(x, y);
      d.drawn += (p[0] | p[1] | p[2]) != 0;
      bool far = false, inexact = false;
      for (int k = 0; k < 4; ++k) {
        far |= std::abs(int(p[k]) - int(q[k])) > 1;
        inexact |= p[k] != q[k];
      }
      d.inexact += inexact;
      if (far && d.far++ == 0) {
        d.first = label + " pixel " + std::to_string(x) + "," + std::to_string(y) + ": Mesa";
        for (int k = 0; k < 4; ++k) d.first += " " + std::to_string(p[k]);
        d.first += ", soft";
        for (int k = 0; k < 4; ++k) d.first += " " + std::to_string(q[k]);
      }
    }
  return d;
}

// Draws `draw(seed)` on both from a fresh default state and compares.
inline Difference run_both(int size, int seed, const std::function<void(int)>& draw) {
  Pair& p = pair(size);
  image::Image pic[2];
  backends::Backend* be[2] = {p.mesa.get(), p.soft.get()};
  for (int b = 0; b < 2; ++b) {
    be[b]->begin(size, size);
    draw(seed);
    pic[b] = be[b]->read();
  }
  return compare(pic[0], pic[1], "case " + std::to_string(seed));
}

// Cases 0 .. count-1 of `draw`: cases with a far pixel, pixels not identical and pixels drawn, in
// all; the first case that differs described.
struct Tally {
  int far_cases = 0, inexact = 0, drawn = 0;
  std::string first;
};
inline Tally run_cases(int size, int count, const std::function<void(int)>& draw) {
  Tally t;
  for (int seed = 0; seed < count; ++seed) {
    const Difference d = run_both(size, seed, draw);
    t.far_cases += d.far > 0, t.inexact += d.inexact, t.drawn += d.drawn;
    if (d.inexact && t.first.empty())
      t.first = "case " + std::to_string(seed) + ": " + std::to_string(d.inexact) + " pixels not identical, " +
                std::to_string(d.far) + " more than one step apart " + d.first;
  }
  return t;
}

}  // namespace ffc::picture_test
