// Chapter 8's benchmark: Mrays/s of BVH4MB (and BVH8MB) against the static BVH4 with the same
// triangle4i leaves, on a static scene and on scenes whose objects move by 1 % and 30 % of the
// scene's size during the shutter; and the bytes per triangle of sparse and dense motion with
// a scene where 10 % of the vertices move.
//   ch08_bench --benchmark_filter='motion/diffuse/.*'
// Each benchmark compares two contenders A and B on the same ISA (bm_pair below); names read
// motion/<rays>/<sceneA>.<structureA>_vs_<sceneB>.<structureB>/<isa>, scenes static, move1,
// move30, cross30, tenth (make_scene below), structures bvh4 (chapter 6's BVH4 with
// triangle4i.moeller leaves, which ignores the time), bvh4mb.sparse, bvh4mb.dense, bvh8mb.sparse.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <span>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "02_bvh2/bench_support.h"
#include "06_layouts/layout_build.h"
#include "08_motion/bvh4mb.h"
#include "testing/scenes.h"

using namespace rtk;

namespace {

constexpr int kImage = 256;        // primary rays: a 256 x 256 image
constexpr int kDiffuse = 1 << 12;  // diffuse rays: few, so that many iterations run uninterrupted

// [ch08-bench-scene]
// Sixteen spheres of 2,046 triangles in a 4 x 4 grid in front of a static wall, in the unit
// square: the spheres move by `shift` of the scene's size along x during the shutter (all of
// them the same way, or with `crossing` the rows in turn left and right, so that they pass
// through each other). With `every_tenth`, instead, one vertex in ten moves (by 1 %): the
// scene for the memory of sparse against dense motion.
struct Scene {
  TriangleMesh t0, t1;
};
Scene make_scene(float shift, bool crossing, bool every_tenth) {
  Scene s;
  for (int i = 0; i < 16; ++i) {
    const Vec3f center{0.125f + 0.25f * float(i % 4), 0.125f + 0.25f * float(i / 4), 0.5f};
    const TriangleMesh sphere = test::make_sphere(32, 33, center, 0.1f);
    const uint32_t first = uint32_t(s.t0.vertices.size());
    s.t0.vertices.insert(s.t0.vertices.end(), sphere.vertices.begin(), sphere.vertices.end());
    for (auto t : sphere.triangles) s.t0.triangles.push_back({t[0] + first, t[1] + first, t[2] + first});
  }
  const size_t moving_vertices = s.t0.vertices.size();
  const uint32_t w = uint32_t(s.t0.vertices.size());
  s.t0.vertices.insert(s.t0.vertices.end(), {{-0.5f, -0.5f, 1.0f}, {1.5f, -0.5f, 1.0f}, {1.5f, 1.5f, 1.0f}, {-0.5f, 1.5f, 1.0f}});
  s.t0.triangles.push_back({w, w + 1, w + 2});
  s.t0.triangles.push_back({w, w + 2, w + 3});
  s.t1 = s.t0;
  const size_t per_sphere = moving_vertices / 16;
  for (size_t v = 0; v < moving_vertices; ++v) {
    const bool left = crossing && (v / per_sphere / 4) % 2 == 1;
    if (!every_tenth || v % 10 == 0) s.t1.vertices[v].x += every_tenth ? 0.01f : left ? -shift : shift;
  }
  return s;
}
// [ch08-bench-scene]

struct SceneSet {
  Scene scene;
  std::vector<Ray> primary, diffuse;
};

// Rays with uniform random shutter times (fixed seed), made on the scene at time 0.
const SceneSet& scene_of(const std::string& name) {
  static std::map<std::string, std::unique_ptr<SceneSet>> cache;
  auto& slot = cache[name];
  if (!slot) {
    slot = std::make_unique<SceneSet>();
    slot->scene = name == "static"    ? make_scene(0.0f, false, false)
                  : name == "move1"   ? make_scene(0.01f, false, false)
                  : name == "move30"  ? make_scene(0.3f, false, false)
                  : name == "cross30" ? make_scene(0.3f, true, false)
                                      : make_scene(0.0f, false, true);
    // Primary rays at uniform random times (a fixed seed). Diffuse rays leave the surfaces as
    // they are at the ray's time: 16 batches, batch k made on the scene at time (k + 0.5) / 16.
    slot->primary = bench::primary_rays(slot->scene.t0, kImage, kImage);
    std::mt19937_64 random(5);
    for (Ray& r : slot->primary) r.time = float(double(random() >> 40) * 0x1.0p-24);
    const MotionMesh mesh = make_motion_mesh(slot->scene.t0, slot->scene.t1);
    for (int k = 0; k < 16; ++k) {
      const float time = (float(k) + 0.5f) / 16.0f;
      for (Ray r : bench::diffuse_rays(mesh.at(time), kDiffuse / 16, uint64_t(k) + 1)) {
        r.time = time;
        slot->diffuse.push_back(r);
      }
    }
  }
  return *slot;
}

template <int N>
const BVHMB<N>& mb_of(const std::string& name, MotionStorage storage) {
  static std::map<std::string, std::unique_ptr<BVHMB<N>>> cache;
  auto& slot = cache[name + std::string(motion_storage_name(storage))];
  if (!slot) {
    const Scene& s = scene_of(name).scene;
    slot = std::make_unique<BVHMB<N>>(build_bvhmb<N>(make_motion_mesh(s.t0, s.t1, storage)));
  }
  return *slot;
}

const LayoutBVH<4>& bvh4_of(const std::string& name) {
  static std::map<std::string, std::unique_ptr<LayoutBVH<4>>> cache;
  auto& slot = cache[name];
  if (!slot)
    slot = std::make_unique<LayoutBVH<4>>(
        build_layout_bvh<4>(scene_of(name).scene.t0, TriangleLayout::triangle4i));
  return *slot;
}

/// One contender of a pair: a scene and a structure, "bvh4" (chapter 6's static BVH4 with
/// triangle4i.moeller leaves), "bvh4mb.sparse", "bvh4mb.dense" or "bvh8mb.sparse".
struct Contender {
  std::string scene, structure;
  std::string name() const { return scene + "." + structure; }
  void trace(Isa isa, std::span<const Ray> rays, std::span<Hit> hits) const {
    if (structure == "bvh4") intersect(isa, bvh4_of(scene), rays, hits);
    else if (structure == "bvh8mb.sparse") intersect(isa, mb_of<8>(scene, MotionStorage::sparse), rays, hits);
    else intersect(isa, mb_of<4>(scene, structure == "bvh4mb.dense" ? MotionStorage::dense : MotionStorage::sparse), rays, hits);
  }
  /// Bytes of the whole structure and of its vertex data alone.
  std::pair<size_t, size_t> bytes() const {
    if (structure == "bvh4") return {bvh4_of(scene).bytes(), bvh4_of(scene).shared->vertices.size() * sizeof(Vec3f)};
    if (structure == "bvh8mb.sparse") return {mb_of<8>(scene, MotionStorage::sparse).bytes(), mb_of<8>(scene, MotionStorage::sparse).mesh.vertex_bytes()};
    const BVH4MB& b = mb_of<4>(scene, structure == "bvh4mb.dense" ? MotionStorage::dense : MotionStorage::sparse);
    return {b.bytes(), b.mesh.vertex_bytes()};
  }
};

// [ch08-bench-pair]
// The machine is shared, and its load changes from one second to the next, so two contenders
// measured one after the other can differ by more than what sets them apart. Each iteration
// therefore traces A's rays through A and then B's through B, and each keeps its fastest
// iteration: the ratio B/A compares two best cases taken under the same conditions.
void bm_pair(benchmark::State& state, Contender a, Contender b, Isa isa, bool diffuse) {
  using Clock = std::chrono::steady_clock;
  const std::vector<Ray>& rays_a = diffuse ? scene_of(a.scene).diffuse : scene_of(a.scene).primary;
  const std::vector<Ray>& rays_b = diffuse ? scene_of(b.scene).diffuse : scene_of(b.scene).primary;
  std::vector<Hit> hits(std::max(rays_a.size(), rays_b.size()));
  double best_a = 1e30, best_b = 1e30;
  for (auto _ : state) {
    const auto t0 = Clock::now();
    a.trace(isa, rays_a, std::span(hits).first(rays_a.size()));
    const auto t1 = Clock::now();
    b.trace(isa, rays_b, std::span(hits).first(rays_b.size()));
    const auto t2 = Clock::now();
    benchmark::DoNotOptimize(hits.data());
    best_a = std::min(best_a, std::chrono::duration<double>(t1 - t0).count());
    best_b = std::min(best_b, std::chrono::duration<double>(t2 - t1).count());
  }
  const double tris = double(scene_of(a.scene).scene.t0.size());
  state.counters["A_Mrays/s"] = double(rays_a.size()) / best_a * 1e-6;
  state.counters["B_Mrays/s"] = double(rays_b.size()) / best_b * 1e-6;
  state.counters["B/A"] = (double(rays_b.size()) / best_b) / (double(rays_a.size()) / best_a);
  state.counters["A_bytes/tri"] = double(a.bytes().first) / tris;
  state.counters["B_bytes/tri"] = double(b.bytes().first) / tris;
  state.counters["A_vtx_bytes/tri"] = double(a.bytes().second) / tris;
  state.counters["B_vtx_bytes/tri"] = double(b.bytes().second) / tris;
}
// [ch08-bench-pair]

const bool registered = [] {
  const std::vector<std::pair<Contender, Contender>> pairs = {
      {{"static", "bvh4"}, {"static", "bvh4mb.sparse"}},           // what the motion structure costs
      {{"static", "bvh4mb.sparse"}, {"move1", "bvh4mb.sparse"}},   // what small motion costs
      {{"static", "bvh4mb.sparse"}, {"move30", "bvh4mb.sparse"}},  // large motion, all one way
      {{"static", "bvh4mb.sparse"}, {"cross30", "bvh4mb.sparse"}}, // large motion, crossing
      {{"tenth", "bvh4mb.dense"}, {"tenth", "bvh4mb.sparse"}},     // sparse against dense
      {{"static", "bvh4mb.sparse"}, {"static", "bvh8mb.sparse"}},  // wider nodes
      {{"move30", "bvh4mb.sparse"}, {"move30", "bvh8mb.sparse"}},
  };
  for (const auto& [a, b] : pairs)
    for (const bool diffuse : {false, true})
      for (const Isa isa : supported_isas()) {
        if (b.structure == "bvh8mb.sparse" && isa != Isa::avx2 && isa != Isa::avx512) continue;
        std::string name = "motion/";
        name.append(diffuse ? "diffuse/" : "primary/").append(a.name()).append("_vs_").append(b.name());
        name.append("/").append(isa_name(isa));
        benchmark::RegisterBenchmark(name.c_str(), bm_pair, a, b, isa, diffuse)->Unit(benchmark::kMillisecond)->MinTime(diffuse ? 1.5 : 0.5);
      }
  return true;
}();

}  // namespace
