#include "rates/rates_csv.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/errors.hpp"

namespace swarmagg {
namespace {

std::filesystem::path write_temp(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / name;
  std::ofstream(path) << text;
  return path;
}

TEST(RatesCsv, ReadsBackWhatItWritesAndFeedsTheMeasuredTerms) {
  std::vector<RateRow> rows;
  rows.push_back({"creation",
                  std::nullopt,
                  estimate_rate(120, 4.0e5),
                  {{"bayindir", "original", 3e-4}, {"bayindir", "collision", 2.5e-4}}});
  rows.push_back({"growth", 2, estimate_rate(30, 1.0e4), {{"bayindir", "original", 2e-3}}});
  rows.push_back({"growth", 3, estimate_rate(4, 1.0e3), {}});
  rows.push_back({"initial", 2, estimate_rate(7, 10.0), {}});
  const std::string text = rates_csv(rows);
  EXPECT_EQ(text.substr(0, text.find('\n')),
            "term,size,events,exposure,rate,ci_low,ci_high,model,variant,model_rate");
  const std::vector<RateRow> back = read_rates_csv(write_temp("swarmagg-rates-test.csv", text));
  ASSERT_EQ(back.size(), rows.size());
  EXPECT_EQ(back[0].models.size(), 2u);
  EXPECT_EQ(*back[0].estimate.rate, *rows[0].estimate.rate);
  EXPECT_EQ(*back[0].estimate.high, *rows[0].estimate.high);
  EXPECT_TRUE(back[2].estimate.too_few());
  EXPECT_EQ(rates_csv(back), text);

  const MeasuredTerms terms = measured_terms(back);
  EXPECT_DOUBLE_EQ(*terms.creation, 120 / 4.0e5);
  EXPECT_DOUBLE_EQ(terms.growth.at(2), 30 / 1.0e4);
  EXPECT_FALSE(terms.growth.contains(3));      // too few events: the model's term is used
  EXPECT_DOUBLE_EQ(terms.initial.at(2), 0.7);  // a mean count needs no minimum
}

TEST(RatesCsv, RejectsAFileThatIsNotRatesCsv) {
  EXPECT_THROW(read_rates_csv(write_temp("swarmagg-not-rates.csv", "a,b\n1,2\n")), InputError);
  EXPECT_THROW(read_rates_csv(write_temp("swarmagg-bad-rates.csv",
                                         "term,size,events,exposure,rate,ci_low,ci_high,model,"
                                         "variant,model_rate\ncreation,,many,1,,,,,,\n")),
               InputError);
}

TEST(RatesCsv, RejectsNegativeInfiniteOrFractionalQuantitiesNamingLineAndColumn) {
  const std::string header =
      "term,size,events,exposure,rate,ci_low,ci_high,model,variant,model_rate\n";
  const std::string good = "creation,,120,400000,0.0003,0.00025,0.00036,bayindir,original,3e-4\n";
  EXPECT_NO_THROW(read_rates_csv(write_temp("swarmagg-good-rates.csv", header + good)));
  const std::vector<std::pair<std::string, std::string>> damaged = {
      {"creation,,120,400000,-0.0003,0.00025,0.00036,,,\n", "column 'rate'"},
      {"creation,,120,400000,inf,0.00025,0.00036,,,\n", "column 'rate'"},
      {"creation,,120,400000,0.0003,nan,0.00036,,,\n", "column 'ci_low'"},
      {"creation,,120,-5,0.0003,0.00025,0.00036,,,\n", "column 'exposure'"},
      {"creation,,12.5,400000,0.0003,0.00025,0.00036,,,\n", "column 'events'"},
      {"creation,,,400000,0.0003,0.00025,0.00036,,,\n", "a whole number from 0"},
      {"growth,0,12,400000,0.0003,0.00025,0.00036,,,\n", "column 'size'"},
      {"creation,,120,400000,0.0003,0.00025,0.00036,bayindir,original,-1\n", "column 'model_rate'"},
      // A return fraction above 1, or more returns than attempts.
      {"return,2,12,20,5,0.3,0.8,,,\n", "column 'rate': expected a fraction from 0 to 1"},
      {"return,2,12,20,0.6,0.3,1.5,,,\n", "column 'ci_high'"},
      {"return,2,30,20,0.6,0.3,0.8,,,\n", "cannot exceed its exposure"},
      // Events over no exposure; the same term measured twice.
      {"initial,2,10,0,,,,,,\n", "expected an exposure above 0"},
      {"creation,,121,400000,0.0003025,0.00025,0.00036,bayindir,collision,3e-4\n",
       "repeats term 'creation' of line 2 with another measurement"},
      // A misspelt term, which every model would ignore; a rate that is not its counts; a
      // rate from fewer events (or a fraction from fewer attempts) than any measurement gives.
      {"creatoin,,120,400000,0.0003,0.00025,0.00036,,,\n",
       "column 'term': unknown term 'creatoin'; did you mean 'creation'?"},
      {"growth,3,120,400000,0.003,0.00025,0.00036,,,\n",
       "column 'rate': got '0.003', expected events / exposure = 3e-04"},
      {"growth,3,5,400000,0.0000125,0.00025,0.00036,,,\n",
       "column 'rate': a growth rate from 5 events"},
      {"return,2,3,6,0.5,0.2,0.8,,,\n", "a return rate from 6 LEAVE attempts"},
  };
  for (const auto& [row, column] : damaged) {
    try {
      read_rates_csv(write_temp("swarmagg-damaged-rates.csv", header + good + row));
      ADD_FAILURE() << "accepted " << row;
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("swarmagg-damaged-rates.csv:3"), std::string::npos) << message;
      EXPECT_NE(message.find(column), std::string::npos) << message;
    }
  }
}

TEST(RatesCsv, ATermIsReadOncePerVariantOnConsecutiveLines) {
  const std::string header =
      "term,size,events,exposure,rate,ci_low,ci_high,model,variant,model_rate\n";
  const std::string initial = "initial,2,35,10,3.5,2.4,4.9,bayindir,original,3.4\n";
  const std::string again = "initial,2,35,10,3.5,2.4,4.9,bayindir,collision,3.4\n";
  const std::string other = "growth,2,40,1000,0.04,0.03,0.05,bayindir,original,0.05\n";
  const std::vector<RateRow> rows =
      read_rates_csv(write_temp("swarmagg-variants-rates.csv", header + initial + again + other));
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].models.size(), 2u);
  try {
    read_rates_csv(write_temp("swarmagg-repeat-rates.csv", header + initial + other + again));
    ADD_FAILURE() << "accepted a term measured twice";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(":4: repeats term 'initial' size 2 of line 2 after "
                                         "other terms"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace swarmagg
