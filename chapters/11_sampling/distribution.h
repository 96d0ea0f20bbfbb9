/// \file
/// Piecewise-constant distributions in one and two dimensions: sampling a tabulated function
/// in proportion to its value. Environment maps (chapter 13) and light selection use them.
#pragma once

#include <span>
#include <vector>

#include "11_sampling/vec2.h"

namespace rtk {

/// A piecewise-constant density on [0, 1) with n equal bins, proportional to non-negative
/// bin values f[i]. Sampling inverts the cumulative distribution by a binary search without
/// branches; each bin's density and probability are computed once, when the table is built.
/// If every value is zero the density is uniform (so that sampling never divides by zero);
/// integral() still reports 0 so that callers can tell.
class Distribution1D {
 public:
  /// Builds the table; throws std::invalid_argument for an empty list or a negative, NaN or
  /// infinite value.
  explicit Distribution1D(std::span<const float> values);

  /// The number of bins.
  int size() const { return static_cast<int>(func_.size()); }
  /// The integral of the function over [0, 1): the mean of the bin values.
  float integral() const { return integral_; }
  /// The value of bin i.
  float value(int i) const { return func_[i]; }

  /// A point x in [0, 1) with density pdf(x); `bin` receives its bin.
  float sample_continuous(float u, float* pdf = nullptr, int* bin = nullptr) const;
  /// A bin with probability f[i] / sum f; `pmf` receives that probability.
  int sample_discrete(float u, float* pmf = nullptr) const;
  /// The density at x in [0, 1) (0 outside).
  float pdf(float x) const;
  /// The probability of bin i under sample_discrete.
  float pmf(int i) const;

 private:
  int find_bin(float u) const;

  std::vector<float> func_;     // bin values (uniform replacement when all are zero)
  std::vector<float> cdf_;      // size n + 1, cdf_[0] = 0, cdf_[n] = 1
  std::vector<float> density_;  // per bin: f[i] n / sum f, the density of its points
  std::vector<float> mass_;     // per bin: f[i] / sum f, its probability
  float integral_ = 0.0f;       // the true integral (0 for an all-zero function)
};

/// A piecewise-constant density on [0, 1)^2 over an nu x nv grid of values f[v * nu + u]:
/// a marginal distribution picks the row (v), the row's conditional distribution the column.
class Distribution2D {
 public:
  /// Builds the tables from nu * nv values, row by row; throws std::invalid_argument for
  /// a size mismatch or invalid values.
  Distribution2D(std::span<const float> values, int nu, int nv);

  /// A point of [0, 1)^2 with density pdf(point).
  Vec2f sample(Vec2f u, float* pdf = nullptr) const;
  /// The density at a point of [0, 1)^2.
  float pdf(Vec2f p) const;
  /// The integral of the function over the unit square.
  float integral() const { return marginal_.integral(); }

 private:
  std::vector<Distribution1D> conditional_;
  Distribution1D marginal_;
};

}  // namespace rtk
