// Chapter 12 benchmarks: the cost of sampling each BSDF model (direction, value, pdf and
// weight). Run: build/chapters/12_materials/ch12_bench
#include <benchmark/benchmark.h>

#include <vector>

#include "11_sampling/rng.h"
#include "11_sampling/warp.h"
#include "12_materials/bsdf.h"

using namespace rtk;

namespace {

BsdfModel model(int which) {
  const Color eta{0.19f, 0.45f, 1.50f}, k{3.06f, 2.40f, 1.88f};
  switch (which) {
    case 0:
      return Lambertian{Color(0.5f)};
    case 1:
      return SmoothConductor{eta, k};
    case 2:
      return RoughConductor{eta, k, GgxDistribution{0.2f}};
    case 3:
      return SmoothDielectric{1.5f, Color(1)};
    case 4:
      return ThinDielectric{1.5f, Color(0.9f), 0.1f};
    case 5:
      return Plastic{Color(0.5f), 1.5f, GgxDistribution{0.0f}};
    case 6:
      return Plastic{Color(0.5f), 1.5f, GgxDistribution{0.2f}};
    case 7:
      return Velvet{};
    default:
      return MetallicPaint{Color(0.5f, 0.1f, 0.1f), Color(0.3f), 1.45f, GgxDistribution{0.2f}};
  }
}
const char* kNames[] = {"Lambertian",       "SmoothConductor", "RoughConductor a=0.2",
                        "SmoothDielectric", "ThinDielectric",  "Plastic smooth",
                        "Plastic a=0.2",    "Velvet",          "MetallicPaint glitter a=0.2"};

void BM_bsdf_sample(benchmark::State& state) {
  const Bsdf bsdf(Frame(normalize(Vec3f{0.1f, 0.9f, 0.2f})),
                  model(static_cast<int>(state.range(0))));
  // Pre-drawn directions and numbers, so that the loop measures the BSDF alone.
  Pcg32 rng(1);
  std::vector<Vec3f> wo(1024);
  std::vector<float> u(3 * 1024);
  for (auto& w : wo) w = sample_uniform_sphere({rng.next_float(), rng.next_float()});
  for (auto& v : u) v = rng.next_float();
  std::size_t i = 0;
  float sink = 0;
  for (auto _ : state) {
    const std::size_t j = i++ & 1023;
    const auto s = bsdf.sample(wo[j], u[3 * j], {u[3 * j + 1], u[3 * j + 2]});
    if (s) sink += s->weight.r;
  }
  benchmark::DoNotOptimize(sink);
  state.SetItemsProcessed(state.iterations());
  state.SetLabel(kNames[state.range(0)]);
}
BENCHMARK(BM_bsdf_sample)->DenseRange(0, 8);

}  // namespace
