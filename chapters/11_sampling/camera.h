/// \file
/// Cameras: the pinhole camera of the Embree 1.1 viewer and the thin-lens camera that
/// replaces it when a lens radius is given, with the guide's parameters (-vp, -vi, -vu, -fov,
/// -radius).
#pragma once

#include "01_base/ray.h"
#include "11_sampling/vec2.h"

namespace rtk {

/// What places and shapes a camera. Defaults are the Embree 1.1 viewer's.
struct CameraParams {
  Vec3f position{0, 0, 0};    ///< -vp: the eye (the centre of the lens)
  Vec3f look_at{1, 0, 0};     ///< -vi: the point of interest, seen at the centre of the image
  Vec3f up{0, 1, 0};          ///< -vu: the up direction (need not be orthogonal to the view)
  float fov_degrees = 64.0f;  ///< -fov: the vertical field of view in degrees, in (0, 180)
  float aspect = 1.0f;        ///< image width / height
  float lens_radius = 0.0f;   ///< -radius: 0 is a pinhole; > 0 a thin lens (depth of field)
  float focal_distance = 0;   ///< distance to the plane in focus; 0 means |look_at - position|
  bool right_handed = false;  ///< -righthanded: the image mirrored left to right (Embree 2/3)
  bool vignetting = false;    ///< -vignetting: the natural cos^4 falloff toward the corners
};

/// A perspective camera in the Embree 1.1 convention: Z = normalize(look_at - position),
/// U = normalize(cross(up, Z)) points right in the image and V = cross(Z, U) up, a
/// left-handed frame (with up = +y and a view along +z, right is +x). With `right_handed`
/// (Embree 2 and 3's option, Embree 3's default) right is -U instead: the same view, mirrored
/// left to right, as a right-handed world expects (with up = +y and a view along +z, right
/// is -x).
class Camera {
 public:
  /// Builds the camera; throws std::invalid_argument with the reason for a NaN or infinite
  /// parameter, look_at == position, up parallel to the view direction, a field of view
  /// outside (0, 180) degrees, a non-positive aspect, or a negative lens radius or focal
  /// distance.
  explicit Camera(const CameraParams& params);

  /// The primary ray through film point `film` in [0, 1]^2 ((0, 0) is the top-left corner of
  /// the image, y grows downward), through lens point `lens` (a uniform sample of the unit
  /// square, mapped onto the lens disk), at shutter time `time` in [0, 1] (motion blur).
  /// The direction is normalised, tnear = 0 and tfar = infinity.
  Ray generate_ray(Vec2f film, Vec2f lens, float time) const;

  /// The share of the light from the scene that reaches film point `film`: cos^4 of the
  /// angle between the view axis and the ray through the lens centre with `vignetting`
  /// (natural vignetting), 1 without it.
  float vignetting(Vec2f film) const;

  /// The parameters the camera was made with (focal distance resolved).
  const CameraParams& params() const { return params_; }
  /// The right, up and forward axes (unit vectors).
  Vec3f right() const { return u_; }
  /// The image's up axis.
  Vec3f up() const { return v_; }
  /// The viewing direction.
  Vec3f forward() const { return z_; }

 private:
  CameraParams params_;
  Vec3f u_, v_, z_;
  float image_distance_ = 1.0f;  // distance from the eye to a film plane of height 1
};

}  // namespace rtk
