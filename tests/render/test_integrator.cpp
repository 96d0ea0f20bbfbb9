// The path tracer's answers: the white furnace, thread-count independence, progressive
// passes, and convergence at the Monte Carlo rate.
#include <doctest/doctest.h>

#include <atomic>
#include <cmath>
#include <vector>

#include "13_lights/distant_light.h"
#include "render_test_support.h"

using namespace rtk;

namespace {

RenderScene furnace_scene(bool concave) {
  RenderScene scene;
  const uint32_t white = test::white_material(scene);
  test::add_sphere(scene, {0, 0, 0}, 1.0f, 24, 48, white);
  if (concave) {
    // A floor and two walls around the sphere: light now bounces between surfaces many times.
    test::add_quad(scene, {-3, -1, -3}, {6, 0, 0}, {0, 0, 6}, white);
    test::add_quad(scene, {-3, -1, 3}, {6, 0, 0}, {0, 4, 0}, white);
    test::add_quad(scene, {3, -1, -3}, {0, 0, 6}, {0, 4, 0}, white);
  }
  scene.add_light(std::make_shared<AmbientLight>(Color(1.0f)));
  scene.camera.position = {0, 1.5f, -5};
  scene.camera.look_at = {0, 0, 0};
  scene.camera.fov_degrees = 50;
  return scene;
}

}  // namespace

TEST_CASE("ch14: white furnace, convex: every pixel is exactly 1") {
  // A white Lambertian sphere under a uniform white sky. Light sampling (cosine around the
  // normal) and BSDF sampling (cosine too) have the same density, so each takes MIS weight
  // 1/2 and each estimates exactly 1/2: no noise at all, any error is a bias (a wrong MIS
  // weight, a double-counted light, a lost pi).
  RenderOptions options;
  options.width = options.height = 24;
  options.spp = 2;
  options.max_depth = 8;
  const Image image = test::render_image(furnace_scene(false), options);
  for (const Color& c : image.pixels) {
    REQUIRE(c.r == doctest::Approx(1.0).epsilon(2e-4));
    REQUIRE(c.g == doctest::Approx(1.0).epsilon(2e-4));
  }
}

TEST_CASE("ch14: white furnace, concave: the mean is 1 within the noise") {
  // Surfaces of albedo 1 in a sky of radiance 1 reflect exactly what they receive, so every
  // pixel's expected value is 1, however often light bounces (Russian roulette keeps the
  // estimate unbiased). The noise bound: the P pixels are independent estimates (their
  // samplers are seeded apart), so by the central limit theorem their mean m has standard
  // error s / sqrt(P), with s the pixels' sample standard deviation. We require
  // |m - 1| <= 4 s / sqrt(P) (false alarm 6e-5 for a Gaussian; the seed is fixed anyway),
  // plus 2e-3 for the paths that max_depth = 64 cuts short.
  RenderOptions options;
  options.width = options.height = 32;
  options.spp = 4;
  options.max_depth = 64;
  options.sampler = SamplerType::independent;
  const Image image = test::render_image(furnace_scene(true), options);
  double sum = 0, sum2 = 0;
  for (const Color& c : image.pixels) {
    REQUIRE(std::isfinite(c.g));
    sum += c.g;
    sum2 += double(c.g) * c.g;
  }
  const double n = double(image.pixels.size());
  const double mean = sum / n, sd = std::sqrt(std::max(0.0, (sum2 - n * mean * mean) / (n - 1)));
  const double bound = 4.0 * sd / std::sqrt(n) + 2e-3;
  MESSAGE("furnace mean " << mean << ", pixel sd " << sd << ", bound " << bound);
  CHECK(sd > 0.0);  // the concave scene is noisy: the test measures something
  CHECK(std::fabs(mean - 1.0) <= bound);
}

TEST_CASE("ch14: images are identical for 1 and 2 threads and for split passes") {
  SceneScript script = test::cornell_box();
  RenderOptions options = script.options;
  options.width = 40;
  options.height = 24;  // tiles that do not divide the frame
  options.spp = 4;
  options.seed = 5;
  options.threads = 1;
  const AccelKernels kernels(script.scene, {});
  Framebuffer one(options.width, options.height), two(options.width, options.height),
      passes(options.width, options.height);
  Renderer(script.scene, kernels, options).render(one);
  options.threads = 2;
  const Renderer renderer(script.scene, kernels, options);
  const RenderStats stats = renderer.render(two);
  renderer.render_pass(passes, 0, 1);
  renderer.render_pass(passes, 1, 3);
  const Image a = one.resolve(), b = two.resolve(), c = passes.resolve();
  double total = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    REQUIRE(a.pixels[i] == b.pixels[i]);
    REQUIRE(a.pixels[i] == c.pixels[i]);
    total += luminance(a.pixels[i]);
  }
  CHECK(total > 0.0);
  CHECK(stats.samples == 40u * 24u * 4u);
  CHECK(stats.rays > stats.samples);
  CHECK(stats.kernel_share() > 0.0);
  CHECK(stats.kernel_share() <= 1.0);
  // Another seed gives another image.
  options.seed = 6;
  Framebuffer other(options.width, options.height);
  Renderer(script.scene, kernels, options).render(other);
  CHECK_FALSE(other.resolve().pixels == a.pixels);
}

TEST_CASE("ch14: minContribution ends faint paths: none at 0, the bounced light above every throughput") {
  SceneScript script = test::cornell_box();
  RenderOptions options = script.options;
  options.width = 16;
  options.height = 16;
  options.spp = 4;
  options.threads = 1;
  const AccelKernels kernels(script.scene, {});
  auto render = [&](float min_contribution, int depth) {
    RenderOptions o = options;
    o.min_contribution = min_contribution;
    o.max_depth = depth;
    Framebuffer f(o.width, o.height);
    Renderer(script.scene, kernels, o).render(f);
    return f.resolve();
  };
  auto mean = [](const Image& image) {
    double sum = 0;
    for (const Color& c : image.pixels) sum += luminance(c);
    return sum / double(image.pixels.size());
  };
  const Image full = render(0.0f, 8);
  // A cutoff no throughput of this box falls under before Russian roulette changes nothing.
  CHECK(render(1e-6f, 8).pixels == full.pixels);
  // A cutoff above every throughput ends each path at its first bounce: what is left is the
  // direct light, less than the full image, and more than the emitters alone (depth 0).
  const double cut = mean(render(2.0f, 8));
  CHECK(cut < 0.9 * mean(full));
  CHECK(cut > mean(render(0.0f, 0)));
}

TEST_CASE("ch14: camera rays that meet nothing see the backplate; reflections see the lights") {
  // A white sphere in the middle of a 6 x 4 frame, a backplate of six by four distinct texels
  // looked up nearest, under a uniform sky.
  RenderScene scene;
  test::add_sphere(scene, {0, 0, 0}, 1.5f, 24, 48, test::white_material(scene));
  scene.add_light(std::make_shared<AmbientLight>(Color(1.0f)));
  scene.camera.position = {0, 0, -5};
  scene.camera.look_at = {0, 0, 0};
  scene.camera.fov_degrees = 40;
  std::vector<Color> texels;
  for (int i = 0; i < 24; ++i) texels.push_back(Color(0.1f * (i % 6), 0.2f * (i / 6), 0.5f));
  scene.backplate = std::make_shared<ImageTexture>(6, 4, texels, WrapMode::clamp,
                                                   TextureLookup::nearest, TextureOrigin::bottom);
  RenderOptions options;
  options.width = 6;
  options.height = 4;
  options.spp = 8;
  options.threads = 1;
  const Image image = test::render_image(scene, options);
  // The corners miss the sphere: each pixel is its own texel (the box filter keeps every
  // sample inside its pixel), up to the rounding of the mean of its samples.
  for (int y : {0, 3})
    for (int x : {0, 5}) {
      INFO(x, ", ", y);
      const Color got = image.pixels[size_t(y) * 6 + x], want = texels[size_t(y) * 6 + x];
      CHECK(got.r == doctest::Approx(want.r).epsilon(1e-5));
      CHECK(got.g == doctest::Approx(want.g).epsilon(1e-5));
      CHECK(got.b == doctest::Approx(want.b).epsilon(1e-5));
    }
  // The white sphere under a white sky is white (the furnace), not the backplate's colours.
  const Color centre = image.pixels[1 * 6 + 2];
  CHECK(centre.b > 0.9f);
  CHECK(centre.r > 0.9f);
}

TEST_CASE("ch14: the Cornell box converges like 1/sqrt(spp)") {
  // RMS error against a 128-spp reference (another seed, so that its samples are not the
  // test images' own) at 1, 4 and 16 spp. Independent samples: error ~ spp^-1/2. The
  // reference's own noise adds var/128 to var/spp, which flattens the fitted slope to about
  // -0.48; a bias (a path that never converges) would flatten it far more, and a sampler
  // that repeats samples would stop the error falling.
  SceneScript script = test::cornell_box();
  RenderOptions options = script.options;
  options.width = options.height = 24;
  options.max_depth = 4;
  options.sampler = SamplerType::independent;
  const AccelKernels kernels(script.scene, {});
  auto render = [&](int spp, uint32_t seed) {
    options.spp = spp;
    options.seed = seed;
    Framebuffer fb(options.width, options.height);
    Renderer(script.scene, kernels, options).render(fb);
    return fb.resolve();
  };
  const Image reference = render(128, 1000);
  std::vector<double> x, y;
  for (int spp : {1, 4, 16}) {
    const Image image = render(spp, 7);
    double sum = 0;
    for (size_t i = 0; i < image.pixels.size(); ++i) {
      const Color d = image.pixels[i] - reference.pixels[i];
      sum += (d.r * d.r + d.g * d.g + d.b * d.b) / 3.0;
    }
    x.push_back(std::log(double(spp)));
    y.push_back(std::log(std::sqrt(sum / image.pixels.size())));
  }
  // Least-squares slope of log(rms) against log(spp).
  const double mx = (x[0] + x[1] + x[2]) / 3, my = (y[0] + y[1] + y[2]) / 3;
  double sxy = 0, sxx = 0;
  for (int i = 0; i < 3; ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
  }
  const double slope = sxy / sxx;
  MESSAGE("RMS error slope " << slope);
  CHECK(slope < -0.35);
  CHECK(slope > -0.65);
}

TEST_CASE("ch14: renderer refuses bad options") {
  RenderScene scene = furnace_scene(false);
  const AccelKernels kernels(scene, {});
  RenderOptions bad;
  bad.spp = 0;
  CHECK_THROWS_WITH_AS(Renderer(scene, kernels, bad), doctest::Contains("-spp"), std::invalid_argument);
  bad = {};
  bad.width = 0;
  CHECK_THROWS_WITH_AS(Renderer(scene, kernels, bad), doctest::Contains("-size"), std::invalid_argument);
  bad = {};
  scene.camera.look_at = scene.camera.position;
  CHECK_THROWS_AS(Renderer(scene, kernels, bad), std::invalid_argument);
  scene = furnace_scene(false);
  scene.triangle_material[0] = 99;
  CHECK_THROWS_WITH_AS(Renderer(scene, kernels, bad), doctest::Contains("material"), std::invalid_argument);
}

namespace {

// Kernels that ask the render to stop at their first closest-hit batch: the tile under way is
// finished, the others are skipped. The Tracer's structure is this object, whose kernels raise
// the flag and pass the rays on to the real ones.
class StoppingKernels : public RayKernels {
 public:
  StoppingKernels(const RayKernels& inner, std::atomic<bool>& stop)
      : inner_(inner.tracer()), stop_(stop), name_(inner.name()) {}
  Tracer tracer() const override {
    Tracer t;
    t.structure = this;
    t.kernels.intersect = [](const void* self, std::span<const Ray> rays, std::span<Hit> hits) {
      const auto& k = *static_cast<const StoppingKernels*>(self);
      k.stop_ = true;
      k.inner_.intersect(rays, hits);
    };
    t.kernels.occluded = [](const void* self, std::span<const Ray> rays,
                            std::span<uint8_t> occluded) {
      static_cast<const StoppingKernels*>(self)->inner_.occluded(rays, occluded);
    };
    return t;
  }
  std::string name() const override { return name_; }

 private:
  Tracer inner_;
  std::atomic<bool>& stop_;
  std::string name_;
};

}  // namespace

TEST_CASE(
    "ch14: a stop request ends the render at the next tile, keeping every finished tile whole") {
  const RenderScene scene = furnace_scene(false);
  const AccelKernels kernels(scene, {});
  RenderOptions options;
  options.width = 64, options.height = 32, options.spp = 2, options.threads = 1;
  std::atomic<bool> stop{false};
  options.stop = &stop;
  // Not asked: every tile.
  Framebuffer full(64, 32);
  const RenderStats all = Renderer(scene, kernels, options).render(full);
  CHECK(all.tiles == 8);
  CHECK(all.tiles_done == 8);
  CHECK(!all.stopped());
  // Asked before the start: nothing is rendered.
  stop = true;
  Framebuffer none(64, 32);
  const RenderStats nothing = Renderer(scene, kernels, options).render(none);
  CHECK(nothing.tiles_done == 0);
  CHECK(nothing.stopped());
  CHECK(none.weight(0, 0) == 0.0f);
  // Asked during the first tile (one thread): that tile is finished with all its samples and
  // equal to the full render's, the others stay empty.
  stop = false;
  const StoppingKernels stopping(kernels, stop);
  Framebuffer part(64, 32);
  const RenderStats some = Renderer(scene, stopping, options).render(part);
  CHECK(some.tiles_done == 1);
  CHECK(some.stopped());
  int whole = 0, empty = 0;
  const Image a = part.resolve(), b = full.resolve();
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 64; ++x) {
      if (part.weight(x, y) == 2.0f && a.at(x, y) == b.at(x, y)) ++whole;
      if (part.weight(x, y) == 0.0f) ++empty;
    }
  CHECK(whole == 16 * 16);
  CHECK(empty == 64 * 32 - 16 * 16);
}

TEST_CASE("ch14: every ISA's kernels render the image the scalar kernels render") {
  // The same layout and intersector in every variant: the random numbers depend only on the
  // pixel and sample, so paths differ only where a hit differs in its last bits, which moves
  // a bounce's origin by ulps. Pixels may then differ slightly, never the picture.
  SceneScript script = test::cornell_box();
  RenderOptions options = script.options;
  options.width = options.height = 24;
  options.spp = 2;
  AccelConfig config;
  config.accel = "bvh4";
  config.tri = "triangle4.moeller";
  config.isa = Isa::scalar;
  const Image scalar = test::render_image(script.scene, options, config);
  double scalar_sum = 0;
  for (const Color& c : scalar.pixels) scalar_sum += luminance(c);
  REQUIRE(scalar_sum > 0.0);
  for (Isa isa : supported_isas()) {
    if (isa == Isa::scalar) continue;
    CAPTURE(isa_name(isa));
    config.isa = isa;
    const Image image = test::render_image(script.scene, options, config);
    double sum = 0;
    size_t differ = 0;
    for (size_t i = 0; i < image.pixels.size(); ++i) {
      sum += luminance(image.pixels[i]);
      const float a = luminance(image.pixels[i]), b = luminance(scalar.pixels[i]);
      differ += std::fabs(a - b) > 1e-3f * std::max(1.0f, b);
    }
    CHECK(differ <= image.pixels.size() / 50);
    CHECK(sum == doctest::Approx(scalar_sum).epsilon(0.005));
  }
}
