#include "trace/scene_screens.h"

#include "scene/animation_clock.h"
#include "trace/curved_propagator.h"
#include "trace/scene_accel.h"
#include "util/check.h"

namespace mirage {

Result<std::shared_ptr<const PhaseScreens>> scene_screens(const Scene& scene,
                                                          const MirageSettings& settings) {
    MIRAGE_CHECK(settings.turbulence.has_value());
    const Camera& camera = scene.camera;
    ScreenLayout layout;
    layout.origin = camera.location * settings.unit_m;
    layout.axis = glm::normalize(camera.direction);
    layout.aperture_m = settings.turbulence_aperture_m;
    double reach = 0.0;
    if (settings.extent) {
        reach = *settings.extent;
    } else {
        auto accel = SceneAccel::build(scene);
        if (!accel) return accel.error();
        reach = bounded_reach(*accel, camera.location);
    }
    if (!(reach > 0.0))
        return make_error(scene.file +
                          ": Mirage_Turbulence_Cn2: the scene has no bounded object to say how far "
                          "the turbulent air reaches: declare Mirage_Extent");
    layout.reach_m = reach * settings.unit_m;
    auto screens = PhaseScreens::make(*settings.turbulence, layout);
    if (!screens) return make_error(scene.file + ": turbulence: " + screens.message());
    return std::make_shared<const PhaseScreens>(std::move(*screens));
}

double turbulence_time_s(const ParseOptions& parsed) {
    return parsed.animation ? parsed.animation->clock : thread_animation_clock().clock;
}

}  // namespace mirage
