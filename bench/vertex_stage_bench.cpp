// The float vertex stage's figure: lit vertices per second on one core, per SIMD target and
// lighting key. Each iteration runs what the stage does to a batch after the fetch
// (vertex_stage.cpp's run_columns): positions to clip and eye space, normals to eye space
// (normalized), the lighting (one light; lighting_simd.cpp), on the depth-4 icosphere's 2562
// vertices repeated to 4096, in batches of 64 as the stage runs them.
//   BM_Batches: as run_columns holds them, each batch's eye positions, normals and colours in
//     64-vertex buffers that stay in the L1 cache (StageOut), the clip positions into the draw's
//     array (the list);
//   BM_Stage: every column 4096 vertices long (27 columns, in the L2 cache): the figure this bench
//     reported first, bound by the cache more than by the kernels;
//   BM_Lighting: the lighting alone on BM_Stage's columns;
//   BM_ScalarLighting: the scalar float kernel alone (AoS, specialised per key), whose bits every
//     target reproduces.
// Keys (the `key` argument): 0 directional, 1 directional with specular, 2 point, 3 point with
// specular, 4 point with attenuation, 5 directional two-sided, 6 directional with colour material
// (GL_AMBIENT_AND_DIFFUSE).
//   build/bench/vertex_stage_bench --benchmark_filter=BM_Batches --benchmark_repetitions=5
//     --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

#include "lighting/lighting.h"
#include "lighting/lighting_simd.h"
#include "mesh/icosphere.h"
#include "simd/target.h"
#include "state/vertex_stage.h"

namespace {

using namespace ffc::lighting;
constexpr size_t kVertices = 4096, kBatch = kSoaPad;

struct Scene {
  Prepared<float> prepared;
  glm::mat4 mvp, mv;
  glm::dmat3 inv{1.0};
  std::vector<float> obj[4], color[4], eye[4], normal[3], lit[16];
  std::vector<double> raw[3];
  std::vector<glm::vec4> clip, p, c;
  std::vector<glm::vec3> n;
  std::vector<Lit<float>> out;
};

// One light (the key above); the icosphere 4 units in front of the eye under a perspective
// projection.
Scene make_scene(int key) {
  const bool point = key >= 2 && key <= 4, specular = key == 1 || key == 3;
  Scene s;
  const auto mesh = ffc::mesh::make_icosphere(4);
  for (auto& v : s.obj) v.resize(kVertices);
  for (auto& v : s.color) v.assign(kVertices, 0.5f);
  for (auto& v : s.eye) v.resize(kVertices);
  for (auto& v : s.normal) v.resize(kVertices);
  for (auto& v : s.lit) v.resize(kVertices);
  for (auto& v : s.raw) v.resize(kVertices);
  s.clip.resize(kVertices);
  for (size_t i = 0; i < kVertices; ++i) {
    const auto q = mesh.point(mesh.vertex_handle(int(i % mesh.n_vertices())));
    for (int k = 0; k < 3; ++k) s.obj[k][i] = float(q[k]), s.raw[k][i] = q[k];
    s.obj[3][i] = 1;
    s.p.emplace_back(q[0], q[1], q[2] - 4, 1);
    s.n.emplace_back(q[0], q[1], q[2]);
    s.c.emplace_back(0.5f);
  }
  s.out.resize(kVertices);
  s.mv = glm::mat4(1), s.mv[3][2] = -4;
  glm::mat4 proj(0);  // a frustum: near 1, far 10, 90 degrees
  proj[0][0] = proj[1][1] = 1, proj[2][2] = -11.f / 9, proj[2][3] = -1, proj[3][2] = -20.f / 9;
  s.mvp = proj * s.mv;
  LightParams l[8];
  MaterialParams m[2];
  ModelParams model;
  l[0].enabled = true;
  l[0].diffuse = glm::dvec4(0.8, 0.7, 0.6, 1);
  l[0].specular = specular ? glm::dvec4(1) : glm::dvec4(0, 0, 0, 1);
  l[0].position = point ? glm::dvec4(3, 4, 5, 1) : glm::dvec4(1, 1, 1, 0);
  m[0].specular = m[1].specular = specular ? glm::dvec4(1) : glm::dvec4(0, 0, 0, 1);
  m[0].shininess = 10;
  if (key == 4) l[0].constant_attenuation = 0.5, l[0].linear_attenuation = 0.1, l[0].quadratic_attenuation = 0.02;
  model.two_side = key == 5;
  model.color_material = key == 6;
  s.prepared = prepare<float>(l, m, model, make_key(l, m, model, true, false));
  return s;
}

void lighting_only(Scene& s, size_t b) {
  const SoaIn in{{s.eye[0].data() + b, s.eye[1].data() + b, s.eye[2].data() + b, s.eye[3].data() + b},
                 {s.normal[0].data() + b, s.normal[1].data() + b, s.normal[2].data() + b},
                 {s.color[0].data() + b, s.color[1].data() + b, s.color[2].data() + b, s.color[3].data() + b}};
  SoaOut out;
  for (int k = 0; k < 16; ++k) out.col[k >> 3][k >> 2 & 1][k & 3] = s.lit[k].data() + b;
  light_soa(s.prepared, in, kBatch, out);
}

// The stage as run_columns runs it: the batch's columns in buffers of its own (L1), the clip
// positions into the draw's array.
void batch(Scene& s, size_t b) {
  constexpr size_t P = kSoaPad;
  alignas(64) float eye[4][P], normal[3][P], lit[16][P];
  const float* obj[4] = {s.obj[0].data() + b, s.obj[1].data() + b, s.obj[2].data() + b, s.obj[3].data() + b};
  float* eye_cols[4] = {eye[0], eye[1], eye[2], eye[3]};
  ffc::state::transform_columns(s.mvp, &s.mv, obj, kBatch, &s.clip[b], eye_cols, true);
  const double* raw[3] = {s.raw[0].data() + b, s.raw[1].data() + b, s.raw[2].data() + b};
  float* normal_cols[3] = {normal[0], normal[1], normal[2]};
  ffc::state::eye_normal_columns(s.inv, true, 0, raw, kBatch, normal_cols);
  const SoaIn in{{eye[0], eye[1], eye[2], eye[3]},
                 {normal[0], normal[1], normal[2]},
                 {s.color[0].data() + b, s.color[1].data() + b, s.color[2].data() + b, s.color[3].data() + b}};
  SoaOut out;
  for (int k = 0; k < 16; ++k) out.col[k >> 3][k >> 2 & 1][k & 3] = lit[k];
  out.keyed = true;  // as run_columns asks (the columns the key makes)
  light_soa(s.prepared, in, kBatch, out);
  benchmark::DoNotOptimize(lit[0][0]);
}

void stage(Scene& s, size_t b) {
  const float* obj[4] = {s.obj[0].data() + b, s.obj[1].data() + b, s.obj[2].data() + b, s.obj[3].data() + b};
  float* eye[4] = {s.eye[0].data() + b, s.eye[1].data() + b, s.eye[2].data() + b, s.eye[3].data() + b};
  ffc::state::transform_columns(s.mvp, &s.mv, obj, kBatch, &s.clip[b], eye);
  const double* raw[3] = {s.raw[0].data() + b, s.raw[1].data() + b, s.raw[2].data() + b};
  float* normal[3] = {s.normal[0].data() + b, s.normal[1].data() + b, s.normal[2].data() + b};
  ffc::state::eye_normal_columns(s.inv, true, 0, raw, kBatch, normal);
  std::fill(eye[3], eye[3] + kBatch, 1.0f);
  const SoaIn in{{eye[0], eye[1], eye[2], eye[3]},
                 {normal[0], normal[1], normal[2]},
                 {s.color[0].data() + b, s.color[1].data() + b, s.color[2].data() + b, s.color[3].data() + b}};
  SoaOut out;
  for (int k = 0; k < 16; ++k) out.col[k >> 3][k >> 2 & 1][k & 3] = s.lit[k].data() + b;
  light_soa(s.prepared, in, kBatch, out);
}

// args: target (an index into ffc::simd::available()), key (above)
template <void (*Batch)(Scene&, size_t)>
void on_target(benchmark::State& st) {
  const auto targets = ffc::simd::available();
  if (size_t(st.range(0)) >= targets.size()) return st.SkipWithError("no such target here");
  const std::string t = targets[size_t(st.range(0))];
  ffc::simd::restrict(t);
  st.SetLabel(t);
  Scene s = make_scene(int(st.range(1)));
  for (size_t b = 0; b < kVertices; b += kBatch) stage(s, b);  // eye positions and normals for lighting_only
  for (auto _ : st) {
    for (size_t b = 0; b < kVertices; b += kBatch) Batch(s, b);
    benchmark::DoNotOptimize(s.lit[0].data());
    benchmark::ClobberMemory();
  }
  st.SetItemsProcessed(int64_t(st.iterations()) * int64_t(kVertices));
  ffc::simd::restrict("");
}

void BM_Batches(benchmark::State& st) { on_target<batch>(st); }
void BM_Stage(benchmark::State& st) { on_target<stage>(st); }
void BM_Lighting(benchmark::State& st) { on_target<lighting_only>(st); }

void BM_ScalarLighting(benchmark::State& st) {
  Scene s = make_scene(int(st.range(0)));
  const Kernel<float> k = specialised<float>(s.prepared.key);
  for (auto _ : st) {
    k(s.prepared, s.p.data(), s.n.data(), s.c.data(), kVertices, s.out.data());
    benchmark::DoNotOptimize(s.out.data());
    benchmark::ClobberMemory();
  }
  st.SetItemsProcessed(int64_t(st.iterations()) * int64_t(kVertices));
}

constexpr int kKeys = 7;
void StageArgs(benchmark::internal::Benchmark* b) {
  for (int t = 0; t < 6; ++t)
    for (int key = 0; key < kKeys; ++key) b->Args({t, key});
  b->ArgNames({"target", "key"});
}
BENCHMARK(BM_Batches)->Apply(StageArgs);
BENCHMARK(BM_Stage)->Apply(StageArgs);
BENCHMARK(BM_Lighting)->Apply(StageArgs);
BENCHMARK(BM_ScalarLighting)->DenseRange(0, kKeys - 1)->ArgNames({"key"});

}  // namespace

BENCHMARK_MAIN();
