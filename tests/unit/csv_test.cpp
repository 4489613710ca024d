// The one CSV writer: what a spreadsheet would run is defused, numbers stay numbers.
#include <gtest/gtest.h>

#include "app/measure/report.h"
#include "app/util/csv.h"

using namespace shadelab;

TEST(Csv, QuotesWhatWouldSplitACell) {
  EXPECT_EQ(csvField("plain"), "plain");
  EXPECT_EQ(csvField(""), "");
  EXPECT_EQ(csvField("a,b"), "\"a,b\"");
  EXPECT_EQ(csvField("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(csvField("two\nlines"), "\"two\nlines\"");
}

TEST(Csv, DefusesFormulasButNotNumbers) {
  EXPECT_EQ(csvField("=HYPERLINK(\"x\")"), "\"'=HYPERLINK(\"\"x\"\")\"");
  EXPECT_EQ(csvField("+1+2"), "'+1+2");
  EXPECT_EQ(csvField("-cmd"), "'-cmd");
  EXPECT_EQ(csvField("@SUM(A1)"), "'@SUM(A1)");
  EXPECT_EQ(csvField("\t=1"), "'\t=1");
  EXPECT_EQ(csvField("-0.25"), "-0.25");
  EXPECT_EQ(csvField("+3"), "+3");
  EXPECT_EQ(csvField("-1e-3"), "-1e-3");
  EXPECT_EQ(csvField("-1-1"), "'-1-1");
}

TEST(Csv, ASweepTableDefusesANameAUserChose) {
  SweepReport r;
  SweepRow row;
  row.params = {{"scene", "=cmd|' /C calc'!A0"}, {"bias", "-0.002"}};
  row.values = {{"rmse", 0.5}};
  r.rows = {row};
  EXPECT_EQ(sweepCsv(r), "scene,bias,truth,rmse\n'=cmd|' /C calc'!A0,-0.002,,0.5\n");
}
