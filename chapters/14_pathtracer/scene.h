/// \file
/// The render scene: everything the path tracer needs to make an image, independent of the
/// file it came from. One triangle mesh (all objects merged, so that one acceleration
/// structure holds them and a hit's primID names the triangle), per-triangle materials,
/// optional per-vertex normals and texture coordinates, optional vertex positions at shutter
/// time 1 (motion blur), the lights of chapter 13 and the camera of chapter 11.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "01_base/triangle_mesh.h"
#include "11_sampling/camera.h"
#include "11_sampling/vec2.h"
#include "12_materials/material.h"
#include "13_lights/area_light.h"
#include "13_lights/light.h"

namespace rtk {

/// The value of RenderScene::triangle_light for a triangle that does not emit.
inline constexpr int32_t kNoLight = -1;

// [ch14-scene]
/// A scene ready to render. The vectors that hold one entry per vertex (`normals`, `uvs`,
/// `vertices_t1`) are either empty (the attribute is absent for the whole scene) or exactly as
/// long as `mesh.vertices`. Those that hold one entry per triangle (`triangle_material`,
/// `triangle_light`) are as long as `mesh.triangles`. validate() checks all of this.
///
/// Emitting surfaces are ordinary triangles of the mesh whose triangle_light names one of the
/// `lights` (a TriangleLight): rays hit them like any other surface, and the light samples
/// them for next-event estimation. The other lights (point, directional, distant, ambient,
/// environment) have no geometry.
struct RenderScene {
  TriangleMesh mesh;                        ///< every triangle of the scene (time 0 if it moves)
  std::vector<Vec3f> vertices_t1;           ///< positions at shutter time 1, or empty if static
  std::vector<Vec3f> normals;               ///< per-vertex shading normals (zero: use the face's)
  std::vector<Vec2f> uvs;                   ///< per-vertex texture coordinates
  std::vector<uint32_t> triangle_material;  ///< per triangle: an index into `materials`
  std::vector<int32_t> triangle_light;      ///< per triangle: an index into `lights`, or kNoLight
  std::vector<Material> materials;          ///< chapter 12's materials
  std::vector<std::shared_ptr<const Light>> lights;  ///< chapter 13's lights
  CameraParams camera;  ///< the view; its aspect is replaced by the image's width / height
  /// Embree 1.1's backplate: an image behind the scene, which camera rays that hit nothing see
  /// instead of the lights at infinity (texture (0, 0) is the image's bottom-left corner and
  /// (1, 1) its top-right, stretched over the frame). Null: none. Reflections and refractions
  /// still see the lights.
  std::shared_ptr<const ImageTexture> backplate;

  /// Whether any vertex moves during the shutter interval.
  bool has_motion() const { return !vertices_t1.empty(); }
  /// Whether any material lets light through (OBJ d < 1 or map_d).
  bool has_transparency() const;
  /// The corners of triangle `prim` at shutter time `time`.
  std::array<Vec3f, 3> corners(uint32_t prim, float time) const;
  /// The texture coordinates at barycentrics (u, v) of triangle `prim`: the interpolated
  /// `uvs`, or (u, v) themselves when the scene has none.
  Vec2f texcoords(uint32_t prim, float u, float v) const {
    if (uvs.empty()) return {u, v};
    const auto& tri = mesh.triangles[prim];
    return uvs[tri[0]] * (1.0f - u - v) + uvs[tri[1]] * u + uvs[tri[2]] * v;
  }
  /// How the point of triangle `prim` (corners `c`) moves per unit of the texture
  /// coordinates texcoords() gives: dp/du and dp/dv, the tangents a bump map tilts.
  void texture_tangents(uint32_t prim, const std::array<Vec3f, 3>& c, Vec3f& dpdu, Vec3f& dpdv) const;

  /// Adds a material and returns its index.
  uint32_t add_material(Material material);
  /// Adds a light without geometry (point, directional, distant, ambient, environment).
  void add_light(std::shared_ptr<const Light> light);
  /// Adds an emitting triangle: the light goes to `lights` and its triangle to the mesh with
  /// material `material` (whose emission should match the light's radiance), so that rays can
  /// hit it. Returns the triangle's primID. In a scene with motion the light stands still.
  uint32_t add_triangle_light(std::shared_ptr<const TriangleLight> light, uint32_t material);
  /// Adds an area light made of `triangles`, all of radiance `radiance`: one emitting,
  /// otherwise black material for all of them, and each triangle as add_triangle_light() adds it.
  void add_area_light(std::span<const std::shared_ptr<const TriangleLight>> triangles, Color radiance);

  /// Throws std::invalid_argument naming the first inconsistency: an attribute vector of the
  /// wrong length, a vertex, material or light index out of range, a triangle_light that is
  /// not a TriangleLight, a non-finite vertex.
  void validate() const;
};
// [ch14-scene]

}  // namespace rtk
