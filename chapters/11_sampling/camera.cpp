#include "11_sampling/camera.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "11_sampling/warp.h"

namespace rtk {

namespace {
void require(bool ok, const char* what) {
  if (!ok) throw std::invalid_argument(std::string("camera: ") + what);
}
}  // namespace

Camera::Camera(const CameraParams& p) : params_(p) {
  require(is_finite(p.position) && is_finite(p.look_at) && is_finite(p.up),
          "position, look-at point and up vector must be finite");
  require(std::isfinite(p.fov_degrees) && p.fov_degrees > 0.0f && p.fov_degrees < 180.0f,
          "field of view must lie in (0, 180) degrees");
  require(std::isfinite(p.aspect) && p.aspect > 0.0f, "aspect ratio must be positive");
  require(std::isfinite(p.lens_radius) && p.lens_radius >= 0.0f, "lens radius must be >= 0");
  require(std::isfinite(p.focal_distance) && p.focal_distance >= 0.0f,
          "focal distance must be >= 0");
  const Vec3f view = p.look_at - p.position;
  require(length(view) > 0.0f, "look-at point equals the camera position");
  z_ = normalize(view);
  const Vec3f side = cross(p.up, z_);
  // The up vector must leave a usable sideways direction (not parallel to the view).
  require(length(side) > 1e-6f * length(p.up),
          "up vector is zero or parallel to the viewing direction");
  // [ch11-camera-handedness]
  // Up is the same in both conventions; only the image's right axis turns around.
  const Vec3f left_handed_right = normalize(side);
  v_ = cross(z_, left_handed_right);
  u_ = p.right_handed ? -left_handed_right : left_handed_right;
  // [ch11-camera-handedness]
  image_distance_ = 0.5f / std::tan(0.5f * p.fov_degrees * kPi / 180.0f);
  if (params_.focal_distance == 0.0f) params_.focal_distance = length(view);
}

// [ch11-camera-ray]
Ray Camera::generate_ray(Vec2f film, Vec2f lens, float time) const {
  // Pinhole direction through the film point: the film is a plane of height 1 at distance
  // 0.5 / tan(fov / 2), so its top and bottom edges are fov / 2 away from the view axis.
  const Vec3f dir =
      (film.x - 0.5f) * params_.aspect * u_ + (0.5f - film.y) * v_ + image_distance_ * z_;
  Ray ray;
  ray.time = time;
  if (params_.lens_radius == 0.0f) {
    ray.org = params_.position;
    ray.dir = normalize(dir);
    return ray;
  }
  // Thin lens: every ray through this film point meets the pinhole ray on the plane of
  // focus, at distance focal_distance along the view axis; start it from a point of the lens.
  const Vec3f focus = params_.position + dir * (params_.focal_distance / image_distance_);
  const Vec2f d = sample_uniform_disk(lens) * params_.lens_radius;
  ray.org = params_.position + d.x * u_ + d.y * v_;
  ray.dir = normalize(focus - ray.org);
  return ray;
}
// [ch11-camera-ray]

// [ch11-vignetting]
float Camera::vignetting(Vec2f film) const {
  if (!params_.vignetting) return 1.0f;
  // The chief ray through the film point makes the angle theta with the axis, where
  // cos(theta) = image distance / length of the pinhole direction. Irradiance on the film
  // falls as cos^4(theta): once for the lens seen obliquely (its projected area), twice for the
  // inverse square of the longer way to the film, once for the film met obliquely.
  const float x = (film.x - 0.5f) * params_.aspect, y = 0.5f - film.y;
  const float d2 = image_distance_ * image_distance_;
  const float cos2 = d2 / (x * x + y * y + d2);
  return cos2 * cos2;
}
// [ch11-vignetting]

}  // namespace rtk
