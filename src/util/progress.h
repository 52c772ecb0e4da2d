// A progress bar on stderr for long loops, shown only when stderr is a terminal: the label,
// a bar, the percentage and the time so far, redrawn when the percentage changes.
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
    /// Clears the bar's line (the destructor does it too).
    void finish();

  private:
    void draw(long done);

    std::string label_;
    long total_ = 1;
    bool shown_ = false;
    std::atomic<long> done_{0};
    std::atomic<int> percent_{-1};
    std::mutex mutex_;
    std::chrono::steady_clock::time_point start_;
};

}  // namespace mirage
