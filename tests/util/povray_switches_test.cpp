// POV-Ray's spellings of trace's and compile's options, translated to their long options.
#include "util/povray_switches.h"

#include <gtest/gtest.h>

namespace mirage {
namespace {

using Words = std::vector<std::string>;

const Words kValueOptions = {"-o", "--output", "-L",       "--library-path",
                             "-W", "--image",  "--declare"};

Words trace_words(const Words& words) {
    auto r = translate_povray_switches(words, SwitchTarget::Trace, kValueOptions);
    EXPECT_TRUE(r.ok()) << r.message();
    return r.ok() ? *r : Words{};
}

Words compile_words(const Words& words) {
    auto r = translate_povray_switches(words, SwitchTarget::Compile, kValueOptions);
    EXPECT_TRUE(r.ok()) << r.message();
    return r.ok() ? *r : Words{};
}

std::string trace_error(const Words& words) {
    auto r = translate_povray_switches(words, SwitchTarget::Trace, kValueOptions);
    EXPECT_FALSE(r.ok());
    return r.ok() ? std::string() : r.message();
}

std::string compile_error(const Words& words) {
    auto r = translate_povray_switches(words, SwitchTarget::Compile, kValueOptions);
    EXPECT_FALSE(r.ok());
    return r.ok() ? std::string() : r.message();
}

TEST(PovraySwitches, SizeImageClockAndDeclareForBothCommands) {
    EXPECT_EQ(trace_words({"s.pov", "+W640", "+H480", "+Oout.png", "+K0.5", "Declare=Height=2",
                           "+Lpov_includes"}),
              (Words{"s.pov", "--width=640", "--height=480", "--output=out.png", "--clock=0.5",
                     "--declare=Height=2", "--library-path=pov_includes"}));
    // The image is compile's --image; the clock may be negative.
    EXPECT_EQ(compile_words({"s.pov", "+W64", "+H48", "+Oa.png", "+K-1.5e-3"}),
              (Words{"s.pov", "--width=64", "--height=48", "--image=a.png", "--clock=-1.5e-3"}));
    // Either case, as POV-Ray reads them.
    EXPECT_EQ(trace_words({"+w32", "+h24", "+ox.png", "declare=N=1", "+k2"}),
              (Words{"--width=32", "--height=24", "--output=x.png", "--declare=N=1", "--clock=2"}));
}

TEST(PovraySwitches, AntialiasingForTrace) {
    EXPECT_EQ(trace_words({"+A"}), Words{"--antialias"});
    EXPECT_EQ(trace_words({"+A0.1"}), Words{"--antialias=0.1"});
    EXPECT_EQ(trace_words({"+a0.3", "+AM2", "+am1", "+R3", "+r4"}),
              (Words{"--antialias=0.3", "--antialias-method=2", "--antialias-method=1",
                     "--antialias-depth=3", "--antialias-depth=4"}));
    EXPECT_EQ(trace_error({"+AMx"}), "+AMx: the antialiasing method must be 1 or 2 (+AM2)");
    EXPECT_EQ(trace_error({"+Rdeep"}),
              "+Rdeep: the antialiasing depth must be a whole number (+R3)");
    EXPECT_EQ(trace_error({"+Ahigh"}),
              "+Ahigh: the antialiasing threshold must be a number (+A0.3)");
}

TEST(PovraySwitches, CompileTakesTheDefaultThresholdOnly) {
    EXPECT_EQ(compile_words({"+A"}), Words{"--antialias"});
    EXPECT_EQ(compile_words({"+A0.3"}), Words{"--antialias"});
    const std::string why =
        ": mirage compile antialiases at POV-Ray's threshold 0.3 only, its corrected camera "
        "averaging five fixed rays in every pixel: give +A (or --antialias) alone";
    EXPECT_EQ(compile_error({"+A0.1"}), "+A0.1" + why);
    EXPECT_EQ(compile_error({"+AM2"}), "+AM2" + why);
    EXPECT_EQ(compile_error({"+R3"}), "+R3" + why);
}

TEST(PovraySwitches, TheValueAttachedAndChecked) {
    EXPECT_EQ(trace_error({"+W", "640"}),
              "+W: POV-Ray's switches take their value attached: +W640");
    EXPECT_EQ(trace_error({"+H"}), "+H: POV-Ray's switches take their value attached: +H640");
    EXPECT_EQ(trace_error({"+O"}), "+O: POV-Ray's switches take their value attached: +Oout.png");
    EXPECT_EQ(trace_error({"+W64.5"}),
              "+W64.5: the width must be a whole number of pixels (+W640)");
    EXPECT_EQ(trace_error({"+H-3"}), "+H-3: the height must be a whole number of pixels (+H640)");
    EXPECT_EQ(trace_error({"+Kx1"}),
              "+Kx1: an animation's switch (+KFI, +KFF, +KI, +KF, +KC): mirage animate renders "
              "animations; for one frame give its clock, +K0.5 (--clock 0.5)");
    EXPECT_EQ(trace_error({"+K0.5s"}), "+K0.5s: the clock must be a number (+K0.5)");
    EXPECT_EQ(trace_error({"Declare="}),
              "Declare=: give the name and the number: Declare=NAME=VALUE");
    EXPECT_EQ(compile_error({"+FN"}),
              "+FN: a POV-Ray switch mirage compile does not take (it takes +W, +H, +A, +O, +K, "
              "+L and Declare=; a file whose name begins with '+' is given as ./+FN)");
    EXPECT_EQ(trace_error({"+D"}),
              "+D: a POV-Ray switch mirage trace does not take (it takes +W, +H, +A, +AM, +R, +O, "
              "+K, +L and Declare=; a file whose name begins with '+' is given as ./+D)");
}

TEST(PovraySwitches, ValuesAndTheRestAreLeftAsTheyAre) {
    // The value of an option that takes one, and every word after "--".
    EXPECT_EQ(trace_words({"-o", "+W1.png", "-W", "64", "--", "+H2.pov"}),
              (Words{"-o", "+W1.png", "-W", "64", "--", "+H2.pov"}));
    // Long options, short options, negative numbers and a lone '+' are no POV-Ray switches.
    EXPECT_EQ(trace_words({"--width=3", "-q", "-1", "+", "+3", "./+W.pov"}),
              (Words{"--width=3", "-q", "-1", "+", "+3", "./+W.pov"}));
}

}  // namespace
}  // namespace mirage

namespace mirage {
namespace {

TEST(PovraySwitches, OffSwitchesAskForNothingButJitter) {
    EXPECT_EQ(trace_words({"-D", "s.pov", "-A", "+W64", "-J"}),
              (Words{"s.pov", "--width=64", "--no-jitter"}));
    EXPECT_EQ(compile_words({"-d", "s.pov", "-a", "-j", "+H48"}), (Words{"s.pov", "--height=48"}));
}

TEST(PovraySwitches, IniKeysAsTheSwitches) {
    EXPECT_EQ(
        trace_words({"s.pov", "Width=640", "height=480", "Output_File_Name=o.png", "Clock=0.25",
                     "Library_Path=inc", "Antialias=on", "Antialias_Threshold=0.1",
                     "Antialias_Depth=2", "Sampling_Method=2", "Jitter=off"}),
        (Words{"s.pov", "--width=640", "--height=480", "--output=o.png", "--clock=0.25",
               "--library-path=inc", "--antialias", "--antialias=0.1", "--antialias-depth=2",
               "--antialias-method=2", "--no-jitter"}));
    EXPECT_EQ(compile_words({"s.pov", "WIDTH=64", "Output_File_Name=o.png", "Antialias=off"}),
              (Words{"s.pov", "--width=64", "--image=o.png"}));
    // Checked as the switches are; other words with '=' left to the parser.
    EXPECT_EQ(trace_error({"s.pov", "Width=wide"}),
              "Width=wide: the width must be a whole number of pixels (+W640)");
    EXPECT_EQ(trace_error({"s.pov", "Antialias_Threshold="}),
              "Antialias_Threshold=: give the value after '='");
    EXPECT_NE(trace_error({"s.pov", "Antialias=maybe"}).find("on or off"), std::string::npos);
    EXPECT_NE(compile_error({"s.pov", "Sampling_Method=2"}).find("0.3 only"), std::string::npos);
    EXPECT_EQ(trace_words({"a=b.pov", "dir/Width=3.pov", "--declare", "Width=3"}),
              (Words{"a=b.pov", "dir/Width=3.pov", "--declare", "Width=3"}));
}

}  // namespace
}  // namespace mirage
