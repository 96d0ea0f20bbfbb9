// Chapter 12 tests: every BSDF with a non-delta part samples directions with the density its
// pdf() claims: Pearson's chi-square test over a (phi, theta) grid of 20 x 10 cells, plus
// one cell for samples from a delta lobe and one for absorbed samples, for several incident
// angles and roughnesses (Mitsuba's method; see chapter 11's chi_square.h).
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "11_sampling/chi_square.h"
#include "11_sampling/rng.h"
#include "12_materials/bsdf.h"

using namespace rtk;

namespace {

struct Case {
  std::string name;
  BsdfModel model;
};

// The probability of the delta lobe of a mixed model (a smooth-coated plastic).
double delta_probability(const BsdfModel& model, Vec3f wo) {
  if (const auto* p = std::get_if<Plastic>(&model); p && p->smooth())
    return p->coat_probability(std::fabs(wo.z));
  if (const auto* p = std::get_if<MetallicPaint>(&model))
    return p->coat_probability(std::fabs(wo.z));
  return 0.0;
}

std::vector<Case> cases() {
  const Color gold_eta{0.19f, 0.45f, 1.50f},
      gold_k{3.06f, 2.40f, 1.88f};  // sphere_gold.xml's values
  std::vector<Case> c;
  c.push_back({"Lambertian", Lambertian{Color(0.8f, 0.5f, 0.2f)}});
  for (float alpha : {0.05f, 0.2f, 0.6f})
    c.push_back({"RoughConductor alpha=" + std::to_string(alpha).substr(0, 4),
                 RoughConductor{gold_eta, gold_k, GgxDistribution{alpha}}});
  for (float alpha : {0.1f, 0.4f})
    c.push_back({"Plastic alpha=" + std::to_string(alpha).substr(0, 4),
                 Plastic{Color(0.5f, 0.3f, 0.2f), 1.5f, GgxDistribution{alpha}}});
  c.push_back({"Plastic smooth", Plastic{Color(0.5f, 0.3f, 0.2f), 1.5f, GgxDistribution{0.0f}}});
  c.push_back({"Velvet", Velvet{Color(0.4f), 0.5f, Color(0.6f), 10.0f}});
  for (float alpha : {0.1f, 0.5f})
    c.push_back({"MetallicPaint flakes alpha=" + std::to_string(alpha).substr(0, 4),
                 MetallicPaint{Color(0.5f, 0.0f, 0.0f), Color(0.3f, 0.3f, 0.2f), 1.45f,
                               GgxDistribution{alpha}}});
  return c;
}

constexpr int kAngles = 4;  // three incident angles above the surface, one below
constexpr float kThetas[kAngles] = {0.17f, 0.79f, 1.40f, 2.3f};

}  // namespace

TEST_CASE("ch12: chi-square: sampled BSDF directions follow pdf()") {
  const std::vector<Case> all = cases();
  const double alpha_level =
      chi2::sidak_alpha(chi2::kSuiteSignificance, static_cast<int>(all.size()) * kAngles);
  const int n = 100000;
  uint64_t seed = 1000;
  for (const Case& c : all)
    for (float theta_o : kThetas) {
      const Vec3f wo{std::sin(theta_o) * 0.5f, std::sin(theta_o) * 0.866f, std::cos(theta_o)};
      chi2::SphericalHistogram hist(10);
      double delta = 0, none = 0;
      Pcg32 rng(seed++);
      for (int i = 0; i < n; ++i) {
        const float u_lobe = rng.next_float(), u0 = rng.next_float(), u1 = rng.next_float();
        const auto s = std::visit(
            [&](const auto& m) {
              return m.sample(wo, u_lobe, {u0, u1});
            },
            c.model);
        if (!s)
          none += 1;
        else if (s->delta)
          delta += 1;
        else
          hist.add(s->wi);
      }
      std::vector<double> expected = hist.expected([&](Vec3f wi) {
        return std::visit([&](const auto& m) { return m.pdf(wo, wi); }, c.model);
      });
      double total = 0;
      for (double& e : expected) total += e;
      const double p_delta = delta_probability(c.model, wo);
      // Observed and expected counts, with the two extra cells.
      std::vector<double> observed = hist.counts;
      observed.push_back(delta);
      observed.push_back(none);
      expected.push_back(p_delta);
      expected.push_back(std::max(0.0, 1.0 - total - p_delta));
      for (double& e : expected) e *= n;
      const chi2::Result r = chi2::pearson(observed, expected);
      if (chi2::report_enabled())
        std::printf("ch12 chi2 %-22s theta_o=%.2f  %s  (absorbed %.4f)\n", c.name.c_str(), theta_o,
                    r.summary().c_str(), none / n);
      INFO(c.name, " theta_o ", theta_o, ": ", r.summary());
      CHECK(hist.outside == 0);
      CHECK(r.passed(alpha_level));
    }
}

TEST_CASE("ch12: chi-square: specular lobes are chosen with their probabilities") {
  // Delta-only models: the branch taken (reflection or transmission) must follow the Fresnel
  // probabilities; two cells, one degree of freedom.
  const double alpha_level = chi2::sidak_alpha(chi2::kSuiteSignificance, 6);
  const int n = 100000;
  uint64_t seed = 2000;
  for (float theta_o : {0.3f, 1.2f, 2.0f}) {
    const Vec3f wo{std::sin(theta_o), 0.0f, std::cos(theta_o)};
    for (int which = 0; which < 2; ++which) {
      double p_reflect = 0;
      BsdfModel model;
      if (which == 0) {
        const SmoothDielectric glass{1.5f, Color(1.0f)};
        p_reflect = fresnel_dielectric(wo.z, 1.5f);
        model = glass;
      } else {
        const ThinDielectric sheet{1.5f, Color(0.9f, 0.8f, 0.7f), 0.5f};
        Color r, t;
        sheet.reflect_transmit(std::fabs(wo.z), r, t);
        p_reflect = average(r) / (average(r) + average(t));
        model = sheet;
      }
      Pcg32 rng(seed++);
      double reflected = 0;
      for (int i = 0; i < n; ++i) {
        const float u = rng.next_float();
        const auto s = std::visit(
            [&](const auto& m) {
              return m.sample(wo, u, {0.5f, 0.5f});
            },
            model);
        REQUIRE(s);
        REQUIRE(s->delta);
        if (same_hemisphere(s->wi, wo)) reflected += 1;
      }
      const std::vector<double> observed = {reflected, n - reflected};
      const std::vector<double> expected = {n * p_reflect, n * (1 - p_reflect)};
      const chi2::Result r = chi2::pearson(observed, expected);
      if (chi2::report_enabled())
        std::printf("ch12 chi2 %-22s theta_o=%.2f  %s\n",
                    which == 0 ? "SmoothDielectric" : "ThinDielectric", theta_o,
                    r.summary().c_str());
      CHECK(r.passed(alpha_level));
    }
  }
}
