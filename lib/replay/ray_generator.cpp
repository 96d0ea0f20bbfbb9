#include "replay/ray_generator.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

namespace rtk {

namespace {

// Only +, -, *, / and sqrt below (all correctly rounded by IEEE 754) and no library function
// such as sin or cos (whose last bit each C library rounds its own way): the same seed gives
// the same bits everywhere. Disks and spheres are therefore sampled by rejection.
class Random {
 public:
  explicit Random(uint64_t seed) : engine_(seed) {}
  /// A float in [0, 1): the top 24 bits of the next 64-bit word, times 2^-24 (exact).
  float uniform() { return float(engine_() >> 40) * 0x1.0p-24f; }
  /// A float in [-1, 1).
  float symmetric() { return 2.0f * uniform() - 1.0f; }
  bool coin() { return (engine_() >> 63) != 0; }
  /// A point uniform in the unit disk.
  void disk(float& x, float& y) {
    do {
      x = symmetric();
      y = symmetric();
    } while (x * x + y * y >= 1.0f);
  }
  /// A direction uniform on the unit sphere (normalized from a point uniform in the ball).
  Vec3f sphere() {
    for (;;) {
      const float x = symmetric(), y = symmetric(), z = symmetric();
      const float len2 = x * x + y * y + z * z;
      if (len2 < 1.0f && len2 > 1e-4f) return Vec3f{x, y, z} * (1.0f / std::sqrt(len2));
    }
  }

 private:
  std::mt19937_64 engine_;
};

float diagonal(const Box3f& b) { return length(b.size()); }

// Triangles chosen in proportion to their area: a running sum of areas (in double, so that a
// million small triangles do not drown in rounding) searched with a uniform number.
class AreaSampler {
 public:
  explicit AreaSampler(const TriangleMesh& mesh) : mesh_(mesh) {
    cdf_.reserve(mesh.size());
    double total = 0.0;
    for (uint32_t prim = 0; prim < mesh.size(); ++prim) {
      total += 0.5 * length_d(cross_d(mesh.vertex(prim, 1) - mesh.vertex(prim, 0),
                                       mesh.vertex(prim, 2) - mesh.vertex(prim, 0)));
      cdf_.push_back(total);
    }
    if (!(total > 0.0)) throw std::invalid_argument("the scene has no triangle with an area to start rays from");
  }

  struct Sample {
    Vec3f point;
    Vec3f normal;  // unit length
  };

  Sample sample(Random& random) const {
    // The first triangle whose running sum exceeds x: a zero-area triangle adds nothing to
    // the sum and so is never the first to exceed it.
    const double x = double(random.uniform()) * cdf_.back();
    const size_t prim = size_t(std::upper_bound(cdf_.begin(), cdf_.end(), x) - cdf_.begin());
    const uint32_t id = uint32_t(std::min(prim, cdf_.size() - 1));
    const Vec3f p0 = mesh_.vertex(id, 0), p1 = mesh_.vertex(id, 1), p2 = mesh_.vertex(id, 2);
    // Uniform on the triangle: the square root warps the first number so that the density
    // does not pile up at p0 (Osada et al., "Shape distributions", 2002, eq. 1).
    const float s = std::sqrt(random.uniform());
    const float t = random.uniform();
    const Vec3f point = p0 * (1.0f - s) + p1 * (s * (1.0f - t)) + p2 * (s * t);
    const Vec3f n = normal_of(p0, p1, p2);
    return {point, n};
  }

 private:
  struct V3d {
    double x, y, z;
  };
  static V3d cross_d(Vec3f a, Vec3f b) {
    return {double(a.y) * b.z - double(a.z) * b.y, double(a.z) * b.x - double(a.x) * b.z,
            double(a.x) * b.y - double(a.y) * b.x};
  }
  static double length_d(V3d v) { return std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z); }
  static Vec3f normal_of(Vec3f p0, Vec3f p1, Vec3f p2) {
    const V3d c = cross_d(p1 - p0, p2 - p0);
    const double len = length_d(c);
    return {float(c.x / len), float(c.y / len), float(c.z / len)};
  }

  const TriangleMesh& mesh_;
  std::vector<double> cdf_;
};

// A cosine-distributed direction about the unit normal n: a point uniform in the disk lifted
// onto the hemisphere (Malley's method), in the orthonormal basis of Duff et al., "Building an
// orthonormal basis, revisited", JCGT 6(1), 2017.
Vec3f cosine_direction(Vec3f n, Random& random) {
  const float sign = std::copysign(1.0f, n.z);
  const float a = -1.0f / (sign + n.z);
  const float b = n.x * n.y * a;
  const Vec3f b1{1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x};
  const Vec3f b2{b, sign + n.y * n.y * a, -n.y};
  float x, y;
  random.disk(x, y);
  const float z = std::sqrt(std::max(0.0f, 1.0f - x * x - y * y));
  return normalize(b1 * x + b2 * y + n * z);
}

std::vector<Ray> primary_rays(const Box3f& bounds, size_t count, Random& random) {
  const Vec3f from = primary_camera_position(bounds);
  const Vec3f to = bounds.center();
  // The camera frame of the guide's viewer: Z toward the scene, U to the right, V up.
  const Vec3f Z = normalize(to - from);
  const Vec3f U = normalize(cross(Vec3f{0, 1, 0}, Z));
  const Vec3f V = cross(Z, U);
  const size_t width = std::max<size_t>(1, size_t(std::ceil(std::sqrt(double(count)))));
  const size_t height = std::max<size_t>(1, (count + width - 1) / width);
  const float aspect = float(width) / float(height);
  const float tan_half_fov = 0.41421356f;  // tan(22.5 degrees): a 45-degree vertical view
  std::vector<Ray> rays(count);
  for (size_t i = 0; i < count; ++i) {
    const float px = (float(i % width) + random.uniform()) / float(width);
    const float py = (float(i / width) + random.uniform()) / float(height);
    Ray& ray = rays[i];
    ray.org = from;
    ray.dir = normalize(U * ((2.0f * px - 1.0f) * tan_half_fov * aspect) +
                        V * ((1.0f - 2.0f * py) * tan_half_fov) + Z);
    ray.time = random.uniform();
  }
  return rays;
}

std::vector<Ray> diffuse_rays(const TriangleMesh& mesh, const Box3f& bounds, size_t count, Random& random) {
  const AreaSampler sampler(mesh);
  const float eps = surface_epsilon(bounds);
  std::vector<Ray> rays(count);
  for (Ray& ray : rays) {
    const AreaSampler::Sample s = sampler.sample(random);
    const Vec3f n = random.coin() ? s.normal : -s.normal;
    ray.org = s.point;
    ray.dir = cosine_direction(n, random);
    ray.tnear = eps;
    ray.time = random.uniform();
  }
  return rays;
}

std::vector<Ray> shadow_rays(const TriangleMesh& mesh, const Box3f& bounds, size_t count, Random& random) {
  const AreaSampler sampler(mesh);
  const Vec3f light = shadow_light_position(bounds);
  const float eps = surface_epsilon(bounds);
  std::vector<Ray> rays(count);
  for (Ray& ray : rays) {
    const AreaSampler::Sample s = sampler.sample(random);
    ray.org = s.point;
    ray.dir = light - s.point;  // t = 1 is the light
    const float margin = eps / length(ray.dir);
    ray.tnear = margin;
    ray.tfar = 1.0f - margin;
    ray.time = random.uniform();
  }
  return rays;
}

std::vector<Ray> random_rays(const Box3f& bounds, size_t count, Random& random) {
  const Vec3f margin = bounds.size() * 0.5f + Vec3f(0.05f * diagonal(bounds));
  const Box3f outer{bounds.lower - margin, bounds.upper + margin};
  const Vec3f extent = outer.size();
  std::vector<Ray> rays(count);
  for (Ray& ray : rays) {
    const float x = random.uniform(), y = random.uniform(), z = random.uniform();
    ray.org = outer.lower + Vec3f{x, y, z} * extent;
    ray.dir = random.sphere();
    ray.time = random.uniform();
  }
  return rays;
}

}  // namespace

std::string_view ray_kind_name(RayKind kind) {
  switch (kind) {
    case RayKind::primary: return "primary";
    case RayKind::diffuse: return "diffuse";
    case RayKind::shadow: return "shadow";
    case RayKind::random: return "random";
  }
  return "?";
}

std::optional<RayKind> parse_ray_kind(std::string_view name) {
  for (RayKind kind : {RayKind::primary, RayKind::diffuse, RayKind::shadow, RayKind::random})
    if (ray_kind_name(kind) == name) return kind;
  return std::nullopt;
}

Box3f used_bounds(const TriangleMesh& mesh) {
  Box3f box;
  for (const auto& tri : mesh.triangles)
    for (uint32_t index : tri) box.extend(mesh.vertices[index]);
  return box;
}

Vec3f primary_camera_position(const Box3f& bounds) {
  float radius = 0.5f * diagonal(bounds);
  if (!(radius > 0.0f)) radius = 1.0f;
  // The sphere fills 90% of the height when sin(half the view) = radius / distance / 0.9.
  const float sin_half_fov = 0.38268343f;  // sin(22.5 degrees)
  const float distance = radius / (0.9f * sin_half_fov);
  return bounds.center() + normalize(Vec3f{0.4f, 0.3f, 1.0f}) * distance;
}

Vec3f shadow_light_position(const Box3f& bounds) {
  float radius = 0.5f * diagonal(bounds);
  if (!(radius > 0.0f)) radius = 1.0f;
  const Vec3f c = bounds.center();
  return {c.x, bounds.upper.y + radius, c.z};
}

float surface_epsilon(const Box3f& bounds) {
  const float d = diagonal(bounds);
  return d > 0.0f ? 1e-4f * d : 1e-4f;
}

std::vector<Ray> generate_rays(const TriangleMesh& mesh, RayKind kind, size_t count, uint64_t seed) {
  if (mesh.triangles.empty()) throw std::invalid_argument("the scene has no triangles to aim rays at");
  const Box3f bounds = used_bounds(mesh);
  Random random(seed);
  switch (kind) {
    case RayKind::primary: return primary_rays(bounds, count, random);
    case RayKind::diffuse: return diffuse_rays(mesh, bounds, count, random);
    case RayKind::shadow: return shadow_rays(mesh, bounds, count, random);
    case RayKind::random: return random_rays(bounds, count, random);
  }
  return {};
}

}  // namespace rtk
