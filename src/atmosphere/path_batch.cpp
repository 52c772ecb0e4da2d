#include "atmosphere/path_batch.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <tuple>
#include <vector>

#include "atmosphere/exact_ray.h"
#include "atmosphere/general_profile.h"

namespace mirage {

const char* const kPathBatchColumns =
    "case_id,k2,k,y_turn,dz_turn,turn_kind,ray_class,y_d1,y_d2,y_d3,dydz_d1,dydz_d2,dydz_d3,"
    "hits_ground,dz_ground";

namespace {

std::string g17(double v) {
    if (std::isnan(v) || std::isinf(v)) return std::isinf(v) && v > 0 ? "inf" : "nan";
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

std::string quoted(const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string out = "\"";
    for (char ch : s) out += ch == '"' ? std::string("\"\"") : std::string(1, ch);
    return out + "\"";
}

}  // namespace

Result<std::string> run_path_batch(const CsvTable& table) {
    static const char* const required[] = {"case_id", "profile", "eta0", "eta1", "alpha",
                                           "y0",      "i_rad",   "d1",   "d2",   "d3"};
    int col[10];
    for (int j = 0; j < 10; ++j) {
        col[j] = table.column(required[j]);
        if (col[j] < 0)
            return make_error(table.source + ":1: missing column '" + required[j] + "'");
    }
    std::string out = std::string(kPathBatchColumns) + "\n";
    for (const auto& row : table.rows) {
        auto place = [&](int j) { return to_string(row.places.at(static_cast<size_t>(col[j]))); };
        auto kind = parse_profile_kind(row.fields[col[1]]);
        if (!kind) return make_error(table.where(row, col[1]) + ": " + kind.message());
        double v[8];
        for (int j = 0; j < 8; ++j) {
            auto x = csv_number(table, row, col[j + 2]);
            if (!x) return x.error();
            v[j] = *x;
        }
        const Profile profile{*kind, v[0], v[1], v[2]};
        const ProfileNames names{place(2) + ": eta0", place(3) + ": eta1", place(4) + ": alpha"};
        if (auto s = validate(profile, names); !s) return s.error();
        if (!(v[3] > 0.0 && v[3] <= kMaxHeight))
            return make_error(place(5) + ": y0 = " + g17(v[3]) +
                              " m: the eye must be above the ground and at most 1e+09 m");
        auto ray = make_exact_ray(profile, v[3], v[4]);
        if (!ray) return make_error(place(6) + ": i_rad: " + ray.message());
        for (int j = 0; j < 3; ++j)
            if (!(v[5 + j] >= 0.0 && std::isfinite(v[5 + j])))
                return make_error(place(7 + j) + ": d" + std::to_string(j + 1) + " = " +
                                  g17(v[5 + j]) + ": a distance must be finite and >= 0 (m)");
        std::string line = quoted(row.fields[col[0]]);
        auto add = [&](const std::string& s) { line += "," + s; };
        add(g17(ray->k2));
        add(g17(ray->k2 >= 0.0 ? ray->q : NAN));
        add(g17(ray->y_turn));
        add(g17(ray->dz_turn));
        add(std::string(turn_kind_name(ray->turn_kind)));
        add(std::string(ray_class_name(ray->ray_class)));
        for (int j = 0; j < 3; ++j) {
            const double d = v[5 + j];
            add(g17(ray->hits_ground && d > ray->dz_ground ? NAN : height_at(*ray, d)));
        }
        for (int j = 0; j < 3; ++j) {
            const double d = v[5 + j];
            add(g17(ray->hits_ground && d > ray->dz_ground ? NAN : slope_at(*ray, d)));
        }
        add(ray->hits_ground ? "1" : "0");
        add(g17(ray->hits_ground ? ray->dz_ground : NAN));
        out += line + "\n";
    }
    return out;
}

namespace {

// One row of the general engine's batch: the columns of kPathBatchColumns, or an error naming
// the row's place.  col: case_id, y0, i_rad, d1, d2, d3.
Result<std::string> general_row(const CsvTable& table, const CsvRow& row, const int* col,
                                const Atmosphere& atmosphere) {
    const double R = atmosphere.earth_radius();
    auto place = [&](int j) { return to_string(row.places.at(static_cast<size_t>(col[j]))); };
    double v[5];
    for (int j = 0; j < 5; ++j) {
        auto x = csv_number(table, row, col[j + 1]);
        if (!x) return x.error();
        v[j] = *x;
    }
    if (!(v[0] > 0.0 && v[0] <= kMaxHeight))
        return make_error(place(1) + ": y0 = " + g17(v[0]) +
                          " m: the eye must be above the ground and at most 1e+09 m");
    const double y0 = flattened_height(v[0], R);
    auto path = ExactPath::make(atmosphere, y0, v[1]);
    if (!path) return make_error(place(2) + ": i_rad: " + path.message());
    for (int j = 0; j < 3; ++j)
        if (!(v[2 + j] >= 0.0 && std::isfinite(v[2 + j])))
            return make_error(place(3 + j) + ": d" + std::to_string(j + 1) + " = " + g17(v[2 + j]) +
                              ": a distance must be finite and >= 0 (m)");
    // The turning point behind the eye is the first one ahead of the reversed ray.
    double y_turn = NAN, dz_turn = NAN;
    std::string turn_kind = "none";
    if (path->turning_point_count() != 0 && path->turning_point(0).dz > 0.0) {
        const TurningPoint t = path->turning_point(0);
        if (!(path->hits_ground() && t.dz > path->dz_ground())) {
            y_turn = height_above_sphere(t.y, R);
            dz_turn = t.dz;
            turn_kind = "ahead";
        }
    } else {
        auto back = ExactPath::make(atmosphere, y0, M_PI - v[1]);
        if (back && back->turning_point_count() != 0) {
            const TurningPoint t = back->turning_point(0);
            y_turn = height_above_sphere(t.y, R);
            dz_turn = -t.dz;
            turn_kind = "behind";
        }
    }
    std::string line = quoted(row.fields[col[0]]);
    auto add = [&](const std::string& s) { line += "," + s; };
    add("nan");
    add("nan");
    add(g17(y_turn));
    add(g17(dz_turn));
    add(turn_kind);
    add(path->class_name());
    auto beyond = [&](double d) { return path->hits_ground() && d > path->dz_ground(); };
    for (int j = 0; j < 3; ++j) {
        const double d = v[2 + j];
        add(g17(beyond(d) ? NAN : height_above_sphere(path->height_at(d), R)));
    }
    for (int j = 0; j < 3; ++j) {
        const double d = v[2 + j];
        // d(h)/dx = (dh/dy) (dy/dx), dh/dy = exp(y / R) in the flattened frame.
        const double scale = R > 0.0 ? std::exp(path->height_at(d) / R) : 1.0;
        add(g17(beyond(d) ? NAN : scale * path->slope_at(d)));
    }
    add(path->hits_ground() ? "1" : "0");
    add(g17(path->hits_ground() ? path->dz_ground() : NAN));
    return line + "\n";
}

Result<std::vector<int>> general_columns(const CsvTable& table) {
    static const char* const required[] = {"case_id", "y0", "i_rad", "d1", "d2", "d3"};
    std::vector<int> col(6);
    for (int j = 0; j < 6; ++j) {
        col[j] = table.column(required[j]);
        if (col[j] < 0)
            return make_error(table.source + ":1: missing column '" + required[j] + "'");
    }
    return col;
}

}  // namespace

Result<std::string> run_path_batch(const CsvTable& table, const Atmosphere& atmosphere) {
    auto col = general_columns(table);
    if (!col) return col.error();
    std::string out = std::string(kPathBatchColumns) + "\n";
    for (const auto& row : table.rows) {
        auto line = general_row(table, row, col->data(), atmosphere);
        if (!line) return line.error();
        out += *line;
    }
    return out;
}

bool batch_rows_give_profiles(const CsvTable& table) {
    const int c = table.column("profile");
    if (c < 0) return false;
    for (const auto& row : table.rows)
        if (!row.fields[static_cast<size_t>(c)].empty()) return true;
    return false;
}

Result<std::string> run_path_batch(const CsvTable& table, const AirSpec& base,
                                   const FitSettings& fit) {
    static const char* const profile_columns[] = {"profile", "eta0", "eta1", "alpha"};
    int pc[4];
    for (int j = 0; j < 4; ++j) {
        pc[j] = table.column(profile_columns[j]);
        if (pc[j] < 0)
            return make_error(table.source + ":1: missing column '" + profile_columns[j] + "'");
    }
    auto col = general_columns(table);
    if (!col) return col.error();
    // One fitted model per profile, shared by the rows that give it.
    std::map<std::tuple<int, double, double, double>, Atmosphere> models;
    std::string out = std::string(kPathBatchColumns) + "\n";
    for (const auto& row : table.rows) {
        auto place = [&](int j) { return to_string(row.places.at(static_cast<size_t>(pc[j]))); };
        auto kind = parse_profile_kind(row.fields[pc[0]]);
        if (!kind) return make_error(table.where(row, pc[0]) + ": " + kind.message());
        Profile profile;
        profile.kind = *kind;
        double* values[3] = {&profile.eta0, &profile.eta1, &profile.alpha};
        for (int j = 0; j < 3; ++j) {
            auto x = csv_number(table, row, pc[j + 1]);
            if (!x) return x.error();
            *values[j] = *x;
        }
        const ProfileNames names{place(1) + ": eta0", place(2) + ": eta1", place(3) + ": alpha"};
        if (auto s = validate(profile, names); !s) return s.error();
        const auto key = std::make_tuple(static_cast<int>(profile.kind), profile.eta0, profile.eta1,
                                         profile.alpha);
        auto it = models.find(key);
        if (it == models.end()) {
            AirSpec spec = base;
            spec.source = AirSpec::Source::Exponential;
            spec.exponential = profile;
            auto q = fit_air(spec, fit);
            if (!q) return make_error(table.where(row, pc[0]) + ": " + q.message());
            it = models.emplace(key, Atmosphere::quadratic(*q)).first;
        }
        auto line = general_row(table, row, col->data(), it->second);
        if (!line) return line.error();
        out += *line;
    }
    return out;
}

}  // namespace mirage
