/// \file
/// The viewer's camera model, apart from any window: the orbit camera of the Embree 1.1 viewer
/// (the guide's section 2.3), which revolves around a centre of interest with the y axis up,
/// and the mouse gestures that move it (rotate, pan, dolly, roll, pick), each a small piece of
/// vector algebra that the chapter's tests check analytically.
#pragma once

#include <optional>
#include <string>

#include "11_sampling/camera.h"
#include "11_sampling/vec2.h"
#include "14_pathtracer/ray_kernels.h"

namespace rtk {

// [ch16-orbit-state]
/// An orbit camera: an eye that looks at a centre of interest, an up direction, a vertical
/// field of view and a thin lens. Every gesture keeps the state valid (eye != centre, up not
/// parallel to the view), so that to_params() always gives a camera chapter 11 accepts.
struct OrbitCamera {
  Vec3f eye{0, 0, 0};         ///< the eye (the guide's -vp)
  Vec3f centre{1, 0, 0};      ///< the centre of interest (-vi), what orbiting revolves around
  Vec3f up{0, 1, 0};          ///< the up direction (-vu); y unless rolled
  float fov_degrees = 64.0f;  ///< the vertical field of view (-fov)
  float lens_radius = 0.0f;   ///< the lens radius (-radius); 0 is a pinhole
  float focal_distance = 0;   ///< the distance of the plane in focus (-focaldistance); 0: |centre - eye|
  bool right_handed = false;  ///< the image mirrored left to right (-righthanded, chapter 11)

  /// The orbit camera of a scene's camera parameters (their aspect is not part of the state).
  static OrbitCamera from_params(const CameraParams& params);
  /// The camera parameters for an image of the given aspect (width / height).
  CameraParams to_params(float aspect) const;

  /// The unit view direction, from the eye to the centre.
  Vec3f forward() const;
  /// The unit right axis of the image (chapter 11's U = normalize(cross(up, forward)), or -U
  /// for a right-handed camera).
  Vec3f right() const;
  /// The distance from the eye to the centre of interest.
  float distance() const;
// [ch16-orbit-state]

  /// Revolves the eye around the centre: by `azimuth` radians about the up direction, then by
  /// `elevation` radians about the right axis (positive raises the eye). The elevation stops
  /// one degree short of the poles, where "up" would no longer define an image.
  void rotate(float azimuth, float elevation);
  /// Slides eye and centre together in the image plane so that the scene at the centre's
  /// depth moves by `dx` image heights to the right and `dy` up on the screen (the camera goes
  /// the other way, and the point under a dragging mouse follows it); the view direction does
  /// not change.
  void pan(float dx, float dy);
  /// Moves the eye along the view direction toward the centre, scaling the distance by
  /// exp(-amount): positive comes closer and the same negative amount goes back. The eye
  /// never reaches or passes the centre: it stops 1e-4 x max(1, |centre|_inf) short of it.
  void dolly(float amount);
  /// Turns the up direction by `angle` radians about the view direction (positive is
  /// clockwise as seen by the eye); the eye, the centre and the view do not move.
  void roll(float angle);

  /// The pinhole ray (through the centre of the lens) through film point `film` in [0, 1]^2
  /// ((0, 0) the top-left corner) of an image of the given aspect.
  Ray ray_through(Vec2f film, float aspect) const;
  /// The first surface point seen through film point `film`, traced with `kernels`; nothing
  /// when the ray leaves the scene.
  std::optional<Vec3f> pick(const RayKernels& kernels, Vec2f film, float aspect) const;
  /// Makes `point` the centre of interest (the guide's Ctrl+click): the eye stays and turns
  /// toward it. Ignored (returns false) when the point is the eye itself or straight above or
  /// below it, where no image is defined.
  bool look_at(Vec3f point);
  /// Puts the plane of focus through `point` (the guide's Ctrl+Shift+click): the focal
  /// distance becomes its depth along the view direction. Ignored (returns false) for a
  /// point not in front of the eye.
  bool focus_on(Vec3f point);

  /// The guide's command-script options that reproduce this camera: "-vp x y z -vi x y z
  /// -vu x y z -fov f -radius r -focaldistance d" and -righthanded or -lefthanded, with enough digits that reading them back
  /// gives exactly the same floats.
  std::string to_ecs_options() const;
};

}  // namespace rtk
