// The public API: every configuration it accepts traces a small scene like the brute-force
// oracle on every ISA, `.fast` and `.accurate` resolve per layout, the defaults follow chapter
// 6's rule, and bad strings are refused with the list of supported ones.
#include <doctest/doctest.h>

#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "07_intersectors/triangle_config.h"
#include "10_kernel_api/accel.h"
#include "10_kernel_api/motion_accel.h"
#include "testing/brute_force.h"
#include "01_base/ray_sets.h"
#include "testing/sanitizer_build.h"
#include "testing/scenes.h"

namespace {

using namespace rtk;

/// The message an invalid configuration is refused with, or "" if it is accepted.
std::string refusal(const AccelConfig& config) {
  try {
    resolve_config(config);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

/// A closed sphere, a soup with zero-area triangles and a few long diagonal triangles (which
/// the spatial splits cut), in one scene.
TriangleMesh mixed_scene() {
  TriangleMesh mesh = test::make_sphere(10, 20, {0.5f, 0.5f, 0.5f}, 0.3f);
  const TriangleMesh soup = test::make_random_soup(300, 601);
  const TriangleMesh slivers = test::make_slivers(40, 602);
  for (const TriangleMesh* part : {&soup, &slivers}) {
    const uint32_t base = uint32_t(mesh.vertices.size());
    mesh.vertices.insert(mesh.vertices.end(), part->vertices.begin(), part->vertices.end());
    for (auto t : part->triangles) mesh.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  }
  test::add_degenerate_triangles(mesh, 20, 603);
  return mesh;
}

}  // namespace

TEST_CASE("ch10: every accepted configuration agrees with brute force on every ISA") {
  const TriangleMesh mesh = mixed_scene();
  const std::vector<Ray> rays = test::mixed_rays(mesh.bounds(), 200, 604);
  std::vector<Hit> oracle(rays.size());
  std::vector<uint8_t> oracle_occluded(rays.size());
  for (size_t i = 0; i < rays.size(); ++i) {
    oracle[i] = test::brute_force_intersect(mesh, rays[i]);
    oracle_occluded[i] = test::brute_force_occluded(mesh, rays[i]) ? 1 : 0;
  }
  int configs = 0;
  for (const std::string& accel : supported_accels()) {
    for (const std::string& tri : supported_tris(accel)) {
      for (const Isa isa : supported_isas()) {
        CAPTURE(accel);
        CAPTURE(tri);
        CAPTURE(std::string(isa_name(isa)));
        AccelConfig config;
        config.accel = accel, config.tri = tri, config.isa = isa;
        const Accel structure(mesh, config);
        CHECK(structure.info().accel == accel);
        CHECK(structure.info().tri == tri);
        std::vector<Hit> hits(rays.size());
        std::vector<uint8_t> blocked(rays.size());
        structure.intersect(rays, hits);
        structure.occluded(rays, blocked);
        int wrong = 0, wrong_occlusion = 0;
        std::string first;
        for (size_t i = 0; i < rays.size(); ++i) {
          const std::string why = test::compare_hits(mesh, rays[i], hits[i], oracle[i]);
          if (!why.empty() && first.empty()) first = why;
          wrong += why.empty() ? 0 : 1;
          if (why.empty() && blocked[i] != (hits[i].found() ? 1 : 0) && blocked[i] != oracle_occluded[i])
            ++wrong_occlusion;
        }
        CAPTURE(first);
        CHECK(wrong == 0);
        CHECK(wrong_occlusion == 0);
      }
      ++configs;
    }
  }
  // bvh2, bvh4 and bvh8: all 15 layout configurations with both splits.
  CHECK(configs == 6 * 15);
}

// [ch10-test-one-answer]
TEST_CASE("ch10: for one intersector, every structure, layout and ISA gives the same bits") {
  // The hits and occlusion of the first configuration of each intersector, then every other
  // configuration with that intersector (bvh2/bvh4/bvh8, object and spatial splits, every
  // layout that has it) on every ISA, compared bit for bit: t, u, v, primID and occlusion.
  const TriangleMesh mesh = mixed_scene();
  std::vector<Ray> rays = test::mixed_rays(mesh.bounds(), 400, 605);
  const std::vector<Ray> inside = test::random_rays(mesh.bounds(), 400, 606);
  rays.insert(rays.end(), inside.begin(), inside.end());
  // Under the sanitizers, a sample of the rays on the scalar and the best ISA.
  rays = test::sanitizer_sample(rays, 8);
  std::vector<Isa> isas = supported_isas();
  if (test::kSanitizerBuild) isas = {Isa::scalar, best_isa()};
  struct Answer {
    std::string config;
    std::vector<Hit> hits;
    std::vector<uint8_t> blocked;
  };
  std::map<IntersectorKind, Answer> first;
  int compared = 0;
  for (const std::string& accel : supported_accels())
    for (const std::string& tri : supported_tris(accel))
      for (const Isa isa : isas) {
        AccelConfig config;
        config.accel = accel, config.tri = tri, config.isa = isa;
        const Accel structure(mesh, config);
        Answer answer{accel + " " + tri + " " + std::string(isa_name(isa)), std::vector<Hit>(rays.size()),
                      std::vector<uint8_t>(rays.size())};
        structure.intersect(rays, answer.hits);
        structure.occluded(rays, answer.blocked);
        const auto [it, is_first] = first.try_emplace(parse_triangle_config(tri).intersector, answer);
        if (is_first) continue;
        CAPTURE(answer.config);
        CAPTURE(it->second.config);
        int differ = 0;
        for (size_t i = 0; i < rays.size(); ++i)
          differ += !test::same_bits(answer.hits[i], it->second.hits[i]) || answer.blocked[i] != it->second.blocked[i];
        CHECK(differ == 0);
        ++compared;
      }
  CHECK(first.size() == 3);
  CHECK(compared > 0);
}
// [ch10-test-one-answer]

TEST_CASE("ch10: the table offers every configuration chapter 6 supports, with both split strategies") {
  std::set<std::string> chapter6;
  for (const TriangleConfig& c : supported_triangle_configs()) chapter6.insert(c.name());
  for (const std::string base : {"bvh2", "bvh4", "bvh8"})
    for (const std::string split : {".objectsplit", ".spatialsplit"}) {
      const std::vector<std::string> tris = supported_tris(base + split);
      CHECK(std::set<std::string>(tris.begin(), tris.end()) == chapter6);
      CHECK(tris.size() == chapter6.size());
    }
  const std::vector<std::string> accels = supported_accels();
  for (const std::string name : {"bvh2.objectsplit", "bvh2.spatialsplit", "bvh4.objectsplit", "bvh4.spatialsplit",
                                 "bvh8.objectsplit", "bvh8.spatialsplit"})
    CHECK(std::count(accels.begin(), accels.end(), name) == 1);
}

TEST_CASE("ch10: .fast and .accurate resolve per layout, and bare names take the defaults") {
  auto tri_of = [](const std::string& accel, const std::string& tri) {
    AccelConfig c;
    c.accel = accel, c.tri = tri;
    return resolve_config(c).tri;
  };
  CHECK(tri_of("bvh4", "triangle4v.accurate") == "triangle4v.watertight");
  CHECK(tri_of("bvh8", "triangle1i.accurate") == "triangle1i.watertight");
  CHECK(tri_of("bvh4", "triangle4.accurate") == "triangle4.moeller");  // precomputed: Möller only
  CHECK(tri_of("bvh4", "triangle4i.fast") == "triangle4i.moeller");
  CHECK(tri_of("bvh8.spatialsplit", "triangle4v") == "triangle4v.moeller");
  CHECK(tri_of("bvh4", "triangle1v.pluecker") == "triangle1v.pluecker");
  CHECK(tri_of("bvh2", "triangle1.accurate") == "triangle1.moeller");
  CHECK(tri_of("bvh2", "triangle4i.accurate") == "triangle4i.watertight");
  CHECK(tri_of("bvh2.spatialsplit", "triangle8") == "triangle8.moeller");
  AccelConfig c;
  c.accel = "bvh4";
  CHECK(resolve_config(c).accel == "bvh4.objectsplit");
  c.accel = "bvh4.spatialsplit";
  CHECK(resolve_config(c).accel == "bvh4.spatialsplit");
}

TEST_CASE("ch10: the default layout follows chapter 6's rule and says why") {
  for (const Isa isa : supported_isas()) {
    CAPTURE(std::string(isa_name(isa)));
    AccelConfig config;
    config.isa = isa;
    const AccelInfo info = resolve_config(config);
    CHECK(info.accel == (isa == Isa::avx2 || isa == Isa::avx512 ? "bvh8.objectsplit" : "bvh4.objectsplit"));
    const int width = isa == Isa::avx2 || isa == Isa::avx512 ? 8 : 4;
    CHECK(info.tri == std::string(layout_name(choose_default_layout(0, isa, width))) + ".moeller");
    CHECK(contains(info.choice, "default"));
    // A scene too large for the memory budget gets the leanest layout.
    const TriangleMesh mesh = test::make_sphere(20, 40);
    config.memory_budget = 1000;
    const Accel lean(mesh, config);
    CHECK(lean.info().tri == "triangle4i.moeller");
    CHECK(contains(lean.info().choice, "leanest"));
    // BVH2 follows the same rule.
    config.accel = "bvh2";
    config.memory_budget = 0;
    CHECK(resolve_config(config).tri == std::string(layout_name(choose_default_layout(0, isa, 2))) + ".moeller");
  }
}

TEST_CASE("ch10: unsupported configurations are refused with the supported list") {
  AccelConfig c;
  c.accel = "bvh3";
  std::string why = refusal(c);
  CHECK(contains(why, "-accel"));
  CHECK(contains(why, "bvh8.spatialsplit"));
  c.accel = "bvh4.nosplit";
  CHECK(contains(refusal(c), "bvh4.objectsplit"));
  c.accel = "bvh4";
  c.tri = "triangle4.pluecker";  // precomputed edges: Möller-Trumbore only
  why = refusal(c);
  CHECK(contains(why, "-tri"));
  CHECK(contains(why, "triangle4v.pluecker"));
  c.tri = "triangle5";
  CHECK(contains(refusal(c), "triangle4i.watertight"));
  c.tri = "triangle4.fastest";
  CHECK(contains(refusal(c), "-tri"));
  c.accel = "bvh2.spatialsplit";  // BVH2 refuses what BVH4 refuses, and names the same list
  c.tri = "triangle4.watertight";
  why = refusal(c);
  CHECK(contains(why, "-tri"));
  CHECK(contains(why, "supported with bvh2.spatialsplit"));
  CHECK(contains(why, "triangle4v.watertight"));
  c.tri = "triangle4";
  CHECK(refusal(c) == "");
  c.tri = "";
  CHECK(refusal(c) == "");
}

TEST_CASE("ch10: a vertex index past the vertices is refused by every structure, naming the triangle") {
  // Triangle 3 of a small sphere names a vertex that does not exist. Every structure refuses
  // the scene before it reads a vertex, with the builders' message: which triangle, which
  // vertex, how many there are.
  TriangleMesh mesh = test::make_sphere(4, 4);
  const uint32_t past = uint32_t(mesh.vertices.size()) + 5;
  mesh.triangles[3][1] = past;
  std::vector<std::string> accels = supported_accels();
  accels.push_back("");                         // the default
  accels.push_back(std::string(kMotionAccel));  // chapter 8's, on a scene that does not move
  for (const std::string& accel : accels) {
    CAPTURE(accel);
    AccelConfig config;
    config.accel = accel;
    std::string message;
    try {
      Accel built(mesh, config);
    } catch (const std::invalid_argument& e) {
      message = e.what();
    }
    CHECK(contains(message, "triangle 3 names vertex " + std::to_string(past)));
  }
}

TEST_CASE("ch10: a batch traced sorted or in packets gives the answers of the batch traced one ray at a time") {
  // Chapter 9's order and packets change when and with what each ray is traced, never its
  // answer: the same bits with the order always, never and automatic (which traces this small
  // scene's batches as given), with packets and without, on one and on two threads, for
  // incoherent rays and for rays from one point (which form packets). The batches are larger
  // than the policy's minimum and cross a thread's share.
  const TriangleMesh mesh = mixed_scene();
  std::vector<Ray> incoherent = test::random_rays(mesh.bounds(), 6000, 611);
  const std::vector<Ray> mixed = test::mixed_rays(mesh.bounds(), 400, 612);
  incoherent.insert(incoherent.end(), mixed.begin(), mixed.end());
  std::vector<Ray> camera = test::random_rays(mesh.bounds(), 5000, 613);
  for (Ray& r : camera) r.dir = r.dir - r.org + Vec3f{0.5f, 0.5f, -3.0f}, r.org = {0.5f, 0.5f, -3.0f};
  for (const std::vector<Ray>* rays : {&incoherent, &camera}) {
    std::vector<Hit> given(rays->size());
    std::vector<uint8_t> given_blocked(rays->size());
    AccelConfig config;
    config.order = RayOrderPolicy::Mode::never;
    config.packets = false;
    const Accel reference(mesh, config);
    reference.intersect(*rays, given);
    reference.occluded(*rays, given_blocked);
    for (const auto order : {RayOrderPolicy::Mode::always, RayOrderPolicy::Mode::automatic, RayOrderPolicy::Mode::never})
      for (const bool packets : {true, false})
      for (const int threads : {1, 2}) {
        config.order = order, config.packets = packets, config.threads = threads;
        const Accel accel(mesh, config);
        std::vector<Hit> hits(rays->size());
        std::vector<uint8_t> blocked(rays->size(), 7);
        accel.intersect(*rays, hits);
        accel.occluded(*rays, blocked);
        int differ = 0;
        for (size_t i = 0; i < rays->size(); ++i)
          differ += !test::same_bits(hits[i], given[i]) || blocked[i] != given_blocked[i];
        CHECK(differ == 0);
      }
  }
}
