#include "11_sampling/chi_square.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>

namespace rtk::chi2 {

double sidak_alpha(double alpha, int test_count) {
  return 1.0 - std::pow(1.0 - alpha, 1.0 / std::max(test_count, 1));
}

double chi2_p_value(double statistic, int dof) {
  if (dof <= 0) return 1.0;
  if (!(statistic > 0.0)) return statistic == 0.0 ? 1.0 : 0.0;  // NaN fails
  const double a = 0.5 * dof, x = 0.5 * statistic;
  const double log_prefix = -x + a * std::log(x) - std::lgamma(a);
  if (x < a + 1.0) {
    // Series for the lower function P(a, x); Q = 1 - P.
    double ap = a, sum = 1.0 / a, term = sum;
    for (int n = 0; n < 10000; ++n) {
      ap += 1.0;
      term *= x / ap;
      sum += term;
      if (std::fabs(term) < std::fabs(sum) * 1e-15) break;
    }
    return std::clamp(1.0 - sum * std::exp(log_prefix), 0.0, 1.0);
  }
  // Continued fraction for Q(a, x) by the modified Lentz method.
  constexpr double kTiny = 1e-300;
  double b = x + 1.0 - a, c = 1.0 / kTiny, d = 1.0 / b, h = d;
  for (int i = 1; i < 10000; ++i) {
    const double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::fabs(d) < kTiny) d = kTiny;
    c = b + an / c;
    if (std::fabs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    const double delta = d * c;
    h *= delta;
    if (std::fabs(delta - 1.0) < 1e-15) break;
  }
  return std::clamp(std::exp(log_prefix) * h, 0.0, 1.0);
}

int Grid::cell(double x, double y) const {
  if (!(x >= x0 && x <= x1 && y >= y0 && y <= y1)) return -1;
  const int i = std::min(static_cast<int>((x - x0) / (x1 - x0) * nx), nx - 1);
  const int j = std::min(static_cast<int>((y - y0) / (y1 - y0) * ny), ny - 1);
  return i + nx * j;
}

namespace {

// Adaptive Simpson quadrature. The first levels are always refined, so that a narrow peak
// between the first five points of a cell is not mistaken for zero.
constexpr int kMinDepth = 2;
constexpr int kMaxDepth = 10;

template <class F>
double simpson(const F& f, double a, double b, double fa, double fm, double fb, double whole,
               double eps, int depth) {
  const double m = 0.5 * (a + b), lm = 0.5 * (a + m), rm = 0.5 * (m + b);
  const double flm = f(lm), frm = f(rm);
  const double left = (m - a) / 6.0 * (fa + 4.0 * flm + fm);
  const double right = (b - m) / 6.0 * (fm + 4.0 * frm + fb);
  const double delta = left + right - whole;
  if (depth >= kMaxDepth || (depth >= kMinDepth && std::fabs(delta) <= 15.0 * eps))
    return left + right + delta / 15.0;
  return simpson(f, a, m, fa, flm, fm, left, 0.5 * eps, depth + 1) +
         simpson(f, m, b, fm, frm, fb, right, 0.5 * eps, depth + 1);
}

template <class F>
double integrate(const F& f, double a, double b, double eps) {
  const double fa = f(a), fm = f(0.5 * (a + b)), fb = f(b);
  return simpson(f, a, b, fa, fm, fb, (b - a) / 6.0 * (fa + 4.0 * fm + fb), eps, 0);
}

}  // namespace

std::vector<double> integrate_cells(const Grid& g,
                                    const std::function<double(double, double)>& density,
                                    double tolerance) {
  std::vector<double> result(g.size());
  const double dx = (g.x1 - g.x0) / g.nx, dy = (g.y1 - g.y0) / g.ny;
  for (int j = 0; j < g.ny; ++j) {
    const double ya = g.y0 + j * dy, yb = ya + dy;
    for (int i = 0; i < g.nx; ++i) {
      const double xa = g.x0 + i * dx, xb = xa + dx;
      const auto inner = [&](double y) {
        return integrate([&](double x) { return density(x, y); }, xa, xb, tolerance / dy);
      };
      result[i + g.nx * j] = std::max(integrate(inner, ya, yb, tolerance), 0.0);
    }
  }
  return result;
}

std::vector<double> integrate_cells_midpoint(const Grid& g,
                                             const std::function<double(double, double)>& density,
                                             int points) {
  std::vector<double> result(g.size());
  const double dx = (g.x1 - g.x0) / g.nx, dy = (g.y1 - g.y0) / g.ny;
  const double hx = dx / points, hy = dy / points;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      double sum = 0;
      for (int b = 0; b < points; ++b)
        for (int a = 0; a < points; ++a)
          sum += density(g.x0 + i * dx + (a + 0.5) * hx, g.y0 + j * dy + (b + 0.5) * hy);
      result[i + g.nx * j] = sum * hx * hy;
    }
  return result;
}

Result pearson(std::span<const double> observed, std::span<const double> expected,
               double min_expected) {
  Result r;
  if (observed.size() != expected.size()) {
    r.failure = "observed and expected counts differ in size";
    return r;
  }
  // Pool the cells with a low expectation: the chi-square distribution describes the
  // statistic only when every cell expects a handful of samples.
  double pool_observed = 0, pool_expected = 0;
  int cells = 0;
  std::vector<std::pair<double, double>> kept;
  for (std::size_t i = 0; i < observed.size(); ++i) {
    if (expected[i] == 0.0 && observed[i] > 0.0) {
      r.failure = "cell " + std::to_string(i) + " holds " +
                  std::to_string(static_cast<long>(observed[i])) +
                  " samples but its density integrates to zero";
      return r;
    }
    if (expected[i] < min_expected) {
      pool_observed += observed[i];
      pool_expected += expected[i];
      ++r.pooled;
    } else {
      kept.emplace_back(observed[i], expected[i]);
    }
  }
  if (pool_expected > 0.0) {
    if (pool_expected < min_expected && !kept.empty()) {
      // Still too small: merge the pool into the smallest kept cell.
      auto smallest = std::min_element(kept.begin(), kept.end(),
                                       [](auto& a, auto& b) { return a.second < b.second; });
      smallest->first += pool_observed;
      smallest->second += pool_expected;
    } else {
      kept.emplace_back(pool_observed, pool_expected);
    }
  } else if (pool_observed > 0.0) {
    r.failure = "samples fell where the density integrates to zero";
    return r;
  }
  for (const auto& [o, e] : kept) {
    r.statistic += (o - e) * (o - e) / e;
    ++cells;
  }
  r.dof = cells - 1;
  r.p_value = chi2_p_value(r.statistic, r.dof);
  return r;
}

std::string Result::summary() const {
  char buf[160];
  std::snprintf(buf, sizeof buf, "chi2 = %.1f, dof = %d, p = %.4f, pooled cells = %d%s%s",
                statistic, dof, p_value, pooled,
                failure.empty() ? "" : ", FAILED: ", failure.c_str());
  return buf;
}

SphericalHistogram::SphericalHistogram(int res)
    : grid{0.0, 2.0 * std::numbers::pi, 0.0, std::numbers::pi, 2 * res, res},
      counts(grid.size(), 0.0) {}

void SphericalHistogram::add(Vec3f w) {
  const double len = std::sqrt(double(w.x) * w.x + double(w.y) * w.y + double(w.z) * w.z);
  if (!(std::fabs(len - 1.0) < 1e-3)) {
    ++outside;
    return;
  }
  double phi = std::atan2(double(w.y), double(w.x));
  if (phi < 0.0) phi += 2.0 * std::numbers::pi;
  const double theta = std::acos(std::clamp(w.z / len, -1.0, 1.0));
  const int c = grid.cell(phi, theta);
  if (c < 0)
    ++outside;
  else
    counts[c] += 1.0;
}

Vec3f spherical_direction(double theta, double phi) {
  const double s = std::sin(theta);
  return {static_cast<float>(s * std::cos(phi)), static_cast<float>(s * std::sin(phi)),
          static_cast<float>(std::cos(theta))};
}

std::vector<double> SphericalHistogram::expected(const std::function<double(Vec3f)>& pdf,
                                                 double tolerance) const {
  return integrate_cells(
      grid,
      [&](double phi, double theta) {
        return pdf(spherical_direction(theta, phi)) * std::sin(theta);
      },
      tolerance);
}

std::vector<double> SphericalHistogram::expected_midpoint(const std::function<double(Vec3f)>& pdf,
                                                          int points) const {
  return integrate_cells_midpoint(
      grid,
      [&](double phi, double theta) {
        return pdf(spherical_direction(theta, phi)) * std::sin(theta);
      },
      points);
}

bool report_enabled() { return std::getenv("RTK_CHI2_REPORT") != nullptr; }

}  // namespace rtk::chi2
