// The motion-blur side of the public API (api/motion_accel.h): Accel(t0, t1) chooses bvh4mb when
// the scene moves and the static default when it does not, refuses what cannot trace motion,
// and its hits are the chapter's hits at each ray's time.
#include <doctest/doctest.h>

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "10_kernel_api/accel.h"
#include "10_kernel_api/motion_accel.h"
#include "testing/brute_force.h"
#include "01_base/ray_sets.h"
#include "testing/scenes.h"

using namespace rtk;

namespace {

// A sphere that moves by (0.3, 0.1, 0) over the shutter, and the mesh at time t as chapter 8
// computes it (p0 + t (p1 - p0)).
struct Pair {
  TriangleMesh t0 = test::make_sphere(10, 16, {0.5f, 0.5f, 0.5f}, 0.3f), t1 = t0;
  Pair() {
    for (Vec3f& v : t1.vertices) v += Vec3f{0.3f, 0.1f, 0.0f};
  }
  TriangleMesh at(float t) const {
    TriangleMesh m = t0;
    for (size_t v = 0; v < m.vertices.size(); ++v) {
      const Vec3f p0 = t0.vertices[v], d = t1.vertices[v] - p0;
      m.vertices[v] = {p0.x + t * d.x, p0.y + t * d.y, p0.z + t * d.z};
    }
    return m;
  }
};

// A configuration without designated initializers (which -Wextra wants complete).
AccelConfig make_config(const std::string& accel, const std::string& tri = "", std::optional<Isa> isa = std::nullopt,
                        int threads = 1) {
  AccelConfig c;
  c.accel = accel, c.tri = tri, c.isa = isa, c.threads = threads;
  return c;
}

std::string refusal(const TriangleMesh& t0, const TriangleMesh& t1, const AccelConfig& config) {
  try {
    Accel accel(t0, t1, config);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("ch10: Accel(t0, t1) builds bvh4mb for a moving scene and traces at each ray's time") {
  const Pair pair;
  std::vector<Ray> rays = test::random_rays(merge(pair.t0.bounds(), pair.t1.bounds()), 300, 4);
  for (size_t i = 0; i < rays.size(); ++i) rays[i].time = float(i % 11) / 10.0f;
  for (const Isa isa : supported_isas())
    for (const std::string tri : {"", "triangle4i.pluecker", "triangle4i.accurate"}) {
      CAPTURE(isa_name(isa));
      CAPTURE(tri);
      const Accel accel(pair.t0, pair.t1, make_config("", tri, isa, 2));
      CHECK(accel.info().accel == "bvh4mb.objectsplit");
      CHECK(accel.info().tri.starts_with("triangle4i."));
      CHECK(accel.info().bytes > 0);
      std::vector<Hit> hits(rays.size());
      std::vector<uint8_t> occluded(rays.size());
      accel.intersect(rays, hits);
      accel.occluded(rays, occluded);
      size_t found = 0;
      for (size_t i = 0; i < rays.size(); ++i) {
        const TriangleMesh at = pair.at(rays[i].time);
        const std::string why = test::compare_hits(at, rays[i], hits[i], test::brute_force_intersect(at, rays[i]));
        CHECK_MESSAGE(why.empty(), "ray ", i, ": ", why);
        CHECK(occluded[i] == uint8_t(hits[i].found()));
        found += hits[i].found();
      }
      CHECK(found > rays.size() / 10);
    }
}

TEST_CASE("ch10: a static pair builds the static default; bvh4mb builds on one mesh too") {
  const Pair pair;
  const Accel still(pair.t0, pair.t0);
  const AccelInfo plain = resolve_config({});
  CHECK(still.info().accel == plain.accel);
  CHECK(still.info().tri == plain.tri);
  // Forced, the motion structure gives the static structure's hits on a static scene.
  const Accel forced(pair.t0, pair.t0, make_config("bvh4mb"));
  CHECK(forced.info().accel == "bvh4mb.objectsplit");
  const std::vector<Ray> rays = test::random_rays(pair.t0.bounds(), 200, 8);
  std::vector<Hit> a(rays.size()), b(rays.size());
  still.intersect(rays, a);
  forced.intersect(rays, b);
  for (size_t i = 0; i < rays.size(); ++i) {
    const Hit oracle = test::brute_force_intersect(pair.t0, rays[i]);
    CHECK(test::compare_hits(pair.t0, rays[i], a[i], oracle) == "");
    CHECK(test::compare_hits(pair.t0, rays[i], b[i], oracle) == "");
  }

  // As in Embree 1.1, the motion structure builds on a static scene: every vertex stands still.
  const Accel one(pair.t0, make_config("bvh4mb"));
  CHECK(one.info().accel == "bvh4mb.objectsplit");
  std::vector<Hit> c(rays.size());
  one.intersect(rays, c);
  for (size_t i = 0; i < rays.size(); ++i)
    CHECK(test::compare_hits(pair.t0, rays[i], c[i], test::brute_force_intersect(pair.t0, rays[i])) == "");
  CHECK(refusal(pair.t0, pair.t1, make_config("bvh4")).find("cannot trace motion") != std::string::npos);
  CHECK(refusal(pair.t0, pair.t1, make_config("bvh4mb.spatialsplit")).find("object splits") != std::string::npos);
  CHECK(refusal(pair.t0, pair.t1, make_config("", "triangle4")).find("-tri") != std::string::npos);
  CHECK(refusal(pair.t0, pair.t1, make_config("", "", std::nullopt, 0)).find("-threads") !=
        std::string::npos);
  TriangleMesh fewer = pair.t1;
  fewer.triangles.pop_back();
  CHECK(refusal(pair.t0, fewer, {}).find("triangles") != std::string::npos);
  CHECK_THROWS_WITH_AS(check_motion_meshes(pair.t0, fewer, "a.obj", "b.obj"), doctest::Contains("b.obj does not match a.obj"),
                       std::invalid_argument);
}

TEST_CASE("ch10: motion is stored sparsely unless most vertices move") {
  // Sparse storage costs 16 bytes per vertex plus 12 per moving one, dense 24 per vertex: the
  // API keeps sparse motion while fewer than two vertices in three move (chapter 8).
  const Pair all_move;
  const Accel dense(all_move.t0, all_move.t1, make_config(""));
  CHECK(dense.info().choice.find("dense motion") != std::string::npos);
  Pair few_move;
  few_move.t1 = few_move.t0;
  for (size_t v = 0; v < few_move.t1.vertices.size(); v += 4) few_move.t1.vertices[v] += Vec3f{0.01f, 0, 0};
  const Accel sparse(few_move.t0, few_move.t1, make_config(""));
  CHECK(sparse.info().choice.find("sparse motion") != std::string::npos);
  // Both storages trace the same scene to the same hits (chapter 8 checks it bit for bit).
  std::vector<Ray> rays = test::random_rays(merge(all_move.t0.bounds(), all_move.t1.bounds()), 200, 5);
  for (size_t i = 0; i < rays.size(); ++i) rays[i].time = float(i % 7) / 6.0f;
  std::vector<Hit> hits(rays.size());
  dense.intersect(rays, hits);
  for (size_t i = 0; i < rays.size(); ++i) {
    const TriangleMesh at = all_move.at(rays[i].time);
    const std::string why = test::compare_hits(at, rays[i], hits[i], test::brute_force_intersect(at, rays[i]));
    CHECK_MESSAGE(why.empty(), "ray ", i, ": ", why);
  }
}
