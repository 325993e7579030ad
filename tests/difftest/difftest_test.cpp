// The differential tester's parts: the generator is a function of its seed, streams survive the
// text format, the shrinker finds a planted minimal list, a crash or hang in a child is a result,
// and a known deviation is recognised on real runs of both sides.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "difftest/compare.h"
#include "difftest/fuzz.h"
#include "difftest/generator.h"
#include "difftest/known.h"
#include "difftest/runner.h"
#include "difftest/shrink.h"
#include "difftest/stream.h"
#include "state/display_list.h"

namespace ffc::difftest {
namespace {

Arg n(double v) { return Arg::number(v); }

bool has_call(const Stream& s, const std::string& name) {
  return std::any_of(s.begin(), s.end(), [&](const Call& c) { return name_of(c) == name; });
}

TEST(Generator, SameSeedSameStream) {
  GenOptions o;
  for (uint64_t seed : {1ull, 2ull, 99ull}) {
    const Stream a = generate(seed, o), b = generate(seed, o);
    EXPECT_EQ(a, b) << "seed " << seed;
    EXPECT_GE(a.size(), size_t(o.calls));
  }
  EXPECT_NE(generate(1, o), generate(2, o));
  EXPECT_NE(stream_seed(1, 0), stream_seed(1, 1));
  EXPECT_NE(stream_seed(1, 0), stream_seed(2, 0));
}

TEST(Generator, CategoriesAreHonoured) {
  GenOptions o;
  o.categories = select_categories({"state", "lighting"}, {});
  for (uint64_t seed = 0; seed < 20; ++seed) {
    const Stream s = generate(seed, o);
    EXPECT_FALSE(has_call(s, "glBegin") || has_call(s, "glDrawArrays") || has_call(s, "glMatrixMode") ||
                 has_call(s, "glRasterPos2f") || has_call(s, "glReadPixels"))
        << to_c(s);
    EXPECT_EQ(name_of(s.back()), "checkpoint");
  }
  o.categories = select_categories({}, {"rasterpos"});
  EXPECT_EQ(o.categories.count("rasterpos"), 0u);
  EXPECT_EQ(o.categories.count("arrays"), 1u);
  EXPECT_THROW(select_categories({"no-such"}, {}), std::invalid_argument);
}

TEST(Stream, TextRoundTrip) {
  GenOptions o;  // every category: NaN, infinities, arrays of every type, output buffers
  for (uint64_t seed = 0; seed < 30; ++seed) {
    const Stream s = generate(stream_seed(5, seed), o);
    const std::string text = to_text(s);
    EXPECT_EQ(parse_text(text), s) << text;
    EXPECT_EQ(to_text(parse_text(text)), text);
  }
}

TEST(Stream, TextFormatByHand) {
  const Stream s = parse_text(
      "# a comment\n"
      "glLightfv GL_LIGHT1 GL_POSITION float[1 -2.5 nan inf]\n"
      "glClear GL_COLOR_BUFFER_BIT|GL_DEPTH_BUFFER_BIT\n"
      "glFeedbackBuffer 64 GL_3D_COLOR out[64]\n"
      "glDrawElements GL_TRIANGLES 3 GL_UNSIGNED_SHORT ushort[0 1 2]\n"
      "glFeedbackBuffer 0 GL_3D null\n"
      "checkpoint\n");
  ASSERT_EQ(s.size(), 6u);
  EXPECT_EQ(name_of(s[0]), "glLightfv");
  EXPECT_EQ(s[0].args[0].num, GL_LIGHT1);
  EXPECT_TRUE(std::isnan(s[0].args[2].blob[2]));
  EXPECT_EQ(s[1].args[0].num, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  EXPECT_EQ(s[2].args[2].kind, Arg::Kind::Out);
  EXPECT_EQ(s[3].args[3].type, GLenum(GL_UNSIGNED_SHORT));
  EXPECT_EQ(s[4].args[2].kind, Arg::Kind::Null);
  const std::string c = to_c(s);
  EXPECT_NE(c.find("glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);"), std::string::npos) << c;
  EXPECT_NE(c.find("{1, -2.5, NAN, INFINITY}"), std::string::npos) << c;
  EXPECT_NE(c.find("static GLfloat a1[64];"), std::string::npos) << c;
  EXPECT_THROW(parse_text("glBegin\n"), std::invalid_argument);           // wrong count
  EXPECT_THROW(parse_text("glNoSuch 1\n"), std::invalid_argument);        // unknown function
  EXPECT_THROW(parse_text("glBegin GL_NOPE\n"), std::invalid_argument);   // unknown enum
  EXPECT_THROW(parse_text("glLightfv 1 2 float[1 2\n"), std::invalid_argument);
}

TEST(Shrink, PlantedPairIsFound) {
  // A "mismatch" that needs glFrontFace(GL_CW) somewhere before glCullFace(GL_FRONT), planted in a
  // generated stream; every other call is noise the shrinker must drop.
  Stream s = generate(3, GenOptions{});
  const Call front = make_call("glFrontFace", {n(GL_CW)}), cull = make_call("glCullFace", {n(GL_FRONT)});
  s.insert(s.begin() + long(s.size() / 3), front);
  s.insert(s.begin() + long(2 * s.size() / 3), cull);
  auto fails = [&](const Stream& t) {
    auto f = std::find(t.begin(), t.end(), front);
    return f != t.end() && std::find(f, t.end(), cull) != t.end();
  };
  ASSERT_TRUE(fails(s));
  const Stream small = shrink(s, fails);
  EXPECT_EQ(small, (Stream{front, cull})) << to_c(small);
}

TEST(Shrink, NumbersAreSimplified) {
  Stream s = {make_call("glLineWidth", {n(3.5)}), make_call("glClearDepth", {n(0.7)}),
              make_call("glLightfv", {n(GL_LIGHT0), n(GL_DIFFUSE), Arg::values(GL_FLOAT, {0.3, 0.6, 2.5, 1})})};
  // Fails while the width is positive and the light's blue is above 2.
  auto fails = [](const Stream& t) {
    bool width = false, blue = false;
    for (const Call& c : t) {
      if (name_of(c) == "glLineWidth") width = c.args[0].num > 0;
      if (name_of(c) == "glLightfv") blue = c.args[2].blob[2] > 2;
    }
    return width && blue;
  };
  const Stream small = shrink(s, fails);
  ASSERT_EQ(small.size(), 2u) << to_c(small);
  EXPECT_EQ(small[0].args[0].num, 1);  // 3.5 -> 1 (0 no longer fails)
  EXPECT_EQ(small[1].args[2].blob, (std::vector<double>{0, 0, 3, 0}));  // 2.5 rounds to 3
}

TEST(Runner, CrashInTheChildIsReported) {
  const Stream s = {make_call("glEnable", {n(GL_LIGHTING)}), make_call("glFlush", {}), make_call("glFinish", {})};
  RunOptions o;
  o.crash_at = 1;
  for (Side side : {Side::Mesa, Side::Soft}) {
    const SideResult r = run_side(s, side, o);
    EXPECT_EQ(r.status, SideResult::Status::Crashed) << side_name(side);
    EXPECT_EQ(r.call, 1);
    EXPECT_NE(r.what.find("signal 11"), std::string::npos) << r.what;
  }
  SideResult ok = run_side(s, Side::Mesa, {});
  const SideResult crashed = run_side(s, Side::Soft, o);
  const auto m = compare(s, ok, crashed);
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].key, "crash soft glFlush");
}

TEST(Runner, HangInTheChildIsReported) {
  const Stream s = {make_call("glEnable", {n(GL_LIGHTING)}), make_call("glFlush", {})};
  RunOptions o;
  o.hang_at = 1;
  o.timeout = 1.5;
  const SideResult r = run_side(s, Side::Soft, o);
  EXPECT_EQ(r.status, SideResult::Status::Hung);
  EXPECT_EQ(r.call, 1);
  EXPECT_LT(r.seconds, 10);
}

TEST(Runner, BothSidesAgreeOnErrorsAndState) {
  const Stream s = {make_call("glEnable", {n(0x1234)}),  // GL_INVALID_ENUM on both
                    make_call("glLightf", {n(GL_LIGHT0), n(GL_SPOT_CUTOFF), n(45)}),
                    make_call("glGetLightfv", {n(GL_LIGHT0), n(GL_SPOT_CUTOFF), Arg::out(4)}),
                    make_call("checkpoint", {})};
  const SideResult mesa = run_side(s, Side::Mesa), soft = run_side(s, Side::Soft);
  ASSERT_EQ(mesa.status, SideResult::Status::Ok) << mesa.what;
  ASSERT_EQ(soft.status, SideResult::Status::Ok) << soft.what;
  EXPECT_EQ(mesa.errors[0], GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(soft.errors[0], GLenum(GL_INVALID_ENUM));
  ASSERT_EQ(mesa.outputs.size(), 1u);
  EXPECT_EQ(mesa.outputs[0].values[0], 45);
  EXPECT_EQ(mesa.checkpoints.size(), 1u);
  EXPECT_EQ(mesa.pixels.size(), size_t(32 * 32 * 4));
  EXPECT_TRUE(compare(s, mesa, soft).empty());
  // A difference planted in soft's results is a mismatch of its kind, at its call.
  SideResult changed = soft;
  changed.errors[1] = GL_INVALID_VALUE;
  changed.outputs[0].values[0] = 44;
  const auto m = compare(s, mesa, changed);
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m[0].key, "error glLightf");
  EXPECT_EQ(m[0].call, 1);
  EXPECT_EQ(m[1].kind, "output");
}

TEST(Known, NegativeStrideIsExplainedByName) {
  // Mesa sets the array despite the error (tests/state/errors_test.cpp pins it); the checkpoint
  // then reads a different GL_VERTEX_ARRAY_SIZE, which the table must explain.
  const Stream s = {make_call("glVertexPointer", {n(2), n(GL_FLOAT), n(-1), Arg::values(GL_FLOAT, {0, 0, 1, 1})}),
                    make_call("checkpoint", {})};
  const Checked c = check(s, {});
  EXPECT_TRUE(c.unexplained.empty()) << (c.unexplained.empty() ? "" : c.unexplained[0].key);
  ASSERT_FALSE(c.explained.empty());
  for (const auto& [m, name] : c.explained) EXPECT_EQ(name, "mesa-negative-stride-applied") << m.key;
}

// An enabled vertex array never given a pointer, drawn by a GL_COMPILE_AND_EXECUTE list: Mesa
// reads address 0 and crashes (repro null_vertex_array_list_crash); named. Not with a pointer
// given, nor for a draw of no vertex.
TEST(Known, NullArrayCrashIsNamedOnlyWhereAnArrayHadNoPointer) {
  const Stream s = {make_call("glEnableClientState", {n(GL_VERTEX_ARRAY)}), make_call("glNewList", {n(2), n(GL_COMPILE_AND_EXECUTE)}),
                    make_call("glDrawArrays", {n(GL_TRIANGLE_STRIP), n(0), n(2)})};
  const Checked c = check(s, {});
  EXPECT_TRUE(c.unexplained.empty()) << (c.unexplained.empty() ? "" : c.unexplained[0].key);
  ASSERT_FALSE(c.explained.empty());
  EXPECT_EQ(c.explained[0].first.kind, "crash");
  EXPECT_EQ(c.explained[0].second, "soft-null-array-pointer-crash");
  // The same crash, planted, after a pointer was given or with a draw of no vertex: not this name.
  const Mismatch crash{"crash", "crash mesa glDrawArrays", 3, ""};
  SideResult mesa, soft;
  soft.errors.assign(4, GL_NO_ERROR), mesa.errors = soft.errors;
  Stream given = {s[0], make_call("glVertexPointer", {n(2), n(GL_FLOAT), n(0), Arg::values(GL_FLOAT, {0, 0, 1, 1})}), s[1], s[2]};
  const KnownDeviation* named = explain(given, crash, mesa, soft);
  EXPECT_TRUE(named == nullptr || named->name != "soft-null-array-pointer-crash");
  Stream none = {s[0], s[1], make_call("glDrawArrays", {n(GL_TRIANGLE_STRIP), n(0), n(0)}), make_call("glFinish", {})};
  named = explain(none, crash, mesa, soft);
  EXPECT_TRUE(named == nullptr || named->name != "soft-null-array-pointer-crash");
}

TEST(Known, NegativeStrideHiddenInsideExecutingBegin) {
  // Seed 577215 stream 11801004284260778288: the glVertexPointer runs while GL_COMPILE_AND_EXECUTE's
  // executing side is inside the list's wrapped glBegin, where glGetError returns no error on either
  // side; Mesa sets the array all the same, and the table must still name it.
  const Stream s = {make_call("glNewList", {n(1), n(GL_COMPILE_AND_EXECUTE)}), make_call("glBegin", {n(GL_QUAD_STRIP)}),
                    make_call("glVertex3f", {n(0), n(0), n(0)}), make_call("glColor3fv", {Arg::values(GL_FLOAT, {0, 0, 0})}),
                    make_call("glVertexPointer", {n(2), n(GL_SHORT), n(-1), Arg::values(GL_SHORT, {0, 0, 1, 1})}),
                    make_call("checkpoint", {})};
  const Checked c = check(s, {});
  EXPECT_TRUE(c.unexplained.empty()) << (c.unexplained.empty() ? "" : c.unexplained[0].key);
  ASSERT_FALSE(c.explained.empty());
  for (const auto& [m, name] : c.explained) EXPECT_EQ(name, "mesa-negative-stride-applied") << m.key;
  // Not a pointer call soft refused for another reason with Mesa showing nothing (soft's own error
  // shows), nor one with a stride that is not negative.
  const Mismatch size{"state", "state glGetIntegerv(GL_VERTEX_ARRAY_SIZE)", 5, ""};
  SideResult refused = c.soft;
  refused.errors[4] = GL_INVALID_OPERATION;
  EXPECT_EQ(explain(s, size, c.mesa, refused), nullptr);
  Stream positive = s;
  positive[4].args[2] = n(4);
  EXPECT_EQ(explain(positive, size, c.mesa, c.soft), nullptr);
}

TEST(Known, ListMaterialfColourIsNamedAlone) {
  // Mesa's garbage differs from run to run, so the recogniser is asked directly: the compiled
  // glMaterialf(GL_FRONT, GL_AMBIENT_AND_DIFFUSE) explains GL_FRONT's ambient and diffuse read back
  // after the list; not GL_BACK's, not its specular, not the same call outside a list, not a
  // compiled glMaterialf(GL_SHININESS) (both sides agree on it).
  const auto stream = [](bool listed, GLenum pname) {
    Stream s;
    if (listed) s.push_back(make_call("glNewList", {n(4), n(GL_COMPILE)}));
    s.push_back(make_call("glMaterialf", {n(GL_FRONT), n(pname), n(76)}));
    if (listed) s.push_back(make_call("glEndList", {})), s.push_back(make_call("glCallList", {n(4)}));
    s.push_back(make_call("checkpoint", {}));
    return s;
  };
  const auto read = [](const Stream& s, const char* what) {
    return Mismatch{"state", std::string("state glGetMaterialfv(") + what + ")", int(s.size()) - 1, ""};
  };
  SideResult ok;
  ok.errors.assign(8, GL_NO_ERROR);
  const auto named = [&](const Stream& s, const Mismatch& m) {
    const KnownDeviation* d = explain(s, m, ok, ok);
    return d && d->name == "mesa-list-materialf-colour-unwritten";
  };
  const Stream listed = stream(true, GL_AMBIENT_AND_DIFFUSE);
  EXPECT_TRUE(named(listed, read(listed, "GL_FRONT, GL_AMBIENT")));
  EXPECT_TRUE(named(listed, read(listed, "GL_FRONT, GL_DIFFUSE")));
  EXPECT_TRUE(named(listed, Mismatch{"pixels", "pixels", int(listed.size()) - 1, ""}));
  EXPECT_FALSE(named(listed, read(listed, "GL_BACK, GL_AMBIENT")));
  EXPECT_FALSE(named(listed, read(listed, "GL_FRONT, GL_SPECULAR")));
  const Stream outside = stream(false, GL_AMBIENT_AND_DIFFUSE);
  EXPECT_FALSE(named(outside, read(outside, "GL_FRONT, GL_AMBIENT")));
  const Stream shininess = stream(true, GL_SHININESS);
  EXPECT_FALSE(named(shininess, read(shininess, "GL_FRONT, GL_SHININESS")));
}

TEST(Known, CurrentValuesReadByTheStreamsGet) {
  // Row 65's current colour read by the stream's own glGetFloatv (an output, seed 577215 stream
  // 5988082728378332109) is named as at a checkpoint; another value read so is not, nor the colour
  // where soft's model met no wrapped line loop.
  const Stream s = {make_call("glGetFloatv", {n(GL_CURRENT_COLOR), Arg::out(16)}), make_call("checkpoint", {})};
  SideResult mesa, soft;
  mesa.errors.assign(2, GL_NO_ERROR), soft.errors = mesa.errors;
  soft.deviations = {state::kListLineLoopCurrent};
  const Mismatch colour{"output", "output glGetFloatv(GL_CURRENT_COLOR)", 0, ""};
  const KnownDeviation* d = explain(s, colour, mesa, soft);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->name, "mesa-list-line-loop-wrap-current");
  EXPECT_EQ(explain(s, Mismatch{"output", "output glGetFloatv(GL_MODELVIEW_MATRIX)", 0, ""}, mesa, soft), nullptr);
  soft.deviations.clear();
  EXPECT_EQ(explain(s, colour, mesa, soft), nullptr);
}

TEST(Known, MaterialAfterLastPointIsNamedAlone) {
  // Seed 161803 stream 2269: a glMaterialf after the last vertex of a list's GL_POINTS leaves a vertex
  // list with the material and no vertex (row 55); the shininess read back after glCallList is named.
  // Not where the material comes before the vertex, nor after the last vertex of a GL_LINE_STRIP
  // (its wrap copies the vertex).
  const auto stream = [](GLenum mode, bool after) {
    Stream s = {make_call("glNewList", {n(5), n(GL_COMPILE)}), make_call("glBegin", {n(mode)})};
    const Call material = make_call("glMaterialf", {n(GL_FRONT), n(GL_SHININESS), n(1)});
    if (!after) s.push_back(material);
    s.push_back(make_call("glVertex3f", {n(0), n(0), n(0)}));
    if (after) s.push_back(material);
    for (const char* f : {"glEnd", "glEndList"}) s.push_back(make_call(f, {}));
    s.push_back(make_call("glCallList", {n(5)}));
    s.push_back(make_call("checkpoint", {}));
    return s;
  };
  SideResult ok;
  ok.errors.assign(8, GL_NO_ERROR);
  const auto named = [&](const Stream& s, const char* what) {
    const Mismatch m{"state", std::string("state glGetMaterialfv(") + what + ")", int(s.size()) - 1, ""};
    const KnownDeviation* d = explain(s, m, ok, ok);
    return d && d->name == "mesa-list-primitive-without-vertex";
  };
  EXPECT_TRUE(named(stream(GL_POINTS, true), "GL_FRONT, GL_SHININESS"));
  EXPECT_FALSE(named(stream(GL_POINTS, false), "GL_FRONT, GL_SHININESS"));
  EXPECT_FALSE(named(stream(GL_LINE_STRIP, true), "GL_FRONT, GL_SHININESS"));
}

TEST(Known, CurrentUndefinedAfterDrawOnlyWithItsArrayOn) {
  // GL 2.1 section 2.8 leaves the current normal indeterminate after a draw only with the normal
  // array enabled. A draw with no normal array (seed 299792 stream 6292637399379987596), or with it
  // enabled and then disabled, or followed by a glNormal3f, leaves it defined: not named.
  const auto stream = [](bool enable, bool disable, bool normal_after) {
    Stream s;
    if (enable) s.push_back(make_call("glEnableClientState", {n(GL_NORMAL_ARRAY)}));
    if (disable) s.push_back(make_call("glDisableClientState", {n(GL_NORMAL_ARRAY)}));
    s.push_back(make_call("glDrawArrays", {n(GL_POINTS), n(0), n(0)}));
    if (normal_after) s.push_back(make_call("glNormal3f", {n(0), n(0), n(1)}));
    s.push_back(make_call("checkpoint", {}));
    return s;
  };
  SideResult ok;
  ok.errors.assign(8, GL_NO_ERROR);
  const auto named = [&](const Stream& s, const char* key) {
    const KnownDeviation* d = explain(s, Mismatch{"state", key, int(s.size()) - 1, ""}, ok, ok);
    return d && d->name == "current-undefined-after-draw";
  };
  EXPECT_TRUE(named(stream(true, false, false), "state glGetDoublev(GL_CURRENT_NORMAL)"));
  EXPECT_FALSE(named(stream(true, false, false), "state glGetDoublev(GL_CURRENT_COLOR)"));
  EXPECT_FALSE(named(stream(false, false, false), "state glGetDoublev(GL_CURRENT_NORMAL)"));
  EXPECT_FALSE(named(stream(true, true, false), "state glGetDoublev(GL_CURRENT_NORMAL)"));
  EXPECT_FALSE(named(stream(true, false, true), "state glGetDoublev(GL_CURRENT_NORMAL)"));
}

}  // namespace
}  // namespace ffc::difftest
