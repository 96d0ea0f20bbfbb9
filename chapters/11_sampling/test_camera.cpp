// Chapter 11 tests: cameras.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "11_sampling/camera.h"
#include "11_sampling/rng.h"

using namespace rtk;

namespace {
// The angle as 2 atan2(|a - b|, |a + b|) of the unit vectors: acos of their dot product
// resolves small angles to no better than a percent (for 0.06 degrees the cosine is 1 - 5.5e-7,
// nine float steps below 1), which a test of a narrow field of view cannot use.
float angle_between(Vec3f a, Vec3f b) {
  const Vec3f u = normalize(a), v = normalize(b);
  return 2.0f * std::atan2(length(u - v), length(u + v));
}
float degrees(float radians) { return radians * 180.0f / std::numbers::pi_v<float>; }

// The Cornell box view of Embree 1.1's cornell_box.ecs.
CameraParams cornell() {
  CameraParams p;
  p.position = {278, 273, -800};
  p.look_at = {278, 273, 0};
  p.up = {0, 1, 0};
  p.fov_degrees = 37;
  return p;
}
}  // namespace

TEST_CASE("ch11: the centre of the image looks at the point of interest") {
  CameraParams p;
  p.position = {1, 2, 3};
  p.look_at = {-4, 0.5f, 7};
  p.up = {0.2f, 1, 0.1f};
  p.aspect = 1.5f;
  const Camera camera(p);
  const Ray ray = camera.generate_ray({0.5f, 0.5f}, {0.5f, 0.5f}, 0.0f);
  CHECK(ray.org == p.position);
  CHECK(length(ray.dir - normalize(p.look_at - p.position)) < 1e-6f);
  CHECK(is_valid(ray));
}

TEST_CASE("ch11: the vertical field of view spans the image height") {
  for (float fov : {0.06f, 37.0f, 64.0f, 120.0f, 179.0f}) {
    CameraParams p = cornell();
    p.fov_degrees = fov;
    p.aspect = 2.0f;
    const Camera camera(p);
    const Vec3f top = camera.generate_ray({0.5f, 0.0f}, {}, 0).dir;
    const Vec3f bottom = camera.generate_ray({0.5f, 1.0f}, {}, 0).dir;
    const Vec3f left = camera.generate_ray({0.0f, 0.5f}, {}, 0).dir;
    const Vec3f right = camera.generate_ray({1.0f, 0.5f}, {}, 0).dir;
    // Relative errors (scale 0): doctest's default would let 0.06 degrees be off by 2 %.
    CHECK(degrees(angle_between(top, bottom)) == doctest::Approx(fov).epsilon(1e-5).scale(0));
    // The horizontal field follows from the aspect ratio: tan(h/2) = aspect * tan(v/2).
    const float h =
        2.0f * std::atan(2.0f * std::tan(0.5f * fov * std::numbers::pi_v<float> / 180.0f));
    CHECK(angle_between(left, right) == doctest::Approx(h).epsilon(1e-5).scale(0));
  }
}

TEST_CASE("ch11: the image is upright and right is the Embree convention's +x") {
  // Looking along +z with y up, the left-handed Embree 1.1 frame puts +x on the right.
  CameraParams p;
  p.look_at = {0, 0, 1};
  const Camera camera(p);
  CHECK(camera.right().x == doctest::Approx(1.0f));
  CHECK(camera.up().y == doctest::Approx(1.0f));
  CHECK(camera.generate_ray({0.5f, 0.0f}, {}, 0).dir.y > 0.0f);  // top row looks up
  CHECK(camera.generate_ray({1.0f, 0.5f}, {}, 0).dir.x > 0.0f);  // right column looks right
}

TEST_CASE("ch11: a right-handed camera sees the left-handed image mirrored left to right") {
  // Embree 3's default: the same eye, view and up, with the image's right axis turned around.
  for (float lens : {0.0f, 20.0f}) {
    CameraParams p = cornell();
    p.aspect = 1.5f;
    p.lens_radius = lens;
    const Camera left(p);
    p.right_handed = true;
    const Camera right(p);
    CHECK(length(right.right() + left.right()) < 1e-6f);
    CHECK(length(right.up() - left.up()) < 1e-6f);
    CHECK(length(right.forward() - left.forward()) < 1e-6f);
    // Film point (x, y) of one is film point (1 - x, y) of the other, lens point (u, v)
    // likewise (1 - u, v): the same ray, bit for bit up to rounding.
    Pcg32 rng(7);
    for (int i = 0; i < 100; ++i) {
      const Vec2f film{rng.next_float(), rng.next_float()}, l{rng.next_float(), rng.next_float()};
      const Ray a = left.generate_ray(film, l, 0);
      const Ray b = right.generate_ray({1.0f - film.x, film.y}, {1.0f - l.x, l.y}, 0);
      CHECK(length(a.dir - b.dir) < 1e-5f);
      CHECK(length(a.org - b.org) < 1e-3f);
    }
  }
  // Looking along +z with y up, right is -x: the measured Cornell box's red wall (x = 552.8)
  // on the left, as in the photographs.
  CameraParams p;
  p.look_at = {0, 0, 1};
  p.right_handed = true;
  CHECK(Camera(p).generate_ray({1.0f, 0.5f}, {}, 0).dir.x < 0.0f);
}

TEST_CASE("ch11: thin-lens rays through one film point meet on the plane of focus") {
  CameraParams p = cornell();
  p.lens_radius = 20.0f;
  p.focal_distance = 600.0f;
  const Camera lens(p);
  p.lens_radius = 0.0f;
  const Camera pinhole(p);
  Pcg32 rng(14);
  for (int film = 0; film < 20; ++film) {
    const Vec2f f{rng.next_float(), rng.next_float()};
    const Ray pin = pinhole.generate_ray(f, {}, 0);
    // Where the pinhole ray crosses the plane of focus (600 along the view axis).
    const Vec3f focus = pin.org + pin.dir * (600.0f / dot(pin.dir, pinhole.forward()));
    for (int s = 0; s < 10; ++s) {
      const Ray r = lens.generate_ray(f, {rng.next_float(), rng.next_float()}, 0);
      // The origin lies on the lens disk...
      const Vec3f offset = r.org - p.position;
      CHECK(std::fabs(dot(offset, lens.forward())) < 1e-3f);
      CHECK(length(offset) <= 20.0f * (1 + 1e-5f));
      // ...and the ray passes through the pinhole ray's point of focus.
      const Vec3f hit =
          r.org + r.dir * (dot(focus - r.org, lens.forward()) / dot(r.dir, lens.forward()));
      CHECK(length(hit - focus) < 1e-3f * 600.0f);
      CHECK(length(r.dir) == doctest::Approx(1.0f));
    }
  }
  // The default focal distance is the distance to the point of interest.
  CameraParams q = cornell();
  q.lens_radius = 1.0f;
  CHECK(Camera(q).params().focal_distance == doctest::Approx(800.0f));
}

TEST_CASE("ch11: camera rays carry the shutter time") {
  const Camera camera(cornell());
  CHECK(camera.generate_ray({0.3f, 0.7f}, {}, 0.625f).time == 0.625f);
  const Ray r = camera.generate_ray({0.3f, 0.7f}, {}, 0.0f);
  CHECK(r.tnear == 0.0f);
  CHECK(std::isinf(r.tfar));
}

TEST_CASE("ch11: bad camera parameters are refused with a reason") {
  auto with = [](auto change) {
    CameraParams p = cornell();
    change(p);
    return p;
  };
  CHECK_THROWS_AS(Camera(with([](CameraParams& p) { p.look_at = p.position; })),
                  std::invalid_argument);
  CHECK_THROWS_AS(Camera(with([](CameraParams& p) { p.up = {0, 0, 1}; })), std::invalid_argument);
  CHECK_THROWS_AS(Camera(with([](CameraParams& p) { p.up = {0, 0, 0}; })), std::invalid_argument);
  CHECK_THROWS_AS(Camera(with([](CameraParams& p) { p.fov_degrees = 0; })), std::invalid_argument);
  CHECK_THROWS_AS(Camera(with([](CameraParams& p) { p.fov_degrees = 180; })),
                  std::invalid_argument);
  CHECK_THROWS_AS(Camera(with([](CameraParams& p) { p.fov_degrees = NAN; })),
                  std::invalid_argument);
  CHECK_THROWS_AS(Camera(with([](CameraParams& p) { p.aspect = 0; })), std::invalid_argument);
  CHECK_THROWS_AS(Camera(with([](CameraParams& p) { p.lens_radius = -1; })), std::invalid_argument);
  CHECK_THROWS_AS(Camera(with([](CameraParams& p) { p.position.x = INFINITY; })),
                  std::invalid_argument);
  try {
    Camera(with([](CameraParams& p) { p.up = {0, 0, 1}; }));
  } catch (const std::invalid_argument& e) {
    CHECK(std::string(e.what()).find("parallel") != std::string::npos);
  }
}

TEST_CASE("ch11: natural vignetting falls off as cos^4 of the angle to the view axis") {
  CameraParams p;
  p.position = {0, 0, 0};
  p.look_at = {0, 0, 1};
  p.fov_degrees = 70.0f;
  p.aspect = 1.5f;
  // Off by default: every film point gets all the light.
  CHECK(Camera(p).vignetting({0.0f, 0.0f}) == 1.0f);
  CHECK(Camera(p).vignetting({0.9f, 0.3f}) == 1.0f);
  p.vignetting = true;
  const Camera camera(p);
  CHECK(camera.vignetting({0.5f, 0.5f}) == doctest::Approx(1.0f));
  // The top edge's centre is half the field of view off the axis.
  const double half = 35.0 * std::numbers::pi / 180.0;
  CHECK(camera.vignetting({0.5f, 0.0f}) == doctest::Approx(std::pow(std::cos(half), 4)).epsilon(1e-5));
  // Anywhere: the angle between the view axis and the ray through the lens centre, as the
  // camera generates it, to the fourth power of its cosine.
  Pcg32 rng(77);
  for (int i = 0; i < 100; ++i) {
    const Vec2f film{rng.next_float(), rng.next_float()};
    const Ray ray = camera.generate_ray(film, {0.5f, 0.5f}, 0.0f);
    const double c = dot(normalize(ray.dir), camera.forward());
    CHECK(camera.vignetting(film) == doctest::Approx(c * c * c * c).epsilon(1e-5));
  }
  // A thin lens darkens its corners as the pinhole does (the law follows the chief ray).
  p.lens_radius = 0.1f;
  CHECK(Camera(p).vignetting({0.0f, 1.0f}) == doctest::Approx(camera.vignetting({0.0f, 1.0f})));
}
