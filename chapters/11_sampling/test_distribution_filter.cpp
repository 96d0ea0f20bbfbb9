// Chapter 11 tests: piecewise-constant distributions and pixel filters.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "11_sampling/chi_square.h"
#include "11_sampling/distribution.h"
#include "11_sampling/filter.h"
#include "11_sampling/rng.h"

using namespace rtk;

namespace {
constexpr int kChi2Tests = 4;
const double kAlpha = chi2::sidak_alpha(chi2::kSuiteSignificance, kChi2Tests);
}  // namespace

TEST_CASE("ch11: a 1D distribution samples bins in proportion to their values") {
  const std::vector<float> f = {1, 3, 0, 4};
  const Distribution1D d(f);
  CHECK(d.integral() == doctest::Approx(2.0));
  CHECK(d.pmf(0) == doctest::Approx(0.125));
  CHECK(d.pmf(2) == 0.0f);
  CHECK(d.pdf(0.3f) == doctest::Approx(1.5));  // bin 1: 3 / mean 2
  CHECK(d.pdf(1.0f) == 0.0f);
  // The inverse CDF is monotonic, never enters the empty bin, and reports the right density.
  float last = -1.0f;
  for (int i = 0; i < 1000; ++i) {
    float pdf = 0;
    int bin = -1;
    const float x = d.sample_continuous((i + 0.5f) / 1000.0f, &pdf, &bin);
    CHECK(x >= last);
    CHECK(bin != 2);
    CHECK(x < 1.0f);
    CHECK(pdf == doctest::Approx(d.pdf(x)));
    last = x;
  }
  // Discrete sampling hits each bin with its probability: u in [0, 1/8) is bin 0, etc.
  CHECK(d.sample_discrete(0.1f) == 0);
  CHECK(d.sample_discrete(0.2f) == 1);
  CHECK(d.sample_discrete(0.6f) == 3);
}

// [ch11-test-distribution-search]
TEST_CASE("ch11: the search picks the bin a linear scan of the cumulative sum picks") {
  // Tables of 1 to 40 bins, a third of them empty, searched at random points and exactly at
  // every bin's border. The reference walks the cumulative sum, built as the class builds it,
  // and takes the last bin whose lower border is at most u: an empty bin's border equals the
  // next one's, so it is never the last.
  Pcg32 rng(11);
  for (int n = 1; n <= 40; ++n) {
    std::vector<float> f(n);
    for (float& v : f) v = rng.next_float() < 0.3f ? 0.0f : rng.next_float() * 10.0f;
    const Distribution1D d(f);
    double sum = 0.0;
    for (float v : f) sum += v;
    if (sum == 0.0) continue;  // the all-zero table is the next test's
    std::vector<float> cdf(n + 1, 0.0f);
    double running = 0.0;
    for (int i = 0; i < n; ++i) cdf[i + 1] = static_cast<float>((running += f[i]) / sum);
    cdf[n] = 1.0f;
    std::vector<float> us;  // every border below 1 (a sample is always below 1)
    for (float border : cdf)
      if (border < 1.0f) us.push_back(border);
    for (int k = 0; k < 64; ++k) us.push_back(rng.next_float());
    for (float u : us) {
      int expected = 0;
      for (int i = 0; i < n; ++i)
        if (cdf[i] <= u) expected = i;
      float pmf = -1.0f;
      CHECK(d.sample_discrete(u, &pmf) == expected);
      CHECK(f[expected] > 0.0f);
      CHECK(pmf == static_cast<float>(f[expected] / sum));
      int bin = -1;
      float pdf = -1.0f;
      d.sample_continuous(u, &pdf, &bin);
      CHECK(bin == expected);
      CHECK(pdf == static_cast<float>(static_cast<double>(f[expected]) * n / sum));
    }
  }
}
// [ch11-test-distribution-search]

TEST_CASE("ch11: degenerate distributions are handled, bad ones refused") {
  const std::vector<float> zero = {0, 0, 0};
  const Distribution1D d(zero);
  CHECK(d.integral() == 0.0f);
  float pdf = 0;
  const float x = d.sample_continuous(0.7f, &pdf);
  CHECK(x == doctest::Approx(0.7f));
  CHECK(pdf == doctest::Approx(1.0f));
  CHECK_THROWS_AS(Distribution1D(std::vector<float>{}), std::invalid_argument);
  CHECK_THROWS_AS(Distribution1D(std::vector<float>{1, -1}), std::invalid_argument);
  CHECK_THROWS_AS(Distribution1D(std::vector<float>{1, NAN}), std::invalid_argument);
  CHECK_THROWS_AS(Distribution2D(std::vector<float>{1, 2, 3}, 2, 2), std::invalid_argument);
}

TEST_CASE("ch11: a 2D distribution follows its density (chi-square)") {
  // A random 8 x 6 table with two empty cells and one empty row; the test grid is twice as
  // fine, so each test cell lies inside one constant table cell.
  const int nu = 8, nv = 6;
  std::vector<float> f(nu * nv);
  Pcg32 rng(11);
  for (float& v : f) v = rng.next_float() * 4.0f;
  f[5] = 0, f[17] = 0;
  for (int u = 0; u < nu; ++u) f[3 * nu + u] = 0;
  const Distribution2D d(f, nu, nv);
  chi2::Grid grid{0, 1, 0, 1, 2 * nu, 2 * nv};
  std::vector<double> observed(grid.size(), 0.0);
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    float pdf = 0;
    const float u0 = rng.next_float();
    const Vec2f p = d.sample({u0, rng.next_float()}, &pdf);
    REQUIRE(pdf > 0.0f);
    REQUIRE(pdf == doctest::Approx(d.pdf(p)));
    observed[grid.cell(p.x, p.y)] += 1.0;
  }
  std::vector<double> expected = chi2::integrate_cells(grid, [&](double x, double y) {
    return d.pdf({static_cast<float>(x), static_cast<float>(y)});
  });
  double total = 0;
  for (double& e : expected) total += e, e *= n;
  CHECK(total == doctest::Approx(1.0).epsilon(1e-4));
  const chi2::Result r = chi2::pearson(observed, expected);
  if (chi2::report_enabled())
    std::printf("ch11 chi2 %-24s %s\n", "distribution 2D", r.summary().c_str());
  CHECK(r.passed(kAlpha));
}

TEST_CASE("ch11: filters sample offsets in proportion to their weights") {
  for (FilterType type : {FilterType::box, FilterType::tent, FilterType::bspline}) {
    const PixelFilter filter(type);
    const float r = filter.radius();
    // The integral is right (midpoint rule on a fine grid).
    double sum = 0;
    const int m = 400;
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i)
        sum += filter.evaluate({-r + 2 * r * (i + 0.5f) / m, -r + 2 * r * (j + 0.5f) / m});
    CHECK(sum * (2 * r / m) * (2 * r / m) == doctest::Approx(filter.integral()).epsilon(1e-3));
    // Sampled offsets follow evaluate / integral.
    chi2::Grid grid{-r, r, -r, r, 12, 12};
    std::vector<double> observed(grid.size(), 0.0);
    Pcg32 rng(12 + static_cast<int>(type));
    const int n = 100000;
    for (int i = 0; i < n; ++i) {
      const float u0 = rng.next_float();
      const FilterSample s = filter.sample({u0, rng.next_float()});
      REQUIRE(s.weight == 1.0f);
      const int c = grid.cell(s.offset.x, s.offset.y);
      REQUIRE(c >= 0);
      observed[c] += 1.0;
    }
    std::vector<double> expected = chi2::integrate_cells(grid, [&](double x, double y) {
      return filter.evaluate({static_cast<float>(x), static_cast<float>(y)}) / filter.integral();
    });
    for (double& e : expected) e *= n;
    const chi2::Result res = chi2::pearson(observed, expected);
    if (chi2::report_enabled())
      std::printf("ch11 chi2 %-24s %s\n",
                  type == FilterType::box ? "box filter" : type == FilterType::tent ? "tent filter" : "B-spline filter",
                  res.summary().c_str());
    CHECK(res.passed(kAlpha));
  }
  CHECK(PixelFilter(FilterType::box).radius() == 0.5f);
  CHECK(PixelFilter(FilterType::tent).radius() == 1.0f);
  CHECK(parse_filter_type("tent") == FilterType::tent);
  CHECK(PixelFilter(FilterType::bspline).radius() == 2.0f);
  CHECK(parse_filter_type("bspline") == FilterType::bspline);
  // The B-spline's profile: 2/3 at the centre, 1/6 one pixel out (half its radius), 0 at the edge.
  const PixelFilter b(FilterType::bspline);
  CHECK(b.evaluate({0, 0}) == doctest::Approx(4.0 / 9.0));
  CHECK(b.evaluate({1, 0}) == doctest::Approx(1.0 / 9.0));
  CHECK(b.evaluate({2, 0}) == doctest::Approx(0.0));
  // Its sampled offsets are symmetric, half on each side of the centre.
  CHECK(std::fabs(b.sample({0.5f, 0.5f}).offset.x) < 1e-6f);  // 0 by symmetry: an absolute bound
  CHECK(b.sample({0.25f, 0.75f}).offset.x == doctest::Approx(-b.sample({0.75f, 0.25f}).offset.x));
  CHECK_THROWS_AS(parse_filter_type("mitchell"), std::invalid_argument);
  CHECK_THROWS_AS(PixelFilter(FilterType::tent, INFINITY), std::invalid_argument);
}
