#include "01_base/ray_sets.h"

#include <cmath>
#include <limits>
#include <random>

namespace rtk::test {

namespace {

struct Random {
  std::mt19937_64 engine;
  explicit Random(uint64_t seed) : engine(seed) {}
  float uniform() { return float(double(engine() >> 11) * 0x1.0p-53); }
  int below(int n) { return int(engine() % uint64_t(n)); }
  Vec3f in(const Box3f& b) {
    const float x = uniform(), y = uniform(), z = uniform();
    return b.lower + Vec3f{x, y, z} * b.size();
  }
};

Box3f enlarged(const Box3f& b, float factor) {
  const Vec3f margin = b.size() * factor + Vec3f(1e-3f);
  return {b.lower - margin, b.upper + margin};
}

}  // namespace

std::vector<Ray> random_rays(const Box3f& bounds, int count, uint64_t seed) {
  Random random(seed);
  const Box3f outer = enlarged(bounds, 0.5f);
  std::vector<Ray> rays;
  for (int i = 0; i < count; ++i) {
    Ray r;
    r.org = random.in(outer);
    r.dir = random.in(bounds) - r.org;
    if (r.dir == Vec3f(0)) r.dir = {0, 0, 1};
    rays.push_back(r);
  }
  return rays;
}

std::vector<Ray> axis_aligned_rays(const Box3f& bounds, int count, uint64_t seed) {
  Random random(seed);
  const Box3f outer = enlarged(bounds, 0.25f);
  std::vector<Ray> rays;
  for (int i = 0; i < count; ++i) {
    Ray r;
    r.org = random.in(outer);
    const int axis = random.below(3);
    Vec3f dir(random.below(2) ? 0.0f : -0.0f);
    dir[axis] = random.below(2) ? 1.0f : -1.0f;
    if (i % 3 == 0) dir[(axis + 1) % 3] = random.uniform() - 0.5f;  // two zeros become one
    // Put a third of the origins exactly on a plane of the scene's box.
    if (i % 3 == 1) r.org[(axis + 1) % 3] = random.below(2) ? bounds.lower[(axis + 1) % 3] : bounds.upper[(axis + 1) % 3];
    r.dir = dir;
    rays.push_back(r);
  }
  return rays;
}

std::vector<Ray> grazing_rays(const Box3f& bounds, int count, uint64_t seed) {
  Random random(seed);
  std::vector<Ray> rays;
  for (int i = 0; i < count; ++i) {
    // A target on a face of the box (or just outside it), approached from outside.
    Vec3f target = random.in(bounds);
    const int axis = random.below(3);
    const float offset = (random.below(2) ? 1.0f : -1.0f) * (i % 2 ? 0.0f : 1e-4f) * (bounds.size()[axis] + 1e-3f);
    target[axis] = (random.below(2) ? bounds.lower[axis] : bounds.upper[axis]) + offset;
    Ray r;
    Vec3f dir = random.in(bounds) - random.in(bounds);
    dir[axis] = 0.0f;  // travel inside the face's plane
    if (dir == Vec3f(0)) dir[(axis + 1) % 3] = 1.0f;
    r.org = target - dir * 2.0f;
    r.dir = dir;
    rays.push_back(r);
  }
  return rays;
}

std::vector<Ray> invalid_rays() {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  std::vector<Ray> rays;
  Ray base;
  base.org = {0.5f, 0.5f, -1.0f};
  base.dir = {0.0f, 0.0f, 1.0f};
  for (int field = 0; field < 8; ++field) {
    for (float bad : {nan, inf, -inf}) {
      Ray r = base;
      float* fields[] = {&r.org.x, &r.org.y, &r.org.z, &r.dir.x, &r.dir.y, &r.dir.z, &r.tnear, &r.tfar};
      *fields[field] = bad;
      // An infinite tnear, or tfar = +inf, leaves a valid ray: only NaN, and tfar = -inf
      // (which puts tnear above it), make the interval itself invalid.
      if (field == 6 && !std::isnan(bad)) continue;
      if (field == 7 && bad == inf) continue;
      rays.push_back(r);
    }
  }
  Ray zero = base;
  zero.dir = {0, 0, 0};
  rays.push_back(zero);
  Ray reversed = base;
  reversed.tnear = 2.0f;
  reversed.tfar = 1.0f;
  rays.push_back(reversed);
  return rays;
}

std::vector<Ray> mixed_rays(const Box3f& bounds, int count, uint64_t seed) {
  std::vector<Ray> rays = random_rays(bounds, count / 2, seed);
  for (const Ray& r : axis_aligned_rays(bounds, count / 4, seed + 1)) rays.push_back(r);
  for (const Ray& r : grazing_rays(bounds, count / 4, seed + 2)) rays.push_back(r);
  for (const Ray& r : invalid_rays()) rays.push_back(r);
  Random random(seed + 3);
  for (size_t i = 0; i < rays.size(); i += 4) {
    const float a = random.uniform() * 2.0f, b = random.uniform() * 2.0f;
    rays[i].tnear = a < b ? a : b;
    rays[i].tfar = a < b ? b : a;
  }
  return rays;
}

}  // namespace rtk::test
