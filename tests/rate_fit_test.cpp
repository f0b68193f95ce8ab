// The rates' least squares fit (src/machine/rate_fit.h) against values worked out by hand:
// exact runs give back the rates they were made from, a one-kind fit its closed form, and an
// overdetermined two-kind case its normal equations' solution, worked on paper.
#include "machine/rate_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace ncube {
namespace {

TEST(RateFit, ExactRunsGiveBackTheRatesTheyWereMadeFrom) {
  // Made from 2e8 flop/s for the first kind (a ray's own work) and 5e9 for the second (tests),
  // with mixes of 5 to 500 tests a ray, as machine_probe's rooms.
  const double ray = 1 / 2e8, test = 1 / 5e9;
  std::vector<TimedRun> runs;
  for (double tests_a_ray : {5.0, 20.0, 80.0, 500.0}) {
    const double rays = 1e6 / tests_a_ray;
    runs.push_back({{9 * rays, 20 * tests_a_ray * rays},
                    9 * rays * ray + 20 * tests_a_ray * rays * test});
  }
  const RateFit fit = fit_seconds_per_flop(runs);
  ASSERT_EQ(fit.seconds_per_flop.size(), 2u);
  EXPECT_NEAR(fit.seconds_per_flop[0] / ray, 1, 1e-12);
  EXPECT_NEAR(fit.seconds_per_flop[1] / test, 1, 1e-12);
  ASSERT_EQ(fit.relative_residuals.size(), 4u);
  for (double r : fit.relative_residuals) EXPECT_NEAR(r, 0, 1e-12);
  EXPECT_NEAR(fit.rms_relative_residual, 0, 1e-12);
}

TEST(RateFit, OneKindIsTheClosedFormOfRelativeLeastSquares) {
  // Minimising sum (f_i x / t_i - 1)^2: x = sum (f_i / t_i) / sum (f_i / t_i)^2.
  // f/t = 2, 4: x = 6 / 20 = 0.3; residuals 0.6 - 1 = -0.4 and 1.2 - 1 = 0.2.
  const RateFit fit = fit_seconds_per_flop({{{2.0}, 1.0}, {{8.0}, 2.0}});
  EXPECT_NEAR(fit.seconds_per_flop[0], 0.3, 1e-15);
  EXPECT_NEAR(fit.relative_residuals[0], -0.4, 1e-15);
  EXPECT_NEAR(fit.relative_residuals[1], 0.2, 1e-15);
  EXPECT_NEAR(fit.rms_relative_residual, std::sqrt(0.1), 1e-15);
}

TEST(RateFit, TwoKindsOverThreeRunsIsTheNormalEquationsSolution) {
  // Rows f / t: (1, 0), (0, 1), (2/3, 2/3) against 1. Normal equations
  // [13/9 4/9; 4/9 13/9] x = [5/3; 5/3]: x = (15/17, 15/17). Residuals: 15/17 - 1 = -2/17
  // twice, and (2/3)(30/17) - 1 = 3/17. The flops are scaled by 1e9 and 1e6 (kinds of very
  // different sizes): x scales back by them.
  const RateFit fit =
      fit_seconds_per_flop({{{1e9, 0.0}, 1.0}, {{0.0, 1e6}, 1.0}, {{1e9, 1e6}, 1.5}});
  EXPECT_NEAR(fit.seconds_per_flop[0] * 1e9, 15.0 / 17, 1e-14);
  EXPECT_NEAR(fit.seconds_per_flop[1] * 1e6, 15.0 / 17, 1e-14);
  EXPECT_NEAR(fit.relative_residuals[0], -2.0 / 17, 1e-14);
  EXPECT_NEAR(fit.relative_residuals[1], -2.0 / 17, 1e-14);
  EXPECT_NEAR(fit.relative_residuals[2], 3.0 / 17, 1e-14);
}

TEST(RateFit, RefusesWhatCannotBeFitted) {
  // Fewer runs than kinds; kinds in the same proportion in every run; a run that took no
  // time; runs of different lengths.
  EXPECT_THROW(fit_seconds_per_flop({{{1.0, 2.0}, 1.0}}), std::invalid_argument);
  EXPECT_THROW(fit_seconds_per_flop({{{1.0, 2.0}, 1.0}, {{3.0, 6.0}, 2.0}, {{2.0, 4.0}, 1.0}}),
               std::invalid_argument);
  EXPECT_THROW(fit_seconds_per_flop({{{1.0}, 0.0}, {{1.0}, 1.0}}), std::invalid_argument);
  EXPECT_THROW(fit_seconds_per_flop({{{1.0, 0.0}, 1.0}, {{1.0}, 1.0}}), std::invalid_argument);
  EXPECT_THROW(fit_seconds_per_flop({}), std::invalid_argument);
}

}  // namespace
}  // namespace ncube
