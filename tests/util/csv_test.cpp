#include "util/csv.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mirage {
namespace {

TEST(Csv, FieldsKnowTheirLineAndColumn) {
    auto t = parse_csv("a,b,c\n1,\"two, three\",3\n\n4,55,6\n", "t.csv");
    ASSERT_TRUE(t.ok()) << t.message();
    ASSERT_EQ(t->rows.size(), 2u);
    EXPECT_EQ(to_string(t->rows[0].places[1]), "t.csv:2:3");
    EXPECT_EQ(to_string(t->rows[0].places[2]), "t.csv:2:16");
    EXPECT_EQ(t->where(t->rows[1], 2), "t.csv:4:6: column 'c'");
}

TEST(Csv, AByteOrderMarkIsNotPartOfTheHeader) {
    auto t = parse_csv(
        "\xEF\xBB\xBF"
        "case_id,y0\nA,1\n",
        "bom.csv");
    ASSERT_TRUE(t.ok()) << t.message();
    EXPECT_EQ(t->column("case_id"), 0);
    EXPECT_EQ(to_string(t->rows[0].places[0]), "bom.csv:2:1");
}

TEST(Csv, NumbersAreDecimalAndInTheRangeOfADouble) {
    auto t = parse_csv("x\n1e999\n0x1p3\n2.5e-3\nnan\n1e-400\nabc\n", "n.csv");
    ASSERT_TRUE(t.ok());
    EXPECT_EQ(csv_number(*t, t->rows[0], 0).message(),
              "n.csv:2:1: column 'x': '1e999' is out of the range of a double");
    EXPECT_EQ(csv_number(*t, t->rows[1], 0).message(),
              "n.csv:3:1: column 'x': '0x1p3' is not a decimal number");
    EXPECT_DOUBLE_EQ(*csv_number(*t, t->rows[2], 0), 2.5e-3);
    EXPECT_TRUE(std::isnan(*csv_number(*t, t->rows[3], 0)));  // the reference's own "nan"
    EXPECT_EQ(*csv_number(*t, t->rows[4], 0), 0.0);           // an underflow loses only digits
    EXPECT_EQ(csv_number(*t, t->rows[5], 0).message(),
              "n.csv:7:1: column 'x': 'abc' is not a number");
}

}  // namespace
}  // namespace mirage
