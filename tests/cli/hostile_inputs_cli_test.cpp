// Every command given values out of range and input files that are not what they claim to
// be (issue 29): each reproducer gives a clear message naming the file, line and column or
// the option, the value and the limit, a non-zero exit, and leaves nothing behind.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

#include "../trace/povray_runner.h"
#include "run_tool.h"

namespace mirage {
namespace {

namespace fs = std::filesystem;
using testing::quoted;
using testing::read_bytes;
using testing::write_bytes;
using testing::run_tool;
using testing::test_dir;

const std::string kDesert = std::string(MIRAGE_SOURCE_DIR) + "/scenes/desert.pov";
const std::string kSetting = "#declare Mirage_Tolerance = 0.5;";

/// The desert scene with `line` added after its tolerance setting, as dir/name.
fs::path desert_plus(const fs::path& dir, const std::string& name, const std::string& line) {
    std::string text = read_bytes(kDesert);
    const auto at = text.find(kSetting);
    EXPECT_NE(at, std::string::npos);
    const auto end = text.find('\n', at);
    text.insert(end + 1, line + "\n");
    write_bytes(dir / name, text);
    return dir / name;
}

/// The line (1-based) of the desert scene after its tolerance setting.
int line_after_tolerance() {
    const std::string text = read_bytes(kDesert);
    const auto at = text.find(kSetting);
    int line = 1;
    for (std::size_t i = 0; i < at; ++i) line += text[i] == '\n';
    return line + 1;
}

int entries(const fs::path& dir) {
    int n = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
    return n;
}

const std::string kRaysHeader = "case_id,profile,eta0,eta1,alpha,y0,i_rad,d1,d2,d3\n";

TEST(HostileInputs, SceneValuesAreCheckedWhereTheyAreRead) {
    const auto dir = test_dir("hostile_inputs", "scene_values");
    const std::string line = std::to_string(line_after_tolerance());
    const auto high = desert_plus(dir, "high.pov", "#declare Mirage_Ground_Height = 1e308;");
    auto r = run_tool("trace " + quoted(high) + " -W 16 -H 12 -o " + quoted(dir / "high.png"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err, "mirage trace: " + high.string() + ":" + line +
                         ":10: Mirage_Ground_Height = 1e+308 must be from -1e+09 to 1e+09 (scene "
                         "units)\n");
    const auto low = desert_plus(dir, "low.pov", "#declare Mirage_Ground_Height = -1e308;");
    r = run_tool("compile " + quoted(low) + " -W 16 -H 12 -o " + quoted(dir / "outc"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err, "mirage compile: " + low.string() + ":" + line +
                         ":10: Mirage_Ground_Height = -1e+308 must be from -1e+09 to 1e+09 "
                         "(scene units)\n");
    const auto ior =
        desert_plus(dir, "ior.pov", "sphere { 0, 1 interior { ior 1e308 } pigment { rgb 1 } }");
    r = run_tool("trace " + quoted(ior) + " -W 16 -H 12 -o " + quoted(dir / "ior.png"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err.substr(0, r.err.find('\n')), "mirage trace: " + ior.string() + ":" + line +
                                                     ":30: ior 1e+308 must be 0 or from "
                                                     "0.001 to 1000");
    // Nothing written: the three scenes are all the folder holds.
    EXPECT_EQ(entries(dir), 3);
}

TEST(HostileInputs, StudyLevelsAndStepsAreBoundedBeforeAnyWork) {
    const auto dir = test_dir("hostile_inputs", "study");
    const std::pair<const char*, const char*> cases[] = {
        {"--graded-levels 100000000",
         "--graded-levels 1e+08: the layer count must be a whole number from 1 to 4096"},
        {"--graded-levels -1",
         "--graded-levels -1: the layer count must be a whole number from 1 to 4096"},
        {"--graded-levels 0",
         "--graded-levels 0: the layer count must be a whole number from 1 to 4096"},
        {"--graded-steps 1e308", "--graded-steps 1e+308: must be from 0 to 4096 levels"},
        {"--graded-steps nan", "--graded-steps nan: must be from 0 to 4096 levels"},
    };
    for (const auto& [option, message] : cases) {
        auto r = run_tool("study " + quoted(fs::path(kDesert)) + " -W 16 -H 12 --no-render -o " +
                          quoted(dir / "st") + " " + option);
        EXPECT_EQ(r.exit_code, 1) << option;
        EXPECT_EQ(r.err, std::string("mirage study: ") + message + "\n");
    }
    EXPECT_FALSE(fs::exists(dir / "st"));
}

TEST(HostileInputs, PathOptionsAreNumbersInTheirRanges) {
    const auto dir = test_dir("hostile_inputs", "path_options");
    // NaN read as "not given", or turning a check off: refused as the option is read.
    const std::pair<const char*, const char*> nans[] = {
        {"--preset paper --eye-height nan --elevation-deg 0", "--eye-height"},
        {"--preset paper --object-height 1 --object-distance nan --eye-height 1",
         "--object-distance"},
        {"--sounding x.csv --sounding-max-gap nan --eye-height 1 --elevation-deg 0",
         "--sounding-max-gap"},
    };
    for (const auto& [args, option] : nans) {
        auto r = run_tool(std::string("path ") + args);
        EXPECT_EQ(r.exit_code, 2) << args;
        EXPECT_EQ(r.err.substr(0, r.err.find('\n')),
                  std::string(option) + ": 'nan' is not a number");
    }
    auto r = run_tool("path --surface-layer 1e308,1 --eye-height 1 --elevation-deg 0");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err,
              "mirage path: --surface-layer 1e308,1: temperature excess 1e+308 K must be from -100 "
              "to 100 K\n");
    r = run_tool("path --inversion 50,60,2,1e9 --eye-height 1 --elevation-deg 0");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err,
              "mirage path: --inversion 50,60,2,1e9: smoothing 1e+09 m must be from 0 to 100 m\n");
    const auto sounding = dir / "s.csv";
    write_bytes(sounding, "height_m,temperature_c\n0,20\n10,19\n");
    r = run_tool("path --sounding " + quoted(sounding) +
                 " --sounding-max-gap 1e300 --eye-height 1 --elevation-deg 0");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err,
              "mirage path: --sounding-max-gap 1e+300: must be more than 0 and at most 10000 m\n");
    // --svg draws one ray's fan: beside --batch it would be dropped without a word.
    write_bytes(dir / "rays.csv", kRaysHeader + "A,inferior,1.0003,0.02,3,1.5,1.5707,10,20,30\n");
    r = run_tool("path --batch " + quoted(dir / "rays.csv") + " --svg " + quoted(dir / "x.svg"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err,
              "mirage path: --svg draws one ray's diagram: it does not go with --batch, which "
              "prints a CSV of its rows\n");
    EXPECT_EQ(r.out, "");
    EXPECT_FALSE(fs::exists(dir / "x.svg"));
}

TEST(HostileInputs, LibraryPathsAreDirectories) {
    const auto dir = test_dir("hostile_inputs", "library_paths");
    auto r = run_tool("trace " + quoted(fs::path(kDesert)) + " -W 16 -H 12 -L " +
                      quoted(fs::path(kDesert)) + " -o " + quoted(dir / "d.png"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err, "mirage trace: -L " + kDesert +
                         ": is not a directory: -L names a directory to look for include files "
                         "in\n");
    r = run_tool("compile " + quoted(fs::path(kDesert)) + " -W 16 -H 12 -L " +
                 quoted(dir / "none") + " -o " + quoted(dir / "outc"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err, "mirage compile: -L " + (dir / "none").string() +
                         ": no such directory: -L names a directory to look for include files "
                         "in\n");
    EXPECT_EQ(entries(dir), 0);
}

TEST(HostileInputs, InputFilesAreRegularFilesOfBoundedSize) {
    const auto dir = test_dir("hostile_inputs", "input_files");
    // A device grew to gigabytes; a FIFO blocked for ever; a directory was an "empty CSV".
    const fs::path fifo = dir / "fifo.csv";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    fs::create_directories(dir / "folder.csv");
    const std::pair<fs::path, std::string> cases[] = {
        {"/dev/zero",
         ": is not a regular file (a device, a pipe or a socket?): CSV tables are read from "
         "files"},
        {fifo,
         ": is not a regular file (a device, a pipe or a socket?): CSV tables are read from "
         "files"},
        {dir / "folder.csv", ": is a directory, not a CSV table"},
        {dir / "none.csv", ": cannot be opened: No such file or directory"},
    };
    for (const auto& [path, why] : cases) {
        auto r = run_tool("path --batch " + quoted(path));
        EXPECT_EQ(r.exit_code, 1) << path;
        EXPECT_EQ(r.err, "mirage path: " + path.string() + why + "\n");
        r = run_tool("path --sounding " + quoted(path) + " --eye-height 1 --elevation-deg 0");
        EXPECT_EQ(r.exit_code, 1) << path;
        std::string sounding_why = why;
        for (const auto& [from, to] :
             {std::pair<std::string, std::string>{"CSV tables", "soundings"},
              {"a CSV table", "a sounding"}}) {
            const auto at = sounding_why.find(from);
            if (at != std::string::npos) sounding_why.replace(at, from.size(), to);
        }
        EXPECT_EQ(r.err, "mirage path: " + path.string() + sounding_why + "\n");
    }
    // Larger than the limit (a sparse file: no disk used), refused before it is read.
    const fs::path huge = dir / "huge.csv";
    std::ofstream(huge).close();
    fs::resize_file(huge, (std::uintmax_t{64} << 20) + 1);
    auto r = run_tool("path --batch " + quoted(huge));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err, "mirage path: " + huge.string() +
                         ": is 67108865 bytes, more than the 67108864 bytes (64 MiB) mirage reads "
                         "for a CSV table\n");
    // CR-only line ends (old Mac files) end lines.
    const std::string row = "A,inferior,1.0003,0.02,3,1.5,1.5707,10,20,30";
    write_bytes(dir / "lf.csv", kRaysHeader + row + "\n");
    std::string cr_text = kRaysHeader;
    cr_text.back() = '\r';
    write_bytes(dir / "cr.csv", cr_text + row + "\r");
    const auto lf = run_tool("path --batch " + quoted(dir / "lf.csv"));
    const auto cr = run_tool("path --batch " + quoted(dir / "cr.csv"));
    EXPECT_EQ(cr.exit_code, 0) << cr.err;
    EXPECT_EQ(cr.out, lf.out);
    // 10 MB of a field is not quoted on stderr: its ends are.
    write_bytes(dir / "long.csv", kRaysHeader + "A,inferior," + std::string(10'000'000, '9') +
                                ",0.02,3,1.5,1.5707,10,20,30\n");
    r = run_tool("path --batch " + quoted(dir / "long.csv"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err, "mirage path: " + (dir / "long.csv").string() + ":2:12: column 'eta0': '" +
                         std::string(30, '9') + "..." + std::string(30, '9') +
                         " (10000000 bytes)' is out of the range of a double\n");
}

TEST(HostileInputs, ASoundingFitThatFailsNamesTheFileAndTheRows) {
    const auto dir = test_dir("hostile_inputs", "sounding_fit");
    const auto sounding = dir / "road.csv";
    write_bytes(sounding, "height_m,temperature_c\n0,45\n0.5,31\n10,28.5\n");
    auto r = run_tool("path --sounding " + quoted(sounding) +
                      " --fit-tolerance 1e-30 --eye-height 1 --elevation-deg 0");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err.rfind("mirage path: " + sounding.string() +
                              ":2: the rows at 0 m (line 2) and 0.5 m (line 3): the profile "
                              "changes too fast near ",
                          0),
              0u)
        << r.err;
}

// A level ray from 10 m with no gradient on the Earth is 41.392424 m above the sphere 20 km
// away.  In a batch with --earth-radius its row's profile, `none`, was dropped for the default
// air at 15 degC, whose refraction left 0.78 of the curvature (34.46 m).
TEST(HostileInputs, ABatchOnTheCurvedEarthTracesEachRowsProfile) {
    const auto dir = test_dir("hostile_inputs", "batch_curved");
    write_bytes(dir / "rays.csv", kRaysHeader +
                                "level,none,1,0,0,10,1.5707963267948966,10000,20000,"
                                "30000\n"
                                "low,inferior,1.0003,0.0002,1,10,1.5707963267948966,"
                                "10000,20000,30000\n");
    auto batch = run_tool("path --batch " + quoted(dir / "rays.csv") + " --earth-radius 6371000");
    ASSERT_EQ(batch.exit_code, 0) << batch.err;
    auto single = [](const std::string& profile) {
        auto r = run_tool("path " + profile +
                          " --earth-radius 6371000 --eye-height 10 --elevation-deg 0 --json "
                          "--max-distance 20000");
        EXPECT_EQ(r.exit_code, 0) << r.err;
        // The last sample, at 20 km: [20000, y].
        const auto last = nlohmann::json::parse(r.out)["samples"].back();
        EXPECT_EQ(last[0].get<double>(), 20000.0);
        return last[1].get<double>();
    };
    std::istringstream lines(batch.out);
    std::string header, level, low;
    std::getline(lines, header);
    std::getline(lines, level);
    std::getline(lines, low);
    auto y_d2 = [&](const std::string& row) {
        std::vector<std::string> f;
        std::stringstream s(row);
        for (std::string x; std::getline(s, x, ',');) f.push_back(x);
        return std::stod(f.at(8));
    };
    EXPECT_NEAR(y_d2(level), 41.392424, 1e-6);
    EXPECT_NEAR(y_d2(level), single("--profile none"), 1e-9);
    EXPECT_NEAR(y_d2(low), single("--profile inferior --eta0 1.0003 --eta1 0.0002 --alpha 1"),
                1e-9);
}

}  // namespace
}  // namespace mirage
