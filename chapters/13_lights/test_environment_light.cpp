// Chapter 13 tests: the HDR environment light.
#include <doctest/doctest.h>
#include <stb/stb_image_write.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "11_sampling/chi_square.h"
#include "11_sampling/rng.h"
#include "11_sampling/warp.h"
#include "13_lights/environment_light.h"

using namespace rtk;

namespace {

// A 40 x 20 map: a dim gradient, a bright "sun" of 2 x 2 texels, a black band, and one
// texel at each pole row.
std::shared_ptr<const ImageTexture> test_map() {
  const int w = 40, h = 20;
  std::vector<Color> t(w * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) t[y * w + x] = Color(0.1f + 0.02f * x, 0.2f, 0.05f + 0.01f * y);
  for (int y = 12; y < 14; ++y)
    for (int x = 0; x < w; ++x) t[y * w + x] = Color();  // black band
  for (int y = 4; y < 6; ++y)
    for (int x = 30; x < 32; ++x) t[y * w + x] = Color(200, 180, 150);  // the sun
  t[0 * w + 3] = Color(5);
  t[19 * w + 7] = Color(5);
  return std::make_shared<ImageTexture>(w, h, std::move(t));
}

// The identity frame puts the map's poles on +-z, so that its texels line up with the cells of
// the chi-square test's (phi, theta) grid: each cell holds 2 x 2 texels.
const Frame kZUp;

}  // namespace

TEST_CASE(
    "ch13: environment sampling follows the map's own pdf (chi-square), which integrates to 1") {
  const EnvironmentLight light(test_map(), Color(1), kZUp);
  chi2::SphericalHistogram hist(10);
  Pcg32 rng(7000);
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const float u0 = rng.next_float();
    const auto s = light.sample_li({}, {u0, rng.next_float()});
    REQUIRE(s);
    REQUIRE(s->pdf == doctest::Approx(light.pdf_li({}, s->wi)).epsilon(1e-3));
    REQUIRE(s->L == light.le(s->wi));
    hist.add(s->wi);
  }
  // The density is constant on each texel's (u, v) rectangle once multiplied by sin(theta),
  // so the midpoint rule on 2 x 2 points per texel is exact.
  std::vector<double> expected =
      hist.expected_midpoint([&](Vec3f w) { return light.pdf_li({}, w); }, 4);
  double total = 0;
  for (double& e : expected) total += e, e *= n;
  CHECK(total == doctest::Approx(1.0).epsilon(1e-4));
  const chi2::Result r = chi2::pearson(hist.counts, expected);
  if (chi2::report_enabled())
    std::printf("ch13 chi2 %-22s %s\n", "environment map", r.summary().c_str());
  CHECK(hist.outside == 0);
  CHECK(r.passed(chi2::sidak_alpha(chi2::kSuiteSignificance, 1)));
}

TEST_CASE("ch13: environment pdf is proportional to radiance per solid angle") {
  const EnvironmentLight light(test_map(), Color(1), kZUp);
  // pdf / luminance is the same in every lit texel away from the poles, up to the ratio of
  // sin(theta) at the texel's centre and at the point.
  double ratio0 = -1;
  for (float v : {0.225f, 0.275f, 0.5f, 0.775f})
    for (float u : {0.1f, 0.5f, 0.76f, 0.9f}) {
      const Vec3f w = light.direction({u, v});
      const float row_centre = (std::floor(v * 20) + 0.5f) / 20;
      const double ratio = light.pdf_li({}, w) / luminance(light.le(w)) * std::sin(kPi * v) /
                           std::sin(kPi * row_centre);
      if (ratio0 < 0) ratio0 = ratio;
      CHECK(ratio == doctest::Approx(ratio0).epsilon(1e-4));
    }
  // The black band is never sampled, and the sun is sampled most.
  CHECK(light.pdf_li({}, light.direction({0.5f, 0.63f})) == 0.0f);
  CHECK(light.pdf_li({}, light.direction({0.76f, 0.25f})) >
        100 * light.pdf_li({}, light.direction({0.5f, 0.5f})));
}

TEST_CASE("ch13: the environment frame rotates the map and coordinates invert directions") {
  // The default frame is y-up: the first row of the map is the +y zenith.
  const EnvironmentLight yup(test_map(), Color(2));
  const Vec3f zenith = yup.direction({0.3f, 0.0f});
  CHECK(zenith.y == doctest::Approx(1.0f));
  CHECK(yup.le({0, 1, 0}) == test_map()->texel(0, 0) * 2.0f);
  const EnvironmentLight zup(test_map(), Color(1), kZUp);
  CHECK(zup.direction({0.3f, 0.0f}).z == doctest::Approx(1.0f));
  for (float u : {0.05f, 0.4f, 0.95f})
    for (float v : {0.1f, 0.5f, 0.9f}) {
      const Vec2f back = yup.coordinates(yup.direction({u, v}));
      CHECK(back.x == doctest::Approx(u).epsilon(1e-4));
      CHECK(back.y == doctest::Approx(v).epsilon(1e-4));
    }
}

TEST_CASE("ch13: Embree 1.1's environment mapping is RTK's mirrored, and interpolated") {
  const EnvironmentLight rtk_map(test_map(), Color(1));
  const EnvironmentLight old(test_map(), Color(1), Frame({1, 0, 0}, {0, 0, 1}, {0, 1, 0}),
                             EnvironmentMapping::embree11);
  Pcg32 rng(11);
  for (int i = 0; i < 200; ++i) {
    const Vec3f w = sample_uniform_sphere({rng.next_float(), rng.next_float()});
    // The same direction mirrored in z (the map's azimuth runs the other way) has RTK's
    // coordinates; and coordinates still invert directions.
    const Vec2f a = old.coordinates(w), b = rtk_map.coordinates({w.x, w.y, -w.z});
    CHECK(a.x == doctest::Approx(b.x).epsilon(1e-4));
    CHECK(a.y == doctest::Approx(b.y).epsilon(1e-4));
    CHECK(length(old.direction(a) - w) < 1e-4f);
  }
  // At a texel centre the texel itself; halfway between two centres of a row, their mean.
  const auto map = test_map();
  const Vec3f centre = old.direction({(10 + 0.5f) / 40, (7 + 0.5f) / 20});
  CHECK(length(Vec3f(old.le(centre).r, old.le(centre).g, old.le(centre).b) -
               Vec3f(map->texel(10, 7).r, map->texel(10, 7).g, map->texel(10, 7).b)) < 1e-4f);
  const Color half = old.le(old.direction({11.0f / 40, (7 + 0.5f) / 20}));
  const Color mean = (map->texel(10, 7) + map->texel(11, 7)) * 0.5f;
  CHECK(half.r == doctest::Approx(mean.r).epsilon(1e-3));
  // Light reaches into the black band's border, and the dilated distribution samples it there.
  const Vec3f edge = old.direction({0.5f, 12.1f / 20});
  CHECK(luminance(old.le(edge)) > 0.0f);
  CHECK(old.pdf_li({}, edge) > 0.0f);
  CHECK(rtk_map.le(rtk_map.direction({0.5f, 12.1f / 20})) == Color());
}

TEST_CASE("ch13: Embree 1.1's interpolated map, light-sampled, integrates to its radiance") {
  // The estimate E[le / pdf] over light samples must equal the radiance integrated over the
  // sphere, found here by a fine midpoint rule: it checks that the dilated distribution covers
  // every direction with light (a gap would lose energy).
  const EnvironmentLight old(test_map(), Color(1), kZUp, EnvironmentMapping::embree11);
  double reference = 0;
  const int nu = 800, nv = 400;
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const float theta = kPi * (j + 0.5f) / nv, phi = 2 * kPi * (i + 0.5f) / nu;
      const Vec3f w{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
      reference += luminance(old.le(w)) * std::sin(theta) * (kPi / nv) * (2 * kPi / nu);
    }
  Pcg32 rng(12);
  double sum = 0;
  const int n = 400000;
  for (int k = 0; k < n; ++k) {
    const auto s = old.sample_li({}, {rng.next_float(), rng.next_float()});
    if (s) sum += luminance(s->L) / s->pdf;
  }
  CHECK(sum / n == doctest::Approx(reference).epsilon(0.02));
}

TEST_CASE("ch13: environment power, black maps and bad input") {
  // A constant map is the ambient light: power 4 pi^2 r^2 L.
  const auto grey = std::make_shared<ImageTexture>(8, 4, std::vector<Color>(32, Color(0.5f)));
  const EnvironmentLight constant(grey, Color(1));
  CHECK(constant.power(2).r == doctest::Approx(4 * kPi * kPi * 4 * 0.5f).epsilon(1e-4));
  // A black map samples uniformly in (u, v) and returns black: no NaN, no crash.
  const auto black = std::make_shared<ImageTexture>(8, 4, std::vector<Color>(32, Color()));
  const EnvironmentLight dark(black, Color(1));
  const auto s = dark.sample_li({}, {0.3f, 0.4f});
  REQUIRE(s);
  CHECK(is_black(s->L));
  CHECK(std::isfinite(s->pdf));
  CHECK(is_black(dark.le({NAN, 0, 1})));
  CHECK(dark.pdf_li({}, {NAN, 0, 1}) == 0.0f);
  CHECK_THROWS_AS(EnvironmentLight(nullptr, Color(1)), std::invalid_argument);
  CHECK_THROWS_AS(
      EnvironmentLight(std::make_shared<ImageTexture>(1, 1, std::vector<Color>{Color(-1)}),
                       Color(1)),
      std::invalid_argument);
}

TEST_CASE("ch13: environment maps load from Radiance HDR files") {
  const std::string path = (std::filesystem::temp_directory_path() / "rtk_ch12_env.hdr").string();
  std::vector<float> data(16 * 8 * 3, 0.25f);
  for (int c = 0; c < 3; ++c) data[(2 * 16 + 5) * 3 + c] = 1000.0f;  // a sun at texel (5, 2)
  REQUIRE(stbi_write_hdr(path.c_str(), 16, 8, 3, data.data()) != 0);
  const EnvironmentLight light(load_environment_image(path), Color(1));
  std::remove(path.c_str());
  const Vec3f sun = light.direction({5.5f / 16, 2.5f / 8});
  CHECK(light.le(sun).r == doctest::Approx(1000.0f).epsilon(0.01));
  // Most samples go to the sun: 1000 sin(theta_2) against 0.25 sin(theta) for 127 texels,
  // 97.6% of the weight.
  int hits = 0;
  Pcg32 rng(7100);
  for (int i = 0; i < 1000; ++i) {
    const auto s = light.sample_li({}, {rng.next_float(), rng.next_float()});
    if (s && s->L.r > 100) ++hits;
  }
  CHECK(hits > 900);
  CHECK_THROWS_AS(load_environment_image("/nonexistent/sky.hdr"), std::runtime_error);
}
