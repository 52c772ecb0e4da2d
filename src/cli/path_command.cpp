// `mirage path`: one exact ray (class, invariant, turning point, ground hit, samples), a ray
// diagram as SVG, or a batch of rays from a CSV.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "atmosphere/exact_ray.h"
#include "atmosphere/path_batch.h"
#include "atmosphere/profile.h"
#include "atmosphere/sampler.h"
#include "atmosphere/vanishing.h"
#include "cli/commands.h"
#include "report/ray_diagram.h"
#include "util/csv.h"
#include "util/format.h"
#include "util/output_set.h"

namespace mirage {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct PathOptions {
    std::string preset;
    std::string profile;
    double eta0 = kNaN, eta1 = kNaN, alpha = kNaN;
    double eye_height = kNaN;
    double elevation_deg = kNaN;
    double i_rad = kNaN;
    double tolerance_rad = 1e-3;
    double tolerance_m = 0.0;
    double max_distance = std::numeric_limits<double>::infinity();
    bool json = false;
    std::string svg;
    double fan_from_deg = kNaN, fan_to_deg = kNaN;
    int fan_count = 13;
    std::string batch;
    double object_distance = kNaN, object_height = kNaN;  // the vanishing of a point's mirage
};

[[noreturn]] void fail(const std::string& message) {
    std::cerr << "mirage path: " << message << "\n";
    throw CommandFailed{1};
}

std::string g(double v, int digits = 10) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    return buf;
}

Profile resolve_profile(const PathOptions& o, std::string& label) {
    Profile p;
    if (!o.preset.empty()) {
        auto preset = preset_profile(o.preset);
        if (!preset) fail("--preset: " + preset.message());
        p = *preset;
        label = o.preset + " (" + std::string(profile_kind_name(p.kind)) + ")";
        if (!o.profile.empty() || !std::isnan(o.eta0) || !std::isnan(o.eta1) ||
            !std::isnan(o.alpha))
            fail("--preset " + o.preset +
                 " fixes the profile: give either --preset or --profile/--eta0/--eta1/--alpha");
    } else {
        if (o.profile.empty()) fail("give --preset NAME or --profile inferior|superior|none");
        auto kind = parse_profile_kind(o.profile);
        if (!kind) fail("--profile: " + kind.message());
        p.kind = *kind;
        if (p.kind != ProfileKind::None) {
            if (std::isnan(o.eta0) || std::isnan(o.eta1) || std::isnan(o.alpha))
                fail("--profile " + o.profile + " needs --eta0, --eta1 and --alpha");
            p.eta0 = o.eta0;
            p.eta1 = o.eta1;
            p.alpha = o.alpha;
        } else if (!std::isnan(o.eta0)) {
            p.eta0 = o.eta0;
        }
        label = o.profile;
    }
    if (auto s = validate(p, ProfileNames{"--eta0", "--eta1", "--alpha"}); !s) fail(s.message());
    return p;
}

double resolve_angle(const PathOptions& o) {
    if (!std::isnan(o.i_rad) && !std::isnan(o.elevation_deg))
        fail("give either --elevation-deg or --i-rad, not both");
    if (!std::isnan(o.i_rad)) return o.i_rad;
    if (!std::isnan(o.elevation_deg)) {
        if (!(std::fabs(o.elevation_deg) < 90.0))
            fail("--elevation-deg " + g(o.elevation_deg) +
                 ": must lie strictly between -90 and 90");
        return M_PI / 2 - o.elevation_deg * M_PI / 180.0;
    }
    fail("give the ray's direction with --elevation-deg DEG (or --i-rad RAD)");
}

void run_batch(const PathOptions& o) {
    auto table = read_csv_file(o.batch);
    if (!table) fail(table.message());
    auto out = run_path_batch(*table);
    if (!out) fail(out.message());
    std::cout << *out;
}

void write_svg(const PathOptions& o, const Profile& profile, const std::string& label,
               double elev_deg) {
    RayDiagramSettings st;
    st.profile = profile;
    st.profile_label = label;
    st.eye_height = o.eye_height;
    const double span = std::max(std::fabs(elev_deg), 1e-3);
    st.elev_from_deg =
        std::isnan(o.fan_from_deg) ? (elev_deg < 0 ? 2.0 * elev_deg : -span) : o.fan_from_deg;
    st.elev_to_deg =
        std::isnan(o.fan_to_deg) ? (elev_deg < 0 ? 0.25 * span : 2.0 * span) : o.fan_to_deg;
    st.count = o.fan_count;
    st.tolerance_rad = o.tolerance_rad;
    st.tolerance_m = o.tolerance_m;
    if (std::isfinite(o.max_distance)) {
        st.max_distance = o.max_distance;
    } else {
        // Far enough to show every turn and ground hit of the fan.
        double reach = 10.0 * o.eye_height;
        for (int j = 0; j < st.count; ++j) {
            const double t = st.count == 1 ? 0.5 : double(j) / (st.count - 1);
            const double e =
                (st.elev_from_deg + t * (st.elev_to_deg - st.elev_from_deg)) * M_PI / 180;
            auto ray = make_exact_ray(profile, o.eye_height, M_PI / 2 - e);
            if (!ray) continue;
            if (ray->turn_kind == TurnKind::Ahead) reach = std::max(reach, 1.6 * ray->dz_turn);
            if (ray->hits_ground) reach = std::max(reach, 1.1 * ray->dz_ground);
        }
        st.max_distance = std::min(reach, 1e6);
    }
    auto svg = ray_diagram_svg(st);
    if (!svg) fail(svg.message());
    OutputSet outputs;
    if (auto s = outputs.write_text(o.svg, *svg); !s) fail(s.message());
    if (auto s = outputs.commit(); !s) fail(s.message());
}

// `--object-height H [--object-distance D]`: from which eye distances the point has a mirrored
// image (atmosphere/vanishing.h), and whether it has one from D.
void run_vanishing(const PathOptions& o) {
    std::string label;
    const Profile profile = resolve_profile(o, label);
    if (std::isnan(o.eye_height)) fail("give the eye height with --eye-height M");
    if (std::isnan(o.object_height)) fail("give the point's height with --object-height M");
    if (!std::isnan(o.elevation_deg) || !std::isnan(o.i_rad))
        fail(
            "--object-height asks for the rays that reach the point: give no --elevation-deg or "
            "--i-rad");
    if (!std::isnan(o.object_distance) &&
        !(o.object_distance > 0.0 && std::isfinite(o.object_distance)))
        fail("--object-distance " + g(o.object_distance) + ": must be a distance > 0 m");
    auto reach = mirror_reach(profile, o.eye_height, o.object_height);
    if (!reach) fail(reach.message());
    const double elev_deg = reach->nearest_elevation_rad * 180.0 / M_PI;
    const bool has_d = !std::isnan(o.object_distance);
    const bool seen =
        has_d && o.object_distance >= reach->nearest && o.object_distance <= reach->farthest;
    if (o.json) {
        nlohmann::json j;
        j["profile"] = {{"kind", profile_kind_name(profile.kind)},
                        {"eta0", profile.eta0},
                        {"eta1", profile.eta1},
                        {"alpha", profile.alpha}};
        j["eye_height"] = o.eye_height;
        j["object_height"] = o.object_height;
        j["nearest_eye_distance"] = reach->nearest;
        j["farthest_eye_distance"] = reach->farthest;
        j["nearest_turn_height"] = reach->nearest_turn_height;
        j["nearest_elevation_deg"] = elev_deg;
        j["grazing"] = reach->grazing;
        if (has_d) {
            j["object_distance"] = o.object_distance;
            j["mirrored"] = seen;
        }
        std::cout << j.dump(2) << "\n";
        return;
    }
    std::cout << "profile     " << label << ": eta0 = " << shortest(profile.eta0)
              << ", eta1 = " << shortest(profile.eta1) << ", alpha = " << shortest(profile.alpha)
              << " /m\n";
    std::cout << "eye         y0 = " << g(o.eye_height) << " m\n";
    std::cout << "point       y = " << g(o.object_height) << " m\n";
    std::cout << "vanishing   nearest eye distance with a mirrored image " << g(reach->nearest)
              << " m (the ray turning at y = " << g(reach->nearest_turn_height) << " m"
              << (reach->grazing ? ", grazing the ground" : "") << ", elevation " << g(elev_deg)
              << " deg)\n";
    std::cout << "            farthest " << g(reach->farthest) << " m\n";
    if (has_d)
        std::cout
            << "at " << g(o.object_distance) << " m    "
            << (seen ? "mirrored: rays from the eye reach the point after turning"
                     : "no mirrored image: no ray from the eye reaches the point after turning")
            << "\n";
}

void run_single(const PathOptions& o) {
    std::string label;
    const Profile profile = resolve_profile(o, label);
    if (std::isnan(o.eye_height)) fail("give the eye height with --eye-height M");
    if (!(o.eye_height > 0.0 && o.eye_height <= kMaxHeight))
        fail("--eye-height " + g(o.eye_height) +
             ": the eye must be above the ground (> 0 m) and at most " + shortest(kMaxHeight) +
             " m");
    const double i = resolve_angle(o);
    if (!(o.tolerance_rad == 0.0 ||
          (o.tolerance_rad >= kMinToleranceRad && o.tolerance_rad <= 1.0)))
        fail("--tolerance " + g(o.tolerance_rad) + ": must be 0 or from " + g(kMinToleranceRad) +
             " to 1 rad");
    if (!(o.tolerance_m == 0.0 || (o.tolerance_m >= kMinToleranceM && o.tolerance_m <= 1e9)))
        fail("--tolerance-m " + g(o.tolerance_m) + ": must be 0 or from " + g(kMinToleranceM) +
             " to 1e+09 m");
    if (!(o.tolerance_rad > 0.0 || o.tolerance_m > 0.0))
        fail("--tolerance " + g(o.tolerance_rad) + " and --tolerance-m " + g(o.tolerance_m) +
             ": need a positive tolerance");
    if (!(o.max_distance > 0.0)) fail("--max-distance " + g(o.max_distance) + ": must be > 0 m");
    auto ray = make_exact_ray(profile, o.eye_height, i);
    if (!ray) fail(ray.message());
    SampleSettings st;
    st.tolerance_rad = o.tolerance_rad;
    st.tolerance_m = o.tolerance_m;
    st.max_dz = o.max_distance;
    const SampledPath path = sample_path(*ray, st);
    const double elev_deg = (M_PI / 2 - i) * 180.0 / M_PI;
    const char* end_name = path.end == PathEnd::Ground     ? "ground"
                           : path.end == PathEnd::Straight ? "straight"
                                                           : "cut";
    if (o.json) {
        nlohmann::json j;
        j["profile"] = {{"kind", profile_kind_name(profile.kind)},
                        {"eta0", profile.eta0},
                        {"eta1", profile.eta1},
                        {"alpha", profile.alpha}};
        j["eye_height"] = o.eye_height;
        j["elevation_deg"] = elev_deg;
        j["i_rad"] = i;
        j["eta_eye"] = ray->eta_p;
        j["beta"] = ray->beta;
        j["k2"] = ray->k2;
        j["ray_class"] = ray_class_name(ray->ray_class);
        j["turn_kind"] = turn_kind_name(ray->turn_kind);
        j["y_turn"] = std::isnan(ray->y_turn) ? nlohmann::json() : nlohmann::json(ray->y_turn);
        j["dz_turn"] = std::isnan(ray->dz_turn) ? nlohmann::json() : nlohmann::json(ray->dz_turn);
        j["hits_ground"] = ray->hits_ground;
        j["dz_ground"] = ray->hits_ground ? nlohmann::json(ray->dz_ground) : nlohmann::json();
        j["tolerance_rad"] = o.tolerance_rad;
        j["tolerance_m"] = o.tolerance_m;
        nlohmann::json pts = nlohmann::json::array();
        for (const auto& p : path.points) pts.push_back({p.x, p.y});
        j["samples"] = pts;
        j["end"] = end_name;
        if (path.end != PathEnd::Ground) j["end_slope"] = path.end_slope;
        std::cout << j.dump(2) << "\n";
    } else {
        std::cout << "profile     " << label << ": eta0 = " << shortest(profile.eta0)
                  << ", eta1 = " << shortest(profile.eta1)
                  << ", alpha = " << shortest(profile.alpha) << " /m\n";
        std::cout << "eye         y0 = " << g(o.eye_height) << " m, elevation " << g(elev_deg)
                  << " deg (i = " << shortest(i) << " rad)\n";
        std::cout << "invariant   beta = eta(y0) sin i = " << shortest(ray->beta)
                  << " (eta(y0) = " << shortest(ray->eta_p) << ", k2 = " << shortest(ray->k2)
                  << ")\n";
        std::cout << "class       " << ray_class_name(ray->ray_class) << "\n";
        if (ray->turn_kind == TurnKind::None) {
            std::cout << "turning     none\n";
        } else {
            const char* what = ray->s > 0 ? "lowest point" : "apex";
            std::cout << "turning     " << what << " y = " << g(ray->y_turn)
                      << " m at dz = " << g(ray->dz_turn) << " m ("
                      << turn_kind_name(ray->turn_kind) << ")\n";
        }
        if (ray->hits_ground)
            std::cout << "ground      hit at dz = " << g(ray->dz_ground) << " m\n";
        else
            std::cout << "ground      not reached\n";
        std::cout << "samples     " << path.points.size() << " (tolerance " << g(o.tolerance_rad)
                  << " rad seen from the eye";
        if (o.tolerance_m > 0.0) std::cout << " + " << g(o.tolerance_m) << " m";
        std::cout << "), then " << end_name;
        if (path.end != PathEnd::Ground) std::cout << " with slope " << g(path.end_slope);
        std::cout << "\n        dz (m)            y (m)\n";
        for (const auto& p : path.points) std::printf("  %14.8g  %14.8g\n", p.x, p.y);
    }
    if (!o.svg.empty()) write_svg(o, profile, label, elev_deg);
}

}  // namespace

void setup_path_command(CLI::App& app) {
    auto o = std::make_shared<PathOptions>();
    auto* sub = app.add_subcommand(
        "path", "Exact ray path in an exponential atmosphere: class, turning point, samples");
    sub->add_option("--preset", o->preset, "paper, paper-superior, hot-road or cold-sea");
    sub->add_option("--profile", o->profile, "inferior, superior or none (with --eta0 ...)");
    sub->add_option("--eta0", o->eta0, "index at the ground");
    sub->add_option("--eta1", o->eta1, "amplitude of eta^2's change");
    sub->add_option("--alpha", o->alpha, "decay rate, 1/m");
    sub->add_option("--eye-height", o->eye_height, "height of the eye, m");
    sub->add_option("--elevation-deg", o->elevation_deg,
                    "elevation of the ray, degrees (< 0 down)");
    sub->add_option("--i-rad", o->i_rad, "angle from the upward vertical, rad (the paper's i)");
    sub->add_option("--tolerance", o->tolerance_rad,
                    "sampling tolerance: largest error as an angle seen from the eye, rad")
        ->capture_default_str();
    sub->add_option("--tolerance-m", o->tolerance_m, "fixed part of the tolerance, m")
        ->capture_default_str();
    sub->add_option("--max-distance", o->max_distance, "follow the ray this far, m");
    sub->add_flag("--json", o->json, "print the result as JSON");
    sub->add_option("--svg", o->svg, "draw a ray diagram (a fan of rays) to this SVG file");
    sub->add_option("--fan-from-deg", o->fan_from_deg, "first elevation of the fan, degrees");
    sub->add_option("--fan-to-deg", o->fan_to_deg, "last elevation of the fan, degrees");
    sub->add_option("--fan-count", o->fan_count, "rays in the fan")
        ->check(CLI::Range(1, kMaxFanRays))
        ->capture_default_str();
    sub->add_option("--batch", o->batch,
                    "evaluate the rays of a CSV (reference columns) and print a CSV");
    sub->add_option("--object-height", o->object_height,
                    "height of an object point, m: the eye distances at which it has a "
                    "mirrored image (the vanishing of the inferior mirage)");
    sub->add_option("--object-distance", o->object_distance,
                    "horizontal distance from the eye to that point, m: is it mirrored from here?");
    sub->callback([o] {
        if (!std::isnan(o->object_height) || !std::isnan(o->object_distance)) {
            if (std::isnan(o->object_height))
                fail("--object-distance needs the point's height: --object-height M");
            run_vanishing(*o);
        } else if (!o->batch.empty()) {
            run_batch(*o);
        } else {
            run_single(*o);
        }
    });
}

}  // namespace mirage
