#include "util/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace mirage {

ProgressBar::ProgressBar(std::string label, long total, bool enabled)
    : label_(std::move(label)),
      total_(std::max(1L, total)),
      enabled_(enabled),
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

void ProgressBar::set_done(long done) {
    done_.store(done);
    if (!shown_) return;
    percent_.store(static_cast<int>(100 * std::clamp(done, 0L, total_) / total_));
    draw(done);
}

void ProgressBar::message(const std::string& line) {
    if (!enabled_) return;
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        if (shown_) std::fprintf(stderr, "\r%*s\r", 100, "");
        std::fprintf(stderr, "%s\n", line.c_str());
        std::fflush(stderr);
    }
    if (shown_) draw(done_.load());
}

void ProgressBar::draw(long done) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (!shown_) return;
    constexpr int kWidth = 30;
    const int filled = static_cast<int>(kWidth * std::min(done, total_) / total_);
    const double s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    std::fprintf(stderr, "\r%-10s [%.*s%*s] %3d%% %ld/%ld %6.1f s", label_.c_str(), filled,
                 "##############################", kWidth - filled, "",
                 static_cast<int>(100 * std::min(done, total_) / total_), std::min(done, total_),
                 total_, s);
    std::fflush(stderr);
}

void ProgressBar::finish() {
    if (!shown_) return;
    const std::lock_guard<std::mutex> lock(mutex_);
    std::fprintf(stderr, "\r%*s\r", 100, "");
    std::fflush(stderr);
    shown_ = false;
}

}  // namespace mirage
