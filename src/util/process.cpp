#include "util/process.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <sstream>

namespace mirage {

namespace {

bool is_executable_file(const std::string& path) {
    struct stat st {};
    return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode) &&
           ::access(path.c_str(), X_OK) == 0;
}

}  // namespace

std::optional<std::string> find_program(const std::string& program) {
    if (program.empty()) return std::nullopt;
    if (program.find('/') != std::string::npos) {
        if (is_executable_file(program)) return program;
        return std::nullopt;
    }
    const char* path = std::getenv("PATH");
    std::istringstream dirs(path ? path : "");
    std::string dir;
    while (std::getline(dirs, dir, ':')) {
        const std::string candidate = (dir.empty() ? std::string(".") : dir) + "/" + program;
        if (is_executable_file(candidate)) return candidate;
    }
    return std::nullopt;
}

Result<ProcessRun> run_process(const std::vector<std::string>& argv, const std::string& work_dir,
                               const std::string& log_path) {
    if (argv.empty()) return make_error("run_process: no program given");
    const auto program = find_program(argv[0]);
    if (!program) return make_error(argv[0] + ": not found on PATH");
    // Everything the child needs is prepared before fork: after it, only async-signal-safe
    // calls are allowed.
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    const int out_fd = log_path.empty() ? ::open("/dev/null", O_WRONLY | O_CLOEXEC)
                                        : ::open(log_path.c_str(),
                                                 O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
    if (out_fd < 0)
        return make_error((log_path.empty() ? std::string("/dev/null") : log_path) +
                          ": cannot open: " + std::strerror(errno));
    // A pipe closed on exec tells the parent whether chdir or exec failed, and why.
    int status_pipe[2];
    if (::pipe2(status_pipe, O_CLOEXEC) != 0) {
        ::close(out_fd);
        return make_error(argv[0] + ": cannot start: " + std::strerror(errno));
    }
    const auto t0 = std::chrono::steady_clock::now();
    const pid_t pid = ::fork();
    if (pid < 0) {
        const int err = errno;
        ::close(out_fd);
        ::close(status_pipe[0]);
        ::close(status_pipe[1]);
        return make_error(argv[0] + ": cannot start: " + std::strerror(err));
    }
    if (pid == 0) {
        ::close(status_pipe[0]);
        // mirage ignores SIGPIPE (cli/main.cpp); an ignored signal stays ignored across exec,
        // and the programs run from here expect the default.
        struct sigaction dfl {};
        dfl.sa_handler = SIG_DFL;
        ::sigaction(SIGPIPE, &dfl, nullptr);
        int err = 0;
        if (!work_dir.empty() && ::chdir(work_dir.c_str()) != 0) {
            err = errno;
        } else {
            ::dup2(out_fd, STDOUT_FILENO);
            ::dup2(out_fd, STDERR_FILENO);
            const int null_in = ::open("/dev/null", O_RDONLY);
            if (null_in >= 0) ::dup2(null_in, STDIN_FILENO);
            ::execv(program->c_str(), args.data());
            err = errno;
        }
        [[maybe_unused]] const ssize_t n = ::write(status_pipe[1], &err, sizeof err);
        ::_exit(127);
    }
    ::close(out_fd);
    ::close(status_pipe[1]);
    int child_errno = 0;
    ssize_t got;
    do {
        got = ::read(status_pipe[0], &child_errno, sizeof child_errno);
    } while (got < 0 && errno == EINTR);
    ::close(status_pipe[0]);
    int status = 0;
    struct rusage usage {};
    while (::wait4(pid, &status, 0, &usage) < 0) {
        if (errno != EINTR) return make_error(argv[0] + ": lost: " + std::strerror(errno));
    }
    ProcessRun run;
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    auto secs = [](const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * t.tv_usec; };
    run.cpu_seconds = secs(usage.ru_utime) + secs(usage.ru_stime);
    if (got == static_cast<ssize_t>(sizeof child_errno)) {
        if (!work_dir.empty() && ::access(work_dir.c_str(), X_OK) != 0)
            return make_error(work_dir + ": cannot run " + argv[0] +
                              " there: " + std::strerror(child_errno));
        return make_error(*program + ": cannot run: " + std::strerror(child_errno));
    }
    run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return run;
}

}  // namespace mirage
