// The engine of `mirage path`: one exact ray (class, invariant, turning points, ground hit,
// samples) with its fan diagram, a batch of rays from a CSV, the ducts, the transfer curve, or
// the eye distances from which a point has a mirrored image; printed as text or JSON.
//
// One driver serves every atmosphere through ExactPath (atmosphere/exact_path.h): an
// exponential profile given alone is traced in its closed forms and shown in the reference
// form (path_air.h, AirForm), anything else in the general form.
#pragma once

#include <ostream>

#include "paths/path_air.h"
#include "paths/path_options.h"
#include "util/result.h"

namespace mirage {

/// The options that only go together refused: --turbulence-cn2 without --svg, --svg or --png
/// with --batch, --object-distance without --object-height, --png without --transfer.
Status check_path_options(const PathOptions& options);

/// Everything `mirage path` does for the options, printed to `out`, the diagrams written (all
/// of them or none).  An error names the option and its bad value; what was printed before it
/// stays printed.
Status run_path(const PathOptions& options, std::ostream& out);

/// One ray from the options' eye in their direction through `air`, sampled to their tolerance,
/// reported in the air's form, and its fan diagram with --svg.
Status report_ray(const PathOptions& options, const PathAir& air, std::ostream& out);

}  // namespace mirage
