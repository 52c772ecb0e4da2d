#include "frame/frame_output.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "util/format.h"

namespace mirage {

namespace {

constexpr double kDeg = 180.0 / 3.14159265358979323846;

std::string deg(double rad) { return sig(rad * kDeg, 4) + " deg"; }
std::string rows_text(double row) { return sig(row, 4); }

std::string span_text(const RowSpan& s) {
    if (s.count == 0) return "none";
    return std::to_string(s.count) + " rows (" + std::to_string(s.first) + " to " +
           std::to_string(s.last) + ")";
}

nlohmann::json span_json(const RowSpan& s) {
    return {{"count", s.count}, {"first", s.first}, {"last", s.last}};
}

nlohmann::json image_json(const ImageSpan& i) {
    nlohmann::json j = {{"visible", i.visible}};
    if (!i.visible) return j;
    j["elevation_low_deg"] = i.elevation_low_rad * kDeg;
    j["elevation_high_deg"] = i.elevation_high_rad * kDeg;
    j["angular_size_deg"] = i.angular_size_rad() * kDeg;
    j["row_top"] = i.row_top;
    j["row_bottom"] = i.row_bottom;
    j["rows"] = i.rows();
    j["column"] = i.column;
    return j;
}

std::string image_text(const ImageSpan& i) {
    if (!i.visible) return "none";
    return deg(i.angular_size_rad()) + " tall, " + sig(i.rows(), 3) + " rows (rows " +
           rows_text(i.row_top) + " to " + rows_text(i.row_bottom) + "), elevations " +
           deg(i.elevation_low_rad) + " to " + deg(i.elevation_high_rad) +
           (i.rows() < 0.5 ? ": less than half a row, not seen" : "");
}

double m(double v, const FrameReading& f) { return v * f.unit_m; }

}  // namespace

std::string frame_text(const FrameReading& f) {
    std::ostringstream o;
    const FrameView& v = f.view;
    o << "scene        " << f.scene << " at " << v.width << "x" << v.height << "\n";
    o << "atmosphere   " << f.atmosphere << "\n";
    o << "camera       eye " << sig(m(v.camera.location.y, f), 4) << " m above the ground, angle "
      << sig(camera_angle_deg(v.camera), 4) << " deg, one row " << sig(f.pixel_rad * kDeg, 3)
      << " deg; the scene reaches " << sig(m(v.reach, f), 4) << " m\n";
    o << "true horizon row " << rows_text(f.true_horizon_row) << " (the horizontal direction)\n";
    if (f.inferior) {
        const double depression = -f.apparent_horizon_rad;
        o << "apparent horizon row " << rows_text(f.apparent_horizon_row) << ", " << deg(depression)
          << " (" << sig(depression / f.pixel_rad, 3)
          << " rows) below the true horizon: the grazing ray, touching the ground "
          << sig(m(f.ground_ends, f), 4) << " m away; steeper rays meet the ground\n";
        if (f.earth_radius > 0.0)
            o << "  (on the curved Earth, radius " << sig(m(f.earth_radius, f) / 1000.0, 5)
              << " km: heights are above the sphere, and the apparent horizon is the visible "
                 "horizon, its dip the Earth's curvature and the air's bending together; the "
                 "rays above it pass over the horizon)\n";
        o << "mirage band  " << span_text(f.column.turning_low)
          << ": rays that turn before the ground (the mirrored sky)\n";
        o << "  in reach   " << span_text(f.column.turning_low_in_reach)
          << ": of them, turning within the scene's " << sig(m(v.reach, f), 4)
          << " m (where its objects can be mirrored)";
        if (std::isfinite(f.band_top_in_reach_rad))
            o << "; the highest such ray at " << deg(f.band_top_in_reach_rad);
        o << "\n";
    }
    if (f.superior) {
        o << "lifted rows  " << span_text(f.column.turning_high)
          << ": rays that reach an apex and come down (superior mirage, looming), up to "
          << deg(f.apex_limit_rad) << "\n";
        o << "  in reach   " << span_text(f.column.turning_high_in_reach) << "\n";
    }
    if (!f.inferior && !f.superior)
        o << "no ray of the centre column turns: no mirage in this frame\n";
    o << "\nobjects (heights above the ground; images in the vertical plane through the eye and "
         "the object's centre)\n";
    for (const ObjectReading& r : f.objects) {
        o << "  " << r.object.name << "\n";
        o << "    distance " << sig(m(r.distance, f), 4) << " m, top " << sig(m(r.top, f), 4)
          << " m\n";
        o << "    direct image    " << image_text(r.direct) << "\n";
        o << "    mirrored image  " << image_text(r.mirrored) << "\n";
        if (std::isfinite(r.vanishing)) {
            o << "    its top is mirrored from eye distances " << sig(m(r.vanishing, f), 4)
              << " to " << sig(m(r.farthest, f), 4) << " m (nearer, its mirrored image vanishes)";
            if (std::isfinite(r.vanishing_row))
                o << "; vanishing mark at row " << rows_text(r.vanishing_row);
            o << "\n";
        } else {
            o << "    no mirrored image of its top: " << r.vanishing_note << "\n";
        }
    }
    if (!f.lenses.empty()) {
        o << "\nlens (camera angle): rows of the mirage band, in reach, lifted\n";
        for (const LensOption& l : f.lenses)
            o << "  angle " << sig(l.angle_deg, 3) << ": " << l.band_rows << ", "
              << l.band_rows_in_reach << ", " << l.lifted_rows << "\n";
    }
    if (!f.heights.empty()) {
        o << "\ncamera height: apparent horizon's depression, where the ground ends, band rows; "
             "each object's vanishing distance\n";
        for (const HeightOption& h : f.heights) {
            o << "  " << sig(m(h.eye_height, f), 3) << " m: ";
            if (std::isfinite(h.apparent_depression_rad))
                o << deg(h.apparent_depression_rad) << ", " << sig(m(h.ground_ends, f), 4)
                  << " m, ";
            o << h.band_rows << " rows;";
            for (double d : h.vanishing) o << " " << sig(m(d, f), 4);
            o << "\n";
        }
    }
    if (!f.distances.empty()) {
        o << "\nobject distance: where each object without a mirrored image would have its "
             "tallest\n";
        for (const DistanceOption& d : f.distances)
            o << "  " << f.objects[d.object].object.name << ": at " << sig(m(d.distance, f), 4)
              << " m, " << image_text(d.mirrored) << "\n";
    }
    if (!f.exaggerations.empty()) {
        o << "\nexaggeration (Mirage_Exaggeration, not air): depression, band rows, in reach; "
             "vanishing distances\n";
        for (const ExaggerationOption& e : f.exaggerations) {
            o << "  " << shortest(e.factor) << ": ";
            if (std::isfinite(e.apparent_depression_rad))
                o << deg(e.apparent_depression_rad) << ", ";
            o << e.band_rows << ", " << e.band_rows_in_reach << ";";
            for (double d : e.vanishing) o << " " << sig(m(d, f), 4);
            o << " (" << e.mirrored_objects << " objects mirrored)\n";
        }
    }
    if (!f.advice.empty()) {
        o << "\nadvice\n";
        for (const std::string& a : f.advice) o << "  " << a << "\n";
    }
    return o.str();
}

nlohmann::json frame_json(const FrameReading& f) {
    nlohmann::json j;
    const FrameView& v = f.view;
    j["scene"] = f.scene;
    j["width"] = v.width;
    j["height"] = v.height;
    j["atmosphere"] = f.atmosphere;
    j["earth_radius_m"] = m(f.earth_radius, f);
    j["exaggeration"] = f.exaggeration;
    j["eye_height_m"] = m(v.camera.location.y, f);
    j["angle_deg"] = camera_angle_deg(v.camera);
    j["row_deg"] = f.pixel_rad * kDeg;
    j["reach_m"] = m(v.reach, f);
    j["true_horizon_row"] = f.true_horizon_row;
    j["inferior"] = f.inferior;
    j["superior"] = f.superior;
    if (f.inferior) {
        j["apparent_horizon"] = {{"elevation_deg", f.apparent_horizon_rad * kDeg},
                                 {"depression_deg", -f.apparent_horizon_rad * kDeg},
                                 {"row", f.apparent_horizon_row},
                                 {"ground_ends_m", m(f.ground_ends, f)}};
        j["band_top_in_reach_deg"] = f.band_top_in_reach_rad * kDeg;
    }
    if (f.superior) j["apex_limit_deg"] = f.apex_limit_rad * kDeg;
    j["mirage_band"] = span_json(f.column.turning_low);
    j["mirage_band_in_reach"] = span_json(f.column.turning_low_in_reach);
    j["lifted_rows"] = span_json(f.column.turning_high);
    j["lifted_rows_in_reach"] = span_json(f.column.turning_high_in_reach);
    j["objects"] = nlohmann::json::array();
    for (const ObjectReading& r : f.objects) {
        nlohmann::json o;
        o["name"] = r.object.name;
        o["place"] = to_string(r.object.loc);
        o["kind"] = r.object.kind;
        o["distance_m"] = m(r.distance, f);
        o["top_m"] = m(r.top, f);
        o["column"] = r.column;
        o["direct"] = image_json(r.direct);
        o["mirrored"] = image_json(r.mirrored);
        o["vanishing_distance_m"] = m(r.vanishing, f);
        o["farthest_distance_m"] = m(r.farthest, f);
        if (std::isfinite(r.vanishing_row)) o["vanishing_row"] = r.vanishing_row;
        if (!r.vanishing_note.empty()) o["no_vanishing"] = r.vanishing_note;
        j["objects"].push_back(o);
    }
    j["lenses"] = nlohmann::json::array();
    for (const LensOption& l : f.lenses)
        j["lenses"].push_back({{"angle_deg", l.angle_deg},
                               {"band_rows", l.band_rows},
                               {"band_rows_in_reach", l.band_rows_in_reach},
                               {"lifted_rows", l.lifted_rows}});
    j["camera_heights"] = nlohmann::json::array();
    for (const HeightOption& h : f.heights) {
        nlohmann::json o = {{"eye_height_m", m(h.eye_height, f)},
                            {"depression_deg", h.apparent_depression_rad * kDeg},
                            {"ground_ends_m", m(h.ground_ends, f)},
                            {"band_rows", h.band_rows}};
        o["vanishing_distance_m"] = nlohmann::json::array();
        for (double d : h.vanishing) o["vanishing_distance_m"].push_back(m(d, f));
        j["camera_heights"].push_back(o);
    }
    j["object_distances"] = nlohmann::json::array();
    for (const DistanceOption& d : f.distances)
        j["object_distances"].push_back({{"object", f.objects[d.object].object.name},
                                         {"distance_m", m(d.distance, f)},
                                         {"mirrored", image_json(d.mirrored)}});
    j["exaggerations"] = nlohmann::json::array();
    for (const ExaggerationOption& e : f.exaggerations) {
        nlohmann::json o = {{"factor", e.factor},
                            {"depression_deg", e.apparent_depression_rad * kDeg},
                            {"band_rows", e.band_rows},
                            {"band_rows_in_reach", e.band_rows_in_reach},
                            {"mirrored_objects", e.mirrored_objects}};
        o["vanishing_distance_m"] = nlohmann::json::array();
        for (double d : e.vanishing) o["vanishing_distance_m"].push_back(m(d, f));
        j["exaggerations"].push_back(o);
    }
    j["advice"] = f.advice;
    return j;
}

std::string overlay_legend() {
    return "overlay: green line the true horizon (horizontal direction); red line the apparent "
           "horizon (the grazing ray: below it the ground); cyan tint the mirage band (rays that "
           "turn before the ground), blue tint where they turn within the scene's reach; yellow "
           "frame each object's mirrored image; magenta mark each object's vanishing row (its "
           "top seen from its vanishing distance: the top is mirrored only while it is seen "
           "between that mark and the true horizon)\n";
}

Image frame_overlay(const FrameReading& f, const Image& background) {
    const int w = f.view.width, h = f.view.height;
    Image img = background;
    if (img.width != w || img.height != h) {
        img = Image(w, h);
        const int horizon = static_cast<int>(std::floor(f.true_horizon_row));
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                img.set(x, y, y < horizon ? glm::vec3(0.45f, 0.6f, 0.85f) : glm::vec3(0.3f));
    }
    auto blend = [&](int x, int y, const float* c, float a) {
        if (x < 0 || y < 0 || x >= w || y >= h) return;
        const glm::vec3 old = img.at(x, y);
        img.set(x, y, (1.0f - a) * old + a * glm::vec3(c[0], c[1], c[2]));
    };
    auto line = [&](double row, const float* c, int x0, int x1) {
        if (!std::isfinite(row)) return;
        const int y = static_cast<int>(std::floor(row));
        for (int x = std::max(x0, 0); x <= std::min(x1, w - 1); ++x) blend(x, y, c, 1.0f);
    };
    for (int y = 0; y < h && y < static_cast<int>(f.column.rows.size()); ++y) {
        const RayOutcome& o = f.column.rows[y];
        if (o.fate != RayFate::TurnsLow && o.fate != RayFate::TurnsHigh) continue;
        const float* c = o.dz <= f.view.reach ? OverlayKey::kBandInReach : OverlayKey::kBand;
        for (int x = 0; x < w; ++x) blend(x, y, c, 0.35f);
    }
    line(f.true_horizon_row, OverlayKey::kTrueHorizon, 0, w - 1);
    if (f.inferior) line(f.apparent_horizon_row, OverlayKey::kApparentHorizon, 0, w - 1);
    for (const ObjectReading& r : f.objects) {
        const int half = std::max(3, w / 40);
        if (r.mirrored.visible) {
            const int x0 = static_cast<int>(r.mirrored.column) - half;
            const int x1 = static_cast<int>(r.mirrored.column) + half;
            line(r.mirrored.row_top, OverlayKey::kMirrored, x0, x1);
            line(r.mirrored.row_bottom, OverlayKey::kMirrored, x0, x1);
            for (int y = static_cast<int>(r.mirrored.row_top);
                 y <= static_cast<int>(r.mirrored.row_bottom); ++y) {
                blend(x0, y, OverlayKey::kMirrored, 1.0f);
                blend(x1, y, OverlayKey::kMirrored, 1.0f);
            }
        }
        if (std::isfinite(r.vanishing_row) && std::isfinite(r.column)) {
            const double col = r.column;
            line(r.vanishing_row, OverlayKey::kVanishing, static_cast<int>(col) - half,
                 static_cast<int>(col) + half);
        }
    }
    return img;
}

}  // namespace mirage
