// Chapter 9: a batch sorted by octant and origin cell. The keys mean what they say, the sort is a
// stable permutation, the policy sorts only incoherent batches, and the answers of a sorted batch
// land where the caller expects them.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <span>
#include <stdexcept>
#include <vector>

#include "09_inflight/ray_order.h"
#include "replay/ray_generator.h"
#include "testing/scenes.h"

using namespace rtk;

namespace {

const Box3f kUnitBox{{0, 0, 0}, {1, 1, 1}};

Ray ray_at(Vec3f org, Vec3f dir) {
  Ray r;
  r.org = org;
  r.dir = dir;
  return r;
}

// A kernel that answers each ray with what identifies it: the ray's tnear, which the tests set
// to the ray's index in the batch, as the primitive ID.
void answer_with_tnear(const void*, std::span<const Ray> rays, std::span<Hit> hits) {
  for (size_t i = 0; i < rays.size(); ++i) hits[i].prim = uint32_t(rays[i].tnear);
}
void occluded_if_odd(const void*, std::span<const Ray> rays, std::span<uint8_t> occluded) {
  for (size_t i = 0; i < rays.size(); ++i) occluded[i] = uint8_t(uint32_t(rays[i].tnear) % 2);
}

// Diffuse rays of a small scene, each ray's tnear set to its index.
std::vector<Ray> numbered_diffuse_rays(size_t n) {
  std::vector<Ray> rays =
      generate_rays(test::make_sphere(12, 24, {0.5f, 0.5f, 0.5f}, 0.4f), RayKind::diffuse, n, 3);
  for (size_t i = 0; i < rays.size(); ++i) rays[i].tnear = float(i);
  return rays;
}

}  // namespace

TEST_CASE("the key is the octant above the Morton code of the origin's cell") {
  const RayOrderKey key(kUnitBox);
  CHECK(key(ray_at({0, 0, 0}, {1, 1, 1})) == 0u);
  CHECK(key(ray_at({0, 0, 0}, {-1, 1, 1})) == 1u << 12);
  CHECK(key(ray_at({0, 0, 0}, {1, -1, -1})) == 6u << 12);
  // The far corner is cell (15, 15, 15): all twelve Morton bits set.
  CHECK(key(ray_at({1, 1, 1}, {1, 1, 1})) == 0xfffu);
  // One cell along x, y or z is Morton bit 0, 1 or 2; cell 2 along x is bit 3.
  const float step = 1.0f / 16;
  CHECK(key(ray_at({1.5f * step, 0, 0}, {1, 1, 1})) == 1u);
  CHECK(key(ray_at({0, 1.5f * step, 0}, {1, 1, 1})) == 2u);
  CHECK(key(ray_at({0, 0, 1.5f * step}, {1, 1, 1})) == 4u);
  CHECK(key(ray_at({2.5f * step, 0, 0}, {1, 1, 1})) == 8u);
  // Outside the box: the nearest cell.
  CHECK(key(ray_at({-5, 0.01f, 7}, {1, 1, 1})) == key(ray_at({0, 0.01f, 1}, {1, 1, 1})));
  // NaN and infinite rays get a key like any other.
  const float nan = std::numeric_limits<float>::quiet_NaN(),
              inf = std::numeric_limits<float>::infinity();
  CHECK(key(ray_at({nan, nan, nan}, {nan, 1, 1})) < kOrderKeys);
  CHECK(key(ray_at({inf, -inf, 0}, {1, 1, 1})) < kOrderKeys);
  // An empty or flat box puts every origin in one cell along the axes it lacks.
  const RayOrderKey none{Box3f{}};
  CHECK(none(ray_at({3, -4, 5}, {1, 1, 1})) == 0u);
  const RayOrderKey flat(Box3f{{0, 0, 0}, {1, 0, 1}});
  CHECK(flat(ray_at({0, 9, 0}, {1, 1, 1})) == flat(ray_at({0, -9, 0}, {1, 1, 1})));
}

TEST_CASE("sorting is a stable permutation in key order, the rays copied bit for bit") {
  const std::vector<Ray> rays = numbered_diffuse_rays(5000);
  const RayOrderKey key(Box3f{{0.1f, 0.1f, 0.1f}, {0.9f, 0.9f, 0.9f}});
  SortedRays sorted;
  RayOrderPolicy always;
  always.mode = RayOrderPolicy::Mode::always;
  REQUIRE(sort_rays(rays, key, always, sorted));
  REQUIRE(sorted.size() == rays.size());
  REQUIRE(sorted.from.size() == rays.size());
  std::vector<uint8_t> seen(rays.size(), 0);
  for (size_t i = 0; i < sorted.size(); ++i) {
    const uint32_t from = sorted.from[i];
    REQUIRE(from < rays.size());
    CHECK(seen[from] == 0);
    seen[from] = 1;
    CHECK(std::memcmp(&sorted.rays[i], &rays[from], sizeof(Ray)) == 0);
    if (i > 0) {
      const uint32_t a = key(sorted.rays[i - 1]), b = key(sorted.rays[i]);
      CHECK(a <= b);
      if (a == b) CHECK(sorted.from[i - 1] < from);  // equal keys in their given order
    }
  }
  // Diffuse rays of a scene are incoherent: many keys, so the order really changed.
  CHECK_FALSE(std::is_sorted(sorted.from.begin(), sorted.from.end()));
}

TEST_CASE("sorting on several threads gives the order of one thread") {
  // Enough rays for three threads to take a part each.
  const std::vector<Ray> rays = numbered_diffuse_rays(50000);
  const RayOrderKey key(kUnitBox);
  RayOrderPolicy always;
  always.mode = RayOrderPolicy::Mode::always;
  SortedRays one, many;
  REQUIRE(sort_rays(rays, key, always, one, 1));
  for (const int threads : {2, 3}) {
    CAPTURE(threads);
    REQUIRE(sort_rays(rays, key, always, many, threads));
    CHECK(many.from == one.from);
    CHECK(std::memcmp(many.rays.data(), one.rays.data(), one.size() * sizeof(Ray)) == 0);
  }
}

TEST_CASE("the policy sorts large incoherent batches only") {
  const RayOrderKey key(kUnitBox);
  SortedRays sorted;
  RayOrderPolicy policy;  // automatic
  const std::vector<Ray> diffuse = numbered_diffuse_rays(policy.min_rays);
  CHECK(sort_rays(diffuse, key, policy, sorted));
  // Fewer rays than min_rays: as given.
  CHECK_FALSE(
      sort_rays(std::span<const Ray>(diffuse).first(policy.min_rays - 1), key, policy, sorted));
  CHECK(sorted.size() == 0);
  // One origin and one octant (a pinhole camera's rays into one quadrant): coherent already.
  std::vector<Ray> camera(policy.min_rays, ray_at({0.5f, 0.5f, 2.0f}, {0.1f, 0.2f, -1.0f}));
  for (size_t i = 0; i < camera.size(); ++i) camera[i].dir.x = 0.001f * float(i);
  CHECK_FALSE(sort_rays(camera, key, policy, sorted));
  // The modes that override it.
  policy.mode = RayOrderPolicy::Mode::always;
  CHECK(sort_rays(camera, key, policy, sorted));
  CHECK(sorted.size() == camera.size());
  policy.mode = RayOrderPolicy::Mode::never;
  CHECK_FALSE(sort_rays(diffuse, key, policy, sorted));
  CHECK(sorted.size() == 0);
}

TEST_CASE("a sorted batch's answers land where the caller expects them, from any range") {
  const std::vector<Ray> rays = numbered_diffuse_rays(1000);
  SortedRays sorted;
  RayOrderPolicy always;
  always.mode = RayOrderPolicy::Mode::always;
  REQUIRE(sort_rays(rays, RayOrderKey(kUnitBox), always, sorted));
  const TraceKernels kernels{answer_with_tnear, occluded_if_odd};
  std::vector<Hit> hits(rays.size());
  std::vector<uint8_t> occluded(rays.size(), 7);
  // Three ranges of different lengths, as threads would take them; one crosses a call's 256.
  const size_t cuts[] = {0, 3, 700, rays.size()};
  for (int r = 0; r < 3; ++r) {
    intersect_sorted(kernels, nullptr, sorted, cuts[r], cuts[r + 1] - cuts[r], hits);
    occluded_sorted(kernels, nullptr, sorted, cuts[r], cuts[r + 1] - cuts[r], occluded);
  }
  for (size_t i = 0; i < rays.size(); ++i) {
    CHECK(hits[i].prim == i);
    CHECK(occluded[i] == i % 2);
  }
  CHECK_THROWS_AS(intersect_sorted(kernels, nullptr, sorted, 999, 2, hits), std::invalid_argument);
  std::vector<Hit> short_hits(10);
  CHECK_THROWS_AS(intersect_sorted(kernels, nullptr, sorted, 0, 10, short_hits),
                  std::invalid_argument);
}
