// mirage animate end to end: the mirrored image vanishing where the exact paths say, frames
// kept and redone, failures named, bad input refused, POV-Ray seeing the frame's clock, and
// a frame's bytes the same whichever runner rendered it.
#include "animate/animate.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "../cli/run_tool.h"
#include "../trace/povray_runner.h"
#include "animate/marked.h"
#include "animate/video.h"
#include "atmosphere/vanishing.h"
#include "image/image_io.h"
#include "load/atmosphere_settings.h"
#include "scene/camera.h"
#include "scene/parser.h"
#include "util/hex_args.h"
#include "util/process.h"

namespace mirage {
namespace {

namespace fs = std::filesystem;
using testing::run_tool;

const std::string kSource = MIRAGE_SOURCE_DIR;
const std::string kWalk = kSource + "/scenes/walk.pov";

std::string read_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

void write_text(const fs::path& path, const std::string& text) {
    std::ofstream out(path);
    out << text;
}

bool have_ffmpeg() { return find_program("ffmpeg").has_value() && find_program("ffprobe"); }

double symbol(const Scene& s, const std::string& name) {
    return std::get<double>(s.symbols.at(name).value);
}

// Pixels of exactly `rgb` (8-bit codes) whose camera ray leaves the eye downwards: for an
// object entirely above the eye they can only be its mirrored image (a ray going down meets
// nothing above the eye before it turns).
int mirrored_pixels(const Image& img, const Camera& cam, glm::ivec3 rgb) {
    int n = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const glm::vec3 c = img.at(x, y);
            const glm::ivec3 code(std::lround(c.x * 255.f), std::lround(c.y * 255.f),
                                  std::lround(c.z * 255.f));
            if (code != rgb) continue;
            if (camera_ray(cam, x + 0.5, y + 0.5, img.width, img.height).direction.y < 0.0) ++n;
        }
    return n;
}

TEST(Animate, MirroredImageVanishesAtTheComputedDistance) {
    if (!have_ffmpeg()) GTEST_SKIP() << "ffmpeg/ffprobe not on PATH";
    const fs::path dir = testing::test_dir("animate", "vanishing");
    // The walk with its marked spheres in flat colours.
    write_text(dir / "walk_flat.pov", "#declare Marked_Flat = 1;\n#include \"walk.pov\"\n");
    ParseOptions po;
    po.library_paths = {kSource + "/scenes", kSource + "/pov_includes"};
    po.strict = false;
    auto scene = parse_scene_file((dir / "walk_flat.pov").string(), po);
    ASSERT_TRUE(scene.ok()) << scene.message();
    auto settings = read_atmosphere_settings(*scene);
    ASSERT_TRUE(settings.ok()) << settings.message();
    const Profile profile = profile_in_scene_units(*settings);
    const glm::dvec3 red = std::get<glm::dvec3>(scene->symbols.at("Marked_Center").value);
    const double radius = symbol(*scene, "Marked_Radius");
    const double eye = symbol(*scene, "Eye_Height");
    ASSERT_GT(red.y - radius, eye) << "the count below needs the sphere above the eye";
    auto vanish = sphere_vanishing_distance(profile, eye, red.y, radius);
    ASSERT_TRUE(vanish.ok()) << vanish.message();
    // Four frames 1 m apart around the vanishing distance: 1.5 and 0.5 m before it, 0.5 and
    // 1.5 m past it.  The walk's distance is Walk_Start + (Walk_End - Walk_Start) clock.
    const double start = symbol(*scene, "Walk_Start"), end = symbol(*scene, "Walk_End");
    auto clock_at = [&](double d) { return (d - start) / (end - start); };
    std::ostringstream cmd;
    cmd.precision(9);
    cmd << "animate " << (dir / "walk_flat.pov") << " +KFI1 +KFF4 +KI" << clock_at(*vanish + 1.5)
        << " +KF" << clock_at(*vanish - 1.5) << " -L " << kSource << "/scenes"
        << " -W 320 -H 240 --model trace --tolerance 0.1 -q -o " << (dir / "out");
    const auto run = run_tool(cmd.str());
    ASSERT_EQ(run.exit_code, 0) << run.err;
    std::vector<int> counts;
    for (int f = 1; f <= 4; ++f) {
        po.animation = AnimationClock{};
        AnimationRange range;
        range.initial_frame = 1;
        range.final_frame = 4;
        range.initial_clock = clock_at(*vanish + 1.5);
        range.final_clock = clock_at(*vanish - 1.5);
        po.animation = plan_frames(range)->frames[f - 1].clock;
        auto frame_scene = parse_scene_file((dir / "walk_flat.pov").string(), po);
        ASSERT_TRUE(frame_scene.ok());
        const double d = std::hypot(red.x - frame_scene->camera.location.x,
                                    red.z - frame_scene->camera.location.z);
        auto img = read_image(
            (dir / "out" / "frames" / ("frame_000" + std::to_string(f) + ".png")).string());
        ASSERT_TRUE(img.ok()) << img.message();
        counts.push_back(mirrored_pixels(*img, frame_scene->camera, {255, 0, 255}));
        std::cout << "frame " << f << ": eye " << d << " m from the sphere (vanishes at " << *vanish
                  << " m), " << counts.back() << " mirrored pixels\n";
    }
    EXPECT_GT(counts[0], 0) << "1.5 m before the vanishing distance";
    EXPECT_GT(counts[1], 0) << "0.5 m before the vanishing distance";
    EXPECT_GT(counts[0], counts[1]) << "the image shrinks as the eye comes closer";
    EXPECT_EQ(counts[2], 0) << "0.5 m past the vanishing distance";
    EXPECT_EQ(counts[3], 0) << "1.5 m past the vanishing distance";
    // The report says the same from the exact paths.
    std::ifstream csv(dir / "out" / "vanishing.csv");
    std::string line;
    std::getline(csv, line);
    int mirrored_rows = 0, rows = 0;
    while (std::getline(csv, line)) {
        if (line.find("red sphere") == std::string::npos) continue;
        ++rows;
        mirrored_rows += line.find(",1,") != std::string::npos;
    }
    EXPECT_EQ(rows, 4);
    EXPECT_EQ(mirrored_rows, 2);
}

TEST(Animate, FramesVideoReportAndOnlyMissingFramesRedone) {
    if (!have_ffmpeg()) GTEST_SKIP() << "ffmpeg/ffprobe not on PATH";
    const fs::path dir = testing::test_dir("animate", "resume");
    const std::string cmd = "animate " + kWalk + " --frames 4 -W 64 -H 48 --model trace -q -o " +
                            (dir / "out").string();
    auto first = run_tool(cmd);
    ASSERT_EQ(first.exit_code, 0) << first.err;
    const fs::path out = dir / "out";
    for (int f = 1; f <= 4; ++f)
        EXPECT_TRUE(fs::exists(out / "frames" / ("frame_000" + std::to_string(f) + ".png")));
    auto frames = count_video_frames((out / "walk.mp4").string());
    ASSERT_TRUE(frames.ok()) << frames.message();
    EXPECT_EQ(*frames, 4);
    auto gif_frames = count_video_frames((out / "walk.gif").string());
    ASSERT_TRUE(gif_frames.ok()) << gif_frames.message();
    EXPECT_EQ(*gif_frames, 4);
    EXPECT_TRUE(fs::exists(out / "vanishing.png"));
    EXPECT_TRUE(fs::exists(out / "vanishing.svg"));
    EXPECT_TRUE(fs::exists(out / "summary.md"));

    const std::string frame3 = (out / "frames" / "frame_0003.png").string();
    const std::string bytes3 = read_bytes(frame3);
    const auto time1 = fs::last_write_time(out / "frames" / "frame_0001.png");
    fs::remove(frame3);
    auto second = run_tool(cmd);
    ASSERT_EQ(second.exit_code, 0) << second.err;
    EXPECT_EQ(read_bytes(frame3), bytes3) << "a frame rendered again has the same bytes";
    EXPECT_EQ(fs::last_write_time(out / "frames" / "frame_0001.png"), time1)
        << "a frame done before is not rendered again";
    const auto report = nlohmann::json::parse(read_bytes((out / "report.json").string()));
    std::vector<bool> now;
    for (const auto& f : report["frames"]) now.push_back(f["rendered_now"].get<bool>());
    EXPECT_EQ(now, (std::vector<bool>{false, false, true, false}));

    // Other settings over the same frames: refused, nothing touched.
    auto other = run_tool("animate " + kWalk + " --frames 4 -W 80 -H 60 --model trace -q -o " +
                          out.string());
    EXPECT_EQ(other.exit_code, 1);
    EXPECT_NE(other.err.find("holds the frames of another animation"), std::string::npos)
        << other.err;
    EXPECT_EQ(read_bytes(frame3), bytes3);
}

TEST(Animate, FailedFrameIsNamedWithItsClockAndTheOthersKept) {
    if (!have_ffmpeg()) GTEST_SKIP() << "ffmpeg/ffprobe not on PATH";
    const fs::path dir = testing::test_dir("animate", "failure");
    // From clock 0.5 on the scene needs a file that is not there yet.
    write_text(dir / "late.pov",
               "#version 3.7;\n#declare Marked_Flat = 1;\n#if (clock > 0.5)\n"
               "  #include \"later.inc\"\n#end\n#include \"walk.pov\"\n");
    const std::string cmd = "animate " + (dir / "late.pov").string() + " -L " + kSource +
                            "/scenes --frames 4 -W 48 -H 36 --model trace -q -o " +
                            (dir / "out").string();
    auto run = run_tool(cmd);
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_NE(run.err.find("2 of 4 frames failed"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("frame 3 (clock 0.666666687) failed: "), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("later.inc"), std::string::npos) << run.err;
    EXPECT_TRUE(fs::exists(dir / "out" / "frames" / "frame_0001.png"));
    EXPECT_TRUE(fs::exists(dir / "out" / "frames" / "frame_0002.png"));
    EXPECT_FALSE(fs::exists(dir / "out" / "frames" / "frame_0003.png"));
    EXPECT_FALSE(fs::exists(dir / "out" / "late.mp4"));
    const auto kept = fs::last_write_time(dir / "out" / "frames" / "frame_0001.png");
    // Once the file is there, the run completes the missing frames only.
    write_text(dir / "later.inc", "// now here\n");
    auto again = run_tool(cmd);
    ASSERT_EQ(again.exit_code, 0) << again.err;
    EXPECT_EQ(fs::last_write_time(dir / "out" / "frames" / "frame_0001.png"), kept);
    EXPECT_TRUE(fs::exists(dir / "out" / "late.mp4"));
}

TEST(Animate, BadInputNamesTheValueAndLosesNothing) {
    const fs::path dir = testing::test_dir("animate", "bad_input");
    const std::string base = "animate " + kWalk + " --model trace -W 32 -H 24 -q ";
    auto zero = run_tool(base + "--frames 0 -o " + (dir / "a").string());
    EXPECT_EQ(zero.exit_code, 1);
    EXPECT_EQ(zero.err, "mirage animate: --frames 0: must be at least 1\n");
    auto huge = run_tool(base + "--frames 1000000000 -o " + (dir / "a").string());
    EXPECT_EQ(huge.exit_code, 1);
    EXPECT_EQ(huge.err, "mirage animate: --frames 1000000000: at most 100000 frames\n");
    auto empty = run_tool(base + "+KFI5 +KFF2 -o " + (dir / "a").string());
    EXPECT_EQ(empty.exit_code, 1);
    EXPECT_EQ(empty.err,
              "mirage animate: a frame range with no frames: +KFF2 2 is before +KFI5 5\n");
    auto subset = run_tool(base + "--frames 8 +SF9 -o " + (dir / "a").string());
    EXPECT_EQ(subset.exit_code, 1);
    EXPECT_NE(subset.err.find("+SF9 9 is frame 9, after the last frame 8"), std::string::npos)
        << subset.err;
    EXPECT_FALSE(fs::exists(dir / "a")) << "nothing written for a bad range";

    write_text(dir / "file", "a file, not a directory\n");
    auto unwritable = run_tool(base + "--frames 2 -o " + (dir / "file" / "out").string());
    EXPECT_EQ(unwritable.exit_code, 1);
    EXPECT_NE(unwritable.err.find((dir / "file" / "out").string() +
                                  ": cannot create the output directory"),
              std::string::npos)
        << unwritable.err;
    EXPECT_EQ(read_bytes((dir / "file").string()), "a file, not a directory\n");

    // --slurm with no sbatch on PATH: refused before anything is rendered.
    if (have_ffmpeg()) {
        fs::create_directories(dir / "bin");
        fs::create_symlink(*find_program("ffmpeg"), dir / "bin" / "ffmpeg");
        const std::string with_path = "PATH=" + (dir / "bin").string() + " " +
                                      std::string(MIRAGE_BINARY_DIR) + "/mirage " + base +
                                      "--frames 2 --slurm -o " + (dir / "b").string() + " 2>&1";
        FILE* p = popen(with_path.c_str(), "r");
        std::string said;
        char buf[512];
        while (std::fgets(buf, sizeof buf, p)) said += buf;
        EXPECT_NE(pclose(p), 0);
        EXPECT_EQ(said,
                  "mirage animate: --slurm: sbatch is not on PATH (run on the cluster's login "
                  "node, or install slurm-client)\n");
        EXPECT_FALSE(fs::exists(dir / "b" / "frames" / "frame_0001.png"));
    }
}

TEST(Animate, PovRaySeesTheClockTheCompilerSaw) {
    if (!testing::povray_available() || !have_ffmpeg()) GTEST_SKIP() << "povray or ffmpeg missing";
    const fs::path dir = testing::test_dir("animate", "bands_clock");
    // The camera walks with the clock, and both parsers print what they see.
    write_text(dir / "clocked.pov",
               "#version 3.7;\n#declare Mirage_Preset = \"paper\";\n#include \"mirage.inc\"\n"
               "#debug concat(\"clock=\", str(clock, 0, 12), \" frame=\", str(frame_number, 0, "
               "0), \" delta=\", str(clock_delta, 0, 12), \"\\n\")\n"
               "camera { location <0, 1.5, 10 * clock> look_at <0, 1, 10 * clock + 10> angle 60 }\n"
               "light_source { <0, 50, -20>, rgb 1 }\n"
               "plane { y, 0 pigment { checker rgb 0.2, rgb 0.8 } }\n"
               "sphere { <0, 2, 20>, 1 pigment { rgb <1, 0, 0> } }\n");
    auto run = run_tool("animate " + (dir / "clocked.pov").string() +
                        " +KFI2 +KFF5 +KI0.1 +KF0.7 -W 40 -H 30 -q -o " + (dir / "out").string());
    ASSERT_EQ(run.exit_code, 0) << run.err;
    AnimationRange range;
    range.initial_frame = 2;
    range.final_frame = 5;
    range.initial_clock = 0.1;
    range.final_clock = 0.7;
    auto plan = plan_frames(range);
    ASSERT_TRUE(plan.ok());
    for (const auto& f : plan->frames) {
        ParseOptions po;
        po.animation = f.clock;
        po.library_paths = {kSource + "/pov_includes"};
        po.strict = false;
        auto ours = parse_scene_file((dir / "clocked.pov").string(), po);
        ASSERT_TRUE(ours.ok()) << ours.message();
        std::string said;
        for (const auto& m : ours->messages)
            if (m.find("clock=") != std::string::npos) said = m;
        ASSERT_FALSE(said.empty());
        const std::string values = said.substr(said.find("clock="));
        const std::string log = read_bytes(
            (dir / "out" / "frames" / ("frame_000" + std::to_string(f.number)) / "povray.log")
                .string());
        EXPECT_NE(log.find(values), std::string::npos)
            << "frame " << f.number << ": the compiler saw '" << values << "'";
    }
    // POV-Ray dates its images; a frame rendered again has the same bytes all the same.
    const fs::path frame = dir / "out" / "frames" / "frame_0003.png";
    const std::string before = read_bytes(frame.string());
    EXPECT_EQ(before.find("tIME"), std::string::npos);
    EXPECT_EQ(before.find("Render Date"), std::string::npos);
    fs::remove(frame);
    auto again = run_tool("animate " + (dir / "clocked.pov").string() +
                          " +KFI2 +KFF5 +KI0.1 +KF0.7 -W 40 -H 30 -q -o " + (dir / "out").string());
    ASSERT_EQ(again.exit_code, 0) << again.err;
    EXPECT_EQ(read_bytes(frame.string()), before);
    auto img = read_image(frame.string());
    ASSERT_TRUE(img.ok()) << img.message();
    EXPECT_EQ(img->width, 40);
}

TEST(Animate, ReadsTheRangeFromAnIniFile) {
    if (!have_ffmpeg()) GTEST_SKIP() << "ffmpeg/ffprobe not on PATH";
    const fs::path dir = testing::test_dir("animate", "ini");
    write_text(dir / "walk.ini",
               "; three frames of the walk\nInitial_Frame=3\nFinal_Frame=5\nInitial_Clock=0.2\n"
               "Antialias=on\n");
    auto run = run_tool("animate " + kWalk + " " + (dir / "walk.ini").string() +
                        " --model trace -W 32 -H 24 -o " + (dir / "out").string());
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_NE(run.out.find("note: " + (dir / "walk.ini").string() +
                           ":5: Antialias: not an animation option, ignored"),
              std::string::npos)
        << run.out;
    for (int f = 3; f <= 5; ++f)
        EXPECT_TRUE(
            fs::exists(dir / "out" / "frames" / ("frame_000" + std::to_string(f) + ".png")));
    EXPECT_FALSE(fs::exists(dir / "out" / "frames" / "frame_0001.png"));
    const auto first =
        nlohmann::json::parse(read_bytes((dir / "out/frames/frame_0003.json").string()));
    EXPECT_EQ(first["clock"].get<double>(), static_cast<double>(0.2f));
    auto frames = count_video_frames((dir / "out" / "walk.mp4").string());
    ASSERT_TRUE(frames.ok()) << frames.message();
    EXPECT_EQ(*frames, 3);
}

TEST(Animate, EachFramesSceneIsLoadedAsCompileAndTraceLoadIt) {
    // The second frame's camera is out of mirage's reach: the check is the scene loader's
    // (load/mirage_scene.h), made with that frame's clock, before the table of vanishing
    // distances is made.
    const fs::path dir = testing::test_dir("animate", "floor");
    write_text(dir / "far.pov",
               "#version 3.7;\n"
               "#declare Mirage_Preset = \"paper\";\n"
               "#include \"mirage.inc\"\n"
               "camera { location <0, (clock > 0.5 ? 1e308 : 1.5), 0> look_at <0, 1, 10> }\n"
               "sphere { <0, 1, 10>, 1 pigment { rgb 1 } }\n");
    AnimateOptions o;
    o.scene = (dir / "far.pov").string();
    o.frames = 2;
    o.width = 32;
    o.height = 24;
    auto a = resolve_animation(o);
    ASSERT_TRUE(a.ok()) << a.message();
    auto rows = vanishing_rows(*a);
    ASSERT_FALSE(rows.ok());
    EXPECT_EQ(rows.message(),
              "frame 2 (clock 1): " + fs::absolute(dir / "far.pov").string() +
                  ":4:1: the camera is at y = 1e+308: mirage follows scenes within 1e+09 units "
                  "of the origin");
}

// Real air: walking down the hot road of scenes/hot_road.csv (the general engine, on the curved
// Earth) towards a balloon above the eye.  The report's vanishing distance comes from the same
// fitted model the tracer renders; the traced frames show the balloon's mirrored image (pixels
// of its flat colour whose rays leave the eye downwards) 15 and 5 % farther than that
// distance, and none 5 and 15 % nearer.
TEST(Animate, RealAirMirroredImageVanishesAtTheComputedDistance) {
    if (!have_ffmpeg()) GTEST_SKIP() << "ffmpeg/ffprobe not on PATH";
    const fs::path dir = testing::test_dir("animate", "real_air_vanishing");
    fs::copy_file(kSource + "/scenes/hot_road.csv", dir / "hot_road.csv",
                  fs::copy_options::overwrite_existing);
    const std::string text =
        "#version 3.7;\n"
        "#declare Mirage_Sounding = \"hot_road.csv\";\n"
        "#declare Mirage_Tolerance = 0.1;\n"
        "#include \"mirage.inc\"\n"
        "#declare Walk_Start = 800;\n"
        "#declare Walk_End = 200;\n"
        "#declare Eye_Distance = Walk_Start + (Walk_End - Walk_Start) * clock;\n"
        "#declare Marked_Center = <0, 1.9, 1000>;\n"
        "#declare Marked_Radius = 0.3;\n"
        "#declare Marked_Name = \"balloon\";\n"
        "camera { location <0, 1.2, 1000 - Eye_Distance>\n"
        "  look_at <0, 1.2 - 100 * tan(radians(0.2)), 1100 - Eye_Distance>\n"
        "  right x * image_width / image_height angle 1.5 }\n"
        "sky_sphere { pigment { color rgb <0.6, 0.7, 0.9> } }\n"
        "plane { y, 0 pigment { color rgb 0.3 } finish { ambient 1 diffuse 0 } }\n"
        "sphere { Marked_Center, Marked_Radius\n"
        "  texture { pigment { color rgb <1, 0, 1> } finish { ambient 1 diffuse 0 } } }\n";
    write_text(dir / "balloon.pov", text);
    ParseOptions po;
    po.library_paths = {dir.string(), kSource + "/pov_includes"};
    po.strict = false;
    auto scene = parse_scene_file((dir / "balloon.pov").string(), po);
    ASSERT_TRUE(scene.ok()) << scene.message();
    auto views = view_marked_spheres(*scene, 320, 240);
    ASSERT_TRUE(views.ok()) << views.message();
    ASSERT_EQ(views->size(), 1u);
    const double vanish = (*views)[0].vanishing_distance;
    // A hot road's mirage: some hundreds of metres out (the sounding's own figures).
    ASSERT_GT(vanish, 200.0);
    ASSERT_LT(vanish, 700.0);
    const double start = 800.0, end = 200.0;
    auto clock_at = [&](double d) { return (d - start) / (end - start); };
    const double first = clock_at(1.15 * vanish), last = clock_at(0.85 * vanish);
    std::ostringstream cmd;
    cmd.precision(9);
    cmd << "animate " << (dir / "balloon.pov") << " +KFI1 +KFF4 +KI" << first << " +KF" << last
        << " -W 320 -H 240 --model trace -q -o " << (dir / "out");
    const auto run = run_tool(cmd.str());
    ASSERT_EQ(run.exit_code, 0) << run.err;
    std::vector<int> counts;
    AnimationRange range;
    range.initial_frame = 1;
    range.final_frame = 4;
    range.initial_clock = first;
    range.final_clock = last;
    for (int f = 1; f <= 4; ++f) {
        po.animation = plan_frames(range)->frames[f - 1].clock;
        auto frame_scene = parse_scene_file((dir / "balloon.pov").string(), po);
        ASSERT_TRUE(frame_scene.ok());
        auto img = read_image(
            (dir / "out" / "frames" / ("frame_000" + std::to_string(f) + ".png")).string());
        ASSERT_TRUE(img.ok()) << img.message();
        counts.push_back(mirrored_pixels(*img, frame_scene->camera, {255, 0, 255}));
        std::cout << "frame " << f << ": eye " << 1000.0 - frame_scene->camera.location.z
                  << " m from the balloon (vanishes at " << vanish << " m), " << counts.back()
                  << " mirrored pixels\n";
    }
    EXPECT_GT(counts[0], 0) << "15 % farther than the vanishing distance";
    EXPECT_GT(counts[1], 0) << "5 % farther";
    EXPECT_GT(counts[0], counts[1]) << "the image shrinks as the eye comes closer";
    EXPECT_EQ(counts[2], 0) << "5 % nearer";
    EXPECT_EQ(counts[3], 0) << "15 % nearer";
    std::ifstream csv(dir / "out" / "vanishing.csv");
    std::string line;
    std::getline(csv, line);
    int mirrored_rows = 0, rows = 0;
    while (std::getline(csv, line)) {
        if (line.find("balloon") == std::string::npos) continue;
        ++rows;
        mirrored_rows += line.find(",1,") != std::string::npos;
    }
    EXPECT_EQ(rows, 4);
    EXPECT_EQ(mirrored_rows, 2);
}

TEST(Animate, MarkedSpheresAreSeenAboveTheDeclaredGround) {
    // The same scene with its floor at y = 0 and at y = -1 (Mirage_Ground_Height = -1): the
    // marked sphere's vanishing distance and mirrored image are the same; without the setting
    // the ground is 1 m under the floor and they are not.
    auto scene = [](double floor, const std::string& ground_line) {
        std::ostringstream s;
        s << "#version 3.7;\n#declare Mirage_Preset = \"paper\";\n"
          << ground_line << "#include \"mirage.inc\"\n"
          << "camera { location <0, " << 1.5 + floor << ", 0> look_at <0, " << 1.5 + floor
          << ", 10> }\n"
          << "#declare Marked_Center = <0, " << 1.8 + floor << ", 14>;\n"
          << "#declare Marked_Radius = 0.2;\n"
          << "plane { y, " << floor << " pigment { rgb 1 } }\n"
          << "sphere { Marked_Center, Marked_Radius pigment { rgb x } }\n";
        ParseOptions po;
        po.library_paths = {kSource + "/pov_includes"};
        po.strict = false;
        auto parsed = parse_scene_text(s.str(), "scene.pov", po);
        EXPECT_TRUE(parsed.ok()) << parsed.message();
        auto views = view_marked_spheres(*parsed, 64, 48);
        EXPECT_TRUE(views.ok()) << views.message();
        return views.ok() && views->size() == 1 ? (*views)[0] : MarkedView{};
    };
    const MarkedView at_zero = scene(0.0, "");
    const MarkedView lowered = scene(-1.0, "#declare Mirage_Ground_Height = -1;\n");
    const MarkedView wrong = scene(-1.0, "");
    ASSERT_GT(at_zero.vanishing_distance, 0.0);
    EXPECT_NEAR(lowered.vanishing_distance, at_zero.vanishing_distance, 1e-9);
    EXPECT_EQ(lowered.mirrored, at_zero.mirrored);
    EXPECT_NEAR(lowered.elevation_low_deg, at_zero.elevation_low_deg, 1e-9);
    EXPECT_NEAR(lowered.angular_size_deg, at_zero.angular_size_deg, 1e-9);
    EXPECT_GT(std::abs(wrong.vanishing_distance - at_zero.vanishing_distance), 1e-3);
}

TEST(Animate, SlurmScriptStatesTheResourcesPerTask) {
    AnimateOptions o;
    o.scene = kWalk;
    o.frames = 12;
    o.threads = 2;
    o.slurm.partition = "render";
    o.slurm.mem = "3G";
    o.slurm.time = "00:20:00";
    o.out_dir = "/shared/walk";
    o.self = "/opt/mirage/bin/mirage";
    auto a = resolve_animation(o);
    ASSERT_TRUE(a.ok()) << a.message();
    EXPECT_EQ(slurm_array_list({1, 2, 3, 4, 7, 9, 10}), "1-4,7,9-10");
    const std::string s = slurm_script(*a, {1, 2, 3, 5});
    for (const char* line :
         {"#SBATCH --array=1-3,5\n", "#SBATCH --ntasks=1\n", "#SBATCH --cpus-per-task=2\n",
          "#SBATCH --mem=3G\n", "#SBATCH --time=00:20:00\n", "#SBATCH --partition=render\n"})
        EXPECT_NE(s.find(line), std::string::npos) << line << " in\n" << s;
    // The names of files go to sbatch as arguments, never into a line of the script.
    const auto argv = slurm_submit_argv(*a, "job.sbatch");
    ASSERT_EQ(argv.size(), 6u);
    EXPECT_EQ(argv[1], "--parsable");
    EXPECT_EQ(argv[2], "--job-name=mirage-walk");
    EXPECT_EQ(argv[3], "--output=/shared/walk/frames/frame_%4a.log");
    EXPECT_EQ(argv[5], "job.sbatch");
    EXPECT_NE(s.find("# The task: /opt/mirage/bin/mirage animate " + kWalk +
                     " --frames 12 -W 320 -H 240 --model bands -o /shared/walk --threads 2 "
                     "--frame \"$SLURM_ARRAY_TASK_ID\"\n"),
              std::string::npos)
        << s;
    // The task itself, its options in hex.
    const std::string exec = "exec /opt/mirage/bin/mirage --args-hex ";
    const auto at = s.find(exec);
    ASSERT_NE(at, std::string::npos) << s;
    const auto hex = s.substr(at + exec.size(), s.find(' ', at + exec.size()) - at - exec.size());
    std::vector<std::string> task = a->task_argv("");
    task.erase(task.begin());
    EXPECT_EQ(args_from_hex(hex), task);
    EXPECT_NE(s.find(hex + " --frame \"$SLURM_ARRAY_TASK_ID\"\n"), std::string::npos) << s;
}

TEST(Animate, FramesOverGnuParallelAreByteIdenticalToLocalOnes) {
    if (!have_ffmpeg() || !find_program("parallel"))
        GTEST_SKIP() << "ffmpeg or GNU parallel missing";
    const fs::path dir = testing::test_dir("animate", "hosts");
    const std::string out = (dir / "out").string();
    const std::string cmd =
        "animate " + kWalk + " --frames 3 -W 48 -H 36 --model trace -q -o " + out;
    auto local = run_tool(cmd);
    ASSERT_EQ(local.exit_code, 0) << local.err;
    std::vector<std::string> bytes;
    for (int f = 1; f <= 3; ++f) {
        const std::string p = out + "/frames/frame_000" + std::to_string(f) + ".png";
        bytes.push_back(read_bytes(p));
        fs::remove(p);
    }
    // ':' is this machine in an sshloginfile: GNU parallel runs the same task lines it would
    // send over ssh.
    write_text(dir / "hosts.txt", "2/:\n");
    auto hosts = run_tool(cmd + " --hosts " + (dir / "hosts.txt").string());
    ASSERT_EQ(hosts.exit_code, 0) << hosts.err;
    for (int f = 1; f <= 3; ++f)
        EXPECT_EQ(read_bytes(out + "/frames/frame_000" + std::to_string(f) + ".png"), bytes[f - 1])
            << "frame " << f;
    EXPECT_TRUE(fs::exists(dir / "out" / "hosts" / "joblog.txt"));
}

}  // namespace
}  // namespace mirage
