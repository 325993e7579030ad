// What specialisation buys: the generic lighting kernel (every choice read from the key per
// vertex) against the kernel compiled for the key's shape, on 4096 vertices of an icosphere.
//   build/bench/lighting_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "lighting/lighting.h"
#include "mesh/icosphere.h"

namespace {

using namespace ffc::lighting;

struct Scene {
  Prepared<float> prepared;
  std::vector<glm::vec4> p, color;
  std::vector<glm::vec3> n;
  std::vector<Lit<float>> out;
};

// The icosphere at depth 4 (2562 vertices), repeated to 4096, 4 units in front of the eye.
Scene make_scene(int lights, bool point, bool specular) {
  Scene s;
  const auto mesh = ffc::mesh::make_icosphere(4);
  for (size_t i = 0; i < 4096; ++i) {
    const auto q = mesh.point(mesh.vertex_handle(int(i % mesh.n_vertices())));
    s.n.emplace_back(q[0], q[1], q[2]);
    s.p.emplace_back(q[0], q[1], q[2] - 4, 1);
    s.color.emplace_back(1, 0.5, 0.25, 1);
  }
  s.out.resize(s.p.size());
  LightParams l[8];
  MaterialParams m[2];
  ModelParams model;
  for (int i = 0; i < lights; ++i) {
    l[i].enabled = true;
    l[i].diffuse = glm::dvec4(0.8, 0.7, 0.6, 1) / double(lights);
    l[i].ambient = glm::dvec4(0.1, 0.1, 0.1, 1);
    l[i].specular = specular ? glm::dvec4(1) : glm::dvec4(0, 0, 0, 1);
    l[i].position = point ? glm::dvec4(3 * std::cos(i), 4, 5 * std::sin(i + 1), 1) : glm::dvec4(std::cos(i), 1, 1, 0);
  }
  m[0].specular = m[1].specular = specular ? glm::dvec4(1) : glm::dvec4(0, 0, 0, 1);
  m[0].shininess = 10;
  s.prepared = prepare<float>(l, m, model, make_key(l, m, model, false, false));
  return s;
}

void run(benchmark::State& state, Kernel<float> kernel, Scene& s) {
  for (auto _ : state) {
    kernel(s.prepared, s.p.data(), s.n.data(), s.color.data(), s.p.size(), s.out.data());
    benchmark::DoNotOptimize(s.out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(s.p.size()));
}

// args: lights, point light (0/1), specular (0/1)
void BM_Generic(benchmark::State& st) {
  Scene s = make_scene(int(st.range(0)), st.range(1), st.range(2));
  run(st, generic<float>(), s);
}
void BM_Specialised(benchmark::State& st) {
  Scene s = make_scene(int(st.range(0)), st.range(1), st.range(2));
  run(st, specialised<float>(s.prepared.key), s);
}

#define FFC_CASES ->Args({1, 0, 0})->Args({1, 0, 1})->Args({1, 1, 1})->Args({8, 0, 1})->Args({8, 1, 1})
BENCHMARK(BM_Generic) FFC_CASES->ArgNames({"lights", "point", "specular"});
BENCHMARK(BM_Specialised) FFC_CASES->ArgNames({"lights", "point", "specular"});

}  // namespace

BENCHMARK_MAIN();
