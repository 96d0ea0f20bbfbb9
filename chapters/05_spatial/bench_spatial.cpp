// Chapter 5 benchmarks: what spatial splits cost to build (time relative to object splits,
// references per triangle, SAH) and what they buy (Mrays/s of primary and diffuse rays through
// chapter 3's BVH4 on the best ISA), for object splits, the guide's centre splits and SBVH's
// binned splits; and how the duplication budget trades memory for speed.
//
//   build/chapters/05_spatial/ch05_bench --benchmark_counters_tabular=true
//   RTK_SCENES=../shared/scenes build/chapters/05_spatial/ch05_bench   # adds sponza, bunny
#include <benchmark/benchmark.h>

#include <time.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "01_base/cpu_features.h"
#include "02_bvh2/bench_support.h"
#include "03_bvh4/bvh4.h"
#include "04_sah/build_sah.h"
#include "05_spatial/architecture_scene.h"
#include "05_spatial/build_spatial.h"
#include "testing/scenes.h"

namespace {

using namespace rtk;

enum class Flavour { object, centre, binned };
const char* flavour_name(Flavour f) {
  return f == Flavour::object ? "object" : f == Flavour::centre ? "centre" : "binned";
}

struct Scene {
  std::string name;
  TriangleMesh mesh;
};

/// The procedural scenes of the chapter, then sponza (architecture) and the bunny (compact
/// triangles, where spatial splits should gain nothing) from $RTK_SCENES.
const std::vector<Scene>& scenes() {
  static const std::vector<Scene> list = [] {
    std::vector<Scene> s;
    s.push_back({"slivers_4k", test::make_slivers(4000, 7)});
    s.push_back({"architecture_20k", make_architecture(10, 1500, 300, 7)});
    for (const auto& source : bench::bench_scenes())
      if (source.name == "sponza" || source.name == "bunny") s.push_back({source.name, bench::scene_mesh(source)});
    return s;
  }();
  return list;
}

SpatialBuildOptions options_for(Flavour f, float budget = SpatialBuildOptions{}.budget) {
  SpatialBuildOptions o;
  o.mode = f == Flavour::centre ? SpatialSplitMode::centre : SpatialSplitMode::binned;
  o.budget = f == Flavour::object ? 0.0f : budget;
  return o;
}

/// A tree of one flavour over a scene, built once.
struct Built {
  BuildTree<4> tree;
  SpatialBuildStats stats;
  BVH4 bvh;
};
const Built& built(const Scene& scene, Flavour f, float budget = SpatialBuildOptions{}.budget) {
  static std::map<std::string, std::unique_ptr<Built>> cache;
  const std::string key = scene.name + "/" + flavour_name(f) + "/" + std::to_string(budget);
  auto& slot = cache[key];
  if (!slot) {
    slot = std::make_unique<Built>();
    slot->tree = build_spatial_sah<4>(scene.mesh, options_for(f, budget), &slot->stats);
    slot->bvh = make_bvh<4>(slot->tree, scene.mesh);
  }
  return *slot;
}

/// CPU seconds of the calling thread: the machine is shared, and a single-threaded build or
/// trace should not be charged for the time other programs hold the cores.
double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// [ch05-bench-build]
/// One iteration builds the scene three times on one thread (a one-thread arena runs on the
/// calling thread), with object, centre and binned splits, one after the other; the counters
/// are the build-time ratios to object splits over three iterations (the guide: about 3), so
/// that a moment when the shared machine is slow weighs on one build of each flavour rather
/// than on one flavour, the references per triangle and the SAH ratios.
void build_ratios(benchmark::State& state, const Scene* scene) {
  double seconds[3] = {0, 0, 0};
  SpatialBuildStats stats[3];
  double sah[3] = {0, 0, 0};
  for (auto _ : state) {
    for (const Flavour f : {Flavour::object, Flavour::centre, Flavour::binned}) {
      SpatialBuildOptions o = options_for(f);
      o.sah.threads = 1;
      const double start = thread_seconds();
      const BuildTree<4> tree = build_spatial_sah<4>(scene->mesh, o, &stats[int(f)]);
      seconds[int(f)] += thread_seconds() - start;
      sah[int(f)] = sah_cost(tree);
      benchmark::DoNotOptimize(tree.nodes.data());
    }
  }
  const double tris = double(scene->mesh.size());
  state.counters["tris"] = tris;
  state.counters["object_Mtris/s"] = tris * double(state.iterations()) / seconds[0] * 1e-6;
  state.counters["centre_time"] = seconds[1] / seconds[0];
  state.counters["binned_time"] = seconds[2] / seconds[0];
  state.counters["centre_refs/tri"] = double(stats[1].references) / tris;
  state.counters["binned_refs/tri"] = double(stats[2].references) / tris;
  state.counters["centre_sah"] = sah[1] / sah[0];
  state.counters["binned_sah"] = sah[2] / sah[0];
}
// [ch05-bench-build]

/// Closest hits of primary or diffuse rays through the BVH4 of one flavour, on the best ISA,
/// one thread (CPU time, Google Benchmark's default).
void trace(benchmark::State& state, const Scene* scene, Flavour f, bool diffuse, float budget) {
  const Built& b = built(*scene, f, budget);
  const std::vector<Ray> rays =
      diffuse ? bench::diffuse_rays(scene->mesh, 1 << 14, 1) : bench::primary_rays(scene->mesh, 128, 128);
  std::vector<Hit> hits(rays.size());
  const Isa isa = best_isa();
  for (auto _ : state) {
    intersect(isa, b.bvh, rays, hits);
    benchmark::DoNotOptimize(hits.data());
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(rays.size()));
  state.counters["refs/tri"] = double(b.stats.references) / double(scene->mesh.size());
  state.counters["sah"] = sah_cost(b.tree);
  state.counters["bytes/tri"] = double(b.bvh.bytes()) / double(scene->mesh.size());
}

/// One binned build per iteration with `bins` spatial bins per axis, one thread: the build time
/// is the benchmark's CPU time, the SAH and references are counters.
void spatial_bins(benchmark::State& state, const Scene* scene, int bins) {
  SpatialBuildOptions o = options_for(Flavour::binned);
  o.spatial_bins = bins;
  o.sah.threads = 1;
  double sah = 0, refs = 0;
  for (auto _ : state) {
    const BuildTree<4> tree = build_spatial_sah<4>(scene->mesh, o);
    sah = sah_cost(tree), refs = double(tree.prim_ids.size());
  }
  state.counters["sah"] = sah;
  state.counters["refs/tri"] = refs / double(scene->mesh.size());
}

// [ch05-bench-overlap]
/// Where to look for spatial splits: binned builds with the pricing rules of `binned`, one
/// thread. One iteration builds the object-split tree five times (it takes a few milliseconds,
/// too short to time once) and the binned one once, timing each; then both trace the same
/// diffuse rays (best ISA, BVH4, five rounds each, alternating). The counters are the binned
/// build's time and its ratio to the object split's, the sets priced, the references per
/// triangle, and the SAH and diffuse-ray speed relative to object splits.
void pricing_rule(benchmark::State& state, const Scene* scene, SpatialBuildOptions binned) {
  SpatialBuildOptions object = options_for(Flavour::object);
  object.sah.threads = binned.sah.threads = 1;
  constexpr int kObjectBuilds = 5;
  double seconds[2] = {0, 0};
  SpatialBuildStats stats;
  BuildTree<4> trees[2];
  for (auto _ : state) {
    double start = thread_seconds();
    for (int k = 0; k < kObjectBuilds; ++k) trees[0] = build_spatial_sah<4>(scene->mesh, object);
    seconds[0] += (thread_seconds() - start) / kObjectBuilds;
    start = thread_seconds();
    trees[1] = build_spatial_sah<4>(scene->mesh, binned, &stats);
    seconds[1] += thread_seconds() - start;
  }
  const BVH4 bvh[2] = {make_bvh<4>(trees[0], scene->mesh), make_bvh<4>(trees[1], scene->mesh)};
  const std::vector<Ray> rays = bench::diffuse_rays(scene->mesh, 1 << 14, 1);
  std::vector<Hit> hits(rays.size());
  double trace_seconds[2] = {0, 0};
  for (int round = 0; round < 10; ++round) {
    const double start = thread_seconds();
    intersect(best_isa(), bvh[round % 2], rays, hits);
    trace_seconds[round % 2] += thread_seconds() - start;
  }
  const double tris = double(scene->mesh.size());
  state.counters["build_ms"] = 1e3 * seconds[1] / double(state.iterations());
  state.counters["build_time"] = seconds[1] / seconds[0];
  state.counters["searches"] = double(stats.spatial_searches);
  state.counters["refs/tri"] = double(stats.references) / tris;
  state.counters["sah"] = sah_cost(trees[1]) / sah_cost(trees[0]);
  state.counters["diffuse_speed"] = trace_seconds[0] / trace_seconds[1];
}
// [ch05-bench-overlap]

const bool registered = [] {
  for (const Scene& scene : scenes()) {
    benchmark::RegisterBenchmark(("build/" + scene.name).c_str(), build_ratios, &scene)
        ->Unit(benchmark::kMillisecond)
        ->Iterations(3);
    for (const bool diffuse : {false, true})
      for (const Flavour f : {Flavour::object, Flavour::centre, Flavour::binned})
        benchmark::RegisterBenchmark(
            ("trace/" + scene.name + "/" + (diffuse ? "diffuse/" : "primary/") + flavour_name(f)).c_str(), trace,
            &scene, f, diffuse, SpatialBuildOptions{}.budget)
            ->Unit(benchmark::kMillisecond);
    if (scene.name != "slivers_4k" && scene.name != "bunny")
      for (const int bins : {8, 16, 32})
        benchmark::RegisterBenchmark(("bins/" + scene.name + "/" + std::to_string(bins)).c_str(), spatial_bins,
                                     &scene, bins)
            ->Unit(benchmark::kMillisecond)
            ->Iterations(2);
    for (const int percent : {0, 5, 10, 20, 40}) {
      SpatialBuildOptions o = options_for(Flavour::binned);
      o.min_overlap = float(percent) / 100.0f;
      benchmark::RegisterBenchmark(("overlap/" + scene.name + "/" + std::to_string(percent) + "%").c_str(),
                                   pricing_rule, &scene, o)
          ->Unit(benchmark::kMillisecond)
          ->Iterations(2);
    }
    for (const uint32_t leaves : {0u, 1u, 2u, 4u, 8u, 32u}) {
      SpatialBuildOptions o = options_for(Flavour::binned);
      o.min_leaves = leaves;
      benchmark::RegisterBenchmark(("min_leaves/" + scene.name + "/" + std::to_string(leaves)).c_str(), pricing_rule,
                                   &scene, o)
          ->Unit(benchmark::kMillisecond)
          ->Iterations(2);
    }
    // The budget: diffuse rays through binned-split trees with 10 % to 200 % more references.
    for (const float budget : {0.1f, 0.3f, 0.6f, 1.0f, 2.0f})
      benchmark::RegisterBenchmark(("budget/" + scene.name + "/" + std::to_string(int(budget * 100)) + "%").c_str(),
                                   trace, &scene, Flavour::binned, true, budget)
          ->Unit(benchmark::kMillisecond);
  }
  return true;
}();

}  // namespace
