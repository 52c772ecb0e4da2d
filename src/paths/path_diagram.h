// `mirage path --svg`: the ray diagram of a fan of rays about the one asked for, with the fan's
// rays through turbulent air drawn over it when --turbulence-cn2 is given.
#pragma once

#include "paths/path_air.h"
#include "paths/path_options.h"
#include "report/ray_diagram.h"
#include "util/result.h"

namespace mirage {

/// The diagram's settings: the fan from the options (by default about `elevation_deg`, the
/// asked ray's), drawn far enough to show every turn and ground hit of the fan unless
/// --max-distance is given.
RayDiagramSettings fan_diagram_settings(const PathOptions& options, const PathAir& air,
                                        double elevation_deg);

/// The fan's rays through `options.realizations` of turbulent air (phase screens across the
/// level line of sight, out to the drawn distance, seeds from --turbulence-seed on), each
/// walked as the tracer walks it (followed_points), cut where it reaches the ground, added to
/// `settings.overlaid`.  An error names the option at fault.
Status add_perturbed_rays(const PathOptions& options, RayDiagramSettings& settings);

/// Writes the diagram to options.svg (through a temporary name; never over an input).
Status write_fan_diagram(const PathOptions& options, const PathAir& air, double elevation_deg);

}  // namespace mirage
