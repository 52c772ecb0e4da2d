// Soundings: a measured profile of the air as a CSV file, read strictly (every refusal names
// the file, line and column), and the C^1 quadratic spline that interpolates its columns.
//
// Columns (header row first; a UTF-8 byte-order mark is skipped):
//   height_m, temperature_c [, pressure_hpa] [, relative_humidity]     (humidity in %), or
//   height_m, n                                                        (the index itself).
// The first row is at the ground (0 m); heights increase, no two rows further apart than the
// stated gap limit; at least two rows; every field a finite number.
//
// Interpolation: a shape-preserving C^1 quadratic spline (Schumaker's, with a knot halfway
// between rows): at every row the slope is the Fritsch-Butland weighted harmonic mean of the
// neighbouring secants (0 where they differ in sign; the secant at the first and last rows),
// then each interval's two slopes are scaled down together until they sum to at most four
// times its secant, which keeps the quadratic monotone where the data are.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "util/result.h"

namespace mirage {

struct Sounding {
    enum class Kind { Temperature, Index };
    std::string source;  // file name, for messages
    Kind kind = Kind::Temperature;
    std::vector<double> height_m;
    std::vector<double> temperature_k;      // Temperature
    std::vector<double> pressure_pa;        // Temperature, optional (empty when not given)
    std::vector<double> relative_humidity;  // Temperature, optional, 0 to 1
    std::vector<double> index;              // Index: n
    std::vector<int> line;                  // the file's line of each row, for messages
};

/// The largest sounding file read, bytes (a million rows of four columns fit in it).
constexpr std::size_t kMaxSoundingBytes = std::size_t{64} << 20;

/// A row's temperature and pressure: the scenes' ranges of air (100 to 400 K, 1 to 2000 hPa).
constexpr double kMinSoundingTemperatureC = -173.15, kMaxSoundingTemperatureC = 126.85;
constexpr double kMinSoundingPressureHpa = 1.0, kMaxSoundingPressureHpa = 2000.0;

/// The largest gap between rows that may be allowed, m (SoundingRules::max_gap_m).
constexpr double kMaxSoundingGapM = 1e4;

struct SoundingRules {
    double max_gap_m = 1000.0;  // largest allowed distance between consecutive rows, > 0
    int min_rows = 2;
};

/// Parses sounding CSV text; `source` names it in messages ("FILE:LINE:COL: column 'NAME':
/// ...").
Result<Sounding> parse_sounding(std::string_view text, const std::string& source,
                                const SoundingRules& rules = {});

/// Reads and parses a sounding file.
Result<Sounding> read_sounding(const std::string& path, const SoundingRules& rules = {});

/// A C^1 quadratic spline through (x_j, f_j): on each half interval f = v + s u + c u^2.
struct QuadraticSpline {
    std::vector<double> knots;       // rows and the midpoints between them
    std::vector<double> values;      // at the knots
    std::vector<double> slopes;      // per piece (knots - 1): at its start
    std::vector<double> curvatures;  // per piece: half the second derivative

    /// Value and slope at x (constant beyond the first and last knots; the slope at the last
    /// knot is the last piece's).
    double value(double x) const;
    double slope(double x) const;
};

/// The shape-preserving spline of the header comment through (x, f); x strictly increasing,
/// at least two points.
QuadraticSpline make_shape_preserving_spline(const std::vector<double>& x,
                                             const std::vector<double>& f);

}  // namespace mirage
