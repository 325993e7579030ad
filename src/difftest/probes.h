// The read-back of GL state: every glGet value that the fuzzer compares at its checkpoints and the
// state tests (tests/state/harness.h) compare after each case, read on the current context. One
// list for both: a name added here is checked by both.
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

// The parameters read back: of glGetLightfv, of glGetMaterialfv, of glGet*v, and the capabilities
// glIsEnabled answers for (each also read through glGet*v).
const std::vector<GLenum>& light_pnames();
const std::vector<GLenum>& material_pnames();
const std::vector<GLenum>& get_pnames();
const std::vector<GLenum>& capabilities();
const std::vector<Probe>& probes();
std::string probe_name(const Probe& p);

// Every probe's values in order, then the error the read-back raised as the last value.
std::vector<double> read_back();

// The probe that value i of a read-back belongs to (nullptr for the trailing error).
const Probe* probe_of(size_t i);
// Whether values a and b of slot i agree: floats and doubles within rel relative to
// max(1, |a|, |b|), integers exactly but for those GL maps from floats (colours, normals, depths;
// Mesa maps the matrices the same way): within rel of 2^31; NaN equal to NaN.
bool slot_close(size_t i, double a, double b, double rel = 1e-6);

}  // namespace ffc::difftest
