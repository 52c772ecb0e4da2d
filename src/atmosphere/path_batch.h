// Batch evaluation of exact rays from a CSV in the reference's columns (`mirage path --batch`).
#pragma once

#include <string>

#include "atmosphere/exact_path.h"
#include "atmosphere/general_profile.h"
#include "atmosphere/quadratic_profile.h"
#include "util/csv.h"
#include "util/result.h"

namespace mirage {

/// The output columns, in order.
extern const char* const kPathBatchColumns;

/// Evaluates every row of `table` (columns case_id, profile, eta0, eta1, alpha, y0, i_rad,
/// d1, d2, d3 at least; others ignored) and returns the output CSV text: case_id, k2, k,
/// y_turn, dz_turn, turn_kind, ray_class, y_d1..3, dydz_d1..3, hits_ground, dz_ground, with 17
/// significant digits and "nan" where a value is not defined.  The first bad row or value is
/// an error naming the file, the line and the column; nothing is returned then.
Result<std::string> run_path_batch(const CsvTable& table);

/// The same columns for every row traced in one atmosphere (any profile): only case_id, y0,
/// i_rad and d1..d3 are read (the profile columns may be absent or empty).  y0 and the heights
/// are above the ground (the sphere with an Earth radius), the distances along it, and dydz is
/// d(height)/d(distance).  k2 and k are nan (they belong to the exponential closed forms);
/// ray_class is the path's fate (ground, escape, ducted, level, straight); y_turn and dz_turn
/// are the first turning point ahead (turn_kind "ahead"), else the last one behind the eye
/// ("behind", dz_turn < 0), else nan ("none").
Result<std::string> run_path_batch(const CsvTable& table, const Atmosphere& atmosphere);

/// Whether some row of `table` names a profile (a non-empty `profile` field).
bool batch_rows_give_profiles(const CsvTable& table);

/// Every row traced in its own profile (the columns of run_path_batch(table)) through the
/// general engine, with the Earth radius and the top of `base` (each profile fitted once, as
/// `mirage path --profile ... --earth-radius R` fits it for one ray); the output as the
/// general engine's above.
Result<std::string> run_path_batch(const CsvTable& table, const AirSpec& base,
                                   const FitSettings& fit);

}  // namespace mirage
