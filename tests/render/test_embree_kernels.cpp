// The guide's second way to compare: the same renderer on another system's kernels. RTK's path
// tracer on Embree 3 (`-kernels embree`) must render the image it renders on RTK's own kernels:
// nearly pixel for pixel with the same seed, and within the Monte Carlo noise with another.
// Built only where Embree is installed; elsewhere CTest reports the test as skipped.
#include <doctest/doctest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "render_kernels/choose_kernels.h"
#include "render_test_support.h"
#include "testing/run_program.h"

using namespace rtk;

namespace {

Image render_with(const SceneScript& script, const RenderOptions& options, std::string_view which,
                  AccelConfig config = {}) {
  config.threads = options.threads;
  const RenderKernels kernels = make_render_kernels(script.scene, config, which);
  const Renderer renderer(script.scene, *kernels.kernels, options);
  Framebuffer fb(options.width, options.height);
  renderer.render(fb);
  return fb.resolve();
}

RenderOptions small(const SceneScript& script, int size, int spp, uint32_t seed) {
  RenderOptions options = script.options;
  options.width = options.height = size;
  options.spp = spp;
  options.seed = seed;
  options.threads = 2;
  return options;
}

}  // namespace

TEST_CASE("ch14: the same seed on RTK's and Embree's kernels gives nearly the same pixels") {
  // The random numbers depend only on pixel, sample and seed, so the two renders trace the same
  // paths until a hit differs in its last bits (Embree's Möller-Trumbore test rounds
  // differently), which moves a bounce's origin by ulps and, rarely, sends a path down another
  // branch. Pixels may differ slightly, never the picture.
  REQUIRE(embree_kernels_available());
  const SceneScript script = test::cornell_box();
  const RenderOptions options = small(script, 32, 4, 0);
  const Image rtk = render_with(script, options, "rtk");
  const Image embree = render_with(script, options, "embree");
  double sum_rtk = 0, sum_embree = 0;
  size_t differ = 0;
  for (size_t i = 0; i < rtk.pixels.size(); ++i) {
    const float a = luminance(rtk.pixels[i]), b = luminance(embree.pixels[i]);
    sum_rtk += a, sum_embree += b;
    differ += std::fabs(a - b) > 1e-3f * std::max(1.0f, a);
  }
  MESSAGE("pixels differing by more than 1e-3: " << differ << " of " << rtk.pixels.size());
  REQUIRE(sum_rtk > 0.0);
  CHECK(differ <= rtk.pixels.size() / 50);
  CHECK(sum_embree == doctest::Approx(sum_rtk).epsilon(0.005));
}

TEST_CASE("ch14: with independent seeds the two kernels' images agree within the noise") {
  // Each pixel's difference d = rtk - embree has expectation 0 if both kernels find the same
  // surfaces, and the pixels' samplers are independent, so the mean of the P differences has
  // standard error s / sqrt(P) (s their sample standard deviation). A kernel that lost hits
  // (leaks) or found wrong ones would shift the mean; we require |mean| <= 4 s / sqrt(P).
  REQUIRE(embree_kernels_available());
  const SceneScript script = test::cornell_box();
  const Image rtk = render_with(script, small(script, 48, 4, 1), "rtk");
  const Image embree = render_with(script, small(script, 48, 4, 2), "embree");
  const size_t n = rtk.pixels.size();
  double sum = 0, sum_sq = 0;
  for (size_t i = 0; i < n; ++i) {
    const double d = double(luminance(rtk.pixels[i])) - luminance(embree.pixels[i]);
    sum += d, sum_sq += d * d;
  }
  const double mean = sum / n, sd = std::sqrt((sum_sq - n * mean * mean) / (n - 1));
  const double bound = 4 * sd / std::sqrt(double(n));
  MESSAGE("mean difference " << mean << ", bound " << bound);
  CHECK(sd > 0.0);  // independent seeds: the images must differ, or the seeds were not applied
  CHECK(std::fabs(mean) <= bound);
}

TEST_CASE("ch14: -kernels embree refuses what applies only to RTK's kernels") {
  const SceneScript script = test::cornell_box();
  AccelConfig config;
  config.accel = "bvh4";
  CHECK_THROWS_WITH_AS(make_render_kernels(script.scene, config, "embree"),
                       doctest::Contains("-kernels embree"), std::invalid_argument);
  CHECK_THROWS_WITH_AS(make_render_kernels(script.scene, {}, "optix"),
                       doctest::Contains("rtk or embree"), std::invalid_argument);
  SceneScript moving = script;
  moving.scene.vertices_t1 = moving.scene.mesh.vertices;
  CHECK_THROWS_WITH_AS(make_render_kernels(moving.scene, {}, "embree"),
                       doctest::Contains("-kernels rtk"), std::invalid_argument);
}

TEST_CASE("ch14: rtk render -kernels embree writes the image and says which kernels it used") {
  const std::string out = (std::filesystem::temp_directory_path() /
                           ("rtk_render_embree_" + std::to_string(::getpid()) + ".png"))
                              .string();
  const rtk::test::ProgramResult r = rtk::test::run_program(
      RTK_BINARY, std::string("render -c ") + RTK_SOURCE_DIR +
                      "/scenes/cornell_box/cornell_box.ecs -size 16 16 -spp 1 "
                      "-kernels embree -o " +
                      out);
  INFO(r.output);
  CHECK(r.status == 0);
  CHECK(r.output.find("kernels: embree") != std::string::npos);
  std::remove(out.c_str());
}
