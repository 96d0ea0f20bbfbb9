/// \file
/// Pearson's chi-square goodness-of-fit test for sampling routines, the way Mitsuba tests its
/// BSDFs (Jakob, "Mitsuba renderer", 2010, src/tests/test_chisquare.cpp): bin many samples on a
/// grid, integrate the claimed density over each cell to get the expected counts, pool cells
/// with low expectation, and ask how likely the observed deviation is if the sampler really
/// follows the density. Chapters 11, 12 and 13 test every warp, BSDF and light sampler with it.
#pragma once

#include <functional>
#include <span>
#include <string>
#include <vector>

#include "01_base/vec3.h"

namespace rtk::chi2 {

/// The significance level of one suite of tests: the probability that a correct sampler is
/// rejected somewhere in the suite. Each test divides it by Sidak's correction
/// (sidak_alpha), so that adding tests does not add false alarms. Seeds are fixed, so a
/// test's outcome never changes from run to run.
inline constexpr double kSuiteSignificance = 0.01;

/// The per-test significance that keeps the family-wise error at `alpha` over `test_count`
/// independent tests: 1 - (1 - alpha)^(1 / test_count).
double sidak_alpha(double alpha, int test_count);

/// The probability that a chi-square variable with `dof` degrees of freedom exceeds
/// `statistic`: the regularised upper incomplete gamma function Q(dof / 2, statistic / 2)
/// (series or continued fraction, Numerical Recipes section 6.2).
double chi2_p_value(double statistic, int dof);

/// A rectangle [x0, x1] x [y0, y1] cut into nx x ny equal cells; cell (i, j) is i + nx * j.
struct Grid {
  double x0 = 0, x1 = 1, y0 = 0, y1 = 1;
  int nx = 1, ny = 1;

  /// The cell of a point, or -1 outside the rectangle (or NaN).
  int cell(double x, double y) const;
  /// The number of cells.
  int size() const { return nx * ny; }
};

/// The expected probability of each cell: the density integrated over the cell by nested
/// adaptive Simpson quadrature to an absolute tolerance `tolerance` per cell.
std::vector<double> integrate_cells(const Grid& grid,
                                    const std::function<double(double, double)>& density,
                                    double tolerance = 1e-7);

/// The expected probability of each cell by the midpoint rule on `points` x `points`
/// sub-cells: exact, and free of the trouble adaptive quadrature has with jumps, when the
/// density is constant on each sub-cell (a piecewise-constant density on a grid that the
/// sub-cells refine, such as an environment map's texels).
std::vector<double> integrate_cells_midpoint(const Grid& grid,
                                             const std::function<double(double, double)>& density,
                                             int points);

/// The outcome of one test.
struct Result {
  double statistic = 0;  ///< Pearson's sum of (observed - expected)^2 / expected
  int dof = 0;           ///< degrees of freedom: cells after pooling - 1
  double p_value = 0;    ///< chance of a statistic at least this large for a correct sampler
  int pooled = 0;        ///< cells merged because their expected count was below the minimum
  std::string failure;   ///< why the test failed outright (a sample where the density is 0)
  /// Whether the sampler passes at significance `alpha`.
  bool passed(double alpha) const { return failure.empty() && p_value > alpha; }
  /// One line for a report: statistic, dof, p-value.
  std::string summary() const;
};

/// Compares observed counts with expected counts (both per cell, any extra cells such as
/// "the delta lobe" appended by the caller). Cells expected to hold fewer than `min_expected`
/// samples are pooled into one; a sample observed in a cell whose expectation is exactly zero
/// fails the test at once.
Result pearson(std::span<const double> observed, std::span<const double> expected,
               double min_expected = 5.0);

/// The spherical domain of direction samplers: phi in [0, 2 pi) by theta in [0, pi]; the
/// density on it is pdf(w) * sin(theta). Theta bins (not cos-theta bins) resolve peaks near
/// the poles, where glossy lobes of small roughness live.
struct SphericalHistogram {
  Grid grid;
  std::vector<double> counts;
  int outside = 0;  ///< samples that were not unit directions (NaN, zero, not normalised)

  /// A histogram of 2 * res by res cells.
  explicit SphericalHistogram(int res);
  /// Adds one sampled direction (expected to be normalised).
  void add(Vec3f w);
  /// Expected probabilities of the cells for a density over solid angle.
  std::vector<double> expected(const std::function<double(Vec3f)>& pdf,
                               double tolerance = 1e-7) const;
  /// The same by the midpoint rule on `points` x `points` sub-cells of each cell.
  std::vector<double> expected_midpoint(const std::function<double(Vec3f)>& pdf, int points) const;
};

/// The unit direction with spherical coordinates (theta from +z, phi from +x toward +y).
Vec3f spherical_direction(double theta, double phi);

/// Whether RTK_CHI2_REPORT is set in the environment: the tests then print every p-value,
/// which is how the chapters' tables of p-values were made.
bool report_enabled();

}  // namespace rtk::chi2
