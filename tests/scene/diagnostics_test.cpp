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

TEST(Diagnostics, ALongChainOfFramesShowsItsEnds) {
    std::vector<std::string> frames;
    for (int i = 0; i < 30; ++i) frames.push_back("  frame " + std::to_string(i));
    const std::string m = format_diagnostic("a.inc", 1, 1, "oops", frames, "");
    std::string want = "a.inc:1:1: oops";
    for (int i = 0; i < 8; ++i) want += "\n  frame " + std::to_string(i);
    want += "\n  ... 14 more";
    for (int i = 22; i < 30; ++i) want += "\n  frame " + std::to_string(i);
    EXPECT_EQ(m, want);
    // Up to twice the ends, every frame is shown.
    frames.resize(16);
    const std::string all = format_diagnostic("a.inc", 1, 1, "oops", frames, "");
    EXPECT_EQ(all.find("more"), std::string::npos);
    EXPECT_NE(all.find("frame 15"), std::string::npos);
}

TEST(Diagnostics, TabsKeepTheCaretAligned) {
    std::string m = format_diagnostic("s.pov", 1, 3, "m", {}, "\t\tbad");
    EXPECT_EQ(m, "s.pov:1:3: m\n\t\tbad\n\t\t^");
}

TEST(Diagnostics, ALongLineIsCutAroundTheColumn) {
    std::string line(100000, 'x');
    line.replace(50000, 5, "spere");
    std::string m = format_diagnostic("s.pov", 1, 50001, "unknown keyword 'spere'", {}, line);
    const std::string shown = "..." + std::string(60, 'x') + "spere" + std::string(55, 'x') + "...";
    EXPECT_EQ(
        m, "s.pov:1:50001: unknown keyword 'spere'\n" + shown + "\n" + std::string(63, ' ') + "^");
    // Near the start only the end is cut.
    m = format_diagnostic("s.pov", 1, 3, "m", {}, std::string(500, 'y'));
    EXPECT_EQ(m, "s.pov:1:3: m\n" + std::string(120, 'y') + "...\n  ^");
}

TEST(Diagnostics, BytesThatAreNotTextEchoAsQuestionMarks) {
    // A binary file's line: control bytes and broken UTF-8 become '?', valid UTF-8 stays, and
    // the caret counts characters, not bytes.
    const std::string line = std::string("a\x01\x7f\xff") + "\xc3\xa9" + "b";
    std::string m = format_diagnostic("s.pov", 1, 7, "m", {}, line);
    EXPECT_EQ(m,
              "s.pov:1:7: m\na???\xc3\xa9"
              "b\n     ^");
}

}  // namespace
}  // namespace mirage
