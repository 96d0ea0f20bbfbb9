// Chapter 4 benchmarks: how fast the binned SAH builder builds (Mtris/s at 1 and 2 threads,
// with and without rotations, against chapter 2's median builder), what its trees cost (SAH,
// peak memory) and what they buy (Mrays/s through chapter 3's BVH4, occlusion visits with
// occluder ordering).
//
//   build/chapters/04_sah/ch04_bench                       # the default, modest run
//   RTK_BENCH_LARGE=1 build/chapters/04_sah/ch04_bench --benchmark_filter='tris:(4|16)'
//                                                             # adds 4M and 16M triangles
//   RTK_SCENES=../shared/scenes build/chapters/04_sah/ch04_bench   # adds real meshes
//   RTK_BENCH_GROWTH=1 build/chapters/04_sah/ch04_bench --benchmark_filter='^growth/'
//                                                             # BVH8 at 1M, 4M, 16M triangles
#include <benchmark/benchmark.h>
#include <malloc.h>
#include <sys/resource.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <limits>
#include <map>
#include <memory>
#include <new>
#include <string>
#include <utility>
#include <vector>

#include "01_base/block_cache.h"
#include "01_base/cpu_features.h"
#include "02_bvh2/bench_support.h"
#include "02_bvh2/median_builder.h"
#include "03_bvh4/bvh4.h"
#include "04_sah/build_sah.h"
#include "testing/scenes.h"

// Peak memory: every operator new and delete of the program goes through these counters, so a
// benchmark can ask how many bytes a build held at most beyond what existed before it.
namespace {
std::atomic<size_t> g_bytes{0}, g_peak{0};
void* allocate(size_t n, size_t alignment) {
  void* p = alignment <= alignof(std::max_align_t)
                ? std::malloc(n ? n : 1)
                : std::aligned_alloc(alignment, (n + alignment - 1) / alignment * alignment);
  if (!p) throw std::bad_alloc();
  const size_t now = g_bytes += malloc_usable_size(p);
  size_t peak = g_peak.load();
  while (now > peak && !g_peak.compare_exchange_weak(peak, now)) {
  }
  return p;
}
void release(void* p) {
  if (!p) return;
  g_bytes -= malloc_usable_size(p);
  std::free(p);
}
}  // namespace

void* operator new(size_t n) { return allocate(n, 1); }
void* operator new[](size_t n) { return allocate(n, 1); }
void* operator new(size_t n, std::align_val_t a) { return allocate(n, size_t(a)); }
void* operator new[](size_t n, std::align_val_t a) { return allocate(n, size_t(a)); }
void operator delete(void* p) noexcept { release(p); }
void operator delete[](void* p) noexcept { release(p); }
void operator delete(void* p, size_t) noexcept { release(p); }
void operator delete[](void* p, size_t) noexcept { release(p); }
void operator delete(void* p, std::align_val_t) noexcept { release(p); }
void operator delete[](void* p, std::align_val_t) noexcept { release(p); }
void operator delete(void* p, size_t, std::align_val_t) noexcept { release(p); }
void operator delete[](void* p, size_t, std::align_val_t) noexcept { release(p); }

namespace {

using namespace rtk;

/// The builders compared.
enum class Builder { median, binned, binned_rotations };
const char* builder_name(Builder b) {
  return b == Builder::median ? "median" : b == Builder::binned ? "binned" : "binned+rot";
}

/// The median builder's leaf size: chapters 2 and 3 use 4.
constexpr int kMedianLeaf = 4;

/// The SAH of a tree, priced with the SAH builder's default costs.
template <int N>
double sah(const BuildTree<N>& tree) {
  const SahBuildOptions defaults;
  return sah_cost(tree, defaults.traversal_cost, defaults.intersection_cost);
}

template <int N>
BuildTree<N> build(std::span<const PrimRef> refs, Builder builder, int threads, int bins = 32,
                   OccluderOrder order = OccluderOrder::likely_blocker, int leaf_block = 1) {
  if (builder == Builder::median) return build_median<N>(refs, kMedianLeaf);
  // Leaves in blocks are priced as chapter 6 builds its layouts; by count, the defaults.
  SahBuildOptions options = leaf_block > 1 ? block_priced_options(leaf_block) : SahBuildOptions{};
  options.rotations = builder == Builder::binned_rotations;
  options.threads = threads;
  options.bins = bins;
  options.occluder_order = order;
  return build_binned_sah<N>(refs, options);
}

/// CPU time of the calling thread, for single-threaded work on a shared machine: time the
/// scheduler gave to other processes is not counted.
double thread_seconds() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

/// The calling thread's CPU time so far, split into its own (user) and the kernel's on its
/// behalf (system: mapping and zeroing the fresh pages a build touches first). The kernel keeps
/// the total exactly and divides it between the two in the proportion of its timer ticks, so the
/// split is good for builds of many milliseconds, not for short ones.
struct UserSystem {
  double user = 0.0, system = 0.0;
  static UserSystem now() {
    rusage u{};
    getrusage(RUSAGE_THREAD, &u);
    auto seconds = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); };
    return {seconds(u.ru_utime), seconds(u.ru_stime)};
  }
};

/// Procedural terrain of about `triangles` triangles (2 n^2), made once per size.
const std::vector<PrimRef>& terrain_refs(int triangles) {
  static std::map<int, std::vector<PrimRef>> cache;
  auto it = cache.find(triangles);
  if (it == cache.end()) {
    int n = 1;
    while (2 * (n + 1) * (n + 1) <= triangles) ++n;
    it = cache.emplace(triangles, make_prim_refs(test::make_terrain(n, 7))).first;
  }
  return it->second;
}

// [ch04-bench-build]
/// Build speed: wall-clock time (two threads need it), peak bytes beyond what existed before,
/// and the SAH cost of the tree, for builds into fresh memory.
template <int N>
void bm_build(benchmark::State& state, const std::vector<PrimRef>* refs, Builder builder,
              int threads, int bins, int leaf_block) {
  size_t peak = 0;
  UserSystem spent;
  BuildTree<N> tree;
  for (auto _ : state) {
    // Free the previous tree, and the blocks chapter 1's cache keeps, before measuring this
    // build's peak: every build here starts from fresh memory, as a program's first does.
    tree = BuildTree<N>();
    release_cached_blocks();
    const size_t before = g_bytes.load();
    g_peak = before;
    const UserSystem start = UserSystem::now();
    tree = build<N>(*refs, builder, threads, bins, OccluderOrder::likely_blocker, leaf_block);
    const UserSystem end = UserSystem::now();
    spent.user += end.user - start.user;
    spent.system += end.system - start.system;
    peak = std::max(peak, g_peak.load() - before);
    benchmark::DoNotOptimize(tree.nodes.data());
  }
  const double prims = double(refs->size());
  state.counters["Mtris"] =
      benchmark::Counter(double(state.iterations()) * prims * 1e-6, benchmark::Counter::kIsRate);
  state.counters["sah"] = sah(tree);
  state.counters["nodes"] = double(tree.nodes.size());
  state.counters["peak_MB"] = double(peak) * 1e-6;
  state.counters["peak_B/tri"] = double(peak) / prims;
  // The calling thread's user and system time per triangle (all of the build's with one thread).
  const double per_tri = 1e9 / (double(state.iterations()) * prims);
  state.counters["user_ns/tri"] = spent.user * per_tri;
  state.counters["system_ns/tri"] = spent.system * per_tri;
}
// [ch04-bench-build]

void add_build(const std::string& name, const std::vector<PrimRef>* refs, int width, Builder b,
               int threads, int bins = 32, int leaf_block = 1) {
  auto fn = width == 2 ? bm_build<2> : width == 4 ? bm_build<4> : bm_build<8>;
  benchmark::RegisterBenchmark(name.c_str(), fn, refs, b, threads, bins, leaf_block)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
}

void register_builds(int triangles, bool widths) {
  const std::vector<PrimRef>* refs = &terrain_refs(triangles);
  const std::string size = "/tris:" + std::to_string(triangles);
  for (const int width : {2, 4, 8}) {
    if (!widths && width != 4) continue;
    const std::string prefix = "build/bvh" + std::to_string(width) + "/";
    add_build(prefix + "median" + size + "/threads:1", refs, width, Builder::median, 1);
    for (const Builder b : {Builder::binned, Builder::binned_rotations})
      for (const int threads : {1, 2})
        add_build(prefix + builder_name(b) + size + "/threads:" + std::to_string(threads), refs,
                  width, b, threads);
  }
}

/// Shadow rays: from the origins of diffuse rays (just off a surface) to point lights at random
/// places on a sphere around the scene, stopping short of the light. Random lights, so that no
/// child order is favoured by the direction the rays share.
std::vector<Ray> shadow_rays(const TriangleMesh& mesh, int count, uint64_t seed) {
  const Box3f box = mesh.bounds();
  const float radius = length(box.size());
  std::vector<Ray> rays = bench::diffuse_rays(mesh, count, seed);
  const std::vector<Ray> lights = bench::diffuse_rays(mesh, count, seed + 1);  // random directions
  for (size_t i = 0; i < rays.size(); ++i) {
    const Vec3f light = box.center() + normalize(lights[i].dir) * radius;
    rays[i].dir = light - rays[i].org;
    rays[i].tnear = 0.0f;
    rays[i].tfar = 0.999f;
  }
  return rays;
}

/// One scene's BVH4 from each builder, and its rays.
struct Traced {
  std::map<std::string, BVH4> bvh;
  std::map<std::string, double> sah;
  std::map<std::string, BuildTree<4>> trees;  ///< by occluder order
  std::map<std::string, BVH4> ordered;        ///< by occluder order
  std::map<std::string, BVH4> by_cost;        ///< by intersection cost (Ct = 1)
  std::vector<Ray> primary, diffuse, shadow;
};

/// The intersection costs compared (the traversal cost is 1).
constexpr const char* kCosts[] = {"1", "0.5", "0.25"};

const Traced& traced(const bench::SceneSource& scene) {
  static std::map<std::string, std::unique_ptr<Traced>> cache;
  auto& slot = cache[scene.name];
  if (!slot) {
    const TriangleMesh& mesh = bench::scene_mesh(scene);
    const std::vector<PrimRef> refs = make_prim_refs(mesh);
    slot = std::make_unique<Traced>();
    for (const Builder b : {Builder::median, Builder::binned, Builder::binned_rotations}) {
      BuildTree<4> tree = build<4>(refs, b, 0);
      slot->sah[builder_name(b)] = sah(tree);
      slot->bvh[builder_name(b)] = make_bvh<4>(tree, mesh);
    }
    for (const OccluderOrder order :
         {OccluderOrder::off, OccluderOrder::largest_box, OccluderOrder::likely_blocker}) {
      const std::string key = std::to_string(int(order));
      slot->trees[key] = build<4>(refs, Builder::binned_rotations, 0, 32, order);
      slot->ordered[key] = make_bvh<4>(slot->trees[key], mesh);
    }
    for (const char* cost : kCosts) {
      SahBuildOptions options;
      options.intersection_cost = std::stof(cost);
      slot->by_cost[cost] = make_bvh<4>(build_binned_sah<4>(refs, options), mesh);
    }
    slot->primary = bench::primary_rays(mesh, 256, 256);
    slot->diffuse = bench::diffuse_rays(mesh, 1 << 16, 1);
    slot->shadow = shadow_rays(mesh, 1 << 16, 2);
  }
  return *slot;
}

// [ch04-bench-trace]
/// Mrays/s through chapter 3's BVH4 kernels (best ISA, all tricks) of a tree from `builder`.
void bm_trace(benchmark::State& state, bench::SceneSource scene, Builder builder,
              std::string kind) {
  const Traced& t = traced(scene);
  const BVH4& bvh = t.bvh.at(builder_name(builder));
  const std::vector<Ray>& rays = kind == "primary"   ? t.primary
                                 : kind == "diffuse" ? t.diffuse
                                                     : t.shadow;
  std::vector<Hit> hits(rays.size());
  std::vector<uint8_t> blocked(rays.size());
  const Isa isa = best_isa();
  for (auto _ : state) {
    const double start = thread_seconds();
    if (kind == "shadow")
      occluded(isa, bvh, rays, blocked);
    else
      intersect(isa, bvh, rays, hits);
    state.SetIterationTime(thread_seconds() - start);
  }
  state.counters["Mrays"] = benchmark::Counter(
      double(state.iterations()) * double(rays.size()) * 1e-6, benchmark::Counter::kIsRate);
  state.counters["sah"] = t.sah.at(builder_name(builder));
}
// [ch04-bench-trace]

/// Mrays/s of trees built with intersection cost `cost` (traversal cost 1): which prices make
/// the trees chapter 3's kernels trace fastest.
void bm_costs(benchmark::State& state, bench::SceneSource scene, std::string cost,
              std::string kind) {
  const Traced& t = traced(scene);
  const BVH4& bvh = t.by_cost.at(cost);
  const std::vector<Ray>& rays = kind == "primary" ? t.primary : t.diffuse;
  std::vector<Hit> hits(rays.size());
  for (auto _ : state) {
    const double start = thread_seconds();
    intersect(best_isa(), bvh, rays, hits);
    state.SetIterationTime(thread_seconds() - start);
  }
  state.counters["Mrays"] = benchmark::Counter(
      double(state.iterations()) * double(rays.size()) * 1e-6, benchmark::Counter::kIsRate);
  state.counters["nodes"] = double(bvh.nodes.size());
}

// [ch04-bench-occluder]
/// How many nodes and leaves a shadow ray visits in a traversal that stops at the first hit and
/// enters the hit children of each node in their stored order (what occluder ordering is for)
/// or nearest first (what chapter 3's kernels do). Counted, not timed, so it is exact on a
/// shared machine.
double occlusion_visits(const BuildTree<4>& tree, const TriangleMesh& mesh, const Ray& ray,
                        bool by_distance) {
  std::vector<BuildTree<4>::Child> stack{tree.root};
  double visits = 0;
  auto entry = [&](const Box3f& b) {  // the entry distance, or +inf for a miss
    float t0 = ray.tnear, t1 = ray.tfar;
    for (int a = 0; a < 3; ++a) {
      const float inv = 1.0f / ray.dir[a];
      float n = (b.lower[a] - ray.org[a]) * inv, f = (b.upper[a] - ray.org[a]) * inv;
      if (n > f) std::swap(n, f);
      t0 = n > t0 ? n : t0;
      t1 = f < t1 ? f : t1;
    }
    return t0 <= t1 ? t0 : std::numeric_limits<float>::infinity();
  };
  auto hits_triangle = [&](uint32_t prim) {  // Möller-Trumbore, enough for counting
    const Vec3f p0 = mesh.vertex(prim, 0), e1 = mesh.vertex(prim, 1) - p0,
                e2 = mesh.vertex(prim, 2) - p0;
    const Vec3f p = cross(ray.dir, e2);
    const float det = dot(e1, p);
    if (det == 0.0f) return false;
    const Vec3f s = ray.org - p0;
    const float u = dot(s, p) / det;
    const Vec3f q = cross(s, e1);
    const float v = dot(ray.dir, q) / det, t = dot(e2, q) / det;
    return u >= 0 && v >= 0 && u + v <= 1 && t >= ray.tnear && t <= ray.tfar;
  };
  while (!stack.empty()) {
    const auto c = stack.back();
    stack.pop_back();
    ++visits;
    if (c.is_leaf()) {
      for (uint32_t i = c.index; i < c.index + c.leaf_count; ++i)
        if (hits_triangle(tree.prim_ids[i])) return visits;
      continue;
    }
    const auto& node = tree.nodes[c.index];
    std::array<std::pair<float, int>, 4> hit;
    int k = 0;
    for (int i = 0; i < node.num_children; ++i)
      if (const float t = entry(node.children[i].box); t < std::numeric_limits<float>::infinity())
        hit[k++] = {t, i};
    // Stored order: slot 0 on top of the stack. By distance: the nearest on top.
    for (int a = 1; by_distance && a < k; ++a)
      for (int b = a; b > 0 && hit[b].first < hit[b - 1].first; --b) std::swap(hit[b], hit[b - 1]);
    for (int j = k - 1; j >= 0; --j) stack.push_back(node.children[hit[j].second]);
  }
  return visits;
}

void bm_occluder(benchmark::State& state, bench::SceneSource scene, OccluderOrder order) {
  const Traced& t = traced(scene);
  const BuildTree<4>& tree = t.trees.at(std::to_string(int(order)));
  const BVH4& bvh = t.ordered.at(std::to_string(int(order)));
  const TriangleMesh& mesh = bench::scene_mesh(scene);
  std::vector<uint8_t> blocked(t.shadow.size());
  for (auto _ : state) {
    const double start = thread_seconds();
    occluded(best_isa(), bvh, t.shadow, blocked);
    state.SetIterationTime(thread_seconds() - start);
  }
  double stored = 0, nearest = 0;
  for (size_t i = 0; i < t.shadow.size(); i += 4) {
    stored += occlusion_visits(tree, mesh, t.shadow[i], false);
    nearest += occlusion_visits(tree, mesh, t.shadow[i], true);
  }
  state.counters["Mrays"] = benchmark::Counter(
      double(state.iterations()) * double(t.shadow.size()) * 1e-6, benchmark::Counter::kIsRate);
  state.counters["visits/ray"] = stored / double((t.shadow.size() + 3) / 4);
  state.counters["visits/ray_nearest"] = nearest / double((t.shadow.size() + 3) / 4);
  state.counters["blocked"] =
      double(std::count(blocked.begin(), blocked.end(), 1)) / double(blocked.size());
}
// [ch04-bench-occluder]

void register_traces() {
  for (const bench::SceneSource& scene : bench::bench_scenes()) {
    for (const char* kind : {"primary", "diffuse", "shadow"})
      for (const Builder b : {Builder::median, Builder::binned, Builder::binned_rotations})
        benchmark::RegisterBenchmark(
            ("trace/" + scene.name + "/" + kind + "/" + builder_name(b)).c_str(), bm_trace, scene,
            b, std::string(kind))
            ->UseManualTime();
    for (const char* kind : {"primary", "diffuse"})
      for (const char* cost : kCosts)
        benchmark::RegisterBenchmark(("costs/" + scene.name + "/" + kind + "/ci:" + cost).c_str(),
                                     bm_costs, scene, std::string(cost), std::string(kind))
            ->UseManualTime();
    const char* orders[] = {"off", "largest_box", "likely_blocker"};
    for (const OccluderOrder order :
         {OccluderOrder::off, OccluderOrder::largest_box, OccluderOrder::likely_blocker})
      benchmark::RegisterBenchmark(("occluder/" + scene.name + "/" + orders[int(order)]).c_str(),
                                   bm_occluder, scene, order)
          ->UseManualTime();
  }
}

/// Real meshes (under $RTK_SCENES), built with each builder at 1 and 2 threads.
void register_real_builds() {
  static std::map<std::string, std::vector<PrimRef>> refs;
  for (const bench::SceneSource& scene : bench::bench_scenes()) {
    if (scene.path.empty()) continue;
    refs[scene.name] = make_prim_refs(bench::scene_mesh(scene));
    const std::string prefix = "real/bvh4/" + scene.name + "/";
    add_build(prefix + "median/threads:1", &refs[scene.name], 4, Builder::median, 1);
    for (const Builder b : {Builder::binned, Builder::binned_rotations})
      for (const int threads : {1, 2})
        add_build(prefix + builder_name(b) + "/threads:" + std::to_string(threads),
                  &refs[scene.name], 4, b, threads);
    // What the rotations buy the wider tree (they cost it the most, having the most swaps).
    for (const Builder b : {Builder::binned, Builder::binned_rotations})
      add_build("real/bvh8/" + scene.name + "/" + builder_name(b) + "/threads:1", &refs[scene.name], 8, b, 1);
  }
}

/// A sphere of about `triangles` triangles (r rings of 2r segments, 4 r^2 triangles), made once
/// per size. Unlike the terrain, whose random bumps keep their height as its cells shrink, a
/// finer sphere is the same surface: only the count changes.
const std::vector<PrimRef>& sphere_refs(int triangles) {
  static std::map<int, std::vector<PrimRef>> cache;
  auto it = cache.find(triangles);
  if (it == cache.end()) {
    const int rings = int(std::lround(std::sqrt(double(triangles)) / 2));
    it = cache.emplace(triangles, make_prim_refs(test::make_sphere(rings, 2 * rings))).first;
  }
  return it->second;
}

// [ch04-bench-growth]
/// How build time and memory grow with the scene: the default structure's tree (BVH8, rotations
/// on, leaves priced in blocks of eight as RTK's default layout stores them) over spheres of 1M,
/// 4M and 16M triangles, one and two threads. A top-down build makes about log n passes over
/// the primitives, so time per triangle may grow like log n; the memory it holds per triangle
/// should not grow at all. The time of the thread that builds alone is also counted as CPU
/// time, which the load of a shared machine does not inflate.
void register_growth() {
  for (const int triangles : {1'000'000, 4'000'000, 16'000'000})
    for (const int threads : {1, 2})
      add_build("growth/bvh8/binned+rot+blocks8/tris:" + std::to_string(triangles) + "/threads:" +
                    std::to_string(threads),
                &sphere_refs(triangles), 8, Builder::binned_rotations, threads, 32, 8);
}
// [ch04-bench-growth]

const bool registered = [] {
  register_builds(100'000, true);
  register_builds(1'000'000, true);
  if (std::getenv("RTK_BENCH_LARGE")) {
    register_builds(4'000'000, false);
    register_builds(16'000'000, false);
  }
  // Bins per axis: build speed against tree quality.
  for (const int bins : {4, 8, 16, 32, 64})
    add_build("bins/bvh4/binned/bins:" + std::to_string(bins) + "/tris:1000000/threads:1",
              &terrain_refs(1'000'000), 4, Builder::binned, 1, bins);
  register_traces();
  register_real_builds();
  if (std::getenv("RTK_BENCH_GROWTH")) register_growth();
  return true;
}();

}  // namespace
