#include "16_viewer/orbit_camera.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace rtk {

namespace {

// [ch16-rotate-about]
// Rodrigues' rotation formula: v turned by `angle` about the unit axis k.
Vec3f rotate_about(Vec3f v, Vec3f k, float angle) {
  const float c = std::cos(angle), s = std::sin(angle);
  return v * c + cross(k, v) * s + k * (dot(k, v) * (1.0f - c));
}
// [ch16-rotate-about]

constexpr float kDegree = std::numbers::pi_v<float> / 180.0f;

}  // namespace

OrbitCamera OrbitCamera::from_params(const CameraParams& p) {
  OrbitCamera c;
  c.eye = p.position;
  c.centre = p.look_at;
  c.up = p.up;
  c.fov_degrees = p.fov_degrees;
  c.lens_radius = p.lens_radius;
  c.focal_distance = p.focal_distance;
  c.right_handed = p.right_handed;
  return c;
}

CameraParams OrbitCamera::to_params(float aspect) const {
  CameraParams p;
  p.position = eye;
  p.look_at = centre;
  p.up = up;
  p.fov_degrees = fov_degrees;
  p.aspect = aspect;
  p.lens_radius = lens_radius;
  p.focal_distance = focal_distance;
  p.right_handed = right_handed;
  return p;
}

Vec3f OrbitCamera::forward() const { return normalize(centre - eye); }
Vec3f OrbitCamera::right() const {
  const Vec3f u = normalize(cross(up, forward()));
  return right_handed ? -u : u;
}
float OrbitCamera::distance() const { return length(centre - eye); }

// [ch16-rotate]
void OrbitCamera::rotate(float azimuth, float elevation) {
  const Vec3f axis = normalize(up);
  // Azimuth: the eye's offset from the centre turns about the up direction.
  Vec3f offset = rotate_about(eye - centre, axis, azimuth);
  // Elevation: about the image's right axis, clamped so that the offset keeps at least one
  // degree from the up direction on either side (the angle from up shrinks as the eye rises).
  const float from_up = std::acos(std::clamp(dot(normalize(offset), axis), -1.0f, 1.0f));
  const float target = std::clamp(from_up - elevation, kDegree, 179.0f * kDegree);
  const Vec3f right_axis = normalize(cross(axis, -offset));
  offset = rotate_about(offset, right_axis, from_up - target);
  eye = centre + offset;
}
// [ch16-rotate]

// [ch16-pan-dolly-roll]
void OrbitCamera::pan(float dx, float dy) {
  // One image height at the centre's depth, in world units.
  const float height = 2.0f * distance() * std::tan(0.5f * fov_degrees * kDegree);
  // The image's up is the same in both conventions (chapter 11); its right is right().
  const Vec3f u = right(), v = cross(forward(), normalize(cross(up, forward())));
  // The camera moves against the gesture, so the scene follows the mouse.
  const Vec3f delta = (u * dx + v * dy) * -height;
  eye += delta;
  centre += delta;
}

void OrbitCamera::dolly(float amount) {
  // The eye stops where float positions could no longer tell it from the centre.
  const Vec3f a = abs(centre);
  const float closest = 1e-4f * std::max({1.0f, a.x, a.y, a.z});
  const float d = distance();
  const float target = std::max(d * std::exp(-amount), closest);
  eye = centre + (eye - centre) * (target / d);
}

void OrbitCamera::roll(float angle) { up = rotate_about(up, forward(), angle); }
// [ch16-pan-dolly-roll]

Ray OrbitCamera::ray_through(Vec2f film, float aspect) const {
  CameraParams p = to_params(aspect);
  p.lens_radius = 0.0f;
  return Camera(p).generate_ray(film, Vec2f{0.5f, 0.5f}, 0.0f);
}

// [ch16-pick]
std::optional<Vec3f> OrbitCamera::pick(const RayKernels& kernels, Vec2f film, float aspect) const {
  const Ray ray = ray_through(film, aspect);
  Hit hit;
  kernels.tracer().intersect(std::span<const Ray>(&ray, 1), std::span<Hit>(&hit, 1));
  if (!hit.found()) return std::nullopt;
  return ray.org + ray.dir * hit.t;
}

bool OrbitCamera::look_at(Vec3f point) {
  const Vec3f view = point - eye;
  const float len = length(view);
  if (!is_finite(point) || !(len > 0.0f)) return false;
  // Straight along the up direction there is no "right", hence no image.
  if (length(cross(view / len, normalize(up))) < 1e-4f) return false;
  centre = point;
  return true;
}

bool OrbitCamera::focus_on(Vec3f point) {
  const float depth = dot(point - eye, forward());
  if (!std::isfinite(depth) || !(depth > 0.0f)) return false;
  focal_distance = depth;
  return true;
}
// [ch16-pick]

std::string OrbitCamera::to_ecs_options() const {
  // Nine significant digits are enough to print any float so that it reads back exactly.
  char buffer[512];
  std::snprintf(buffer, sizeof buffer,
                "-vp %.9g %.9g %.9g -vi %.9g %.9g %.9g -vu %.9g %.9g %.9g -fov %.9g -radius %.9g "
                "-focaldistance %.9g %s",
                eye.x, eye.y, eye.z, centre.x, centre.y, centre.z, up.x, up.y, up.z, fov_degrees,
                lens_radius, focal_distance, right_handed ? "-righthanded" : "-lefthanded");
  return buffer;
}

}  // namespace rtk
