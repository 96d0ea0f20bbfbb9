#include "10_sampling/filter.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace rtk {

FilterType parse_filter_type(std::string_view name) {
  if (name == "box") return FilterType::box;
  if (name == "tent") return FilterType::tent;
  throw std::invalid_argument("unknown pixel filter '" + std::string(name) +
                              "' (supported: box, tent)");
}

PixelFilter::PixelFilter(FilterType type, float radius) : type_(type), radius_(radius) {
  if (!std::isfinite(radius)) throw std::invalid_argument("pixel filter radius must be finite");
  if (radius <= 0.0f) radius_ = type == FilterType::box ? 0.5f : 1.0f;
}

float PixelFilter::evaluate(Vec2f p) const {
  if (std::fabs(p.x) > radius_ || std::fabs(p.y) > radius_) return 0.0f;
  if (type_ == FilterType::box) return 1.0f;
  return (1.0f - std::fabs(p.x) / radius_) * (1.0f - std::fabs(p.y) / radius_);
}

float PixelFilter::integral() const {
  // Box: the square's area; tent: each axis integrates to the radius.
  return type_ == FilterType::box ? 4.0f * radius_ * radius_ : radius_ * radius_;
}

// [ch10-tent]
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
  return {{radius_ * sample_tent(u.x), radius_ * sample_tent(u.y)}, 1.0f};
}
// [ch10-tent]

}  // namespace rtk
