// `rtk render` end to end: the image file it writes, its refusals and exit codes.
#include <doctest/doctest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "image/image_error.h"
#include "image/image_io.h"
#include "io/read_file.h"
#include "render_test_support.h"
#include "testing/run_program.h"

namespace fs = std::filesystem;

namespace {

using Result = rtk::test::ProgramResult;

Result run_rtk(const std::string& args) { return rtk::test::run_program(RTK_BINARY, args); }

const std::string kCornell = std::string(RTK_SOURCE_DIR) + "/scenes/cornell_box/cornell_box.ecs";

}  // namespace

TEST_CASE("ch14: rtk render writes a PNG of the size asked for") {
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

TEST_CASE("ch14: rtk render goes through the device and writes chapter 14's image, bit for bit") {
  // The command hands the script's scene to chapter 15's device, which renders from committed
  // versions; a PFM file keeps the linear floats, so the file must hold exactly the image that
  // chapter 14's renderer makes of the same scene and options in this process.
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

TEST_CASE("ch14: rtk render refuses what it cannot do, with exit status 2") {
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

TEST_CASE("rtk -help lists every option of the scripts, also after -c; -version names the kernels") {
  for (const std::string& args : std::vector<std::string>{"-help", "help", "--help", "render -help",
                                                          "view --help", "-c " + kCornell + " -help"}) {
    const Result r = run_rtk(args);
    INFO(args, r.output);
    CHECK(r.status == 0);
    for (const rtk::ScriptOptionHelp& o : rtk::script_option_help())
      CHECK_MESSAGE(r.output.find("  " + std::string(o.name) + " ") != std::string::npos, o.name);
    CHECK(r.output.find("-screenshot") != std::string::npos);
  }
  // The list of commands comes with the plain -help.
  CHECK(run_rtk("-help").output.find("compare") != std::string::npos);
  for (const char* args : {"-version", "--version", "version"}) {
    const Result v = run_rtk(args);
    INFO(args, v.output);
    CHECK(v.status == 0);
    CHECK(v.output.find("rtk 0.") == 0);
    CHECK(v.output.find("scalar sse4 avx2 avx512") != std::string::npos);
  }
}

namespace {
// How much redder than green the left and the right halves of an image are.
std::pair<double, double> red_minus_green(const rtk::Image& image) {
  double left = 0, right = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const auto& c = image.pixels[size_t(y) * image.width + x];
      (2 * x < image.width ? left : right) += c.r - c.g;
    }
  return {left, right};
}
}  // namespace

TEST_CASE("ch14: the measured Cornell box is right-handed, red on the left; -lefthanded mirrors it") {
  const fs::path out = fs::temp_directory_path() / ("rtk_handed_" + std::to_string(getpid()) + ".pfm");
  // 256 samples per pixel: at 8 the halves' sums still move by a third between the two images.
  const std::string common = "render -c " + kCornell + " -size 16 16 -spp 256 -threads 2 ";
  REQUIRE(run_rtk(common + "-o " + out.string()).status == 0);
  const auto [left, right] = red_minus_green(rtk::read_image(out.string()));
  // The lamp is warm, so both halves lean red; the half with the red wall leans more.
  CHECK(left > right + 1.0);  // the red wall on the left, as in the photographs
  // Embree 1.1's camera, given after the script, overrides it: the mirror image.
  REQUIRE(run_rtk(common + "-lefthanded -o " + out.string()).status == 0);
  const auto [left1, right1] = red_minus_green(rtk::read_image(out.string()));
  CHECK(right1 > left1 + 1.0);
  // The mirror image: each half is the other's, up to the noise of 256 samples.
  CHECK(left1 == doctest::Approx(right).epsilon(0.1));
  CHECK(right1 == doctest::Approx(left).epsilon(0.1));
  fs::remove(out);
}

TEST_CASE("ch14: each -o renders at its position, as in Embree 1.1") {
  const fs::path dir = fs::temp_directory_path() / ("rtk_outputs_" + std::to_string(getpid()));
  fs::create_directories(dir);
  const std::string a = (dir / "a.pfm").string(), b = (dir / "b.ppm").string(), c = (dir / "c.pfm").string();
  const Result r = run_rtk("render -c " + kCornell + " -spp 1 -threads 2 -size 12 8 -o " + a + " -o " + b +
                           " -size 6 4 -o " + c + " -spp 2");
  INFO(r.output);
  REQUIRE(r.status == 0);
  CHECK(rtk::read_image(a).width == 12);
  CHECK(rtk::read_image(b).height == 8);
  CHECK(rtk::read_image(c).width == 6);
  // Two renders for three files: a and b are one image.
  size_t renders = 0;
  for (size_t at = r.output.find("samples/s"); at != std::string::npos; at = r.output.find("samples/s", at + 1))
    ++renders;
  CHECK(renders == 2);
  // The -spp after the last -o changes nothing, and rtk says so.
  CHECK(r.output.find("after the last -o") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("ch14: rtk render writes OpenEXR, and reads it back as an environment map") {
  const fs::path dir = fs::temp_directory_path() / ("rtk_exr_" + std::to_string(getpid()));
  fs::create_directories(dir);
  const std::string exr = (dir / "box.exr").string(), pfm = (dir / "box.pfm").string();
  const Result r = run_rtk("render -c " + kCornell + " -size 12 6 -spp 2 -threads 2 -seed 3 -o " + exr + " -o " + pfm);
  INFO(r.output);
  REQUIRE(r.status == 0);
  // The same floats as the PFM of the same render: both formats keep them exactly.
  CHECK(rtk::read_image(exr).pixels == rtk::read_image(pfm).pixels);
  const Result sky = run_rtk("render -trisphere 0 0 0 1 8 16 -hdrilight 1 1 1 " + exr +
                             " -vp 0 0 -4 -vi 0 0 0 -size 8 8 -spp 2 -o " + (dir / "lit.pfm").string());
  INFO(sky.output);
  CHECK(sky.status == 0);
  double sum = 0;
  for (const auto& c : rtk::read_image((dir / "lit.pfm").string()).pixels) sum += c.r + c.g + c.b;
  CHECK(sum > 0.0);
  fs::remove_all(dir);
}

namespace {
// The number after `key` in the program's output, or -1.
double number_after(const std::string& output, const std::string& key) {
  const size_t at = output.find(key);
  return at == std::string::npos ? -1.0 : std::stod(output.substr(at + key.size()));
}

bool same_pixels(const rtk::Image& a, const rtk::Image& b) {
  if (a.width != b.width || a.height != b.height) return false;
  for (size_t i = 0; i < a.pixels.size(); ++i)
    if (!(a.pixels[i] == b.pixels[i])) return false;
  return true;
}
}  // namespace

TEST_CASE("ch14: rtk render -time renders progressively, and its image is that of the samples it reached") {
  // Whatever the machine's speed, the passes of -time must add up to exactly the image of
  // -spp N, N being the count it reports: the test holds on a slow machine and a fast one.
  const std::string tag = std::to_string(getpid());
  const fs::path timed = fs::temp_directory_path() / ("rtk_time_" + tag + ".pfm");
  const fs::path fixed = fs::temp_directory_path() / ("rtk_time_spp_" + tag + ".pfm");
  const std::string common = "render -c " + kCornell + " -size 12 10 -seed 3 -threads 2 ";
  const Result r = run_rtk(common + "-time 0.25 -o " + timed.string());
  INFO(r.output);
  REQUIRE(r.status == 0);
  const double spp = number_after(r.output, "render: 12x10, ");
  CHECK(r.output.find("spp reached in the time given") != std::string::npos);
  REQUIRE(spp >= 1);
  const Result f = run_rtk(common + "-spp " + std::to_string(static_cast<int>(spp)) + " -o " + fixed.string());
  REQUIRE(f.status == 0);
  CHECK(same_pixels(rtk::read_image(timed.string()), rtk::read_image(fixed.string())));
  fs::remove(timed);
  fs::remove(fixed);
}

TEST_CASE("ch14: rtk render -reference prints the relative RMS error against a converged image") {
  const std::string tag = std::to_string(getpid());
  const fs::path ref = fs::temp_directory_path() / ("rtk_reference_" + tag + ".pfm");
  const fs::path out = fs::temp_directory_path() / ("rtk_reference_out_" + tag + ".pfm");
  const std::string common = "render -c " + kCornell + " -size 16 12 -threads 2 ";
  REQUIRE(run_rtk(common + "-spp 64 -seed 9 -o " + ref.string()).status == 0);
  // The same image has no error; another seed's image has some, less than the image itself;
  // more samples, less error.
  const Result same = run_rtk(common + "-spp 64 -seed 9 -reference " + ref.string() + " -o " + out.string());
  INFO(same.output);
  REQUIRE(same.status == 0);
  CHECK(number_after(same.output, "error: ") == 0.0);
  const Result few = run_rtk(common + "-spp 2 -seed 1 -reference " + ref.string() + " -o " + out.string());
  const Result more = run_rtk(common + "-spp 16 -seed 1 -reference " + ref.string() + " -o " + out.string());
  REQUIRE(few.status == 0);
  REQUIRE(more.status == 0);
  const double e_few = number_after(few.output, "error: "), e_more = number_after(more.output, "error: ");
  CHECK(e_few > 0.0);
  CHECK(e_few < 1.0);
  CHECK(e_more < e_few);
  // The figure is lib/image's, computed on the image the command wrote.
  CHECK(rtk::relative_rms_error(rtk::read_image(out.string()), rtk::read_image(ref.string())) ==
        doctest::Approx(e_more).epsilon(1e-5));

  // What cannot be judged is refused before any work, naming the option. The options come
  // before the -o, which renders what was set up before it.
  auto refused = [&](const std::string& args, const std::string& message) {
    const Result bad = run_rtk(common + args + " -o " + out.string());
    INFO(args, "\n", bad.output);
    CHECK(bad.status == 2);
    CHECK(bad.output.find(message) != std::string::npos);
  };
  refused("-spp 1 -reference " + ref.string() + " -size 8 8", "-reference: " + ref.string() + " is 16 x 12, the render 8 x 8");
  refused("-reference /nonexistent/ref.pfm", "-reference: cannot open");
  refused("-reference " + ref.string() + ".png", "needs a linear image");
  refused("-time -1", "-time");
  refused("-time nan", "-time: 'nan' is not a finite number");
  refused("-time 0", "-time: 0 seconds is not above 0");
  {  // The reference, or an image the scene shows, is not written over: it is kept as it was.
    const std::string ref_bytes = rtk::read_file(ref);
    refused("-spp 1 -reference " + ref.string() + " -o " + ref.string(),
            "-o: " + ref.string() + " is also the image of -reference");
    refused("-spp 1 -backplate " + ref.string() + " -o " + ref.string(),
            "-o: " + ref.string() + " is also a file the scene reads");
    CHECK(rtk::read_file(ref) == ref_bytes);
  }
  {  // -time with nothing after it: the last argument
    const Result bad = run_rtk(common + "-o " + out.string() + " -time");
    INFO(bad.output);
    CHECK(bad.status == 2);
    CHECK(bad.output.find("-time: missing a number of seconds") != std::string::npos);
  }
  const fs::path black = fs::temp_directory_path() / ("rtk_reference_black_" + tag + ".pfm");
  rtk::write_image(black.string(), rtk::Image(16, 12));
  refused("-spp 1 -reference " + black.string(), "the reference is black");
  fs::remove(black);
  fs::remove(ref);
  fs::remove(out);
}
