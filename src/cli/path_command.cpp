// `mirage path`: the options of one exact ray, its fan diagram, a batch of rays, the ducts,
// the transfer curve or a point's mirrored image, handed to the engine (paths/path_report.h).
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <set>

#include "cli/commands.h"
#include "paths/path_report.h"
#include "report/ray_diagram.h"
#include "util/text_escape.h"

namespace mirage {

namespace {

// The options of real air (any of them selects the general engine), and --general.
void add_real_air_options(CLI::App& sub, PathAirOptions& a) {
    sub.add_option("--air-temperature-c", a.air_temperature_c,
                   "real air: temperature at the ground of the base profile, degC (default 15)");
    sub.add_option("--lapse-k-per-km", a.lapse_k_per_km,
                   "real air: the base cools by this much per km of height (standard: 6.5)");
    sub.add_option("--surface-layer", a.surface_layers,
                   "real air: + DT_K exp(-y / SCALE_M) (hot ground: DT_K > 0), as DT_K,SCALE_M "
                   "(repeat to add)");
    sub.add_option("--inversion", a.inversions,
                   "real air: the temperature rises by DT_K from BOTTOM_M to TOP_M, corners "
                   "smoothed by a Gaussian of standard deviation SMOOTHING_M (default 0), as "
                   "BOTTOM_M,TOP_M,DT_K[,SMOOTHING_M] (repeat to add)");
    sub.add_option("--sounding", a.sounding,
                   "real air from a CSV: height_m,temperature_c[,pressure_hpa][,relative_humidity] "
                   "or height_m,n");
    sub.add_option("--sounding-max-gap", a.sounding_max_gap,
                   "largest distance between sounding rows, m")
        ->capture_default_str();
    sub.add_option("--pressure-hpa", a.pressure_hpa,
                   "pressure at the ground, hPa (default 1013.25)");
    sub.add_flag("--isobaric", a.isobaric, "the same pressure at every height (else hydrostatic)");
    sub.add_option("--humidity-pct", a.humidity_pct, "relative humidity, % (Ciddor)");
    sub.add_option("--index", a.index, "index of air: gladstone-dale (default) or ciddor");
    sub.add_option("--gladstone-dale", a.gladstone_dale,
                   "Gladstone-Dale: n - 1 at 288.15 K and 1013.25 hPa (default 2.93e-4)");
    sub.add_option("--wavelength-nm", a.wavelength_nm,
                   "Ciddor: vacuum wavelength, nm (default 550)");
    sub.add_option("--co2-ppm", a.co2_ppm, "Ciddor: CO2, ppm (default 450)");
    sub.add_option("--earth-radius", a.earth_radius,
                   "Earth radius, m (0: flat ground, the default; 6371000 for the Earth)");
    sub.add_option("--top", a.top,
                   "height above which the air is homogeneous, m (default 1000 or twice the "
                   "highest inversion or surface layer's reach; a sounding's last row)");
    sub.add_option("--fit-tolerance", a.fit_tolerance,
                   "largest |n_fit - n| of the general engine's piecewise-quadratic model")
        ->capture_default_str();
    sub.add_flag("--general", a.general,
                 "trace a --preset/--profile through the general engine (its n^2 fitted)");
}

}  // namespace

void setup_path_command(CLI::App& app) {
    auto o = std::make_shared<PathOptions>();
    auto* sub = app.add_subcommand("path",
                                   "Exact ray path in any stratified atmosphere: class, turning "
                                   "points, samples, transfer curve");
    sub->add_option("--preset", o->air.preset, "paper, paper-superior, hot-road or cold-sea");
    sub->add_option("--profile", o->air.profile, "inferior, superior or none (with --eta0 ...)");
    sub->add_option("--eta0", o->air.eta0, "index at the ground");
    sub->add_option("--eta1", o->air.eta1, "amplitude of eta^2's change");
    sub->add_option("--alpha", o->air.alpha, "decay rate, 1/m");
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
    sub->add_option("--svg", o->svg, "draw a ray diagram (a fan of rays) to this SVG file")
        ->check(non_empty_name());
    sub->add_option("--fan-from-deg", o->fan_from_deg, "first elevation of the fan, degrees");
    sub->add_option("--fan-to-deg", o->fan_to_deg, "last elevation of the fan, degrees");
    sub->add_option("--fan-count", o->fan_count, "rays in the fan")
        ->check(CLI::Range(1, kMaxFanRays))
        ->capture_default_str();
    sub->add_option("--turbulence-cn2", o->turbulence_cn2,
                    "with --svg: draw the fan's rays through turbulent air of this C_n^2, m^-2/3 "
                    "(dashed; docs/turbulence.md)");
    sub->add_option("--turbulence-inner", o->turbulence_inner,
                    "its inner scale, m (default 0.005)");
    sub->add_option("--turbulence-outer", o->turbulence_outer, "its outer scale, m (default 1)");
    sub->add_option("--turbulence-aperture", o->turbulence_aperture,
                    "the aperture its tilts are averaged over, m (default 0: a point)");
    sub->add_option("--turbulence-seed", o->turbulence_seed, "the first realization's seed")
        ->capture_default_str();
    sub->add_option("--realizations", o->realizations, "realizations of the turbulent air drawn")
        ->check(CLI::Range(1, 64))
        ->capture_default_str();
    sub->add_option("--batch", o->batch,
                    "evaluate the rays of a CSV (reference columns) and print a CSV")
        ->check(non_empty_name());
    add_real_air_options(*sub, o->air);
    sub->add_flag("--ducts", o->ducts, "print the profile's ducts (with no ray: only them)");
    sub->add_option("--transfer", o->transfer,
                    "transfer curve: apparent against true elevation of points at this distance, m "
                    "(--svg/--png draw it with the profile)");
    sub->add_option("--transfer-from-deg", o->transfer_from_deg,
                    "first apparent elevation, degrees")
        ->capture_default_str();
    sub->add_option("--transfer-to-deg", o->transfer_to_deg, "last apparent elevation, degrees")
        ->capture_default_str();
    sub->add_option("--transfer-count", o->transfer_count, "rays of the transfer curve")
        ->capture_default_str();
    sub->add_option("--png", o->png, "draw the transfer diagram to this PNG file")
        ->check(non_empty_name());
    sub->add_option("--object-height", o->object_height,
                    "height of an object point, m: the eye distances at which it has a "
                    "mirrored image (the vanishing of the inferior mirage)");
    sub->add_option("--object-distance", o->object_distance,
                    "horizontal distance from the eye to that point, m: is it mirrored from here?");
    // A number option's "nan" would read as the option not given (its default is NaN), or
    // turn its check off: refused as the option is read.
    const CLI::Validator number(
        [](std::string& text) -> std::string {
            char* end = nullptr;
            const double v = std::strtod(text.c_str(), &end);
            if (end != text.c_str() && std::isnan(v)) return "'" + text + "' is not a number";
            return "";
        },
        "NUMBER", "number");
    for (CLI::Option* opt : sub->get_options()) {
        static const std::set<std::string> kNotNumbers = {
            "--help",           "--preset",        "--profile",   "--json",     "--svg",
            "--batch",          "--surface-layer", "--inversion", "--sounding", "--isobaric",
            "--index",          "--general",       "--ducts",     "--png",      "--fan-count",
            "--transfer-count", "--realizations"};
        if (!opt->get_name().empty() && !kNotNumbers.count(opt->get_name()) &&
            opt->get_type_size() != 0)
            opt->check(number);
    }
    sub->callback([o] {
        if (auto s = run_path(*o, std::cout); !s) {
            std::cerr << "mirage path: " << escape_terminal(s.message()) << "\n";
            throw CommandFailed{1};
        }
    });
}

}  // namespace mirage
