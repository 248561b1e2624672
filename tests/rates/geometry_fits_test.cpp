#include "rates/geometry_fits.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace swarmagg {
namespace {

// A measured mean of `observations` observations (no spread: the interval is the mean).
RateEstimate mean_of(double value, std::uint64_t observations) {
  return {.events = observations,
          .exposure = static_cast<double>(observations),
          .rate = value,
          .low = value,
          .high = value};
}

// Rows made from known laws: R1 = r 1.35 m^0.52 with r = 1.5, rim = pi (1.1 m^0.6 - 1).
std::vector<RateRow> rows_from_laws(const std::vector<int>& sizes) {
  std::vector<RateRow> rows;
  for (const int m : sizes) {
    rows.push_back({"radius", m, mean_of(1.5 * 1.35 * std::pow(m, 0.52), 50), {}});
    rows.push_back({"rim", m, mean_of(std::numbers::pi * (1.1 * std::pow(m, 0.6) - 1.0), 50), {}});
  }
  return rows;
}

TEST(GeometryFits, RecoverTheLawsTheRowsWereMadeFrom) {
  std::vector<RateRow> rows = rows_from_laws({2, 3, 5, 9, 17});
  // Rows of other terms and sizes with too few observations are left out of the fit.
  rows.push_back({"growth", 4, mean_of(100.0, 50), {}});
  rows.push_back({"radius", 40, RateEstimate{.events = 3, .exposure = 3.0}, {}});
  const GeometryFits fits = fit_geometry_laws(rows, 1.5);
  ASSERT_TRUE(fits.radius.fitted());
  ASSERT_TRUE(fits.rim.fitted());
  EXPECT_EQ(fits.radius.sizes, 5);
  EXPECT_NEAR(fits.radius.a->value, 1.35, 1e-12);
  EXPECT_NEAR(fits.radius.b->value, 0.52, 1e-12);
  EXPECT_NEAR(fits.rim.a->value, 1.1, 1e-12);
  EXPECT_NEAR(fits.rim.b->value, 0.6, 1e-12);

  const nlohmann::json json = geometry_fits_json(fits);
  EXPECT_NEAR(json["radius"]["b"].get<double>(), 0.52, 1e-12);
  EXPECT_FALSE(json["radius"]["paper_b_in_ci"].get<bool>());
  EXPECT_EQ(json["paper"]["a"].get<double>(), 1.20);
}

TEST(GeometryFits, PairsOnlyGiveNoFitAndSaySo) {
  const GeometryFits fits = fit_geometry_laws(rows_from_laws({2}), 1.0);
  EXPECT_FALSE(fits.radius.fitted());
  EXPECT_FALSE(fits.rim.fitted());
  const nlohmann::json json = geometry_fits_json(fits);
  EXPECT_FALSE(json["radius"].contains("a"));
  EXPECT_NE(json["rim"]["refused"].get<std::string>().find("needs 3"), std::string::npos);
}

}  // namespace
}  // namespace swarmagg
