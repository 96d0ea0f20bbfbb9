// Chapter 8: the moving mesh: mismatched pairs are refused naming both meshes, sparse storage
// keeps only the moving vertices, and positions are exact where they must be.
#include <stdexcept>
#include <string>

#include "test_support_ch08.h"

using namespace rtk;

namespace {

std::string refusal(const TriangleMesh& t0, const TriangleMesh& t1) {
  try {
    check_motion_pair(t0, t1, "S0.obj", "S1.obj");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("ch08: a mesh at time 1 that does not match is refused, naming both files") {
  const test::MovingScene scene = test::make_moving_scene(0.1f, 1);
  CHECK(refusal(scene.t0, scene.t1).empty());

  TriangleMesh fewer_vertices = scene.t1;
  fewer_vertices.vertices.pop_back();
  TriangleMesh fewer_triangles = scene.t1;
  fewer_triangles.triangles.pop_back();
  TriangleMesh other_face = scene.t1;
  std::swap(other_face.triangles[7][0], other_face.triangles[7][1]);  // same vertices, other order
  for (const auto& [bad, what] : {std::pair{&fewer_vertices, "vertices"}, std::pair{&fewer_triangles, "triangles"},
                                  std::pair{&other_face, "triangle 7"}}) {
    const std::string message = refusal(scene.t0, *bad);
    CAPTURE(message);
    CHECK(contains(message, "S0.obj"));
    CHECK(contains(message, "S1.obj"));
    CHECK(contains(message, what));
    CHECK_THROWS_AS(make_motion_mesh(scene.t0, *bad), std::invalid_argument);
  }
  TriangleMesh bad_index = scene.t0;
  bad_index.triangles[0][2] = uint32_t(bad_index.vertices.size());
  CHECK_THROWS_AS(make_motion_mesh(bad_index, bad_index), std::invalid_argument);
}

TEST_CASE("ch08: sparse storage keeps the moving vertices only, and both storages move them alike") {
  const test::MovingScene scene = test::make_moving_scene(0.1f, 2);
  const MotionMesh sparse = make_motion_mesh(scene.t0, scene.t1, MotionStorage::sparse);
  const MotionMesh dense = make_motion_mesh(scene.t0, scene.t1, MotionStorage::dense);
  size_t moving = 0;
  for (size_t v = 0; v < scene.t0.vertices.size(); ++v) moving += scene.t0.vertices[v] == scene.t1.vertices[v] ? 0 : 1;
  REQUIRE(moving > 0);
  REQUIRE(moving < scene.t0.vertices.size());
  CHECK(sparse.moving == moving);
  CHECK(dense.moving == moving);
  CHECK(sparse.motion.size() == moving + 1);  // plus the shared zero in slot 0
  CHECK(dense.motion.size() == scene.t0.vertices.size());
  const size_t n = scene.t0.vertices.size();
  CHECK(sparse.vertex_bytes() == n * 16 + (moving + 1) * 12);
  CHECK(dense.vertex_bytes() == n * 24);
  for (uint32_t v = 0; v < n; ++v) {
    CAPTURE(v);
    const Vec3f p0 = scene.t0.vertices[v], p1 = scene.t1.vertices[v];
    // Exact at time 0; p1 up to the rounding of p1 - p0 at time 1; a static vertex never moves.
    CHECK(sparse.position(v, 0.0f) == p0);
    const Vec3f e = sparse.position(v, 1.0f) - p1;
    CHECK(reduce_max(abs(e)) <= 0x1p-23f * reduce_max(max(abs(p0), abs(p1))));
    if (p0 == p1) CHECK(sparse.position(v, 0.37f) == p0);
    for (const float t : {0.0f, 0.25f, 0.8f, 1.0f}) CHECK(sparse.position(v, t) == dense.position(v, t));
  }
  // Converting storage keeps every motion vector.
  const MotionMesh back = convert_storage(convert_storage(sparse, MotionStorage::dense), MotionStorage::sparse);
  CHECK(back.motion.size() == sparse.motion.size());
  for (uint32_t v = 0; v < n; ++v) CHECK(back.motion_of(v) == sparse.motion_of(v));
  // A static pair moves nothing and stores one zero.
  const MotionMesh still = make_motion_mesh(scene.t0, scene.t0);
  CHECK(!still.moves());
  CHECK(still.motion.size() == 1);
}
