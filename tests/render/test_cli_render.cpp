// `rtk render` end to end: the image file it writes, its refusals and exit codes.
#include <doctest/doctest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "image/image_io.h"
#include "render_test_support.h"
#include "testing/run_program.h"

namespace fs = std::filesystem;

namespace {

using Result = rtk::test::ProgramResult;

Result run_rtk(const std::string& args) { return rtk::test::run_program(RTK_BINARY, args); }

const std::string kCornell = std::string(RTK_SOURCE_DIR) + "/scenes/cornell_box/cornell_box.ecs";

}  // namespace

TEST_CASE("ch13: rtk render writes a PNG of the size asked for") {
  const fs::path out = fs::temp_directory_path() / ("rtk_render_cli_" + std::to_string(getpid()) + ".png");
  const Result r = run_rtk("render -c " + kCornell + " -size 24 16 -spp 2 -threads 2 -o " + out.string());
  INFO(r.output);
  REQUIRE(r.status == 0);
  CHECK(r.output.find("accel") != std::string::npos);
  CHECK(r.output.find("Mrays/s") != std::string::npos);
  const rtk::Image image = rtk::read_image(out.string());
  CHECK(image.width == 24);
  CHECK(image.height == 16);
  double sum = 0;
  for (const auto& c : image.pixels) sum += c.r + c.g + c.b;
  CHECK(sum > 0.0);
  fs::remove(out);
  // The guide's short form, without the command's name.
  const Result s = run_rtk("-c " + kCornell + " -size 8 8 -spp 1 -o " + out.string());
  INFO(s.output);
  CHECK(s.status == 0);
  CHECK(fs::exists(out));
  fs::remove(out);
}

TEST_CASE("ch13: rtk render goes through the device and writes chapter 13's image, bit for bit") {
  // The command hands the script's scene to chapter 14's device, which renders from committed
  // versions; a PFM file keeps the linear floats, so the file must hold exactly the image that
  // chapter 13's renderer makes of the same scene and options in this process.
  const fs::path out = fs::temp_directory_path() / ("rtk_render_device_" + std::to_string(getpid()) + ".pfm");
  const Result r = run_rtk("render -c " + kCornell + " -size 20 14 -spp 3 -seed 5 -threads 2 -o " + out.string());
  INFO(r.output);
  REQUIRE(r.status == 0);
  const rtk::Image file = rtk::read_image(out.string());
  fs::remove(out);
  rtk::SceneScript script = rtk::test::cornell_box();
  rtk::RenderOptions options = script.options;
  options.width = 20, options.height = 14, options.spp = 3, options.seed = 5, options.threads = 1;
  const rtk::Image direct = rtk::test::render_image(script.scene, options);
  REQUIRE(file.pixels.size() == direct.pixels.size());
  size_t differ = 0;
  for (size_t i = 0; i < file.pixels.size(); ++i)
    differ += file.pixels[i].r != direct.pixels[i].r || file.pixels[i].g != direct.pixels[i].g ||
              file.pixels[i].b != direct.pixels[i].b;
  CHECK(differ == 0);
}

TEST_CASE("ch13: rtk render refuses what it cannot do, with exit status 2") {
  const Result no_output = run_rtk("render -c " + kCornell + " -size 8 8");
  CHECK(no_output.status == 2);
  CHECK(no_output.output.find("-o") != std::string::npos);
  const Result bad_ext = run_rtk("render -c " + kCornell + " -o image.gif");
  CHECK(bad_ext.status == 2);
  const Result bad_accel = run_rtk("render -c " + kCornell + " -accel bvh7 -o x.png");
  CHECK(bad_accel.status == 2);
  CHECK(bad_accel.output.find("-accel") != std::string::npos);
  const fs::path script = fs::temp_directory_path() / ("rtk_render_bad_" + std::to_string(getpid()) + ".ecs");
  std::ofstream(script) << "-size 8 8\n-spp two\n";
  const Result bad_line = run_rtk("render -c " + script.string() + " -o x.png");
  CHECK(bad_line.status == 2);
  CHECK(bad_line.output.find(script.filename().string() + ":2:") != std::string::npos);
  fs::remove(script);
  const Result bad_kernels = run_rtk("render -c " + kCornell + " -kernels optix -o x.png");
  CHECK(bad_kernels.status == 2);
  CHECK(bad_kernels.output.find("-kernels: unknown kernels 'optix' (rtk or embree)") != std::string::npos);
#if !RTK_WITH_EMBREE
  // A build without Embree says how to get one, instead of rendering on RTK's kernels unasked.
  const Result no_embree = run_rtk("render -c " + kCornell + " -kernels embree -size 8 8 -o x.png");
  CHECK(no_embree.status == 2);
  CHECK(no_embree.output.find("libembree-dev") != std::string::npos);
#endif
}
