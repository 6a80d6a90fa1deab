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
  EXPECT_TRUE(std::isnan(parseNumber(formatNumber(std::nan("")))));
  EXPECT_EQ(parseNumber(formatNumber(-INFINITY)), -INFINITY);
  EXPECT_THROW(parseNumber("1.5x"), std::invalid_argument);
  EXPECT_THROW(parseNumber(""), std::invalid_argument);
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
