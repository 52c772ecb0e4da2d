// The phase screens of a scene's turbulent air, for every command that follows its rays
// exactly (the tracer, and the compile's aim of its corrected camera).
#pragma once

#include <memory>

#include "atmosphere/phase_screens.h"
#include "load/atmosphere_settings.h"
#include "scene/parser.h"
#include "scene/scene.h"
#include "util/result.h"

namespace mirage {

/// The phase screens of the scene's turbulent air (settings.turbulence, which must be set):
/// across the camera's line of sight from its eye, out to Mirage_Extent or the farthest corner
/// of the scene's bounded objects, in metres.  `scene` as traced (lowered to its ground).
Result<std::shared_ptr<const PhaseScreens>> scene_screens(const Scene& scene,
                                                          const MirageSettings& settings);

/// When the scene's turbulent air stands, in seconds: the clock the scene was parsed at (--clock,
/// Clock=), else the animation frame's being rendered on this thread.
double turbulence_time_s(const ParseOptions& parsed);

}  // namespace mirage
