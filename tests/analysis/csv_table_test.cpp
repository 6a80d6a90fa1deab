#include <cmath>
#include <sstream>

#include <gtest/gtest.h>

#include "analysis/csv_table.hpp"

namespace sl {
namespace {

TEST(CsvTable, NumbersRoundTripExactly) {
  for (double value : {0.1, 1.0 / 3.0, -2.5e-300, 6.02214076e23, 5e-324, 1e-13, 0.0}) {
    EXPECT_EQ(parseNumber(formatNumber(value)), value) << formatNumber(value);
  }
  EXPECT_EQ(formatNumber(0.1), "0.1");  // shortest form, not 0.10000000000000001
  // Non-finite values are no value: an empty field (a CSV never holds nan or inf), read back as NaN.
  for (double value : {std::nan(""), double(INFINITY), -double(INFINITY)}) {
    EXPECT_EQ(formatNumber(value), "");
    EXPECT_TRUE(std::isnan(parseNumber(formatNumber(value))));
  }
  EXPECT_THROW(parseNumber("1.5x"), std::invalid_argument);
}

// The console tables of bench and stability: every column starts at the same offset on every line
// (bulirsch-stoer rows were misaligned), and a field with no value shows as "-".
TEST(CsvTable, AlignedTextLinesUpItsColumns) {
  const CsvTable table{{"method", "integrator", "error"},
                       {{"ambient", "bulirsch-stoer", "1e-12"}, {"christoffel-fd", "rk4", ""}, {"x", "dopri5", "0.5"}}};
  const std::string text = alignedText(table);
  std::istringstream lines(text);
  std::string line;
  std::vector<std::string> all;
  while (std::getline(lines, line)) all.push_back(line);
  ASSERT_EQ(all.size(), 4u);
  const std::size_t second = all[0].find("integrator"), third = all[0].find("error");
  for (const std::string& l : all) {
    EXPECT_NE(l[second], ' ') << l;
    EXPECT_EQ(l[second - 1], ' ') << l;
    EXPECT_NE(l[third], ' ') << l;
    EXPECT_EQ(l[third - 1], ' ') << l;
    EXPECT_NE(l.back(), ' ') << "trailing blanks: " << l;
  }
  EXPECT_EQ(all[2].substr(third), "-");
}

TEST(CsvTable, QuotedFieldsSurviveARoundTrip) {
  CsvTable table{{"name", "detail"}, {{"a", "plain"}, {"b", "with, comma and \"quotes\"\nand a newline"}}};
  std::istringstream in(csvText(table));
  const CsvTable back = readCsv(in, "memory");
  EXPECT_EQ(back.columns, table.columns);
  EXPECT_EQ(back.rows, table.rows);
  EXPECT_EQ(back.text(1, "name"), "b");
  EXPECT_THROW(back.column("missing"), std::out_of_range);
}

TEST(CsvTable, ARowWithTheWrongFieldCountNamesTheFileAndLine) {
  std::istringstream in("a,b\n1,2\n3\n");
  try {
    readCsv(in, "shard.csv");
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("shard.csv:3"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace sl
