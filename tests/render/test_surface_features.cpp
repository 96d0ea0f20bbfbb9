// The renderer's surface features beyond the BSDF: OBJ transparency (d and map_d) for camera,
// indirect and shadow rays, the tangents a bump map tilts, and natural vignetting, each
// against its analytic answer.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "13_lights/distant_light.h"
#include "13_lights/point_light.h"
#include "render_test_support.h"

using namespace rtk;

namespace {

uint32_t lambertian(RenderScene& scene, Color reflectance, float opacity = 1.0f) {
  Material m;
  m.prototype = Lambertian{reflectance};
  m.opacity = opacity;
  return scene.add_material(m);
}

// The quad p, p+u, p+u+v, p+v with texture coordinates (0, 0), (1, 0), (1, 1), (0, 1); the
// scene keeps a texture coordinate for every vertex.
void add_textured_quad(RenderScene& scene, Vec3f p, Vec3f u, Vec3f v, uint32_t material) {
  scene.uvs.resize(scene.mesh.vertices.size());
  test::add_quad(scene, p, u, v, material);
  for (Vec2f t : {Vec2f{0, 0}, Vec2f{1, 0}, Vec2f{1, 1}, Vec2f{0, 1}}) scene.uvs.push_back(t);
}

double mean(const Image& image) {
  double sum = 0;
  for (const Color& c : image.pixels) sum += average(c);
  return sum / image.pixels.size();
}

RenderOptions small(int w, int h, int spp, int depth) {
  RenderOptions o;
  o.width = w;
  o.height = h;
  o.spp = spp;
  o.max_depth = depth;
  o.threads = 1;
  return o;
}

}  // namespace

TEST_CASE("ch14: a half-transparent sheet between a light and a floor lets half the light through") {
  // A white floor under a point light; the camera looks at it from below the sheet, so that
  // only shadow rays cross the sheet (black, d = 0.5). Direct light only (depth 1).
  auto scene = [](bool sheet) {
    RenderScene s;
    test::add_quad(s, {-10, 0, -10}, {0, 0, 20}, {20, 0, 0}, lambertian(s, Color(0.8f)));
    if (sheet) test::add_quad(s, {-50, 5, -50}, {0, 0, 100}, {100, 0, 0}, lambertian(s, Color(0.0f), 0.5f));
    s.add_light(std::make_shared<PointLight>(Vec3f{0, 10, 0}, Color(100.0f)));
    s.camera.position = {0, 2, -8};
    s.camera.look_at = {0, 0, 0};
    s.camera.fov_degrees = 30;
    return s;
  };
  const RenderOptions options = small(16, 12, 4, 1);
  const Image open = test::render_image(scene(false), options);
  const Image shaded = test::render_image(scene(true), options);
  CHECK(shaded.pixels.size() == open.pixels.size());
  // The centre sees the floor right under the light: rho / pi * I / r^2 = 0.8 / pi.
  const Color centre = open.pixels[6 * 16 + 8];
  CHECK(centre.g == doctest::Approx(0.8 / kPi).epsilon(0.03));
  // Shadow rays take no random number: every pixel is exactly half.
  for (size_t i = 0; i < open.pixels.size(); ++i) {
    INFO("pixel ", i);
    CHECK(shaded.pixels[i].g == doctest::Approx(0.5f * open.pixels[i].g).epsilon(1e-5));
  }
}

TEST_CASE("ch14: camera rays pass a sheet of opacity d with probability 1 - d") {
  // An emitting wall fills the view behind a black sheet of opacity 0.25.
  auto scene = [](float opacity) {
    RenderScene s;
    std::vector<std::shared_ptr<const TriangleLight>> wall;
    const Vec3f p{-20, -20, 5}, u{40, 0, 0}, v{0, 40, 0};  // emitting toward the camera (-z)
    wall.push_back(std::make_shared<TriangleLight>(p, p + u, p + u + v, Color(1.0f)));
    wall.push_back(std::make_shared<TriangleLight>(p, p + u + v, p + v, Color(1.0f)));
    s.add_area_light(wall, Color(1.0f));
    test::add_quad(s, {-20, -20, 2}, {0, 40, 0}, {40, 0, 0}, lambertian(s, Color(0.0f), opacity));
    s.camera.position = {0, 0, -5};
    s.camera.look_at = {0, 0, 0};
    s.camera.fov_degrees = 30;
    return s;
  };
  const RenderOptions options = small(8, 8, 64, 4);
  CHECK(mean(test::render_image(scene(1.0f), options)) == 0.0);  // opaque: black
  CHECK(mean(test::render_image(scene(0.0f), options)) == doctest::Approx(1.0));  // not there
  // 4096 samples, each 1 with probability 0.75: a standard error of 0.007.
  CHECK(mean(test::render_image(scene(0.25f), options)) == doctest::Approx(0.75).epsilon(0.04));
}

TEST_CASE("ch14: a map_d cut-out renders as the geometry without the cut-out part") {
  // A white card in front of a grey floor under a uniform sky, seen at an angle; the card's
  // right half is cut out by a two-texel opacity map (1, 0), or simply not there.
  auto scene = [](bool cut_out) {
    RenderScene s;
    add_textured_quad(s, {-5, -1, -5}, {0, 0, 10}, {10, 0, 0}, lambertian(s, Color(0.5f)));
    Material card;
    card.prototype = Lambertian{Color(0.9f)};
    if (cut_out) {
      card.opacity_map = std::make_shared<ImageTexture>(2, 1, std::vector<Color>{Color(1.0f), Color(0.0f)},
                                                        WrapMode::clamp, TextureLookup::nearest);
      add_textured_quad(s, {-1, -1, 0}, {2, 0, 1}, {0, 2, 0}, s.add_material(card));
    } else {
      add_textured_quad(s, {-1, -1, 0}, {1, 0, 0.5f}, {0, 2, 0}, s.add_material(card));
    }
    s.add_light(std::make_shared<AmbientLight>(Color(1.0f)));
    s.camera.position = {0.5f, 1.5f, -5};
    s.camera.look_at = {0, 0, 0};
    s.camera.fov_degrees = 40;
    return s;
  };
  const RenderOptions options = small(24, 16, 8, 3);
  const Image cut = test::render_image(scene(true), options);
  const Image half = test::render_image(scene(false), options);
  // The same random numbers meet the same surfaces: equal up to the rounding of hit points
  // found from another origin (a sample that lands on the cut itself may go either way).
  int differ = 0;
  double diff = 0;
  for (size_t i = 0; i < cut.pixels.size(); ++i) {
    const float d = std::fabs(cut.pixels[i].g - half.pixels[i].g);
    diff += d;
    if (d > 1e-3f) ++differ;
  }
  CHECK(differ <= 4);
  CHECK(diff / cut.pixels.size() < 1e-3);
  CHECK(std::fabs(mean(cut) - mean(half)) < 1e-3);
}

TEST_CASE("ch14: texture tangents: how the point moves per unit of u and v") {
  RenderScene s;
  // A quad whose texture is rotated and stretched: u runs along +y, 2 units per unit of u;
  // v along -x, 4 units per unit of v.
  test::add_quad(s, {0, 0, 0}, {4, 0, 0}, {0, 2, 0}, lambertian(s, Color(0.5f)));
  s.uvs = {Vec2f{0, 1}, Vec2f{0, 0}, Vec2f{1, 0}, Vec2f{1, 1}};  // corner p, p+u, p+u+v, p+v
  for (uint32_t prim : {0u, 1u}) {
    Vec3f dpdu, dpdv;
    s.texture_tangents(prim, s.corners(prim, 0.0f), dpdu, dpdv);
    CHECK(dpdu.x == doctest::Approx(0.0f));
    CHECK(dpdu.y == doctest::Approx(2.0f));
    CHECK(dpdv.x == doctest::Approx(-4.0f));
    CHECK(dpdv.y == doctest::Approx(0.0f));
  }
}

TEST_CASE("ch14: vignetting: a uniform sky seen through the camera falls off as cos^4") {
  RenderScene s;
  test::add_quad(s, {-1, -1, -20}, {0, 2, 0}, {2, 0, 0}, lambertian(s, Color(0.5f)));  // behind the camera
  s.add_light(std::make_shared<AmbientLight>(Color(1.0f)));
  s.camera.position = {0, 0, 0};
  s.camera.look_at = {0, 0, 1};
  s.camera.fov_degrees = 90;
  const RenderOptions options = small(16, 16, 16, 1);
  const Image plain = test::render_image(s, options);
  for (const Color& c : plain.pixels) CHECK(c.g == 1.0f);
  s.camera.vignetting = true;
  const Image vignetted = test::render_image(s, options);
  CameraParams params = s.camera;
  const Camera camera(params);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      // The pixel's mean of cos^4 over its area is its centre's value to within 1 %.
      const float want = camera.vignetting({(x + 0.5f) / 16, (y + 0.5f) / 16});
      INFO(x, ", ", y);
      CHECK(vignetted.pixels[size_t(y) * 16 + x].g == doctest::Approx(want).epsilon(0.01));
    }
  // The corner: 45 degrees up and sideways, cos^2 = 1 / (1 + 1 + 1) at the very corner.
  CHECK(camera.vignetting({0.0f, 0.0f}) == doctest::Approx(1.0f / 9.0f));
}
