// lib/scene's XML reader: small inline files (valid and malformed) and, where
// /work/shared/scenes is present, the real Embree scene files.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "io/file_error.h"
#include "scene/scene_script.h"
#include "scene/xml_scene.h"

namespace {

namespace fs = std::filesystem;

// A scratch folder per test case and process (builds of the same sources may run this test
// at the same time), with helpers to write files into it.
struct Scratch {
  fs::path dir;
  explicit Scratch(const std::string& name)
      : dir(fs::temp_directory_path() / ("rtk_xml_" + name + "_" + std::to_string(::getpid()))) {
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  ~Scratch() { fs::remove_all(dir); }
  fs::path write(const std::string& file, const std::string& text) const {
    std::ofstream(dir / file, std::ios::binary) << text;
    return dir / file;
  }
};

std::string error_of(const fs::path& p) {
  rtk::RenderScene s;
  try {
    rtk::load_xml_scene(p, s);
  } catch (const rtk::FileError& e) {
    return e.what();
  }
  return "";
}

bool near(rtk::Vec3f a, rtk::Vec3f b) {
  return std::abs(a.x - b.x) < 1e-4f && std::abs(a.y - b.y) < 1e-4f && std::abs(a.z - b.z) < 1e-4f;
}

}  // namespace

TEST_CASE("lib_scene: an XML scene with groups, transforms, meshes, spheres, materials and lights") {
  Scratch t("valid");
  const fs::path p = t.write("s.xml", R"(<?xml version="1.0"?>
<scene>
  <assign type="material" id="red">
    <material><code>"Matte"</code><parameters><float3 name="reflectance">1 0 0</float3></parameters></material>
  </assign>
  <Group>
    <Transform>
      <AffineSpace translate="10 0 0"/>
      <TriangleMesh>
        <positions>0 0 0  1 0 0  0 1 0</positions>
        <motions>0 0 0  0 0 1  0 0 0</motions>
        <normals>0 0 1  0 0 1  0 0 1</normals>
        <triangles>0 1 2</triangles>
        <material id="red"/>
      </TriangleMesh>
    </Transform>
    <Transform>
      <AffineSpace>0 -1 0 5   1 0 0 0   0 0 1 0</AffineSpace>
      <Sphere><position>0 0 0</position><radius>2</radius><numTheta>3</numTheta><numPhi>4</numPhi>
        <material><code>"Metal"</code><parameters><float3 name="eta">0.2 0.9 1.1</float3><float3 name="k">3.9 2.4 2.2</float3></parameters></material>
      </Sphere>
    </Transform>
    <QuadLight><AffineSpace>2 0 0 1  0 0 1 3  0 2 0 1</AffineSpace><L>5 5 5</L></QuadLight>
    <PointLight><AffineSpace translate="0 7 0"/><I>1 2 3</I></PointLight>
  </Group>
</scene>)");
  rtk::RenderScene s;
  std::vector<std::string> warnings;
  rtk::load_xml_scene(p, s, [&](const std::string& w) { warnings.push_back(w); });
  CHECK_NOTHROW(s.validate());
  // 1 mesh triangle + 2 * 4 * (3 - 1) sphere triangles + 2 quad-light triangles; the sphere
  // has (3 + 1) * 4 vertices, each light triangle 3 of its own.
  REQUIRE(s.mesh.triangles.size() == 1u + 16u + 2u);
  REQUIRE(s.mesh.vertices.size() == 3u + 16u + 6u);
  // The mesh is translated; its motion goes through the same transform.
  CHECK(near(s.mesh.vertices[1], {11, 0, 0}));
  REQUIRE(s.has_motion());
  CHECK(near(s.vertices_t1[1], {11, 0, 1}));
  CHECK(near(s.vertices_t1[5], s.mesh.vertices[5]));  // the sphere stands still
  // The sphere went through the 3x4 matrix (a rotation about z and a translation by x = 5):
  // its top pole (0, 2, 0) lands at (5 - 2, 0, 0) and its normal turns with it.
  CHECK(near(s.mesh.vertices[3], {3, 0, 0}));
  REQUIRE(s.normals.size() == s.mesh.vertices.size());
  CHECK(near(s.normals[3], {-1, 0, 0}));
  CHECK(near(s.normals[0], {0, 0, 1}));
  // Materials: red Matte, the Metal, the light's; the quad light's triangles emit.
  CHECK(s.materials[s.triangle_material[0]].name == "Matte");
  CHECK(s.materials[s.triangle_material[1]].name == "Metal");
  CHECK(s.triangle_light[17] != rtk::kNoLight);
  CHECK(s.triangle_light[18] != rtk::kNoLight);
  CHECK(s.lights.size() == 3u);  // two triangles and the point light
  CHECK(warnings.empty());
}

TEST_CASE("lib_scene: XML binary arrays come from the side file") {
  Scratch t("binary");
  const float pos[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
  const int32_t tri[] = {0, 1, 2, 2, 1, 3};
  {
    std::ofstream bin(t.dir / "b.xml.bin", std::ios::binary);
    bin.write(reinterpret_cast<const char*>(pos), sizeof pos);
    bin.write(reinterpret_cast<const char*>(tri), sizeof tri);
  }
  const fs::path p = t.write("b.xml", R"(<scene><TriangleMesh>
    <positions ofs="0" size="4"/><normals ofs="48" size="0"/><triangles ofs="48" size="2"/>
  </TriangleMesh></scene>)");
  rtk::RenderScene s;
  rtk::load_xml_scene(p, s);
  REQUIRE(s.mesh.triangles.size() == 2u);
  CHECK(s.mesh.triangles[1] == std::array<uint32_t, 3>{2, 1, 3});
  CHECK(near(s.mesh.vertices[3], {1, 1, 0}));
  CHECK(s.normals.empty());

  CHECK(error_of(t.write("n.xml", "<scene><TriangleMesh><positions ofs=\"0\" size=\"4\"/></TriangleMesh></scene>"))
            .find("no side file") != std::string::npos);
  fs::copy_file(t.dir / "b.xml.bin", t.dir / "c.bin");
  const fs::path bad = t.write("c.xml", "<scene><TriangleMesh>\n<positions ofs=\"40\" size=\"4\"/>\n<triangles>0 1 2</triangles></TriangleMesh></scene>");
  CHECK(error_of(bad).find("c.xml:2:") != std::string::npos);
  CHECK(error_of(bad).find("outside the binary file") != std::string::npos);
}

TEST_CASE("lib_scene: XML reuse and inclusion: assigned scenes, refs, OBJ and XML files, material files") {
  Scratch t("include");
  t.write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  t.write("part.xml", "<scene><TriangleMesh><positions>0 0 0 2 0 0 0 2 0</positions><triangles>0 1 2</triangles>"
                      "<material file=\"gold.xml\"/></TriangleMesh></scene>");
  t.write("gold.xml", "<material><code>\"Metal\"</code><parameters><float3 name=\"eta\">0.2 0.4 1.4</float3>"
                      "<float3 name=\"k\">3.6 2.4 1.8</float3></parameters></material>");
  const fs::path p = t.write("main.xml", R"(<scene>
  <assign type="scene" id="unit"><obj src="tri.obj"/></assign>
  <Transform><AffineSpace translate="0 0 5"/><ref id="unit"/></Transform>
  <Transform><AffineSpace scale="3 3 3"/><ref id="unit"/></Transform>
  <Transform><AffineSpace rotate_z="90"/><xml src="part.xml"/></Transform>
</scene>)");
  rtk::RenderScene s;
  rtk::load_xml_scene(p, s);
  CHECK_NOTHROW(s.validate());
  REQUIRE(s.mesh.triangles.size() == 3u);
  CHECK(near(s.mesh.vertices[0], {0, 0, 5}));   // the first instance, translated
  CHECK(near(s.mesh.vertices[4], {3, 0, 0}));   // the second, scaled
  CHECK(near(s.mesh.vertices[7], {0, 2, 0}));   // the included file, rotated by 90 degrees
  CHECK(s.materials[s.triangle_material[2]].name == "Metal");
}

TEST_CASE("lib_scene: a <ref> names the scene assigned before it, so an id can be reassigned") {
  // Embree's cornell_box_instanced.xml (v4.3.1) builds cornell_box_4 from four copies of the
  // previous cornell_box_4: a reference resolved when the scene is used would recurse forever.
  Scratch t("reassign");
  t.write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const fs::path p = t.write("main.xml", R"(<scene>
  <assign type="scene" id="s"><obj src="tri.obj"/></assign>
  <assign type="scene" id="left"><Transform><AffineSpace translate="-2 0 0"/><ref id="s"/></Transform></assign>
  <assign type="scene" id="right"><Transform><AffineSpace translate="2 0 0"/><ref id="s"/></Transform></assign>
  <assign type="scene" id="s"><Group><ref id="left"/><ref id="right"/></Group></assign>
  <ref id="s"/>
</scene>)");
  rtk::RenderScene s;
  rtk::load_xml_scene(p, s);
  REQUIRE(s.mesh.triangles.size() == 2u);
  CHECK(near(s.mesh.vertices[0], {-2, 0, 0}));
  CHECK(near(s.mesh.vertices[3], {2, 0, 0}));
  // A scene that names itself refers to nothing assigned before it: an error, not a recursion.
  CHECK(error_of(t.write("self.xml", "<scene>\n<assign type=\"scene\" id=\"x\"><Group><ref id=\"x\"/></Group></assign>\n<ref id=\"x\"/></scene>"))
            .find("self.xml:2: <ref>: no scene assigned with id 'x' before this point") != std::string::npos);
}

TEST_CASE("lib_scene: malformed XML scenes are refused with file and line") {
  Scratch t("bad");
  // Broken XML: pugixml's offset becomes a line.
  CHECK(error_of(t.write("a.xml", "<scene>\n<Group>\n</Grp>\n</scene>")).find("a.xml:3: malformed XML") != std::string::npos);
  CHECK(error_of(t.write("b.xml", "<world/>")).find("b.xml:1: the root element must be <scene>") != std::string::npos);
  CHECK(error_of(t.write("c.xml", "<scene>\n<TriangleMesh>\n<positions>0 0 0 1 0 0 0 1 x</positions>\n<triangles>0 1 2</triangles></TriangleMesh></scene>"))
            .find("c.xml:3: positions: 'x' is not a finite number") != std::string::npos);
  CHECK(error_of(t.write("d.xml", "<scene><TriangleMesh>\n<positions>0 0 0 1 0 0 0 1 0</positions>\n<triangles>0 1 3</triangles></TriangleMesh></scene>"))
            .find("d.xml:3: <triangles>: vertex index 3 of triangle 0 is out of range") != std::string::npos);
  CHECK(error_of(t.write("e.xml", "<scene>\n\n<TriangleMesh><triangles>0 1 2</triangles></TriangleMesh></scene>"))
            .find("e.xml:3: <TriangleMesh> needs a <positions>") != std::string::npos);
  CHECK(error_of(t.write("f.xml", "<scene><Sphere><position>0 0 0</position><radius>-1</radius><numTheta>3</numTheta><numPhi>4</numPhi></Sphere></scene>"))
            .find("radius must be positive") != std::string::npos);
  CHECK(error_of(t.write("g.xml", "<scene>\n<TriangleMesh><positions>0 0 0 1 0 0 0 1 0</positions><triangles>0 1 2</triangles>\n<material id=\"nope\"/></TriangleMesh></scene>"))
            .find("g.xml:3: <material id=\"nope\">: no material assigned") != std::string::npos);
  CHECK(error_of(t.write("h.xml", "<scene><Transform><Group/></Transform></scene>")).find("first child must be an <AffineSpace>") != std::string::npos);
  CHECK(error_of(t.dir / "missing.xml").find("missing.xml") != std::string::npos);
  // A self-including file stops at the nesting limit instead of recursing forever.
  CHECK(error_of(t.write("i.xml", "<scene><xml src=\"i.xml\"/></scene>")).find("nested more than 16 deep") != std::string::npos);

  // Unknown materials and elements are warnings, not errors.
  rtk::RenderScene s;
  std::vector<std::string> warnings;
  rtk::load_xml_scene(t.write("w.xml", "<scene><QuadMesh/><TriangleMesh><positions>0 0 0 1 0 0 0 1 0</positions><triangles>0 1 2</triangles>"
                                       "<material><code>\"Velour\"</code></material></TriangleMesh></scene>"),
                      s, [&](const std::string& w) { warnings.push_back(w); });
  CHECK(s.mesh.triangles.size() == 1u);
  REQUIRE(warnings.size() >= 2u);
  CHECK(warnings[0].find("<QuadMesh> is not supported") != std::string::npos);
  CHECK(warnings[1].find("Velour") != std::string::npos);
}

TEST_CASE("lib_scene: the real Embree XML scenes load (when /work/shared/scenes is present)") {
  const fs::path root = "/work/shared/scenes/embree_models";
  if (!fs::is_directory(root)) return;  // the files are not shipped with the sources
  struct Case {
    const char* file;
    size_t triangles;
    bool motion;
  };
  // Triangle counts: spheres 2 * numPhi * (numTheta - 1), plus the meshes and quad lights.
  const Case cases[] = {
      {"v1.1_release_2012/accuracy.xml", 2 * 500 * 1, false},
      {"v1.1_release_2012/cornell_box_spheres.xml", 2 * (2 * 50 * 49) + 5 * 2 + 2, false},
      {"v1.1_release_2012/sphere_glass.xml", 2 * 50 * 49 + 2, false},
      {"v1.1_release_2012/motionblur.xml", 2 * 2 * 50 * 49 + 2 + 2, true},
      {"v2.17.7_2019/cornell_box.xml", 34, false},
  };
  // Embree 4's instanced Cornell box names an OBJ file that the shared folder does not hold:
  // the reader must say so, with the file and line, after resolving its reassigned refs.
  {
    rtk::RenderScene s;
    CHECK_THROWS_WITH_AS(rtk::load_xml_scene(root / "v4.3.1_2024/cornell_box_instanced.xml", s),
                         doctest::Contains("cornell_box.obj"), rtk::FileError);
  }
  for (const Case& c : cases) {
    CAPTURE(c.file);
    rtk::RenderScene s;
    rtk::load_xml_scene(root / c.file, s);
    CHECK_NOTHROW(s.validate());
    CHECK(s.mesh.triangles.size() > 0u);
    if (c.triangles) CHECK(s.mesh.triangles.size() == c.triangles);
    CHECK(s.has_motion() == c.motion);
  }
  // The scripts that name them load unmodified through -i.
  for (const char* ecs : {"v1.1_release_2012/cornell_box_spheres.ecs", "v1.1_release_2012/motionblur.ecs",
                          "v1.1_release_2012/sphere_glass.ecs", "v1.1_release_2012/accuracy.ecs"}) {
    CAPTURE(ecs);
    rtk::SceneScript script;
    CHECK_NOTHROW(rtk::read_script_file(root / ecs, script));
    CHECK(script.scene.mesh.triangles.size() > 0u);
  }
}

TEST_CASE("lib_scene: Embree 2's scripts load without a warning, beside Embree 1.1's files") {
  // The shared folder keeps only the files each version changed: Embree 2.0's scripts name
  // lines.ppm, the Cornell box's OBJ and 1.1's sphere_view.ecs and sphere_carpaint.xml, which
  // sit in 1.1's folder. Put together as Embree 2.0 shipped them, every script loads, with
  // no warning: its lights (the quad light, the HDRI) and materials (Metal, Mirror, Dielectric,
  // MetallicPaint, MatteTextured) are all modelled.
  const fs::path root = "/work/shared/scenes/embree_models";
  if (!fs::is_directory(root / "v2.0.0_2015")) return;  // the files are not shipped with the sources
  const fs::path dir = fs::temp_directory_path() / ("rtk_embree2_" + std::to_string(getpid()));
  fs::create_directories(dir);
  for (const auto& e : fs::directory_iterator(root / "v2.0.0_2015"))
    fs::copy_file(e.path(), dir / e.path().filename(), fs::copy_options::overwrite_existing);
  for (const char* f : {"lines.ppm", "sphere_view.ecs", "cornell_box.obj", "cornell_box.mtl", "sphere_carpaint.xml"})
    fs::copy_file(root / "v1.1_release_2012" / f, dir / f, fs::copy_options::overwrite_existing);
  for (const char* ecs : {"cornell_box.ecs", "sphere_carpaint.ecs", "sphere_glass.ecs", "sphere_gold.ecs",
                          "sphere_mirror.ecs", "sphere_motion.ecs"}) {
    CAPTURE(ecs);
    rtk::SceneScript script;
    std::vector<std::string> warnings;
    CHECK_NOTHROW(rtk::read_script_file(dir / ecs, script, [&](const std::string& w) { warnings.push_back(w); }));
    CHECK(script.scene.mesh.triangles.size() > 0u);
    CHECK(script.scene.lights.size() > 0u);
    CHECK_NOTHROW(script.scene.validate());
    for (const std::string& w : warnings) CHECK_MESSAGE(false, w);
  }
  fs::remove_all(dir);
}
