#include "animate/frame_plan.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "util/format.h"

namespace mirage {

namespace {

std::string lower(std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

std::string trim(const std::string& s) {
    const auto a = s.find_first_not_of(" \t\r\n");
    if (a == std::string::npos) return "";
    const auto b = s.find_last_not_of(" \t\r\n");
    return s.substr(a, b - a + 1);
}

Result<double> to_number(const std::string& text, const std::string& name,
                         const std::string& where) {
    const std::string t = trim(text);
    char* end = nullptr;
    const double v = std::strtod(t.c_str(), &end);
    if (t.empty() || end != t.c_str() + t.size() || !std::isfinite(v))
        return make_error(where + ": " + name + " '" + t + "' is not a number");
    return v;
}

Result<int> to_frame(const std::string& text, const std::string& name, const std::string& where) {
    auto v = to_number(text, name, where);
    if (!v) return v.error();
    if (*v != std::floor(*v) || std::fabs(*v) > 2e9)
        return make_error(where + ": " + name + " " + trim(text) + " is not a frame number");
    return static_cast<int>(*v);
}

Result<bool> to_bool(const std::string& text, const std::string& name, const std::string& where) {
    const std::string t = lower(trim(text));
    if (t == "on" || t == "true" || t == "yes" || t == "1") return true;
    if (t == "off" || t == "false" || t == "no" || t == "0") return false;
    return make_error(where + ": " + name + " '" + trim(text) + "' is not on or off");
}

// POV-Ray keeps these values in POVMS floats (single precision).
double as_float(double v) { return static_cast<double>(static_cast<float>(v)); }

// What the scene sees of a value POV-Ray's front end declares (clock_delta, frame_number...):
// the float is printed to a stream with its default six significant digits and the text is
// parsed (backend/scene/scene.cpp, the declared variables).
double declared(double v) {
    std::ostringstream s;
    s << static_cast<float>(v);
    return std::strtod(s.str().c_str(), nullptr);
}

// POV-Ray's subset frame: a fraction of the range when strictly between 0 and 1, a frame
// number otherwise (animationprocessing.cpp).
int subset_frame(double value, int initial, int final_frame) {
    const float pct = std::max(static_cast<float>(value), 0.0f);
    if (pct == 0.0f || pct >= 1.0f) return static_cast<int>(pct);
    return static_cast<int>(static_cast<float>((final_frame - initial + 1) * pct));
}

}  // namespace

std::string clock_text(double clock) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", clock);
    return buf;
}

Result<FramePlan> plan_frames(const AnimationRange& r) {
    FramePlan plan;
    // vfe/vfe.cpp: a still unless the frame range (read with default 0) is other than 0-0
    // or 1-1.  A still's clock is the Clock option; the six frame identifiers are 0.
    const int i0 = r.initial_frame.value_or(0), f0 = r.final_frame.value_or(0);
    if ((i0 == 0 && f0 == 0) || (i0 == 1 && f0 == 1)) {
        AnimationClock still;
        if (r.clock) {
            still.clock = as_float(*r.clock);
            still.clock_on = true;
            if (!std::isfinite(still.clock))
                return make_error("Clock " + shortest(*r.clock) +
                                  ": beyond the range of POV-Ray's clock (a float, at most "
                                  "3.4e+38)");
        }
        plan.frames.push_back({0, still});
        return plan;
    }
    plan.animation = true;
    const int initial = r.initial_frame.value_or(1);
    if (initial < 0)
        return make_error(r.initial_frame_from + " " + std::to_string(initial) +
                          ": frame numbers start at 0");
    int final_frame = r.final_frame.value_or(1);
    if (final_frame < initial)
        return make_error("a frame range with no frames: " + r.final_frame_from + " " +
                          std::to_string(final_frame) + " is before " + r.initial_frame_from + " " +
                          std::to_string(initial));
    if (final_frame == initial)
        return make_error("a frame range of one frame (" + r.initial_frame_from + " = " +
                          r.final_frame_from + " = " + std::to_string(initial) +
                          "): POV-Ray 3.7 divides the clock range by zero frames; render a "
                          "still with +K instead");
    if (static_cast<long long>(final_frame) - initial + 1 > kMaxAnimationFrames)
        return make_error("a frame range of " +
                          std::to_string(static_cast<long long>(final_frame) - initial + 1) +
                          " frames (" + r.initial_frame_from + " " + std::to_string(initial) +
                          " to " + r.final_frame_from + " " + std::to_string(final_frame) +
                          "): at most " + std::to_string(kMaxAnimationFrames));
    const float initial_clock = static_cast<float>(r.initial_clock.value_or(0.0));
    const float final_clock = static_cast<float>(r.final_clock.value_or(1.0));
    if (r.cyclic) ++final_frame;

    int start = initial, end = r.cyclic ? final_frame - 1 : final_frame;
    if (r.subset_start) {
        start = std::max(subset_frame(*r.subset_start, initial, final_frame), initial);
        if (start > end)
            return make_error("a subset with no frames: " + r.subset_start_from + " " +
                              shortest(*r.subset_start) + " is frame " + std::to_string(start) +
                              ", after the last frame " + std::to_string(end));
    }
    if (r.subset_end) {
        end = subset_frame(*r.subset_end, initial, final_frame);
        if (end < start)
            return make_error("a subset with no frames: " + r.subset_end_from + " " +
                              shortest(*r.subset_end) + " is frame " + std::to_string(end) +
                              ", before the first frame " + std::to_string(start));
    }

    // animationprocessing.cpp: the difference of the two float clocks, in float, over the
    // frame count in double; the clock is a float, the others are declared (above).
    const double clock_delta = double(final_clock - initial_clock) / double(final_frame - initial);
    plan.digits = 1;
    for (int i = final_frame; i >= 10; i /= 10) ++plan.digits;
    for (int frame = start; frame <= end; ++frame) {
        AnimationClock c;
        c.clock = static_cast<float>(double(clock_delta * double(frame - initial)) +
                                     double(initial_clock));
        // POV-Ray keeps the clocks in floats: 1e39, or two clocks 3e38 apart, are infinite.
        if (!std::isfinite(c.clock) || !std::isfinite(clock_delta))
            return make_error("the clock of frame " + std::to_string(frame) +
                              " is not a number: Initial_Clock " +
                              shortest(r.initial_clock.value_or(0.0)) + " and Final_Clock " +
                              shortest(r.final_clock.value_or(1.0)) +
                              " and their difference must be within the range of POV-Ray's "
                              "clock (a float, at most 3.4e+38)");
        c.clock_on = true;
        c.clock_delta = declared(clock_delta);
        c.initial_clock = declared(initial_clock);
        c.final_clock = declared(final_clock);
        c.initial_frame = declared(initial);
        c.final_frame = declared(final_frame);
        c.frame_number = declared(frame);
        plan.frames.push_back({frame, c});
    }
    return plan;
}

Result<bool> read_animation_option(const std::string& option, const std::string& where,
                                   AnimationRange& r) {
    std::string name, value;
    bool is_switch = false, switch_on = true;
    if (!option.empty() && (option[0] == '+' || option[0] == '-')) {
        is_switch = true;
        switch_on = option[0] == '+';
        std::string body = lower(option.substr(1));
        // Longest switch first: KFI and KFF before KF, KC, KI, K.
        static const char* const kSwitches[] = {"kfi", "kff", "kf", "ki", "kc", "sf", "ef", "k"};
        for (const char* s : kSwitches) {
            if (body.rfind(s, 0) == 0) {
                name = s;
                value = body.substr(std::string(s).size());
                break;
            }
        }
        if (name.empty()) return false;
        // "+KLA" (clockless animation) and other K... switches are not ours.
        if (name == "k" && !value.empty() &&
            !(std::isdigit(static_cast<unsigned char>(value[0])) || value[0] == '.' ||
              value[0] == '-'))
            return false;
    } else {
        const auto eq = option.find('=');
        if (eq == std::string::npos) return false;
        name = lower(trim(option.substr(0, eq)));
        value = trim(option.substr(eq + 1));
        static const std::pair<const char*, const char*> kIni[] = {
            {"initial_frame", "kfi"},     {"final_frame", "kff"},
            {"initial_clock", "ki"},      {"final_clock", "kf"},
            {"subset_start_frame", "sf"}, {"subset_end_frame", "ef"},
            {"cyclic_animation", "kc"},   {"clock", "k"},
        };
        std::string key;
        for (const auto& [ini, sw] : kIni)
            if (name == ini) key = sw;
        if (key.empty()) return false;
        name = key;
    }
    const std::string shown = is_switch ? option : trim(option.substr(0, option.find('=')));
    const std::string at = where.empty() ? shown : where + ": " + shown;
    if (name == "kc") {
        if (is_switch) {
            if (!value.empty()) return make_error(at + ": +KC takes no value");
            r.cyclic = switch_on;
        } else {
            auto b = to_bool(value, "Cyclic_Animation", where.empty() ? shown : where);
            if (!b) return b.error();
            r.cyclic = *b;
        }
        return true;
    }
    const std::string place = where.empty() ? shown : where;
    if (name == "kfi" || name == "kff") {
        auto f = to_frame(value, name == "kfi" ? "Initial_Frame" : "Final_Frame", place);
        if (!f) return f.error();
        (name == "kfi" ? r.initial_frame : r.final_frame) = *f;
        (name == "kfi" ? r.initial_frame_from : r.final_frame_from) = at;
        return true;
    }
    const char* long_name = name == "ki"   ? "Initial_Clock"
                            : name == "kf" ? "Final_Clock"
                            : name == "sf" ? "Subset_Start_Frame"
                            : name == "ef" ? "Subset_End_Frame"
                                           : "Clock";
    auto v = to_number(value, long_name, place);
    if (!v) return v.error();
    if (name == "ki") r.initial_clock = *v;
    if (name == "kf") r.final_clock = *v;
    if (name == "k") r.clock = *v;
    if (name == "sf") {
        r.subset_start = *v;
        r.subset_start_from = at;
    }
    if (name == "ef") {
        r.subset_end = *v;
        r.subset_end_from = at;
    }
    return true;
}

Status read_animation_ini(const std::string& path, AnimationRange& range,
                          std::vector<std::string>& ignored) {
    std::ifstream in(path);
    if (!in) return make_error(path + ": cannot read");
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
        ++number;
        const std::string where = path + ":" + std::to_string(number);
        std::string t = trim(line);
        if (const auto c = t.find(';'); c != std::string::npos) t = trim(t.substr(0, c));
        if (t.empty()) continue;
        if (t[0] == '[') break;  // the first section label ends what is read
        auto read = read_animation_option(t, where, range);
        if (!read) return read.error();
        if (!*read) ignored.push_back(where + ": " + trim(t.substr(0, t.find('='))));
    }
    return Ok{};
}

}  // namespace mirage
