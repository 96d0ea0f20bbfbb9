#include "11_sampling/distribution.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rtk {

Distribution1D::Distribution1D(std::span<const float> values)
    : func_(values.begin(), values.end()) {
  if (func_.empty()) throw std::invalid_argument("Distribution1D: no values");
  const int n = size();
  // Accumulate in double: a long table of small values loses its tail in float.
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    if (!(func_[i] >= 0.0f) || !std::isfinite(func_[i]))
      throw std::invalid_argument("Distribution1D: value " + std::to_string(i) +
                                  " is negative, NaN or infinite");
    sum += func_[i];
  }
  integral_ = static_cast<float>(sum / n);
  if (sum == 0.0) {
    std::fill(func_.begin(), func_.end(), 1.0f);
    sum = n;
  }
  cdf_.resize(n + 1);
  double running = 0.0;
  cdf_[0] = 0.0f;
  for (int i = 0; i < n; ++i) {
    running += func_[i];
    cdf_[i + 1] = static_cast<float>(running / sum);
  }
  cdf_[n] = 1.0f;
  // In double, as the bins' values were summed: a long table's small bins keep their digits.
  density_.resize(n);
  mass_.resize(n);
  for (int i = 0; i < n; ++i) {
    density_[i] = static_cast<float>(static_cast<double>(func_[i]) * n / sum);
    mass_[i] = static_cast<float>(static_cast<double>(func_[i]) / sum);
  }
}

// [ch11-distribution-sample]
// The bin i with cdf[i] <= u < cdf[i+1]: the last lower border at most u. An empty bin's
// border equals the next one's, so it is never the last, and never chosen. Each step halves
// the range by a conditional move rather than a branch: u is random, and a branch on it would
// be guessed wrong half the time, each time discarding the work the processor began.
int Distribution1D::find_bin(float u) const {
  const float* first = cdf_.data();
  size_t count = func_.size();  // the answer lies in [first, first + count)
  while (count > 1) {
    const size_t half = count / 2;
    first = first[half] <= u ? first + half : first;
    count -= half;
  }
  return static_cast<int>(first - cdf_.data());
}

float Distribution1D::sample_continuous(float u, float* pdf, int* bin) const {
  const int i = find_bin(u);
  // Place x inside the bin by the fraction of the bin's probability that u covers.
  const float width = cdf_[i + 1] - cdf_[i];
  float offset = width > 0.0f ? (u - cdf_[i]) / width : 0.5f;
  offset = std::clamp(offset, 0.0f, 1.0f);
  const float x =
      std::min((static_cast<float>(i) + offset) / static_cast<float>(size()), 0x1.fffffep-1f);
  // The density comes from the bin's value, not from the difference of two CDF entries,
  // which loses all precision for small bins near the end of a long table.
  if (pdf) *pdf = density_[i];
  if (bin) *bin = i;
  return x;
}
// [ch11-distribution-sample]

int Distribution1D::sample_discrete(float u, float* pmf_out) const {
  const int i = find_bin(u);
  if (pmf_out) *pmf_out = mass_[i];
  return i;
}

float Distribution1D::pdf(float x) const {
  if (!(x >= 0.0f && x < 1.0f)) return 0.0f;
  const int n = size();
  const int i = std::min(static_cast<int>(x * static_cast<float>(n)), n - 1);
  return density_[i];
}

float Distribution1D::pmf(int i) const {
  if (i < 0 || i >= size()) return 0.0f;
  return mass_[i];
}

namespace {
std::vector<float> row_integrals(std::span<const float> values, int nu, int nv) {
  if (nu <= 0 || nv <= 0 ||
      values.size() != static_cast<std::size_t>(nu) * static_cast<std::size_t>(nv))
    throw std::invalid_argument("Distribution2D: expected " + std::to_string(nu) + " x " +
                                std::to_string(nv) + " values, got " +
                                std::to_string(values.size()));
  std::vector<float> rows(nv);
  for (int v = 0; v < nv; ++v)
    rows[v] = Distribution1D(values.subspan(static_cast<std::size_t>(v) * nu, nu)).integral();
  return rows;
}
}  // namespace

Distribution2D::Distribution2D(std::span<const float> values, int nu, int nv)
    : marginal_(row_integrals(values, nu, nv)) {
  conditional_.reserve(nv);
  for (int v = 0; v < nv; ++v)
    conditional_.emplace_back(values.subspan(static_cast<std::size_t>(v) * nu, nu));
}

Vec2f Distribution2D::sample(Vec2f u, float* pdf_out) const {
  float pdf_v = 0.0f, pdf_u = 0.0f;
  int row = 0;
  const float y = marginal_.sample_continuous(u.y, &pdf_v, &row);
  const float x = conditional_[row].sample_continuous(u.x, &pdf_u);
  if (pdf_out) *pdf_out = pdf_u * pdf_v;
  return {x, y};
}

float Distribution2D::pdf(Vec2f p) const {
  if (!(p.y >= 0.0f && p.y < 1.0f)) return 0.0f;
  const int nv = static_cast<int>(conditional_.size());
  const int row = std::min(static_cast<int>(p.y * static_cast<float>(nv)), nv - 1);
  return marginal_.pdf(p.y) * conditional_[row].pdf(p.x);
}

}  // namespace rtk
