// CSV files read back (plots, model errors, reports): a damaged file is an error naming the
// file, the line and what was wrong, not a point silently dropped or a bare "stod".
#include "analysis/csv_table.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "core/errors.hpp"
#include "testing/scratch_dir.hpp"

namespace swarmagg {
namespace {

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

}  // namespace
}  // namespace swarmagg
