/// \file
/// The spatial-split builder of chapter 5: chapter 4's binned SAH builder in which every node
/// also prices a spatial split, under a duplication budget shared breadth-first over the top of
/// the tree (Embree 1.1 user's guide, section 4.3.2; Stich, Friedrich and Dietrich, "Spatial
/// Splits in Bounding Volume Hierarchies", HPG 2009).
#pragma once

#include <vector>

#include "01_base/triangle_mesh.h"
#include "02_bvh2/build_tree.h"
#include "05_spatial/spatial_options.h"

namespace rtk {

/// Builds a tree with 2 to N children per node (N = 2, 4, 8 or 16) over the triangles of `mesh`.
/// A leaf may reference a triangle that other leaves reference too, each time with the box of
/// the part of the triangle that lies in the leaf's region; `prim_ids` then repeats IDs.
/// Triangles whose boxes are not finite are left out (counted in `stats->skipped`).
///
/// When `leaf_refs` is not null it receives the references in leaf order, with their clipped
/// boxes: entry i is the reference behind `prim_ids[i]`.
///
/// The result depends on the mesh and the options only, not on the number of threads. Invalid
/// options (those of chapter 4, spatial bins outside [2, kMaxSpatialBins], a negative or
/// non-finite budget) throw std::invalid_argument naming the option; a triangle whose vertex
/// index is out of range throws std::invalid_argument naming the triangle.
template <int N>
BuildTree<N> build_spatial_sah(const TriangleMesh& mesh, const SpatialBuildOptions& options = {},
                               SpatialBuildStats* stats = nullptr,
                               std::vector<PrimRef>* leaf_refs = nullptr);

extern template BuildTree<2> build_spatial_sah<2>(const TriangleMesh&, const SpatialBuildOptions&,
                                                  SpatialBuildStats*, std::vector<PrimRef>*);
extern template BuildTree<4> build_spatial_sah<4>(const TriangleMesh&, const SpatialBuildOptions&,
                                                  SpatialBuildStats*, std::vector<PrimRef>*);
extern template BuildTree<8> build_spatial_sah<8>(const TriangleMesh&, const SpatialBuildOptions&,
                                                  SpatialBuildStats*, std::vector<PrimRef>*);
extern template BuildTree<16> build_spatial_sah<16>(const TriangleMesh&, const SpatialBuildOptions&,
                                                    SpatialBuildStats*, std::vector<PrimRef>*);

}  // namespace rtk
