// The step search both path samplers share: the longest step from a point that a monotone
// test still passes, to within a factor 1.5.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include "util/check.h"

namespace mirage {

// The step from `a` (at most to `limit`): the room halved k times for the smallest k >= 0 that
// passes, found by galloping from the k of `guess` (the previous step, or an estimate from the
// local curvature; 0: start from the whole room) and bisecting, then grown by 1.5 while it
// passes.  A step passes whenever a longer one does.  Starting near the answer keeps the
// tested points close to `a`, so a lazily computed path is computed only as far as needed.
template <class Within>
inline double next_step(double a, double limit, Within within, double guess) {
    const double room = limit - a;
    MIRAGE_CHECK(std::isfinite(room) && room > 0.0);
    constexpr int kMaxHalvings = 1074;
    auto halved = [&](int k) {
        // room * 2^-k, exactly: by the exponent's bits while 2^-k is normal.
        if (k < 1022)
            return room * std::bit_cast<double>(static_cast<std::uint64_t>(1023 - k) << 52);
        return std::ldexp(room, -k);
    };
    auto passes = [&](int k) { return within(a, a + halved(k)); };
    int k0 = 0;
    if (guess > 0.0 && guess < room)
        k0 = std::clamp(static_cast<int>(std::lround(std::log2(room / guess))), 0, kMaxHalvings);
    int fail = -1, pass = -1;  // fail < pass: the room halved `fail` times fails, `pass` passes
    if (passes(k0)) {
        pass = k0;
        for (int d = 1; pass > 0; d *= 2) {
            const int t = std::max(0, pass - d);
            if (t <= fail) break;
            if (passes(t)) {
                pass = t;
            } else {
                fail = t;
                break;
            }
        }
    } else {
        fail = k0;
        for (int d = 1; pass < 0; d *= 2) {
            const int t = std::min(fail + d, kMaxHalvings);
            if (passes(t)) {
                pass = t;
            } else {
                MIRAGE_CHECK(t < kMaxHalvings);
                fail = t;
            }
        }
    }
    while (pass - fail > 1) {
        const int mid = fail + (pass - fail) / 2;
        if (passes(mid)) {
            pass = mid;
        } else {
            fail = mid;
        }
    }
    double step = halved(pass);
    MIRAGE_CHECK(a + step > a);
    for (int iter = 0; iter < 60; ++iter) {
        const double grown = 1.5 * step;
        if (grown >= room || !within(a, a + grown)) break;
        step = grown;
    }
    return step;
}

}  // namespace mirage
