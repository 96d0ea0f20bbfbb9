// Chapter 6's benchmark: Mrays/s and bytes per triangle for every layout (Möller-Trumbore),
// through BVH2, BVH4 and BVH8, for every ISA, on primary and diffuse rays.
//   ch06_bench --benchmark_filter='sphere_130k/diffuse/bvh4/.*/avx512'
// Set RTK_SCENES=<shared/scenes> to add real meshes. Names read
// layouts/<scene>/<rays>/bvh<N>/<layout>.moeller/<isa> (chapter 7 measures the other tests), and
// pack/<scene>/bvh8/triangle8 times the making of the structure from a built tree, one thread.
#include <benchmark/benchmark.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "02_bvh2/bench_support.h"
#include "04_sah/build_sah.h"
#include "06_layouts/layout_build.h"

using namespace rtk;

namespace {

constexpr int kImage = 256;        // primary rays: a 256 x 256 image
constexpr int kDiffuse = 1 << 16;  // as many diffuse rays

struct Rays {
  std::vector<Ray> primary, diffuse;
};

const Rays& rays_of(const bench::SceneSource& scene) {
  static std::map<std::string, std::unique_ptr<Rays>> cache;
  auto& slot = cache[scene.name];
  if (!slot) {
    const TriangleMesh& mesh = bench::scene_mesh(scene);
    slot = std::make_unique<Rays>(Rays{bench::primary_rays(mesh, kImage, kImage), bench::diffuse_rays(mesh, kDiffuse, 1)});
  }
  return *slot;
}

/// One structure per scene, width and configuration, built on first use.
template <int N>
const LayoutBVH<N>& bvh_of(const bench::SceneSource& scene, TriangleLayout layout) {
  static std::map<std::string, std::unique_ptr<LayoutBVH<N>>> cache;
  auto& slot = cache[scene.name + "/" + std::string(layout_name(layout))];
  if (!slot) slot = std::make_unique<LayoutBVH<N>>(build_layout_bvh<N>(bench::scene_mesh(scene), layout));
  return *slot;
}

template <int N>
void bm_trace(benchmark::State& state, bench::SceneSource scene, TriangleLayout layout, Isa isa, bool diffuse) {
  const LayoutBVH<N>& bvh = bvh_of<N>(scene, layout);
  const std::vector<Ray>& rays = diffuse ? rays_of(scene).diffuse : rays_of(scene).primary;
  std::vector<Hit> hits(rays.size());
  for (auto _ : state) {
    intersect(isa, bvh, rays, hits);
    benchmark::DoNotOptimize(hits.data());
  }
  const double triangles = double(bench::scene_mesh(scene).size());
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(rays.size()));
  state.counters["Mrays/s"] =
      benchmark::Counter(double(rays.size()) * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["bytes/tri"] = double(bvh.bytes()) / triangles;
  state.counters["leaf_bytes/tri"] = double(bvh.bvh.leaves.bytes.size()) / triangles;
}

/// Making the default structure (BVH8, triangle8) from its tree on one thread: the nodes and
/// the packing of the leaves, which reads every triangle's vertices in leaf order.
void bm_pack(benchmark::State& state, bench::SceneSource scene) {
  const TriangleMesh& mesh = bench::scene_mesh(scene);
  SahBuildOptions options = sah_options_for(TriangleLayout::triangle8);
  options.threads = 1;
  const BuildTree<8> tree = build_binned_sah<8>(make_prim_refs(mesh), options);
  for (auto _ : state) {
    const LayoutBVH<8> bvh = make_layout_bvh<8>(tree, mesh, TriangleLayout::triangle8, 1);
    benchmark::DoNotOptimize(bvh.bvh.nodes.data());
  }
  state.counters["Mtris/s"] =
      benchmark::Counter(double(mesh.size()) * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
}

const bool registered = [] {
  for (const bench::SceneSource& scene : bench::bench_scenes())
    benchmark::RegisterBenchmark(("pack/" + scene.name + "/bvh8/triangle8").c_str(), bm_pack, scene)
        ->Unit(benchmark::kMillisecond);
  for (const bench::SceneSource& scene : bench::bench_scenes())
    for (const bool diffuse : {false, true})
      for (const int width : {2, 4, 8})
        for (const TriangleLayout layout : kAllLayouts)
          for (const Isa isa : supported_isas()) {
            const std::string name = "layouts/" + scene.name + (diffuse ? "/diffuse" : "/primary") + "/bvh" +
                                     std::to_string(width) + "/" + std::string(layout_name(layout)) + ".moeller/" +
                                     std::string(isa_name(isa));
            auto* b = width == 2   ? benchmark::RegisterBenchmark(name.c_str(), bm_trace<2>, scene, layout, isa, diffuse)
                      : width == 4 ? benchmark::RegisterBenchmark(name.c_str(), bm_trace<4>, scene, layout, isa, diffuse)
                                   : benchmark::RegisterBenchmark(name.c_str(), bm_trace<8>, scene, layout, isa, diffuse);
            b->Unit(benchmark::kMillisecond)->MinTime(0.3);
          }
  return true;
}();

}  // namespace
