#include "util/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace mirage {

ProgressBar::ProgressBar(std::string label, long total, bool enabled)
    : label_(std::move(label)),
      total_(std::max(1L, total)),
      shown_(enabled && isatty(fileno(stderr)) != 0),
      start_(std::chrono::steady_clock::now()) {}

ProgressBar::~ProgressBar() { finish(); }

void ProgressBar::advance(long steps) {
    const long done = done_.fetch_add(steps) + steps;
    if (!shown_) return;
    const int pct = static_cast<int>(100 * std::min(done, total_) / total_);
    int shown = percent_.load();
    if (pct == shown || !percent_.compare_exchange_strong(shown, pct)) return;
    draw(done);
}

void ProgressBar::draw(long done) {
    const std::lock_guard<std::mutex> lock(mutex_);
    constexpr int kWidth = 30;
    const int filled = static_cast<int>(kWidth * std::min(done, total_) / total_);
    const double s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    std::fprintf(stderr, "\r%-10s [%.*s%*s] %3d%% %6.1f s", label_.c_str(), filled,
                 "##############################", kWidth - filled, "",
                 static_cast<int>(100 * std::min(done, total_) / total_), s);
    std::fflush(stderr);
}

void ProgressBar::finish() {
    if (!shown_) return;
    const std::lock_guard<std::mutex> lock(mutex_);
    std::fprintf(stderr, "\r%*s\r", 60, "");
    std::fflush(stderr);
    shown_ = false;
}

}  // namespace mirage
