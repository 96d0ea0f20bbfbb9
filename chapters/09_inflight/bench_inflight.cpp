// Chapter 9's benchmark: rays in flight against chapter 3's one ray at a time, on the real
// meshes and on a closed sphere of 869,880 triangles (the size of the full Stanford dragon, a
// tree far larger than the caches), BVH8 with triangle8 leaves (the default configuration),
// primary, diffuse and shadow rays.
//   RTK_SCENES=../shared/scenes build/chapters/09_inflight/ch09_bench [--benchmark_filter=...]
// Names: ablation/SCENE/KIND/CONFIG (the best ISA; CONFIG as InflightConfig::name()) and
// isa/SCENE/KIND/ISA (kDefaultInflight on each ISA). Each alternates, on the same rays and
// tree, the single-ray kernel and the in-flight one, and reports speedup = time of the
// single-ray kernel / time in flight (above 1: rays in flight are faster), in the thread's CPU
// time, so that the ratio survives a shared machine. order/SCENE/KIND alternates the
// single-ray kernel on a batch of 2^18 rays as given and the same kernel on the batch sorted
// (the sort included), and reports speedup = given / sorted. packets/SCENE/KIND/ISA alternates,
// on the same 2^18 rays, the single-ray kernel and the packet kernel of an ISA, and reports
// speedup = single / packets.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "06_layouts/layout_build.h"
#include "07_intersectors/layout_intersectors.h"
#include "09_inflight/inflight.h"
#include "09_inflight/packets.h"
#include "09_inflight/ray_order.h"
#include "io/obj_loader.h"
#include "replay/ray_generator.h"
#include "testing/scenes.h"

using namespace rtk;

namespace {

constexpr size_t kRays = size_t(1) << 16;
// The order's batches: as many rays as the Embree comparison traces at once.
constexpr size_t kOrderRays = size_t(1) << 18;
constexpr RayKind kKinds[] = {RayKind::primary, RayKind::diffuse, RayKind::shadow};
constexpr TriangleConfig kTri{TriangleLayout::triangle8, IntersectorKind::moeller};

struct Scene {
  std::string name;
  std::filesystem::path path;
  TriangleMesh mesh;
  std::unique_ptr<LayoutBVH<8>> bvh;
  std::map<RayKind, std::vector<Ray>> rays;
  std::map<RayKind, std::vector<Ray>> order_rays;
};

// Loads the mesh, builds the tree and makes the rays on first use.
Scene& prepare(Scene& s, RayKind kind) {
  if (!s.bvh) {
    s.mesh = s.path.empty() ? test::make_sphere(660, 660) : load_obj(s.path);
    s.bvh = std::make_unique<LayoutBVH<8>>(build_layout_bvh<8>(s.mesh, kTri.layout));
  }
  auto& rays = s.rays[kind];
  if (rays.empty()) rays = generate_rays(s.mesh, kind, kRays, 1);
  return s;
}

double thread_seconds() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// [ch09-bench]
/// Alternates, on the same rays and tree, the single-ray kernels and `other`, timing each in the
/// thread's CPU time, and reports speedup = time of the single-ray kernels / time of `other`.
void alternate(benchmark::State& state, Scene& s, RayKind kind, const std::vector<Ray>& rays,
               const TraceKernels& single, const TraceKernels& other) {
  const bool occlusion = kind == RayKind::shadow;
  std::vector<Hit> hits(rays.size());
  std::vector<uint8_t> occ(rays.size());
  auto run = [&](const TraceKernels& k) {
    if (occlusion) k.occluded(&s.bvh->bvh, rays, occ);
    else k.intersect(&s.bvh->bvh, rays, hits);
    benchmark::DoNotOptimize(hits.data());
    benchmark::DoNotOptimize(occ.data());
  };
  double single_seconds = 0, other_seconds = 0;
  for (auto _ : state) {
    const double t0 = thread_seconds();
    run(single);
    const double t1 = thread_seconds();
    run(other);
    const double t2 = thread_seconds();
    single_seconds += t1 - t0;
    other_seconds += t2 - t1;
    state.SetIterationTime(t2 - t1);
  }
  const double n = double(state.iterations()) * double(rays.size());
  state.counters["mrays_per_s"] = n / other_seconds * 1e-6;
  state.counters["single_mrays_per_s"] = n / single_seconds * 1e-6;
  state.counters["speedup"] = single_seconds / other_seconds;
  state.counters["triangles"] = double(s.mesh.size());
  state.counters["tree_mb"] = double(s.bvh->bytes()) * 1e-6;
}

void bm_inflight(benchmark::State& state, Scene* scene, RayKind kind, Isa isa, InflightConfig config) {
  Scene& s = prepare(*scene, kind);
  alternate(state, s, kind, s.rays[kind], RTK_PICK_ISA(isa, intersector_kernels<8>)(kTri),
            RTK_PICK_ISA(isa, inflight_kernels<8>)(kTri, config));
}
// [ch09-bench]

// [ch09-packets-bench]
/// The batches of the order benchmark (the Embree comparison's size: primary rays of a 512 x 512
/// image), traced by the single-ray kernel and by the packet kernel of `isa`.
void bm_packets(benchmark::State& state, Scene* scene, RayKind kind, Isa isa) {
  Scene& s = prepare(*scene, kind);
  auto& rays = s.order_rays[kind];
  if (rays.empty()) rays = generate_rays(s.mesh, kind, kOrderRays, 1);
  alternate(state, s, kind, rays, RTK_PICK_ISA(isa, intersector_kernels<8>)(kTri),
            RTK_PICK_ISA(isa, packet_kernels<8>)(kTri));
}
// [ch09-packets-bench]

// [ch09-order-bench]
void bm_order(benchmark::State& state, Scene* scene, RayKind kind) {
  Scene& s = prepare(*scene, kind);
  auto& rays = s.order_rays[kind];
  if (rays.empty()) rays = generate_rays(s.mesh, kind, kOrderRays, 1);
  const bool occlusion = kind == RayKind::shadow;
  const TraceKernels kernels = RTK_PICK_ISA(best_isa(), intersector_kernels<8>)(kTri);
  const RayOrderKey key(s.mesh.bounds());
  // The default policy, as chapter 10 applies it: a large batch is sorted unless it is
  // coherent already.
  const RayOrderPolicy policy;
  std::vector<Hit> hits(rays.size());
  std::vector<uint8_t> occ(rays.size());
  SortedRays sorted;
  bool was_sorted = false;
  double given_seconds = 0, sorted_seconds = 0, sort_seconds = 0;
  for (auto _ : state) {
    const double t0 = thread_seconds();
    if (occlusion) kernels.occluded(&s.bvh->bvh, rays, occ);
    else kernels.intersect(&s.bvh->bvh, rays, hits);
    const double t1 = thread_seconds();
    was_sorted = sort_rays(rays, key, policy, sorted);
    const double t2 = thread_seconds();
    if (!was_sorted && occlusion) kernels.occluded(&s.bvh->bvh, rays, occ);
    else if (!was_sorted) kernels.intersect(&s.bvh->bvh, rays, hits);
    else if (occlusion) occluded_sorted(kernels, &s.bvh->bvh, sorted, 0, sorted.size(), occ);
    else intersect_sorted(kernels, &s.bvh->bvh, sorted, 0, sorted.size(), hits);
    const double t3 = thread_seconds();
    benchmark::DoNotOptimize(hits.data());
    benchmark::DoNotOptimize(occ.data());
    given_seconds += t1 - t0;
    sort_seconds += t2 - t1;
    sorted_seconds += t3 - t1;
    state.SetIterationTime(t3 - t1);
  }
  const double n = double(state.iterations()) * double(rays.size());
  state.counters["mrays_per_s"] = n / sorted_seconds * 1e-6;
  state.counters["given_mrays_per_s"] = n / given_seconds * 1e-6;
  state.counters["speedup"] = given_seconds / sorted_seconds;
  state.counters["sort_share"] = sort_seconds / sorted_seconds;  // of the sorted batch's time
  state.counters["sorted"] = was_sorted;
  state.counters["tree_mb"] = double(s.bvh->bytes()) * 1e-6;
}
// [ch09-order-bench]

std::vector<std::unique_ptr<Scene>> scenes;

[[maybe_unused]] const bool registered = [] {
  const char* root = std::getenv("RTK_SCENES");
  const std::pair<const char*, const char*> real[] = {
      {"bunny", "bunny_stanford_full/stanford-bunny.obj"}, {"dragon", "dragon_stanford/dragon_vrip_res3.obj"},
      {"buddha", "happy_buddha_100k/buddha.obj"},         {"sponza", "sponza_dabrovic/sponza.obj"},
      {"teapot", "teapot_newell/teapot.obj"},
  };
  for (const auto& [name, file] : real) {
    if (!root) break;
    const std::filesystem::path path = std::filesystem::path(root) / file;
    if (!std::filesystem::exists(path)) continue;
    scenes.push_back(std::make_unique<Scene>(Scene{name, path, {}, nullptr, {}, {}}));
  }
  scenes.push_back(std::make_unique<Scene>(Scene{"sphere_870k", {}, {}, nullptr, {}, {}}));
  const Isa best = best_isa();
  for (auto& owned : scenes) {
    Scene* s = owned.get();
    for (RayKind kind : kKinds) {
      const std::string prefix = s->name + "/" + std::string(ray_kind_name(kind)) + "/";
      for (const InflightConfig& config : kInflightConfigs)
        benchmark::RegisterBenchmark(("ablation/" + prefix + config.name()).c_str(), bm_inflight, s, kind, best,
                                     config)
            ->UseManualTime()
            ->Unit(benchmark::kMillisecond);
      for (Isa isa : supported_isas())
        benchmark::RegisterBenchmark(("isa/" + prefix + std::string(isa_name(isa))).c_str(), bm_inflight, s, kind,
                                     isa, kDefaultInflight)
            ->UseManualTime()
            ->Unit(benchmark::kMillisecond);
      for (Isa isa : supported_isas())
        if (has_packets(isa, kTri))
          benchmark::RegisterBenchmark(("packets/" + prefix + std::string(isa_name(isa))).c_str(), bm_packets, s,
                                       kind, isa)
              ->UseManualTime()
              ->Unit(benchmark::kMillisecond);
      benchmark::RegisterBenchmark(("order/" + s->name + "/" + std::string(ray_kind_name(kind))).c_str(), bm_order,
                                   s, kind)
          ->UseManualTime()
          ->Unit(benchmark::kMillisecond);
    }
  }
  return true;
}();

}  // namespace
