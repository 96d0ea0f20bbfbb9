// The slab test (slab.h) of every variant and width against the scalar variant, against an
// exact oracle, and on the rays that lie in a box's plane.
#include <doctest/doctest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "01_base/slab_kernels.h"
#include "01_base/ray_sets.h"

using namespace rtk;

namespace {

const float kInf = std::numeric_limits<float>::infinity();

// Random boxes in [-1, 1]^3, and boxes on a grid of quarters whose planes the axis-parallel
// rays below start on, some of them flat in one axis.
std::vector<Box3f> make_boxes(uint64_t seed) {
  std::mt19937_64 random(seed);
  auto uniform = [&] { return float(double(random() >> 11) * 0x1.0p-53); };
  std::vector<Box3f> boxes;
  for (int i = 0; i < 120; ++i) {
    Vec3f lo{uniform() * 2 - 1, uniform() * 2 - 1, uniform() * 2 - 1};
    boxes.push_back({lo, lo + Vec3f{uniform(), uniform(), uniform()} * 0.5f});
  }
  for (int i = 0; i < 80; ++i) {
    Vec3f lo, hi;
    for (int axis = 0; axis < 3; ++axis) {
      lo[axis] = float(int(random() % 8) - 4) * 0.25f;
      hi[axis] = lo[axis] + float(random() % 3) * 0.25f;  // 0: a flat box
    }
    boxes.push_back({lo, hi});
  }
  return boxes;
}

// Rays parallel to two axes whose origins sit on the grid's planes, with both signs of zero.
std::vector<Ray> grid_rays(uint64_t seed) {
  std::mt19937_64 random(seed);
  std::vector<Ray> rays;
  for (int i = 0; i < 60; ++i) {
    Ray r;
    for (int axis = 0; axis < 3; ++axis) r.org[axis] = float(int(random() % 12) - 6) * 0.25f;
    const int axis = int(random() % 3);
    r.dir = Vec3f(random() % 2 ? 0.0f : -0.0f);
    r.dir[axis] = random() % 2 ? 1.0f : -1.0f;
    r.org[axis] = r.dir[axis] > 0 ? -2.0f : 2.0f;
    rays.push_back(r);
  }
  return rays;
}

// Mixed rays from the test support (random, axis-aligned, grazing, not rays at all), the grid
// rays, and rays aimed at the centres of some boxes, so that hits are not rare.
std::vector<Ray> all_rays(const std::vector<Box3f>& boxes) {
  const Box3f bounds{Vec3f(-1.2f), Vec3f(1.2f)};
  std::vector<Ray> rays = test::mixed_rays(bounds, 120, 42);
  for (const Ray& r : grid_rays(43)) rays.push_back(r);
  const std::vector<Ray> origins = test::random_rays(bounds, 60, 44);
  for (size_t i = 0; i < origins.size(); ++i) {
    Ray r = origins[i];
    r.dir = boxes[i * 3 % boxes.size()].center() - r.org;
    rays.push_back(r);
  }
  return rays;
}

struct Result {
  std::vector<uint8_t> hit;
  std::vector<float> entry;
};

Result intersect(Isa isa, int width, const Ray& ray, const BoxesSoA& boxes) {
  Result r{std::vector<uint8_t>(boxes.padded_count(), 2),
           std::vector<float>(boxes.padded_count(), -1.0f)};
  RTK_PICK_ISA(isa, intersect_boxes)(width, ray, boxes, r.hit.data(), r.entry.data());
  return r;
}

// The exact answer for a closed box, in double precision: a slab the ray is parallel to either
// contains the origin (and restricts nothing) or misses it.
struct Interval {
  double enter, exit;
  bool hit() const { return enter <= exit; }
};
Interval exact_interval(const Ray& r, const Box3f& b) {
  Interval t{r.tnear, r.tfar};
  for (int axis = 0; axis < 3; ++axis) {
    const double o = r.org[axis], d = r.dir[axis], lo = b.lower[axis], hi = b.upper[axis];
    if (d == 0) {
      if (o < lo || o > hi) return {1, 0};
      continue;
    }
    const double t0 = (lo - o) / d, t1 = (hi - o) / d;
    t.enter = std::max(t.enter, std::min(t0, t1));
    t.exit = std::min(t.exit, std::max(t0, t1));
  }
  return t;
}

// The same slab test as slab.h, written with std::min and std::max in the same argument order.
bool slab_with_std_minmax(const Ray& r, const Box3f& b) {
  float enter = r.tnear, exit = r.tfar;
  for (int axis = 2; axis >= 0; --axis) {
    const float rdir = 1.0f / r.dir[axis];
    const bool negative = std::signbit(r.dir[axis]);
    const float near_plane = negative ? b.upper[axis] : b.lower[axis];
    const float far_plane = negative ? b.lower[axis] : b.upper[axis];
    enter = std::max((near_plane - r.org[axis]) * rdir, enter);
    exit = std::min((far_plane - r.org[axis]) * rdir, exit);
  }
  return enter <= exit;
}

}  // namespace

TEST_CASE("ch01: the slab test of every variant and width matches the scalar one bit for bit") {
  const std::vector<Box3f> box_list = make_boxes(1);
  const BoxesSoA boxes(box_list);
  for (const Ray& ray : all_rays(box_list)) {
    const Result want = intersect(Isa::scalar, 1, ray, boxes);
    for (Isa isa : supported_isas())
      for (int width : kSlabWidths) {
        INFO(isa_name(isa), " width ", width, " ray org ", ray.org.x, " ", ray.org.y, " ",
             ray.org.z, " dir ", ray.dir.x, " ", ray.dir.y, " ", ray.dir.z);
        const Result got = intersect(isa, width, ray, boxes);
        CHECK(got.hit == want.hit);
        // Entries compared as bits: -0 and +0 differ, and the same NaN would be unequal.
        bool same_entries = true;
        for (size_t i = 0; i < got.entry.size(); ++i)
          same_entries = same_entries && std::bit_cast<uint32_t>(got.entry[i]) ==
                                             std::bit_cast<uint32_t>(want.entry[i]);
        CHECK(same_entries);
      }
  }
}

TEST_CASE("ch01: the slab test agrees with the exact answer away from the boundary") {
  const std::vector<Box3f> box_list = make_boxes(2);
  const BoxesSoA boxes(box_list);
  int checked = 0, hits = 0;
  for (const Ray& ray : all_rays(box_list)) {
    const Result got = intersect(best_isa(), 16, ray, boxes);
    for (size_t i = 0; i < box_list.size(); ++i) {
      if (!is_valid(ray)) {
        CHECK(got.hit[i] == 0);
        continue;
      }
      const Interval t = exact_interval(ray, box_list[i]);
      // Float rounding moves the ends by a few ulps: decide only where the gap is wider.
      const double scale = 1 + std::max(std::fabs(t.enter), std::fabs(t.exit));
      if (std::isinf(scale) || std::fabs(t.exit - t.enter) < 1e-5 * scale) continue;
      ++checked;
      hits += t.hit();
      INFO("box ", i, " exact [", t.enter, ", ", t.exit, "]");
      REQUIRE(got.hit[i] == uint8_t(t.hit()));
      if (t.hit()) CHECK(std::fabs(got.entry[i] - t.enter) <= 1e-5 * scale);
    }
    for (size_t i = box_list.size(); i < boxes.padded_count(); ++i) CHECK(got.hit[i] == 0);
  }
  CHECK(checked > 10000);  // the test decided enough cases, hits and misses both
  CHECK(hits > 400);
  CHECK(checked - hits > 1000);
}

TEST_CASE("ch01: a ray lying on a face of a box hits it, where std::min would miss it") {
  const std::vector<Box3f> box_list = {
      {Vec3f(0), Vec3f(1)},                  // the unit box
      {Vec3f{0, 0, 0}, Vec3f{0, 1, 1}},      // flat in x, in the plane x = 0
      {Vec3f{0.5f, 0, 0}, Vec3f{1, 1, 1}}};  // beside the ray
  const BoxesSoA boxes(box_list);
  Ray on_lower;  // in the plane x = 0, the lower face of the unit box, travelling along z
  on_lower.org = {0, 0.5f, -1};
  on_lower.dir = {0, 0, 1};
  Ray on_upper = on_lower;  // in the plane x = 1, the upper face, direction x = -0
  on_upper.org.x = 1;
  on_upper.dir.x = -0.0f;

  // [ch01-test-on-face]
  for (Isa isa : supported_isas())
    for (int width : kSlabWidths) {
      INFO(isa_name(isa), " width ", width);
      const Result lower = intersect(isa, width, on_lower, boxes);
      CHECK(lower.hit[0] == 1);
      CHECK(lower.entry[0] == 1.0f);  // enters the box at z = 0, one unit along
      CHECK(lower.hit[1] == 1);       // and the flat box it lies in
      CHECK(lower.hit[2] == 0);
      const Result upper = intersect(isa, width, on_upper, boxes);
      CHECK(upper.hit[0] == 1);
      CHECK(upper.hit[1] == 0);
      CHECK(upper.hit[2] == 1);  // x = 1 is that box's upper face too
    }
  // The exact answer agrees; the same test written with std::min and std::max does not:
  // it returns the NaN that 0 * inf made, and the comparison with NaN is false.
  CHECK(exact_interval(on_lower, box_list[0]).hit());
  CHECK_FALSE(slab_with_std_minmax(on_lower, box_list[0]));
  CHECK_FALSE(slab_with_std_minmax(on_upper, box_list[0]));
  // [ch01-test-on-face]
}

TEST_CASE("ch01: rays that are not rays hit no box, and bad calls are refused") {
  const BoxesSoA boxes(make_boxes(3));
  int invalid = 0;
  for (const Ray& ray : test::invalid_rays()) {
    if (is_valid(ray)) continue;  // tnear = -inf is an ordinary ray
    ++invalid;
    for (Isa isa : supported_isas())
      for (int width : kSlabWidths) {
        const Result r = intersect(isa, width, ray, boxes);
        CHECK(std::count(r.hit.begin(), r.hit.end(), 1) == 0);
        CHECK(RTK_PICK_ISA(isa, count_box_hits)(width, std::span(&ray, 1), boxes) == 0);
      }
  }
  CHECK(invalid >= 20);
  std::vector<uint8_t> hit(boxes.padded_count());
  std::vector<float> entry(boxes.padded_count());
  CHECK_THROWS_AS(RTK_PICK_ISA(best_isa(), intersect_boxes)(3, Ray{}, boxes, hit.data(), entry.data()),
                  std::invalid_argument);
  BoxesSoA broken = boxes;
  broken.upper[1].pop_back();
  CHECK_THROWS_AS(RTK_PICK_ISA(best_isa(), count_box_hits)(4, std::span<const Ray>(), broken),
                  std::invalid_argument);
}

TEST_CASE("ch01: counting hits over many rays agrees with the per-box results") {
  const std::vector<Box3f> box_list = make_boxes(4);
  const BoxesSoA boxes(box_list);
  const std::vector<Ray> rays = all_rays(box_list);
  uint64_t expected = 0;
  for (const Ray& ray : rays) {
    const Result r = intersect(Isa::scalar, 1, ray, boxes);
    expected += uint64_t(std::count(r.hit.begin(), r.hit.end(), 1));
  }
  CHECK(expected > 0);
  for (Isa isa : supported_isas())
    for (int width : kSlabWidths)
      CHECK(RTK_PICK_ISA(isa, count_box_hits)(width, rays, boxes) == expected);
}
