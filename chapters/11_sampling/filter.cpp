#include "11_sampling/filter.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace rtk {

FilterType parse_filter_type(std::string_view name) {
  if (name == "box") return FilterType::box;
  if (name == "tent") return FilterType::tent;
  if (name == "bspline") return FilterType::bspline;
  throw std::invalid_argument("unknown pixel filter '" + std::string(name) +
                              "' (supported: box, tent, bspline)");
}

PixelFilter::PixelFilter(FilterType type, float radius) : type_(type), radius_(radius) {
  if (!std::isfinite(radius)) throw std::invalid_argument("pixel filter radius must be finite");
  if (radius <= 0.0f) radius_ = type == FilterType::box ? 0.5f : type == FilterType::tent ? 1.0f : 2.0f;
}

// [ch11-bspline]
namespace {
/// The uniform cubic B-spline on [-2, 2]: four unit boxes convolved, a bell that integrates
/// to 1 and whose first two derivatives are continuous.
double bspline(double x) {
  x = std::fabs(x);
  if (x >= 2.0) return 0.0;
  if (x >= 1.0) return (2.0 - x) * (2.0 - x) * (2.0 - x) / 6.0;
  return (4.0 - 6.0 * x * x + 3.0 * x * x * x) / 6.0;
}
/// Its CDF: (2 + t)^4 / 24 on the outer piece, then the outer piece's 1/24 plus the integral
/// of the inner cubic from -1, and symmetry about 0 for t > 0 (the two meet at 1/2).
double bspline_cdf(double t) {
  if (t > 0.0) return 1.0 - bspline_cdf(-t);
  if (t <= -2.0) return 0.0;
  if (t <= -1.0) return (2.0 + t) * (2.0 + t) * (2.0 + t) * (2.0 + t) / 24.0;
  return 1.0 / 24.0 + (4.0 * t - 2.0 * t * t * t - 0.75 * t * t * t * t + 2.75) / 6.0;
}
/// Inverts the CDF by bisection: 40 halvings of [-2, 2] leave an error far below a float's.
float sample_bspline(float u) {
  double lo = -2.0, hi = 2.0;
  for (int i = 0; i < 40; ++i) {
    const double mid = 0.5 * (lo + hi);
    (bspline_cdf(mid) < u ? lo : hi) = mid;
  }
  return static_cast<float>(0.5 * (lo + hi));
}
}  // namespace
// [ch11-bspline]

float PixelFilter::evaluate(Vec2f p) const {
  if (std::fabs(p.x) > radius_ || std::fabs(p.y) > radius_) return 0.0f;
  if (type_ == FilterType::box) return 1.0f;
  if (type_ == FilterType::bspline)
    return static_cast<float>(bspline(2.0 * p.x / radius_) * bspline(2.0 * p.y / radius_));
  return (1.0f - std::fabs(p.x) / radius_) * (1.0f - std::fabs(p.y) / radius_);
}

float PixelFilter::integral() const {
  // Box: the square's area; tent: each axis integrates to the radius; B-spline: to half of it.
  if (type_ == FilterType::bspline) return 0.25f * radius_ * radius_;
  return type_ == FilterType::box ? 4.0f * radius_ * radius_ : radius_ * radius_;
}

// [ch11-tent]
namespace {
/// Inverts the CDF of the 1D tent on [-1, 1]: each half is a triangle whose CDF is a square,
/// so its inverse is a square root.
float sample_tent(float u) {
  return u < 0.5f ? std::sqrt(2.0f * u) - 1.0f : 1.0f - std::sqrt(2.0f - 2.0f * u);
}
}  // namespace

FilterSample PixelFilter::sample(Vec2f u) const {
  if (type_ == FilterType::box)
    return {{radius_ * (2.0f * u.x - 1.0f), radius_ * (2.0f * u.y - 1.0f)}, 1.0f};
  if (type_ == FilterType::bspline)
    return {{0.5f * radius_ * sample_bspline(u.x), 0.5f * radius_ * sample_bspline(u.y)}, 1.0f};
  return {{radius_ * sample_tent(u.x), radius_ * sample_tent(u.y)}, 1.0f};
}
// [ch11-tent]

}  // namespace rtk
