// Chapter 12 tests: the Fresnel equations, refraction, and the GGX distribution.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>

#include "11_sampling/chi_square.h"
#include "11_sampling/rng.h"
#include "12_materials/fresnel.h"
#include "12_materials/microfacet.h"

using namespace rtk;

TEST_CASE("ch12: dielectric Fresnel matches the closed forms at its limits") {
  for (float eta : {1.33f, 1.5f, 2.4f}) {
    const float r0 = (eta - 1) * (eta - 1) / ((eta + 1) * (eta + 1));
    CHECK(fresnel_dielectric(1.0f, eta) == doctest::Approx(r0));
    CHECK(fresnel_dielectric(-1.0f, eta) ==
          doctest::Approx(r0));  // same from inside at normal incidence
    CHECK(fresnel_dielectric(1e-4f, eta) == doctest::Approx(1.0f).epsilon(1e-3));
    // From inside, beyond the critical angle, everything is reflected.
    const float cos_critical = std::sqrt(1.0f - 1.0f / (eta * eta));
    CHECK(fresnel_dielectric(-(cos_critical - 0.01f), eta) == 1.0f);
    CHECK(fresnel_dielectric(-(cos_critical + 0.01f), eta) < 1.0f);
    // Stokes reciprocity: the reflectance is the same for the two directions of a refracted pair.
    for (float cos_i : {0.2f, 0.5f, 0.9f}) {
      const float sin_t = std::sqrt(1 - cos_i * cos_i) / eta, cos_t = std::sqrt(1 - sin_t * sin_t);
      CHECK(fresnel_dielectric(cos_i, eta) ==
            doctest::Approx(fresnel_dielectric(-cos_t, eta)).epsilon(1e-4));
    }
  }
  CHECK(fresnel_dielectric(0.7f, 1.0f) == 0.0f);  // no interface, no reflection
  // Brewster's angle: the parallel polarisation vanishes, leaving half the perpendicular one.
  const float eta = 1.5f, brewster = std::atan(eta);
  const float ci = std::cos(brewster), ct = std::cos(std::asin(std::sin(brewster) / eta));
  const float rs = (ci - eta * ct) / (ci + eta * ct);
  CHECK(fresnel_dielectric(ci, eta) == doctest::Approx(0.5f * rs * rs).epsilon(1e-4));
}

TEST_CASE("ch12: conductor Fresnel reduces to the known cases") {
  // Normal incidence: ((n - 1)^2 + k^2) / ((n + 1)^2 + k^2).
  const float n = 0.19f, k = 3.06f;
  CHECK(fresnel_conductor(1.0f, n, k) ==
        doctest::Approx(((n - 1) * (n - 1) + k * k) / ((n + 1) * (n + 1) + k * k)));
  // With k = 0 it is the dielectric formula.
  for (float c : {0.1f, 0.4f, 0.8f, 1.0f})
    CHECK(fresnel_conductor(c, 1.5f, 0.0f) ==
          doctest::Approx(fresnel_dielectric(c, 1.5f)).epsilon(1e-4));
  // Grazing incidence reflects everything, and all values lie in [0, 1].
  CHECK(fresnel_conductor(1e-5f, n, k) == doctest::Approx(1.0f).epsilon(1e-3));
  for (int i = 0; i <= 100; ++i) {
    const float f = fresnel_conductor(i / 100.0f, n, k);
    CHECK(f >= 0.0f);
    CHECK(f <= 1.0f);
  }
}

TEST_CASE("ch12: refraction obeys Snell's law and can be undone") {
  const Vec3f n{0, 0, 1};
  for (float theta : {0.0f, 0.3f, 0.9f, 1.4f}) {
    const Vec3f w{std::sin(theta) * 0.6f, std::sin(theta) * 0.8f, std::cos(theta)};
    const auto t = refract(w, n, 1.5f);
    REQUIRE(t);
    CHECK(length(*t) == doctest::Approx(1.0f));
    CHECK(t->z < 0.0f);
    const float sin_t = std::sqrt(t->x * t->x + t->y * t->y);
    CHECK(sin_t * 1.5f == doctest::Approx(std::sin(theta)).epsilon(1e-4));
    const auto back = refract(*t, -n, 1.0f / 1.5f);
    REQUIRE(back);
    CHECK(length(*back - w) < 1e-5f);
  }
  // Total internal reflection: no refracted direction.
  CHECK_FALSE(refract(Vec3f{0.8f, 0, 0.6f}, n, 1.0f / 1.5f));
}

namespace {
// Integrates a function of a direction over the upper hemisphere in (cos theta, phi), with a
// finer grid toward the pole where narrow lobes live.
template <class F>
double integrate_hemisphere(const F& f, int n = 800) {
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    // z = 1 - s^2 concentrates samples near the pole; dz = 2 s ds.
    const double s0 = double(i) / n, s1 = double(i + 1) / n, s = 0.5 * (s0 + s1);
    const double z = 1 - s * s, dz = 2 * s * (s1 - s0);
    const int nphi = 64;
    for (int j = 0; j < nphi; ++j) {
      const double phi = 2 * M_PI * (j + 0.5) / nphi, r = std::sqrt(std::max(0.0, 1 - z * z));
      sum += f(Vec3f(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z))) * dz * 2 *
             M_PI / nphi;
    }
  }
  return sum;
}
}  // namespace

TEST_CASE("ch12: GGX normals and visible normals are normalised") {
  // The projected microfacet area is the macro-surface's: integral of D(m) cos(theta_m) = 1.
  // The visible normals' density integrates to 1 only if Smith's Lambda is right.
  for (float alpha : {0.05f, 0.2f, 0.6f, 1.0f}) {
    const GgxDistribution ggx{alpha};
    CHECK(integrate_hemisphere([&](Vec3f m) { return ggx.d(m) * m.z; }) ==
          doctest::Approx(1.0).epsilon(2e-3));
    for (float theta_o : {0.1f, 0.8f, 1.4f}) {
      const Vec3f wo{std::sin(theta_o), 0, std::cos(theta_o)};
      CHECK(integrate_hemisphere([&](Vec3f m) { return ggx.pdf_visible(wo, m); }) ==
            doctest::Approx(1.0).epsilon(2e-3));
      CHECK(ggx.g1(wo) <= 1.0f);
      CHECK(ggx.g1(wo) > 0.0f);
    }
  }
  CHECK(roughness_to_alpha(0.0f) == 0.0f);
  CHECK(roughness_to_alpha(0.005f) == doctest::Approx(std::sqrt(2.0f / 202.0f)));
  CHECK(roughness_to_alpha(0.01f) < roughness_to_alpha(0.1f));
}

TEST_CASE("ch12: visible normals are sampled with their density (chi-square)") {
  const double alpha_level = chi2::sidak_alpha(chi2::kSuiteSignificance, 6);
  int test = 0;
  for (float alpha : {0.1f, 0.5f})
    for (float theta_o : {0.2f, 0.9f, 1.45f}) {
      const GgxDistribution ggx{alpha};
      const Vec3f wo{std::sin(theta_o) * 0.8f, std::sin(theta_o) * 0.6f, std::cos(theta_o)};
      chi2::SphericalHistogram hist(10);
      Pcg32 rng(100 + test++);
      const int n = 100000;
      for (int i = 0; i < n; ++i) {
        const float u0 = rng.next_float();
        hist.add(ggx.sample_visible(wo, {u0, rng.next_float()}));
      }
      std::vector<double> expected = hist.expected([&](Vec3f m) { return ggx.pdf_visible(wo, m); });
      for (double& e : expected) e *= n;
      const chi2::Result r = chi2::pearson(hist.counts, expected);
      if (chi2::report_enabled())
        std::printf("ch12 chi2 GGX VNDF alpha=%.2f theta_o=%.2f  %s\n", alpha, theta_o,
                    r.summary().c_str());
      INFO("alpha ", alpha, " theta_o ", theta_o, ": ", r.summary());
      CHECK(hist.outside == 0);
      CHECK(r.passed(alpha_level));
    }
}
