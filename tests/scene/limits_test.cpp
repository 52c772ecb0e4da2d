// The parser against hostile and broken scenes: every limit ends the parse with a message
// naming the place and the limit, never a crash, a hang or memory without end.  The
// reproducers of the crashes found by hand and by the fuzz target are here with their exact
// messages (tests/fuzz/crashes/ replays them all through the fuzz target too).
#include <gtest/gtest.h>
#include <pthread.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "parse_helpers.h"

namespace mirage {
namespace {

using testing::parse_error;
using testing::parse_ok;

std::string first_line(const std::string& s) { return s.substr(0, s.find('\n')); }

std::string repeat(const std::string& s, int n) {
    std::string out;
    for (int i = 0; i < n; ++i) out += s;
    return out;
}

TEST(Limits, ADirectiveInsideAConditionsValueMayNotCloseIt) {
    // The inner #end used to pop the #switch, and the outer #case then read an empty stack.
    EXPECT_EQ(first_line(parse_error("#switch(1)#case(#case(1)#end 1)")),
              "scene.pov:1:17: '#case' inside the value of '#case' at 1:11");
    // The #end of a loop inside the loop's own condition recursed without end.
    EXPECT_EQ(first_line(parse_error("#while (1 #end")),
              "scene.pov:1:11: '#end' inside the condition of '#while' at 1:1");
    EXPECT_EQ(first_line(parse_error("#if (0)\n#elseif (1 #end)\n#end")),
              "scene.pov:2:12: '#end' inside the condition of '#elseif' at 2:1");
    EXPECT_EQ(first_line(parse_error("#while (1 #break)\n#end")),
              "scene.pov:1:11: '#break' inside the condition of '#while' at 1:1");
    // A conditional opened in a value must close there.
    EXPECT_EQ(first_line(parse_error("#switch (1)\n#case (#if (1) 1)\n#end\n#end")),
              "scene.pov:2:1: '#if' at 2:8 is not closed in the value of '#case' at 2:1");
    // What stays allowed: a conditional opened and closed inside a value.
    Scene s = parse_ok("#switch (2) #case (#if (1) 2 #end) #declare B = 1; #break #end");
    EXPECT_DOUBLE_EQ(testing::float_symbol(s, "B"), 1.0);
}

TEST(Limits, ALoopMustEndAfterTheDirectivesInIt) {
    // The #end jumped back to the loop's start in the middle of the #declare, which then
    // began again inside itself: a stack overflow.
    EXPECT_EQ(first_line(parse_error("#declare I=0; #while (I < 10) #declare I = I + #end")),
              "scene.pov:1:48: '#end' of the '#while' at 1:15 comes inside the '#declare' at "
              "1:31: a loop must end after the directives in it");
    ParseOptions lenient;
    lenient.strict = false;
    EXPECT_EQ(first_line(
                  parse_error("#declare I = 0; #while (I < 10) #declare I = normal #end", lenient)),
              "scene.pov:1:53: '#end' of the '#while' at 1:17 comes inside the '#declare' at "
              "1:33: a loop must end after the directives in it");
    EXPECT_EQ(first_line(parse_error("#for (I, 0, 3) #declare X = (I #end)")),
              "scene.pov:1:32: '#end' of the '#for' at 1:1 comes inside the '#declare' at 1:16: "
              "a loop must end after the directives in it");
    // Loops inside values and macros called from values keep working.
    Scene s = parse_ok(
        "#macro Sum(N) #local S = 0; #local I = 1; #while (I <= N) #local S = S + I; "
        "#local I = I + 1; #end S #end\n"
        "#declare T = Sum(4);\n");
    EXPECT_DOUBLE_EQ(testing::float_symbol(s, "T"), 10.0);
}

TEST(Limits, NestingDeeperThanTheLimitIsAnErrorNotAStackOverflow) {
    const std::string deep =
        "scene.pov:1:%d: nesting too deep: more than 256 levels of parentheses, objects and "
        "directives inside each other";
    auto expected = [&](int column) {
        char buf[200];
        std::snprintf(buf, sizeof buf, deep.c_str(), column);
        return std::string(buf);
    };
    // The 257th union; in a #declare the directive is one of the levels: the 256th
    // parenthesis, the 256th minus, the 255th choice of ?: (its value is one more), the 256th
    // concat.
    EXPECT_EQ(first_line(parse_error(repeat("union {", 2500))), expected(1 + 7 * 256));
    EXPECT_EQ(first_line(parse_error("#declare X = " + repeat("(", 10000) + "1" +
                                     repeat(")", 10000) + ";")),
              expected(14 + 255));
    EXPECT_EQ(first_line(parse_error("#declare X = " + repeat("-", 30000) + "1;")),
              expected(14 + 255));
    EXPECT_EQ(first_line(parse_error("#declare X = (" + repeat("1 ? ", 3000) + "1" +
                                     repeat(" : 0", 3000) + ");")),
              expected(15 + 4 * 254));
    EXPECT_EQ(first_line(parse_error("#declare S = " + repeat("concat(", 3000) + "\"a\"" +
                                     repeat(")", 3000) + ";")),
              expected(14 + 7 * 255));
    EXPECT_EQ(first_line(parse_error(repeat("#if (1)\n", 3000))),
              "scene.pov:257:1: conditional directives nested more than 256 deep, mirage's "
              "limit");
    // Within the limit it parses.
    Scene s =
        parse_ok("#declare X = " + repeat("(", 200) + "2" + repeat(")", 200) + ";\n" +
                 repeat("union {", 200) + "sphere { 0, 1 } sphere { 1, 1 }" + repeat("}", 200));
    EXPECT_DOUBLE_EQ(testing::float_symbol(s, "X"), 2.0);
    EXPECT_EQ(s.primitives.size(), 2u);
}

// The level count does not bound the stack by itself: a parse on a thread with a small stack
// (or in a build with large frames) stops at the stack it has, with the same kind of message.
TEST(Limits, NestingStopsAtTheStackThisThreadHasNotPastIt) {
    ParseOptions o;
    o.limits.max_nesting = 1000000;  // only the stack can stop these
    o.limits.max_loop_passes = 1000000;
    const std::vector<std::string> deep = {
        repeat("union {", 200000),
        "#declare X = " + repeat("(", 200000) + "1" + repeat(")", 200000) + ";",
        "#declare A = " + repeat("#declare B = ", 100000) + "1;",
    };
    for (const std::string& text : deep) {
        std::string message;
        pthread_attr_t attr;
        ASSERT_EQ(pthread_attr_init(&attr), 0);
        ASSERT_EQ(pthread_attr_setstacksize(&attr, std::size_t{4} << 20), 0);  // 4 MiB
        struct Job {
            const std::string* text;
            const ParseOptions* options;
            std::string* message;
        } job{&text, &o, &message};
        pthread_t thread;
        ASSERT_EQ(pthread_create(
                      &thread, &attr,
                      [](void* p) -> void* {
                          auto* j = static_cast<Job*>(p);
                          auto r = parse_scene_text(*j->text, "scene.pov", *j->options);
                          *j->message = r ? "parsed" : r.message();
                          return nullptr;
                      },
                      &job),
                  0);
        pthread_join(thread, nullptr);
        pthread_attr_destroy(&attr);
        EXPECT_NE(first_line(message).find(": nesting too deep: "), std::string::npos)
            << first_line(message);
        EXPECT_NE(first_line(message).find("fill the stack this parse has"), std::string::npos)
            << first_line(message);
    }
}

// An endless recursion of macros stops at the limit of frames or at the stack, whichever
// comes first (with a Release build's frames, the stack: a #declare's value holds values of
// several KiB); the message shows the ends of the chain, not hundreds of lines.
TEST(Limits, AnEndlessMacroRecursionNamesItsEnds) {
    const std::string m =
        parse_error("#macro Inc(V) #declare V = Inc(K) #end\n#declare K = 1;\nInc(K)\n");
    const std::string first = first_line(m);
    EXPECT_TRUE(first.find("too many nested macro calls and include files") != std::string::npos ||
                first.find("nesting too deep") != std::string::npos)
        << first;
    EXPECT_LT(std::count(m.begin(), m.end(), '\n'), 25) << m;
    std::smatch more;
    ASSERT_TRUE(std::regex_search(m, more, std::regex("\n  \\.\\.\\. ([0-9]+) more\n"))) << m;
    EXPECT_GT(std::stoi(more[1]), 50) << m;
    // The innermost frame first, the scene's own call last.
    EXPECT_NE(m.find("\n  in macro 'Inc' called from scene.pov:1:28\n"), std::string::npos) << m;
    EXPECT_NE(m.find("in macro 'Inc' called from scene.pov:3:1\n"), std::string::npos) << m;
}

TEST(Limits, CopiesMayNotNestOrGrowWithoutEnd) {
    ParseOptions o;
    o.limits.max_objects = 1000;
    EXPECT_EQ(first_line(parse_error("#declare U = sphere { 0, 1 }\n"
                                     "#while (1)\n"
                                     "  #declare U = union { object { U } object { U } }\n"
                                     "#end\n",
                                     o)),
              "scene.pov:3:46: more than 1000 objects parsed or copied in all, mirage's limit");
    EXPECT_EQ(first_line(parse_error("#declare U = sphere { 0, 1 }\n"
                                     "#while (1)\n"
                                     "  #declare U = union { object { U } sphere { 0, 1 } }\n"
                                     "#end\n")),
              "scene.pov:3:33: 'U' holds objects or arrays nested more than 256 deep, mirage's "
              "limit");
    EXPECT_EQ(first_line(parse_error("#declare A = array[1];\n#declare A[0] = 1;\n"
                                     "#while (1) #declare A[0] = A; #end\n")),
              "scene.pov:3:28: 'A' holds objects or arrays nested more than 256 deep, mirage's "
              "limit");
}

TEST(Limits, LoopsHaveAPassLimitThatNamesTheLoop) {
    EXPECT_EQ(first_line(parse_error("sphere { 0, 1 }\n#while (1)\n#end\n")),
              "scene.pov:2:1: '#while' reached mirage's limit of 1000000 loop passes (all "
              "loops together): an endless loop?");
    ParseOptions o;
    o.limits.max_loop_passes = 1000;
    EXPECT_EQ(first_line(parse_error("#for (I, 0, 1e12)\n#end\n", o)),
              "scene.pov:1:1: '#for' reached mirage's limit of 1000 loop passes (all loops "
              "together): an endless loop?");
    // The passes of nested loops add up.
    EXPECT_EQ(first_line(parse_error("#for (I, 1, 40)\n  #for (J, 1, 40)\n  #end\n#end\n", o)),
              "scene.pov:2:3: '#for' reached mirage's limit of 1000 loop passes (all loops "
              "together): an endless loop?");
    Scene within = parse_ok(
        "#declare N = 0;\n#for (I, 1, 30)\n  #for (J, 1, 30)\n    #declare N = N + 1;\n  "
        "#end\n#end\n",
        o);
    EXPECT_DOUBLE_EQ(testing::float_symbol(within, "N"), 900.0);
}

TEST(Limits, AnArrayDeclaredAnewInItsElementsValueIsAnError) {
    // The element's place was kept as a pointer into the array the value's own #declare
    // freed (found by the fuzz target: heap use after free).
    EXPECT_EQ(first_line(parse_error("#declare A = array[2]\n#declare A[0] = #declare A = "
                                     "array[2] 5;\n")),
              "scene.pov:2:10: the array 'A' was declared anew while the value of its element "
              "was read");
    Scene s = parse_ok("#declare A = array[2]\n#declare A[1] = 5;\n#declare B = A[1];\n");
    EXPECT_DOUBLE_EQ(testing::float_symbol(s, "B"), 5.0);
}

TEST(Limits, ArraysAndStringsHaveASize) {
    EXPECT_EQ(first_line(parse_error("#declare A = array[1e9];")),
              "scene.pov:1:19: an array of more than 1000000 elements, mirage's limit");
    EXPECT_EQ(first_line(parse_error("#declare A = array[1000][1000][1000];")),
              "scene.pov:1:31: an array of more than 1000000 elements, mirage's limit");
    EXPECT_EQ(first_line(parse_error("#declare A = array[2];\n#declare B = A[1e300];")),
              "scene.pov:2:15: index 1e+300 of the array 'A' is out of range 0 to 1");
    ParseOptions o;
    o.limits.max_string_bytes = 1024;
    EXPECT_EQ(first_line(parse_error(
                  "#declare S = \"ab\";\n#while (1) #declare S = concat(S, S); #end\n", o)),
              "scene.pov:2:25: a string of 2048 bytes, more than the 1024 bytes mirage keeps");
}

TEST(Limits, NumbersStayFiniteAndIntegersInRange) {
    EXPECT_EQ(first_line(parse_error("#declare X = 1e999;")),
              "scene.pov:1:14: the number 1e999 is out of the range of a double");
    EXPECT_EQ(first_line(parse_error("#declare X = 1e300 * 1e300;")),
              "scene.pov:1:20: '*' gives inf, not a finite number");
    EXPECT_EQ(first_line(parse_error("#declare X = exp(1000);")),
              "scene.pov:1:14: this expression gives inf, not a finite number");
    EXPECT_EQ(first_line(parse_error("#declare X = bitwise_and(1e20, 1);")),
              "scene.pov:1:26: an argument of bitwise_and() 1e+20 is out of range: it must be "
              "from -2147483648 to 2147483647");
    EXPECT_EQ(first_line(parse_error("#declare X = seed(1e20);")),
              "scene.pov:1:14: seed 1e+20 is out of range: it must be from -2147483648 to "
              "2147483647");
    EXPECT_EQ(first_line(parse_error("#declare S = str(1, 1e9, 2);")),
              "scene.pov:1:21: the width of str() 1e+09 is out of range: it must be from -100 to "
              "100");
    EXPECT_EQ(first_line(parse_error("#declare S = substr(\"abc\", 1e300, 1);")),
              "scene.pov:1:14: substr(\"abc\", 1e+300, 1) is outside the string");
    // max_trace_level far past 256 is still POV-Ray's warning and 256.
    Scene s = parse_ok("global_settings { max_trace_level 1e30 }");
    EXPECT_EQ(s.global.max_trace_level, 256);
}

class LimitsOnFiles : public ::testing::Test {
  protected:
    std::filesystem::path dir_ = std::filesystem::path(::testing::TempDir()) /
                                 ("mirage_limits_" + std::to_string(::getpid()));
    void SetUp() override { std::filesystem::create_directories(dir_); }
    void TearDown() override { std::filesystem::remove_all(dir_); }
    std::string write(const std::string& name, const std::string& text) {
        const auto p = dir_ / name;
        std::ofstream(p, std::ios::binary) << text;
        return p.string();
    }
};

TEST_F(LimitsOnFiles, ASceneMustBeARegularFileOfBoundedSize) {
    auto dir = parse_scene_file(dir_.string(), ParseOptions{});
    ASSERT_FALSE(dir.ok());
    EXPECT_EQ(dir.message(), dir_.string() + ": is a directory, not a scene file");
    auto zero = parse_scene_file("/dev/zero", ParseOptions{});
    ASSERT_FALSE(zero.ok());
    EXPECT_EQ(zero.message(),
              "/dev/zero: is not a regular file (a device, a pipe or a socket?): scenes are read "
              "from files");
    ParseOptions small;
    small.limits.max_source_bytes = 1000;
    const std::string big = write("big.pov", std::string(2000, ' '));
    auto r = parse_scene_file(big, small);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.message(), big +
                               ": is 2000 bytes, more than the 1000 bytes mirage reads (the "
                               "scene and its include files together)");
    // Includes: the same checks, named at the #include.
    EXPECT_EQ(first_line(parse_error("#include \"/dev/zero\"")),
              "scene.pov:1:10: include file '/dev/zero' is not a regular file (a device, a pipe "
              "or a socket?): scenes are read from files");
    const std::string main = write("main.pov", "#include \"big.pov\"\n");
    auto inc = parse_scene_file(main, small);
    ASSERT_FALSE(inc.ok());
    EXPECT_EQ(first_line(inc.message()),
              main + ":1:10: include file '" + big +
                  "' would bring the files read to 2019 bytes, more than the 1000 bytes mirage "
                  "reads (the scene and its include files together)");
    // Every file read is listed: the scene first, then its includes.
    write("small.inc", "#declare A = 1;\n");
    const std::string top = write("top.pov", "#include \"small.inc\"\n#include \"small.inc\"\n");
    auto ok = parse_scene_file(top, ParseOptions{});
    ASSERT_TRUE(ok.ok()) << ok.message();
    ASSERT_EQ(ok->files.size(), 2u);
    EXPECT_EQ(ok->files[0], top);
    EXPECT_EQ(ok->files[1], (dir_ / "small.inc").string());
}

}  // namespace
}  // namespace mirage

namespace mirage {
namespace {

std::string first_line_of(const std::string& s) { return s.substr(0, s.find('\n')); }

// Big-endian bytes for the files the tests make.
void put16(std::string& s, unsigned v) {
    s += static_cast<char>((v >> 8) & 0xFF);
    s += static_cast<char>(v & 0xFF);
}
void put32(std::string& s, std::uint32_t v) {
    put16(s, v >> 16);
    put16(s, v & 0xFFFF);
}

// A PNG file's header claiming `width` x `height` grey pixels, with one empty IDAT: the size a
// reader sees before it decodes a pixel.
std::string png_header(std::uint32_t width, std::uint32_t height) {
    auto crc = [](const std::string& bytes) {
        std::uint32_t c = 0xFFFFFFFFu;
        for (unsigned char b : bytes) {
            c ^= b;
            for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
        }
        return c ^ 0xFFFFFFFFu;
    };
    auto chunk = [&](const std::string& type, const std::string& data) {
        std::string out;
        put32(out, static_cast<std::uint32_t>(data.size()));
        out += type + data;
        put32(out, crc(type + data));
        return out;
    };
    std::string ihdr;
    put32(ihdr, width);
    put32(ihdr, height);
    ihdr += std::string("\x08\x00\x00\x00\x00", 5);  // 8 bits, grey, deflate, no interlace
    return std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", ihdr) +
           chunk("IDAT", std::string("\x78\x9c\x03\x00\x00\x00\x00\x01", 8)) + chunk("IEND", "");
}

// A TrueType font whose 'A' is a composite glyph naming 16 copies of a composite glyph, 8
// levels deep (16^8 copies of a triangle), and whose 'B' is a simple glyph of 25 000 points.
std::string exploding_font() {
    std::vector<std::string> glyphs;
    // 0: .notdef and 1: a triangle.
    for (int g = 0; g < 2; ++g) {
        std::string t;
        put16(t, 1);  // one contour
        for (int b : {0, 0, 100, 100}) put16(t, b);
        put16(t, 2);                  // its last point
        put16(t, 0);                  // no instructions
        t += std::string(3, '\x01');  // on the curve, coordinates as words
        for (int x : {0, 100, 50}) put16(t, static_cast<unsigned>(x));
        for (int y : {0, 0, 100}) put16(t, static_cast<unsigned>(y));
        glyphs.push_back(t);
    }
    // 2..9: each 16 copies of the one before.
    for (int g = 2; g <= 9; ++g) {
        std::string t;
        put16(t, 0xFFFF);  // -1 contours: composite
        for (int b : {0, 0, 100, 100}) put16(t, b);
        for (int k = 0; k < 16; ++k) {
            put16(t, 1 | 2 | (k < 15 ? 32 : 0));  // word args, x-y values, more to come
            put16(t, static_cast<unsigned>(g - 1));
            put16(t, static_cast<unsigned>(k));
            put16(t, 0);
        }
        glyphs.push_back(t);
    }
    // 10: 25 000 points at the origin (flags: on the curve, x and y the same as before).
    {
        std::string t;
        put16(t, 1);
        for (int b : {0, 0, 100, 100}) put16(t, b);
        put16(t, 24999);
        put16(t, 0);
        t += std::string(25000, '\x31');
        glyphs.push_back(t);
    }
    const unsigned count = static_cast<unsigned>(glyphs.size());
    std::string glyf, loca;
    for (const auto& g : glyphs) {
        put32(loca, static_cast<std::uint32_t>(glyf.size()));
        glyf += g;
    }
    std::string head(54, '\0');
    {
        std::string magic;
        put32(magic, 0x5F0F3CF5u);
        head.replace(12, 4, magic);
        std::string em;
        put16(em, 1000);
        head.replace(18, 2, em);
        std::string loc;
        put16(loc, 1);  // long offsets
        head.replace(50, 2, loc);
    }
    std::string maxp;
    put32(maxp, 0x00005000u);
    put16(maxp, count);
    std::string hhea(36, '\0');
    {
        std::string n;
        put16(n, count);
        hhea.replace(34, 2, n);
    }
    std::string hmtx;
    for (unsigned g = 0; g < count; ++g) {
        put16(hmtx, 600);
        put16(hmtx, 0);
    }
    std::string cmap;
    put16(cmap, 0);
    put16(cmap, 1);  // one subtable
    put16(cmap, 1);  // Macintosh
    put16(cmap, 0);
    put32(cmap, 12);
    put16(cmap, 0);  // format 0
    put16(cmap, 262);
    put16(cmap, 0);
    std::string map(256, '\0');
    map['A'] = 9;
    map['B'] = 10;
    cmap += map;
    const std::pair<const char*, const std::string*> tables[] = {
        {"cmap", &cmap}, {"glyf", &glyf}, {"head", &head}, {"hhea", &hhea},
        {"hmtx", &hmtx}, {"loca", &loca}, {"maxp", &maxp}};
    std::string font;
    put32(font, 0x00010000u);
    put16(font, 7);
    put16(font, 0);
    put16(font, 0);
    put16(font, 0);
    std::uint32_t offset = 12 + 16 * 7;
    std::string data;
    for (const auto& [tag, bytes] : tables) {
        font += tag;
        put32(font, 0);
        put32(font, offset + static_cast<std::uint32_t>(data.size()));
        put32(font, static_cast<std::uint32_t>(bytes->size()));
        data += *bytes;
    }
    return font + data;
}

class HostileFiles : public ::testing::Test {
  protected:
    const std::filesystem::path dir_ = std::filesystem::path(::testing::TempDir()) /
                                       ("mirage_hostile_files_" + std::to_string(::getpid()));
    void SetUp() override { std::filesystem::create_directories(dir_); }
    void TearDown() override { std::filesystem::remove_all(dir_); }
    std::string write(const std::string& name, const std::string& bytes) {
        std::ofstream(dir_ / name, std::ios::binary) << bytes;
        return (dir_ / name).string();
    }
    std::string error(const std::string& scene) {
        const std::string path = write("scene.pov", scene);
        auto r = parse_scene_file(path, ParseOptions{});
        return r.ok() ? std::string("(no error)") : first_line_of(r.message());
    }
};

// An image's size is checked against the limit from its header, before its pixels are decoded
// (a 40000^2 PNG of a few hundred bytes took 4.8 GB as floats).
TEST_F(HostileFiles, AnImageLargerThanTheLimitIsRefusedByItsHeader) {
    const std::string big = write("big.png", png_header(40000, 40000));
    const std::string why = big +
                            ": the image is 40000x40000 pixels, more than the 16777216 pixels "
                            "(4096x4096) mirage reads for an image map or a height field";
    EXPECT_EQ(error("plane { y, 0 pigment { image_map { png \"big.png\" } } }"),
              dir_.string() + "/scene.pov:1:40: " + why);
    EXPECT_EQ(error("height_field { png \"big.png\" }"), dir_.string() + "/scene.pov:1:20: " + why);
    // A small image with the same header form is read.
    write("small.png", png_header(2, 2));
    EXPECT_EQ(
        error("plane { y, 0 pigment { image_map { png \"small.png\" } } }").find("pixels, more"),
        std::string::npos);
}

// A glyph's work is bounded when the font is read: composite glyphs naming parts that name
// parts (1.2 to 1.4 s a ray and up to 1 GB with mutated fonts) and glyphs of very many points.
TEST_F(HostileFiles, AFontsGlyphsAreBoundedWhenTheyAreRead) {
    const std::string font = write("boom.ttf", exploding_font());
    EXPECT_EQ(error("text { ttf \"boom.ttf\" \"A\" 1, 0 }"),
              dir_.string() + "/scene.pov:1:12: " + font +
                  ": the glyph of U+0041 is made of more than 1000 parts");
    EXPECT_EQ(error("text { ttf \"boom.ttf\" \"B\" 1, 0 }"),
              dir_.string() + "/scene.pov:1:12: " + font +
                  ": the glyph of U+0042 has 25000 points, more than the 20000 mirage traces in "
                  "a glyph");
    // A device or a directory is no font (find_scene_file looks for regular files only).
    EXPECT_EQ(error("text { ttf \"/dev/zero\" \"A\" 1, 0 }"),
              dir_.string() + "/scene.pov:1:12: cannot find the font file '/dev/zero'");
}

// Every token read counts, each time it is read: a loop whose body is an include file or a
// chain of macros reaches this limit long before the passes'.
TEST_F(HostileFiles, TheTokensReadHaveALimit) {
    write("body.inc", "#declare A = 1; #declare B = A + 2; #declare C = B * 3;\n");
    ParseOptions o;
    o.limits.max_tokens = 10000;
    const std::string path = write("loop.pov",
                                   "#declare I = 0;\n#while (I < 1000)\n#include \"body.inc\"\n"
                                   "#declare I = I + 1;\n#end\n");
    auto r = parse_scene_file(path, o);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(first_line_of(r.message())
                  .find(": the scene reached mirage's limit of 10000 tokens read (those of loops, "
                        "macros and include files each time they are read): an endless loop?"),
              std::string::npos)
        << r.message();
    o.limits.max_tokens = 100000;
    EXPECT_TRUE(parse_scene_file(path, o).ok());
}

}  // namespace
}  // namespace mirage
