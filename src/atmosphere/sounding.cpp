#include "atmosphere/sounding.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "util/csv.h"
#include "util/format.h"
#include "util/input_file.h"

namespace mirage {

namespace {

std::string trim(std::string_view s) {
    size_t a = 0, b = s.size();
    while (a < b && (s[a] == ' ' || s[a] == '\t')) ++a;
    while (b > a && (s[b - 1] == ' ' || s[b - 1] == '\t')) --b;
    return std::string(s.substr(a, b - a));
}

// The lines of the text, without their line ends.
std::vector<std::string_view> split_lines(std::string_view text) {
    std::vector<std::string_view> lines;
    size_t start = 0;
    for (size_t i = 0; i <= text.size(); ++i) {
        // LF, CRLF or a lone CR ends a line, as parse_csv reads them.
        if (i == text.size() || text[i] == '\n' || text[i] == '\r') {
            lines.push_back(text.substr(start, i - start));
            if (i + 1 < text.size() && text[i] == '\r' && text[i + 1] == '\n') ++i;
            start = i + 1;
        }
    }
    return lines;
}

// 1-based character column where field k of the line starts (commas inside quotes skipped).
int field_column(std::string_view line, size_t k) {
    bool quoted = false;
    size_t field = 0;
    for (size_t i = 0; i < line.size(); ++i) {
        if (field == k) {
            while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
            return static_cast<int>(i) + 1;
        }
        if (line[i] == '"') quoted = !quoted;
        if (line[i] == ',' && !quoted) ++field;
    }
    return static_cast<int>(line.size()) + 1;
}

enum Column { kHeight, kTemperature, kPressure, kHumidity, kIndex, kColumns };
constexpr const char* kNames[kColumns] = {"height_m", "temperature_c", "pressure_hpa",
                                          "relative_humidity", "n"};
constexpr const char* kLayout =
    "(a sounding has height_m with temperature_c [, pressure_hpa] [, relative_humidity], or "
    "height_m with n)";

}  // namespace

Result<Sounding> parse_sounding(std::string_view text, const std::string& source,
                                const SoundingRules& rules) {
    if (!(rules.max_gap_m > 0.0 && rules.max_gap_m <= kMaxSoundingGapM))
        return make_error(source + ": the largest gap between rows " + shortest(rules.max_gap_m) +
                          " m must be more than 0 and at most " + shortest(kMaxSoundingGapM) +
                          " m");
    if (text.size() >= 3 && text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    auto table = parse_csv(text, source);
    if (!table) return table.error();
    const auto lines = split_lines(text);
    auto place = [&](int line, size_t field) {
        const std::string_view l = line - 1 < static_cast<int>(lines.size()) ? lines[line - 1] : "";
        return source + ":" + std::to_string(line) + ":" + std::to_string(field_column(l, field)) +
               ": ";
    };
    int col[kColumns];
    std::fill(col, col + kColumns, -1);
    for (size_t k = 0; k < table->header.size(); ++k) {
        const std::string name = trim(table->header[k]);
        int which = -1;
        for (int c = 0; c < kColumns; ++c)
            if (name == kNames[c]) which = c;
        if (which < 0)
            return make_error(place(1, k) + "unknown column '" + quote_cut(name) + "' " + kLayout);
        if (col[which] >= 0)
            return make_error(place(1, k) + "column '" + quote_cut(name) + "' appears twice");
        col[which] = static_cast<int>(k);
    }
    auto header_error = [&](const std::string& what) {
        return make_error(source + ":1: " + what + " " + kLayout);
    };
    if (col[kHeight] < 0) return header_error("missing column 'height_m'");
    if (col[kTemperature] < 0 && col[kIndex] < 0)
        return header_error("missing column 'temperature_c' or 'n'");
    if (col[kTemperature] >= 0 && col[kIndex] >= 0)
        return make_error(place(1, col[kIndex]) + "column 'n' with 'temperature_c': give one " +
                          kLayout);
    if (col[kIndex] >= 0 && (col[kPressure] >= 0 || col[kHumidity] >= 0))
        return make_error(place(1, col[kPressure] >= 0 ? col[kPressure] : col[kHumidity]) +
                          "column '" +
                          (col[kPressure] >= 0 ? "pressure_hpa" : "relative_humidity") +
                          "' goes with temperature_c, not with n " + kLayout);

    Sounding s;
    s.source = source;
    s.kind = col[kIndex] >= 0 ? Sounding::Kind::Index : Sounding::Kind::Temperature;
    int previous_line = 0;
    for (const auto& row : table->rows) {
        double v[kColumns] = {};
        for (int c = 0; c < kColumns; ++c) {
            if (col[c] < 0) continue;
            const std::string field = trim(row.fields[col[c]]);
            const std::string where = place(row.line, col[c]) + "column '" + kNames[c] + "': ";
            if (field.empty()) return make_error(where + "missing number");
            char* end = nullptr;
            errno = 0;
            const double x = std::strtod(field.c_str(), &end);
            if (end != field.c_str() + field.size())
                return make_error(where + "'" + quote_cut(field) + "' is not a number");
            if (!std::isfinite(x))
                return make_error(where + "'" + quote_cut(field) + "' is not a finite number");
            v[c] = x;
        }
        auto bad = [&](int c, const std::string& why) {
            return make_error(place(row.line, col[c]) + "column '" + kNames[c] + "': " + why);
        };
        const double h = v[kHeight];
        if (s.height_m.empty()) {
            if (h != 0.0)
                return bad(kHeight,
                           "the first row must be at the ground, 0 m (got " + shortest(h) + " m)");
        } else {
            const double prev = s.height_m.back();
            if (!(h > prev))
                return bad(kHeight, "height " + shortest(h) +
                                        " m is not above the previous row's " + shortest(prev) +
                                        " m (line " + std::to_string(previous_line) + ")");
            if (h - prev > rules.max_gap_m)
                return bad(kHeight,
                           "gap of " + shortest(h - prev) + " m from the previous row (line " +
                               std::to_string(previous_line) + ", " + shortest(prev) +
                               " m) exceeds the limit of " + shortest(rules.max_gap_m) + " m");
        }
        if (s.kind == Sounding::Kind::Temperature) {
            if (!(v[kTemperature] > -273.15))
                return bad(kTemperature, "temperature " + shortest(v[kTemperature]) +
                                             " degC is at or below absolute zero");
            // The scenes' range of air temperatures: 3.7e6 degC in one row made the fit follow
            // it with a million pieces (48 s, 935 MB) before it gave up.
            if (!(v[kTemperature] >= kMinSoundingTemperatureC &&
                  v[kTemperature] <= kMaxSoundingTemperatureC))
                return bad(kTemperature, "temperature " + shortest(v[kTemperature]) +
                                             " degC must be from " +
                                             shortest(kMinSoundingTemperatureC) + " to " +
                                             shortest(kMaxSoundingTemperatureC) + " degC");
            if (col[kPressure] >= 0 &&
                !(v[kPressure] >= kMinSoundingPressureHpa && v[kPressure] <= kMaxSoundingPressureHpa))
                return bad(kPressure, "pressure " + shortest(v[kPressure]) + " hPa must be from " +
                                          shortest(kMinSoundingPressureHpa) + " to " +
                                          shortest(kMaxSoundingPressureHpa) + " hPa");
            if (col[kHumidity] >= 0 && !(v[kHumidity] >= 0.0 && v[kHumidity] <= 100.0))
                return bad(kHumidity, "relative humidity " + shortest(v[kHumidity]) +
                                          " % must lie in [0, 100]");
            s.temperature_k.push_back(v[kTemperature] + 273.15);
            if (col[kPressure] >= 0) s.pressure_pa.push_back(100.0 * v[kPressure]);
            if (col[kHumidity] >= 0) s.relative_humidity.push_back(0.01 * v[kHumidity]);
        } else {
            if (!(v[kIndex] >= 1.0 && v[kIndex] < 2.0))
                return bad(kIndex, "index " + shortest(v[kIndex]) + " must lie in [1, 2)");
            s.index.push_back(v[kIndex]);
        }
        s.height_m.push_back(h);
        s.line.push_back(row.line);
        previous_line = row.line;
    }
    if (static_cast<int>(s.height_m.size()) < rules.min_rows)
        return make_error(source + ": a sounding needs at least " + std::to_string(rules.min_rows) +
                          " rows, this one has " + std::to_string(s.height_m.size()));
    return s;
}

Result<Sounding> read_sounding(const std::string& path, const SoundingRules& rules) {
    auto text = read_input_file(path, InputKind{"a sounding", "soundings", kMaxSoundingBytes});
    if (!text) return text.error();
    return parse_sounding(*text, path, rules);
}

double QuadraticSpline::value(double x) const {
    if (x <= knots.front()) return values.front();
    if (x >= knots.back()) return values.back();
    const size_t j = std::upper_bound(knots.begin(), knots.end(), x) - knots.begin() - 1;
    const double u = x - knots[j];
    return values[j] + (slopes[j] + curvatures[j] * u) * u;
}

double QuadraticSpline::slope(double x) const {
    if (x < knots.front() || x > knots.back()) return 0.0;
    if (x == knots.back()) {
        const size_t j = slopes.size() - 1;
        return slopes[j] + 2.0 * curvatures[j] * (knots[j + 1] - knots[j]);
    }
    const size_t j = std::upper_bound(knots.begin(), knots.end(), x) - knots.begin() - 1;
    return slopes[j] + 2.0 * curvatures[j] * (x - knots[j]);
}

QuadraticSpline make_shape_preserving_spline(const std::vector<double>& x,
                                             const std::vector<double>& f) {
    const size_t n = x.size();
    std::vector<double> d(n - 1), h(n - 1), m(n);
    for (size_t j = 0; j + 1 < n; ++j) {
        h[j] = x[j + 1] - x[j];
        d[j] = (f[j + 1] - f[j]) / h[j];
    }
    m[0] = d[0];
    m[n - 1] = d[n - 2];
    for (size_t j = 1; j + 1 < n; ++j) {
        if (d[j - 1] * d[j] <= 0.0) {
            m[j] = 0.0;
            continue;
        }
        // Fritsch-Butland: weights from the neighbouring interval lengths.
        const double w1 = 2.0 * h[j] + h[j - 1], w2 = h[j] + 2.0 * h[j - 1];
        m[j] = (w1 + w2) / (w1 / d[j - 1] + w2 / d[j]);
    }
    // Keep each interval's midpoint slope 2 d - (m_a + m_b)/2 of the secant's sign.
    std::vector<double> scale(n, 1.0);
    for (size_t j = 0; j + 1 < n; ++j) {
        const double sum = m[j] + m[j + 1];
        double s = 1.0;
        if (d[j] == 0.0) {
            s = 0.0;
        } else if (sum / d[j] > 4.0) {
            s = 4.0 * d[j] / sum;
        }
        scale[j] = std::min(scale[j], s);
        scale[j + 1] = std::min(scale[j + 1], s);
    }
    for (size_t j = 0; j < n; ++j) m[j] *= scale[j];
    QuadraticSpline sp;
    for (size_t j = 0; j + 1 < n; ++j) {
        const double mid_slope = 2.0 * d[j] - 0.5 * (m[j] + m[j + 1]);
        const double c_left = (mid_slope - m[j]) / h[j];
        const double c_right = (m[j + 1] - mid_slope) / h[j];
        const double half = 0.5 * h[j];
        sp.knots.push_back(x[j]);
        sp.values.push_back(f[j]);
        sp.slopes.push_back(m[j]);
        sp.curvatures.push_back(c_left);
        sp.knots.push_back(x[j] + half);
        sp.values.push_back(f[j] + (m[j] + c_left * half) * half);
        sp.slopes.push_back(mid_slope);
        sp.curvatures.push_back(c_right);
    }
    sp.knots.push_back(x[n - 1]);
    sp.values.push_back(f[n - 1]);
    return sp;
}

}  // namespace mirage
