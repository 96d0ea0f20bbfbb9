// Chapter 3's benchmark: BVH4/BVH8/BVH16 traversal per ISA, the trick ablation, and the
// traversal statistics (nodes per ray, children hit per node).
//   ch03_bench [--benchmark_filter=...]; set RTK_SCENES=<shared/scenes> to add real meshes.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <ctime>
#include <map>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "02_bvh2/bench_support.h"
#include "02_bvh2/median_builder.h"
#include "02_bvh2/bvh2.h"
#include "03_bvh4/bvh4.h"

using namespace rtk;

namespace {

constexpr int kImage = 256;        // primary rays: a 256 x 256 image
constexpr int kDiffuse = 1 << 16;  // as many diffuse rays

template <int N>
struct Prepared {
  std::conditional_t<N == 2, BVH2, BVHN<N>> bvh;
  std::vector<Ray> primary, diffuse;
};

template <int N>
const Prepared<N>& prepare(const bench::SceneSource& scene) {
  static std::map<std::string, std::unique_ptr<Prepared<N>>> cache;
  auto& slot = cache[scene.name];
  if (!slot) {
    const TriangleMesh& mesh = bench::scene_mesh(scene);
    slot = std::make_unique<Prepared<N>>();
    if constexpr (N == 2) slot->bvh = make_bvh2(build_median<2>(make_prim_refs(mesh), 4), mesh);
    else slot->bvh = make_bvh<N>(build_median<N>(make_prim_refs(mesh), 4), mesh);
    slot->primary = bench::primary_rays(mesh, kImage, kImage);
    slot->diffuse = bench::diffuse_rays(mesh, kDiffuse, 1);
  }
  return *slot;
}

// CPU time of the calling thread: time the scheduler gave to other processes is not counted.
double thread_seconds() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// The statistics of a configuration as counters: nodes and leaves per ray, and the share of
// node visits that hit k children (hit0, hit1, ...), with hit0-2 their sum for k <= 2.
void add_stats_counters(benchmark::State& state, const TraversalStats& s, int width) {
  state.counters["nodes_per_ray"] = s.nodes_per_ray();
  state.counters["leaves_per_ray"] = s.leaves_per_ray();
  for (int k = 0; k <= width; ++k) state.counters["hit" + std::to_string(k)] = s.hit_fraction(k);
  state.counters["hit0-2"] = s.hit_fraction(0) + s.hit_fraction(1) + s.hit_fraction(2);
}

// [ch03-bench-trace]
template <int N>
void bm_trace(benchmark::State& state, bench::SceneSource scene, Isa isa, bool diffuse, bool occlusion) {
  const Prepared<N>& p = prepare<N>(scene);
  const std::vector<Ray>& rays = diffuse ? p.diffuse : p.primary;
  std::vector<Hit> hits(rays.size());
  std::vector<uint8_t> occ(rays.size());
  for (auto _ : state) {
    if (occlusion) occluded(isa, p.bvh, rays, occ);
    else intersect(isa, p.bvh, rays, hits);
    benchmark::DoNotOptimize(hits.data());
    benchmark::DoNotOptimize(occ.data());
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(rays.size()));
  state.counters["bytes_per_tri"] = double(p.bvh.bytes()) / double(bench::scene_mesh(scene).size());
  // The statistics of the same rays, counted outside the timed loop (BVH2 has no such mode).
  if constexpr (N != 2) {
    TraversalStats stats;
    if (occlusion) occluded(isa, p.bvh, Tricks{}, rays, occ, &stats);
    else intersect(isa, p.bvh, Tricks{}, rays, hits, &stats);
    add_stats_counters(state, stats, N);
  }
}
// [ch03-bench-trace]

// [ch03-bench-ablation]
// One trick configuration against all tricks, timed alternately on the same rays in the same
// run, in the thread's CPU time, so that the ratio (vs_all: time with the configuration / time
// with all tricks; above 1 means the missing trick was worth that much) survives a shared,
// noisy machine.
template <int N>
void bm_ablation(benchmark::State& state, bench::SceneSource scene, Isa isa, bool diffuse, bool occlusion,
                 NamedTricks config) {
  const Prepared<N>& p = prepare<N>(scene);
  const std::vector<Ray>& rays = diffuse ? p.diffuse : p.primary;
  std::vector<Hit> hits(rays.size());
  std::vector<uint8_t> occ(rays.size());
  auto run = [&](const Tricks& tricks, TraversalStats* stats) {
    if (occlusion) occluded(isa, p.bvh, tricks, rays, occ, stats);
    else intersect(isa, p.bvh, tricks, rays, hits, stats);
  };
  double config_seconds = 0, all_seconds = 0;
  for (auto _ : state) {
    const double t0 = thread_seconds();
    run(Tricks{}, nullptr);
    const double t1 = thread_seconds();
    run(config.tricks, nullptr);
    const double t2 = thread_seconds();
    benchmark::DoNotOptimize(hits.data());
    benchmark::DoNotOptimize(occ.data());
    all_seconds += t1 - t0;
    const double seconds = t2 - t1;
    config_seconds += seconds;
    state.SetIterationTime(seconds);
  }
  // Google Benchmark's own rate would divide by the time of both runs: report this one.
  state.counters["mrays_per_s"] = double(state.iterations()) * double(rays.size()) / config_seconds * 1e-6;
  state.counters["vs_all"] = config_seconds / all_seconds;
  TraversalStats stats;
  run(config.tricks, &stats);
  add_stats_counters(state, stats, N);
}
// [ch03-bench-ablation]

template <int N>
void register_width(const bench::SceneSource& scene, Isa isa) {
  for (const char* kind : {"primary", "diffuse"})
    for (const char* op : {"intersect", "occluded"}) {
      const std::string name = "bvh" + std::to_string(N) + "/" + scene.name + "/" + kind + "/" + op + "/" +
                               std::string(isa_name(isa));
      benchmark::RegisterBenchmark(name.c_str(), bm_trace<N>, scene, isa, std::string(kind) == "diffuse",
                                   std::string(op) == "occluded")
          ->Unit(benchmark::kMillisecond);
    }
}

template <int N>
void register_ablation(const bench::SceneSource& scene, Isa isa) {
  // Closest hits of primary and diffuse rays, and occlusion of the diffuse rays (which leave a
  // surface, as shadow rays do).
  for (const char* kind : {"primary", "diffuse", "diffuse-occluded"})
    for (const NamedTricks& config : kTrickConfigs) {
      const std::string name = "ablation/bvh" + std::to_string(N) + "-" + std::string(isa_name(isa)) + "/" +
                               scene.name + "/" + kind + "/" + std::string(config.name);
      const std::string_view k = kind;
      benchmark::RegisterBenchmark(name.c_str(), bm_ablation<N>, scene, isa, k != "primary",
                                   k == "diffuse-occluded", config)
          ->UseManualTime()
          ->Unit(benchmark::kMillisecond);
    }
}

[[maybe_unused]] const bool registered = [] {
  const std::vector<Isa> isas = supported_isas();
  auto has = [&](Isa isa) { return std::find(isas.begin(), isas.end(), isa) != isas.end(); };
  for (const bench::SceneSource& scene : bench::bench_scenes()) {
    for (Isa isa : isas) {
      register_width<2>(scene, isa);
      register_width<4>(scene, isa);
      register_width<8>(scene, isa);
    }
    if (has(Isa::avx512)) register_width<16>(scene, Isa::avx512);
    // The ablation on the pairing the guide has in mind: BVH4 with SSE, and BVH8 with AVX2.
    if (has(Isa::sse4)) register_ablation<4>(scene, Isa::sse4);
    if (has(Isa::avx2)) register_ablation<8>(scene, Isa::avx2);
  }
  return true;
}();

}  // namespace
