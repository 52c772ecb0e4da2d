// Framing help: where the mirage lies in a scene's frame, how large each object's mirrored
// image is, from how far it vanishes, and which lens, camera height, object distance or
// exaggeration would show it better, all from the exact paths of the scene's atmosphere
// (atmosphere/exact_path.h, atmosphere/vanishing.h).
//
// Rows are read in the image's centre column (x = width / 2), for a perspective camera: the
// true horizon is the row of the horizontal direction; the apparent horizon the grazing ray,
// the boundary between rays that meet the ground and rays that turn (a lowest point) before
// it; the mirage band the rows whose ray turns before the ground (the mirrored sky); of them,
// the rows whose ray turns within the scene's reach (where the scene's objects can be
// mirrored).  Over cold ground the lifted rows are those whose ray reaches an apex and comes
// down again.  Objects are read in the vertical plane through the eye and their box's centre.
#pragma once

#include <glm/glm.hpp>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "atmosphere/exact_path.h"
#include "image/image.h"
#include "load/atmosphere_settings.h"
#include "scene/scene.h"
#include "util/result.h"
#include "util/scene_input.h"

namespace mirage {

/// What a ray from the eye does first.
enum class RayFate {
    Ground,     // meets the ground before any turning point
    TurnsLow,   // reaches a lowest point (inferior mirage) above the ground
    TurnsHigh,  // reaches an apex and comes down (superior mirage, looming)
    Escapes,    // neither: rises or runs on without a turn
};

struct RayOutcome {
    RayFate fate = RayFate::Escapes;
    double dz = 0.0;  // where: the turning point's or the ground's horizontal distance
};

/// The fate of the ray from height y0 (model units, > 0) at elevation e (rad, |e| < pi/2).
RayOutcome ray_outcome(const Atmosphere& atmosphere, double y0, double elevation_rad);

/// The view a frame is read in: the camera (a perspective one) at its height above the
/// atmosphere's ground, the image size and the scene's horizontal reach.
struct FrameView {
    Camera camera;  // heights above the ground (the scene lowered by Mirage_Ground_Height)
    int width = 320, height = 240;
    double eye_y = 0.0;  // the eye's model height (flattened on the curved Earth)
    double reach = 0.0;  // horizontal reach of the scene from the eye, scene units
};

/// The elevation of the centre column's ray through image row coordinate `y` (pixels, row
/// r's centre at r + 0.5), rad.
double row_elevation(const FrameView& view, double y);
/// The row coordinate whose centre-column ray has elevation e (rad), by bisection: it may lie
/// outside the image (negative, or beyond the height).
double elevation_row(const FrameView& view, double elevation_rad);

/// Rows [first, last] (inclusive); empty when count == 0.
struct RowSpan {
    int first = -1, last = -1, count = 0;
};

/// The centre column's rows, each row's ray classified.
struct ColumnReading {
    std::vector<RayOutcome> rows;  // per image row, its centre's ray
    RowSpan turning_low;           // rows whose ray turns before the ground (the mirage band)
    RowSpan turning_low_in_reach;  // of them, those whose turn lies within the reach
    RowSpan turning_high;          // rows whose ray comes down from an apex (lifted)
    RowSpan turning_high_in_reach;
};

/// Classifies every row of the centre column (the same exact path per row a tracer follows).
ColumnReading read_column(const Atmosphere& atmosphere, const FrameView& view);

/// One object of the scene: a finite primitive of its own or a compound object, with its box.
struct FrameObject {
    std::string name;  // "box at scene.pov:12:3"
    FileLoc loc;
    std::string kind;             // the shape's keyword, or "union", "merge", "intersection"
    glm::dvec3 lo{0.0}, hi{0.0};  // its box, heights above the ground
};

/// The scene's finite objects (planes and other unbounded ones left out), in scene order.
Result<std::vector<FrameObject>> frame_objects(const Scene& lowered_scene);

/// An image of an object in the vertical plane through the eye and the object's centre.
struct ImageSpan {
    bool visible = false;
    double elevation_low_rad = 0.0, elevation_high_rad = 0.0;
    double row_top = 0.0, row_bottom = 0.0;  // image rows (in the object's column)
    double column = 0.0;                     // the object's centre's column
    double angular_size_rad() const { return elevation_high_rad - elevation_low_rad; }
    double rows() const { return row_bottom - row_top; }
};

struct ObjectReading {
    FrameObject object;
    double distance = 0.0;  // horizontal, eye to the box's centre, scene units
    double top = 0.0;       // the box's top above the ground, scene units
    double column = std::numeric_limits<double>::quiet_NaN();  // its centre's image column
    ImageSpan direct;    // seen along rays that meet it before any turn
    ImageSpan mirrored;  // seen along rays that turn first (inferior mirage)
    // Where the mirrored image of a point at its top height is seen from (mirror_reach, as
    // `mirage path --object-height`): nearer than `vanishing`, or farther than `farthest`, no
    // ray from the eye turns and reaches it.  NaN when the air has no such ray.
    double vanishing = 0.0, farthest = 0.0;
    std::string vanishing_note;  // why there is none
    // The row where its top is seen directly with the object at its vanishing distance (in its
    // column; NaN when not found): its top is mirrored only while it is seen between this row
    // and the true horizon.
    double vanishing_row = std::numeric_limits<double>::quiet_NaN();
};

/// The object read from the view: its images and its top's vanishing distance.
ObjectReading read_object(const Atmosphere& atmosphere, const FrameView& view,
                          const FrameObject& object);

/// The mirrored image an object would have at another horizontal distance (its box moved
/// along the line from the eye through its centre).
ImageSpan mirrored_image_at(const Atmosphere& atmosphere, const FrameView& view,
                            const FrameObject& object, double distance);

/// A camera's horizontal angle (POV-Ray's `angle`), degrees, and the same camera with another.
double camera_angle_deg(const Camera& camera);
Camera with_angle(const Camera& camera, double angle_deg);

struct LensOption {
    double angle_deg = 0.0;
    int band_rows = 0;           // rows of the mirage band
    int band_rows_in_reach = 0;  // of them, turning within the scene's reach
    int lifted_rows = 0;
};

struct HeightOption {
    double eye_height = 0.0;  // above the ground, scene units
    double apparent_depression_rad = 0.0;
    double ground_ends = 0.0;  // where the grazing ray touches the ground (inf: never)
    int band_rows = 0;
    std::vector<double> vanishing;  // per object, its top's vanishing distance (NaN: none)
};

struct DistanceOption {
    int object = -1;        // index into FrameReading::objects
    double distance = 0.0;  // scene units
    ImageSpan mirrored;     // its mirrored image there
};

struct ExaggerationOption {
    double factor = 1.0;  // times the scene's own (Mirage_Exaggeration)
    double apparent_depression_rad = 0.0;
    int band_rows = 0;
    int band_rows_in_reach = 0;
    double apparent_row = 0.0;      // the apparent horizon's image row
    std::vector<double> vanishing;  // per object
    std::vector<double> farthest;   // per object
    int mirrored_objects = 0;       // objects within their [vanishing, farthest]
};

/// Everything `mirage frame` reports.
struct FrameReading {
    std::string scene;
    std::vector<std::string> files;  // every file the scene was read from
    std::string atmosphere;          // the settings' label
    double unit_m = 1.0;             // metres per scene unit
    double earth_radius = 0.0;       // of the model's flattened frame, scene units (0: flat ground)
    double exaggeration = 1.0;       // the scene's Mirage_Exaggeration
    FrameView view;
    double pixel_rad = 0.0;
    double true_horizon_row = 0.0;
    bool inferior = false, superior = false;  // rays turn low / high somewhere below / above
    double apparent_horizon_rad = 0.0;        // elevation of the grazing ray (inferior)
    double apparent_horizon_row = 0.0;
    double ground_ends = 0.0;            // the grazing ray's turning distance, scene units
    double band_top_in_reach_rad = 0.0;  // highest ray turning within the reach (inferior)
    double apex_limit_rad = 0.0;         // superior: the highest ray that still comes down
    ColumnReading column;
    std::vector<ObjectReading> objects;
    std::vector<LensOption> lenses;
    std::vector<HeightOption> heights;
    std::vector<DistanceOption> distances;
    std::vector<ExaggerationOption> exaggerations;
    std::vector<std::string> advice;  // sentences with figures
};

struct FrameOptions : SceneInput {
    bool advise = true;  // compute the lens, height, distance and exaggeration options
};

/// Reads the scene and its frame.  An error names the file, line and column or the option.
Result<FrameReading> frame_scene(const FrameOptions& options);

/// The overlay's background: the scene rendered by `mirage trace` along the exact paths, as
/// its PNG holds it.
Result<Image> frame_background(const FrameOptions& options);

}  // namespace mirage
