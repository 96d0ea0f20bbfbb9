// Chapter 16 tests: the orbit camera's gestures, checked against their analytic answers.
// (tests/render reads its printed .ecs options back with the scene-script parser.)
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "11_sampling/warp.h"  // kPi
#include "16_viewer/orbit_camera.h"
#include "14_pathtracer/accel_kernels.h"

using namespace rtk;

namespace {


// A view that is not aligned with any axis, with a tilted up direction.
OrbitCamera oblique() {
  OrbitCamera c;
  c.eye = {3, 2, -7};
  c.centre = {0.5f, 1, 0.25f};
  c.up = {0.1f, 1, 0.05f};
  c.fov_degrees = 45;
  return c;
}

bool near(Vec3f a, Vec3f b, float tolerance) { return length(a - b) <= tolerance; }

}  // namespace

TEST_CASE("ch16: a full turn of azimuth brings the eye back; elevation up and down cancels") {
  const OrbitCamera start = oblique();
  OrbitCamera c = start;
  for (int i = 0; i < 36; ++i) c.rotate(2 * kPi / 36, 0);
  CHECK(near(c.eye, start.eye, 1e-4f * start.distance()));
  CHECK(c.centre == start.centre);
  c.rotate(0, 0.3f);
  CHECK(c.eye.y > start.eye.y);  // positive elevation raises the eye
  CHECK(std::fabs(c.distance() - start.distance()) < 1e-4f * start.distance());
  c.rotate(0, -0.3f);
  CHECK(near(c.eye, start.eye, 1e-4f * start.distance()));
}

TEST_CASE("ch16: a quarter turn of azimuth about y moves the eye to the side") {
  OrbitCamera c;
  c.eye = {0, 0, -10};
  c.centre = {0, 0, 0};
  c.rotate(kPi / 2, 0);
  // About +y, a quarter turn takes -z to -x (Rodrigues: y x (-z) = -x).
  CHECK(near(c.eye, {-10, 0, 0}, 1e-4f));
}

TEST_CASE("ch16: elevation stops short of the poles") {
  OrbitCamera c = oblique();
  c.rotate(0, 10.0f);  // far past the top
  const float from_up = std::acos(dot(normalize(c.eye - c.centre), normalize(c.up)));
  CHECK(from_up == doctest::Approx(kPi / 180).epsilon(1e-3));
  CHECK_NOTHROW(Camera(c.to_params(1.0f)));
  c.rotate(0, -10.0f);
  const float from_down = std::acos(dot(normalize(c.eye - c.centre), -normalize(c.up)));
  CHECK(from_down == doctest::Approx(kPi / 180).epsilon(1e-3));
}

TEST_CASE("ch16: pan keeps the view direction and moves by image heights") {
  OrbitCamera c;
  c.eye = {0, 0, -10};
  c.centre = {0, 0, 0};
  c.fov_degrees = 90;  // one image height at the centre = 2 * 10 * tan(45 deg) = 20
  const Vec3f before = c.forward();
  c.pan(0.25f, 0.5f);
  CHECK(near(c.forward(), before, 1e-6f));
  CHECK(c.distance() == doctest::Approx(10));
  // Right is +x and up +y here; the camera moves against the gesture by 5 and 10 units.
  CHECK(near(c.eye, {-5, -10, -10}, 1e-4f));
  CHECK(near(c.centre, {-5, -10, 0}, 1e-4f));

  OrbitCamera o = oblique();
  const Vec3f dir = o.forward();
  o.pan(-0.3f, 0.7f);
  CHECK(near(o.forward(), dir, 1e-5f));
}

TEST_CASE("ch16: a right-handed orbit camera pans with its mirrored image") {
  // The image's right is -x here (chapter 11): a drag to the right still drags the scene along.
  OrbitCamera c;
  c.eye = {0, 0, -10};
  c.centre = {0, 0, 0};
  c.fov_degrees = 90;
  c.right_handed = true;
  c.pan(0.25f, 0.5f);
  CHECK(near(c.eye, {5, -10, -10}, 1e-4f));
  // The scene point under the image's right edge is where the camera's own right column looks.
  const Ray r = c.ray_through({1.0f, 0.5f}, 1.0f);
  CHECK(r.dir.x < 0.0f);
  CHECK(c.to_params(1.0f).right_handed);
  CHECK(OrbitCamera::from_params(c.to_params(1.0f)).right_handed);
}

TEST_CASE("ch16: dolly keeps the centre, scales the distance and reverses exactly") {
  OrbitCamera c = oblique();
  const OrbitCamera start = c;
  c.dolly(std::log(2.0f));
  CHECK(c.centre == start.centre);
  CHECK(c.distance() == doctest::Approx(start.distance() / 2).epsilon(1e-5));
  CHECK(near(c.forward(), start.forward(), 1e-5f));
  c.dolly(-std::log(2.0f));
  CHECK(near(c.eye, start.eye, 1e-4f * start.distance()));
  for (int i = 0; i < 100; ++i) c.dolly(1.0f);  // stops short of the centre
  CHECK(c.distance() == doctest::Approx(1e-4f).epsilon(1e-2).scale(0));  // relative, at this size
  CHECK(near(c.forward(), start.forward(), 1e-3f));
  CHECK_NOTHROW(Camera(c.to_params(1.0f)));
}

TEST_CASE("ch16: roll keeps the view direction and turns the image's up") {
  OrbitCamera c;
  c.eye = {0, 0, -10};
  c.centre = {0, 0, 0};
  c.roll(kPi / 2);
  CHECK(near(c.eye, {0, 0, -10}, 0));
  CHECK(near(c.forward(), {0, 0, 1}, 1e-6f));
  // About +z, a quarter turn takes +y to -x.
  CHECK(near(c.up, {-1, 0, 0}, 1e-6f));
  OrbitCamera o = oblique();
  const Vec3f dir = o.forward();
  o.roll(0.4f);
  o.roll(-0.4f);
  CHECK(near(o.forward(), dir, 1e-6f));
  CHECK(near(o.up, oblique().up, 1e-5f));
}

TEST_CASE("ch16: picking finds a known plane; Ctrl+click and Ctrl+Shift+click use the point") {
  // A square of side 20 in the plane z = 5, traced by RTK's kernels.
  RenderScene scene;
  scene.mesh.vertices = {{-10, -10, 5}, {10, -10, 5}, {10, 10, 5}, {-10, 10, 5}};
  scene.mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  const AccelKernels kernels(scene, AccelConfig{});

  OrbitCamera c;
  c.eye = {0, 0, -5};
  c.centre = {0, 0, 0};
  c.fov_degrees = 90;
  // The image centre sees (0, 0, 5). An eighth of the image to the right and up is a quarter
  // of the half height, which at depth 10 is 10 (tan 45 deg = 1): (2.5, 2.5, 5) for aspect 1.
  const auto centre_hit = c.pick(kernels, {0.5f, 0.5f}, 1.0f);
  REQUIRE(centre_hit);
  CHECK(near(*centre_hit, {0, 0, 5}, 1e-4f));
  const auto off_hit = c.pick(kernels, {0.625f, 0.375f}, 1.0f);
  REQUIRE(off_hit);
  CHECK(near(*off_hit, {2.5f, 2.5f, 5}, 1e-4f));
  // Looking away from the square finds nothing.
  OrbitCamera away = c;
  away.centre = {0, 0, -10};
  CHECK_FALSE(away.pick(kernels, {0.5f, 0.5f}, 1.0f));

  // Focus: the plane's depth along the view, whatever point of it was clicked.
  CHECK(c.focus_on(*off_hit));
  CHECK(c.focal_distance == doctest::Approx(10));
  CHECK_FALSE(c.focus_on({0, 0, -6}));  // behind the eye
  // Centre of interest: the eye stays and now looks at the point.
  CHECK(c.look_at(*off_hit));
  CHECK(c.eye == Vec3f{0, 0, -5});
  CHECK(near(c.forward(), normalize(Vec3f{2.5f, 2.5f, 10}), 1e-5f));
  CHECK_FALSE(c.look_at(c.eye));
  CHECK_FALSE(c.look_at(c.eye + Vec3f{0, 3, 0}));  // straight above: no image
}
