/// \file
/// The binned SAH builder of chapter 4: top-down, 32 bins on each axis, the children binned in
/// the pass that partitions their parent, N-ary nodes filled by splitting the child whose split
/// gains most, parallel at three granularities on oneTBB, and the same tree for any number of
/// threads (Embree 1.1 user's guide, sections 4.3 and 4.3.1).
#pragma once

#include <span>

#include "02_bvh2/build_tree.h"
#include "04_sah/sah_options.h"

namespace rtk {

/// Builds a tree with 2 to N children per node (N = 2, 4, 8 or 16) over `refs` with the surface
/// area heuristic. Leaves index `prim_ids`, the primitive IDs of the references in leaf order.
///
/// References whose boxes hold a NaN or an infinity, or whose lower corner exceeds the upper
/// one, cannot be hit and are left out (counted in `stats->skipped`); an empty or all-invalid
/// input gives an empty tree. Invalid options (bins outside [2, kMaxSahBins], max_leaf_size
/// below 1, a leaf_block that is not a power of two up to 16, a negative or non-finite cost, a
/// non-positive intersection cost, negative threads) throw std::invalid_argument naming the
/// option; more than 2^32 - 2 references throw std::length_error.
///
/// The result depends on `refs` and `options` only: the same input gives the same tree, node
/// for node and bit for bit, whatever the number of threads.
template <int N>
BuildTree<N> build_binned_sah(std::span<const PrimRef> refs, const SahBuildOptions& options = {},
                              SahBuildStats* stats = nullptr);

/// The same tree as build_binned_sah(make_prim_refs(mesh), options, stats), with the
/// references made by the builder's first parallel pass instead of a serial one and a copy.
/// Throws as make_prim_refs() does for a vertex index out of range (naming the first such
/// triangle), and as the other overload for invalid options.
template <int N>
BuildTree<N> build_binned_sah(const TriangleMesh& mesh, const SahBuildOptions& options = {},
                              SahBuildStats* stats = nullptr);

extern template BuildTree<2> build_binned_sah<2>(std::span<const PrimRef>, const SahBuildOptions&,
                                                 SahBuildStats*);
extern template BuildTree<4> build_binned_sah<4>(std::span<const PrimRef>, const SahBuildOptions&,
                                                 SahBuildStats*);
extern template BuildTree<8> build_binned_sah<8>(std::span<const PrimRef>, const SahBuildOptions&,
                                                 SahBuildStats*);
extern template BuildTree<16> build_binned_sah<16>(std::span<const PrimRef>, const SahBuildOptions&,
                                                   SahBuildStats*);
extern template BuildTree<2> build_binned_sah<2>(const TriangleMesh&, const SahBuildOptions&, SahBuildStats*);
extern template BuildTree<4> build_binned_sah<4>(const TriangleMesh&, const SahBuildOptions&, SahBuildStats*);
extern template BuildTree<8> build_binned_sah<8>(const TriangleMesh&, const SahBuildOptions&, SahBuildStats*);
extern template BuildTree<16> build_binned_sah<16>(const TriangleMesh&, const SahBuildOptions&,
                                                   SahBuildStats*);

}  // namespace rtk
