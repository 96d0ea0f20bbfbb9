// Chapter 8: BVH4MB and BVH8MB against brute force at the ray's time, every ISA against the
// scalar variant, the static case against chapter 6's BVH4, the node boxes against the
// triangles at many times, bad rays, and sparse against dense storage.
#include <cmath>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include "06_layouts/layout_build.h"
#include "06_layouts/triangle_i.h"
#include "07_intersectors/layout_intersectors.h"
#include "08_motion/bvh4mb.h"
#include "test_support_ch08.h"

using namespace rtk;

namespace {

using test::same_bits;

template <int N>
std::vector<Hit> trace(Isa isa, const BVHMB<N>& bvh, const std::vector<Ray>& rays) {
  std::vector<Hit> hits(rays.size());
  intersect(isa, bvh, rays, hits);
  return hits;
}

template <int N>
std::vector<uint8_t> trace_occlusion(Isa isa, const BVHMB<N>& bvh, const std::vector<Ray>& rays) {
  std::vector<uint8_t> occluded(rays.size());
  rtk::occluded(isa, bvh, rays, occluded);
  return occluded;
}

// The oracle's answers for a scene's rays, computed once per scene.
struct Case {
  MotionMesh mesh;
  std::vector<Ray> rays;
  std::vector<Hit> oracle;
};
const Case& moving_case(float shift) {
  static std::vector<std::pair<float, std::unique_ptr<Case>>> cache;
  for (auto& [s, c] : cache)
    if (s == shift) return *c;
  auto c = std::make_unique<Case>();
  const test::MovingScene scene = test::make_moving_scene(shift, 11);
  c->mesh = make_motion_mesh(scene.t0, scene.t1);
  c->rays = test::timed_rays(c->mesh, 600, 21);
  for (const Ray& r : c->rays) c->oracle.push_back(test::oracle_at_time(c->mesh, r));
  cache.emplace_back(shift, std::move(c));
  return *cache.back().second;
}

// Every ISA against brute force (within the oracle's tolerance) and against the scalar variant
// (bit for bit: the same arithmetic in the same order); occlusion against the closest hits.
template <int N>
void check_against_oracle(const Case& c, IntersectorKind intersector) {
  const BVHMB<N> bvh = build_bvhmb<N>(c.mesh, intersector);
  const std::vector<Hit> scalar = trace(Isa::scalar, bvh, c.rays);
  for (const Isa isa : supported_isas()) {
    CAPTURE(isa_name(isa));
    const std::vector<Hit> hits = trace(isa, bvh, c.rays);
    const std::vector<uint8_t> occluded = trace_occlusion(isa, bvh, c.rays);
    size_t found = 0;
    for (size_t i = 0; i < c.rays.size(); ++i) {
      CAPTURE(i);
      CAPTURE(c.rays[i].time);
      const std::string why = test::compare_hits(c.mesh.at(c.rays[i].time), c.rays[i], hits[i], c.oracle[i]);
      CHECK_MESSAGE(why.empty(), why);
      CHECK(same_bits(hits[i], scalar[i]));
      CHECK(occluded[i] == uint8_t(hits[i].found()));
      found += hits[i].found();
    }
    CHECK(found > c.rays.size() / 4);  // the rays do meet the scene
  }
}

// The triangles under a node reference, from its leaves' blocks (unused lanes repeat lane 0).
template <int N>
void collect_prims(const BVHMB<N>& bvh, NodeRef ref, std::set<uint32_t>& prims) {
  if (is_leaf(ref)) {
    const auto* blocks = reinterpret_cast<const TriangleMi<4>*>(bvh.leaves.bytes.data() + leaf_offset(ref));
    for (uint32_t b = 0; b < leaf_blocks(ref); ++b)
      for (int i = 0; i < 4; ++i) prims.insert(blocks[b].prim[i]);
    return;
  }
  for (int c = 0; c < N; ++c) collect_prims(bvh, bvh.node(ref).children[c], prims);
}

// Checks, at each of `times`, that every child's interpolated box (as the kernels compute it)
// contains every vertex of every triangle under it (as the kernels compute them).
template <int N>
size_t check_boxes(const BVHMB<N>& bvh, const std::vector<float>& times) {
  size_t checked = 0;
  for (const NodeMB<N>& node : bvh.nodes)
    for (int c = 0; c < N; ++c) {
      if (node.children[c] == kEmptyLeaf) continue;
      std::set<uint32_t> prims;
      collect_prims(bvh, node.children[c], prims);
      for (const float t : times) {
        const Box3f box{{node.lower_x[c] + t * node.dlower_x[c], node.lower_y[c] + t * node.dlower_y[c],
                         node.lower_z[c] + t * node.dlower_z[c]},
                        {node.upper_x[c] + t * node.dupper_x[c], node.upper_y[c] + t * node.dupper_y[c],
                         node.upper_z[c] + t * node.dupper_z[c]}};
        for (const uint32_t prim : prims)
          for (const uint32_t v : bvh.mesh.base.triangles[prim]) {
            const Vec3f p = bvh.mesh.position(v, t);
            CHECK_MESSAGE(box.contains(p), "triangle ", prim, " leaves its box at time ", t);
            ++checked;
          }
      }
    }
  return checked;
}

}  // namespace

TEST_CASE("ch08: BVH4MB and BVH8MB agree with brute force at the ray's time, every ISA and intersector") {
  for (const float shift : {0.01f, 0.3f}) {
    CAPTURE(shift);
    const Case& c = moving_case(shift);
    for (const IntersectorKind kind : kAllIntersectors) {
      CAPTURE(intersector_name(kind));
      check_against_oracle<4>(c, kind);
    }
    check_against_oracle<8>(c, IntersectorKind::moeller);
  }
}

TEST_CASE("ch08: a static scene through BVH4MB gives the hits of BVH4 with triangle4i leaves") {
  const test::MovingScene scene = test::make_moving_scene(0.0f, 5);
  const MotionMesh mesh = make_motion_mesh(scene.t0, scene.t0);
  CHECK(!mesh.moves());
  const std::vector<Ray> rays = test::timed_rays(mesh, 800, 6);
  for (const IntersectorKind kind : kAllIntersectors) {
    CAPTURE(intersector_name(kind));
    const BVH4MB mb = build_bvhmb<4>(mesh, kind);
    const LayoutBVH<4> bvh4 = build_layout_bvh<4>(scene.t0, TriangleLayout::triangle4i);
    for (const Isa isa : supported_isas()) {
      CAPTURE(isa_name(isa));
      std::vector<Hit> expected(rays.size());
      intersect(isa, bvh4, kind, rays, expected);
      const std::vector<Hit> hits = trace(isa, mb, rays);
      // The same triangles, computed the same way, in the same tree: the same bits. (The time
      // plays no part: a static vertex is p0 + t * 0 = p0 exactly.)
      for (size_t i = 0; i < rays.size(); ++i) {
        CAPTURE(i);
        CHECK(same_bits(hits[i], expected[i]));
      }
    }
  }
}

TEST_CASE("ch08: every interpolated node box contains its interpolated triangles, over the whole shutter") {
  std::vector<float> times = {0.0f, 1.0f, 0x1p-24f, 1.0f - 0x1p-24f, 0.5f};
  for (int k = 1; k < 64; ++k) times.push_back(float(k) / 64.0f);
  std::mt19937_64 random(3);
  for (int k = 0; k < 32; ++k) times.push_back(float(double(random() >> 40) * 0x1.0p-24));
  for (const float shift : {0.01f, 0.3f, 3.0f}) {
    CAPTURE(shift);
    const test::MovingScene scene = test::make_moving_scene(shift, 17);
    // Far from the origin too, where the interpolation's rounding is largest against the scene.
    for (const Vec3f offset : {Vec3f(0.0f), Vec3f(1000.0f, -3000.0f, 500.0f)}) {
      test::MovingScene moved = scene;
      for (auto* mesh : {&moved.t0, &moved.t1})
        for (Vec3f& v : mesh->vertices) v += offset;
      const BVH4MB bvh4 = build_bvhmb<4>(make_motion_mesh(moved.t0, moved.t1));
      const BVH8MB bvh8 = build_bvhmb<8>(make_motion_mesh(moved.t0, moved.t1));
      CHECK(check_boxes(bvh4, times) > 0);
      CHECK(check_boxes(bvh8, times) > 0);
      // Every triangle with area is in exactly the leaves of the tree, none lost.
      std::set<uint32_t> prims;
      collect_prims(bvh4, bvh4.root, prims);
      CHECK(prims.size() == scene.t0.size());
    }
  }
}

TEST_CASE("ch08: rays outside the shutter, with a NaN time, or not rays at all miss and disturb nothing") {
  const Case& c = moving_case(0.3f);
  const BVH4MB bvh = build_bvhmb<4>(c.mesh);
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  std::vector<Ray> bad = test::invalid_rays();
  Ray through = c.rays[0];
  for (const Ray& r : c.rays)
    if (test::oracle_at_time(c.mesh, r).found()) through = r;  // a ray that hits at its time
  for (const float time : {nan, -nan, inf, -inf, -0x1p-24f, 1.0f + 0x1p-23f, -1.0f, 2.0f}) {
    Ray r = through;
    r.time = time;
    bad.push_back(r);
  }
  // Interleaved with good rays, whose answers must not change.
  std::vector<Ray> mixed;
  for (size_t i = 0; i < c.rays.size(); ++i) {
    mixed.push_back(c.rays[i]);
    mixed.push_back(bad[i % bad.size()]);
  }
  const std::vector<Hit> clean = trace(Isa::scalar, bvh, c.rays);
  for (const Isa isa : supported_isas()) {
    CAPTURE(isa_name(isa));
    const std::vector<Hit> hits = trace(isa, bvh, mixed);
    const std::vector<uint8_t> occluded = trace_occlusion(isa, bvh, mixed);
    for (size_t i = 0; i < c.rays.size(); ++i) {
      CHECK(same_bits(hits[2 * i], clean[i]));
      const Ray& b = mixed[2 * i + 1];
      if (!is_valid_motion_ray(b)) {
        CHECK(!hits[2 * i + 1].found());
        CHECK(hits[2 * i + 1].t == 0.0f);
        CHECK(occluded[2 * i + 1] == 0);
      }
    }
  }
  // A time of -0 is time 0.
  Ray zero = through;
  zero.time = -0.0f;
  Ray plus = through;
  plus.time = 0.0f;
  const std::vector<Hit> both = trace(Isa::scalar, bvh, {zero, plus});
  CHECK(same_bits(both[0], both[1]));
}

TEST_CASE("ch08: sparse and dense storage give identical hits") {
  for (const float shift : {0.01f, 0.3f}) {
    const Case& c = moving_case(shift);
    const MotionMesh dense = convert_storage(c.mesh, MotionStorage::dense);
    CHECK(c.mesh.storage == MotionStorage::sparse);
    CHECK(dense.vertex_bytes() > c.mesh.vertex_bytes());
    for (const IntersectorKind kind : {IntersectorKind::moeller, IntersectorKind::pluecker}) {
      const BVH4MB s = build_bvhmb<4>(c.mesh, kind);
      const BVH4MB d = build_bvhmb<4>(dense, kind);
      for (const Isa isa : supported_isas()) {
        CAPTURE(isa_name(isa));
        const std::vector<Hit> hs = trace(isa, s, c.rays), hd = trace(isa, d, c.rays);
        const std::vector<uint8_t> os = trace_occlusion(isa, s, c.rays), od = trace_occlusion(isa, d, c.rays);
        for (size_t i = 0; i < c.rays.size(); ++i) {
          CHECK(same_bits(hs[i], hd[i]));
          CHECK(os[i] == od[i]);
        }
      }
    }
  }
}

TEST_CASE("ch08: triangles with non-finite motion are never hit and do not disturb the others") {
  const test::MovingScene scene = test::make_moving_scene(0.3f, 23);
  test::MovingScene broken = scene;
  const float inf = std::numeric_limits<float>::infinity();
  // Vertex 0 flies off to infinity; vertex 1's motion overflows; vertex 2 moves to NaN.
  broken.t1.vertices[0] = {inf, 0.0f, 0.0f};
  broken.t0.vertices[1] = {-3e38f, 0.5f, 0.5f};
  broken.t1.vertices[1] = {3e38f, 0.5f, 0.5f};
  broken.t1.vertices[2].y = std::numeric_limits<float>::quiet_NaN();
  const MotionMesh mesh = make_motion_mesh(broken.t0, broken.t1);
  const BVH4MB bvh = build_bvhmb<4>(mesh);
  std::set<uint32_t> broken_prims;
  for (uint32_t p = 0; p < mesh.size(); ++p)
    for (const uint32_t v : mesh.base.triangles[p])
      if (v < 3) broken_prims.insert(p);
  REQUIRE(!broken_prims.empty());
  // The oracle over the other triangles only.
  MotionMesh rest = mesh;
  for (const uint32_t p : broken_prims) rest.base.triangles[p] = {3, 3, 3};  // zero area: never hit
  const std::vector<Ray> rays = test::timed_rays(mesh, 400, 29);
  for (const Isa isa : supported_isas()) {
    CAPTURE(isa_name(isa));
    const std::vector<Hit> hits = trace(isa, bvh, rays);
    for (size_t i = 0; i < rays.size(); ++i) {
      CHECK(broken_prims.count(hits[i].prim) == 0);
      const std::string why = test::compare_hits(rest.at(rays[i].time), rays[i], hits[i], test::oracle_at_time(rest, rays[i]));
      CHECK_MESSAGE(why.empty(), why);
    }
  }
}

TEST_CASE("ch08: an empty scene and a one-triangle scene") {
  const MotionMesh empty = make_motion_mesh({}, {}, MotionStorage::dense);
  const BVH4MB none = build_bvhmb<4>(empty);
  CHECK(none.nodes.empty());
  TriangleMesh one;
  one.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  one.triangles = {{0, 1, 2}};
  TriangleMesh moved = one;
  moved.vertices[1].x = 3.0f;  // the triangle stretches along x
  const BVH4MB single = build_bvhmb<4>(make_motion_mesh(one, moved));
  CHECK(is_leaf(single.root));  // a leaf root: no inner node at all
  // A ray through x = 1.5, y = 0.1 misses at time 0 and hits from the time the edge passes it.
  std::vector<Ray> rays;
  for (const float time : {0.0f, 0.25f, 0.5f, 1.0f}) {
    Ray r;
    r.org = {1.5f, 0.1f, 1.0f};
    r.dir = {0, 0, -1};
    r.time = time;
    rays.push_back(r);
  }
  for (const Isa isa : supported_isas()) {
    CAPTURE(isa_name(isa));
    std::vector<Hit> hits(rays.size());
    intersect(isa, none, rays, hits);
    for (const Hit& h : hits) CHECK(!h.found());
    hits = trace(isa, single, rays);
    // At time t the edge from (1 + 2t, 0) to (0, 1) passes x = 1.5 at y = 0.1 when
    // 1.5 / (1 + 2t) + 0.1 <= 1, that is from t = 1/3 on.
    CHECK(!hits[0].found());
    CHECK(!hits[1].found());
    CHECK(hits[2].found());
    CHECK(hits[3].found());
    CHECK(hits[3].t == 1.0f);
  }
}
