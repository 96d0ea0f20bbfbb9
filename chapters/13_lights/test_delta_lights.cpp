// Chapter 13 tests: point, directional, distant (cone) and ambient lights.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "11_sampling/chi_square.h"
#include "11_sampling/frame.h"
#include "11_sampling/rng.h"
#include "13_lights/distant_light.h"
#include "13_lights/point_light.h"

using namespace rtk;

namespace {
bool close(Color a, Color b, float rel = 1e-5f) {
  for (int i = 0; i < 3; ++i)
    if (std::fabs(a[i] - b[i]) > rel * std::max({std::fabs(a[i]), std::fabs(b[i]), 1e-6f}))
      return false;
  return true;
}
// Every chi-square test of this file counts toward the Sidak correction: the 20-degree
// distant light, the three small ones and the ambient light.
const double kAlpha = chi2::sidak_alpha(chi2::kSuiteSignificance, 5);
}  // namespace

TEST_CASE("ch13: a point light falls off with the square of the distance") {
  const PointLight light({1, 2, 3}, Color(100, 200, 300));
  const auto s = light.sample_li({{1, 2, 13}, {0, 0, 1}}, {0.3f, 0.3f});
  REQUIRE(s);
  CHECK(s->delta);
  CHECK(s->pdf == 1.0f);
  CHECK(s->distance == doctest::Approx(10.0f));
  CHECK(length(s->wi - Vec3f{0, 0, -1}) < 1e-6f);
  CHECK(close(s->L, Color(1, 2, 3)));
  CHECK(light.pdf_li({{0, 0, 0}}, {0, 0, 1}) == 0.0f);
  CHECK(light.is_delta());
  CHECK(close(light.power(1), Color(100, 200, 300) * (4 * kPi)));
  // At the light itself there is no direction: no sample, no NaN.
  CHECK_FALSE(light.sample_li({{1, 2, 3}}, {0.5f, 0.5f}));
  CHECK_THROWS_AS(PointLight({NAN, 0, 0}, Color(1)), std::invalid_argument);
  CHECK_THROWS_AS(PointLight({0, 0, 0}, Color(-1)), std::invalid_argument);
}

TEST_CASE("ch13: a spot light's emitted power matches its analytic value") {
  // Embree 2's commented-out Cornell box spot, narrowed: 20 degrees at full intensity, fading
  // to nothing at 50.
  const Vec3f p{213, 300, 227}, axis = normalize(Vec3f{-1, -1, 1});
  const Color I(3e5f, 2e5f, 1e5f);
  const SpotLight light(p, axis, I, 20.0f, 50.0f);
  const double c_in = std::cos(20 * kPi / 180), c_out = std::cos(50 * kPi / 180);
  const double analytic = 2 * kPi * (1 - c_in + (c_in - c_out) / 2);
  CHECK(close(light.power(1), I * float(analytic), 1e-4f));
  // The power that crosses a sphere of radius R around the light, integrated by Monte Carlo
  // over the sphere's area: the irradiance each point receives, facing the light, times
  // 4 pi R^2. 100,000 stratified points leave an error far below 0.5%.
  const float R = 7.0f;
  Pcg32 rng(3);
  double total = 0;
  const int n = 316;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Vec3f w = sample_uniform_sphere({(i + rng.next_float()) / n, (j + rng.next_float()) / n});
      const auto s = light.sample_li({p + w * R, -w}, {0.5f, 0.5f});
      if (!s) continue;
      CHECK(s->delta);
      total += s->L.r * dot(s->wi, -w);
    }
  const double measured = total / (double(n) * n) * 4 * kPi * R * R;
  CHECK(measured == doctest::Approx(double(light.power(1).r)).epsilon(5e-3));
  // Inside the inner cone the full intensity, outside the outer none, between them linear in
  // the cosine.
  CHECK(light.falloff(axis) == 1.0f);
  CHECK(light.falloff(-axis) == 0.0f);
  const Vec3f side = normalize(cross(axis, Vec3f{0, 1, 0}));
  const float mid = std::acos(float(0.5 * (c_in + c_out)));
  CHECK(light.falloff(axis * std::cos(mid) + side * std::sin(mid)) == doctest::Approx(0.5f).epsilon(1e-3));
  // A spot of 180 degrees at full intensity is a point light.
  CHECK(close(SpotLight(p, axis, I, 180, 180).power(1), PointLight(p, I).power(1), 1e-5f));
  CHECK(SpotLight(p, axis, I, 180, 180).falloff(-axis) == 1.0f);
  CHECK_THROWS_AS(SpotLight(p, axis, I, 60, 30), std::invalid_argument);
  CHECK_THROWS_AS(SpotLight(p, {0, 0, 0}, I, 10, 30), std::invalid_argument);
}

TEST_CASE("ch13: a spot light narrower than a float cosine can tell still shines") {
  // A beam of 0.005 degrees at full intensity fading to nothing at 0.01: both cosines round to
  // 1 in float (below 0.014 degrees they do). The falloff, linear in the cosine, and the power,
  // pi I (h_inner + h_outer) with h = 1 - cos, must hold as for a wide spot.
  const Vec3f p{1, 2, 3}, axis = normalize(Vec3f{-1, -1, 1});
  const double inner = 0.005 * std::numbers::pi / 180, outer = 0.01 * std::numbers::pi / 180;
  const double h_in = 1 - std::cos(inner), h_out = 1 - std::cos(outer);
  const SpotLight light(p, axis, Color(1), 0.005f, 0.01f);
  // Relative bounds (scale 0): with its default scale of 1, doctest's Approx would take any
  // value this small for another.
  CHECK(light.power(1).r == doctest::Approx(std::numbers::pi * (h_in + h_out)).epsilon(1e-4).scale(0));
  const Frame around(axis);
  auto off_axis = [&](double a) { return around.to_world(Vec3f{float(std::sin(a)), 0.0f, float(std::cos(a))}); };
  CHECK(light.falloff(off_axis(0.5 * inner)) == 1.0f);
  CHECK(light.falloff(off_axis(2.0 * outer)) == 0.0f);
  // Halfway between the cones' 1 - cos, halfway in intensity; to the resolution of a float
  // direction, 3e-8 radians across the axis.
  const double mid = std::acos(1 - 0.5 * (h_in + h_out));
  CHECK(light.falloff(off_axis(mid)) == doctest::Approx(0.5).epsilon(1e-2));
  // A point on the axis, a metre away, receives the full intensity.
  const auto s = light.sample_li({p + axis, -axis}, {0.5f, 0.5f});
  REQUIRE(s);
  CHECK(close(s->L, Color(1), 1e-5f));
}

TEST_CASE("ch13: a directional light comes from the opposite of its direction") {
  // The guide's -directionallight -0.5 -0.4 1 2 2 2 (commented out in cornell_box.ecs) travels
  // into the box, so it is seen looking back toward -z.
  const DirectionalLight light({-0.5f, -0.4f, 1}, Color(2));
  const auto s = light.sample_li({{278, 0, 279}}, {0.1f, 0.9f});
  REQUIRE(s);
  CHECK(s->delta);
  CHECK(std::isinf(s->distance));
  CHECK(length(s->wi - normalize(Vec3f{0.5f, 0.4f, -1})) < 1e-6f);
  CHECK(s->L == Color(2));
  CHECK(close(light.power(10), Color(2 * kPi * 100)));
  CHECK_THROWS_AS(DirectionalLight({0, 0, 0}, Color(1)), std::invalid_argument);
}

TEST_CASE("ch13: a distant light fills its cone uniformly (chi-square)") {
  const Vec3f dir = normalize(Vec3f{-0.5f, -0.4f, 1});
  const DistantLight light(dir, Color(150), 20.0f);
  chi2::SphericalHistogram hist(10);
  Pcg32 rng(5000);
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    const float u0 = rng.next_float();
    const auto s = light.sample_li({}, {u0, rng.next_float()});
    REQUIRE(s);
    REQUIRE(s->pdf == doctest::Approx(light.pdf_li({}, s->wi)));
    REQUIRE(close(s->L, light.le(s->wi)));
    hist.add(s->wi);
  }
  std::vector<double> expected = hist.expected([&](Vec3f w) { return light.pdf_li({}, w); });
  double total = 0;
  for (double& e : expected) total += e, e *= n;
  CHECK(total == doctest::Approx(1.0).epsilon(2e-3));
  const chi2::Result r = chi2::pearson(hist.counts, expected);
  if (chi2::report_enabled())
    std::printf("ch13 chi2 %-22s %s\n", "distant light 20 deg", r.summary().c_str());
  CHECK(r.passed(kAlpha));
  // Outside the cone there is nothing; the centre of the cone is -dir.
  CHECK(is_black(light.le(dir)));
  CHECK(light.le(-dir) == Color(150));
  CHECK_THROWS_AS(DistantLight(dir, Color(1), 0.0f), std::invalid_argument);
  CHECK_THROWS_AS(DistantLight(dir, Color(1), 181.0f), std::invalid_argument);
}

TEST_CASE("ch13: a distant light as small as the sun, or a star, still fills its cone") {
  // The sun's half-angle is 0.27 degrees, so 1 - cos(theta_max) is 1.1e-5, while floats just
  // below 1 are 6e-8 apart: a cone held by its cosine has some 190 heights to sample from, and
  // at 0.01 degrees the cosine rounds to 1 and the cone to nothing. Each light here must give
  // the irradiance L pi sin^2(theta_max) at normal incidence, sample its cone uniformly in
  // 1 - cos(theta) (chi-square on ten bins, angles measured in double), keep every sample
  // inside, agree with pdf_li and le, and report the power of its cone. Inside and agree are
  // to the resolution of a float direction, 3e-8 radians across the axis: within 1 % of the
  // edge of the smallest cone a sample may be judged outside, and no farther in.
  const Vec3f dir = normalize(Vec3f{-0.5f, -0.4f, 1});
  const Frame toward(-dir);
  for (const double degrees : {0.27, 0.01, 0.001}) {
    const double theta_max = degrees * std::numbers::pi / 180, h = 1 - std::cos(theta_max);
    const double sin2 = std::sin(theta_max) * std::sin(theta_max);
    const DistantLight light(dir, Color(2), float(degrees));
    Pcg32 rng(uint64_t(5001 + 1e3 * degrees));
    constexpr int kN = 20000, kBins = 10;
    std::vector<double> counts(kBins, 0.0);
    double irradiance = 0, worst_excess = 0;
    for (int i = 0; i < kN; ++i) {
      const float u0 = rng.next_float();
      const auto s = light.sample_li({}, {u0, rng.next_float()});
      REQUIRE(s);
      REQUIRE(std::isfinite(s->pdf));
      const Vec3f w = toward.to_local(s->wi);  // the cone's axis is +z here
      const double sine = std::hypot(double(w.x), double(w.y)), angle = std::atan2(sine, double(w.z));
      worst_excess = std::max(worst_excess, angle - theta_max);
      irradiance += double(s->L.r) * std::cos(angle) / s->pdf;
      const double x = (1 - std::cos(angle)) / h;  // uniform in [0, 1] for a uniform cone
      counts[std::min(kBins - 1, int(x * kBins))] += 1;
      if (x < 0.99) {
        REQUIRE(s->pdf == doctest::Approx(light.pdf_li({}, s->wi)));
        REQUIRE(close(s->L, light.le(s->wi)));
      }
    }
    INFO("half-angle ", degrees, " degrees");
    CHECK(worst_excess < 1e-7);
    // Relative bounds (scale 0), as for the narrow spot above.
    CHECK(irradiance / kN == doctest::Approx(2 * std::numbers::pi * sin2).epsilon(1e-3).scale(0));
    const chi2::Result r = chi2::pearson(counts, std::vector<double>(kBins, double(kN) / kBins));
    if (chi2::report_enabled())
      std::printf("ch13 chi2 distant light %-7g deg %s\n", degrees, r.summary().c_str());
    CHECK(r.passed(kAlpha));
    // Half the half-angle off the axis is inside, twice it outside.
    for (const double off : {0.5, 2.0}) {
      const double a = off * theta_max;
      const Vec3f wi = toward.to_world(Vec3f{float(std::sin(a)), 0.0f, float(std::cos(a))});
      CHECK(is_black(light.le(wi)) == (off > 1));
      CHECK((light.pdf_li({}, wi) > 0) == (off < 1));
    }
    const double power = light.power(1.0f).r;  // through a cross-section of radius 1
    CHECK(power == doctest::Approx(2 * std::numbers::pi * std::numbers::pi * sin2).epsilon(1e-4).scale(0));
  }
}

TEST_CASE("ch13: the ambient light is cosine-sampled about the normal") {
  const AmbientLight light(Color(0.5f));
  const Vec3f n = normalize(Vec3f{0.3f, -0.2f, 0.9f});
  chi2::SphericalHistogram hist(10);
  Pcg32 rng(5100);
  const int n_samples = 100000;
  double irradiance = 0;
  for (int i = 0; i < n_samples; ++i) {
    const float u0 = rng.next_float();
    const auto s = light.sample_li({{0, 0, 0}, n}, {u0, rng.next_float()});
    if (!s) continue;
    REQUIRE(s->pdf == doctest::Approx(light.pdf_li({{0, 0, 0}, n}, s->wi)));
    hist.add(s->wi);
    irradiance += s->L.r * dot(s->wi, n) / s->pdf;
  }
  // Irradiance under a uniform sky is pi L, and cosine sampling makes every estimate exact.
  CHECK(irradiance / n_samples == doctest::Approx(kPi * 0.5f).epsilon(1e-3));
  std::vector<double> expected = hist.expected([&](Vec3f w) {
    return light.pdf_li({{0, 0, 0}, n}, w);
  });
  for (double& e : expected) e *= n_samples;
  const chi2::Result r = chi2::pearson(hist.counts, expected);
  if (chi2::report_enabled())
    std::printf("ch13 chi2 %-22s %s\n", "ambient (cosine)", r.summary().c_str());
  CHECK(r.passed(kAlpha));
  // Without a normal: the whole sphere.
  const auto s = light.sample_li({{0, 0, 0}}, {0.9f, 0.1f});
  REQUIRE(s);
  CHECK(s->pdf == doctest::Approx(1.0f / (4 * kPi)));
  CHECK(light.le({0, 1, 0}) == Color(0.5f));
}
