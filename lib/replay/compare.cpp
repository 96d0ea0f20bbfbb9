#include "replay/compare.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rtk {

namespace {

// |a - b| / scale, where scale = max(|a|, |b|, floor): the floor stands for the origin's
// magnitude in units of dir (or 1 without the rays).
double scaled_difference(float a, float b, double floor) {
  const double diff = std::fabs(double(a) - double(b));
  if (diff == 0.0) return 0.0;
  // NaN distances never agree with anything (the comparison below is false for NaN).
  const double scale = std::max({std::fabs(double(a)), std::fabs(double(b)), floor});
  return scale > 0.0 ? diff / scale : diff;
}

double origin_scale(std::span<const Ray> rays, size_t i) {
  if (rays.empty()) return 1.0;
  const Ray& r = rays[i];
  const double dir = std::sqrt(double(r.dir.x) * r.dir.x + double(r.dir.y) * r.dir.y + double(r.dir.z) * r.dir.z);
  const double org = std::sqrt(double(r.org.x) * r.org.x + double(r.org.y) * r.org.y + double(r.org.z) * r.org.z);
  return dir > 0.0 && std::isfinite(org / dir) ? org / dir : 0.0;
}

}  // namespace

HitComparison compare_hit_arrays(std::span<const Hit> a, std::span<const Hit> b, double t_tolerance,
                                 size_t keep, std::span<const Ray> rays) {
  if (a.size() != b.size()) throw std::invalid_argument("hit arrays of different lengths");
  if (!rays.empty() && rays.size() != a.size())
    throw std::invalid_argument("hit arrays and rays of different lengths");
  HitComparison c;
  c.rays = a.size();
  double sum_error = 0.0;
  for (size_t i = 0; i < a.size(); ++i) {
    const bool ha = a[i].found(), hb = b[i].found();
    bool agrees = false;
    if (!ha && !hb) {
      ++c.both_miss;
      agrees = true;
    } else if (ha && !hb) {
      ++c.only_a_hit;
    } else if (!ha && hb) {
      ++c.only_b_hit;
    } else {
      const double error = scaled_difference(a[i].t, b[i].t, origin_scale(rays, i));
      const bool same_t = error <= t_tolerance;
      if (a[i].prim == b[i].prim) {
        ++c.same_prim;
        if (same_t) {
          agrees = true;
        } else {
          ++c.t_mismatch;
        }
        if (!std::isnan(error)) {  // a NaN distance is a mismatch, not a number to average
          sum_error += error;
          c.max_t_error = std::max(c.max_t_error, error);
        }
      } else {
        ++c.other_prim;
        if (same_t) ++c.other_prim_same_t;
      }
    }
    if (!agrees && c.first_differences.size() < keep) c.first_differences.push_back(i);
  }
  c.mean_t_error = c.same_prim ? sum_error / double(c.same_prim) : 0.0;
  return c;
}

OcclusionComparison compare_occlusion_arrays(std::span<const uint8_t> a, std::span<const uint8_t> b,
                                             size_t keep) {
  if (a.size() != b.size()) throw std::invalid_argument("occlusion arrays of different lengths");
  OcclusionComparison c;
  c.rays = a.size();
  for (size_t i = 0; i < a.size(); ++i) {
    const bool oa = a[i] != 0, ob = b[i] != 0;
    if (oa && ob) ++c.both_blocked;
    else if (!oa && !ob) ++c.both_free;
    else if (oa) ++c.only_a;
    else ++c.only_b;
    if (oa != ob && c.first_differences.size() < keep) c.first_differences.push_back(i);
  }
  return c;
}

}  // namespace rtk
