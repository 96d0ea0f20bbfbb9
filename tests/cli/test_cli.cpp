// End to end: the built `rtk` (its path is RTK_BINARY) makes rays, traces them with every
// structure, layout and ISA this RTK has, and the hits are checked against brute force; bad
// command lines fail with status 2 and a message that names the option or the file.
#include <doctest/doctest.h>

#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "10_kernel_api/accel.h"
#include "testing/brute_force.h"
#include "io/obj_loader.h"
#include "io/obj_writer.h"
#include "io/read_file.h"
#include "io/replay_files.h"
#include "01_base/ray_sets.h"
#include "replay/ray_generator.h"
#include "testing/run_program.h"
#include "testing/sanitizer_build.h"
#include "testing/scenes.h"

namespace {

namespace fs = std::filesystem;

using Result = rtk::test::ProgramResult;

// Runs `rtk ARGS` through the shell, capturing its output.
Result run_rtk(const std::string& args) { return rtk::test::run_program(RTK_BINARY, args); }

// A folder of its own for each test program run, removed at the end.
struct WorkDir {
  fs::path path;
  WorkDir() {
    path = fs::temp_directory_path() / ("rtk_cli_tests_" + std::to_string(getpid()));
    fs::create_directories(path);
  }
  ~WorkDir() { fs::remove_all(path); }
  std::string operator()(const std::string& name) const { return (path / name).string(); }
};
WorkDir work;

// A small scene with what breaks tracers: a closed sphere, overlapping soup, long slivers and
// zero-area triangles (which keep their primIDs and are never hit).
const rtk::TriangleMesh& scene() {
  static const rtk::TriangleMesh mesh = [] {
    rtk::TriangleMesh m = rtk::test::make_sphere(6, 12, {0.5f, 0.5f, 0.5f}, 0.4f);
    auto append = [&m](const rtk::TriangleMesh& other) {
      const uint32_t base = uint32_t(m.vertices.size());
      m.vertices.insert(m.vertices.end(), other.vertices.begin(), other.vertices.end());
      for (auto tri : other.triangles) m.triangles.push_back({tri[0] + base, tri[1] + base, tri[2] + base});
    };
    append(rtk::test::make_random_soup(120, 5, 0.2f));
    append(rtk::test::make_slivers(20, 6));
    rtk::test::add_degenerate_triangles(m, 4, 7);
    return m;
  }();
  return mesh;
}

const std::string& scene_file() {
  static const std::string file = [] {
    const std::string f = work("scene.obj");
    rtk::save_obj(f, scene());
    return f;
  }();
  return file;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// Each command line must fail with status 2 and a message from rtk that holds its words.
void check_refused(const std::vector<std::pair<std::string, std::string>>& cases) {
  for (const auto& [args, words] : cases) {
    CAPTURE(args);
    const Result r = run_rtk(args);
    CAPTURE(r.output);
    CHECK(r.status == 2);
    CHECK(contains(r.output, words));
    CHECK(r.output.starts_with("rtk"));
  }
}

// Every configuration the API accepts, on every ISA the CPU runs.
struct Config {
  std::string accel, tri, isa;
};
std::vector<Config> all_configs() {
  std::vector<Config> configs;
  for (const std::string& accel : rtk::supported_accels())
    for (const std::string& tri : rtk::supported_tris(accel))
      for (rtk::Isa isa : rtk::supported_isas()) configs.push_back({accel, tri, std::string(rtk::isa_name(isa))});
  return configs;
}

// Makes a .rays file of a kind and appends the rays that are not rays.
std::vector<rtk::Ray> make_rays(const std::string& kind, const std::string& file, int n) {
  const Result r = run_rtk("rays -i " + scene_file() + " -kind " + kind + " -n " + std::to_string(n) +
                       " -seed 3 -o " + file);
  REQUIRE_MESSAGE(r.status == 0, r.output);
  std::vector<rtk::Ray> rays = rtk::read_rays(file);
  for (const rtk::Ray& bad : rtk::test::invalid_rays()) rays.push_back(bad);
  rtk::write_rays(file, rays);
  return rays;
}

}  // namespace

TEST_CASE("cli: every structure, layout and ISA agrees with brute force") {
  // Under the sanitizers every process start is slow: every 7th configuration (a stride prime to
  // the number of ISAs, so that each ISA is sampled) end to end; api_tests still trace all of
  // them in-process.
  const std::vector<Config> configs = rtk::test::sanitizer_sample(all_configs(), 7);
  REQUIRE(!configs.empty());
  for (const char* kind : {"primary", "diffuse", "shadow", "random"}) {
    const std::string rays_file = work(std::string(kind) + ".rays");
    const std::vector<rtk::Ray> rays = make_rays(kind, rays_file, 150);
    std::vector<rtk::Hit> oracle(rays.size());
    for (size_t i = 0; i < rays.size(); ++i) oracle[i] = rtk::test::brute_force_intersect(scene(), rays[i]);
    for (const Config& c : configs) {
      CAPTURE(kind);
      CAPTURE(c.accel);
      CAPTURE(c.tri);
      CAPTURE(c.isa);
      const std::string options = " -accel " + c.accel + " -tri " + c.tri + " -isa " + c.isa;
      const Result hit_run = run_rtk("trace -i " + scene_file() + " -rays " + rays_file + " -hits " +
                                 work("out.hits") + options);
      REQUIRE_MESSAGE(hit_run.status == 0, hit_run.output);
      const std::vector<rtk::Hit> hits = rtk::read_hits(work("out.hits"));
      REQUIRE(hits.size() == rays.size());
      for (size_t i = 0; i < rays.size(); ++i) {
        const std::string why = rtk::test::compare_hits(scene(), rays[i], hits[i], oracle[i]);
        CHECK_MESSAGE(why.empty(), "ray ", i, ": ", why);
        if (!rtk::is_valid(rays[i])) CHECK(!hits[i].found());
      }
      // Occlusion is the same question without the closest hit: it must agree with the hits
      // of the same structure exactly (the same triangle tests decide both).
      const Result occl_run = run_rtk("trace -i " + scene_file() + " -rays " + rays_file + " -occl " +
                                  work("out.occl") + options);
      REQUIRE_MESSAGE(occl_run.status == 0, occl_run.output);
      const std::vector<uint8_t> occluded = rtk::read_occlusion(work("out.occl"));
      REQUIRE(occluded.size() == rays.size());
      for (size_t i = 0; i < rays.size(); ++i) CHECK_MESSAGE(occluded[i] == uint8_t(hits[i].found()), "ray ", i);
    }
  }
}

TEST_CASE("cli: invalid rays are misses and do not disturb the others; threads change nothing") {
  const std::string clean = work("clean.rays");
  REQUIRE(run_rtk("rays -i " + scene_file() + " -kind random -n 400 -o " + clean).status == 0);
  const std::vector<rtk::Ray> valid = rtk::read_rays(clean);
  // Interleave the bad rays between the good ones.
  std::vector<rtk::Ray> mixed;
  const std::vector<rtk::Ray> bad = rtk::test::invalid_rays();
  for (size_t i = 0; i < valid.size(); ++i) {
    mixed.push_back(valid[i]);
    if (i < bad.size()) mixed.push_back(bad[i]);
  }
  rtk::write_rays(work("mixed.rays"), mixed);
  REQUIRE(run_rtk("trace -i " + scene_file() + " -rays " + clean + " -hits " + work("clean.hits")).status == 0);
  const Result r = run_rtk("trace -i " + scene_file() + " -rays " + work("mixed.rays") + " -hits " +
                       work("mixed.hits") + " --threads 2");
  REQUIRE_MESSAGE(r.status == 0, r.output);
  const std::vector<rtk::Hit> clean_hits = rtk::read_hits(work("clean.hits"));
  const std::vector<rtk::Hit> mixed_hits = rtk::read_hits(work("mixed.hits"));
  size_t k = 0;
  for (size_t i = 0; i < valid.size(); ++i) {
    CHECK(std::memcmp(&mixed_hits[k++], &clean_hits[i], sizeof(rtk::Hit)) == 0);
    if (i < bad.size()) {
      // The list also holds rays that look odd but are rays (tnear = -inf): those are traced.
      if (rtk::is_valid(bad[i])) {
        const rtk::Hit oracle = rtk::test::brute_force_intersect(scene(), bad[i]);
        CHECK(rtk::test::compare_hits(scene(), bad[i], mixed_hits[k], oracle) == "");
      } else {
        CHECK(!mixed_hits[k].found());
        CHECK(mixed_hits[k].t == 0.0f);
      }
      ++k;
    }
  }
}

TEST_CASE("cli: rays are the library's rays, and trace prints the replay JSON lines") {
  const Result made = run_rtk("rays -i " + scene_file() + " -kind diffuse -n 64 -seed 9 -o " + work("d.rays"));
  REQUIRE(made.status == 0);
  CHECK(contains(made.output, "{\"op\":\"rays\",\"kind\":\"diffuse\",\"rays\":64,\"seed\":9"));
  const std::string expected = rtk::format_rays(rtk::generate_rays(rtk::load_obj(scene_file()), rtk::RayKind::diffuse, 64, 9));
  CHECK(rtk::read_file(work("d.rays")) == expected);

  const Result r = run_rtk("--trace -i " + scene_file() + " --rays " + work("d.rays") + " -hits " + work("d.hits") + " -repeat 3");
  // "--trace" is not a command: commands take no dashes.
  CHECK(r.status == 2);
  const Result t = run_rtk("trace -i " + scene_file() + " --rays " + work("d.rays") + " --hits " + work("d.hits") + " -repeat 3");
  REQUIRE_MESSAGE(t.status == 0, t.output);
  const rtk::AccelInfo info = rtk::resolve_config({});
  CHECK(contains(t.output, "{\"op\":\"build\",\"accel\":\"" + info.accel + "\",\"tri\":\"" + info.tri +
                               "\",\"isa\":\"" + std::string(rtk::isa_name(info.isa)) + "\",\"triangles\":" +
                               std::to_string(scene().size()) + ",\"seconds\":"));
  CHECK(contains(t.output, "\"mtris_per_s\":"));
  CHECK(contains(t.output, "\"bytes\":"));
  CHECK(contains(t.output, "{\"op\":\"intersect\",\"rays\":64,\"seconds\":"));
  CHECK(contains(t.output, "\"mrays_per_s\":"));
  CHECK(contains(t.output, "\"threads\":1"));
}

TEST_CASE("cli: compare finds planted differences and says so in its exit status") {
  REQUIRE(run_rtk("rays -i " + scene_file() + " -kind primary -n 200 -o " + work("p.rays")).status == 0);
  REQUIRE(run_rtk("trace -i " + scene_file() + " -rays " + work("p.rays") + " -hits " + work("a.hits")).status == 0);
  REQUIRE(run_rtk("trace -i " + scene_file() + " -rays " + work("p.rays") + " -occl " + work("a.occl")).status == 0);
  const Result same = run_rtk("compare " + work("a.hits") + " " + work("a.hits"));
  CHECK(same.status == 0);
  CHECK(contains(same.output, "\"agree\":200,\"agree_percent\":100"));

  std::vector<rtk::Hit> hits = rtk::read_hits(work("a.hits"));
  size_t planted = 0;
  for (size_t i = 0; i < hits.size() && planted < 3; ++i)
    if (hits[i].found()) {
      hits[i].prim ^= 1;  // a wrong primID
      ++planted;
    }
  REQUIRE(planted == 3);
  rtk::write_hits(work("b.hits"), hits);
  const Result differ = run_rtk("compare " + work("a.hits") + " " + work("b.hits"));
  CHECK(differ.status == 1);
  CHECK(contains(differ.output, "\"other_prim\":3"));
  CHECK(contains(differ.output, "{\"op\":\"difference\",\"ray\":"));
  CHECK(run_rtk("compare " + work("a.hits") + " " + work("b.hits") + " -allow 2").status == 0);  // 3 of 200 = 1.5%

  std::vector<uint8_t> occl = rtk::read_occlusion(work("a.occl"));
  occl[7] ^= 1;
  rtk::write_occlusion(work("b.occl"), occl);
  const Result occl_differ = run_rtk("compare " + work("a.occl") + " " + work("b.occl"));
  CHECK(occl_differ.status == 1);
  CHECK(contains(occl_differ.output, "{\"op\":\"difference\",\"ray\":7,"));
  const Result mixed = run_rtk("compare " + work("a.hits") + " " + work("a.occl"));
  CHECK(mixed.status == 2);
  CHECK(contains(mixed.output, "a.occl: is not the same kind of file"));
}

TEST_CASE("cli: bad command lines fail with status 2 and name the option or file") {
  REQUIRE(run_rtk("rays -i " + scene_file() + " -kind primary -n 10 -o " + work("ok.rays")).status == 0);
  rtk::write_file(work("bad.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0 x\nf 1 2 3\n");
  rtk::write_file(work("bad.rays"), "RAYS0001 truncated");
  const std::string trace = "trace -i " + scene_file() + " -rays " + work("ok.rays") + " ";
  const std::string h = " -hits " + work("x.hits");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {trace + h + " -accel bvh3", "-accel"},
      {trace + h + " -accel bvh4.nosplit", "-accel"},
      {trace + h + " -tri triangle9", "-tri"},
      {trace + h + " -tri triangle4.exact", "-tri"},
      {trace + h + " -isa neon", "-isa"},
      {trace + h + " -threads 0", "-threads"},
      {trace + h + " -order random", "-order: 'random' is not auto, sorted or given"},
      {trace + h + " -packets maybe", "-packets: 'maybe' is not on or off"},
      {trace + h + " -repeat x", "-repeat"},
      {trace + h + " -bogus 1", "unknown option '-bogus'"},
      {trace, "missing option -hits or -occl"},
      {trace + h + " -occl " + work("x.occl"), "exclude"},
      {trace + "-hits", "option -hits needs a value"},
      {trace + h + " -hits " + work("y.hits"), "given twice"},
      {"trace -i " + work("missing.obj") + " -rays " + work("ok.rays") + h, "missing.obj: cannot open"},
      {"trace -i " + work("bad.obj") + " -rays " + work("ok.rays") + h, "bad.obj:3: bad number 'x'"},
      {"trace -i " + scene_file() + " -rays " + work("bad.rays") + h, "bad.rays: truncated"},
      {"trace -rays " + work("ok.rays") + h, "missing option -i"},
      {"rays -i " + scene_file() + " -kind sideways -n 10 -o " + work("z.rays"), "-kind"},
      {"rays -i " + scene_file() + " -kind primary -n 0 -o " + work("z.rays"), "option -n"},
      {"rays -i " + scene_file() + " -kind primary -n 10", "missing option -o"},
      {"rays -i " + scene_file() + " -kind primary -n 10 -seed -1 -o " + work("z.rays"), "option -seed"},
      {"compare " + work("a.hits"), "expected 2 file arguments"},
      {"compare " + work("ok.rays") + " " + work("ok.rays"), "is a .rays file"},
      {"compare a b -tolerance -1", "option -tolerance"},
      {"info -isa mmx", "-isa"},
      {"nosuchcommand", "unknown command 'nosuchcommand'"},
  };
  check_refused(cases);
}

TEST_CASE("cli: an output that names one of the command's inputs is refused, the input kept") {
  // Writing the rays over the scene they were made from, or the hits over the rays, would
  // destroy a file the command has just read: refused before any work, whatever the spelling
  // (a second path, a hard link), and the input is left as it was.
  const std::string mesh = work("keep.obj"), rays = work("keep.rays");
  rtk::write_file(mesh, rtk::read_file(scene_file()));
  REQUIRE(run_rtk("rays -i " + mesh + " -kind diffuse -n 100 -o " + rays).status == 0);
  const std::string mesh_bytes = rtk::read_file(mesh), rays_bytes = rtk::read_file(rays);
  fs::remove(work("link.obj"));
  fs::create_hard_link(mesh, work("link.obj"));
  const std::string other_spelling = (fs::path(mesh).parent_path() / "." / "keep.obj").string();
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"rays -i " + mesh + " -kind diffuse -n 10 -o " + mesh,
       "-o: " + mesh + " is also the input of -i"},
      {"rays -i " + mesh + " -kind diffuse -n 10 -o " + other_spelling, "is also the input of -i"},
      {"rays -i " + mesh + " -kind diffuse -n 10 -o " + work("link.obj"),
       "is also the input of -i"},
      {"trace -i " + mesh + " -rays " + rays + " -hits " + rays,
       "-hits: " + rays + " is also the input of -rays"},
      {"trace -i " + mesh + " -rays " + rays + " -occl " + mesh,
       "-occl: " + mesh + " is also the input of -i"},
      {"trace -i " + mesh + " -motion " + mesh + " -rays " + rays + " -hits " + work("link.obj"),
       "is also the input of -i"},
  };
  check_refused(cases);
  CHECK(rtk::read_file(mesh) == mesh_bytes);
  CHECK(rtk::read_file(rays) == rays_bytes);
}

namespace {

// The CLI scene in linear motion: the sphere flies by 0.3 along x, every third soup vertex
// jitters, the rest stays. Saved as S0.obj (time 0) and S1.obj (time 1).
const rtk::TriangleMesh& moved_scene() {
  static const rtk::TriangleMesh mesh = [] {
    rtk::TriangleMesh m = scene();
    for (size_t v = 0; v < m.vertices.size(); ++v) {
      if (v < 6 * 12 + 2) m.vertices[v].x += 0.3f;
      else if (v % 3 == 0) m.vertices[v] += rtk::Vec3f{0.05f, -0.04f, 0.03f};
    }
    return m;
  }();
  return mesh;
}

// The scene at a ray's time, each vertex computed as chapter 8 does: p0 + t (p1 - p0).
rtk::TriangleMesh scene_at(float time) {
  rtk::TriangleMesh m = scene();
  for (size_t v = 0; v < m.vertices.size(); ++v) {
    const rtk::Vec3f p0 = scene().vertices[v], d = moved_scene().vertices[v] - p0;
    m.vertices[v] = {p0.x + time * d.x, p0.y + time * d.y, p0.z + time * d.z};
  }
  return m;
}

}  // namespace

TEST_CASE("cli: -motion traces bvh4mb at each ray's time and agrees with brute force") {
  rtk::save_obj(work("S0.obj"), scene());
  rtk::save_obj(work("S1.obj"), moved_scene());
  std::vector<rtk::Ray> rays = make_rays("primary", work("m.rays"), 300);
  for (size_t i = 0; i < rays.size(); ++i) rays[i].time = i % 3 == 0 ? 0.0f : i % 3 == 1 ? 1.0f : float(i % 97) / 97.0f;
  rays.push_back(rays[0]);
  rays.back().time = 1.5f;  // outside the shutter: a miss
  rtk::write_rays(work("m.rays"), rays);
  for (const std::string tri : {"triangle4i.moeller", "triangle4i.pluecker"})
    for (rtk::Isa isa : rtk::supported_isas()) {
      CAPTURE(tri);
      CAPTURE(rtk::isa_name(isa));
      const Result r = run_rtk("trace -i " + work("S0.obj") + " -motion " + work("S1.obj") + " -rays " + work("m.rays") +
                               " -hits " + work("m.hits") + " -tri " + tri + " -isa " + std::string(rtk::isa_name(isa)));
      REQUIRE_MESSAGE(r.status == 0, r.output);
      CHECK(contains(r.output, "\"accel\":\"bvh4mb.objectsplit\",\"tri\":\"" + tri + "\""));
      const std::vector<rtk::Hit> hits = rtk::read_hits(work("m.hits"));
      REQUIRE(hits.size() == rays.size());
      size_t found = 0;
      for (size_t i = 0; i + 1 < rays.size(); ++i) {
        const rtk::TriangleMesh at = scene_at(rays[i].time);
        const std::string why = rtk::test::compare_hits(at, rays[i], hits[i], rtk::test::brute_force_intersect(at, rays[i]));
        CHECK_MESSAGE(why.empty(), "ray ", i, ": ", why);
        found += hits[i].found();
      }
      CHECK(found > rays.size() / 10);  // the rays do meet the moving scene
      CHECK(!hits.back().found());
    }
  // A static pair builds no motion structure: the static default, the static answers.
  const Result still = run_rtk("trace -i " + scene_file() + " -motion " + scene_file() + " -rays " + work("m.rays") +
                               " -hits " + work("still.hits"));
  REQUIRE_MESSAGE(still.status == 0, still.output);
  CHECK(!contains(still.output, "bvh4mb"));
  REQUIRE(run_rtk("trace -i " + scene_file() + " -rays " + work("m.rays") + " -hits " + work("plain.hits")).status == 0);
  CHECK(rtk::read_file(work("still.hits")) == rtk::read_file(work("plain.hits")));
}

TEST_CASE("cli: -motion refuses mismatched files naming both; bvh4mb without -motion is static") {
  rtk::save_obj(work("S0.obj"), scene());
  rtk::save_obj(work("S1.obj"), moved_scene());
  rtk::TriangleMesh fewer = moved_scene();
  fewer.triangles.pop_back();
  rtk::save_obj(work("fewer.obj"), fewer);
  rtk::TriangleMesh other = moved_scene();
  std::swap(other.triangles[3][1], other.triangles[3][2]);
  rtk::save_obj(work("other.obj"), other);
  REQUIRE(run_rtk("rays -i " + scene_file() + " -kind random -n 10 -o " + work("few.rays")).status == 0);
  const std::string trace = "trace -rays " + work("few.rays") + " -hits " + work("x.hits") + " -i " + work("S0.obj");
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {trace + " -motion " + work("fewer.obj"), {"S0.obj", "fewer.obj", "triangles"}},
      {trace + " -motion " + work("other.obj"), {"S0.obj", "other.obj", "triangle 3"}},
      {trace + " -motion " + work("nothere.obj"), {"nothere.obj"}},
      {trace + " -motion " + work("S1.obj") + " -accel bvh4", {"-accel", "cannot trace motion", "bvh4mb"}},
      {trace + " -motion " + work("S1.obj") + " -tri triangle4", {"-tri", "triangle4i"}},
  };
  for (const auto& [args, words] : cases) {
    CAPTURE(args);
    const Result r = run_rtk(args);
    CAPTURE(r.output);
    CHECK(r.status == 2);
    for (const std::string& w : words) CHECK(contains(r.output, w));
  }
  // As in Embree 1.1, bvh4mb builds on a static scene (every vertex stands still) and finds
  // the static structure's hits.
  const Result mb = run_rtk(trace + " -accel bvh4mb");
  CAPTURE(mb.output);
  CHECK(mb.status == 0);
  CHECK(contains(mb.output, "bvh4mb.objectsplit"));
  REQUIRE(run_rtk("trace -rays " + work("few.rays") + " -hits " + work("y.hits") + " -i " + work("S0.obj")).status == 0);
  CHECK(run_rtk("compare " + work("x.hits") + " " + work("y.hits")).status == 0);
  CHECK(run_rtk(trace + " -accel bvh4mb.spatialsplit").status == 2);
}

TEST_CASE("cli: -order changes when each ray is traced, never the answer") {
  make_rays("diffuse", work("o.rays"), 5000);  // incoherent, and larger than a sorted batch must be
  const std::string trace = "trace -i " + scene_file() + " -rays " + work("o.rays");
  for (const std::string order : {"given", "sorted", "auto"}) {
    const Result hits = run_rtk(trace + " -order " + order + " -hits " + work("o_" + order + ".hits"));
    REQUIRE_MESSAGE(hits.status == 0, hits.output);
    const Result occl = run_rtk(trace + " -order " + order + " -occl " + work("o_" + order + ".occl"));
    REQUIRE_MESSAGE(occl.status == 0, occl.output);
  }
  for (const std::string order : {"sorted", "auto"}) {
    CHECK(rtk::read_file(work("o_" + order + ".hits")) == rtk::read_file(work("o_given.hits")));
    CHECK(rtk::read_file(work("o_" + order + ".occl")) == rtk::read_file(work("o_given.occl")));
  }
}

TEST_CASE("cli: -packets changes how camera rays are traced, never the answer") {
  make_rays("primary", work("p.rays"), 5000);  // coherent: packets form
  const std::string trace = "trace -i " + scene_file() + " -rays " + work("p.rays");
  for (const std::string packets : {"on", "off"}) {
    const Result hits = run_rtk(trace + " -packets " + packets + " -hits " + work("p_" + packets + ".hits"));
    REQUIRE_MESSAGE(hits.status == 0, hits.output);
    const Result occl = run_rtk(trace + " -packets " + packets + " -occl " + work("p_" + packets + ".occl"));
    REQUIRE_MESSAGE(occl.status == 0, occl.output);
  }
  CHECK(rtk::read_file(work("p_on.hits")) == rtk::read_file(work("p_off.hits")));
  CHECK(rtk::read_file(work("p_on.occl")) == rtk::read_file(work("p_off.occl")));
}
