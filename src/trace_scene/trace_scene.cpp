#include "trace_scene/trace_scene.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <memory>
#include <sstream>

#include "atmosphere/sampler.h"
#include "image/image_io.h"
#include "load/mirage_scene.h"
#include "scene/camera.h"
#include "scene/animation_clock.h"
#include "scene/ground.h"
#include "trace/curved_propagator.h"
#include "trace/object_query.h"
#include "trace/scene_accel.h"
#include "trace/scene_screens.h"
#include "util/check.h"
#include "util/format.h"
#include "util/output_set.h"

namespace mirage {

void apply_output_gamma(Image& image, const GlobalSettings& global) {
    const bool legacy = global.language_version < 3.7 - 1e-9 && !global.assumed_gamma_given;
    if (!legacy && global.assumed_gamma == 1.0) return;
    for (float& v : image.pixels) {
        if (legacy) {
            // No gamma handling at all: the file holds the rendered values.
            v = decode_srgb_value(std::min(std::max(v, 0.0f), 1.0f));
        } else {
            v = v > 0.0f ? std::pow(v, static_cast<float>(global.assumed_gamma)) : 0.0f;
        }
    }
}

std::string path_mode_name(PathMode mode) {
    switch (mode) {
        case PathMode::Straight:
            return "straight rays";
        case PathMode::PerRay:
            return "per-ray paths";
        case PathMode::Scanline:
            return "per-scanline paths";
    }
    return "";
}

namespace {

// One render of the loaded scene (lowered to its ground) through the atmosphere of
// `settings`: the propagator chosen and the image in report.render.
Status trace_pass(const MirageScene& loaded, const MirageSettings& settings,
                  const TraceOptions& opt, TraceReport& report) {
    const Scene& scene = loaded.scene;
    const Profile profile = profile_in_scene_units(settings);
    const bool bends = bends_rays(settings);
    if (opt.atmosphere && bends) {
        // The tolerance's unit: one pixel along each camera ray, from the eye or, for a
        // camera with many origins, from the ray's own origin.
        auto footprint = pixel_footprint(scene.camera, opt.width, opt.height);
        if (!footprint)
            return make_error(place_prefix(scene.camera.loc, scene.file) + footprint.message() +
                              "; trace it with --no-atmosphere");
        report.footprint = *footprint;
        const double distance = report.tolerance_px * report.footprint.distance;
        if (report.footprint.distance > 0.0 && !(distance >= kMinToleranceM))
            return make_error(place_prefix(scene.camera.loc, scene.file) + "the " +
                              camera_type_name(scene.camera.type) + " camera's tolerance of " +
                              sig(report.tolerance_px, 3) + " px is " + sig(distance, 3) +
                              " units across its rays, less than the " + shortest(kMinToleranceM) +
                              " units mirage samples paths for (widen the view)");
    } else {
        report.footprint.angle_rad = report.pixel_rad;
    }
    if (!opt.atmosphere) {
        report.atmosphere = "off (--no-atmosphere)";
    } else if (!settings.declared) {
        report.atmosphere = "none declared";
    } else {
        report.atmosphere = settings.profile_label;
    }

    CurvedSettings curved;
    curved.atmosphere = Atmosphere::exponential(profile);
    curved.tolerance_rad = report.tolerance_px * report.footprint.angle_rad;
    curved.tolerance_m = report.tolerance_px * report.footprint.distance;
    if (settings.air && opt.atmosphere) {
        // Real air: the general engine's model, fitted finely enough for this tolerance (for
        // a distance across the rays, the angle it makes over the paths' reach).
        double reach = 0.0;
        if (settings.extent) {
            reach = *settings.extent;
        } else {
            auto accel = SceneAccel::build(scene);
            if (!accel) return accel.error();
            reach = general_path_reach(*accel, scene.camera.location);
        }
        auto atmosphere =
            scene_atmosphere(settings, fit_angle_rad(report.footprint, report.tolerance_px, reach),
                             &report.model_pieces);
        if (!atmosphere) return make_error(opt.scene + ": " + atmosphere.message());
        curved.atmosphere = std::move(*atmosphere);
        // Paths are followed to the declared extent, else to twice the scene's reach: the
        // same for every ray, the rows' of --scanline-paths among them.
        curved.max_dz = reach;
    }
    if (opt.reference_sampling) curved.sampling = PathSampling::Reference;
    curved.eye = scene.camera.location;
    // Turbulent air: its screens across the camera's line of sight, out to the farthest
    // bounded object (or Mirage_Extent), at the scene's clock in seconds.
    const bool shimmers = opt.atmosphere && settings.turbulence.has_value();
    if (shimmers) {
        auto screens = scene_screens(scene, settings);
        if (!screens) return screens.error();
        curved.turbulence = std::move(*screens);
        curved.turbulence_time_s = turbulence_time_s(loaded.parse_options);
        curved.unit_m = settings.unit_m;
        report.atmosphere += ", turbulence C_n^2 " + shortest(settings.turbulence->cn2) +
                             " m^-2/3 at " + shortest(curved.turbulence_time_s) + " s";
    }
    std::unique_ptr<Propagator> propagator;
    if (opt.scanline_paths) {
        // Refused for a tilted camera even without an atmosphere: the option asks for it.
        auto scanline = ScanlinePropagator::make(curved, scene.camera, opt.width, opt.height);
        if (!scanline) return scanline.error();
        if (opt.atmosphere && (bends || shimmers)) {
            propagator = std::make_unique<ScanlinePropagator>(std::move(*scanline));
            report.mode = PathMode::Scanline;
        }
    } else if (opt.atmosphere && (bends || shimmers)) {
        propagator = std::make_unique<CurvedPropagator>(curved);
        report.mode = PathMode::PerRay;
    }
    if (!propagator) propagator = std::make_unique<StraightPropagator>();

    RenderSettings rs;
    rs.width = opt.width;
    rs.height = opt.height;
    rs.threads = opt.threads;
    rs.progress = opt.progress;
    rs.antialias = opt.antialias;
    auto rendered = render(scene, rs, *propagator);
    if (!rendered) return rendered.error();
    report.render = std::move(*rendered);
    return Ok{};
}

}  // namespace

Result<TraceReport> trace_scene(const TraceOptions& opt) {
    if (opt.threads < 0) {
        return make_error("--threads " + std::to_string(opt.threads) +
                          ": must be 0 (all cores) or more");
    }
    if (!opt.output.empty())
        if (auto s = check_image_name(opt.output); !s) return s.error();
    std::optional<ChannelWavelengths> asked_colour;
    std::string colour_option;
    if (!opt.wavelengths_nm.empty()) {
        colour_option = "--wavelengths ";
        for (std::size_t k = 0; k < opt.wavelengths_nm.size(); ++k)
            colour_option += (k ? "," : "") + shortest(opt.wavelengths_nm[k]);
        if (!opt.atmosphere)
            return make_error(colour_option +
                              ": straight rays (--no-atmosphere) separate no colours");
        if (opt.monochrome) return make_error(colour_option + ": colour asked for a monochrome render");
        auto nm = check_channel_wavelengths(opt.wavelengths_nm, colour_option);
        if (!nm) return nm.error();
        asked_colour = *nm;
    }

    SceneLoadOptions lo = scene_load_options(opt);
    lo.strict = true;  // the tracer renders every object: none may be left out silently
    lo.object_queries = tracer_object_queries();
    lo.tolerance_px = opt.tolerance_px;
    lo.clock = opt.clock;
    lo.declares = opt.declares;
    // The mirage traced must be one POV-Ray shows too; straight rays need no mirage.inc.
    lo.mirage_inc = opt.atmosphere ? MirageIncCheck::IfDeclared : MirageIncCheck::None;
    auto loaded = load_mirage_scene(lo);
    if (!loaded) return loaded.error();
    MirageSettings settings = loaded->settings;
    if (asked_colour) {
        // The air must have a wavelength; the green channel's stands for it elsewhere.
        if (auto s = set_wavelength(settings, (*asked_colour)[1], colour_option); !s)
            return make_error(opt.scene + ": " + s.message());
        settings.channel_wavelengths_nm = asked_colour;
    }
    if (opt.atmosphere && settings.declared) {
        // A camera under the atmosphere's ground is refused as compile refuses it (its rays
        // would start under the ground and see the ground's underside).
        auto lowest = [&]() -> std::optional<double> {
            auto accel = SceneAccel::build(loaded->scene);
            if (!accel || accel->finite_bounds().empty()) return std::nullopt;
            return accel->finite_bounds().lo.y;
        };
        if (auto s = check_camera_above_ground(loaded->scene, settings.ground_height, lowest); !s)
            return s.error();
        // Heights above the atmosphere's ground (scene/ground.h); straight rays need no ground.
        lower_scene(loaded->scene, settings.ground_height);
    }
    const Scene& scene = loaded->scene;
    // The image may replace no file the scene was read from; refused before the render.
    OutputSet outputs(scene.files);
    if (!opt.output.empty()) {
        if (auto s = outputs.check(opt.output); !s) return s.error();
    }

    TraceReport report;
    report.scene = opt.scene;
    report.files = scene.files;
    report.width = opt.width;
    report.height = opt.height;
    report.tolerance_px = settings.tolerance_px;
    report.pixel_rad = pixel_angle_rad(scene.camera, opt.width, opt.height);
    report.many_origins = !camera_has_one_viewpoint(scene.camera);
    const std::optional<ChannelWavelengths> colour =
        opt.monochrome ? std::nullopt : settings.channel_wavelengths_nm;
    if (!colour || !opt.atmosphere) {
        if (auto s = trace_pass(*loaded, settings, opt, report); !s) return s.error();
    } else {
        // Colour: each channel traced through the air at its wavelength, and taken from
        // that render (docs/colour.md).
        Image combined(opt.width, opt.height);
        RenderStats total;
        std::string label;
        for (int c = 0; c < 3; ++c) {
            MirageSettings channel = settings;
            const std::string name = "the " + std::string(c == 0 ? "red" : c == 1 ? "green" : "blue") +
                                     " channel's wavelength";
            if (auto s = set_wavelength(channel, (*colour)[c], name); !s) return s.error();
            if (auto s = trace_pass(*loaded, channel, opt, report); !s) return s.error();
            const std::vector<float>& px = report.render.image.pixels;
            for (std::size_t k = static_cast<std::size_t>(c); k < px.size(); k += 3)
                combined.pixels[k] = px[k];
            total.counters.add(report.render.stats.counters);
            total.threads = report.render.stats.threads;
            total.seconds += report.render.stats.seconds;
            total.cpu_seconds += report.render.stats.cpu_seconds;
            total.antialiased = report.render.stats.antialiased;
            report.wavelengths_nm.push_back((*colour)[c]);
        }
        report.render.image = std::move(combined);
        report.render.stats = total;
        report.atmosphere = settings.profile_label + ", colour: red " + shortest((*colour)[0]) +
                            " nm, green " + shortest((*colour)[1]) + " nm, blue " +
                            shortest((*colour)[2]) + " nm";
    }
    apply_output_gamma(report.render.image, scene.global);
    if (!opt.output.empty()) {
        if (auto s = write_image(report.render.image, opt.output, &outputs); !s) return s.error();
        if (auto s = outputs.commit(); !s) return s.error();
        report.output = opt.output;
    }
    return report;
}

std::string trace_summary(const TraceReport& r) {
    std::ostringstream out;
    out << r.scene << ": atmosphere " << r.atmosphere;
    if (r.model_pieces > 0) out << " (fitted: " << r.model_pieces << " pieces)";
    out << ", " << path_mode_name(r.mode);
    if (r.mode != PathMode::Straight) {
        out << " within " << sig(r.tolerance_px, 3) << " px (";
        if (r.footprint.distance > 0.0) {
            out << sig(r.tolerance_px * r.footprint.distance, 3) << " units across the rays";
            if (r.footprint.angle_rad > 0.0) out << " + ";
        }
        if (r.footprint.angle_rad > 0.0 || r.footprint.distance == 0.0)
            out << sig(r.tolerance_px * r.footprint.angle_rad, 3) << " rad";
        if (r.many_origins) out << ", from each ray's origin";
        out << ")";
    }
    out << "\n" << format_stats(r.render.stats, r.width, r.height) << "\n";
    if (!r.output.empty()) out << "wrote " << r.output << "\n";
    return out.str();
}

}  // namespace mirage
