#include "02_bvh2/zero_area.h"

#include <cmath>

namespace rtk {

namespace {

// Whether a * b == c * d exactly: a product of doubles is its rounded value plus an error
// that FMA computes exactly, and that pair is unique for each exact product.
bool products_equal(double a, double b, double c, double d) {
  const double p = a * b, q = c * d;
  return p == q && std::fma(a, b, -p) == std::fma(c, d, -q);
}

}  // namespace

bool is_zero_area(Vec3f p0, Vec3f p1, Vec3f p2) {
  const double ax = double(p1.x) - p0.x, ay = double(p1.y) - p0.y, az = double(p1.z) - p0.z;
  const double bx = double(p2.x) - p0.x, by = double(p2.y) - p0.y, bz = double(p2.z) - p0.z;
  return products_equal(ay, bz, az, by) && products_equal(az, bx, ax, bz) &&
         products_equal(ax, by, ay, bx);
}

}  // namespace rtk
