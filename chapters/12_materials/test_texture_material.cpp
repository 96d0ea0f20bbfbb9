// Chapter 12 tests: textures (bilinear lookup, wrap modes, files) and materials built from the
// scene files' names and parameters.
#include <doctest/doctest.h>
#include <stb/stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "12_materials/material.h"
#include "12_materials/texture.h"

using namespace rtk;

namespace {
// A 2 x 2 image: top row red, green; bottom row blue, white.
ImageTexture checker(WrapMode wrap) {
  return ImageTexture(2, 2, {Color(1, 0, 0), Color(0, 1, 0), Color(0, 0, 1), Color(1, 1, 1)}, wrap);
}
bool close(Color a, Color b, float eps = 1e-5f) {
  return std::fabs(a.r - b.r) <= eps && std::fabs(a.g - b.g) <= eps && std::fabs(a.b - b.b) <= eps;
}
std::string temp_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("rtk_ch11_" + name)).string();
}
}  // namespace

TEST_CASE("ch12: image textures interpolate bilinearly between texel centres") {
  const ImageTexture t = checker(WrapMode::clamp);
  // Texel centres: (0.25, 0.75) is the top-left texel (v grows upward).
  CHECK(close(t.eval({0.25f, 0.75f}), Color(1, 0, 0)));
  CHECK(close(t.eval({0.75f, 0.75f}), Color(0, 1, 0)));
  CHECK(close(t.eval({0.25f, 0.25f}), Color(0, 0, 1)));
  CHECK(close(t.eval({0.75f, 0.25f}), Color(1, 1, 1)));
  // The middle is the mean of the four; halfway along the top row, the mean of two.
  CHECK(close(t.eval({0.5f, 0.5f}), Color(0.5f, 0.5f, 0.5f)));
  CHECK(close(t.eval({0.5f, 0.75f}), Color(0.5f, 0.5f, 0)));
  // Clamp: beyond the border the border texel stays.
  CHECK(close(t.eval({-3.0f, 0.75f}), Color(1, 0, 0)));
  CHECK(close(t.eval({0.25f, 7.0f}), Color(1, 0, 0)));
}

TEST_CASE("ch12: the repeat mode tiles the plane") {
  const ImageTexture t = checker(WrapMode::repeat);
  for (float u : {0.1f, 0.37f, 0.8f})
    for (float v : {0.05f, 0.5f, 0.93f}) {
      CHECK(close(t.eval({u, v}), t.eval({u + 1, v}), 1e-4f));
      CHECK(close(t.eval({u, v}), t.eval({u - 3, v + 2}), 1e-4f));
    }
  // At u = 0 the left column blends with the right one (across the seam).
  CHECK(close(t.eval({0.0f, 0.75f}), Color(0.5f, 0.5f, 0)));
  // Coordinates that are not numbers do not crash.
  CHECK(is_finite(t.eval({NAN, 0.5f})));
  CHECK(is_finite(t.eval({INFINITY, -INFINITY})));
  CHECK_THROWS_AS(ImageTexture(2, 2, std::vector<Color>(3)), std::invalid_argument);
  CHECK_THROWS_AS(ImageTexture(0, 1, {}), std::invalid_argument);
}

TEST_CASE("ch12: Embree 1.1's conventions: t = 0 is the top row, the nearest texel, 8-bit linear") {
  const TextureConventions old = TextureConventions::embree11();
  const ImageTexture t(2, 2, {Color(1, 0, 0), Color(0, 1, 0), Color(0, 0, 1), Color(1, 1, 1)},
                       WrapMode::repeat, old.lookup, old.origin);
  // (0.25, 0.25) is in the top-left texel now, and every point of a texel gives it unblended.
  for (float du : {-0.24f, 0.0f, 0.24f})
    for (float dv : {-0.24f, 0.0f, 0.24f}) {
      CHECK(close(t.eval({0.25f + du, 0.25f + dv}), Color(1, 0, 0)));
      CHECK(close(t.eval({0.75f + du, 0.25f + dv}), Color(0, 1, 0)));
      CHECK(close(t.eval({0.25f + du, 0.75f + dv}), Color(0, 0, 1)));
      CHECK(close(t.eval({0.75f + du, 0.75f + dv}), Color(1, 1, 1)));
    }
  // Coordinates wrap as before; the bottom origin's nearest lookup keeps v = 0 in the bottom row.
  CHECK(close(t.eval({1.25f, -0.75f}), Color(1, 0, 0)));
  const ImageTexture b(2, 2, {Color(1, 0, 0), Color(0, 1, 0), Color(0, 0, 1), Color(1, 1, 1)},
                       WrapMode::repeat, TextureLookup::nearest, TextureOrigin::bottom);
  CHECK(close(b.eval({0.0f, 0.0f}), Color(0, 0, 1)));
  CHECK(close(b.eval({0.9f, 0.9f}), Color(0, 1, 0)));
  // RTK's are today's conventions; Embree 1.1's read 8-bit values as linear.
  CHECK(TextureConventions{}.encoding == ColorEncoding::srgb);
  CHECK(old.encoding == ColorEncoding::linear);
  CHECK(old.is_embree11());
  CHECK_FALSE(TextureConventions{}.is_embree11());
}

TEST_CASE("ch12: image files load through lib/image's reader, decoded as asked") {
  // A 3 x 2 PNG of known bytes.
  const unsigned char bytes[] = {0,   64,  128, 255, 255, 255, 10,  20,  30,
                                 200, 100, 50,  1,   2,   3,   128, 128, 128};
  const std::string png = temp_path("tex.png");
  REQUIRE(stbi_write_png(png.c_str(), 3, 2, 3, bytes, 9) != 0);
  const auto lin = load_image_texture(png, ColorEncoding::linear, WrapMode::clamp);
  REQUIRE(lin->width() == 3);
  REQUIRE(lin->height() == 2);
  CHECK(close(lin->texel(0, 0), Color(0, 64 / 255.0f, 128 / 255.0f)));
  CHECK(close(lin->texel(2, 1), Color(128 / 255.0f)));
  const auto srgb = load_image_texture(png, ColorEncoding::srgb);
  CHECK(close(srgb->texel(2, 1), Color(srgb_to_linear(128 / 255.0f))));
  // A Radiance HDR file keeps values above 1 (to the 1% of its shared-exponent encoding).
  const float hdr_data[] = {4.0f, 0.5f, 0.25f, 100.0f, 1.0f, 0.0f};
  const std::string hdr = temp_path("tex.hdr");
  REQUIRE(stbi_write_hdr(hdr.c_str(), 2, 1, 3, hdr_data) != 0);
  const auto h = load_image_texture(hdr);
  CHECK(close(h->texel(0, 0), Color(4.0f, 0.5f, 0.25f), 0.02f));
  CHECK(close(h->texel(1, 0), Color(100.0f, 1.0f, 0.0f), 0.5f));
  // A truncated run-length HDR (a hang in stb_image 2.27) is an error naming the file.
  const float wide[3 * 16] = {};
  REQUIRE(stbi_write_hdr(hdr.c_str(), 16, 1, 3, wide) != 0);
  std::filesystem::resize_file(hdr, std::filesystem::file_size(hdr) - 3);
  CHECK_THROWS_WITH_AS(load_image_texture(hdr), doctest::Contains("tex.hdr"), std::runtime_error);
  std::remove(png.c_str());
  std::remove(hdr.c_str());
  // A missing file names itself in the error.
  try {
    load_image_texture(temp_path("does_not_exist.png"));
    FAIL("no exception");
  } catch (const std::runtime_error& e) {
    CHECK(std::string(e.what()).find("does_not_exist.png") != std::string::npos);
  }
}

TEST_CASE("ch12: the sRGB curve") {
  CHECK(srgb_to_linear(0.0f) == 0.0f);
  CHECK(srgb_to_linear(1.0f) == doctest::Approx(1.0f));
  CHECK(srgb_to_linear(0.5f) == doctest::Approx(0.21404f).epsilon(1e-4));
  CHECK(srgb_to_linear(0.04f) == doctest::Approx(0.04f / 12.92f));
}

TEST_CASE("ch12: parameter lists convert what is safe and refuse the rest") {
  ParameterList p;
  p.set("a", 2);
  p.set("b", 0.5f);
  p.set("c", Color(1, 2, 3));
  p.set("d", Vec2f{1, 2});
  p.set("e", std::string("file.png"));
  CHECK(p.get_float("a", 0) == 2.0f);
  CHECK(p.get_color("b", Color()) == Color(0.5f));
  CHECK(p.get_color("c", Color()) == Color(1, 2, 3));
  CHECK(p.get_float2("d", {}) == Vec2f{1, 2});
  CHECK(p.get_float("missing", 7) == 7.0f);
  CHECK(close(p.get_texture("c")->eval({0.3f, 0.3f}), Color(1, 2, 3)));
  CHECK(p.get_texture("missing") == nullptr);
  CHECK(p.unused() == std::vector<std::string>{"e"});
  CHECK_THROWS_AS(p.get_float("c", 0), std::invalid_argument);
  CHECK_THROWS_AS(p.get_color("d", Color()), std::invalid_argument);
  CHECK_THROWS_AS(p.get_texture("e"), std::invalid_argument);
}

TEST_CASE("ch12: materials are built from the Embree scene names") {
  std::vector<std::string> warnings;
  const WarningHandler warn = [&](const std::string& w) { warnings.push_back(w); };
  const Frame frame;
  SUBCASE("Matte and the case of names") {
    ParameterList p;
    p.set("reflectance", Color(0.2f, 0.4f, 0.6f));
    const Material m = make_material("matte", p, warn);
    REQUIRE(std::holds_alternative<Lambertian>(m.prototype));
    CHECK(std::get<Lambertian>(m.prototype).reflectance == Color(0.2f, 0.4f, 0.6f));
    CHECK(warnings.empty());
  }
  SUBCASE("MatteTextured maps its coordinates by s0 and ds") {
    ParameterList p;
    p.set("Kd", std::shared_ptr<const Texture>(
                    std::make_shared<ImageTexture>(checker(WrapMode::repeat))));
    p.set("s0", Vec2f{0.5f, 0.0f});
    p.set("ds", Vec2f{2.0f, 1.0f});
    const Material m = make_material("MatteTextured", p, warn);
    REQUIRE(m.albedo);
    // uv (0, 0.75) -> texture (0.5, 0.75): the top row's midpoint.
    const Bsdf b = m.make_bsdf(frame, {0.0f, 0.75f});
    CHECK(close(std::get<Lambertian>(b.model()).reflectance, Color(0.5f, 0.5f, 0)));
    CHECK(warnings.empty());
  }
  SUBCASE("Metal: polished or rough by its roughness") {
    ParameterList p;
    p.set("eta", Color(0.19f, 0.45f, 1.5f));
    p.set("k", Color(3.06f, 2.4f, 1.88f));
    p.set("roughness", 0.005f);
    const Material rough = make_material("Metal", p, warn);
    REQUIRE(std::holds_alternative<RoughConductor>(rough.prototype));
    CHECK(std::get<RoughConductor>(rough.prototype).ggx.alpha ==
          doctest::Approx(roughness_to_alpha(0.005f)));
    p.set("roughness", 0.0f);
    CHECK(std::holds_alternative<SmoothConductor>(make_material("Metal", p, warn).prototype));
    // Embree 1.1's reflectance colours the metal: every sample's weight scales by it.
    const Material plain = make_material("Metal", p, warn);
    p.set("reflectance", Color(0.5f, 0.25f, 1.0f));
    const Material tinted = make_material("Metal", p, warn);
    const Vec3f wo = normalize(Vec3f{0.3f, 0.2f, 0.9f});
    const auto a = plain.make_bsdf(frame, {}).sample(wo, 0.5f, {0.3f, 0.7f});
    const auto b = tinted.make_bsdf(frame, {}).sample(wo, 0.5f, {0.3f, 0.7f});
    REQUIRE(a);
    REQUIRE(b);
    CHECK(close(b->weight, a->weight * Color(0.5f, 0.25f, 1.0f)));
    p.set("roughness", 0.1f);
    const Material rough_tinted = make_material("Metal", p, warn);
    p.set("reflectance", Color(1.0f));
    const Material rough_plain = make_material("Metal", p, warn);
    const Vec3f wi = normalize(Vec3f{-0.2f, -0.1f, 0.95f});
    CHECK(close(rough_tinted.make_bsdf(frame, {}).eval(wo, wi),
                rough_plain.make_bsdf(frame, {}).eval(wo, wi) * Color(0.5f, 0.25f, 1.0f)));
    CHECK(warnings.empty());
  }
  SUBCASE("Velvet: its parameters, and a texture for its reflectance") {
    ParameterList p;
    p.set("reflectance", Color(0.3f));
    p.set("backScattering", 2.0f);
    p.set("horizonScatteringColor", Color(0.5f, 0.6f, 0.7f));
    p.set("horizonScatteringFallOff", 4.0f);
    const Material m = make_material("Velvet", p, warn);
    REQUIRE(std::holds_alternative<Velvet>(m.prototype));
    const Velvet& v = std::get<Velvet>(m.prototype);
    CHECK(v.reflectance == Color(0.3f));
    CHECK(v.back_scattering == 2.0f);
    CHECK(v.horizon == Color(0.5f, 0.6f, 0.7f));
    CHECK(v.horizon_falloff == 4.0f);
    ParameterList t;
    t.set("reflectance", std::shared_ptr<const Texture>(std::make_shared<ImageTexture>(checker(WrapMode::clamp))));
    const Material textured = make_material("Velvet", t, warn);
    CHECK(close(std::get<Velvet>(textured.make_bsdf(frame, {0.25f, 0.75f}).model()).reflectance, Color(1, 0, 0)));
    CHECK(warnings.empty());
  }
  SUBCASE("Glass and Dielectric take the ratio of the indices") {
    ParameterList p;
    p.set("etaInside", 1.45f);
    p.set("etaOutside", 1.0f);
    p.set("transmission", Color(1, 1, 1));
    const Material m = make_material("glass", p, warn);
    REQUIRE(std::holds_alternative<SmoothDielectric>(m.prototype));
    CHECK(std::get<SmoothDielectric>(m.prototype).eta == doctest::Approx(1.45f));
    CHECK(make_material("Dielectric", p, warn).name == "Dielectric");
    CHECK(std::holds_alternative<ThinDielectric>(
        make_material("ThinDielectric", {}, warn).prototype));
  }
  SUBCASE("Mirror accepts reflectivity (Embree 2.0) and reflectance") {
    ParameterList p;
    p.set("reflectivity", Color(0.5f));
    CHECK(std::get<Mirror>(make_material("mirror", p, warn).prototype).reflectance == Color(0.5f));
  }
  SUBCASE("Plastic and MetallicPaint") {
    ParameterList p;
    p.set("pigmentColor", Color(0.1f, 0.2f, 0.3f));
    p.set("eta", 1.5f);
    p.set("roughness", 0.0f);
    const Material m = make_material("Plastic", p, warn);
    REQUIRE(std::holds_alternative<Plastic>(m.prototype));
    CHECK(std::get<Plastic>(m.prototype).smooth());
    CHECK(warnings.empty());
    ParameterList paint;
    paint.set("eta", 1.45f);
    paint.set("shadeColor", Color(0.5f, 0, 0));
    paint.set("glitterColor", Color(0.5f));
    paint.set("glitterSpread", 0.2f);
    const Material car = make_material("MetallicPaint", paint, warn);
    REQUIRE(std::holds_alternative<MetallicPaint>(car.prototype));
    const MetallicPaint& mp = std::get<MetallicPaint>(car.prototype);
    CHECK(mp.shade == Color(0.5f, 0, 0));
    CHECK(mp.glitter == Color(0.5f));
    CHECK(mp.flakes.alpha == doctest::Approx(roughness_to_alpha(0.2f)));
    CHECK(warnings.empty());  // the glitter is modelled
    paint.set("glitterColor", Color(1.5f));  // more than all the light
    CHECK_THROWS_AS(make_material("MetallicPaint", paint, warn), std::invalid_argument);
  }
  SUBCASE("OBJ: diffuse, specular approximated, emission") {
    ParameterList p;
    p.set("Kd", Color(0.7f));
    p.set("Ks", Color(0.0f));
    p.set("Ns", 1.0f);
    p.set("d", 1.0f);
    const Material diffuse = make_material("OBJ", p, warn);
    CHECK(std::holds_alternative<Lambertian>(diffuse.prototype));
    CHECK(warnings.empty());
    p.set("Ks", Color(0.3f));
    p.set("Ke", Color(5.0f));
    const Material glossy = make_material("OBJ", p, warn);
    CHECK(std::holds_alternative<Plastic>(glossy.prototype));
    CHECK(glossy.is_emissive());
    CHECK(warnings.size() == 1);
    // A texture map supersedes Kd (which is then not reported as unused).
    p.set("map_Kd", std::shared_ptr<const Texture>(
                        std::make_shared<ImageTexture>(checker(WrapMode::repeat))));
    const Material mapped = make_material("OBJ", p, warn);
    CHECK(mapped.albedo);
    CHECK(warnings.size() == 2);  // only the Ks approximation again
  }
  SUBCASE("unknown names and unused parameters are reported, not fatal") {
    ParameterList p;
    p.set("reflectance", Color(0.5f));
    p.set("sheen", 0.3f);
    const Material m = make_material("Velour", p, warn);
    CHECK(std::holds_alternative<Lambertian>(m.prototype));
    REQUIRE(warnings.size() == 3);  // the name, then both parameters
    CHECK(warnings[0].find("Velour") != std::string::npos);
    warnings.clear();
    make_material("Matte", p, warn);
    REQUIRE(warnings.size() == 1);
    CHECK(warnings[0].find("sheen") != std::string::npos);
  }
  SUBCASE("invalid values are errors") {
    ParameterList p;
    p.set("etaInside", -1.0f);
    CHECK_THROWS_AS(make_material("Dielectric", p, warn), std::invalid_argument);
    ParameterList q;
    q.set("reflectance", Color(NAN, 0, 0));
    CHECK_THROWS_AS(make_material("Matte", q, warn), std::invalid_argument);
  }
}

namespace {
// A height field h(u, v) = k u, exact between any two points (no texels).
struct Ramp final : Texture {
  float k;
  explicit Ramp(float slope) : k(slope) {}
  Color eval(Vec2f uv) const override { return Color(k * uv.x); }
};
}  // namespace

TEST_CASE("ch12: bump maps: a constant height changes nothing, a ramp tilts the normal by atan(slope)") {
  const Vec3f n{0, 0, 1}, dpdu{1, 0, 0}, dpdv{0, 1, 0};
  Material m;
  CHECK(m.bumped_normal(n, dpdu, dpdv, {0.3f, 0.4f}) == n);  // no map
  m.bump = std::make_shared<ConstantTexture>(Color(0.7f));
  const Vec3f flat = m.bumped_normal(n, dpdu, dpdv, {0.3f, 0.4f});
  CHECK(flat.x == doctest::Approx(0.0f));
  CHECK(flat.y == doctest::Approx(0.0f));
  CHECK(flat.z == doctest::Approx(1.0f));
  for (float k : {0.1f, 0.5f, 2.0f}) {
    for (float scale : {1.0f, 0.25f}) {
      m.bump = std::make_shared<Ramp>(k);
      m.bump_scale = scale;
      const Vec3f b = m.bumped_normal(n, dpdu, dpdv, {0.3f, 0.4f});
      INFO("slope ", k, " scale ", scale);
      // The surface z = s k x has the normal (-s k, 0, 1) / |.|: tilted by atan(s k) away
      // from the uphill direction.
      CHECK(std::acos(std::clamp(dot(b, n), -1.0f, 1.0f)) == doctest::Approx(std::atan(scale * k)).epsilon(1e-4));
      CHECK(b.x < 0.0f);
      CHECK(b.y == doctest::Approx(0.0f));
      CHECK(length(b) == doctest::Approx(1.0f));
      // Texture u running the other way (-x) mirrors the tilt; the normal stays on n's side.
      const Vec3f mirrored = m.bumped_normal(n, -dpdu, dpdv, {0.3f, 0.4f});
      CHECK(mirrored.x == doctest::Approx(-b.x));
      CHECK(mirrored.z > 0.0f);
    }
  }
  // The same ramp as an image, read bilinearly: the same tilt between texel centres.
  std::vector<Color> texels;
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 8; ++x) texels.push_back(Color(0.5f * (x + 0.5f) / 8.0f));
  m.bump = std::make_shared<ImageTexture>(8, 4, texels, WrapMode::clamp);
  m.bump_scale = 1.0f;
  const Vec3f b = m.bumped_normal(n, dpdu, dpdv, {0.4f, 0.5f});
  CHECK(std::acos(dot(b, n)) == doctest::Approx(std::atan(0.5f)).epsilon(1e-4));
}

TEST_CASE("ch12: opacity: d times the map's value, clamped to [0, 1]") {
  Material m;
  CHECK_FALSE(m.transparent());
  CHECK(m.opacity_at({0.5f, 0.5f}) == 1.0f);
  m.opacity = 0.5f;
  CHECK(m.transparent());
  CHECK(m.opacity_at({0.5f, 0.5f}) == 0.5f);
  m.opacity = 1.0f;
  m.opacity_map = std::make_shared<ImageTexture>(2, 1, std::vector<Color>{Color(1.0f), Color(0.0f)},
                                                 WrapMode::clamp, TextureLookup::nearest);
  CHECK(m.transparent());
  CHECK(m.opacity_at({0.2f, 0.5f}) == 1.0f);
  CHECK(m.opacity_at({0.8f, 0.5f}) == 0.0f);
  ParameterList p;
  p.set("Kd", Color(0.5f));
  p.set("d", 0.25f);
  p.set("map_d", std::shared_ptr<const Texture>(m.opacity_map));
  p.set("map_Bump", std::shared_ptr<const Texture>(m.opacity_map));
  p.set("bump_scale", 0.1f);
  std::vector<std::string> warnings;
  const Material obj = make_material("OBJ", p, [&](const std::string& w) { warnings.push_back(w); });
  CHECK(warnings.empty());
  CHECK(obj.opacity == 0.25f);
  CHECK(obj.opacity_map == m.opacity_map);
  CHECK(obj.bump == m.opacity_map);
  CHECK(obj.bump_scale == 0.1f);
}
