#include "scene/diagnostics.h"

#include <gtest/gtest.h>

namespace mirage {
namespace {

TEST(Diagnostics, PlaceMessageSourceLineAndCaret) {
    std::string m = format_diagnostic("scene.pov", 12, 7, "unknown keyword 'spere'", {},
                                      "union { spere { 0, 1 } }");
    EXPECT_EQ(m,
              "scene.pov:12:7: unknown keyword 'spere'\n"
              "union { spere { 0, 1 } }\n"
              "      ^");
}

TEST(Diagnostics, ContextLinesComeAfterTheFirstLine) {
    std::string m =
        format_diagnostic("inc/a.inc", 3, 1, "oops", {"  included from scene.pov:3:1"}, "x");
    EXPECT_EQ(m, "inc/a.inc:3:1: oops\n  included from scene.pov:3:1\nx\n^");
}

TEST(Diagnostics, TabsKeepTheCaretAligned) {
    std::string m = format_diagnostic("s.pov", 1, 3, "m", {}, "\t\tbad");
    EXPECT_EQ(m, "s.pov:1:3: m\n\t\tbad\n\t\t^");
}

}  // namespace
}  // namespace mirage
