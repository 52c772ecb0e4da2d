#include "layers/outcome.h"

#include <cmath>

#include "atmosphere/exact_path.h"
#include "atmosphere/exact_ray.h"
#include "util/check.h"

namespace mirage {

BandOutcome exact_outcome(const Profile& profile, double y0, double elevation, double scene_dz) {
    return exact_outcome(Atmosphere::exponential(profile), y0, elevation, scene_dz);
}

BandOutcome exact_outcome(const Atmosphere& air, double y0, double elevation, double scene_dz) {
    BandOutcome out;
    auto path = ExactPath::make(air, y0, M_PI / 2 - elevation);
    MIRAGE_CHECK(path.ok());
    if (path->hits_ground() && path->dz_ground() < scene_dz) {
        out.ground = true;
        out.dz = path->dz_ground();
        out.y = 0.0;
        return out;
    }
    out.dz = scene_dz;
    out.y = path->height_at(scene_dz);
    out.slope = path->slope_at(scene_dz);
    out.sky = !path->hits_ground() && path->fate() != PathFate::Ducted;
    if (air.earth_radius() > 0.0) {
        // On the curved Earth the flattened path's slope is against the local horizontal,
        // which turns by dz / R from the eye's; above the scene the flattened n* keeps
        // growing with the Earth's term (to the model's top, kilometres up), so the path's
        // asymptote there is no direction of the scene.  The direction the ray leaves the
        // scene in, turned to the eye's horizontal, is what the tracer looks the sky up with
        // (trace/curved_propagator.h).
        out.final_slope =
            out.sky ? std::tan(std::atan(out.slope) - scene_dz / air.earth_radius()) : 0.0;
    } else {
        const double a = path->asymptotic_slope();
        out.final_slope = out.sky ? (std::isfinite(a) ? a : out.slope) : 0.0;
    }
    MIRAGE_CHECK(std::isfinite(out.y) && std::isfinite(out.slope));
    return out;
}

double outcome_error_rad(double y0, const BandOutcome& exact, const BandOutcome& model) {
    const double a_exact = std::atan2(exact.y - y0, exact.dz);
    const double a_model = std::atan2(model.y - y0, model.dz);
    double err = std::fabs(a_model - a_exact);
    if (exact.ground || model.ground) return err;
    if (exact.sky && model.sky) {
        err = std::max(err, std::fabs(std::atan(model.final_slope) - std::atan(exact.final_slope)));
    } else if (exact.sky != model.sky) {
        // One goes to the sky, the other comes down beyond the scene: compare the directions
        // in which they leave it.
        err = std::max(err, std::fabs(std::atan(model.slope) - std::atan(exact.slope)));
    }
    return err;
}

}  // namespace mirage
