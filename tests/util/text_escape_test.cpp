#include "util/text_escape.h"

#include <gtest/gtest.h>

#include <string>

#include "util/hex_args.h"
#include "util/json_text.h"

namespace mirage {
namespace {

TEST(TextEscape, ControlBytesAndBrokenUtf8BecomeEscapes) {
    EXPECT_EQ(escape_control("plain: a b-c.pov"), "plain: a b-c.pov");
    EXPECT_EQ(escape_control(std::string("a\nb\r\t\0c", 7)), "a\\nb\\r\\t\\0c");
    EXPECT_EQ(escape_control("\x1b[2Jx\x7f"), "\\x1b[2Jx\\x7f");
    EXPECT_EQ(escape_control("sc\xff.pov"), "sc\\xff.pov");
    EXPECT_EQ(escape_control("\xc3\xa9t\xc3\xa9 \xe2\x82\xac"), "\xc3\xa9t\xc3\xa9 \xe2\x82\xac");
    EXPECT_EQ(escape_control("\xc2\x9b"
                             "31m"),
              "\\u009b31m");                                       // C1 CSI
    EXPECT_EQ(escape_control("\xc0\xaf"), "\\xc0\\xaf");           // overlong '/'
    EXPECT_EQ(escape_control("\xed\xa0\x80"), "\\xed\\xa0\\x80");  // a surrogate
    EXPECT_EQ(escape_terminal("line one\nline \x1b two"), "line one\nline \\x1b two");
}

TEST(TextEscape, ArgumentsGoThroughHexAndBack) {
    const std::vector<std::string> args = {"animate", "w\ntouch PWNED\n{}.pov", "", "\xff"};
    const std::string hex = args_to_hex(args);
    EXPECT_EQ(hex.find_first_not_of("0123456789abcdef"), std::string::npos);
    EXPECT_EQ(args_from_hex(hex), args);
    EXPECT_EQ(args_from_hex("61"), std::nullopt);  // not ended
    EXPECT_EQ(args_from_hex("6g00"), std::nullopt);
}

TEST(TextEscape, JsonIsWrittenFromAnyBytes) {
    nlohmann::json j;
    j["scene"] = "sc\xff.pov";
    EXPECT_EQ(json_text(j, -1), "{\"scene\":\"sc\xef\xbf\xbd.pov\"}");
}

}  // namespace
}  // namespace mirage
