// The air of `mirage path`: its options resolved into one Atmosphere, with what the reports say
// about it (label, legend lines, ducts, the fit) as text or JSON.
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "atmosphere/exact_path.h"
#include "atmosphere/general_profile.h"
#include "paths/path_options.h"
#include "util/result.h"

namespace mirage {

/// How the reports show the air and its rays.  Reference: an exponential profile given alone,
/// in the reference's quantities (the profile's parameters, k2, the turn kind of
/// tests/data/path_public.csv); General: the label, the legend and the ducts, and every
/// turning point ahead, whatever the model (an exponential profile asked for with --ducts or
/// --transfer keeps its closed forms and is shown so).
enum class AirForm { Reference, General };

struct PathAir {
    Atmosphere atmosphere;
    AirForm form = AirForm::General;
    std::string label;                // e.g. "paper (inferior)", "air at 15 degC"
    std::vector<std::string> legend;  // lines describing it (empty in the reference form)
    FitReport fit;                    // the piecewise-quadratic model's fit, when fitted
    AirModel model;                   // temperature and index by height (General)
};

/// The exponential profile of --preset or --profile/--eta0/--eta1/--alpha; `label` is set to
/// its name.  An error names the option at fault.
Result<Profile> resolve_profile(const PathAirOptions& options, std::string& label);

/// That profile alone, in the reference form (its closed forms).
Result<PathAir> resolve_reference_air(const PathAirOptions& options);

/// The air the options describe, in the general form: an exponential profile keeps its closed
/// forms on flat ground unless `general`; everything else is fitted (--fit-tolerance).
Result<PathAir> resolve_air(const PathAirOptions& options);

/// Whether the options say what the air is (else it is the default: air at 15 degC).
bool air_given(const PathAirOptions& options);

/// The ducts' height ranges above the ground (none for an exponential profile: monotone).
std::vector<std::pair<double, double>> duct_heights(const PathAir& air);

/// The air's lines of a report: the reference form's one line of parameters, or the label,
/// the legend, the Earth radius and the ducts.
void write_air_text(const PathAir& air, std::ostream& out);

/// The air as JSON: the profile's kind and parameters (Reference), or its label, legend, fit,
/// Earth radius and ducts (General).
nlohmann::json air_json(const PathAir& air);

}  // namespace mirage
