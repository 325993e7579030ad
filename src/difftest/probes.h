// The checkpoint read-back: every glGet value the state tests (tests/state/harness.h) compare,
// read on the current context. The list is the harness's, kept here because the library cannot
// include the tests' GoogleTest header; names soft does not report yet are fuzzed as arguments of
// in-stream glGet calls instead (generator category "get"), so checkpoints stay meaningful.
#pragma once
#include <GL/gl.h>

#include <string>
#include <vector>

namespace ffc::difftest {

enum class Query : unsigned char { Lightfv, Materialfv, Doublev, Floatv, Integerv, IsEnabled };

struct Probe {
  Query q;
  GLenum a, b;  // light or face and pname; pname or cap (b unused)
  int slots;    // values read back, sentinel-initialised (a short write shows as the sentinel)
};

const std::vector<Probe>& probes();
std::string probe_name(const Probe& p);

// Every probe's values in order, then the error the read-back raised as the last value.
std::vector<double> read_back();

// The probe that value i of a read-back belongs to (nullptr for the trailing error).
const Probe* probe_of(size_t i);
// Whether values a and b of slot i agree: floats and doubles within 1e-6 relative to
// max(1, |a|, |b|), integers exactly, the matrices' integers within 1e-6 of 2^31 (Mesa maps them
// like colours), NaN equal to NaN.
bool slot_close(size_t i, double a, double b);

}  // namespace ffc::difftest
