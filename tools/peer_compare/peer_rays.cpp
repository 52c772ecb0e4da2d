// Traces rays with the peer tracer Wigner-GPU-Lab/numerical-simulate-mirage (GSL RKF45), for
// tools/peer_compare.sh.  Compiled by that script against the peer's own headers and its
// libRungeKuttaRayBendingLib; nothing of the peer is part of mirage.
//
//   peer_rays MODEL T_AMB_C T_BASE_C TOL RAYS.csv OUT.csv [MIN_SECONDS]
//
// MODEL is water, conventional or porous (the peer's Eikonal::Model); T_BASE_C matters only
// for water.  Every row of RAYS.csv (case_id, y0, elevation_rad, d) is traced on flat ground
// with RungeKuttaRayBending::solve4x from (0, y0, 0) in the direction (cos e, sin e, 0) to
// x = d, with the settings of the peer's renderer `main` (RKF45, initial step 0.01 m, smallest
// step 1e-4 m, largest 55.5 m, the direction-change reset at cos 0.99999999999, arc length up
// to twice d) and its absolute and relative tolerances both TOL.  OUT.csv gets, per ray,
// whether it is valid (reached x = d above the ground), the point returned (x, y) and the
// slope dy/dx of the direction there.  The whole list is then traced again and again for at
// least MIN_SECONDS (default 1) of this thread's CPU time, five times; stdout gets one line
// "rays_per_second MEDIAN MIN MAX" (CPU time of this thread).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "RungeKuttaRayBending.h"

namespace {

struct RayRow {
    std::string id;
    double y0, elevation, d;
};

double thread_seconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

std::vector<RayRow> read_rays(const char* path) {
    std::ifstream in(path);
    if (!in) {
        std::cerr << "peer_rays: cannot read " << path << "\n";
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
        std::string f;
        std::getline(s, r.id, ',');
        double v[3];
        for (double& x : v) {
            if (!std::getline(s, f, ',')) {
                std::cerr << "peer_rays: " << path << ":" << line_no << ": expected 4 fields\n";
                std::exit(1);
            }
            char* end = nullptr;
            x = std::strtod(f.c_str(), &end);
            if (end == f.c_str() || !std::isfinite(x)) {
                std::cerr << "peer_rays: " << path << ":" << line_no << ": bad number '" << f
                          << "'\n";
                std::exit(1);
            }
        }
        r.y0 = v[0];
        r.elevation = v[1];
        r.d = v[2];
        rows.push_back(r);
    }
    return rows;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 7) {
        std::cerr << "usage: peer_rays MODEL T_AMB_C T_BASE_C TOL RAYS.csv OUT.csv [MIN_SECONDS]\n";
        return 2;
    }
    const std::string model_name = argv[1];
    Eikonal::Model model;
    if (model_name == "water")
        model = Eikonal::Model::cWater;
    else if (model_name == "conventional")
        model = Eikonal::Model::cConventional;
    else if (model_name == "porous")
        model = Eikonal::Model::cPorous;
    else {
        std::cerr << "peer_rays: model '" << model_name << "': water, conventional or porous\n";
        return 2;
    }
    const double t_amb = std::atof(argv[2]);
    const double t_base = std::atof(argv[3]);
    const double tol = std::atof(argv[4]);
    const std::vector<RayRow> rays = read_rays(argv[5]);
    const double min_seconds = argc > 7 ? std::atof(argv[7]) : 1.0;
    if (rays.empty()) {
        std::cerr << "peer_rays: no rays\n";
        return 1;
    }
    double d_max = 0.0;
    for (const auto& r : rays) d_max = std::max(d_max, r.d);

    // The peer's renderer (main.cpp) defaults, with flat ground.
    RungeKuttaRayBending::Parameters p;
    p.mStepper = StepperType::cRungeKuttaFehlberg45;
    p.mDistAlongRay = 2.0 * d_max;
    p.mTolAbs = tol;
    p.mTolRel = tol;
    p.mStep1 = 0.01;
    p.mStepMin = 1e-4;
    p.mStepMax = 55.5;
    p.mMaxCosDirChange = 0.99999999999;
    Eikonal eikonal(Eikonal::EarthForm::cFlat, 6371000.0, model, t_amb, t_amb, t_amb, t_base);
    RungeKuttaRayBending rk(p, eikonal);

    auto trace = [&](const RayRow& r) {
        Vertex start(0.0, r.y0, 0.0);
        Vector dir(std::cos(r.elevation), std::sin(r.elevation), 0.0);
        return rk.solve4x(start, dir, r.d);
    };

    std::ofstream out(argv[6]);
    out << "case_id,valid,x,y,slope\n";
    char buf[256];
    for (const auto& r : rays) {
        RungeKuttaRayBending::Result res;
        try {
            res = trace(r);
        } catch (const std::exception& e) {
            res.mValid = false;
        }
        const double slope = res.mDirection(1) / res.mDirection(0);
        std::snprintf(buf, sizeof buf, "%s,%d,%.17g,%.17g,%.17g\n", r.id.c_str(),
                      res.mValid ? 1 : 0, res.mValue(0), res.mValue(1), slope);
        out << buf;
    }
    out.close();

    std::vector<double> rates;
    double sink = 0.0;
    for (int rep = 0; rep < 5; ++rep) {
        long n = 0;
        const double t0 = thread_seconds();
        double t = t0;
        while (t - t0 < min_seconds) {
            for (const auto& r : rays) {
                try {
                    sink += trace(r).mValue(1);
                } catch (const std::exception&) {
                }
                ++n;
            }
            t = thread_seconds();
        }
        rates.push_back(n / (t - t0));
    }
    std::sort(rates.begin(), rates.end());
    std::printf("rays_per_second %.6g %.6g %.6g\n", rates[2], rates[0], rates[4]);
    if (sink == 12345.678) std::printf("#\n");  // keeps the traces from being optimized away
    return 0;
}
