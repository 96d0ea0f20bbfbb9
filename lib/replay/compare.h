/// \file
/// How far two tracers agree on the same rays: `rtk compare`, the Embree benchmark's
/// agreement figure and the tests all count the same way.
///
/// Two hits agree when both are misses, or both hit the same primID at distances that differ by
/// at most the tolerance times a scale: |t_a - t_b| <= tolerance * scale. Anything else is a
/// disagreement, counted by kind: one side hit and the other missed, or the primIDs differ.
///
/// The scale is what floating-point error is proportional to. A computed hit point is off by
/// a few units in the last place of the larger of the origin's and the hit point's
/// coordinates, so with the rays at hand scale = max(|t|, |org| / |dir|) (both in units of
/// dir): relative to t for distant hits, and to the origin's magnitude for hits close to an
/// origin far from 0, where t's own digits say nothing (a diffuse ray hitting a neighbouring
/// sliver at t = 0.009 from an origin at 0.9). Without the rays, scale = max(|t|, 1), the
/// rule of the tests' brute-force oracle. Rays that graze a surface amplify the error beyond
/// any fixed tolerance; they are the disagreements that remain between two correct tracers. Files alone cannot tell a wrong answer from a legitimate tie (a ray through a
/// shared edge, or coplanar triangles, may report either triangle), so the primID
/// disagreements whose distances agree are counted separately as likely ties.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "01_base/ray.h"

namespace rtk {

/// The result of comparing two hit arrays ray by ray.
struct HitComparison {
  size_t rays = 0;           ///< rays compared
  size_t both_miss = 0;      ///< both sides missed
  size_t same_prim = 0;      ///< both hit the same primID (t within tolerance or not)
  size_t t_mismatch = 0;     ///< of same_prim, those whose t differ beyond the tolerance
  size_t only_a_hit = 0;     ///< a hit, b missed
  size_t only_b_hit = 0;     ///< b hit, a missed
  size_t other_prim = 0;     ///< both hit, different primIDs
  size_t other_prim_same_t = 0;  ///< of other_prim, those at the same t (likely ties)
  double max_t_error = 0.0;   ///< largest |t_a - t_b| / scale over same_prim rays
  double mean_t_error = 0.0;  ///< mean |t_a - t_b| / scale over same_prim rays
  std::vector<size_t> first_differences;  ///< indices of the first disagreeing rays

  /// The rays that agree: both missed, or the same primID at the same t.
  size_t agree() const { return both_miss + same_prim - t_mismatch; }
  /// The rays that do not.
  size_t differ() const { return rays - agree(); }
  /// agree() / rays, in percent (100 for no rays).
  double agree_percent() const { return rays ? 100.0 * double(agree()) / double(rays) : 100.0; }
};

/// Compares hits ray by ray; both spans must have the same length, and `rays` (the rays that
/// were traced) either that length too or empty. `t_tolerance` bounds |t_a - t_b| / scale
/// (see above); `keep` is how many disagreeing ray indices to list.
HitComparison compare_hit_arrays(std::span<const Hit> a, std::span<const Hit> b, double t_tolerance = 1e-4,
                                 size_t keep = 10, std::span<const Ray> rays = {});

/// The result of comparing two occlusion arrays.
struct OcclusionComparison {
  size_t rays = 0;          ///< rays compared
  size_t both_blocked = 0;  ///< both say occluded
  size_t both_free = 0;     ///< both say not occluded
  size_t only_a = 0;        ///< only a says occluded
  size_t only_b = 0;        ///< only b says occluded
  std::vector<size_t> first_differences;  ///< indices of the first disagreeing rays

  /// The rays on which both agree.
  size_t agree() const { return both_blocked + both_free; }
  /// The rays on which they do not.
  size_t differ() const { return only_a + only_b; }
  /// agree() / rays, in percent (100 for no rays).
  double agree_percent() const { return rays ? 100.0 * double(agree()) / double(rays) : 100.0; }
};

/// Compares occlusion answers (nonzero = occluded) ray by ray; both spans must have the same
/// length.
OcclusionComparison compare_occlusion_arrays(std::span<const uint8_t> a, std::span<const uint8_t> b,
                                             size_t keep = 10);

}  // namespace rtk
