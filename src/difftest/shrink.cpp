#include "difftest/shrink.h"

#include <cmath>

namespace ffc::difftest {

Stream shrink(Stream s, const StillFails& fails, int budget) {
  auto test = [&](const Stream& t) { return budget-- > 0 && fails(t); };
  // ddmin over calls: remove one of n chunks at a time; on success keep the smaller stream and
  // the granularity, otherwise split finer, down to single calls.
  for (size_t n = 2; s.size() > 1 && budget > 0;) {
    const size_t chunk = (s.size() + n - 1) / n;
    bool removed = false;
    for (size_t start = 0; start < s.size() && budget > 0; start += chunk) {
      Stream t(s.begin(), s.begin() + long(start));
      t.insert(t.end(), s.begin() + long(std::min(s.size(), start + chunk)), s.end());
      if (t.size() < s.size() && test(t)) {
        s = std::move(t);
        removed = true;
        break;
      }
    }
    if (removed) {
      n = std::max<size_t>(n - 1, 2);
      continue;
    }
    if (chunk <= 1) break;
    n = std::min(s.size(), n * 2);
  }
  // Simpler numbers: each argument and array element in turn, to 0, then 1, then rounded.
  auto simpler = [](double v) {
    std::vector<double> c;
    for (double x : {0.0, 1.0, std::round(v)})
      if (x != v && !(std::isnan(v) && std::isnan(x)) && (c.empty() || c.back() != x)) c.push_back(x);
    return c;
  };
  for (size_t i = 0; i < s.size() && budget > 0; ++i)
    for (size_t k = 0; k < s[i].args.size() && budget > 0; ++k) {
      Arg& a = s[i].args[k];
      const Param p = functions()[size_t(s[i].fn)].params[k];
      if (a.kind == Arg::Kind::Num) {
        if (p == Param::Enum || p == Param::Bitfield) continue;
        // Enums stay: 0 or 1 in their place is a different call, not a simpler one.
        for (double x : simpler(a.num)) {
          Stream t = s;
          t[i].args[k].num = x;
          if (test(t)) {
            s = std::move(t);
            break;
          }
        }
      } else if (a.kind == Arg::Kind::Blob) {
        // Arrays keep their length: the GL reads as many elements as the call and the array
        // state say, and a shorter array would read past its end in the printed C.
        for (size_t e = 0; e < s[i].args[k].blob.size() && budget > 0; ++e)
          for (double x : simpler(s[i].args[k].blob[e])) {
            Stream t = s;
            t[i].args[k].blob[e] = x;
            if (test(t)) {
              s = std::move(t);
              break;
            }
          }
      }
    }
  return s;
}

}  // namespace ffc::difftest
