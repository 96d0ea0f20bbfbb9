// Chapter 12 tests: sample/eval/pdf agreement, energy conservation, reciprocity, delta lobes,
// and the world-space Bsdf.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "11_sampling/rng.h"
#include "11_sampling/warp.h"
#include "12_materials/bsdf.h"

using namespace rtk;

namespace {

const Color kGoldEta{0.19f, 0.45f, 1.50f}, kGoldK{3.06f, 2.40f, 1.88f};

std::vector<std::pair<std::string, BsdfModel>> all_models() {
  return {
      {"Lambertian", Lambertian{Color(0.9f, 0.5f, 0.1f)}},
      {"Mirror", Mirror{Color(0.9f, 0.8f, 0.7f)}},
      {"SmoothConductor", SmoothConductor{kGoldEta, kGoldK}},
      {"RoughConductor 0.05", RoughConductor{kGoldEta, kGoldK, GgxDistribution{0.05f}}},
      {"RoughConductor 0.3", RoughConductor{kGoldEta, kGoldK, GgxDistribution{0.3f}}},
      {"RoughConductor 0.9", RoughConductor{kGoldEta, kGoldK, GgxDistribution{0.9f}}},
      {"SmoothDielectric", SmoothDielectric{1.5f, Color(1.0f)}},
      {"ThinDielectric", ThinDielectric{1.5f, Color(0.8f, 0.9f, 1.0f), 0.2f}},
      {"Plastic smooth", Plastic{Color(1.0f), 1.5f, GgxDistribution{0.0f}}},
      {"Plastic 0.3", Plastic{Color(1.0f), 1.5f, GgxDistribution{0.3f}}},
      {"Velvet", Velvet{Color(0.5f, 0.3f, 0.2f), 0.5f, Color(0.5f, 0.6f, 0.7f), 10.0f}},
      {"Velvet wide sheen", Velvet{Color(0.2f), 3.0f, Color(0.8f), 1.0f}},
      {"MetallicPaint", MetallicPaint{Color(0.5f, 0.1f, 0.1f), Color(0.4f), 1.45f, GgxDistribution{0.2f}}},
      // All flakes, white: the layer under the coat reflects everything it receives.
      {"MetallicPaint all flakes", MetallicPaint{Color(0.5f), Color(1.0f), 1.5f, GgxDistribution{0.05f}}},
  };
}

Vec3f random_direction(Pcg32& rng) {
  const float u0 = rng.next_float();
  return sample_uniform_sphere({u0, rng.next_float()});
}

template <class F>
auto visit_model(const BsdfModel& m, F&& f) {
  return std::visit(std::forward<F>(f), m);
}

bool close(Color a, Color b, float rel = 1e-3f) {
  for (int i = 0; i < 3; ++i)
    if (std::fabs(a[i] - b[i]) > rel * std::max({std::fabs(a[i]), std::fabs(b[i]), 1e-6f}))
      return false;
  return true;
}

}  // namespace

TEST_CASE("ch12: sample, eval and pdf agree for every model") {
  // For each sample: weight * pdf == f * |cos|; for non-delta samples also f == eval(wo, wi)
  // and pdf == pdf(wo, wi); delta samples are never seen by eval or pdf.
  Pcg32 rng(3000);
  for (const auto& [name, model] : all_models()) {
    INFO(name);
    int checked = 0;
    for (int i = 0; i < 2000; ++i) {
      const Vec3f wo = random_direction(rng);
      const float u_lobe = rng.next_float(), u0 = rng.next_float(), u1 = rng.next_float();
      const auto s = visit_model(model, [&](const auto& m) {
        return m.sample(wo, u_lobe, {u0, u1});
      });
      if (!s) continue;
      ++checked;
      REQUIRE(std::fabs(length(s->wi) - 1.0f) < 1e-4f);
      REQUIRE(s->pdf > 0.0f);
      REQUIRE(is_finite(s->weight));
      CHECK(close(s->weight * s->pdf, s->f * std::fabs(s->wi.z)));
      const Color f = visit_model(model, [&](const auto& m) { return m.eval(wo, s->wi); });
      const float pdf = visit_model(model, [&](const auto& m) { return m.pdf(wo, s->wi); });
      if (!s->delta) {
        CHECK(close(f, s->f));
        CHECK(pdf == doctest::Approx(s->pdf).epsilon(1e-3));
      } else if (is_delta_only(model)) {
        CHECK(is_black(f));
        CHECK(pdf == 0.0f);
      }
    }
    CHECK(checked > 1000);
  }
}

TEST_CASE("ch12: no model reflects more energy than it receives") {
  // Monte Carlo albedo (mean sample weight, absorbed samples counting 0) at several incident
  // angles, below 1 plus five standard errors. For glass, radiance weights are turned back into
  // energy by the factor eta_rel^2 that the radiance scale divided out.
  Pcg32 rng(3100);
  const int n = 20000;
  for (const auto& [name, model] : all_models())
    for (float theta : {0.05f, 0.7f, 1.3f, 1.55f, 2.6f}) {
      const Vec3f wo{std::sin(theta), 0.0f, std::cos(theta)};
      double sum[3] = {0, 0, 0}, sum2[3] = {0, 0, 0};
      for (int i = 0; i < n; ++i) {
        const float u_lobe = rng.next_float(), u0 = rng.next_float(), u1 = rng.next_float();
        const auto s = visit_model(model, [&](const auto& m) {
          return m.sample(wo, u_lobe, {u0, u1});
        });
        if (!s) continue;
        Color w = s->weight;
        if (const auto* g = std::get_if<SmoothDielectric>(&model);
            g && !same_hemisphere(wo, s->wi)) {
          const float eta_rel = wo.z > 0 ? g->eta : 1.0f / g->eta;
          w *= eta_rel * eta_rel;
        }
        for (int c = 0; c < 3; ++c) sum[c] += w[c], sum2[c] += double(w[c]) * w[c];
      }
      for (int c = 0; c < 3; ++c) {
        const double mean = sum[c] / n, var = std::max(0.0, sum2[c] / n - mean * mean);
        INFO(name, " theta ", theta, " channel ", c, " albedo ", mean);
        CHECK(mean <= 1.0 + 5.0 * std::sqrt(var / n) + 1e-4);
      }
    }
}

TEST_CASE("ch12: albedos that are known in closed form") {
  Pcg32 rng(3200);
  const Vec3f wo = normalize(Vec3f{0.3f, 0.2f, 0.7f});
  // Lambertian: every sample's weight is exactly R.
  const Lambertian lambert{Color(0.3f, 0.6f, 0.9f)};
  for (int i = 0; i < 100; ++i) {
    const auto s = lambert.sample(wo, 0, {rng.next_float(), rng.next_float()});
    REQUIRE(s);
    CHECK(close(s->weight, lambert.reflectance, 1e-5f));
  }
  // A polished conductor reflects F(cos); a clear thin sheet reflects and transmits all.
  const auto c = SmoothConductor{kGoldEta, kGoldK}.sample(wo, 0, {});
  REQUIRE(c);
  CHECK(close(c->weight, fresnel_conductor(wo.z, kGoldEta, kGoldK), 1e-5f));
  Color r, t;
  ThinDielectric{1.5f, Color(1.0f), 0.1f}.reflect_transmit(wo.z, r, t);
  CHECK(close(r + t, Color(1.0f), 1e-5f));
  // Glass from outside, every branch: weight 1 on reflection, 1 / eta^2 on refraction.
  const SmoothDielectric glass{1.5f, Color(1.0f)};
  const auto refl = glass.sample(wo, 0.0f, {}), refr = glass.sample(wo, 0.999f, {});
  REQUIRE(refl);
  REQUIRE(refr);
  CHECK(close(refl->weight, Color(1.0f)));
  CHECK(close(refr->weight, Color(1.0f / 2.25f)));
  // White furnace at normal incidence: a rough conductor whose Fresnel term is 1. Visible
  // normals seen head-on follow D(m) cos(theta_m), under which tan^2(theta_m) = alpha^2 u / (1 -
  // u); the reflection leaves the surface only if theta_m < 45 degrees, so exactly alpha^2 / (1 +
  // alpha^2) of the samples are absorbed (GGX's long tail). The albedo is at most the rest, and
  // masking (G2 / G1 < 1) takes a little more.
  for (auto [alpha, lower] : {std::pair{0.2f, 0.97}, std::pair{0.6f, 0.75}}) {
    const RoughConductor white{Color(1.0f), Color(1e4f), GgxDistribution{alpha}};
    REQUIRE(fresnel_conductor(0.5f, 1.0f, 1e4f) == doctest::Approx(1.0f).epsilon(1e-4));
    double sum = 0, absorbed = 0;
    const int n = 50000;
    for (int i = 0; i < n; ++i) {
      const auto s = white.sample(Vec3f{0, 0, 1}, 0, {rng.next_float(), rng.next_float()});
      if (s)
        sum += s->weight.r;
      else
        absorbed += 1;
    }
    const double p_absorbed = alpha * alpha / (1.0 + alpha * alpha);
    CHECK(absorbed / n ==
          doctest::Approx(p_absorbed)
              .epsilon(5.0 * std::sqrt(p_absorbed * (1 - p_absorbed) / n) / p_absorbed));
    CHECK(sum / n <= 1.0 - p_absorbed + 1e-3);
    CHECK(sum / n >= lower * (1.0 - p_absorbed));
  }
}

TEST_CASE("ch12: reflection models are reciprocal and two-sided") {
  Pcg32 rng(3300);
  for (const auto& [name, model] : all_models()) {
    if (is_delta_only(model)) continue;
    INFO(name);
    for (int i = 0; i < 500; ++i) {
      const Vec3f a = random_direction(rng), b = random_direction(rng);
      const Color fab = visit_model(model, [&](const auto& m) { return m.eval(a, b); });
      const Color fba = visit_model(model, [&](const auto& m) { return m.eval(b, a); });
      CHECK(close(fab, fba, 1e-4f));
      // Mirroring both directions through the surface changes nothing.
      const Vec3f fa{a.x, a.y, -a.z}, fb{b.x, b.y, -b.z};
      CHECK(close(fab, visit_model(model, [&](const auto& m) { return m.eval(fa, fb); }), 1e-4f));
      if (!same_hemisphere(a, b)) CHECK(is_black(fab));
    }
  }
}

TEST_CASE("ch12: refraction through glass is reversible and obeys generalised reciprocity") {
  // Radiance that enters and leaves is scaled by 1/eta^2 and then eta^2: the product of the two
  // weights is the square of the transmission colour, whatever the angle.
  const SmoothDielectric glass{1.5f, Color(0.9f)};
  for (float theta : {0.1f, 0.6f, 1.2f}) {
    const Vec3f wo{std::sin(theta), 0.0f, std::cos(theta)};
    const auto in = glass.sample(wo, 0.9999f, {});
    REQUIRE(in);
    REQUIRE(in->wi.z < 0.0f);
    const auto out = glass.sample(in->wi, 0.9999f, {});
    REQUIRE(out);
    CHECK(length(out->wi - wo) < 1e-5f);
    CHECK(close(in->weight * out->weight, Color(0.81f), 1e-4f));
    // Both directions see the same transmittance 1 - F.
    CHECK(in->pdf == doctest::Approx(out->pdf).epsilon(1e-4));
  }
  // Grazing from inside: total internal reflection, always.
  const auto tir = glass.sample(Vec3f{0.9f, 0.0f, -std::sqrt(1 - 0.81f)}, 0.9999f, {});
  REQUIRE(tir);
  CHECK(tir->wi.z < 0.0f);
  CHECK(tir->pdf == 1.0f);
}

TEST_CASE("ch12: degenerate directions give no sample and no NaN") {
  for (const auto& [name, model] : all_models()) {
    INFO(name);
    const Vec3f horizon{1, 0, 0};
    const auto s = visit_model(model, [&](const auto& m) {
      return m.sample(horizon, 0.5f, {0.3f, 0.7f});
    });
    CHECK_FALSE(s);
    const Color f = visit_model(model, [&](const auto& m) {
      return m.eval(horizon, Vec3f{0, 0, 1});
    });
    CHECK(is_finite(f));
  }
  // A microfacet reflection that would go below the surface is absorbed, not flipped.
  const RoughConductor rough{kGoldEta, kGoldK, GgxDistribution{0.9f}};
  int absorbed = 0;
  Pcg32 rng(3400);
  for (int i = 0; i < 1000; ++i)
    if (!rough.sample(normalize(Vec3f{1, 0, 0.05f}), 0, {rng.next_float(), rng.next_float()}))
      ++absorbed;
  CHECK(absorbed > 0);
}

TEST_CASE("ch12: the world-space Bsdf rotates into the shading frame") {
  const Vec3f n = normalize(Vec3f{0.2f, 0.9f, -0.3f});
  const Bsdf bsdf(Frame(n), RoughConductor{kGoldEta, kGoldK, GgxDistribution{0.3f}});
  const Frame frame(n);
  Pcg32 rng(3500);
  for (int i = 0; i < 200; ++i) {
    const Vec3f lo = to_upper(random_direction(rng)), li = to_upper(random_direction(rng));
    const Vec3f wo = frame.to_world(lo), wi = frame.to_world(li);
    const RoughConductor local{kGoldEta, kGoldK, GgxDistribution{0.3f}};
    CHECK(close(bsdf.eval(wo, wi), local.eval(lo, li), 1e-3f));
    CHECK(bsdf.pdf(wo, wi) == doctest::Approx(local.pdf(lo, li)).epsilon(1e-3));
    const auto s = bsdf.sample(wo, 0.5f, {rng.next_float(), rng.next_float()});
    if (s) CHECK(dot(s->wi, n) > 0.0f);
  }
  // A mirror in world space reflects about the normal.
  const Bsdf mirror(Frame(n), Mirror{});
  const Vec3f wo = normalize(Vec3f{0.5f, 0.5f, 0.1f});
  const auto s = mirror.sample(wo, 0, {});
  REQUIRE(s);
  CHECK(length(s->wi - (2 * dot(wo, n) * n - wo)) < 1e-5f);
  CHECK(mirror.delta_only());
  CHECK_FALSE(mirror.transmissive());
  CHECK(Bsdf(Frame(n), ThinDielectric{}).transmissive());
  CHECK_FALSE(Bsdf(Frame(n), Plastic{}).delta_only());
}

TEST_CASE("ch12: MetallicPaint: no glitter is the smooth Plastic; the flakes add a lobe around the mirror direction") {
  Pcg32 rng(3600);
  const Color shade(0.5f, 0.1f, 0.1f);
  const MetallicPaint plain{shade, Color(0.0f), 1.45f, GgxDistribution{0.2f}};
  const Plastic plastic{shade, 1.45f, GgxDistribution{0.0f}};
  for (int i = 0; i < 200; ++i) {
    const Vec3f a = random_direction(rng), b = random_direction(rng);
    CHECK(close(plain.eval(a, b), plastic.eval(a, b), 1e-5f));
    CHECK(plain.pdf(a, b) == doctest::Approx(plastic.pdf(a, b)).epsilon(1e-5));
    CHECK(plain.coat_probability(std::fabs(a.z)) ==
          doctest::Approx(plastic.coat_probability(std::fabs(a.z))).epsilon(1e-5));
  }
  // With flakes, the excess over the pigment's diffuse term is the flakes' GGX lobe: largest
  // for the mirror direction, and exactly glitter D(h) G2 (1 - F_o)(1 - F_i) / (4 cos_o cos_i).
  const Color glitter(0.4f, 0.3f, 0.2f);
  const MetallicPaint paint{shade, glitter, 1.45f, GgxDistribution{0.2f}};
  const Vec3f wo = normalize(Vec3f{0.5f, 0.0f, 1.0f});
  const Vec3f mirror{-wo.x, -wo.y, wo.z};
  const float f_mirror = paint.eval(wo, mirror).r;
  for (float tilt : {0.1f, 0.3f, 0.6f}) {
    const Vec3f off = normalize(Vec3f{mirror.x + tilt, 0.2f * tilt, mirror.z});
    CHECK(paint.eval(wo, off).r < f_mirror);
    const Vec3f h = normalize(wo + off);
    const float t = (1 - fresnel_dielectric(wo.z, 1.45f)) * (1 - fresnel_dielectric(off.z, 1.45f));
    const Color want = ((Color(1.0f) - glitter) * shade * kInvPi +
                        glitter * (paint.flakes.d(h) * paint.flakes.g2(wo, off) / (4 * wo.z * off.z))) * t;
    CHECK(close(paint.eval(wo, off), want, 1e-4f));
  }
}

TEST_CASE("ch12: a model ignores the random numbers it says it does not read") {
  // The path tracer skips the numbers a model does not read (reads_lobe_choice,
  // reads_direction_sample); changing them must then change no sample.
  Pcg32 rng(11);
  for (const auto& [name, model] : all_models()) {
    INFO(name);
    const Bsdf bsdf(Frame(), model);
    for (int i = 0; i < 200; ++i) {
      const Vec3f wo = random_direction(rng);
      const float u_lobe = rng.next_float();
      const Vec2f u{rng.next_float(), rng.next_float()};
      const float other_lobe = reads_lobe_choice(model) ? u_lobe : rng.next_float();
      const Vec2f other_u = reads_direction_sample(model) ? u : Vec2f{rng.next_float(), rng.next_float()};
      const auto a = bsdf.sample(wo, u_lobe, u), b = bsdf.sample(wo, other_lobe, other_u);
      REQUIRE(a.has_value() == b.has_value());
      if (!a) continue;
      CHECK(a->wi == b->wi);
      CHECK(a->weight == b->weight);
      CHECK(a->pdf == b->pdf);
    }
  }
}
