// The frames and clock values of an animation, against POV-Ray 3.7 itself: the same options
// given to POV-Ray (which prints every frame's identifiers with #debug) and to the plan, whose
// values the project's parser then evaluates.
#include "animate/frame_plan.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "../trace/povray_runner.h"
#include "scene/parser.h"

namespace mirage {
namespace {

namespace fs = std::filesystem;

constexpr const char* kNames[] = {"clock",       "clock_on",      "clock_delta", "initial_clock",
                                  "final_clock", "initial_frame", "final_frame", "frame_number"};

// Declares each identifier's value as V_<name>, and prints it for POV-Ray.
std::string probe_scene() {
    std::ostringstream s;
    s << "#version 3.7;\n";
    for (const char* n : kNames) {
        s << "#declare V_" << n << " = " << n << ";\n";
        s << "#debug concat(\"V " << n << " \", str(V_" << n << ", 0, 12), \"\\n\")\n";
    }
    s << "sphere { 0, 1 pigment { rgb 1 } }\n";
    return s.str();
}

Result<AnimationRange> range_of(const std::vector<std::string>& switches) {
    AnimationRange r;
    for (const auto& s : switches) {
        auto read = read_animation_option(s, "", r);
        if (!read) return read.error();
        if (!*read) return make_error("not an animation option: " + s);
    }
    return r;
}

// POV-Ray's values, frame by frame, as printed by the probe.
std::vector<std::map<std::string, double>> povray_frames(const std::vector<std::string>& switches,
                                                         const fs::path& dir) {
    {
        std::ofstream out(dir / "probe.pov");
        out << probe_scene();
    }
    std::string cmd = "cd '" + dir.string() + "' && povray -D +W4 +H4 +Iprobe.pov +Oprobe.png";
    for (const auto& s : switches) cmd += " " + s;
    cmd += " > povray.log 2>&1";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
    std::ifstream log(dir / "povray.log");
    std::vector<std::map<std::string, double>> frames;
    std::string line;
    while (std::getline(log, line)) {
        std::istringstream in(line);
        std::string tag, name;
        double v;
        if (!(in >> tag >> name >> v) || tag != "V") continue;
        if (name == kNames[0]) frames.emplace_back();
        if (!frames.empty()) frames.back()[name] = v;
    }
    return frames;
}

std::map<std::string, double> our_values(const AnimationClock& clock) {
    ParseOptions po;
    po.animation = clock;
    auto scene = parse_scene_text(probe_scene(), "probe.pov", po);
    EXPECT_TRUE(scene.ok()) << (scene.ok() ? "" : scene.message());
    std::map<std::string, double> v;
    if (!scene.ok()) return v;
    for (const char* n : kNames)
        v[n] = std::get<double>(scene->symbols.at(std::string("V_") + n).value);
    return v;
}

void expect_same_as_povray(const std::vector<std::string>& switches, const std::string& name) {
    if (!testing::povray_available()) GTEST_SKIP() << "povray is not on PATH";
    const fs::path dir = testing::test_dir("frame_plan", name);
    const auto theirs = povray_frames(switches, dir);
    auto range = range_of(switches);
    ASSERT_TRUE(range.ok()) << range.message();
    auto plan = plan_frames(*range);
    ASSERT_TRUE(plan.ok()) << plan.message();
    ASSERT_EQ(plan->frames.size(), theirs.size())
        << "frames rendered by POV-Ray (log in " << dir << ")";
    for (std::size_t f = 0; f < theirs.size(); ++f) {
        const auto ours = our_values(plan->frames[f].clock);
        for (const char* n : kNames) {
            // POV-Ray prints 12 decimals: a float-rounded value differs from its double by more.
            EXPECT_NEAR(ours.at(n), theirs[f].at(n), 6e-13) << n << " of frame " << f;
        }
    }
}

TEST(FramePlan, AnimationClocksAreExactlyPovRays) {
    // Clocks that are not exact in binary: POV-Ray rounds them to single precision.
    expect_same_as_povray({"+KFI3", "+KFF10", "+KI0.1", "+KF0.7"}, "range");
}

TEST(FramePlan, SubsetOfFramesIsPovRays) {
    expect_same_as_povray({"+KFI1", "+KFF9", "+KI-0.3", "+KF2.2", "+SF4", "+EF6"}, "subset");
}

TEST(FramePlan, FractionalSubsetIsPovRays) {
    expect_same_as_povray({"+KFF10", "+SF0.25", "+EF0.5"}, "fraction");
}

TEST(FramePlan, CyclicAnimationIsPovRays) {
    expect_same_as_povray({"+KFI1", "+KFF4", "+KC"}, "cyclic");
}

TEST(FramePlan, StillWithAClockIsPovRays) { expect_same_as_povray({"+K0.3"}, "still_clock"); }

TEST(FramePlan, StillIsPovRays) { expect_same_as_povray({}, "still"); }

TEST(FramePlan, FrameCountsAndDigits) {
    AnimationRange r;
    r.final_frame = 120;
    auto plan = plan_frames(r);
    ASSERT_TRUE(plan.ok()) << plan.message();
    EXPECT_TRUE(plan->animation);
    EXPECT_EQ(plan->frames.size(), 120u);
    EXPECT_EQ(plan->digits, 3);
    EXPECT_EQ(plan->frames.front().number, 1);
    EXPECT_DOUBLE_EQ(plan->frames.front().clock.clock, 0.0);
    EXPECT_DOUBLE_EQ(plan->frames.back().clock.clock, 1.0);
}

TEST(FramePlan, RangesWithNoFramesNameTheOption) {
    AnimationRange r;
    ASSERT_TRUE(read_animation_option("+KFI5", "", r).ok());
    ASSERT_TRUE(read_animation_option("Final_Frame=2", "walk.ini:3", r).ok());
    auto plan = plan_frames(r);
    ASSERT_FALSE(plan.ok());
    EXPECT_EQ(plan.message(),
              "a frame range with no frames: walk.ini:3: Final_Frame 2 is before +KFI5 5");

    AnimationRange s;
    s.final_frame = 10;
    s.subset_start = 12;
    auto sub = plan_frames(s);
    ASSERT_FALSE(sub.ok());
    EXPECT_NE(sub.message().find("Subset_Start_Frame 12 is frame 12, after the last frame 10"),
              std::string::npos)
        << sub.message();

    AnimationRange e;
    e.final_frame = 10;
    e.subset_start = 6;
    e.subset_end = 3;
    EXPECT_FALSE(plan_frames(e).ok());

    AnimationRange huge;
    huge.final_frame = 1000000000;
    auto h = plan_frames(huge);
    ASSERT_FALSE(h.ok());
    EXPECT_NE(h.message().find("1000000000 frames"), std::string::npos) << h.message();
    EXPECT_NE(h.message().find("at most 100000"), std::string::npos) << h.message();

    AnimationRange one;
    one.initial_frame = 3;
    one.final_frame = 3;
    EXPECT_FALSE(plan_frames(one).ok());
}

TEST(FramePlan, ReadsIniFilesAndSwitches) {
    const fs::path dir = testing::test_dir("frame_plan", "ini");
    {
        std::ofstream ini(dir / "walk.ini");
        ini << "; the walk\nInitial_Frame = 2\nfinal_frame=8 ; inclusive\nInitial_Clock=0.5\n"
               "Antialias=on\nCyclic_Animation=off\n[other]\nFinal_Frame=99\n";
    }
    AnimationRange r;
    std::vector<std::string> ignored;
    ASSERT_TRUE(read_animation_ini((dir / "walk.ini").string(), r, ignored).ok());
    EXPECT_EQ(r.initial_frame, 2);
    EXPECT_EQ(r.final_frame, 8);  // the section after the label is not read
    EXPECT_EQ(r.initial_clock, 0.5);
    ASSERT_EQ(ignored.size(), 1u);
    EXPECT_EQ(ignored[0], (dir / "walk.ini").string() + ":5: Antialias");

    EXPECT_FALSE(*read_animation_option("+KLA", "", r));  // clockless animation: not ours
    EXPECT_FALSE(*read_animation_option("+W320", "", r));
    EXPECT_TRUE(*read_animation_option("+kff12", "", r));
    EXPECT_EQ(r.final_frame, 12);
    auto bad = read_animation_option("+KFFten", "", r);
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.message(), "+KFFten: Final_Frame 'ten' is not a number");
    auto bad_ini = read_animation_option("Final_Clock=x", "walk.ini:4", r);
    ASSERT_FALSE(bad_ini.ok());
    EXPECT_EQ(bad_ini.message(), "walk.ini:4: Final_Clock 'x' is not a number");
}

TEST(FramePlan, ParserSeesTheThreadsClock) {
    AnimationClock c;
    c.clock = 0.25;
    c.clock_on = true;
    c.frame_number = 7;
    const std::string text =
        "#declare A = clock; #declare B = frame_number; #declare C = clock_on;\n";
    {
        ScopedAnimationClock scoped(c);
        auto s = parse_scene_text(text, "s.pov", ParseOptions{});
        ASSERT_TRUE(s.ok()) << s.message();
        EXPECT_EQ(std::get<double>(s->symbols.at("A").value), 0.25);
        EXPECT_EQ(std::get<double>(s->symbols.at("B").value), 7.0);
        EXPECT_EQ(std::get<double>(s->symbols.at("C").value), 1.0);
    }
    auto still = parse_scene_text(text, "s.pov", ParseOptions{});
    ASSERT_TRUE(still.ok()) << still.message();
    EXPECT_EQ(std::get<double>(still->symbols.at("A").value), 0.0);
    EXPECT_EQ(std::get<double>(still->symbols.at("C").value), 0.0);
}

}  // namespace
}  // namespace mirage
