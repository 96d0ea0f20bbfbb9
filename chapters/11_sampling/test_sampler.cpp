// Chapter 11 tests: random numbers, the scrambled Sobol sequence and the samplers.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "11_sampling/chi_square.h"
#include "11_sampling/rng.h"
#include "11_sampling/sampler.h"
#include "11_sampling/sobol.h"

using namespace rtk;

TEST_CASE("ch11: PCG32 reproduces the reference generator's output") {
  // pcg32_srandom_r(&rng, 42, 54) in O'Neill's pcg-c-basic demo prints these six numbers.
  Pcg32 rng(42u, 54u);
  const uint32_t expected[] = {0xa15c02b7u, 0x7b47f409u, 0xba1d3330u,
                               0x83d2f293u, 0xbfa4784bu, 0xcbed606eu};
  for (uint32_t e : expected) CHECK(rng.next_u32() == e);
}

TEST_CASE("ch11: unit floats lie in [0, 1) and reach both ends of it") {
  CHECK(to_unit_float(0u) == 0.0f);
  CHECK(to_unit_float(0xffffffffu) < 1.0f);
  CHECK(to_unit_float(0xffffffffu) == 1.0f - 0x1p-24f);
  CHECK(to_unit_float(0x80000000u) == 0.5f);
}

TEST_CASE("ch11: the first Sobol dimensions are van der Corput and Pascal's matrix") {
  const float d0[] = {0, 0.5f, 0.25f, 0.75f, 0.125f, 0.625f, 0.375f, 0.875f};
  const float d1[] = {0, 0.5f, 0.75f, 0.25f, 0.625f, 0.125f, 0.375f, 0.875f};
  for (uint32_t i = 0; i < 8; ++i) {
    CHECK(sobol_dim0(i) * 0x1p-32 == d0[i]);
    CHECK(sobol_dim1(i) * 0x1p-32 == d1[i]);
  }
}

TEST_CASE("ch11: the LK hash lets each bit depend only on the bits below it") {
  // Flipping bit j of the input may change bits >= j of the output, never a bit below j:
  // the property that makes owen_scramble an Owen scramble.
  Pcg32 rng(7);
  for (int trial = 0; trial < 2000; ++trial) {
    const uint32_t x = rng.next_u32(), seed = rng.next_u32();
    const int j = static_cast<int>(rng.next_u32() % 32);
    const uint32_t diff = lk_hash(x, seed) ^ lk_hash(x ^ (1u << j), seed);
    REQUIRE(diff != 0);  // a bijection: different inputs, different outputs
    CHECK((diff & ((1u << j) - 1u)) == 0u);
  }
}

TEST_CASE("ch11: bit reversal and the reversed second Sobol dimension by their definitions") {
  Pcg32 rng(11);
  auto reverse_slowly = [](uint32_t w) {
    uint32_t r = 0;
    for (int b = 0; b < 32; ++b) r |= ((w >> b) & 1u) << (31 - b);
    return r;
  };
  for (int trial = 0; trial < 10000; ++trial) {
    const uint32_t w = trial < 32 ? 1u << trial : rng.next_u32(), w2 = rng.next_u32();
    REQUIRE(reverse_bits(w) == reverse_slowly(w));
    REQUIRE(reverse_bits_pairwise((uint64_t{w} << 32) | w2) ==
            ((uint64_t{reverse_slowly(w)} << 32) | reverse_slowly(w2)));
    REQUIRE(sobol_dim1_reversed(w) == reverse_bits(sobol_dim1(w)));
  }
}

TEST_CASE("ch11: the fast Sobol point equals its definition bit for bit") {
  // sobol_owen works on reversed words and tables; sobol_owen_reference is the definition
  // (shuffle, Sobol point, two Owen scrambles). They must agree on every bit, for small
  // indices (a pixel's samples) and arbitrary ones.
  Pcg32 rng(12);
  for (int trial = 0; trial < 20000; ++trial) {
    const uint32_t index = trial < 10000 ? static_cast<uint32_t>(trial) : rng.next_u32();
    const SobolSeeds seeds{rng.next_u32(), rng.next_u32(), rng.next_u32()};
    const std::array<uint32_t, 2> fast = sobol_owen(reverse_bits(index), seeds);
    const std::array<uint32_t, 2> reference = sobol_owen_reference(index, seeds);
    REQUIRE(fast[0] == reference[0]);
    REQUIRE(fast[1] == reference[1]);
    REQUIRE(sobol_owen_1d(reverse_bits(index), seeds) == reference[0]);
  }
  // And the sampler returns those points, with the seeds it reports, dimension after dimension.
  Sampler sampler(SamplerType::sobol, 3), seeds_of(SamplerType::sobol, 3);
  for (uint32_t index : {0u, 1u, 5u, 63u, 1000u}) {
    sampler.start_pixel_sample(17, 4, index);
    seeds_of.start_pixel_sample(17, 4, index);
    for (int d = 0; d < 12; ++d) {
      const std::array<uint32_t, 2> r = sobol_owen_reference(index, seeds_of.next_seeds());
      if (d % 3 == 2) {
        CHECK(sampler.get_1d() == to_unit_float(r[0]));
      } else {
        CHECK(sampler.get_2d() == Vec2f(to_unit_float(r[0]), to_unit_float(r[1])));
      }
    }
  }
}

namespace {
// Whether 2^m points form a (0,m,2)-net in base 2: for every split of m into a + b, each of
// the 2^a x 2^b elementary boxes holds exactly one point.
bool is_net(const std::vector<Vec2f>& points, int m) {
  for (int a = 0; a <= m; ++a) {
    const int nx = 1 << a, ny = 1 << (m - a);
    std::vector<int> count(static_cast<std::size_t>(nx) * ny, 0);
    for (Vec2f p : points) {
      const int i = static_cast<int>(p.x * nx), j = static_cast<int>(p.y * ny);
      if (i < 0 || i >= nx || j < 0 || j >= ny) return false;
      if (++count[i + nx * j] > 1) return false;
    }
  }
  return true;
}
}  // namespace

TEST_CASE("ch11: every dimension pair of the Sobol sampler is a (0,m,2)-net") {
  Sampler sampler(SamplerType::sobol, 1234);
  for (int m = 0; m <= 8; ++m) {
    const int n = 1 << m;
    for (int pixel = 0; pixel < 4; ++pixel) {
      // Collect dimension pairs 0 (the film position), 1 and 5 of each sample.
      std::vector<Vec2f> d0, d1, d5;
      std::vector<float> one_d;
      for (int i = 0; i < n; ++i) {
        sampler.start_pixel_sample(pixel * 37, pixel * 11, static_cast<uint32_t>(i));
        d0.push_back(sampler.get_pixel_2d());
        d1.push_back(sampler.get_2d());
        for (int k = 0; k < 3; ++k) sampler.get_2d();
        d5.push_back(sampler.get_2d());
        one_d.push_back(sampler.get_1d());
      }
      CHECK(is_net(d0, m));
      CHECK(is_net(d1, m));
      CHECK(is_net(d5, m));
      // A 1D dimension is stratified: one value in each interval [k/n, (k+1)/n).
      std::vector<int> strata(n, 0);
      for (float u : one_d) ++strata[static_cast<int>(u * n)];
      CHECK(std::all_of(strata.begin(), strata.end(), [](int c) { return c == 1; }));
    }
  }
}

TEST_CASE("ch11: independent samples are not a net, but they are uniform") {
  // The independent sampler must fail the net test (else the test above proves nothing), and
  // pass a chi-square test of uniformity on a 16 x 16 grid.
  Sampler sampler(SamplerType::independent, 99);
  std::vector<Vec2f> points;
  chi2::Grid grid{0, 1, 0, 1, 16, 16};
  std::vector<double> observed(grid.size(), 0.0);
  const int n = 1 << 14;
  for (int i = 0; i < n; ++i) {
    sampler.start_pixel_sample(3, 4, static_cast<uint32_t>(i));
    const Vec2f u = sampler.get_2d();
    if (i < 64) points.push_back(u);
    observed[grid.cell(u.x, u.y)] += 1.0;
  }
  CHECK_FALSE(is_net(points, 6));
  const std::vector<double> expected(grid.size(), static_cast<double>(n) / grid.size());
  const chi2::Result r = chi2::pearson(observed, expected);
  INFO(r.summary());
  CHECK(r.passed(chi2::sidak_alpha(chi2::kSuiteSignificance, 12)));
}

TEST_CASE("ch11: a pixel's samples do not depend on the order pixels are visited in") {
  for (SamplerType type : {SamplerType::independent, SamplerType::sobol}) {
    // Row by row with one sampler, then in reverse with another, interleaved with a third.
    auto values = [&](Sampler& s, int x, int y, uint32_t i) {
      s.start_pixel_sample(x, y, i);
      std::vector<float> v;
      for (int d = 0; d < 5; ++d) {
        const Vec2f p = s.get_2d();
        v.push_back(p.x);
        v.push_back(p.y);
        v.push_back(s.get_1d());
      }
      return v;
    };
    Sampler forward(type, 5), backward(type, 5), other(type, 5);
    std::vector<std::vector<float>> first;
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 4; ++x)
        for (uint32_t i = 0; i < 4; ++i) first.push_back(values(forward, x, y, i));
    int k = static_cast<int>(first.size());
    bool same = true;
    for (int y = 3; y >= 0; --y)
      for (int x = 3; x >= 0; --x)
        for (int i = 3; i >= 0; --i) {
          values(other, 7 - x, y + 9, static_cast<uint32_t>(i * 3));  // unrelated work in between
          same = same && values(backward, x, y, static_cast<uint32_t>(i)) == first[--k];
        }
    CHECK(same);
    // A different seed gives a different image.
    Sampler reseeded(type, 6);
    CHECK(values(reseeded, 0, 0, 0) != first[0]);
  }
}

TEST_CASE("ch11: a skipped number leaves the numbers after it as they were") {
  // The renderer skips numbers it will not use; every later number must be the one it would
  // have drawn, bit for bit, for both samplers and for 1D numbers and 2D points.
  for (SamplerType type : {SamplerType::independent, SamplerType::sobol}) {
    Sampler drawn(type, 3), skipping(type, 3);
    bool same = true;
    for (uint32_t i = 0; i < 8; ++i) {
      drawn.start_pixel_sample(5, 7, i);
      skipping.start_pixel_sample(5, 7, i);
      for (int d = 0; d < 12; ++d) {
        if (d % 3 == 0) {
          drawn.get_1d();
          skipping.skip_1d();
        } else if (d % 3 == 1) {
          drawn.get_2d();
          skipping.skip_2d();
        } else {
          const Vec2f a = drawn.get_2d(), b = skipping.get_2d();
          same = same && a.x == b.x && a.y == b.y && drawn.get_1d() == skipping.get_1d();
        }
      }
    }
    CHECK(same);
  }
}

TEST_CASE("ch11: Sobol dimensions and pixels are decorrelated by their scrambles") {
  // Padding with independent scrambles must leave no correlation between dimensions; the
  // same sample of two pixels must differ.
  Sampler sampler(SamplerType::sobol, 77);
  const int n = 256;
  double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
  for (int i = 0; i < n; ++i) {
    sampler.start_pixel_sample(10, 20, static_cast<uint32_t>(i));
    const double a = sampler.get_2d().x, b = sampler.get_2d().x;
    sx += a, sy += b, sxx += a * a, syy += b * b, sxy += a * b;
  }
  const double cov = sxy / n - sx / n * sy / n;
  const double corr = cov / std::sqrt((sxx / n - sx / n * sx / n) * (syy / n - sy / n * sy / n));
  CHECK(std::fabs(corr) < 0.25);  // 4 standard deviations of the correlation of independent data
  Sampler a(SamplerType::sobol, 77), b(SamplerType::sobol, 77);
  a.start_pixel_sample(0, 0, 0);
  b.start_pixel_sample(1, 0, 0);
  CHECK(a.get_2d() != b.get_2d());
}

TEST_CASE("ch11: sampler names are parsed strictly") {
  CHECK(parse_sampler_type("sobol") == SamplerType::sobol);
  CHECK(parse_sampler_type("independent") == SamplerType::independent);
  CHECK_THROWS_AS(parse_sampler_type("halton"), std::invalid_argument);
}
