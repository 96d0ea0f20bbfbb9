/// \file
/// The accuracy scene: a closed spindle of long, thin triangles seen through a very narrow
/// camera, where Möller-Trumbore lets rays through between neighbouring slivers. In the spirit
/// of the scene the Embree 1.1 guide uses to show the same failure (section 4.5), with our own
/// geometry and camera; scenes/accuracy/ holds it as OBJ and .ecs files.
#pragma once

#include <span>
#include <vector>

#include "01_base/ray.h"
#include "01_base/triangle_mesh.h"

namespace rtk {

/// A pinhole camera in the convention of the guide's .ecs files: position, a point looked at,
/// an up vector and the vertical field of view in degrees.
struct PinholeCamera {
  Vec3f position;
  Vec3f look_at;
  Vec3f up{0, 1, 0};
  float fov_degrees = 64.0f;
};

/// The accuracy scene's parameters, used by make_accuracy_scene() and quoted by the book.
struct AccuracySceneParams {
  int segments = 720;            ///< slivers per fan: the spindle has twice as many triangles
  float half_length = 40.0f;     ///< pole distance from the ring
  float radius = 1.25f;          ///< ring radius: the slivers are 2 pi r / segments wide
  Vec3f center{3.5f, -1.25f, 2.0f};
  Vec3f axis{0.15f, 1.0f, -0.1f};
  int aimed_vertex = 97;         ///< the ring vertex the camera looks at
  float distance = 8.0f;         ///< camera distance from that vertex
  float fov_degrees = 0.06f;     ///< the guide's narrow field of view
};

/// The scene: a spindle (make_spindle) and a camera looking at a ring vertex, where four
/// slivers meet, from 25 degrees off the surface normal.
struct AccuracyScene {
  TriangleMesh mesh;
  PinholeCamera camera;
};

/// Builds the accuracy scene.
AccuracyScene make_accuracy_scene(const AccuracySceneParams& params = {});

/// Primary rays through the centres of a width x height image, row by row from the top: the
/// direction (x - 1/2) aspect U + (1/2 - y) V + Z / (2 tan(fov/2)) for the camera frame
/// Z = forward, U = up x Z, V = Z x U (the guide's left-handed convention), computed in double
/// and rounded once.
std::vector<Ray> camera_rays(const PinholeCamera& camera, int width, int height);

/// The rays, each cut to end halfway between where it enters and where it leaves the convex
/// closed mesh (convex_interval), so that it must cross exactly one triangle: a miss is a
/// leak. Rays whose line does not pass through the mesh's interior are left out.
std::vector<Ray> rays_through_front(const TriangleMesh& convex_mesh, std::span<const Ray> rays);

/// Rays from eight points inside the scene's spindle (around its centre, up to 1.5 from it
/// along the axis) aimed at every vertex and at four points of every edge (rays_at_vertices,
/// rays_at_edges with s = 1/2, 1/4, 1/3, 1/10): 74,896 rays for the default scene, every one
/// of which must hit. Where the view's rays cross the slivers' long edges, these also meet the
/// vertices where four slivers (ring) or all of them (poles) meet.
std::vector<Ray> accuracy_inside_rays(const AccuracySceneParams& params = {});

}  // namespace rtk
