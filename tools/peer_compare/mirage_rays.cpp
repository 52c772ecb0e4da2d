// Traces rays with mirage's general exact-path engine, for tools/peer_compare.sh (the side-by-side
// comparison with the GSL tracer of Wigner-GPU-Lab/numerical-simulate-mirage,
// docs/peer_comparison.md).
//
//   mirage_peer_rays T0_C DT_K SCALE_M GLADSTONE_DALE FIT_TOLERANCE RAYS.csv OUT.csv [MIN_SECONDS]
//
// The air is what `mirage path --air-temperature-c T0_C --surface-layer DT_K,SCALE_M --isobaric
// --gladstone-dale GLADSTONE_DALE --fit-tolerance FIT_TOLERANCE` describes: T(y) = T0 + DT
// exp(-y / SCALE) on flat ground, n - 1 = GLADSTONE_DALE 288.15 K / T at 1013.25 hPa, fitted to
// |n_fit - n| <= FIT_TOLERANCE.  Every row of RAYS.csv (case_id, y0, elevation_rad, d) is traced
// from height y0 at the elevation (rad above the horizontal) with ExactPath::make, and its height
// and slope at distance d taken with height_at and slope_at (as `mirage path --batch` does).
// OUT.csv gets per ray whether it reaches d above the ground, d, the height and the slope.  The
// whole list is then traced again and again for at least MIN_SECONDS (default 1) of this thread's
// CPU time, five times; stdout gets "pieces N", "fit_seconds S" and "rays_per_second MEDIAN MIN
// MAX" (CPU time of this thread).
#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "atmosphere/exact_path.h"
#include "atmosphere/general_profile.h"

namespace {

struct RayRow {
    std::string id;
    double y0 = 0.0, elevation = 0.0, d = 0.0;
};

double thread_seconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double number(const std::string& text, const std::string& what) {
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (end == text.c_str() || *end != '\0' || !std::isfinite(v)) {
        std::cerr << "mirage_peer_rays: " << what << ": '" << text << "' is not a finite number\n";
        std::exit(1);
    }
    return v;
}

std::vector<RayRow> read_rays(const std::string& path) {
    std::ifstream in(path);
    if (!in) {
        std::cerr << "mirage_peer_rays: cannot read " << path << "\n";
        std::exit(1);
    }
    std::string line;
    std::getline(in, line);  // header: case_id,y0,elevation_rad,d
    std::vector<RayRow> rows;
    int line_no = 1;
    while (std::getline(in, line)) {
        ++line_no;
        if (line.empty()) continue;
        std::stringstream s(line);
        RayRow r;
        std::getline(s, r.id, ',');
        std::string f[3];
        for (auto& x : f)
            if (!std::getline(s, x, ',')) {
                std::cerr << "mirage_peer_rays: " << path << ":" << line_no
                          << ": expected case_id,y0,elevation_rad,d\n";
                std::exit(1);
            }
        const std::string place = path + ":" + std::to_string(line_no);
        r.y0 = number(f[0], place + ": y0");
        r.elevation = number(f[1], place + ": elevation_rad");
        r.d = number(f[2], place + ": d");
        rows.push_back(r);
    }
    return rows;
}

}  // namespace

int main(int argc, char** argv) {
    using namespace mirage;
    if (argc < 8) {
        std::cerr << "usage: mirage_peer_rays T0_C DT_K SCALE_M GLADSTONE_DALE FIT_TOLERANCE "
                     "RAYS.csv OUT.csv [MIN_SECONDS]\n";
        return 2;
    }
    AirSpec spec;
    spec.source = AirSpec::Source::Column;
    spec.column.ground_temperature_k = number(argv[1], "T0_C") + 273.15;
    spec.column.layers.push_back({number(argv[2], "DT_K"), number(argv[3], "SCALE_M")});
    spec.index.formula = IndexFormula::GladstoneDale;
    spec.index.gladstone_dale = number(argv[4], "GLADSTONE_DALE");
    spec.hydrostatic = false;
    FitSettings fs;
    fs.tolerance_n = number(argv[5], "FIT_TOLERANCE");
    const std::vector<RayRow> rays = read_rays(argv[6]);
    const double min_seconds = argc > 8 ? number(argv[8], "MIN_SECONDS") : 1.0;

    FitReport report;
    const double f0 = thread_seconds();
    auto model = fit_air(spec, fs, &report);
    const double fit_seconds = thread_seconds() - f0;
    if (!model) {
        std::cerr << "mirage_peer_rays: " << model.message() << "\n";
        return 1;
    }
    const Atmosphere atmosphere = Atmosphere::quadratic(*model);

    struct Traced {
        bool valid = false;
        double y = NAN, slope = NAN;
    };
    auto trace = [&](const RayRow& r) {
        Traced t;
        auto path = ExactPath::make(atmosphere, r.y0, M_PI / 2 - r.elevation);
        if (!path) return t;
        t.valid = !(path->hits_ground() && r.d > path->dz_ground());
        if (t.valid) {
            t.y = path->height_at(r.d);
            t.slope = path->slope_at(r.d);
        }
        return t;
    };

    std::ofstream out(argv[7]);
    out << "case_id,valid,x,y,slope\n";
    char buf[256];
    for (const auto& r : rays) {
        const Traced t = trace(r);
        std::snprintf(buf, sizeof buf, "%s,%d,%.17g,%.17g,%.17g\n", r.id.c_str(), t.valid ? 1 : 0,
                      r.d, t.y, t.slope);
        out << buf;
    }
    out.close();
    if (!out) {
        std::cerr << "mirage_peer_rays: cannot write " << argv[7] << "\n";
        return 1;
    }

    std::vector<double> rates;
    double sink = 0.0;
    for (int rep = 0; rep < 5; ++rep) {
        long n = 0;
        const double t0 = thread_seconds();
        double t = t0;
        while (t - t0 < min_seconds) {
            for (const auto& r : rays) {
                const Traced tr = trace(r);
                if (tr.valid) sink += tr.y;
                ++n;
            }
            t = thread_seconds();
        }
        rates.push_back(static_cast<double>(n) / (t - t0));
    }
    std::sort(rates.begin(), rates.end());
    std::printf("pieces %d\nfit_seconds %.6g\nrays_per_second %.6g %.6g %.6g\n", report.pieces,
                fit_seconds, rates[2], rates[0], rates[4]);
    if (sink == 12345.678) std::printf("#\n");  // keeps the traces from being optimized away
    return 0;
}
