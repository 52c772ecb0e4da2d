#include "util/povray_switches.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>

namespace mirage {

namespace {

char upper(char c) { return static_cast<char>(std::toupper(static_cast<unsigned char>(c))); }

bool is_letter(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }

bool is_whole(const std::string& s) {
    return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
        return std::isdigit(static_cast<unsigned char>(c)) != 0;
    });
}

bool is_number(const std::string& s) {
    if (s.empty() || std::isspace(static_cast<unsigned char>(s.front()))) return false;
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    return end == s.c_str() + s.size() && std::isfinite(v);
}

bool starts_with_any_case(const std::string& word, const std::string& prefix) {
    if (word.size() < prefix.size()) return false;
    for (std::size_t i = 0; i < prefix.size(); ++i)
        if (upper(word[i]) != upper(prefix[i])) return false;
    return true;
}

// One word: its long option, or the word itself when it is no POV-Ray switch.
Result<std::string> translate_word(const std::string& w, SwitchTarget target) {
    const bool trace = target == SwitchTarget::Trace;
    const std::string command = trace ? "mirage trace" : "mirage compile";
    if (starts_with_any_case(w, "Declare=")) {
        const std::string rest = w.substr(8);
        if (rest.empty())
            return make_error(w + ": give the name and the number: Declare=NAME=VALUE");
        return "--declare=" + rest;
    }
    // POV-Ray's switches that turn something off: the display (mirage shows none) and
    // antialiasing (off unless asked for) need nothing; jitter off is trace's --no-jitter.
    if (w.size() == 2 && w[0] == '-' && (upper(w[1]) == 'D' || upper(w[1]) == 'A'))
        return std::string();
    if (w.size() == 2 && w[0] == '-' && upper(w[1]) == 'J')
        return trace ? std::string("--no-jitter") : std::string();
    // An .ini's spelling on the command line, Key=value, as POV-Ray takes it there too.
    if (const auto eq = w.find('=');
        eq != std::string::npos && eq > 0 && w[0] != '-' && w.find('/') > eq && is_letter(w[0])) {
        std::string key = w.substr(0, eq);
        for (char& c : key) c = upper(c);
        const std::string value = w.substr(eq + 1);
        // As the switch it stands for; a refusal names the word as it was typed.
        const auto as = [&](const std::string& spelled) -> Result<std::string> {
            if (value.empty()) return make_error(w + ": give the value after '='");
            auto r = translate_word(spelled, target);
            if (r || r.message().rfind(spelled + ": ", 0) != 0) return r;
            return make_error(w + r.message().substr(spelled.size()));
        };
        if (key == "WIDTH") return as("+W" + value);
        if (key == "HEIGHT") return as("+H" + value);
        if (key == "OUTPUT_FILE_NAME") return as("+O" + value);
        if (key == "CLOCK") return as("+K" + value);
        if (key == "LIBRARY_PATH") return as("+L" + value);
        if (key == "ANTIALIAS_THRESHOLD") return as("+A" + value);
        if (key == "ANTIALIAS_DEPTH") return as("+R" + value);
        if (key == "SAMPLING_METHOD") return as("+AM" + value);
        if (key == "ANTIALIAS") {
            std::string v = value;
            for (char& c : v) c = upper(c);
            if (v == "ON" || v == "TRUE" || v == "YES" || v == "1") return as("+A");
            if (v == "OFF" || v == "FALSE" || v == "NO" || v == "0") return std::string();
            return make_error(w + ": Antialias is on or off");
        }
        if (key == "JITTER") {
            std::string v = value;
            for (char& c : v) c = upper(c);
            if (v == "OFF" || v == "FALSE" || v == "NO" || v == "0") return as("-J");
            if (v == "ON" || v == "TRUE" || v == "YES" || v == "1") return std::string();
            return make_error(w + ": Jitter is on or off");
        }
        return w;  // a scene file whose name holds '=', or a value: left to the parser
    }
    if (w.size() < 2 || w[0] != '+' || !is_letter(w[1])) return w;
    auto attached = [&](const std::string& example) {
        return make_error(w + ": POV-Ray's switches take their value attached: " + example);
    };
    // The antialiasing switches have no counterpart in compile, whose corrected camera
    // averages five fixed rays in every pixel (and whose perspective .ini uses 0.3).
    const std::string compile_antialias =
        ": mirage compile antialiases at POV-Ray's threshold 0.3 only, its corrected camera "
        "averaging five fixed rays in every pixel: give +A (or --antialias) alone";
    const char letter = upper(w[1]);
    if (letter == 'W' || letter == 'H') {
        const std::string value = w.substr(2);
        const std::string name = letter == 'W' ? "width" : "height";
        if (value.empty()) return attached(std::string("+") + letter + "640");
        if (!is_whole(value))
            return make_error(w + ": the " + name + " must be a whole number of pixels (+" +
                              letter + "640)");
        return "--" + name + "=" + value;
    }
    if (letter == 'O' || letter == 'L') {
        const std::string value = w.substr(2);
        if (value.empty()) return attached(letter == 'O' ? "+Oout.png" : "+Lpov_includes");
        if (letter == 'L') return "--library-path=" + value;
        return (trace ? "--output=" : "--image=") + value;
    }
    if (letter == 'K') {
        const std::string value = w.substr(2);
        if (value.empty()) return attached("+K0.5");
        if (is_letter(value[0]))
            return make_error(w +
                              ": an animation's switch (+KFI, +KFF, +KI, +KF, +KC): mirage "
                              "animate renders animations; for one frame give its clock, "
                              "+K0.5 (--clock 0.5)");
        if (!is_number(value)) return make_error(w + ": the clock must be a number (+K0.5)");
        return "--clock=" + value;
    }
    if (letter == 'A' && w.size() >= 3 && upper(w[2]) == 'M') {
        const std::string value = w.substr(3);
        if (!trace) return make_error(w + compile_antialias);
        if (value.empty()) return attached("+AM2");
        if (!is_whole(value))
            return make_error(w + ": the antialiasing method must be 1 or 2 (+AM2)");
        return "--antialias-method=" + value;
    }
    if (letter == 'A') {
        const std::string value = w.substr(2);
        if (value.empty()) return std::string("--antialias");
        if (!is_number(value))
            return make_error(w + ": the antialiasing threshold must be a number (+A0.3)");
        if (trace) return "--antialias=" + value;
        if (std::strtod(value.c_str(), nullptr) != 0.3) return make_error(w + compile_antialias);
        return std::string("--antialias");
    }
    if (letter == 'R') {
        const std::string value = w.substr(2);
        if (!trace) return make_error(w + compile_antialias);
        if (value.empty()) return attached("+R3");
        if (!is_whole(value))
            return make_error(w + ": the antialiasing depth must be a whole number (+R3)");
        return "--antialias-depth=" + value;
    }
    return make_error(w + ": a POV-Ray switch " + command + " does not take (it takes +W, +H, " +
                      (trace ? "+A, +AM, +R, " : "+A, ") +
                      "+O, +K, +L and Declare=; a file whose name begins with '+' is given as "
                      "./" +
                      w + ")");
}

}  // namespace

Result<std::vector<std::string>> translate_povray_switches(
    const std::vector<std::string>& words, SwitchTarget target,
    const std::vector<std::string>& value_options) {
    std::vector<std::string> out;
    bool values_only = false;
    for (std::size_t i = 0; i < words.size(); ++i) {
        const std::string& w = words[i];
        if (values_only) {
            out.push_back(w);
            continue;
        }
        if (w == "--") {
            values_only = true;
            out.push_back(w);
            continue;
        }
        if (std::find(value_options.begin(), value_options.end(), w) != value_options.end()) {
            out.push_back(w);
            if (i + 1 < words.size()) out.push_back(words[++i]);
            continue;
        }
        auto t = translate_word(w, target);
        if (!t) return t.error();
        if (!t->empty()) out.push_back(std::move(*t));  // a switch that asks for nothing
    }
    return out;
}

}  // namespace mirage
