// The Markdown parameter tables of the reference pages: numbers as the pages write them, ranges
// with their open bound and whole-number mark, cells that cannot break the table.
#include <gtest/gtest.h>

#include "framework/params/param_table_markdown.h"

namespace upf {
namespace {

TEST(ParamTableMarkdown, NumbersAreWrittenCompactly) {
  EXPECT_EQ(compact_number(0), "0");
  EXPECT_EQ(compact_number(1000), "1000");
  EXPECT_EQ(compact_number(1e4), "1e4");
  EXPECT_EQ(compact_number(1e5), "1e5");
  EXPECT_EQ(compact_number(1e-6), "1e-6");
  EXPECT_EQ(compact_number(5e-3), "5e-3");
  EXPECT_EQ(compact_number(0.01), "0.01");
  EXPECT_EQ(compact_number(0.4), "0.4");
  EXPECT_EQ(compact_number(2500), "2500");
}

TEST(ParamTableMarkdown, RangesShowTheOpenBoundAndWholeNumbers) {
  EXPECT_EQ(param_range_text({"cfl", "1", 0.4, 0, 1, "", false, true}), "(0, 1]");
  EXPECT_EQ(param_range_text({"n", "1", 3, 1, 1000, "", true}), "[1, 1000], whole number");
}

TEST(ParamTableMarkdown, RowsNameKeyUnitDefaultRangeAndMeaning) {
  const std::string table =
      param_table_markdown({{"dt_max", "s", 5e-3, 0, 10, "a |v| bound", false, true}}, "/time/");
  EXPECT_EQ(table,
            "| Key | Unit | Default | Range | Meaning |\n|---|---|---|---|---|\n"
            "| `/time/dt_max` | s | 5e-3 | (0, 10] | a \\|v\\| bound |\n");
}

}  // namespace
}  // namespace upf
