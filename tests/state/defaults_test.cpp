// Defaults: every value the context reports (glGetLightfv for all 8 lights and every pname,
// glGetMaterialfv for GL_FRONT and GL_BACK and every pname, glGetDoublev / glGetFloatv /
// glGetIntegerv for every pname of Context::GetDoublev's list, glIsEnabled for every capability)
// agrees with Mesa's in a fresh context. One row per query.
#include <cctype>

#include "harness.h"

namespace ffc::state_test {
namespace {

// Both sides' read-back of a fresh context, taken once for the whole table.
const std::pair<Snapshot, Snapshot>& fresh() {
  static const std::pair<Snapshot, Snapshot> s = [] {
    fresh_context(kMesa);
    Snapshot m = snapshot();
    fresh_context(kSoft);
    Snapshot f = snapshot();
    return std::make_pair(m, f);
  }();
  return s;
}

// A test name from a probe's name: "glGetLightfv(GL_LIGHT3, GL_SPOT_CUTOFF)" becomes
// "GetLightfv_LIGHT3_SPOT_CUTOFF".
std::string identifier(const Probe& p) {
  std::string in = probe_name(p), out;
  for (size_t i = 0; i < in.size(); ++i) {
    if (in.compare(i, 3, "GL_") == 0 && (i == 0 || !std::isalnum(static_cast<unsigned char>(in[i - 1])))) {
      i += 2;
      continue;
    }
    if (in.compare(i, 2, "gl") == 0 && i == 0) {
      ++i;
      continue;
    }
    const char c = in[i];
    if (std::isalnum(static_cast<unsigned char>(c))) out += c;
    else if (!out.empty() && out.back() != '_') out += '_';
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  return out;
}

class Defaults : public ::testing::TestWithParam<size_t> {};

TEST_P(Defaults, MatchMesa) {
  const size_t index = GetParam();
  const auto& [mesa, soft] = fresh();
  EXPECT_EQ(enum_name(mesa.probe_error), "GL_NO_ERROR") << "Mesa's read-back raised an error";
  EXPECT_EQ(enum_name(soft.probe_error), "GL_NO_ERROR") << "soft's read-back raised an error";
  size_t first = 0;
  for (size_t i = 0; i < index; ++i) first += probes()[i].slots;
  const Probe& p = probes()[index];
  for (int k = 0; k < p.slots; ++k) {
    const double m = mesa.values[first + k], s = soft.values[first + k];
    EXPECT_TRUE(slot_close(first + k, m, s, 1e-6))
        << slot_name(first + k) << ": mesa " << num(m) << ", soft " << num(s);
  }
}

std::vector<size_t> all_probes() {
  std::vector<size_t> v(probes().size());
  for (size_t i = 0; i < v.size(); ++i) v[i] = i;
  return v;
}

INSTANTIATE_TEST_SUITE_P(Fresh, Defaults, ::testing::ValuesIn(all_probes()),
                         [](const ::testing::TestParamInfo<size_t>& info) { return identifier(probes()[info.param]); });

// A few defaults spelled out, so the table above is anchored to the spec and not only to Mesa.
TEST(DefaultsSpelledOut, Gl21Table) {
  fresh_context(kSoft);
  GLfloat v[4];
  glGetLightfv(GL_LIGHT0, GL_DIFFUSE, v);
  EXPECT_EQ(v[0], 1.0f);
  glGetLightfv(GL_LIGHT1, GL_DIFFUSE, v);
  EXPECT_EQ(v[0], 0.0f);
  glGetLightfv(GL_LIGHT5, GL_POSITION, v);
  EXPECT_EQ(v[2], 1.0f);
  glGetLightfv(GL_LIGHT5, GL_SPOT_CUTOFF, v);
  EXPECT_EQ(v[0], 180.0f);
  glGetMaterialfv(GL_BACK, GL_DIFFUSE, v);
  EXPECT_FLOAT_EQ(v[0], 0.8f);
  glGetMaterialfv(GL_FRONT, GL_AMBIENT, v);
  EXPECT_FLOAT_EQ(v[0], 0.2f);
  EXPECT_EQ(glIsEnabled(GL_DITHER), GL_TRUE);
  EXPECT_EQ(glIsEnabled(GL_LIGHTING), GL_FALSE);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace ffc::state_test
