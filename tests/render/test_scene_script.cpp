// The scene files: .ecs command scripts and OBJ/MTL with materials. Valid files load with
// what they say; every kind of malformed line fails with its file and line.
#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <unistd.h>

#include "io/file_error.h"
#include "render_test_support.h"
#include "16_viewer/orbit_camera.h"
#include "scene/obj_scene.h"
#include "scene/scene_script.h"

using namespace rtk;
namespace fs = std::filesystem;

namespace {

struct TempDir {
  fs::path path = fs::temp_directory_path() / ("rtk_render_tests_" + std::to_string(getpid()));
  TempDir() { fs::create_directories(path); }
  ~TempDir() { fs::remove_all(path); }
  fs::path write(const std::string& name, const std::string& text) const {
    std::ofstream(path / name) << text;
    return path / name;
  }
};

const char* kObj =
    "mtllib box.mtl\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
    "vt 0 0\nvt 1 0\nvt 1 1\n"
    "vn 0 0 1\n"
    "usemtl red\n"
    "f 1/1/1 2/2/1 3/3/1 4//1\n"
    "usemtl lamp\n"
    "f 1 3 2\n";
const char* kMtl =
    "newmtl red\nKd 0.8 0.1 0.1\nillum 2\n"
    "newmtl lamp\nKd 0 0 0\nKe 5 5 5\n";

// The FileError of reading `script` (a script file's text), checked for file and line.
void expect_error(const TempDir& dir, const std::string& script, const std::string& file, size_t line,
                  const std::string& words) {
  dir.write("box.obj", kObj);
  dir.write("box.mtl", kMtl);
  const fs::path path = dir.write("bad.ecs", script);
  SceneScript s;
  try {
    read_script_file(path, s);
    FAIL("no error for: " << script);
  } catch (const FileError& e) {
    INFO(std::string(e.what()));
    CHECK(fs::path(e.file()).filename() == file);
    CHECK(e.line() == line);
    CHECK(std::string(e.what()).find(words) != std::string::npos);
  }
}

}  // namespace

TEST_CASE("ch14: a valid script loads geometry, materials, lights, camera and options") {
  TempDir dir;
  dir.write("box.obj", kObj);
  dir.write("box.mtl", kMtl);
  dir.write("view.ecs", "-vp 0 0 -5 # the eye\n-vi 0 0 0\n-fov 45\n");
  const fs::path main = dir.write("main.ecs",
                                  "# a comment line\n"
                                  "-i box.obj\n-c view.ecs\n"
                                  "-quadlight 0 2 0  1 0 0  0 0 1  10 10 10\n"
                                  "-pointlight 0 5 0 100 100 100 -ambientlight 0.1 0.1 0.1\n"
                                  "-size 64 32 -spp 3 -gamma 2.2 -accel bvh4 -seed 9\n"
                                  "-renderer pathtracer { depth = 5 minContribution = 0.01 rrDepth = 2 }\n"
                                  "-o out.png\n");
  SceneScript s;
  std::vector<std::string> warnings;
  read_script_file(main, s, [&](const std::string& w) { warnings.push_back(w); });
  const RenderScene& sc = s.scene;
  CHECK(sc.mesh.size() == 3 + 2);  // a fan of 2 + 1 from the OBJ, 2 from the quad light
  CHECK(sc.normals.size() == sc.mesh.vertices.size());
  CHECK(sc.uvs.size() == sc.mesh.vertices.size());
  CHECK(sc.lights.size() == 1 + 2 + 2);  // the Ke triangle, the quad's two, point, ambient
  CHECK(sc.triangle_light[2] == 0);      // the OBJ's emitting triangle
  CHECK(sc.triangle_light[3] != kNoLight);
  CHECK(sc.camera.position == Vec3f(0, 0, -5));
  CHECK(sc.camera.fov_degrees == 45.0f);
  CHECK(s.options.width == 64);
  CHECK(s.options.height == 32);
  CHECK(s.options.spp == 3);
  CHECK(s.options.max_depth == 5);
  CHECK(s.options.rr_depth == 2);
  CHECK(s.options.seed == 9);
  CHECK(s.tone.gamma == doctest::Approx(2.2));
  CHECK(s.accel.accel == "bvh4");
  REQUIRE(s.output_states.size() == 1);
  CHECK(s.output_states[0].path == dir.path / "out.png");
  sc.validate();
  // Embree 1.1's minContribution and RTK's rrDepth are read, not warned about.
  bool warned = false;
  for (const auto& w : warnings)
    warned |= w.find("minContribution") != std::string::npos || w.find("rrDepth") != std::string::npos;
  CHECK_FALSE(warned);
  CHECK(s.options.min_contribution == doctest::Approx(0.01f));
  // The command line is read by the same parser and overrides the script.
  const std::string_view args[] = {"-spp", "7", "-size", "8", "8"};
  read_script_args(args, s);
  CHECK(s.options.spp == 7);
  CHECK(s.options.width == 8);
}

TEST_CASE("ch14: the Embree 1.1 Cornell box script loads unmodified") {
  const char* root = std::getenv("RTK_SCENES");
  const fs::path path = fs::path(root ? root : "/work/shared/scenes") / "embree_models/v1.1_release_2012/cornell_box.ecs";
  if (!fs::exists(path)) {
    MESSAGE("skipped: " << path << " is absent (set RTK_SCENES)");
    return;
  }
  SceneScript s;
  read_script_file(path, s);
  CHECK(s.scene.mesh.size() > 30);
  CHECK(s.scene.lights.size() == 2);  // the -quadlight
  CHECK(s.options.max_depth == 2);
  s.options.width = s.options.height = 16;
  const Image image = test::render_image(s.scene, s.options);
  double sum = 0;
  for (const Color& c : image.pixels) sum += luminance(c);
  CHECK(sum > 0.0);
}

TEST_CASE("ch14: every kind of malformed script line names its file and line") {
  TempDir dir;
  expect_error(dir, "-vp 0 0 0\n-bogus 1\n", "bad.ecs", 2, "unknown option");
  expect_error(dir, "-size 64\n", "bad.ecs", 1, "missing");
  expect_error(dir, "\n-fov wide\n", "bad.ecs", 2, "not a finite number");
  expect_error(dir, "-spp 0\n", "bad.ecs", 1, "not from 1");
  expect_error(dir, "-renderer pathtracer {\n depth = 2\n", "bad.ecs", 1, "without its '}'");
  expect_error(dir, "-renderer pathtracer { depth 2 }\n", "bad.ecs", 1, "expected '='");
  expect_error(dir, "-renderer raytracer\n", "bad.ecs", 1, "unknown renderer");
  expect_error(dir, "\n\n-i missing.obj\n", "bad.ecs", 3, "cannot open");
  expect_error(dir, "-i scene.stl\n", "bad.ecs", 1, "unknown scene format");
  expect_error(dir, "-c bad.ecs\n", "bad.ecs", 1, "include itself");
  expect_error(dir, "-pointlight 0 0 0 -1 1 1\n", "bad.ecs", 1, ">= 0");
  expect_error(dir, "-isa sse9\n", "bad.ecs", 1, "unknown ISA");
  expect_error(dir, "-motion box.obj\n", "bad.ecs", 1, "must follow");
  // Errors inside the files a script names are reported at their own file and line.
  dir.write("broken.obj", "v 0 0 0\nv 1 0 0\nf 1 2 3\n");
  expect_error(dir, "-i broken.obj\n", "broken.obj", 3, "out of range");
  dir.write("nan.obj", "v 0 0 x\n");
  expect_error(dir, "-i nan.obj\n", "nan.obj", 1, "not a finite number");
  dir.write("badmtl.obj", "mtllib badmtl.mtl\nv 0 0 0\n");
  dir.write("badmtl.mtl", "newmtl a\nKd 1 1\n");
  expect_error(dir, "-i badmtl.obj\n", "badmtl.mtl", 2, "Kd takes 3");
  dir.write("nomtl.obj", "mtllib none.mtl\n");
  expect_error(dir, "-i nomtl.obj\n", "nomtl.obj", 1, "none.mtl");
  dir.write("inner.ecs", "-vp 1 2\n");
  expect_error(dir, "-c inner.ecs\n", "inner.ecs", 1, "missing");
}

TEST_CASE("ch14: OBJ vertices are split by their attributes, primIDs follow the file") {
  TempDir dir;
  dir.write("box.mtl", kMtl);
  const fs::path obj = dir.write("box.obj", kObj);
  RenderScene scene;
  load_obj_scene(obj, scene);
  REQUIRE(scene.mesh.size() == 3);
  // Corners 1, 2 and 3 are used with attributes and without: the last face has its own.
  CHECK(scene.mesh.vertices.size() == 7);
  CHECK(scene.mesh.triangles[2] == std::array<uint32_t, 3>{4, 5, 6});
  CHECK(scene.mesh.triangles[0] == std::array<uint32_t, 3>{0, 1, 2});
  CHECK(scene.mesh.triangles[1] == std::array<uint32_t, 3>{0, 2, 3});
  CHECK(scene.normals[0] == Vec3f(0, 0, 1));
  REQUIRE(scene.normals.size() == 7);
  CHECK(scene.normals[4] == Vec3f(0, 0, 0));  // no normal given: the face's is used
  CHECK(scene.materials[scene.triangle_material[0]].name == "red");
  // The emitting triangle (1, 3, 2) turns clockwise seen from +z: it shines toward -z.
  const auto* light = dynamic_cast<const TriangleLight*>(scene.lights.at(0).get());
  REQUIRE(light != nullptr);
  CHECK(light->normal().z == doctest::Approx(-1.0));
}

TEST_CASE("scene scripts read back the camera the viewer prints (chapter 16's c key)") {
  for (const bool right_handed : {false, true}) {
  OrbitCamera c;
  c.right_handed = right_handed;
  c.eye = {3, 2, -7};
  c.centre = {0.5f, 1, 0.25f};
  c.up = {0.1f, 1, 0.05f};
  c.fov_degrees = 45;
  c.rotate(0.7f, 0.2f);
  c.roll(0.1f);
  c.lens_radius = 0.125f;
  c.focal_distance = 6.3f;
  const std::string text = c.to_ecs_options();
  std::istringstream in(text);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  const std::vector<std::string_view> args(words.begin(), words.end());
  SceneScript script;
  read_script_args(args, script);
  const CameraParams p = script.scene.camera;
  CHECK(p.position == c.eye);
  CHECK(p.look_at == c.centre);
  CHECK(p.up == c.up);
  CHECK(p.fov_degrees == c.fov_degrees);
  CHECK(p.lens_radius == c.lens_radius);
  CHECK(p.focal_distance == c.focal_distance);
  CHECK(p.right_handed == right_handed);
  const OrbitCamera back = OrbitCamera::from_params(p);
  CHECK(back.to_ecs_options() == text);
  }
}

TEST_CASE("scene scripts: every option the reader knows is in -help, and every listed one is read") {
  // The reader's options, taken from its source: each `name == "-x"` it dispatches on.
  std::ifstream in(std::string(RTK_SOURCE_DIR) + "/lib/scene/scene_script.cpp");
  REQUIRE(in);
  const std::string source((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::set<std::string> read;
  for (size_t at = source.find("name == \"-"); at != std::string::npos; at = source.find("name == \"-", at + 1)) {
    const size_t begin = at + 9, end = source.find('"', begin);
    read.insert(source.substr(begin, end - begin));
  }
  std::set<std::string> listed;
  for (const ScriptOptionHelp& o : script_option_help()) {
    CHECK_MESSAGE(!o.meaning.empty(), o.name);
    listed.insert(std::string(o.name));
  }
  CHECK(read.size() > 30);
  for (const std::string& name : read) {
    INFO(name, " is not in -help");
    CHECK(listed.count(name) == 1);
  }
  for (const std::string& name : listed) {
    INFO(name, " is listed but not read");
    CHECK(read.count(name) == 1);
  }
}

TEST_CASE("scene scripts: -righthanded and -lefthanded set the camera's handedness, the last one wins") {
  const auto handed = [](std::vector<std::string_view> args) {
    SceneScript s;
    read_script_args(args, s);
    return s.scene.camera.right_handed;
  };
  CHECK_FALSE(handed({}));  // Embree 1.1's default
  CHECK(handed({"-righthanded"}));
  CHECK(handed({"--righthanded"}));  // Embree 3's spelling
  CHECK_FALSE(handed({"-righthanded", "-lefthanded"}));
  // RTK's own scenes say which they are: the measured Cornell box as the photographs show it.
  SceneScript box = test::cornell_box();
  CHECK(box.scene.camera.right_handed);
}

TEST_CASE("scene scripts: -vignetting 0|1 switches the camera's natural vignetting, without a warning") {
  const auto vignetting = [](std::vector<std::string_view> args) {
    SceneScript s;
    std::vector<std::string> warnings;
    read_script_args(args, s, [&](const std::string& w) { warnings.push_back(w); });
    CHECK(warnings.empty());
    return s.scene.camera.vignetting;
  };
  CHECK_FALSE(vignetting({}));
  CHECK(vignetting({"-vignetting", "1"}));
  CHECK_FALSE(vignetting({"-vignetting", "1", "-vignetting", "0"}));
  SceneScript s;
  const std::vector<std::string_view> two = {"-vignetting", "2"};
  CHECK_THROWS(read_script_args(two, s));
}

TEST_CASE("scene scripts: each -o keeps the state set up before it") {
  TempDir dir;
  const std::string a = (dir.path / "a.png").string(), b = (dir.path / "b.png").string(),
                    c = (dir.path / "c.png").string();
  const std::vector<std::string_view> args = {
      "-trisphere", "0", "0", "0", "1", "4", "6", "-size", "16", "8", "-o", a, "-o", b,
      "-size", "8", "8", "-ambientlight", "1", "1", "1", "-righthanded", "-o", c};
  SceneScript s;
  read_script_args(args, s);
  REQUIRE(s.output_states.size() == 3);
  const ScriptOutput &oa = s.output_states[0], &ob = s.output_states[1], &oc = s.output_states[2];
  CHECK(oa.state == ob.state);  // nothing between them: one image
  CHECK(oc.state != ob.state);
  CHECK(oa.options.width == 16);
  CHECK(oc.options.width == 8);
  CHECK_FALSE(oa.camera.right_handed);
  CHECK(oc.camera.right_handed);
  // The light came after the first two: they keep the scene without it (one copy for both);
  // the last renders the final scene.
  REQUIRE(oa.scene);
  CHECK(oa.scene == ob.scene);
  CHECK(oa.scene->lights.empty());
  CHECK(oa.scene->mesh.size() == s.scene.mesh.size());
  CHECK_FALSE(oc.scene);
  CHECK(s.scene.lights.size() == 1);
  CHECK(s.after_last_output.empty());
  // An option after the last -o changes no image, which is recorded for the warning.
  SceneScript t;
  const std::vector<std::string_view> late = {"-o", a, "-spp", "4"};
  read_script_args(late, t);
  CHECK(t.output_states.at(0).options.spp == 1);
  CHECK(t.after_last_output.find("-spp") != std::string::npos);
}
