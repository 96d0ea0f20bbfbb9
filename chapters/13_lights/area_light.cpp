#include "13_lights/area_light.h"

#include <cmath>
#include <stdexcept>

#include "11_sampling/warp.h"
#include "13_lights/point_light.h"

namespace rtk {

TriangleLight::TriangleLight(Vec3f v0, Vec3f v1, Vec3f v2, Color radiance)
    : v_{v0, v1, v2}, radiance_(detail::checked_radiance(radiance, "triangle light radiance")) {
  if (!is_finite(v0) || !is_finite(v1) || !is_finite(v2))
    throw std::invalid_argument("triangle light vertices must be finite");
  const Vec3f c = cross(v2 - v0, v1 - v0);
  const float len = length(c);
  if (!(len > 0.0f) || !std::isfinite(len))
    throw std::invalid_argument("triangle light has zero area");
  normal_ = c / len;
  area_ = 0.5f * len;
}

// [ch13-triangle-sample]
std::optional<LightSample> TriangleLight::sample_li(const LightQuery& q, Vec2f u) const {
  // A uniform point of the triangle (density 1 / A)...
  const Vec3f b = sample_uniform_triangle(u);
  const Vec3f point = b.x * v_[0] + b.y * v_[1] + b.z * v_[2];
  const Vec3f d = point - q.p;
  const float d2 = dot(d, d);
  if (!(d2 > 0.0f) || !std::isfinite(d2)) return std::nullopt;
  const float dist = std::sqrt(d2);
  const Vec3f wi = d / dist;
  // ...seen from q: a patch dA at distance d, tilted by theta_l, subtends
  // dA cos(theta_l) / d^2 of solid angle, so the density per solid angle is d^2 / (A cos).
  const float cos_l = -dot(wi, normal_);
  if (cos_l <= 0.0f) return std::nullopt;  // the back of the light, which does not emit
  return LightSample{wi, radiance_, d2 / (area_ * cos_l), dist, false};
}
// [ch13-triangle-sample]

float TriangleLight::pdf_hit(Vec3f p, Vec3f point) const {
  const Vec3f d = point - p;
  const float d2 = dot(d, d);
  if (!(d2 > 0.0f)) return 0.0f;
  const float cos_l = -dot(d, normal_) / std::sqrt(d2);
  return cos_l > 0.0f ? d2 / (area_ * cos_l) : 0.0f;
}

float TriangleLight::pdf_li(const LightQuery& q, Vec3f wi) const {
  // Where does the ray (q.p, wi) meet the triangle? Moeller-Trumbore in double precision:
  // this runs once per BSDF sample that needs a MIS weight, not in traversal.
  const double ox = q.p.x, oy = q.p.y, oz = q.p.z, dx = wi.x, dy = wi.y, dz = wi.z;
  const double e1[3] = {double(v_[1].x) - v_[0].x, double(v_[1].y) - v_[0].y,
                        double(v_[1].z) - v_[0].z};
  const double e2[3] = {double(v_[2].x) - v_[0].x, double(v_[2].y) - v_[0].y,
                        double(v_[2].z) - v_[0].z};
  const double pv[3] = {dy * e2[2] - dz * e2[1], dz * e2[0] - dx * e2[2], dx * e2[1] - dy * e2[0]};
  const double det = e1[0] * pv[0] + e1[1] * pv[1] + e1[2] * pv[2];
  if (det == 0.0 || !std::isfinite(det)) return 0.0f;
  const double inv = 1.0 / det;
  const double tv[3] = {ox - v_[0].x, oy - v_[0].y, oz - v_[0].z};
  const double bu = (tv[0] * pv[0] + tv[1] * pv[1] + tv[2] * pv[2]) * inv;
  if (bu < 0.0 || bu > 1.0) return 0.0f;
  const double qv[3] = {tv[1] * e1[2] - tv[2] * e1[1], tv[2] * e1[0] - tv[0] * e1[2],
                        tv[0] * e1[1] - tv[1] * e1[0]};
  const double bv = (dx * qv[0] + dy * qv[1] + dz * qv[2]) * inv;
  if (bv < 0.0 || bu + bv > 1.0) return 0.0f;
  const double t = (e2[0] * qv[0] + e2[1] * qv[1] + e2[2] * qv[2]) * inv;
  if (!(t > 0.0)) return 0.0f;
  const double len = std::sqrt(dx * dx + dy * dy + dz * dz);
  const double cos_l = -(dx * normal_.x + dy * normal_.y + dz * normal_.z) / len;
  if (cos_l <= 0.0) return 0.0f;
  const double dist = t * len;
  return static_cast<float>(dist * dist / (area_ * cos_l));
}

Color TriangleLight::power(float) const { return radiance_ * (kPi * area_); }

std::vector<std::shared_ptr<const TriangleLight>> make_quad_light(Vec3f p, Vec3f u, Vec3f v,
                                                                  Color radiance) {
  return {std::make_shared<TriangleLight>(p + u + v, p + u, p, radiance),
          std::make_shared<TriangleLight>(p + u + v, p, p + v, radiance)};
}

}  // namespace rtk
