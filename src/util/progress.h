// A progress bar on stderr for long loops, shown only when stderr is a terminal: the label,
// a bar, the percentage, the steps and the time so far, redrawn when the percentage changes.
// Lines of news (a frame finished) are printed above it, on a terminal or not.
#pragma once

#include <atomic>
#include <chrono>
#include <mutex>
#include <string>

namespace mirage {

class ProgressBar {
  public:
    /// A bar for `total` steps; `enabled` false (or stderr not a terminal) shows nothing.
    ProgressBar(std::string label, long total, bool enabled = true);
    ~ProgressBar();
    ProgressBar(const ProgressBar&) = delete;
    ProgressBar& operator=(const ProgressBar&) = delete;

    /// One more step done (thread-safe).
    void advance(long steps = 1);
    /// `done` steps done in all (thread-safe): for work counted elsewhere.
    void set_done(long done);
    /// Prints `line` on a line of its own above the bar when enabled, whether or not stderr
    /// is a terminal (thread-safe).
    void message(const std::string& line);
    long total() const { return total_; }
    /// Clears the bar's line (the destructor does it too).
    void finish();

  private:
    void draw(long done);

    std::string label_;
    long total_ = 1;
    bool enabled_ = false;
    std::atomic<bool> shown_{false};
    std::atomic<long> done_{0};
    std::atomic<int> percent_{-1};
    std::mutex mutex_;
    std::chrono::steady_clock::time_point start_;
};

}  // namespace mirage
