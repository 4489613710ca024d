// app/util/format.h: the one place numbers and names become the text sentences quote.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "app/util/format.h"

namespace shadelab {

TEST(Format, SignificantDigitsAsPrintfGWritesThem) {
  EXPECT_EQ(formatSignificant(0.35), "0.35");
  EXPECT_EQ(formatSignificant(2.0 / 3.0, 2), "0.67");
  EXPECT_EQ(formatSignificant(1234.5678, 4), "1235");
  EXPECT_EQ(formatSignificant(1.2e-5, 3), "1.2e-05");
  EXPECT_EQ(formatSignificant(100.0), "100");
  EXPECT_EQ(formatSignificant(std::numeric_limits<double>::infinity()), "inf");
}

TEST(Format, FixedDecimalsAndQuotedNames) {
  EXPECT_EQ(formatFixed(0.12345, 2), "0.12");
  EXPECT_EQ(formatFixed(2.0, 1), "2.0");
  EXPECT_EQ(quoted("no acne"), "'no acne'");
  EXPECT_EQ(englishList({"a", "b", "c"}, "'"), "'a', 'b' and 'c'");
  EXPECT_EQ(englishList({"a", "b", "c", "d"}, "", 2), "a, b and 2 more");
  EXPECT_EQ(englishList({"a", "b"}, "", 2), "a and b");
  EXPECT_EQ(englishList({}, ""), "");
}

}  // namespace shadelab
