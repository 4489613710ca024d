// The one CSV writer: what a spreadsheet would run is defused, numbers stay numbers.
#include <gtest/gtest.h>

#include "app/measure/report.h"
#include "app/util/csv.h"

using namespace shadelab;

// Each cell as written, and as the CSV must hold it.
TEST(Csv, QuotesWhatWouldSplitACellAndDefusesFormulasButNotNumbers) {
  const std::pair<const char*, const char*> cells[] = {
      {"plain", "plain"},
      {"", ""},
      {"a,b", "\"a,b\""},
      {"say \"hi\"", "\"say \"\"hi\"\"\""},
      {"two\nlines", "\"two\nlines\""},
      {"=HYPERLINK(\"x\")", "\"'=HYPERLINK(\"\"x\"\")\""},  // a formula: defused, then quoted
      {"+1+2", "'+1+2"},
      {"-cmd", "'-cmd"},
      {"@SUM(A1)", "'@SUM(A1)"},
      {"\t=1", "'\t=1"},
      {"-1-1", "'-1-1"},
      {"-0.25", "-0.25"},  // numbers are read as numbers, never run
      {"+3", "+3"},
      {"-1e-3", "-1e-3"},
  };
  for (auto [cell, written] : cells) EXPECT_EQ(csvField(cell), written) << cell;
}

TEST(Csv, ASweepTableDefusesANameAUserChose) {
  SweepReport r;
  SweepRow row;
  row.params = {{"scene", "=cmd|' /C calc'!A0"}, {"bias", "-0.002"}};
  row.values = {{"rmse", 0.5}};
  r.rows = {row};
  EXPECT_EQ(sweepCsv(r), "scene,bias,truth,rmse\n'=cmd|' /C calc'!A0,-0.002,,0.5\n");
}
