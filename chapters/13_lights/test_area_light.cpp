// Chapter 13 tests: triangle and quad lights.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "11_sampling/chi_square.h"
#include "11_sampling/rng.h"
#include "11_sampling/warp.h"
#include "13_lights/area_light.h"

using namespace rtk;

namespace {

// The solid angle of triangle (a, b, c) seen from p: Van Oosterom and Strackee, "The Solid
// Angle of a Plane Triangle" (IEEE Trans. Biomed. Eng. 30(2), 1983), in double precision.
double solid_angle(Vec3f p, Vec3f a, Vec3f b, Vec3f c) {
  auto sub = [&](Vec3f v) {
    return std::array<double, 3>{double(v.x) - p.x, double(v.y) - p.y, double(v.z) - p.z};
  };
  const auto r1 = sub(a), r2 = sub(b), r3 = sub(c);
  auto dotd = [](const std::array<double, 3>& u, const std::array<double, 3>& v) {
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
  };
  auto len = [&](const std::array<double, 3>& u) { return std::sqrt(dotd(u, u)); };
  const std::array<double, 3> cr = {r2[1] * r3[2] - r2[2] * r3[1], r2[2] * r3[0] - r2[0] * r3[2],
                                    r2[0] * r3[1] - r2[1] * r3[0]};
  const double num = std::fabs(dotd(r1, cr));
  const double l1 = len(r1), l2 = len(r2), l3 = len(r3);
  const double den = l1 * l2 * l3 + dotd(r1, r2) * l3 + dotd(r1, r3) * l2 + dotd(r2, r3) * l1;
  return 2.0 * std::atan2(num, den);
}

const double kAlpha = chi2::sidak_alpha(chi2::kSuiteSignificance, 1);

}  // namespace

TEST_CASE("ch13: the guide's quad light on the Cornell box ceiling shines down") {
  // -quadlight 213 548.77 227 130 0 0 0 0 105 50 50 50 (Embree 1.1 cornell_box.ecs).
  const auto quad = make_quad_light({213, 548.77f, 227}, {130, 0, 0}, {0, 0, 105}, Color(50));
  REQUIRE(quad.size() == 2);
  for (const auto& t : quad) {
    CHECK(t->normal().y == doctest::Approx(-1.0f));
    CHECK(t->area() == doctest::Approx(0.5f * 130 * 105));
    CHECK(t->emitted({0, -1, 0}) == Color(50));
    CHECK(is_black(t->emitted({0, 1, 0})));
  }
  // From the floor the light is seen; from above the ceiling it is not.
  const LightQuery floor{{278, 0, 279.5f}, {0, 1, 0}};
  const auto s = quad[0]->sample_li(floor, {0.3f, 0.6f});
  REQUIRE(s);
  CHECK(s->wi.y > 0.0f);
  CHECK(s->L == Color(50));
  CHECK_FALSE(quad[1]->sample_li({{278, 600, 279.5f}}, {0.3f, 0.6f}));
  // Power: pi A L for the whole quad.
  CHECK(luminance(quad[0]->power(1) + quad[1]->power(1)) == doctest::Approx(kPi * 130 * 105 * 50));
}

TEST_CASE("ch13: the area light's solid-angle pdf matches the triangle's solid angle") {
  // E[1 / pdf] over uniform area samples is the integral of cos / d^2 over the triangle: the
  // exact solid angle, for any triangle; for a small far triangle 1 / pdf itself is the
  // solid angle to first order.
  Pcg32 rng(6000);
  struct Case {
    Vec3f a, b, c, p;
  };
  const Case cases[] = {
      {{0, 0, 5}, {1, 0, 5}, {0, 1, 5}, {0.2f, 0.1f, 0}},            // medium, facing
      {{-3, -3, 1}, {4, -2, 1.5f}, {0, 5, 0.5f}, {0.3f, -0.2f, 0}},  // large, close, tilted
      {{10, 0, 0}, {10, 0.01f, 0}, {10, 0, 0.01f}, {0, 0, 0}},       // small and far
  };
  for (const Case& c : cases) {
    // Emit toward p whatever the winding.
    TriangleLight light(c.a, c.b, c.c, Color(1));
    if (dot(light.normal(), c.p - c.a) < 0) light = TriangleLight(c.a, c.c, c.b, Color(1));
    const double omega = solid_angle(c.p, c.a, c.b, c.c);
    const int n = 200000;
    double sum = 0, sum2 = 0;
    for (int i = 0; i < n; ++i) {
      const auto s = light.sample_li({c.p}, {rng.next_float(), rng.next_float()});
      REQUIRE(s);
      REQUIRE(light.pdf_li({c.p}, s->wi) == doctest::Approx(s->pdf).epsilon(1e-3));
      const Vec3f point = c.p + s->wi * s->distance;
      REQUIRE(light.pdf_hit(c.p, point) == doctest::Approx(s->pdf).epsilon(1e-3));
      sum += 1.0 / s->pdf, sum2 += 1.0 / (double(s->pdf) * s->pdf);
    }
    const double mean = sum / n, stderr_ = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n);
    INFO("solid angle ", omega, " estimate ", mean, " +- ", stderr_);
    CHECK(std::fabs(mean - omega) <= 5 * stderr_ + 1e-6 * omega);
  }
  const TriangleLight tiny({10, 0, 0}, {10, 0.01f, 0}, {10, 0, 0.01f},
                           Color(1));  // facing the origin
  const auto s = tiny.sample_li({{0, 0, 0}}, {0.5f, 0.5f});
  REQUIRE(s);
  CHECK(1.0 / s->pdf ==
        doctest::Approx(solid_angle({0, 0, 0}, {10, 0, 0}, {10, 0.01f, 0}, {10, 0, 0.01f}))
            .epsilon(2e-3));
}

TEST_CASE("ch13: area light directions follow pdf_li (chi-square)") {
  // A triangle spanning a good part of the sky; the density jumps at its edges, which the
  // adaptive quadrature resolves.
  const TriangleLight light({-2, -1, 1.5f}, {0, 2, 1}, {2, -1, 0.8f}, Color(3));
  const TriangleLight lit = dot(light.normal(), Vec3f{0, 0, -1}) > 0
                                ? light
                                : TriangleLight({-2, -1, 1.5f}, {2, -1, 0.8f}, {0, 2, 1}, Color(3));
  const LightQuery q{{0.1f, 0.2f, 0}, {0, 0, 1}};
  chi2::SphericalHistogram hist(10);
  Pcg32 rng(6100);
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    const float u0 = rng.next_float();
    const auto s = lit.sample_li(q, {u0, rng.next_float()});
    REQUIRE(s);
    hist.add(s->wi);
  }
  std::vector<double> expected = hist.expected([&](Vec3f w) { return lit.pdf_li(q, w); });
  double total = 0;
  for (double& e : expected) total += e, e *= n;
  CHECK(total == doctest::Approx(1.0).epsilon(2e-3));
  const chi2::Result r = chi2::pearson(hist.counts, expected);
  if (chi2::report_enabled())
    std::printf("ch13 chi2 %-22s %s\n", "triangle light", r.summary().c_str());
  CHECK(r.passed(kAlpha));
}

TEST_CASE("ch13: the back of an area light is dark and directions that miss have no density") {
  const TriangleLight light({0, 0, 1}, {1, 0, 1}, {0, 1, 1}, Color(1));
  // normal = cross(v2 - v0, v1 - v0) = cross(y, x) = -z: it shines toward z < 1.
  CHECK(light.normal().z == doctest::Approx(-1.0f));
  CHECK(light.pdf_li({{0.2f, 0.2f, 0}}, {0, 0, 1}) > 0.0f);
  CHECK(light.pdf_li({{0.2f, 0.2f, 2}}, {0, 0, -1}) == 0.0f);  // from behind
  CHECK(light.pdf_li({{0.2f, 0.2f, 0}}, {0, 0, -1}) == 0.0f);  // away from it
  CHECK(light.pdf_li({{5, 5, 0}}, {0, 0, 1}) == 0.0f);         // beside it
  CHECK_FALSE(light.sample_li({{0.2f, 0.2f, 2}}, {0.3f, 0.3f}));
  CHECK_THROWS_AS(TriangleLight({0, 0, 0}, {1, 1, 1}, {2, 2, 2}, Color(1)), std::invalid_argument);
  CHECK_THROWS_AS(TriangleLight({0, 0, 0}, {1, 0, 0}, {0, INFINITY, 0}, Color(1)),
                  std::invalid_argument);
  CHECK_THROWS_AS(TriangleLight({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, Color(NAN)),
                  std::invalid_argument);
}
