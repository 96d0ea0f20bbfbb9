/// \file
/// Pixel filters, applied by filter importance sampling: each camera sample's film position is
/// drawn from the filter itself, so every sample lands in exactly one pixel with weight 1.
#pragma once

#include <string_view>

#include "11_sampling/vec2.h"

namespace rtk {

/// The pixel filters of chapter 11.
enum class FilterType {
  box,   ///< constant over a square of half-width `radius` (0.5: the pixel itself)
  tent,  ///< separable triangle, 1 - |x| / radius per axis (radius 1: reaches the neighbours'
         ///< centres)
  bspline,  ///< separable cubic B-spline (Embree 1.1's smoothest filter; radius 2: two pixels
            ///< each way)
};

/// Parses "box", "tent" or "bspline"; throws std::invalid_argument naming them otherwise.
FilterType parse_filter_type(std::string_view name);

/// A sampled film offset from the pixel centre, and the weight the sample carries
/// (filter value / density: 1 for these positive filters, sampled exactly).
struct FilterSample {
  Vec2f offset;
  float weight = 1.0f;
};

/// A separable pixel filter with importance sampling (Ernst, Stamminger and Greiner, "Filter
/// Importance Sampling", RT 2006). Splatting each sample into all pixels under the filter would
/// share noise between neighbours and make tiles write into each other; sampling the filter
/// keeps each sample in one pixel, so tiles stay independent.
class PixelFilter {
 public:
  /// A filter of the given type and radius in pixels; radius <= 0 means the type's default
  /// (box 0.5, tent 1, bspline 2). Throws std::invalid_argument for a NaN or infinite radius.
  explicit PixelFilter(FilterType type = FilterType::box, float radius = 0.0f);

  /// The filter's type.
  FilterType type() const { return type_; }
  /// The half-width of the support in pixels.
  float radius() const { return radius_; }
  /// The (unnormalised) filter value at an offset from the pixel centre.
  float evaluate(Vec2f offset) const;
  /// The integral of evaluate over the plane.
  float integral() const;
  /// An offset with density evaluate(offset) / integral().
  FilterSample sample(Vec2f u) const;

 private:
  FilterType type_;
  float radius_;
};

}  // namespace rtk
