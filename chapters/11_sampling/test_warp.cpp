// Chapter 11 tests: warping functions (chi-square against their densities), frames, and the
// chi-square machinery itself.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>

#include "11_sampling/chi_square.h"
#include "11_sampling/frame.h"
#include "11_sampling/rng.h"
#include "11_sampling/warp.h"

using namespace rtk;

namespace {

// Every chi-square test of this file counts toward the Sidak correction.
constexpr int kChi2Tests = 6;
const double kAlpha = chi2::sidak_alpha(chi2::kSuiteSignificance, kChi2Tests);
constexpr int kSamples = 100000;

// Runs a direction sampler through the spherical chi-square test.
chi2::Result test_directions(const char* name, const std::function<Vec3f(Vec2f)>& sample,
                             const std::function<double(Vec3f)>& pdf, uint64_t seed) {
  chi2::SphericalHistogram hist(10);
  Pcg32 rng(seed);
  for (int i = 0; i < kSamples; ++i) {
    const float u0 = rng.next_float();
    hist.add(sample({u0, rng.next_float()}));
  }
  std::vector<double> expected = hist.expected(pdf);
  for (double& e : expected) e *= kSamples;
  const chi2::Result r = chi2::pearson(hist.counts, expected);
  if (chi2::report_enabled()) std::printf("ch11 chi2 %-24s %s\n", name, r.summary().c_str());
  CHECK(hist.outside == 0);
  return r;
}

}  // namespace

TEST_CASE("ch11: chi-square p-values match the tables") {
  // The 5% critical values of the chi-square distribution for 1, 10 and 100 degrees of freedom.
  CHECK(chi2::chi2_p_value(3.841, 1) == doctest::Approx(0.05).epsilon(1e-3));
  CHECK(chi2::chi2_p_value(18.307, 10) == doctest::Approx(0.05).epsilon(1e-3));
  CHECK(chi2::chi2_p_value(124.342, 100) == doctest::Approx(0.05).epsilon(1e-3));
  CHECK(chi2::chi2_p_value(0.0, 5) == 1.0);
  CHECK(chi2::chi2_p_value(1e6, 5) < 1e-100);
  CHECK(chi2::sidak_alpha(0.01, 1) == doctest::Approx(0.01));
}

TEST_CASE("ch11: warps to the hemisphere, sphere and cone follow their densities") {
  const chi2::Result cosine = test_directions(
      "cosine hemisphere", sample_cosine_hemisphere,
      [](Vec3f w) { return pdf_cosine_hemisphere(w.z); }, 1);
  CHECK(cosine.passed(kAlpha));
  const chi2::Result hemi = test_directions(
      "uniform hemisphere", sample_uniform_hemisphere,
      [](Vec3f w) { return w.z >= 0 ? pdf_uniform_hemisphere() : 0.0; }, 2);
  CHECK(hemi.passed(kAlpha));
  const chi2::Result sphere = test_directions(
      "uniform sphere", sample_uniform_sphere, [](Vec3f) { return pdf_uniform_sphere(); }, 3);
  CHECK(sphere.passed(kAlpha));
  const float cos_max = std::cos(0.6f), h = one_minus_cos(0.6f);
  const chi2::Result cone = test_directions(
      "uniform cone (0.6 rad)", [&](Vec2f u) { return sample_uniform_cone(u, h); },
      [&](Vec3f w) { return w.z >= cos_max ? pdf_uniform_cone(h) : 0.0; }, 4);
  CHECK(cone.passed(kAlpha));
}

TEST_CASE("ch11: the chi-square test rejects a sampler that does not follow its density") {
  // Uniform hemisphere samples claimed to be cosine distributed, and a cone one degree too
  // wide: both must fail, or the tests above prove nothing.
  const chi2::Result wrong = test_directions(
      "uniform as cosine", sample_uniform_hemisphere,
      [](Vec3f w) { return pdf_cosine_hemisphere(w.z); }, 5);
  CHECK(wrong.p_value < 1e-12);
  const float cos_max = std::cos(0.6f), h = one_minus_cos(0.6f), h_wide = one_minus_cos(0.6f + 0.0175f);
  const chi2::Result wide = test_directions(
      "cone 1 degree too wide", [&](Vec2f u) { return sample_uniform_cone(u, h_wide); },
      [&](Vec3f w) { return w.z >= cos_max ? pdf_uniform_cone(h) : 0.0; }, 6);
  CHECK_FALSE(wide.passed(kAlpha));
}

TEST_CASE("ch11: the concentric disk map is uniform") {
  // Binned in (phi, r^2), where the uniform density on the disk is the constant 1 / (2 pi):
  // a smooth integrand, so the expected counts are exact.
  chi2::Grid grid{0, 2 * std::numbers::pi, 0, 1, 16, 8};
  std::vector<double> observed(grid.size(), 0.0);
  Pcg32 rng(8);
  for (int i = 0; i < kSamples; ++i) {
    const float u0 = rng.next_float();
    const Vec2f d = sample_uniform_disk({u0, rng.next_float()});
    double phi = std::atan2(d.y, d.x);
    if (phi < 0) phi += 2 * std::numbers::pi;
    const int c = grid.cell(phi, double(d.x) * d.x + double(d.y) * d.y);
    REQUIRE(c >= 0);
    observed[c] += 1.0;
  }
  const std::vector<double> expected(grid.size(), double(kSamples) / grid.size());
  const chi2::Result r = chi2::pearson(observed, expected);
  if (chi2::report_enabled())
    std::printf("ch11 chi2 %-24s %s\n", "concentric disk", r.summary().c_str());
  CHECK(r.passed(kAlpha));
  // The map's corners: the square's centre is the disk's centre, its edges the circle.
  CHECK(sample_uniform_disk({0.5f, 0.5f}) == Vec2f{0, 0});
  const Vec2f edge = sample_uniform_disk({1.0f, 0.5f});
  CHECK(std::hypot(edge.x, edge.y) == doctest::Approx(1.0));
}

TEST_CASE("ch11: triangle sampling is uniform over the triangle") {
  // In coordinates s = b1 + b2 (distance from vertex 0) and t = b2 / (b1 + b2) (position
  // across), the uniform density of the half-square is 2 s.
  chi2::Grid grid{0, 1, 0, 1, 12, 12};
  std::vector<double> observed(grid.size(), 0.0);
  Pcg32 rng(9);
  const Vec3f p0{1, 2, 3}, p1{4, -1, 3}, p2{0, 0, 7};
  Vec3f mean{0, 0, 0};
  for (int i = 0; i < kSamples; ++i) {
    const float u0 = rng.next_float();
    const Vec3f b = sample_uniform_triangle({u0, rng.next_float()});
    REQUIRE(b.x >= 0.0f);
    REQUIRE(b.y >= 0.0f);
    REQUIRE(b.z >= 0.0f);
    REQUIRE(b.x + b.y + b.z == doctest::Approx(1.0f));
    mean += (b.x * p0 + b.y * p1 + b.z * p2) * (1.0f / kSamples);
    const double s = double(b.y) + b.z;
    observed[grid.cell(s, s > 0 ? b.z / s : 0.0)] += 1.0;
  }
  std::vector<double> expected =
      chi2::integrate_cells(grid, [](double s, double) { return 2.0 * s; });
  for (double& e : expected) e *= kSamples;
  const chi2::Result r = chi2::pearson(observed, expected);
  if (chi2::report_enabled())
    std::printf("ch11 chi2 %-24s %s\n", "uniform triangle", r.summary().c_str());
  CHECK(r.passed(kAlpha));
  // The mean of uniform points is the centroid.
  const Vec3f centroid = (p0 + p1 + p2) * (1.0f / 3.0f);
  CHECK(length(mean - centroid) < 0.02f);
}

TEST_CASE("ch11: frames are orthonormal and right-handed for every normal") {
  // Random normals, the poles, and the near-(0,0,-1) normals where Frisvad's construction fails.
  std::vector<Vec3f> normals = {{0, 0, 1},
                                {0, 0, -1},
                                {1, 0, 0},
                                {0, -1, 0},
                                normalize(Vec3f{1e-7f, 0, -1}),
                                normalize(Vec3f{0, 1e-4f, -1})};
  Pcg32 rng(10);
  for (int i = 0; i < 1000; ++i) {
    const float u0 = rng.next_float();
    normals.push_back(sample_uniform_sphere({u0, rng.next_float()}));
  }
  for (Vec3f n : normals) {
    const Frame f(n);
    CHECK(std::fabs(dot(f.s, f.t)) < 1e-6f);
    CHECK(std::fabs(dot(f.s, f.n)) < 1e-6f);
    CHECK(std::fabs(dot(f.t, f.n)) < 1e-6f);
    CHECK(length(f.s) == doctest::Approx(1.0f).epsilon(1e-6));
    CHECK(length(f.t) == doctest::Approx(1.0f).epsilon(1e-6));
    CHECK(length(cross(f.s, f.t) - f.n) < 1e-5f);
    const Vec3f w = normalize(Vec3f{0.3f, -0.5f, 0.8f});
    CHECK(length(f.to_world(f.to_local(w)) - w) < 1e-5f);
    CHECK(f.to_local(n).z == doctest::Approx(1.0f));
  }
}

TEST_CASE("ch11: spherical coordinates invert the direction map") {
  for (double theta : {0.1, 1.0, 2.0, 3.0})
    for (double phi : {0.2, 2.5, 4.0, 6.0}) {
      const Vec3f w = chi2::spherical_direction(theta, phi);
      CHECK(spherical_theta(w) == doctest::Approx(theta).epsilon(1e-5));
      CHECK(spherical_phi(w) == doctest::Approx(phi).epsilon(1e-5));
    }
  // Near either pole, from 1e-7 to 0.1 radians away, the polar angle keeps its accuracy:
  // relative near +z, within two float steps of pi near -z. acos of the height, which rounds
  // to a float within 6e-8 of 1 in magnitude, would be off by up to 2.4e-4 radians at both.
  double worst_north = 0.0, worst_south = 0.0;
  for (double t = 1e-7; t < 0.1; t *= 1.01) {
    const Vec3f north{float(std::sin(t)), 0.0f, float(std::cos(t))}, south{north.x, 0.0f, -north.z};
    // The exact angles of the float directions.
    const double exact_north = std::atan2(double(north.x), double(north.z));
    const double exact_south = std::atan2(double(south.x), double(south.z));
    worst_north = std::max(worst_north, std::fabs(spherical_theta(north) / exact_north - 1.0));
    worst_south = std::max(worst_south, std::fabs(spherical_theta(south) - exact_south));
  }
  CHECK(worst_north < 1e-6);
  CHECK(worst_south < 5e-7);
}

TEST_CASE("ch11: the disk map's cosine and sine agree with the library's") {
  // Within 45 degrees of the axis, the series must be as good as std::cos and std::sin to a
  // few units in the last place, so that the disk map is the concentric map it always was.
  double worst = 0.0;
  for (int i = -1000; i <= 1000; ++i) {
    const double x = std::numbers::pi / 4 * i / 1000.0;
    const Vec2f cs = cos_sin_quarter(static_cast<float>(x));
    const float xf = static_cast<float>(x);
    worst = std::max({worst, std::fabs(double(cs.x) - std::cos(double(xf))),
                      std::fabs(double(cs.y) - std::sin(double(xf)))});
  }
  CHECK(worst < 3e-7);
  const Vec2f d = sample_uniform_disk({0.9f, 0.7f});  // a = 0.8, b = 0.4: 22.5 degrees
  CHECK(d.x == doctest::Approx(0.8 * std::cos(std::numbers::pi / 8)).epsilon(1e-6));
  CHECK(d.y == doctest::Approx(0.8 * std::sin(std::numbers::pi / 8)).epsilon(1e-6));
}

TEST_CASE("ch11: cosine-weighted directions are unit vectors with the disk point's height") {
  // Over a grid of the square, every direction must have length 1 and height
  // sqrt(1 - r^2), r the disk point's radius, to a few units in the last place: a bounce's
  // direction is used as it is, without normalising it again.
  double worst_length = 0.0, worst_height = 0.0;
  constexpr int kSteps = 257;
  for (int i = 0; i < kSteps; ++i)
    for (int j = 0; j < kSteps; ++j) {
      const Vec2f u{float(i) / (kSteps - 1), float(j) / (kSteps - 1)};
      const Vec3f w = sample_cosine_hemisphere(u);
      const double a = 2.0 * u.x - 1.0, b = 2.0 * u.y - 1.0;
      const double r = std::max(std::fabs(a), std::fabs(b));
      const double length = std::sqrt(double(w.x) * w.x + double(w.y) * w.y + double(w.z) * w.z);
      worst_length = std::max(worst_length, std::fabs(length - 1.0));
      worst_height = std::max(worst_height, std::fabs(double(w.z) - std::sqrt(1.0 - r * r)));
      CHECK(w.z >= 0.0f);
    }
  CHECK(worst_length < 4e-7);
  CHECK(worst_height < 4e-7);
}

TEST_CASE("ch11: uniform sphere and hemisphere directions keep their angle at the poles") {
  // Distances u from 1e-12 to 2^-10 from a pole, in steps of 0.1 %, against the polar angle of
  // the same u in double precision: the sine taken as sqrt(1 - z^2) from the rounded height
  // sends every u below 2^-26 to the pole itself, 2.4e-4 radians off for the largest of them.
  double worst_sphere = 0.0, worst_hemisphere = 0.0;
  const auto polar_error = [](Vec3f w, double sin_exact, double cos_exact) {
    const double sin_w = std::sqrt(double(w.x) * w.x + double(w.y) * w.y);
    return std::fabs(std::atan2(sin_w, double(w.z)) - std::atan2(sin_exact, cos_exact));
  };
  for (float u = 1e-12f; u < 0x1p-10f; u *= 1.001f) {
    for (const float v : {u, 1.0f - u}) {  // near the north and the south pole
      const double cos_exact = 1.0 - 2.0 * v, sin_exact = 2.0 * std::sqrt(double(v) * (1.0 - v));
      worst_sphere = std::max(worst_sphere,
                              polar_error(sample_uniform_sphere({v, 0.3f}), sin_exact, cos_exact));
    }
    const float z = 1.0f - u;
    const double sin_exact = std::sqrt((1.0 - z) * (1.0 + z));
    worst_hemisphere =
        std::max(worst_hemisphere, polar_error(sample_uniform_hemisphere({z, 0.3f}), sin_exact, z));
  }
  CHECK(worst_sphere < 1e-7);
  CHECK(worst_hemisphere < 1e-7);
}

TEST_CASE("ch11: one_minus_cos keeps its digits for small angles") {
  // Against the double-precision 2 sin^2(theta / 2), from 1e-7 radians (six millionths of a
  // degree) to pi: a few float ulps of relative error throughout, where 1 - std::cos in float
  // is 0 below 2.4e-4 radians and off by 0.15 % at the sun's 0.27 degrees.
  double worst = 0.0;
  for (double theta = 1e-7; theta < std::numbers::pi; theta *= 1.1) {
    const double s = std::sin(double(float(theta)) / 2), exact = 2 * s * s;
    worst = std::max(worst, std::fabs(one_minus_cos(float(theta)) / exact - 1));
  }
  CHECK(worst < 1e-6);
  const float sun = 0.27f * kPi / 180;
  CHECK(std::fabs((1.0f - std::cos(sun)) / one_minus_cos(sun) - 1) > 1e-3);  // the classic loss
  CHECK(1.0f - std::cos(1e-4f) == 0.0f);
  CHECK(one_minus_cos(1e-4f) > 0.0f);
  // Between two unit vectors 1e-4 radians apart, where their dot product rounds to 1.
  const Vec3f a{0, 0, 1}, b{std::sin(1e-4f), 0, std::cos(1e-4f)};
  CHECK(dot(a, b) == 1.0f);
  CHECK(one_minus_cos_between(a, b) == doctest::Approx(one_minus_cos(1e-4f)).epsilon(1e-6).scale(0));
}
