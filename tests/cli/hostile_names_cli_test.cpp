// Every command given hostile names and places to write to (issue 29): a file name with a line
// end, a quote or a byte that is not UTF-8, a folder with a space, a device, a FIFO or a link
// to one as an output, a reader that stops early.  No name runs as a command or ends up as
// options of its own, no device or FIFO is replaced, nothing aborts, and a refusal names the
// file and why, and leaves nothing behind.  The names, FIFOs and device nodes are made under
// a test folder at run time.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "../trace/povray_runner.h"
#include "animate/animate.h"
#include "run_tool.h"
#include "util/process.h"

namespace mirage {
namespace {

namespace fs = std::filesystem;
using testing::quoted;
using testing::read_bytes;
using testing::write_bytes;
using testing::run_tool;
using testing::test_dir;

const std::string kSource = MIRAGE_SOURCE_DIR;
const std::string kDesert = kSource + "/scenes/desert.pov";
const std::string kWalk = kSource + "/scenes/walk.pov";
const std::string kRay = "path --preset paper --eye-height 1.5 --elevation-deg -1";

/// Runs `mirage <args>` in `dir` through sh, with `env` (assignments) before it.
testing::ToolRun run_in(const fs::path& dir, const std::string& args, const std::string& env = "") {
    return run_tool("--version >/dev/null; cd " + testing::quoted(dir.string()) + " && " + env + " " +
                    std::string(MIRAGE_BINARY_DIR) + "/mirage " + args);
}

bool is_fifo_node(const fs::path& p) {
    struct stat st {};
    return ::lstat(p.c_str(), &st) == 0 && S_ISFIFO(st.st_mode);
}

bool is_char_device(const fs::path& p) {
    struct stat st {};
    return ::stat(p.c_str(), &st) == 0 && S_ISCHR(st.st_mode);
}

/// Everything written into a FIFO while `run` runs (read without blocking, so that a run that
/// never opens it cannot hang the test).
template <class Run>
std::string read_fifo_while(const fs::path& fifo, Run run) {
    std::atomic<bool> done{false};
    std::string got;
    std::thread reader([&] {
        const int fd = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
        if (fd < 0) return;
        char buf[65536];
        for (;;) {
            const ssize_t n = ::read(fd, buf, sizeof buf);
            if (n > 0) {
                got.append(buf, static_cast<std::size_t>(n));
                continue;
            }
            if (n == 0 && done) break;
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
        }
        ::close(fd);
    });
    run();
    done = true;
    reader.join();
    return got;
}

/// A character device node like /dev/null (1, 3) or /dev/full (1, 7) at `p`; false where
/// nodes cannot be made (not root).
bool make_device(const fs::path& p, unsigned minor) {
    return ::mknod(p.c_str(), S_IFCHR | 0666, makedev(1, minor)) == 0;
}

bool have_animate_tools() { return find_program("ffmpeg") && find_program("ffprobe"); }

TEST(HostileNames, AFileNameRunsNoCommandOverGnuParallel) {
    if (!have_animate_tools() || !find_program("parallel"))
        GTEST_SKIP() << "ffmpeg or GNU parallel missing";
    const auto dir = test_dir("hostile_names", "hosts");
    // A line end splits a task line; what follows it would run as a command.  '{}' and '{=
    // =}' are GNU parallel's replacement strings.
    const std::string name = "w\ntouch PWNED\n{= $_ = `touch PWNED2` =}$(touch PWNED3).pov";
    write_bytes(dir / name, read_bytes(kWalk));
    write_bytes(dir / "hosts.txt", ":\n");
    auto r = run_in(dir, "animate " + testing::quoted(name) +
                             " --model trace --frames 1 -W 16 -H 12 -q -o out --hosts hosts.txt");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_FALSE(fs::exists(dir / "PWNED") || fs::exists(dir / "PWNED2") ||
                 fs::exists(dir / "PWNED3"));
    EXPECT_TRUE(fs::exists(dir / "out" / "frames" / "frame_0000.png")) << r.err;
    // The task's own log, written by the task.
    EXPECT_NE(read_bytes(dir / "out" / "frames" / "frame_0000.log").find("frame 0"), std::string::npos);
}

TEST(HostileNames, GnuParallelsProblemsAreSaidAndAnEmptyHostListRefused) {
    if (!have_animate_tools() || !find_program("parallel"))
        GTEST_SKIP() << "ffmpeg or GNU parallel missing";
    const auto dir = test_dir("hostile_names", "hosts_said");
    write_bytes(dir / "empty.txt", "# no host\n\n");
    auto r = run_tool("animate " + kWalk + " --model trace --frames 1 -W 16 -H 12 -o " +
                      testing::quoted(dir / "out") + " --hosts " + testing::quoted(dir / "empty.txt"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err, "mirage animate: --hosts " + (dir / "empty.txt").string() +
                         ": names no host (one ssh login a line, ':' for this machine)\n");
    EXPECT_FALSE(fs::exists(dir / "out"));
    // A login GNU parallel does not take: its complaint on stderr, not only in its log.
    write_bytes(dir / "bad.txt", "0/:\n");
    r = run_tool("animate " + kWalk + " --model trace --frames 1 -W 16 -H 12 -o " +
                 testing::quoted(dir / "out") + " --hosts " + testing::quoted(dir / "bad.txt"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("mirage animate: --hosts: GNU parallel exited with "), std::string::npos)
        << r.err;
}

TEST(HostileNames, TheSlurmScriptHoldsNoFileName) {
    const auto dir = test_dir("hostile_names", "slurm");
    const std::string name = "w\n#SBATCH --wrap=x\ntouch PWNED\n$(touch PWNED2) 50%.pov";
    write_bytes(dir / name, read_bytes(kWalk));
    AnimateOptions o;
    o.scene = (dir / name).string();
    o.frames = 2;
    o.out_dir = (dir / "o%ut\nx").string();
    o.self = "/bin/true";
    auto a = resolve_animation(o);
    ASSERT_TRUE(a.ok()) << a.message();
    const std::string s = slurm_script(*a, {1, 2});
    // Every #SBATCH line comes before the first command, and none holds a file name.
    std::istringstream lines(s);
    std::string line;
    std::vector<std::string> directives;
    bool in_header = true;
    while (std::getline(lines, line)) {
        if (line.rfind("#SBATCH", 0) == 0) {
            EXPECT_TRUE(in_header) << s;
            directives.push_back(line);
        } else if (!line.empty() && line[0] != '#') {
            in_header = false;
        }
    }
    EXPECT_EQ(directives, (std::vector<std::string>{"#SBATCH --array=1-2", "#SBATCH --ntasks=1",
                                                    "#SBATCH --cpus-per-task=1", "#SBATCH --mem=2G",
                                                    "#SBATCH --time=01:00:00"}))
        << s;
    EXPECT_NE(s.find("# w\\n#SBATCH --wrap=x\\ntouch PWNED\\n$(touch PWNED2) 50%: one task"),
              std::string::npos)
        << s;
    EXPECT_EQ(s.find("\n#SBATCH --wrap"), std::string::npos) << s;
    // The script run as sbatch would: nothing but the task (here /bin/true) runs.
    write_bytes(dir / "job.sh", s);
    EXPECT_EQ(
        std::system(
            ("cd " + testing::quoted(dir.string()) + " && SLURM_ARRAY_TASK_ID=1 sh job.sh").c_str()),
        0);
    EXPECT_FALSE(fs::exists(dir / "PWNED") || fs::exists(dir / "PWNED2"));
    // The names go to sbatch as arguments, '%' doubled in the log pattern.
    const auto argv = slurm_submit_argv(*a, "job.sh");
    ASSERT_EQ(argv.size(), 6u);
    EXPECT_EQ(argv[2], "--job-name=mirage-w__SBATCH_--wrap_x_touch_PWNED___touch_PWNED2__50_");
    EXPECT_EQ(argv[3], "--output=" + (dir / "o%%ut\nx").string() + "/frames/frame_%4a.log");
    // Resources go into #SBATCH lines: a line end there is refused by its option.
    o.slurm.partition = "render\ntouch PWNED";
    auto bad = resolve_animation(o);
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.message(),
              "--partition 'render\\ntouch PWNED': Slurm takes letters, digits and : . _ , + - "
              "here");
}

TEST(HostileNames, NamesPovRayCannotTakeAreRefusedByCompile) {
    const auto dir = test_dir("hostile_names", "compile");
    const std::pair<std::string, std::string> names[] = {
        {"a\nOutput_File_Name=victim.txt\n.pov", "a line end"},
        {"q\"uote.pov", "a '\"'"},
        {"sc\xff.pov", "a byte outside ASCII"},
    };
    for (const auto& [name, why] : names) {
        write_bytes(dir / name, read_bytes(kDesert));
        auto r = run_in(dir, "compile " + testing::quoted(name) + " -o outc -W 16 -H 12");
        EXPECT_EQ(r.exit_code, 1) << name;
        EXPECT_NE(r.err.find(": the scene is read by POV-Ray, and its path holds " + why),
                  std::string::npos)
            << r.err;
        EXPECT_EQ(r.err.find('\xff'), std::string::npos);
        EXPECT_FALSE(fs::exists(dir / "outc") || fs::exists(dir / "victim.txt")) << name;
        fs::remove(dir / name);
    }
    // --image and -L are in the .ini too.
    auto r =
        run_in(dir, "compile " + kDesert + " -o outc -W 16 -H 12 --image " + testing::quoted("x\ny.png"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("x\\ny.png: --image is read by POV-Ray, and its path holds a line end"),
              std::string::npos)
        << r.err;
    r = run_in(dir, "compile " + kDesert + " -o outc -W 16 -H 12 -L " + testing::quoted("i\nnc"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("i\\nnc: -L is read by POV-Ray"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "outc"));
}

TEST(HostileNames, AFolderWithASpaceRendersInEveryPovRayRun) {
    if (!testing::povray_available()) GTEST_SKIP() << "povray is not on PATH";
    const auto dir = test_dir("hostile_names", "space");
    fs::create_directories(dir / "a b");
    write_bytes(dir / "a b" / "s c;x.pov", read_bytes(kDesert));
    // compile's .ini, rendered: it names the scene that renders the template through the
    // corrected camera, which includes the template by its path.
    auto r = run_in(dir, "compile 'a b/s c;x.pov' -o 'o u t' -W 16 -H 12 -q --render");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string ini = read_bytes(dir / "o u t" / "s c;x.ini");
    EXPECT_NE(ini.find("Input_File_Name=\"" + (dir / "o u t" / "s c;x_render.pov").string() +
                       "\"\n"),
              std::string::npos)
        << ini;
    const std::string scene = read_bytes(dir / "o u t" / "s c;x_render.pov");
    EXPECT_NE(scene.find("#include \"" + (dir / "a b" / "s c;x.pov").string() + "\"\n"),
              std::string::npos)
        << scene;
    EXPECT_TRUE(fs::exists(dir / "o u t" / "s c;x.png")) << r.err;
    // compare: POV-Ray renders a design from the .ini in a folder with a space.
    r = run_in(dir,
               "compare 'a b/s c;x.pov' -W 16 -H 12 -o 'c o' --counts 4 --tolerances 2 "
               "--trace-tolerances 2 --reference-tolerance 0.5");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir / "c o" / "renders" / "uniform-bands-4.png")) << r.err;
    EXPECT_EQ(r.err.find("POV-Ray failed"), std::string::npos) << r.err;
    // animate's band model runs POV-Ray on every frame's .ini.
    if (have_animate_tools()) {
        write_bytes(dir / "a b" / "w a;lk.pov", read_bytes(kWalk));
        r = run_in(dir, "animate 'a b/w a;lk.pov' --frames 2 -W 16 -H 12 -q -o 'an i'");
        EXPECT_EQ(r.exit_code, 0) << r.err;
        EXPECT_TRUE(fs::exists(dir / "an i" / "frames" / "frame_0002.png")) << r.err;
    }
}

TEST(HostileNames, FailedPovRayRendersSayWhyAndFailTheCommand) {
    const auto dir = test_dir("hostile_names", "povray_fails");
    // A POV-Ray that fails as a broken installation would, first on PATH.
    fs::create_directories(dir / "bin");
    write_bytes(dir / "bin" / "povray",
          "#!/bin/sh\necho 'Parse Error: Cannot open input file.'\necho 'Render failed'\n"
          "exit 1\n");
    fs::permissions(dir / "bin" / "povray", fs::perms::owner_all);
    const std::string env = "PATH=" + testing::quoted((dir / "bin").string()) + ":\"$PATH\"";
    auto r = run_in(dir,
                    "compare " + kDesert +
                        " -W 16 -H 12 -o c --counts 4 --tolerances 2 --trace-tolerances 2 "
                        "--reference-tolerance 0.5",
                    env);
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_NE(r.err.find("POV-Ray render(s) failed; the results in " +
                         (fs::absolute(dir) / "c").string()),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("): Parse Error: Cannot open input file.\n"), std::string::npos) << r.err;
    r = run_in(dir, "study " + kDesert + " -W 16 -H 12 -o s --counts 4", env);
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_NE(r.err.find("Parse Error: Cannot open input file."), std::string::npos) << r.err;
}

TEST(HostileNames, ADeviceOrAFifoIsWrittenNeverReplaced) {
    const auto dir = test_dir("hostile_names", "devices");
    if (!make_device(dir / "full", 7) || !make_device(dir / "null", 3))
        GTEST_SKIP() << "device nodes cannot be made here (not root)";
    // A full device: the write fails with its reason, and the device stays.
    auto r = run_tool(kRay + " --svg " + testing::quoted(dir / "full"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err, "mirage path: " + (dir / "full").string() +
                         ": cannot write: No space left on device\n");
    EXPECT_TRUE(is_char_device(dir / "full"));
    r = run_tool(kRay + " --svg " + testing::quoted(dir / "null"));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(is_char_device(dir / "null"));
    // Through a link: the link stays a link to the device.
    fs::create_symlink(dir / "null", dir / "link.svg");
    r = run_tool(kRay + " --svg " + testing::quoted(dir / "link.svg"));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(fs::is_symlink(dir / "link.svg"));
    EXPECT_TRUE(is_char_device(dir / "null"));
    // The tracer's image and compile's outputs.
    r = run_tool("trace " + kDesert + " -W 16 -H 12 -q -o " + testing::quoted(dir / "null"));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    r = run_tool("trace " + kDesert + " -W 16 -H 12 -q -o " + testing::quoted(dir / "full"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find(": cannot write: No space left on device"), std::string::npos) << r.err;
    r = run_tool("compile " + kDesert + " -W 16 -H 12 -q -o " + testing::quoted(dir / "c") +
                 " --error-map " + testing::quoted(dir / "full"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("the error map is written as OpenEXR"), std::string::npos) << r.err;
    EXPECT_TRUE(is_char_device(dir / "full"));
    EXPECT_TRUE(is_char_device(dir / "null"));
}

TEST(HostileNames, AFifoGetsTheOutputAndStaysAFifo) {
    const auto dir = test_dir("hostile_names", "fifo");
    ASSERT_EQ(::mkfifo((dir / "svg").c_str(), 0644), 0);
    testing::ToolRun r;
    std::string got =
        read_fifo_while(dir / "svg", [&] { r = run_tool(kRay + " --svg " + testing::quoted(dir / "svg")); });
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(got.find("<svg"), std::string::npos);
    EXPECT_TRUE(is_fifo_node(dir / "svg"));
    // A link to the FIFO stays a link.
    fs::create_symlink(dir / "svg", dir / "to_fifo.svg");
    got = read_fifo_while(dir / "svg",
                          [&] { r = run_tool(kRay + " --svg " + testing::quoted(dir / "to_fifo.svg")); });
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(got.find("<svg"), std::string::npos);
    EXPECT_TRUE(fs::is_symlink(dir / "to_fifo.svg"));
    EXPECT_TRUE(is_fifo_node(dir / "svg"));
    // compile's error map into a FIFO named .exr.
    ASSERT_EQ(::mkfifo((dir / "map.exr").c_str(), 0644), 0);
    got = read_fifo_while(dir / "map.exr", [&] {
        r = run_tool("compile " + kDesert + " -W 16 -H 12 -q -o " + testing::quoted(dir / "c") +
                     " --error-map " + testing::quoted(dir / "map.exr"));
    });
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(got.substr(0, 4), std::string("\x76\x2f\x31\x01", 4));  // OpenEXR's magic
    EXPECT_TRUE(is_fifo_node(dir / "map.exr"));
    // "-" is the standard output.
    r = run_tool(kRay + " --svg -");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("<svg"), std::string::npos);
    EXPECT_FALSE(fs::exists("-"));
    // A link to a file: the file gets the output, the link stays.
    write_bytes(dir / "real.svg", "old");
    fs::create_symlink("real.svg", dir / "to_real.svg");
    r = run_tool(kRay + " --svg " + testing::quoted(dir / "to_real.svg"));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(fs::is_symlink(dir / "to_real.svg"));
    EXPECT_NE(read_bytes(dir / "real.svg").find("<svg"), std::string::npos);
}

TEST(HostileNames, NamesThatAreNotUtf8AreWrittenAsJson) {
    if (!have_animate_tools()) GTEST_SKIP() << "ffmpeg/ffprobe not on PATH";
    const auto dir = test_dir("hostile_names", "utf8");
    // The scene's name, the output folder's and a Marked_Name, none of them UTF-8.
    std::string scene = read_bytes(kWalk);
    const std::string from = "\"red sphere\"";
    ASSERT_NE(scene.find(from), std::string::npos);
    scene.replace(scene.find(from), from.size(), "\"red \xff sphere\"");
    write_bytes(dir / "sc\xff.pov", scene);
    const std::string cmd = "animate " + testing::quoted("sc\xff.pov") +
                            " --model trace --frames 2 -W 16 -H 12 -q -o " + testing::quoted("o\xfe");
    auto r = run_in(dir, cmd);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const fs::path out = dir / "o\xfe";
    for (const char* file : {"animation.json", "report.json", "frames/frame_0001.json"}) {
        const auto j = nlohmann::json::parse(read_bytes(out / file), nullptr, false);
        EXPECT_FALSE(j.is_discarded()) << file;
    }
    EXPECT_NE(read_bytes(out / "animation.json").find("sc\xef\xbf\xbd.pov"), std::string::npos);
    EXPECT_NE(read_bytes(out / "report.json").find("red \xef\xbf\xbd sphere"), std::string::npos);
    // A second run finds the frames its own.
    r = run_in(dir, cmd);
    EXPECT_EQ(r.exit_code, 0) << r.err;
}

TEST(HostileNames, AReaderThatStopsEarlyEndsTheOutputQuietly) {
    const auto dir = test_dir("hostile_names", "pipe");
    // More rows than a pipe holds, so that the write meets the closed pipe.
    std::string csv = "case_id,profile,eta0,eta1,alpha,y0,i_rad,d1,d2,d3\n";
    for (int i = 0; i < 3000; ++i) {
        csv += 'R';
        csv += std::to_string(i);
        csv += ",inferior,1.000233,0.4584,2.303,1.0,1.9,1,2,3\n";
    }
    write_bytes(dir / "rays.csv", csv);
    const std::string cmd =
        "bash -c " + testing::quoted(std::string(MIRAGE_BINARY_DIR) + "/mirage path --batch " +
                               testing::quoted((dir / "rays.csv").string()) +
                               " | head -c 10 > /dev/null; echo ${PIPESTATUS[0]}");
    FILE* p = popen((cmd + " 2>" + testing::quoted((dir / "err").string())).c_str(), "r");
    char buf[64] = {};
    const std::size_t n = std::fread(buf, 1, sizeof buf - 1, p);
    pclose(p);
    EXPECT_EQ(std::string(buf, n), "0\n");
    EXPECT_EQ(read_bytes(dir / "err"), "");
}

TEST(HostileNames, MessagesEscapeWhatWouldActOnATerminal) {
    const auto dir = test_dir("hostile_names", "terminal");
    write_bytes(dir / "e.pov",
          std::string("#error \"nul ") + std::string(1, '\0') + "clear\x1b[2J\x07 bell\"\n");
    auto r =
        run_tool("trace " + testing::quoted(dir / "e.pov") + " -W 16 -H 12 -o " + testing::quoted(dir / "e.png"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("#error: nul \\0clear\\x1b[2J\\x07 bell"), std::string::npos) << r.err;
    for (char c : r.err) EXPECT_TRUE(c == '\n' || static_cast<unsigned char>(c) >= 0x20) << r.err;
}

TEST(HostileNames, RefusalsLeaveNoFolderAndNamelessOutputsAreRefused) {
    const auto dir = test_dir("hostile_names", "leftovers");
    // compile: the error map in a folder that does not exist.
    auto r = run_tool("compile " + kDesert + " -W 16 -H 12 -q -o " + testing::quoted(dir / "outc") +
                      " --error-map " + testing::quoted(dir / "missing" / "map.exr"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_FALSE(fs::exists(dir / "outc"));
    // compare: a scene with no atmosphere, found after the reference.
    write_bytes(dir / "plain.pov",
          "camera { location <0, 1, -4> look_at <0, 1, 0> }\n"
          "light_source { <2, 4, -3>, rgb 1 }\nsphere { <0, 1, 0>, 1 pigment { rgb x } }\n");
    r = run_tool("compare " + testing::quoted(dir / "plain.pov") + " -W 16 -H 12 -o " +
                 testing::quoted(dir / "cmp" / "deep"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("declares no atmosphere"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "cmp"));
    // animate: a clock POV-Ray cannot hold.
    r = run_tool("animate " + kWalk + " --frames 2 +KI-3e38 +KF3e38 --model trace -o " +
                 testing::quoted(dir / "anim"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("the clock of frame 1 is not a number"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "anim"));
    // An empty name is no name.
    r = run_tool("trace " + kDesert + " -W 16 -H 12 -o ''");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("an empty name: give a file or folder name"), std::string::npos) << r.err;
    r = run_tool(kRay + " --svg ''");
    EXPECT_EQ(r.exit_code, 2);
}

}  // namespace
}  // namespace mirage
