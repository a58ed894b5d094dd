// V6: the default reference run against data/golden/reference-history.csv,
// at the tolerances stated beside it (reference-history.tolerance.json).

#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "reference_run.hpp"

namespace rsi {
namespace {

TEST(GoldenHistory, ReferenceRunMatchesTheGoldenBlade1History) {
  const std::string dir = std::string(RSI_SOURCE_DIR) + "/data/golden/";
  std::ifstream tolerance_file(dir + "reference-history.tolerance.json");
  ASSERT_TRUE(tolerance_file) << "missing tolerance file";
  const nlohmann::json tolerance = nlohmann::json::parse(tolerance_file);
  const double gap_tolerance = tolerance.at("gap_1_abs").get<double>();
  const double lambda_tolerance = tolerance.at("lambda_1_abs").get<double>();

  std::ifstream golden(dir + tolerance.at("file").get<std::string>());
  ASSERT_TRUE(golden);
  std::string line;
  std::getline(golden, line);
  ASSERT_EQ(line, "t,gap_1,lambda_1");
  std::vector<std::array<double, 3>> rows;
  while (std::getline(golden, line)) {
    std::array<double, 3> row{};
    char comma = 0;
    std::istringstream in(line);
    in >> row[0] >> comma >> row[1] >> comma >> row[2];
    rows.push_back(row);
  }

  const RunResult r = run_reference(
      load_case(std::string(RSI_SOURCE_DIR) + "/" + tolerance.at("case").get<std::string>()), {});
  ASSERT_EQ(static_cast<size_t>(r.history.n_rows()), rows.size());
  double gap_error = 0.0;
  double lambda_error = 0.0;
  for (size_t i = 0; i < rows.size(); ++i) {
    ASSERT_NEAR(r.history.time[i], rows[i][0], 1e-15) << "row " << i;
    gap_error = std::max(gap_error, std::abs(r.history.gap[i](0) - rows[i][1]));
    lambda_error = std::max(lambda_error, std::abs(r.history.lambda[i](0) - rows[i][2]));
  }
  std::printf("max |gap_1 - golden| = %.3e m (tolerance %.1e), max |lambda_1 - golden| = %.3e N "
              "(tolerance %.1e)\n",
              gap_error, gap_tolerance, lambda_error, lambda_tolerance);
  // Tolerances and their derivation: data/golden/reference-history.tolerance.json.
  EXPECT_LE(gap_error, gap_tolerance);
  EXPECT_LE(lambda_error, lambda_tolerance);
}

} // namespace
} // namespace rsi
