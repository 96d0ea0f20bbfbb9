// Chapter 7's benchmark: what each intersector costs, and what it buys.
//   ch07_bench --benchmark_filter='tests/'   triangle tests per second, per intersector, width, ISA
//   ch07_bench --benchmark_filter='chart/'   the speed-against-accuracy chart's points: Mrays/s
//       through BVH4 and the leak rate, measured on the same rays, for every layout, intersector
//       and ISA, on two ray sets of the accuracy scene: chart/view/ (its 256 x 256 view) and
//       chart/inside/ (rays from inside at its vertices and edges). chart/speed_vs_accuracy.sh
//       plots them.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "06_layouts/layout_build.h"
#include "07_intersectors/layout_intersectors.h"
#include "07_intersectors/accuracy_scene.h"
#include "07_intersectors/intersect_all.h"
#include "07_intersectors/stability_meshes.h"
#include "testing/scenes.h"

using namespace rtk;

namespace {

// [ch07-bench-tests]
/// Brute force: 64 rays against 4,096 triangles of a random soup, so nearly all the time is
/// spent in the intersector (most tests fail early, as in a leaf).
void bm_tests(benchmark::State& state, IntersectorKind kind, int width, Isa isa) {
  static const TriangleMesh soup = test::make_random_soup(4096, 81);
  static const TriangleSoA soa(soup);
  static const std::vector<Ray> rays = [] {
    std::vector<Ray> r;
    for (int i = 0; i < 64; ++i) {
      Ray ray;
      ray.org = {float(i % 8) / 8.0f + 0.05f, float(i / 8) / 8.0f + 0.05f, -1.0f};
      ray.dir = {0.01f * float(i % 3), 0.01f * float(i % 5), 1.0f};
      r.push_back(ray);
    }
    return r;
  }();
  std::vector<Hit> hits(rays.size());
  for (auto _ : state) {
    RTK_PICK_ISA(isa, intersect_all)(soa, kind, width, rays, hits);
    benchmark::DoNotOptimize(hits.data());
  }
  const double tests = double(rays.size()) * double(soup.size());
  state.counters["Mtests/s"] = benchmark::Counter(tests * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
}
// [ch07-bench-tests]

/// The accuracy scene's two ray sets: the view, cut to cross the spindle's front surface once,
/// and the rays from inside at its vertices and edges. On both, a miss is a leak.
const std::vector<Ray>& accuracy_rays(bool inside) {
  static const std::vector<Ray> view = [] {
    const AccuracyScene scene = make_accuracy_scene();
    return rays_through_front(scene.mesh, camera_rays(scene.camera, 256, 256));
  }();
  static const std::vector<Ray> from_inside = accuracy_inside_rays();
  return inside ? from_inside : view;
}

// [ch07-bench-chart]
/// One point of the chart: speed and leak rate of one configuration on the same rays.
void bm_chart(benchmark::State& state, bool inside, TriangleConfig config, Isa isa) {
  static const TriangleMesh mesh = make_accuracy_scene().mesh;
  const LayoutBVH<4> bvh = build_layout_bvh<4>(mesh, config.layout, 1);
  const std::vector<Ray>& rays = accuracy_rays(inside);
  std::vector<Hit> hits(rays.size());
  for (auto _ : state) {
    intersect(isa, bvh, config.intersector, rays, hits);
    benchmark::DoNotOptimize(hits.data());
  }
  const size_t leaks = count_misses(hits);
  state.counters["Mrays/s"] =
      benchmark::Counter(double(rays.size()) * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["leaks"] = double(leaks);
  state.counters["leak_rate"] = double(leaks) / double(rays.size());
}
// [ch07-bench-chart]

const bool registered = [] {
  for (const IntersectorKind kind : kAllIntersectors)
    for (const int width : kIntersectorWidths)
      for (const Isa isa : supported_isas())
        benchmark::RegisterBenchmark(("tests/" + std::string(intersector_name(kind)) + "/w" +
                                      std::to_string(width) + "/" + std::string(isa_name(isa))).c_str(),
                                     bm_tests, kind, width, isa)
            ->Unit(benchmark::kMillisecond)
            ->MinTime(0.2);
  for (const bool inside : {false, true})
    for (const TriangleConfig& config : supported_triangle_configs())
      for (const Isa isa : supported_isas())
        benchmark::RegisterBenchmark((std::string(inside ? "chart/inside/" : "chart/view/") + config.name() + "/" +
                                      std::string(isa_name(isa))).c_str(),
                                     bm_chart, inside, config, isa)
            ->Unit(benchmark::kMillisecond)
            ->MinTime(0.3);
  return true;
}();

}  // namespace
