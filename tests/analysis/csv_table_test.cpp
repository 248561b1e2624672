// CSV files read back (plots, model errors, reports), whole or row by row (files that grow with
// a run's length): a damaged file is an error naming the file, the line and what was wrong,
// not a point silently dropped or a bare "stod".
#include "analysis/csv_table.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "analysis/csv_reader.hpp"
#include "analysis/model_table.hpp"
#include "analysis/step_series.hpp"
#include "core/errors.hpp"
#include "testing/scratch_dir.hpp"

namespace swarmagg {
namespace {

using ::testing::AllOf;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

std::filesystem::path written(const testing::ScratchDir& dir, const std::string& text) {
  const auto file = dir.path() / "t.csv";
  std::ofstream(file) << text;
  return file;
}

TEST(CsvTable, ReadsNumbersAndEmptyCells) {
  const testing::ScratchDir dir("csv-table");
  const CsvTable table = read_csv(written(dir, "a,b,c\n1,2.5e-3,\n\n-4,inf,7\n"));
  ASSERT_EQ(table.rows.size(), 2u);
  EXPECT_EQ(table.number(0, table.column("b")), 2.5e-3);
  EXPECT_TRUE(std::isnan(table.number(0, table.column("c"))));
  EXPECT_EQ(table.number(1, 0), -4.0);
  EXPECT_TRUE(std::isinf(table.number(1, 1)));
}

TEST(CsvTable, ARowCutShortNamesItsLine) {
  const testing::ScratchDir dir("csv-table");
  const auto file = written(dir, "a,b,c\n1,2,3\n\n1,50\n");
  EXPECT_THAT([&] { read_csv(file); },
              ::testing::ThrowsMessage<InputError>(
                  HasSubstr(file.string() + ":4: expected 3 fields as the header has, got 2")));
}

TEST(CsvTable, ACellThatIsNotANumberNamesItsLineAndColumn) {
  const testing::ScratchDir dir("csv-table");
  const auto file = written(dir, "a,noa\n1,2\n1,xx\n1,3abc\n");
  const CsvTable table = read_csv(file);
  const std::size_t noa = table.column("noa");
  EXPECT_EQ(table.number(0, noa), 2.0);
  EXPECT_THAT([&] { table.number(1, noa); },
              ::testing::ThrowsMessage<InputError>(
                  HasSubstr(file.string() + ":3: column 'noa': expected a number, got 'xx'")));
  EXPECT_THAT([&] { table.number(2, noa); },  // std::stod read 3 and ignored the rest
              ::testing::ThrowsMessage<InputError>(HasSubstr("got '3abc'")));
  EXPECT_THAT([&] { table.column("nao"); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("has no column 'nao'")));
}

TEST(CsvReader, ReadsEachRowWithItsLineSkippingBlankOnes) {
  const testing::ScratchDir dir("csv-table");
  const auto file = written(dir, "a,b,c\n1,2.5e-3,\n\n-4,inf,7\nx,,\n");
  CsvReader reader(file);
  EXPECT_EQ(reader.header(), (std::vector<std::string>{"a", "b", "c"}));
  const std::vector<std::vector<std::string>> rows{
      {"1", "2.5e-3", ""}, {"-4", "inf", "7"}, {"x", "", ""}};
  const std::vector<std::size_t> lines{2, 4, 5};
  for (std::size_t row = 0; row < rows.size(); ++row) {
    ASSERT_TRUE(reader.next()) << row;
    EXPECT_EQ(reader.cells(), rows[row]);
    EXPECT_EQ(reader.line(), lines[row]);
  }
  EXPECT_FALSE(reader.next()) << "read past the end";
  const CsvTable whole = read_csv(file);
  EXPECT_EQ(whole.rows, rows);
  EXPECT_EQ(whole.line_of, lines);
}

TEST(CsvReader, AFolderIsNoFileToRead) {
  const testing::ScratchDir dir("csv-table");
  EXPECT_THAT([&] { CsvReader folder(dir.path()); },
              ::testing::ThrowsMessage<InputError>(
                  HasSubstr(dir.path().string() + ": is a folder; expected a CSV file")));
}

TEST(CsvReader, NumbersAndTheirErrorsNameTheLineAndColumn) {
  const testing::ScratchDir dir("csv-table");
  const auto file = written(dir, "a,noa\n1,2\n1,\n1,3abc\n");
  CsvReader reader(file);
  const std::size_t noa = reader.column("noa");
  ASSERT_TRUE(reader.next());
  EXPECT_EQ(reader.number(noa), 2.0);
  ASSERT_TRUE(reader.next());
  EXPECT_TRUE(std::isnan(reader.number(noa)));
  ASSERT_TRUE(reader.next());
  EXPECT_THAT([&] { reader.number(noa); },
              ::testing::ThrowsMessage<InputError>(
                  HasSubstr(file.string() + ":4: column 'noa': expected a number, got '3abc'")));
  EXPECT_THAT([&] { reader.column("nao"); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("has no column 'nao'")));
}

TEST(CsvReader, ARowCutShortOrAMissingFileIsAnInputError) {
  const testing::ScratchDir dir("csv-table");
  const auto file = written(dir, "a,b,c\n1,2,3\n1,50\n");
  CsvReader reader(file);
  ASSERT_TRUE(reader.next());
  EXPECT_THAT([&] { reader.next(); },
              ::testing::ThrowsMessage<InputError>(
                  HasSubstr(file.string() + ":3: expected 3 fields as the header has, got 2")));
  EXPECT_THAT([&] { CsvReader missing(dir.path() / "none.csv"); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("none.csv: no such file")));
}

// Replicates one after another, as timeseries.csv lists them: each step's values side by
// side in file order, the steps increasing, several columns in one read.
TEST(StepSeries, GroupsEachColumnByStepWithTheReplicatesSideBySide) {
  const testing::ScratchDir dir("csv-table");
  const auto file = written(dir,
                            "replicate,step,time,noa,largest\n"
                            "0,0,0,1,2\n0,10,1,2,3\n0,20,2,3,4\n"
                            "1,0,0,5,6\n1,10,1,6,7\n1,20,2,7,8\n"
                            "2,20,2,9,9\n2,5,0.5,8,8\n");
  const std::vector<StepSeries> series =
      read_step_series(file, std::vector<std::string>{"noa", "largest"});
  ASSERT_EQ(series.size(), 2u);
  EXPECT_THAT(series[0].steps, ElementsAre(0, 5, 10, 20));
  EXPECT_THAT(series[0].times, ElementsAre(0.0, 0.5, 1.0, 2.0));
  EXPECT_THAT(series[0].values, ElementsAre(ElementsAre(1, 5), ElementsAre(8), ElementsAre(2, 6),
                                            ElementsAre(3, 7, 9)));
  EXPECT_THAT(series[1].values, ElementsAre(ElementsAre(2, 6), ElementsAre(8), ElementsAre(3, 7),
                                            ElementsAre(4, 8, 9)));
  EXPECT_EQ(read_step_series(file, "largest").values, series[1].values);
  EXPECT_DOUBLE_EQ(series[0].mean_at(3), 19.0 / 3.0);
}

TEST(StepSeries, AFilterKeepsOnlyTheStepsAskedFor) {
  const testing::ScratchDir dir("csv-table");
  const auto file = written(dir,
                            "replicate,step,time,noa\n"
                            "0,0,0,1\n0,10,1,2\n0,20,2,3\n"
                            "1,0,0,5\n1,10,1,6\n1,20,2,7\n");
  const StepSeries kept =
      read_step_series(file, "noa", [](std::int64_t step) { return step != 10; });
  EXPECT_THAT(kept.steps, ElementsAre(0, 20));
  EXPECT_THAT(kept.values, ElementsAre(ElementsAre(1, 5), ElementsAre(3, 7)));
}

TEST(ModelTable, CurvesOfAQuantityOrAPrefixPerVariantInFileOrder) {
  const testing::ScratchDir dir("csv-table");
  const auto file = written(dir,
                            "model,variant,step,time,quantity,value\n"
                            "bayindir,original,0,0,noa,0\n"
                            "bayindir,original,10,1,noa,2\n"
                            "bayindir,collision,0,0,noa,0\n"
                            "bayindir,collision,10,1,noa,3\n"
                            "bayindir,original,10,,aggregates:2,1.5\n"
                            "bayindir,original,10,,aggregates:3,0.25\n"
                            "bayindir,original,,,noise_floor:rmse_noa,0.1\n");
  const std::vector<ModelCurve> noa = model_curves(file, "noa");
  ASSERT_EQ(noa.size(), 2u);
  EXPECT_EQ(noa[0].variant, "original");
  EXPECT_THAT(noa[0].x, ElementsAre(0.0, 1.0));
  EXPECT_THAT(noa[1].y, ElementsAre(0.0, 3.0));
  const std::vector<ModelCurve> later =
      model_curves(file, "noa", [](std::int64_t step) { return step > 0; });
  ASSERT_EQ(later.size(), 2u);
  EXPECT_THAT(later[0].x, ElementsAre(1.0));
  EXPECT_THAT(later[1].y, ElementsAre(3.0));
  const std::vector<ModelCurve> sizes = model_curves_by_suffix(file, "aggregates:", 3);
  ASSERT_EQ(sizes.size(), 1u);
  EXPECT_THAT(sizes[0].x, ElementsAre(2.0, 3.0));
  EXPECT_THAT(sizes[0].y, ElementsAre(1.5, 0.25));
}

TEST(ModelTable, ASizeSuffixThatIsNoNumberNamesItsLine) {
  const testing::ScratchDir dir("csv-table");
  const auto file = written(dir,
                            "model,variant,step,time,quantity,value\n"
                            "bayindir,original,10,,aggregates:2,1.5\n"
                            "bayindir,original,10,,aggregates:two,0.25\n");
  EXPECT_THAT([&] { model_curves_by_suffix(file, "aggregates:", 10); },
              ::testing::ThrowsMessage<InputError>(
                  AllOf(HasSubstr(file.string() + ":3"), HasSubstr("'aggregates:two'"))));
}

// A size no run of the world can have would size what draws it: a billion, say.
TEST(ModelTable, ASizeSuffixBeyondTheWorldsAgentsIsRefused) {
  const testing::ScratchDir dir("csv-table");
  for (const char* size : {"11", "1", "2.5", "1000000000"}) {
    const auto file = written(dir, std::string("model,variant,step,time,quantity,value\n"
                                               "bayindir,original,10,,aggregates:2,1.5\n"
                                               "bayindir,original,10,,aggregates:") +
                                       size + ",0.25\n");
    EXPECT_THAT([&] { model_curves_by_suffix(file, "aggregates:", 10); },
                ::testing::ThrowsMessage<InputError>(AllOf(
                    HasSubstr(file.string() + ":3"),
                    HasSubstr("expected aggregates:<m> with m a whole number from 2 to 10"))))
        << size;
  }
}

}  // namespace
}  // namespace swarmagg
