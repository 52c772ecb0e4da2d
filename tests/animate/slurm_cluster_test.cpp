// mirage animate --slurm on a real one-node Slurm cluster started on this machine: munged with
// a key of its own, slurmctld and slurmd from a generated slurm.conf (no cgroups, no
// accounting, state and spool under a temporary directory, ports chosen free on 127.0.0.1),
// stopped at the end whatever happens.  Where the daemons cannot start, the test is skipped
// with the reason.
#include <arpa/inet.h>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <pwd.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>
#include <vector>

#include "animate/video.h"
#include "util/process.h"

namespace mirage {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

const std::string kSource = MIRAGE_SOURCE_DIR;

std::string read_bytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string tail(const fs::path& path, int lines = 8) {
    std::ifstream in(path);
    std::vector<std::string> all;
    std::string line;
    while (std::getline(in, line)) all.push_back(line);
    std::string s;
    for (std::size_t i = all.size() > std::size_t(lines) ? all.size() - lines : 0; i < all.size();
         ++i)
        s += "    " + all[i] + "\n";
    return s;
}

// A port on 127.0.0.1 that nothing listens on now.
int free_port() {
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    a.sin_port = 0;
    socklen_t len = sizeof a;
    int port = 0;
    if (::bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0 &&
        ::getsockname(fd, reinterpret_cast<sockaddr*>(&a), &len) == 0)
        port = ntohs(a.sin_port);
    ::close(fd);
    return port;
}

// Runs a shell command with a time limit; its exit status (124 on timeout).
int shell(const std::string& cmd, int timeout_s, std::string* out = nullptr) {
    const std::string full = "timeout " + std::to_string(timeout_s) + " sh -c '" + cmd + "' 2>&1";
    FILE* p = popen(full.c_str(), "r");
    std::string text;
    char buf[512];
    while (std::fgets(buf, sizeof buf, p)) text += buf;
    const int status = pclose(p);
    if (out) *out = text;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// munged, slurmctld and slurmd in the foreground, as children of the test.
class OneNodeCluster {
  public:
    ~OneNodeCluster() { stop(); }

    // Empty on success, else why the cluster could not be had.
    std::string start() {
        for (const char* p : {"munged", "slurmctld", "slurmd", "sbatch", "squeue", "sinfo"})
            if (!find_program(p) && !fs::exists(std::string("/usr/sbin/") + p))
                return std::string(p) +
                       " is not installed (Debian: munge, slurmctld, slurmd, "
                       "slurm-client)";
        char tmpl[] = "/tmp/mirage-slurm-XXXXXX";  // short: it holds unix sockets
        if (!::mkdtemp(tmpl)) return "cannot make a temporary directory";
        dir_ = tmpl;
        ::chmod(dir_.c_str(), 0755);  // munged wants the socket's directory searchable
        fs::create_directories(dir_ / "state");
        fs::create_directories(dir_ / "spool");
        // The key: mungekey when there is one, else 1024 random bytes.
        const fs::path key = dir_ / "munge.key";
        if (shell("mungekey -c -k " + key.string() + " || head -c 1024 /dev/urandom > " +
                      key.string(),
                  20) != 0 ||
            !fs::exists(key))
            return "cannot make a munge key";
        fs::permissions(key, fs::perms::owner_read | fs::perms::owner_write);
        const fs::path sock = dir_ / "munge.sock";
        munged_ =
            spawn({sbin("munged"), "-F", "--force", "--socket=" + sock.string(),
                   "--key-file=" + key.string(), "--log-file=" + (dir_ / "munged.log").string(),
                   "--pid-file=" + (dir_ / "munged.pid").string(),
                   "--seed-file=" + (dir_ / "munged.seed").string()},
                  dir_ / "munged.out");
        if (!wait_until("munge -n -S " + sock.string() + " | unmunge -S " + sock.string(), 15))
            return "munged did not start:\n" + tail(dir_ / "munged.out") +
                   tail(dir_ / "munged.log");

        char host[256] = {};
        ::gethostname(host, sizeof host - 1);
        std::string short_host = host;
        short_host = short_host.substr(0, short_host.find('.'));
        const passwd* pw = ::getpwuid(::getuid());
        const std::string user = pw ? pw->pw_name : "root";
        const unsigned cpus = std::max(1u, std::thread::hardware_concurrency());
        const fs::path conf = dir_ / "slurm.conf";
        std::ofstream c(conf);
        c << "ClusterName=miragetest\n"
          << "SlurmctldHost=" << short_host << "(127.0.0.1)\n"
          << "SlurmctldPort=" << free_port() << "\nSlurmdPort=" << free_port() << "\n"
          << "SlurmUser=" << user << "\nSlurmdUser=" << user << "\n"
          << "AuthType=auth/munge\nAuthInfo=socket=" << sock.string() << "\nCredType=cred/munge\n"
          << "StateSaveLocation=" << (dir_ / "state").string() << "\n"
          << "SlurmdSpoolDir=" << (dir_ / "spool").string() << "\n"
          << "SlurmctldPidFile=" << (dir_ / "slurmctld.pid").string() << "\n"
          << "SlurmdPidFile=" << (dir_ / "slurmd.pid").string() << "\n"
          << "SlurmctldLogFile=" << (dir_ / "slurmctld.log").string() << "\n"
          << "SlurmdLogFile=" << (dir_ / "slurmd.log").string() << "\n"
          << "ProctrackType=proctrack/linuxproc\nTaskPlugin=task/none\n"
          << "JobAcctGatherType=jobacct_gather/none\nAccountingStorageType=accounting_storage/"
             "none\n"
          << "JobCompType=jobcomp/none\nSelectType=select/cons_tres\nSelectTypeParameters=CR_CPU\n"
          << "SchedulerType=sched/builtin\nMpiDefault=none\nReturnToService=2\n"
          << "SlurmctldTimeout=30\nSlurmdTimeout=30\nInactiveLimit=0\nMinJobAge=2\nKillWait=5\n"
          << "Waittime=0\n"
          << "NodeName=mnode NodeAddr=127.0.0.1 NodeHostname=" << short_host << " CPUs=" << cpus
          << " RealMemory=1024 State=UNKNOWN\n"
          << "PartitionName=mirage Nodes=mnode Default=YES MaxTime=INFINITE State=UP\n";
        c.close();
        ::setenv("SLURM_CONF", conf.c_str(), 1);
        slurmctld_ =
            spawn({sbin("slurmctld"), "-D", "-i", "-f", conf.string()}, dir_ / "slurmctld.out");
        slurmd_ =
            spawn({sbin("slurmd"), "-D", "-f", conf.string(), "-N", "mnode"}, dir_ / "slurmd.out");
        if (!wait_until("sinfo -h -o %T | grep -q idle", 40))
            return "the node did not come up idle:\n  slurmctld:\n" + tail(dir_ / "slurmctld.out") +
                   tail(dir_ / "slurmctld.log") + "  slurmd:\n" + tail(dir_ / "slurmd.out") +
                   tail(dir_ / "slurmd.log");
        return "";
    }

    void stop() {
        for (pid_t* p : {&slurmd_, &slurmctld_, &munged_}) {
            if (*p <= 0) continue;
            ::kill(*p, SIGTERM);
            const auto t0 = Clock::now();
            int status = 0;
            while (::waitpid(*p, &status, WNOHANG) == 0) {
                if (Clock::now() - t0 > std::chrono::seconds(10)) {
                    ::kill(*p, SIGKILL);
                    ::waitpid(*p, &status, 0);
                    break;
                }
                std::this_thread::sleep_for(std::chrono::milliseconds(50));
            }
            *p = -1;
        }
        ::unsetenv("SLURM_CONF");
        if (!dir_.empty()) {
            std::error_code ec;
            fs::remove_all(dir_, ec);
            dir_.clear();
        }
    }

  private:
    static std::string sbin(const std::string& p) {
        if (auto f = find_program(p)) return *f;
        return "/usr/sbin/" + p;
    }

    static pid_t spawn(const std::vector<std::string>& argv, const fs::path& log) {
        const pid_t pid = ::fork();
        if (pid == 0) {
            ::setpgid(0, 0);
            // Gone with the test, even when it dies without running its destructors.
            ::prctl(PR_SET_PDEATHSIG, SIGKILL);
            const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
            ::dup2(fd, 1);
            ::dup2(fd, 2);
            std::vector<char*> a;
            for (const auto& s : argv) a.push_back(const_cast<char*>(s.c_str()));
            a.push_back(nullptr);
            ::execv(a[0], a.data());
            ::_exit(127);
        }
        return pid;
    }

    static bool wait_until(const std::string& cmd, int seconds) {
        const auto t0 = Clock::now();
        while (Clock::now() - t0 < std::chrono::seconds(seconds)) {
            if (shell(cmd, 5) == 0) return true;
            std::this_thread::sleep_for(std::chrono::milliseconds(250));
        }
        return false;
    }

    fs::path dir_;
    pid_t munged_ = -1, slurmctld_ = -1, slurmd_ = -1;
};

TEST(SlurmCluster, FourFramesThroughAnArrayJobAreTheLocalFrames) {
    if (!find_program("ffmpeg") || !find_program("ffprobe")) GTEST_SKIP() << "ffmpeg not on PATH";
    OneNodeCluster cluster;
    const std::string why = cluster.start();
    if (!why.empty()) GTEST_SKIP() << "no one-node Slurm cluster on this machine: " << why;

    const fs::path dir = fs::path(MIRAGE_BINARY_DIR) / "test_output" / "animate" / "slurm";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string out = (dir / "out").string();
    // The size and model can be changed for a measurement (docs/animation.md).
    const char* args = std::getenv("MIRAGE_SLURM_TEST_ARGS");
    const std::string cmd = std::string(MIRAGE_BINARY_DIR) + "/mirage animate " + kSource +
                            "/scenes/walk.pov --frames 4 " +
                            (args ? args : "-W 64 -H 48 --model trace") + " -q -o " + out;
    const auto t0 = Clock::now();
    std::string said;
    const int slurm = shell(cmd +
                                " --slurm --mem 200M --time 00:05:00 --slurm-poll 0.5 "
                                "--slurm-timeout 240",
                            300, &said);
    const double slurm_s = std::chrono::duration<double>(Clock::now() - t0).count();
    ASSERT_EQ(slurm, 0) << said;
    std::vector<std::string> bytes;
    for (int f = 1; f <= 4; ++f) {
        const fs::path frame =
            fs::path(out) / "frames" / ("frame_000" + std::to_string(f) + ".png");
        ASSERT_TRUE(fs::exists(frame)) << frame;
        bytes.push_back(read_bytes(frame));
        // Each task's log is beside its frame, written by Slurm (--output).
        const std::string log =
            read_bytes(fs::path(out) / "frames" / ("frame_000" + std::to_string(f) + ".log"));
        EXPECT_NE(log.find("frame " + std::to_string(f) + " (clock "), std::string::npos) << log;
    }
    EXPECT_TRUE(fs::exists(fs::path(out) / "slurm" / "walk.sbatch"));
    auto frames = count_video_frames(out + "/walk.mp4");
    ASSERT_TRUE(frames.ok()) << frames.message();
    EXPECT_EQ(*frames, 4);

    // The same frames rendered here, by the same command lines: the same bytes.
    for (int f = 1; f <= 4; ++f)
        fs::remove(fs::path(out) / "frames" / ("frame_000" + std::to_string(f) + ".png"));
    const auto t1 = Clock::now();
    const int local = shell(cmd, 300, &said);
    const double local_s = std::chrono::duration<double>(Clock::now() - t1).count();
    ASSERT_EQ(local, 0) << said;
    for (int f = 1; f <= 4; ++f)
        EXPECT_EQ(read_bytes(fs::path(out) / "frames" / ("frame_000" + std::to_string(f) + ".png")),
                  bytes[f - 1])
            << "frame " << f << " differs between Slurm and this machine";
    std::cout << "4 frames (" << (args ? args : "-W 64 -H 48 --model trace")
              << "): through the one-node Slurm cluster " << slurm_s << " s, locally " << local_s
              << " s (whole commands, wall clock)\n";
}

}  // namespace
}  // namespace mirage
