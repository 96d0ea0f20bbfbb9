// lib/scene on hostile input (issue 15): every character class of a script, every value out
// of its range, nesting and references without end, sizes that overflow. Each is an error
// naming the file and line (or the command-line argument), or, where the input is valid,
// the right result.
#include <doctest/doctest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "io/file_error.h"
#include "io/read_file.h"
#include "scene/mtl_file.h"
#include "scene/scene_limits.h"
#include "scene/scene_script.h"
#include "scene/xml_scene.h"

namespace {

namespace fs = std::filesystem;
using rtk::FileError;

struct Scratch {
  fs::path dir = fs::temp_directory_path() / ("rtk_scene_input_" + std::to_string(::getpid()));
  Scratch() {
    fs::remove_all(dir);
    fs::create_directories(dir);
    rtk::write_file(dir / "tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  }
  ~Scratch() { fs::remove_all(dir); }
  fs::path write(const std::string& name, const std::string& text) const {
    rtk::write_file(dir / name, text);
    return dir / name;
  }
};

// The error of reading a script's text (as if it were the file `name` in the scratch folder).
struct Failure {
  std::string file;
  size_t line = 0;
  std::string what;
};

Failure script_error(const Scratch& s, const std::string& text, rtk::SceneScript* out = nullptr) {
  rtk::SceneScript local;
  rtk::SceneScript& script = out ? *out : local;
  try {
    rtk::read_script_text(text, s.dir / "t.ecs", script);
  } catch (const FileError& e) {
    return {fs::path(e.file()).filename().string(), e.line(), e.what()};
  }
  return {};
}

Failure xml_error(const Scratch& s, const std::string& text, rtk::RenderScene* out = nullptr) {
  rtk::RenderScene local;
  try {
    rtk::read_xml_scene_text(text, s.dir / "t.xml", out ? *out : local);
  } catch (const FileError& e) {
    return {fs::path(e.file()).filename().string(), e.line(), e.what()};
  }
  return {};
}

Failure mtl_error(const Scratch& s, const std::string& text) {
  rtk::RenderScene scene;
  try {
    rtk::read_mtl_text(text, s.dir / "t.mtl", scene);
  } catch (const FileError& e) {
    return {fs::path(e.file()).filename().string(), e.line(), e.what()};
  }
  return {};
}

bool has(const std::string& text, const std::string& words) {
  return text.find(words) != std::string::npos;
}

const std::string kMesh =
    "<TriangleMesh><positions>0 0 0 1 0 0 0 1 0</positions><triangles>0 1 "
    "2</triangles></TriangleMesh>";

std::string xml(const std::string& body) {
  return "<?xml version=\"1.0\"?>\n<scene>\n" + body + "\n</scene>\n";
}

}  // namespace

TEST_CASE(
    "lib_scene: a script's tokens are split at every ASCII white space, after a byte-order mark") {
  Scratch s;
  rtk::SceneScript script;
  // Vertical tab and form feed once made the tokenizer loop, pushing empty tokens forever.
  const Failure f = script_error(s, "\xEF\xBB\xBF-spp\v3\f-depth\t4\r\n-seed 5\v", &script);
  CHECK(f.what.empty());
  CHECK(script.options.spp == 3);
  CHECK(script.options.max_depth == 4);
  CHECK(script.options.seed == 5);
}

TEST_CASE("lib_scene: control bytes and overlong tokens in a script are errors at their line") {
  Scratch s;
  Failure f = script_error(s, std::string("-spp 1\n-depth 2\0\n", 17));
  CHECK(f.line == 2);
  CHECK(has(f.what, "control byte 0x00"));
  f = script_error(s, "-spp 1\n\x1b[31m\n");
  CHECK(f.line == 2);
  CHECK(has(f.what, "0x1B"));
  f = script_error(s, "\n\n-accel " + std::string(10 << 20, 'x'));
  CHECK(f.line == 3);
  CHECK(has(f.what, "10485760 bytes"));
  CHECK(f.what.size() < 300);
  // Unknown options and values are echoed clipped, non-printable bytes escaped.
  f = script_error(s, std::string(1, '-') + std::string(3000, 'y'));
  CHECK(f.what.size() < 300);
  f = script_error(s, "-isa \xff\xfe");
  CHECK(has(f.what, "\\xFF\\xFE"));
}

TEST_CASE("lib_scene: every value of a script is checked for range where it is read") {
  Scratch s;
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"-radius -1", "-radius"},
      {"-fov 0", "-fov"},
      {"-fov 180", "-fov"},
      {"-angle nan", "-angle"},
      {"-fov 1e40", "-fov"},
      {"-vu 0 0 0", "up vector is zero"},
      {"-vd 0 0 0", "view direction"},
      {"-focaldistance -2", "-focaldistance"},
      {"-gamma 0", "-gamma"},
      {"-gamma 1e9", "-gamma"},
      {"-size 32768 32768", "pixels"},
      {"-size 0 5", "-size"},
      {"-spp 0", "-spp"},
      {"-depth -1", "-depth"},
      {"-threads 99999", "-threads"},
      {"-seed -1", "-seed"},
      {"-pointlight 0 0 0 -1 1 1", "-pointlight"},
      {"-ambientlight inf 1 1", "-ambientlight"},
      {"-distantlight 0 1 0 1 1 1 0", "-distantlight"},
      {"-quadlight 0 0 0 1 0 0 2 0 0 1 1 1", "-quadlight"},
      {"-trisphere 0 0 0 -1 8 8", "-trisphere"},
      {"-trisphere 0 0 0 1 4096 4096", "more than"},
      {"-isa vax", "-isa"},
      {"-kernels gpu", "-kernels"},
      {"-renderer pt { spp = 0 }", "spp"},
      {"-vp 1 2", "missing"},
      {"-o missing_folder/x.png", "does not exist"},
      {"-c /dev/zero", "is a device"},
      {"-hdrilight 1 1 1 /dev/zero", "is a device"},
      {"-i /dev/zero", "unknown scene format"}};
  for (const auto& [text, words] : cases) {
    INFO(text);
    const Failure f = script_error(s, "-spp 1\n" + text + "\n");
    CHECK(f.file == "t.ecs");
    CHECK(f.line == 2);
    CHECK(has(f.what, words));
  }
  // The command line's errors name the argument.
  rtk::SceneScript script;
  const std::vector<std::string_view> args = {"-spp", "2", "-radius", "-1"};
  CHECK_THROWS_WITH_AS(rtk::read_script_args(args, script),
                       doctest::Contains("command line, argument 3: -radius"), FileError);
}

TEST_CASE("lib_scene: a number out of range is reported as out of range, a name as unknown") {
  // A number too large for its type is still a number: the message says it is too large (an
  // integer's, the range it should be in) rather than calling 1e40 not a number. An unknown
  // name is reported under the option that was given it.
  Scratch s;
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"-fov 1e40", "-fov: 1e40 is beyond a float's range (3.4e38)"},
      {"-gamma -1e300", "-gamma: -1e300 is beyond a float's range"},
      {"-spp 99999999999999999999", "-spp: 99999999999999999999 is not from 1 to 1048576"},
      {"-seed -99999999999999999999", "-seed: -99999999999999999999 is not from 0 to 4294967295"},
      {"-fov 1e4x", "-fov: '1e4x' is not a finite number"},
      {"-fov 1e40x", "-fov: '1e40x' is not a finite number"},
      {"-spp 9x", "-spp: '9x' is not an integer"},
      {"-sampler halton", "-sampler: unknown sampler 'halton' (supported: independent, sobol)"},
      {"-filter gauss", "-filter: unknown pixel filter 'gauss' (supported: box, tent, bspline)"},
      {"-time 1e-50", "-time: 1e-50 seconds is not above 0"}};  // a float 0, then checked
  for (const auto& [text, message] : cases) {
    INFO(text);
    const Failure f = script_error(s, "-spp 1\n" + text + "\n");
    CHECK(f.line == 2);
    CHECK(has(f.what, message));
  }
  // Too close to 0 for a float: the float's 0. Beyond a double's range, as in OBJ files: an error.
  for (const std::string tiny : {"1e-50", "-1e-50"}) {
    INFO(tiny);
    CHECK(script_error(s, "-pointlight 0 0 0 " + tiny + " 1 1\n").what.empty());
  }
  CHECK(has(script_error(s, "-gamma 1e400\n").what, "-gamma: '1e400' is out of range"));
  CHECK(has(script_error(s, "-gamma 1e-400\n").what, "-gamma: '1e-400' is out of range"));
}

TEST_CASE("lib_scene: options checked after reading carry the place where they were given") {
  Scratch s;
  rtk::SceneScript script;
  CHECK(
      script_error(s, "-vp 1 1 1\n\n-vd 0 0 1\n-accel bvh9\n-isa avx512 -kernels embree\n", &script)
          .what.empty());
  REQUIRE(script.given_at.count("-vi"));  // -vd moves the point of interest
  CHECK(script.given_at.at("-vi").line == 3);
  CHECK(script.given_at.at("-accel").line == 4);
  // The first option the message names wins, else the first given of the list.
  auto fail_with = [&](const std::string& message,
                       std::initializer_list<std::string_view> options) {
    try {
      rtk::at_given_place(script, options, [&]() -> int { throw std::invalid_argument(message); });
    } catch (const FileError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  CHECK(has(fail_with("-accel: 'bvh9' is not available", {"-tri", "-accel"}),
            "t.ecs:4: -accel: 'bvh9'"));
  CHECK(has(fail_with("camera: look-at point equals the camera position", {"-vi", "-vp"}),
            "t.ecs:3: -vi: camera:"));
  CHECK(has(fail_with("-isa: this CPU cannot run 'avx512'", {"-kernels", "-isa", "-accel"}),
            "t.ecs:5: -isa: this CPU"));
  CHECK(has(fail_with("-kernels embree: -accel, -tri and -isa choose RTK's structures",
                      {"-kernels", "-isa", "-accel"}),
            "t.ecs:5: -kernels: -kernels embree:"));
  CHECK_THROWS_AS(
      rtk::at_given_place(script, {"-tri"}, []() -> int { throw std::invalid_argument("x"); }),
      std::invalid_argument);  // never given: the error passes unchanged
}

TEST_CASE(
    "lib_scene: XML nested too deep, by elements or by references, is an error at the element") {
  Scratch s;
  std::string deep;
  for (int i = 0; i < 12000; ++i) deep += "<Group>";
  deep += kMesh;
  for (int i = 0; i < 12000; ++i) deep += "</Group>";
  Failure f = xml_error(s, xml(deep));
  CHECK(f.line == 3);
  CHECK(has(f.what, "nested more than 256 deep"));
  // Just within the limit, it reads.
  std::string ok;
  for (int i = 0; i < rtk::kMaxXmlDepth - 1; ++i) ok += "<Group>";
  ok += kMesh;
  for (int i = 0; i < rtk::kMaxXmlDepth - 1; ++i) ok += "</Group>";
  rtk::RenderScene scene;
  CHECK(xml_error(s, xml(ok), &scene).what.empty());
  CHECK(scene.mesh.size() == 1);
  // A chain of references, one per line: the error is at the element where it goes too deep.
  std::string chain = "<assign type=\"scene\" id=\"s0\">" + kMesh + "</assign>\n";
  for (int i = 1; i <= 1000; ++i)
    chain += "<assign type=\"scene\" id=\"s" + std::to_string(i) + "\"><ref id=\"s" +
             std::to_string(i - 1) + "\"/></assign>\n";
  f = xml_error(s, xml(chain + "<ref id=\"s1000\"/>"));
  CHECK(has(f.what, "nested more than 256 deep"));
  CHECK(f.line > 3);
}

TEST_CASE("lib_scene: references that double at every level stop at the triangle budget") {
  Scratch s;
  std::string body = "<assign type=\"scene\" id=\"s0\">" + kMesh + "</assign>\n";
  for (int i = 1; i <= 40; ++i)
    body += "<assign type=\"scene\" id=\"s" + std::to_string(i) + "\"><Group><ref id=\"s" +
            std::to_string(i - 1) + "\"/><ref id=\"s" + std::to_string(i - 1) +
            "\"/></Group></assign>\n";
  rtk::RenderScene scene;
  const Failure f = xml_error(s, xml(body + "<ref id=\"s40\"/>"), &scene);
  CHECK(has(f.what, "would make more than 1048576 triangles"));
  CHECK(scene.mesh.size() <= rtk::kMaxGeneratedTriangles);
  // A few copies are fine.
  rtk::RenderScene four;
  const std::string two_levels =
      "<assign type=\"scene\" id=\"a\">" + kMesh + "</assign>" +
      "<assign type=\"scene\" id=\"b\"><Group><ref id=\"a\"/><ref id=\"a\"/></Group></assign>" +
      "<ref id=\"b\"/><ref id=\"b\"/>";
  CHECK(xml_error(s, xml(two_levels), &four).what.empty());
  CHECK(four.mesh.size() == 4);
}

TEST_CASE("lib_scene: XML numbers are read strictly, vertices finite after their transforms") {
  Scratch s;
  auto in_transform = [](const std::string& affine) {
    return xml("<Transform>\n<AffineSpace " + affine + "/>\n" + kMesh + "\n</Transform>");
  };
  Failure f = xml_error(s, in_transform("rotate_x=\"abc\""));
  CHECK(f.line == 4);
  CHECK(has(f.what, "<AffineSpace rotate_x>: 'abc' is not a finite number"));
  f = xml_error(s, in_transform("translate=\"1 2 3 junk\""));
  CHECK(has(f.what, "'junk' is not a finite number"));
  f = xml_error(s, in_transform("translate=\"1 2\""));
  CHECK(has(f.what, "needs 3 numbers, has 2"));
  CHECK(xml_error(s, in_transform("scale=\"1e30 1e30 1e30\"")).what.empty());  // 1e30 x 1 is finite
  f = xml_error(
      s,
      xml("<Transform>\n<AffineSpace scale=\"1e30 1e30 1e30\"/>\n"
          "<TriangleMesh>\n<positions>0 0 0 1e30 0 0 0 1 0</positions><triangles>0 1 2</triangles>"
          "</TriangleMesh>\n</Transform>"));
  CHECK(f.line == 6);
  CHECK(has(f.what, "vertex 1 is not finite after the transforms"));
  f = xml_error(s, xml("<HDRILight>\n<AffineSpace scale=\"0 0 0\"/><L>1 1 "
                       "1</L><image>\"sky.hdr\"</image>\n</HDRILight>"));
  CHECK(f.line == 3);
  CHECK(has(f.what, "must be a rotation"));
}

TEST_CASE("lib_scene: binary arrays whose size overflows are refused before anything is read") {
  Scratch s;
  rtk::write_file(s.dir / "t.bin", std::string(48, '\0'));
  const Failure f =
      xml_error(s, xml("<TriangleMesh>\n<positions ofs=\"0\" size=\"4\"/>\n"
                       "<triangles ofs=\"0\" size=\"6148914691236517206\"/>\n</TriangleMesh>"));
  CHECK(f.line == 5);
  INFO(f.what);
  CHECK(has(f.what, "6148914691236517206 elements of 12 bytes"));
  CHECK(has(
      xml_error(s, xml("<TriangleMesh>\n<positions ofs=\"x\" size=\"4\"/>\n</TriangleMesh>")).what,
      "not an integer"));
}

TEST_CASE("lib_scene: a file an XML scene names is reported at the line that names it") {
  Scratch s;
  Failure f = xml_error(s, xml("<Group>\n<obj src=\"missing.obj\"/>\n</Group>"));
  CHECK(f.file == "t.xml");
  CHECK(f.line == 4);
  CHECK(has(f.what, "missing.obj: cannot open"));
  s.write("t.xml", xml("<xml src=\"t.xml\"/>"));
  f = xml_error(s, xml("<xml src=\"t.xml\"/>"));
  CHECK(has(f.what, "nested more than 16 deep"));
  s.write("loop.xml", xml("<xml src=\"loop.xml\"/>"));
  f = xml_error(s, xml("<xml src=\"loop.xml\"/>"));
  CHECK(f.file == "loop.xml");
  // An error inside the included file is at its own line.
  s.write("inner.xml", xml("\n\n<TriangleMesh/>"));
  f = xml_error(s, xml("<xml src=\"inner.xml\"/>"));
  CHECK(f.file == "inner.xml");
  CHECK(f.line == 5);
}

TEST_CASE("lib_scene: MTL values are checked for range at their line") {
  Scratch s;
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"Kd 1e38 1e38 1e38", "Kd: 1e38 is not from 0 to 1"},
      {"Kd 0.5 -0.1 0.5", "Kd: -0.1"},
      {"Ks 2", "Ks: 2"},
      {"Ke nan 1 1", "Ke: 'nan' is not a finite number"},
      {"Ke 1e11 0 0", "Ke: 1e11"},
      {"Ni 1e30", "Ni: 1e30"},
      {"Ns -1", "Ns: -1"},
      {"d 2", "d: 2"},
      {"Tr -0.5", "Tr: -0.5"},
      {"illum 99", "illum: 99 is not from 0 to 10"},
      {"illum 2.5", "illum: '2.5' is not an integer"},
      {"Kd 1 1", "Kd takes 3 numbers"},
      {"map_Kd missing.png", "map_Kd: "},
      {"map_d missing.png", "map_d: "},
      {"map_Bump -bm nan h.pgm", "-bm: 'nan' is not a finite number"},
      {"bump", "map_Bump takes a file name"},
  };
  for (const auto& [line, words] : cases) {
    INFO(line);
    const Failure f = mtl_error(s, "newmtl m\n" + line + "\n");
    CHECK(f.file == "t.mtl");
    CHECK(f.line == 2);
    CHECK(has(f.what, words));
  }
  CHECK(mtl_error(s, "newmtl m\nKd 0.8 0.8 0.8\nKa 20 20 20\nNs 96\nNi 0\nd 1\nillum 2\n")
            .what.empty());
}

TEST_CASE("lib_scene: MTL opacity and bump maps: d, Tr, map_d, map_Bump / bump with -bm") {
  Scratch s;
  // A two-texel grey image: 8-bit values that data maps read as they are (no sRGB curve).
  s.write("h.pgm", std::string("P5\n2 1\n255\n") + std::string(1, '\0') + std::string(1, char(51)));
  s.write("t.mtl",
          "newmtl a\nKd 0.5\nd 0.25\nmap_d h.pgm\nmap_Bump -bm 0.5 h.pgm\n"
          "newmtl b\nKd 0.5\nTr 0.25\nbump h.pgm\n");
  rtk::RenderScene scene;
  std::vector<std::string> warnings;
  const auto names = rtk::load_mtl(s.dir / "t.mtl", scene, [&](const std::string& w) { warnings.push_back(w); });
  for (const std::string& w : warnings) CHECK_MESSAGE(false, w);
  const rtk::Material& a = scene.materials[names.at("a")];
  CHECK(a.opacity == 0.25f);
  REQUIRE(a.opacity_map);
  CHECK(a.opacity_map->eval({0.75f, 0.5f}).r == doctest::Approx(0.2f));  // 51 / 255, linear
  REQUIRE(a.bump);
  CHECK(a.bump_scale == 0.5f);
  const rtk::Material& b = scene.materials[names.at("b")];
  CHECK(b.opacity == 0.75f);  // Tr is 1 - d
  REQUIRE(b.bump);
  CHECK(b.bump_scale == 1.0f);
  // Another texture option is named in a warning, and the map is still read.
  s.write("o.mtl", "newmtl c\nmap_d -clamp on h.pgm\n");
  warnings.clear();
  rtk::RenderScene other;
  const auto c = rtk::load_mtl(s.dir / "o.mtl", other, [&](const std::string& w) { warnings.push_back(w); });
  REQUIRE(warnings.size() == 1);
  CHECK(has(warnings[0], "map_d option '-clamp' is ignored"));
  CHECK(other.materials[c.at("c")].opacity_map);
}
