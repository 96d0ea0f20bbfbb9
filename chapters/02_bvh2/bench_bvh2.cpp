// Chapter 2's benchmark: BVH2 traversal, Mrays/s per ISA, on primary and diffuse rays.
//   ch02_bench [--benchmark_filter=...]; set RTK_SCENES=<shared/scenes> to add real meshes.
#include <benchmark/benchmark.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "02_bvh2/bench_support.h"
#include "02_bvh2/bvh2.h"
#include "02_bvh2/median_builder.h"

using namespace rtk;

namespace {

constexpr int kImage = 256;         // primary rays: a 256 x 256 image
constexpr int kDiffuse = 1 << 16;   // as many diffuse rays

struct Prepared {
  BVH2 bvh;
  std::vector<Ray> primary, diffuse;
};

const Prepared& prepare(const bench::SceneSource& scene) {
  static std::map<std::string, std::unique_ptr<Prepared>> cache;
  auto& slot = cache[scene.name];
  if (!slot) {
    const TriangleMesh& mesh = bench::scene_mesh(scene);
    slot = std::make_unique<Prepared>();
    slot->bvh = make_bvh2(build_median<2>(make_prim_refs(mesh), 4), mesh);
    slot->primary = bench::primary_rays(mesh, kImage, kImage);
    slot->diffuse = bench::diffuse_rays(mesh, kDiffuse, 1);
  }
  return *slot;
}

void bm_trace(benchmark::State& state, bench::SceneSource scene, Isa isa, bool diffuse, bool occlusion) {
  const Prepared& p = prepare(scene);
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
  size_t hit_count = 0;
  for (size_t i = 0; i < rays.size(); ++i) hit_count += occlusion ? occ[i] : hits[i].found();
  state.counters["hit_rate"] = double(hit_count) / double(rays.size());
  state.counters["triangles"] = double(bench::scene_mesh(scene).size());
  state.counters["bytes_per_tri"] = double(p.bvh.bytes()) / double(bench::scene_mesh(scene).size());
}

[[maybe_unused]] const bool registered = [] {
  for (const bench::SceneSource& scene : bench::bench_scenes())
    for (const char* kind : {"primary", "diffuse"})
      for (const char* op : {"intersect", "occluded"})
        for (Isa isa : supported_isas()) {
          const std::string name = "bvh2/" + scene.name + "/" + kind + "/" + op + "/" + std::string(isa_name(isa));
          benchmark::RegisterBenchmark(name.c_str(), bm_trace, scene, isa, std::string(kind) == "diffuse",
                                       std::string(op) == "occluded")
              ->Unit(benchmark::kMillisecond);
        }
  return true;
}();

}  // namespace
