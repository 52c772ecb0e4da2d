#include "shading/shading.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <sstream>
#include <string>

#include "shading/fog.h"
#include "shading/lights.h"
#include "patterns/normals.h"
#include "patterns/pigment_eval.h"
#include "shapes/shape_intersect.h"
#include "patterns/single_precision.h"
#include "shading/spectral.h"
#include "patterns/warps.h"
#include "util/check.h"

namespace mirage {

namespace {

// POV-Ray's texture map: the entries about `value` (their positions in single precision, as
// POV-Ray stores them), `eval`'s colours of the two blended linearly; one entry at or past the
// ends.
template <class Map, class Eval>
glm::dvec3 blend_texture_map(const Map& map, double value, Eval eval) {
    const std::size_t last = map.size() - 1;
    std::size_t prev = 0, cur = 0;
    if (value >= to_single(map[last].position)) {
        prev = cur = last;
    } else {
        while (value > to_single(map[cur].position)) prev = cur++;
    }
    if (value == to_single(map[cur].position)) prev = cur;
    glm::dvec3 colour = eval(*map[cur].texture);
    if (prev != cur) {
        const glm::dvec3 below = eval(*map[prev].texture);
        value = (value - to_single(map[prev].position)) /
                (to_single(map[cur].position) - to_single(map[prev].position));
        colour = value * colour + (1.0 - value) * below;
    }
    return colour;
}

constexpr double kEpsilon = 1.0e-10;  // POV-Ray's EPSILON
constexpr double kHalfPi = 1.57079632679489661923;

inline double max3(const glm::dvec3& v) { return std::max(v.x, std::max(v.y, v.z)); }
inline bool is_black(const glm::dvec3& c) {
    return std::fabs(c.x) < kEpsilon && std::fabs(c.y) < kEpsilon && std::fabs(c.z) < kEpsilon;
}

/// POV-Ray's HAS_FILTER of a pigment (Post_Pigment): some colour lets light through.
bool pigment_has_filter(const Pigment& p) {
    auto transparent = [](const Colour& c) {
        return std::fabs(c.filter) > kEpsilon || std::fabs(c.transmit) > kEpsilon;
    };
    if (p.kind == PatternKind::Solid) return transparent(p.colour);
    if (p.kind == PatternKind::ImageMap) {
        return p.once || p.filter_all != 0.0 || p.transmit_all != 0.0 ||
               (p.image && p.image->has_alpha);
    }
    if (!p.pigment_map.empty()) {
        for (const PigmentMapEntry& e : p.pigment_map) {
            if (pigment_has_filter(*e.pigment)) return true;
        }
        return false;
    }
    if (p.kind == PatternKind::Checker && p.colour_map.empty()) {
        return transparent(p.checker[0]) || transparent(p.checker[1]);
    }
    for (const ColourMapEntry& e : p.colour_map) {
        if (transparent(e.colour)) return true;
    }
    return false;
}

/// POV-Ray's Test_Opacity: opaque when some plain layer's pigment lets no light through.
bool texture_opaque(const Texture& t) {
    if (t.pattern.kind != PatternKind::Solid) return false;
    if (!pigment_has_filter(t.pigment)) return true;
    for (const Texture& layer : t.layers_below) {
        if (!pigment_has_filter(layer.pigment)) return true;
    }
    return false;
}

/// POV-Ray's empirical Fresnel term of the metallic highlights and reflections.
double metallic_fresnel(double cos_angle) {
    const double x = std::fabs(std::acos(cos_angle)) / kHalfPi;
    const double f = 0.014567225 / ((x - 1.12) * (x - 1.12)) - 0.011612903;
    return std::min(1.0, std::max(0.0, f));
}

/// A highlight (phong or specular) of the given intensity: the light's colour, tinted towards
/// the pigment's by `metallic` (POV-Ray's metallic, weighed by its Fresnel term).
glm::dvec3 highlight(double intensity, const glm::dvec3& light_colour, const glm::dvec3& pigment,
                     double metallic, const glm::dvec3& normal, const glm::dvec3& dir) {
    if (!(metallic > 0.0)) return intensity * light_colour;
    const double fr = metallic_fresnel(glm::dot(normal, dir));
    return intensity * light_colour *
           (glm::dvec3(1.0) + (metallic * (1.0 - fr)) * (pigment - glm::dvec3(1.0)));
}

/// A deterministic stand-in for POV-Ray's crand random numbers (its thread-order dependent
/// sequence cannot be reproduced): uniform in [0, 1) from the point.
double crand_value(const glm::dvec3& p) {
    const int a = static_cast<int>(std::floor(p.x * 4096.0));
    const int b = static_cast<int>(std::floor(p.y * 4096.0));
    const int c = static_cast<int>(std::floor(p.z * 4096.0));
    return pattern_rand(static_cast<std::size_t>(hash3d(a, b, c)) * 7u +
                        static_cast<std::size_t>(hash3d(c, a, b)));
}

}  // namespace

void TraceCounters::add(const TraceCounters& o) {
    camera_rays += o.camera_rays;
    reflected_rays += o.reflected_rays;
    shadow_rays += o.shadow_rays;
    segments += o.segments;
    segment_queries += o.segment_queries;
    trace_level_cutoffs += o.trace_level_cutoffs;
}

Status check_supported(const Scene& scene) {
    (void)scene;  // everything the parser accepts is rendered
    return Ok{};
}

/// One intersection's shading state: the hit, the ray that found it and the cache of the
/// lights' shadow tests (POV-Ray's lightColorCache: one test per light per intersection).
struct Shader::Context {
    int primitive = -1;
    glm::dvec3 point{0.0};
    glm::dvec3 direction{0.0};   // the incoming ray's unit direction
    glm::dvec3 raw_normal{0.0};  // facing the ray
    glm::dvec3 pnormal{0.0};     // POV-Ray's PNormal: the last perturbed normal (slope)
    double depth = 0.0;          // the ray's length to the hit
    double weight = 1.0;
    int level = 1;
    const Interiors* inside = nullptr;
    double travelled = 0.0;
    TraceCounters* counters = nullptr;
    const SpectralBand* band = nullptr;  // the ray's spectral band after a dispersive split
    std::vector<std::optional<glm::dvec3>> shadowed;  // per light
};

Shader::Shader(const Scene& scene, const SceneAccel& accel, const Propagator& propagator)
    : scene_(&scene),
      accel_(&accel),
      propagator_(&propagator),
      max_trace_level_(std::clamp(scene.global.max_trace_level, 1, kMaxTraceLevelLimit)),
      adc_bailout_(scene.global.adc_bailout),
      waves_(make_wave_sources(std::max(1, scene.global.number_of_waves))) {
    MIRAGE_CHECK(accel.primitive_count() == static_cast<int>(scene.primitives.size()));
    pattern_context_.noise_generator = scene.global.noise_generator;
    pattern_context_.waves = &waves_;
    // POV-Ray's Post_Process: every object has an interior (a union's children share it),
    // the atmosphere's ior where none is given, and the old finish ior, caustics and
    // refraction of a plain texture promoted to it.
    std::map<const Interior*, Interior*> shared;
    interiors_.resize(scene.primitives.size());
    opaque_.resize(scene.primitives.size());
    for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
        const Primitive& p = scene.primitives[i];
        Interior* resolved = nullptr;
        if (p.interior) {
            auto it = shared.find(p.interior.get());
            if (it == shared.end()) {
                resolved_.push_back(*p.interior);
                resolved = &resolved_.back();
                shared[p.interior.get()] = resolved;
            } else {
                resolved = it->second;
            }
        } else {
            resolved_.emplace_back();
            resolved = &resolved_.back();
        }
        if (p.texture.pattern.kind == PatternKind::Solid) {
            const Finish& f = p.texture.finish;
            if (f.ior >= 0.0) resolved->ior = f.ior;
            if (f.caustics >= 0.0) resolved->caustics = f.caustics;
            resolved->refraction = f.refraction;
        }
        interiors_[i] = resolved;
        opaque_[i] = texture_opaque(p.texture) ? 1 : 0;
        if (!opaque_[i] && !p.no_shadow) any_transparent_caster_ = true;
    }
    for (Interior& interior : resolved_) {
        if (interior.ior == 0.0) interior.ior = 1.0;  // the atmosphere's
    }
    camera_location_ = scene.camera.location;
    camera_inside_ = containing_interiors(camera_location_);
}

Shader::Interiors Shader::containing_interiors(const glm::dvec3& point) const {
    // InitRayContainerState: every object the ray starts in, in object order (a union's
    // children share one interior, entered once).
    // A compound object (CSG) is one object: its inside test is the compound's, and its
    // interior the one its first primitive has (its children share the CSG's interior unless
    // they have their own).
    Interiors list;
    std::vector<std::uint8_t> compound_seen(static_cast<std::size_t>(accel_->compound_count()), 0);
    for (std::size_t i = 0; i < interiors_.size(); ++i) {
        if (std::find(list.begin(), list.end(), interiors_[i]) != list.end()) continue;
        const int compound = scene_->primitives[i].compound;
        bool inside = false;
        if (compound < 0) {
            inside = inside_shape(accel_->shape(static_cast<int>(i)), point);
        } else if (!compound_seen[static_cast<std::size_t>(compound)]) {
            compound_seen[static_cast<std::size_t>(compound)] = 1;
            inside = accel_->inside_compound_object(compound, point);
        }
        if (inside) list.push_back(interiors_[i]);
    }
    return list;
}

glm::dvec3 Shader::trace_camera_ray(const glm::dvec3& origin, const glm::dvec3& direction,
                                    TraceCounters& counters) const {
    RayStart start;
    start.origin = origin;
    start.direction = direction;
    return trace_camera_ray(start, counters);
}

glm::dvec3 Shader::trace_camera_ray(const RayStart& start, TraceCounters& counters) const {
    MIRAGE_CHECK(start.travelled == 0.0);
    ++counters.camera_rays;
    if (start.origin == camera_location_) {
        return trace_ray(start, 1.0, 0, camera_inside_, false, counters);
    }
    return trace_ray(start, 1.0, 0, containing_interiors(start.origin), false, counters);
}

glm::dvec3 Shader::trace_ray(const RayStart& start, double weight, int level,
                             const Interiors& inside, bool continued, TraceCounters& counters,
                             const SpectralBand* band) const {
    // TraceRay: out of trace levels, or too faint to matter, is black (not the sky).
    if (level >= max_trace_level_ || weight < adc_bailout_) {
        if (level >= max_trace_level_) ++counters.trace_level_cutoffs;
        return glm::dvec3(0.0);
    }
    if (level > 0 || continued) ++counters.reflected_rays;
    // In the atmosphere a ray follows the propagator (it may bend); inside a refracting object
    // it goes straight.
    const bool in_air =
        std::all_of(inside.begin(), inside.end(), [](const Interior* i) { return i->ior == 1.0; });
    const Propagator& propagator = in_air ? *propagator_ : straight_;
    const PathHit path = propagator.propagate(*accel_, start);
    counters.segments += static_cast<std::uint64_t>(path.segments);
    counters.segment_queries += static_cast<std::uint64_t>(path.queries);
    const int shade_level = continued ? level : level + 1;
    glm::dvec3 colour = path.hit ? shade_hit(path, start.origin, weight, shade_level, inside,
                                             start.travelled + path.length, counters, band)
                                 : sky_colour(*scene_, path.direction, pattern_context_);
    // Fog, on rays that are not inside a solid (non-hollow) object.
    if (!scene_->fogs.empty() &&
        std::all_of(inside.begin(), inside.end(), [](const Interior* i) { return i->hollow; })) {
        // A curved path is taken as the straight line from its start to its end.
        glm::dvec3 direction = start.direction;
        double depth = kPovBoundHuge;
        if (path.hit) {
            const glm::dvec3 chord = path.surface.point - start.origin;
            depth = glm::length(chord);
            if (depth > 0.0 && path.segments > 1) direction = chord / depth;
        }
        colour = apply_fog(scene_->fogs, start.origin, direction, depth, colour,
                           pattern_context_.noise_generator);
    }
    return colour;
}

glm::dvec3 Shader::shade(const PathHit& path, double weight, int level, TraceCounters& counters,
                         double travelled) const {
    if (!path.hit) return sky_colour(*scene_, path.direction, pattern_context_);
    static const Interiors kOutside;
    return shade_hit(path, path.surface.point - path.length * path.direction, weight, level,
                     kOutside, travelled, counters, nullptr);
}

glm::dvec3 Shader::shade_hit(const PathHit& path, const glm::dvec3& origin, double weight,
                             int level, const Interiors& inside, double travelled,
                             TraceCounters& counters, const SpectralBand* band) const {
    (void)origin;
    const SurfaceHit& hit = path.surface;
    const Primitive& primitive = scene_->primitives[hit.primitive];
    Context c;
    c.primitive = hit.primitive;
    c.point = hit.point;
    c.direction = path.direction;
    // POV-Ray turns the normal to face the incoming ray; a ray from inside sees the
    // interior_texture where there is one.
    c.raw_normal = hit.normal;
    const bool from_inside = glm::dot(c.raw_normal, c.direction) > 0.0;
    if (from_inside) c.raw_normal = -c.raw_normal;
    c.pnormal = c.raw_normal;
    c.depth = path.length;
    c.weight = weight;
    c.level = level;
    c.inside = &inside;
    c.travelled = travelled;
    c.counters = &counters;
    c.band = band;
    c.shadowed.resize(scene_->lights.size());
    std::vector<const Pattern*> warps;
    const Texture& texture =
        from_inside && primitive.interior_texture ? *primitive.interior_texture : primitive.texture;
    return texture_colour(texture, warps, hit.point, c);
}

glm::dvec3 Shader::texture_colour(const Texture& texture, std::vector<const Pattern*>& warps,
                                  const glm::dvec3& ipoint, Context& c) const {
    if (texture.pattern.kind == PatternKind::Solid)
        return lighted_texture(texture, warps, ipoint, c);
    // ComputeOneTextureColour for a patterned texture: the entries are lit at the warped
    // point and blended.  POV-Ray keeps every patterned texture it passes in the list of
    // warps its normals go through (never removing one).
    warps.push_back(&texture.pattern);
    const glm::dvec3 tpoint = warp_point(texture.pattern, ipoint);
    PatternContext ctx = pattern_context_;
    ctx.normal = c.pnormal;
    ctx.point = c.point;
    double value = evaluate_pattern(texture.pattern, tpoint, ctx);
    return blend_texture_map(texture.map, value, [&](const Texture& t) {
        return texture_colour(t, warps, tpoint, c);
    });
}

glm::dvec3 Shader::layer_normal(const Texture& layer, const std::vector<const Pattern*>& warps,
                                const glm::dvec3& ipoint, const glm::dvec3& raw_normal) const {
    glm::dvec3 n = raw_normal;
    if (!layer.normal) return n;
    for (const Pattern* w : warps) n = warp_normal(*w, n, false);
    perturb_normal(n, *layer.normal, ipoint, pattern_context_);
    if (layer.normal->no_bump_scale) n = glm::normalize(n);
    for (auto it = warps.rbegin(); it != warps.rend(); ++it) n = unwarp_normal(**it, n, false);
    return n;
}

glm::dvec3 Shader::lighted_texture(const Texture& texture, const std::vector<const Pattern*>& warps,
                                   const glm::dvec3& ipoint, Context& c) const {
    struct Reflection {
        double weight;
        glm::dvec3 normal;
        glm::dvec3 reflectivity;
        double exponent;
        const Finish* finish;
    };
    std::vector<Reflection> reflections;
    glm::dvec3 result(0.0);
    glm::dvec3 filter(1.0);
    double trans = 1.0;
    bool one_colour_found = false;
    glm::dvec3 top_normal = c.raw_normal;
    const Interior& interior = interior_of(c.primitive);
    const bool legacy = scene_->global.language_version < 3.7 - 1e-9;
    const std::size_t layer_count = 1 + texture.layers_below.size();
    for (std::size_t i = 0; i < layer_count && trans > adc_bailout_; ++i) {
        const Texture& layer = i == 0 ? texture : texture.layers_below[i - 1];
        const Finish& f = layer.finish;
        const glm::dvec3 normal = layer_normal(layer, warps, ipoint, c.raw_normal);
        if (i == 0) top_normal = normal;
        if (layer.normal) c.pnormal = normal;
        const double new_weight = c.weight * trans;
        PigmentColour pigment;
        PatternContext ctx = pattern_context_;
        ctx.normal = c.pnormal;
        ctx.point = c.point;
        const bool colour_found = compute_pigment(layer.pigment, ipoint, ctx, pigment);
        one_colour_found = one_colour_found || colour_found;

        // Angle-dependent reflectivity (ComputeReflectivity).
        Reflection r{new_weight, normal, glm::dvec3(0.0), to_single(f.reflection_exponent), &f};
        const double cos_angle = -glm::dot(c.direction, normal);
        const glm::dvec3 rmax = to_single(f.reflection);
        const glm::dvec3 rmin = to_single(f.reflection_min.value_or(f.reflection));
        if (f.reflection_fresnel) {
            const double ior = relative_ior(*c.inside, interior);
            const double sqx = ior * ior + cos_angle * cos_angle - 1.0;
            if (sqx > 0.0) {
                const double g = std::sqrt(sqx);
                double fr =
                    0.5 * ((g - cos_angle) * (g - cos_angle)) / ((g + cos_angle) * (g + cos_angle));
                const double a = cos_angle * (g + cos_angle) - 1.0;
                const double b = cos_angle * (g - cos_angle) + 1.0;
                fr = fr * (1.0 + (a * a) / (b * b));
                fr = std::min(1.0, std::max(0.0, fr));
                r.reflectivity = fr * rmax + (1.0 - fr) * rmin;
            } else {
                r.reflectivity = rmax;
            }
            r.weight *= max3(r.reflectivity);
        } else {
            r.weight *= std::max(max3(rmax), max3(rmin));
            const double falloff = to_single(f.reflection_falloff);
            const double frac = std::fabs(falloff - 1.0) > kEpsilon
                                    ? std::pow(1.0 - cos_angle, falloff)
                                    : 1.0 - cos_angle;
            if (std::fabs(frac) < kEpsilon) {
                r.reflectivity = rmin;
            } else if (std::fabs(frac - 1.0) < kEpsilon) {
                r.reflectivity = rmax;
            } else {
                r.reflectivity = frac * rmax + (1.0 - frac) * rmin;
            }
        }
        if (f.reflection_metallic != 0.0) {
            const double m = to_single(f.reflection_metallic);
            const double fr = metallic_fresnel(cos_angle);
            r.reflectivity *= glm::dvec3(1.0) + m * (1.0 - fr) * (pigment.rgb - glm::dvec3(1.0));
        }
        reflections.push_back(r);

        // The layer's own light, reduced by its transparency.
        const double att = legacy ? 1.0 - (pigment.filter * max3(pigment.rgb) + pigment.transmit)
                                  : pigment.opacity();
        glm::dvec3 layer_colour =
            pigment.rgb * to_single(f.ambient) * to_single(scene_->global.ambient_light) * att;
        layer_colour += pigment.rgb * to_single(f.emission) * att;
        if (f.diffuse != 0.0 || f.diffuse_back != 0.0 || f.specular != 0.0 || f.phong != 0.0) {
            diffuse_light(f, normal, pigment.rgb, att, c, layer_colour);
        }
        result += layer_colour * filter;

        if (colour_found) {
            filter *= pigment.rgb_transmit();
            if (f.conserve_energy) {
                filter *= glm::dvec3(std::min(1.0, 1.0 - r.reflectivity.x),
                                     std::min(1.0, 1.0 - r.reflectivity.y),
                                     std::min(1.0, 1.0 - r.reflectivity.z));
            }
        }
        trans = std::min(1.0, std::fabs(greyscale(filter)));
    }

    // The transmitted light (every object has an interior in POV-Ray).
    bool tir = false;
    if (trans > adc_bailout_) {
        const double w1 = max3(glm::abs(filter));
        glm::dvec3 refracted(0.0);
        tir = refract(texture.finish, interior, top_normal, c.weight * w1, c, refracted);
        glm::dvec3 att(to_single(interior.refraction));
        const bool inside_this =
            std::find(c.inside->begin(), c.inside->end(), &interior) != c.inside->end();
        if (inside_this && std::fabs(interior.fade_distance) > kEpsilon) {
            const glm::dvec3 fade = to_single(interior.fade_colour);
            const double fade_distance = to_single(interior.fade_distance);
            const double fade_power = to_single(interior.fade_power);
            if (fade_power >= 1000) {
                att *= glm::exp(-(glm::dvec3(1.0) - fade) * (c.depth / fade_distance));
            } else {
                const double k = 1.0 + std::pow(c.depth / fade_distance, fade_power);
                att *= fade + (glm::dvec3(1.0) - fade) / k;
            }
        }
        if (tir || !one_colour_found) {
            result += att * refracted;
        } else {
            result += att * refracted * filter;
        }
    }

    // The reflections, one per layer; after total internal reflection the layers with the
    // top layer's normal are already in.
    for (const Reflection& r : reflections) {
        if (tir && std::fabs(top_normal.x - r.normal.x) <= kEpsilon &&
            std::fabs(top_normal.y - r.normal.y) <= kEpsilon &&
            std::fabs(top_normal.z - r.normal.z) <= kEpsilon) {
            continue;
        }
        if (r.reflectivity == glm::dvec3(0.0)) continue;
        const glm::dvec3 seen = reflect(*r.finish, r.normal, r.weight, c);
        if (r.exponent != 1.0) {
            result +=
                r.reflectivity * glm::pow(glm::max(seen, glm::dvec3(0.0)), glm::dvec3(r.exponent));
        } else {
            result += r.reflectivity * seen;
        }
    }
    return result;
}

double Shader::relative_ior(const Interiors& inside, const Interior& interior) const {
    // ComputeRelativeIOR.
    const double ior = to_single(interior.ior);
    if (inside.empty()) return ior;  // over the atmosphere's 1
    const bool in_it = std::find(inside.begin(), inside.end(), &interior) != inside.end();
    if (in_it) {
        if (inside.size() == 1) return 1.0 / ior;
        return to_single(inside.back()->ior) / ior;
    }
    return ior / to_single(inside.back()->ior);
}

void Shader::diffuse_light(const Finish& f, const glm::dvec3& normal, const glm::dvec3& pigment,
                           double attenuation, Context& c, glm::dvec3& colour) const {
    const glm::dvec3 reye = -c.direction;
    const double diffuse = to_single(f.diffuse);
    const double diffuse_back = to_single(f.diffuse_back);
    const double brilliance = to_single(f.brilliance);
    const double phong = to_single(f.phong);
    const double phong_size = to_single(f.phong_size);
    const double specular = to_single(f.specular);
    // POV-Ray stores 1 / roughness (0 for a roughness of 0).
    const double exponent = f.roughness != 0.0 ? to_single(1.0 / f.roughness) : 0.0;
    const double metallic = to_single(f.metallic);
    const double crand = to_single(f.crand);
    const double irid = to_single(f.irid);

    auto add_light = [&](const glm::dvec3& dir, const glm::dvec3& light_colour, bool highlights,
                         bool backside, glm::dvec3& out) {
        // ComputeDiffuseColour.
        const double d = backside ? diffuse_back : diffuse;
        if (d > 0.0) {
            const double cos_in = glm::dot(normal, dir);
            double intensity =
                brilliance != 1.0 ? std::pow(std::fabs(cos_in), brilliance) : std::fabs(cos_in);
            intensity *= d * attenuation;
            if (crand > 0.0) intensity -= crand_value(c.point) * crand;
            out += intensity * pigment * light_colour;
        }
        if (highlights && !backside) {
            if (phong > 0.0) {
                // ComputePhongColour: the ray's mirror direction against the light.
                const glm::dvec3 reflected =
                    c.direction + (-2.0 * glm::dot(c.direction, normal)) * normal;
                const double cos_r = glm::dot(reflected, dir);
                if (cos_r > 0.0) {
                    const double intensity = (phong_size < 60 || cos_r > 0.0008)
                                                 ? phong * std::pow(cos_r, phong_size)
                                                 : 0.0;
                    out += highlight(intensity, light_colour, pigment, metallic, normal, dir);
                }
            }
            if (specular > 0.0) {
                // ComputeSpecularColour: Blinn's halfway vector.
                const glm::dvec3 halfway = 0.5 * (reye + dir);
                const double length = glm::length(halfway);
                if (length > 0.0) {
                    const double cos_h = glm::dot(halfway, normal) / length;
                    if (cos_h > 0.0) {
                        const double intensity = specular * std::pow(cos_h, exponent);
                        out += highlight(intensity, light_colour, pigment, metallic, normal, dir);
                    }
                }
            }
        }
    };
    auto iridescence = [&](const glm::dvec3& dir, glm::dvec3& out) {
        // ComputeIridColour.
        double thickness = to_single(f.irid_thickness);
        if (f.irid_turbulence != 0.0) {
            Turbulence t;
            t.omega = 0.5;
            t.lambda = 2.0;
            t.octaves = 5;
            double n = turbulence(c.point, t, pattern_context_.noise_generator);
            n = 2.0 * n - 1.0;
            n = 1.0 + n * to_single(f.irid_turbulence);
            thickness *= n;
        }
        const glm::dvec3 wl = scene_->global.irid_wavelength;
        const double interference =
            2.0 * 3.1415926535897932384626 * thickness *
            (std::fabs(glm::dot(normal, dir)) + std::fabs(glm::dot(normal, c.direction)));
        out *= glm::dvec3(1.0 + irid * std::cos(interference / wl.x),
                          1.0 + irid * std::cos(interference / wl.y),
                          1.0 + irid * std::cos(interference / wl.z));
    };

    for (std::size_t li = 0; li < scene_->lights.size(); ++li) {
        const PointLight& light = scene_->lights[li];
        const LightRay ray = light_ray(light, c.point);
        const bool full_area = light.area_light && light.area_illumination;
        glm::dvec3 light_colour = to_single(light.colour);
        if (!full_area) light_colour *= light_attenuation(light, c.point, ray);
        if (is_black(light_colour)) continue;  // outside a spotlight's cone
        bool backside = false;
        if (!full_area && glm::dot(normal, ray.direction) < kEpsilon) {
            if (diffuse_back == 0.0) continue;
            backside = true;
        }
        if (!light.shadowless) {
            if (!c.shadowed[li]) {
                c.shadowed[li] = shadow_filter(light, c.point, ray.direction, ray.depth,
                                               light_colour, *c.inside, *c.counters);
            }
            light_colour = *c.shadowed[li];
        }
        if (is_black(light_colour)) continue;
        if (full_area) {
            // ComputeFullAreaDiffuseLight: every point of the grid lights the surface.
            glm::dvec3 axis1, axis2;
            area_light_axes(light, c.point, true, axis1, axis2);
            const glm::dvec3 sample_colour =
                light_colour / static_cast<double>(light.size1 * light.size2);
            for (int v = 0; v < light.size2; ++v) {
                for (int u = 0; u < light.size1; ++u) {
                    const LightRay sr =
                        light_ray(light, c.point, area_light_offset(light, u, v, axis1, axis2));
                    const glm::dvec3 lc = sample_colour * light_attenuation(light, c.point, sr);
                    bool back = false;
                    if (glm::dot(normal, sr.direction) < kEpsilon) {
                        if (diffuse_back == 0.0) continue;
                        back = true;
                    }
                    glm::dvec3 sample(0.0);
                    add_light(sr.direction, lc, !light.shadowless, back, sample);
                    if (irid > 0.0) iridescence(ray.direction, sample);
                    colour += sample;
                }
            }
            continue;
        }
        glm::dvec3 contribution(0.0);
        add_light(ray.direction, light_colour, !light.shadowless, backside, contribution);
        if (irid > 0.0) iridescence(ray.direction, contribution);
        colour += contribution;
    }
}

glm::dvec3 Shader::reflect(const Finish& f, const glm::dvec3& normal, double weight,
                           Context& c) const {
    // ComputeReflection, with POV-Ray's fix for reflections that point into the surface.
    const glm::dvec3& d = c.direction;
    glm::dvec3 r = d + (-2.0 * glm::dot(d, normal)) * normal;
    double n = glm::dot(r, c.raw_normal);
    if (n < 0.0) {
        if (glm::dot(r, normal) < 0.0) {
            r = d + (-2.0 * glm::dot(d, c.raw_normal)) * c.raw_normal;
        } else {
            r += (-2.0 * n) * c.raw_normal;
        }
    }
    RayStart bounce;
    bounce.origin = c.point;
    bounce.direction = glm::normalize(r);
    // A curved propagator keeps the reflected ray's error an angle seen from the eye.
    bounce.travelled = c.travelled;
    glm::dvec3 seen = trace_ray(bounce, weight, c.level, *c.inside, false, *c.counters, c.band);
    if (f.irid > 0.0) {
        // ComputeIridColour on the reflected light, with the reflected ray as the "light".
        double thickness = to_single(f.irid_thickness);
        if (f.irid_turbulence != 0.0) {
            Turbulence t;
            t.octaves = 5;
            double nz = turbulence(c.point, t, pattern_context_.noise_generator);
            nz = 2.0 * nz - 1.0;
            thickness *= 1.0 + nz * to_single(f.irid_turbulence);
        }
        const glm::dvec3 wl = scene_->global.irid_wavelength;
        const double interference =
            2.0 * 3.1415926535897932384626 * thickness *
            (std::fabs(glm::dot(normal, bounce.direction)) + std::fabs(glm::dot(normal, d)));
        const double irid = to_single(f.irid);
        seen *= glm::dvec3(1.0 + irid * std::cos(interference / wl.x),
                           1.0 + irid * std::cos(interference / wl.y),
                           1.0 + irid * std::cos(interference / wl.z));
    }
    return seen;
}

bool Shader::refract(const Finish& f, const Interior& interior, const glm::dvec3& normal,
                     double weight, Context& c, glm::dvec3& colour) const {
    // ComputeRefraction: the pair of indices (and dispersions) depends only on the ray's
    // interior list.
    Interiors next = *c.inside;
    double ior, dispersion;
    int samples = interior.dispersion_samples;
    const double own_ior = to_single(interior.ior), own_disp = to_single(interior.dispersion);
    if (next.empty()) {
        next.push_back(&interior);
        ior = 1.0 / own_ior;
        dispersion = 1.0 / own_disp;
    } else if (&interior == next.back()) {
        next.pop_back();
        if (next.empty()) {
            ior = own_ior / 1.0;
            dispersion = own_disp / 1.0;
        } else {
            ior = own_ior / to_single(next.back()->ior);
            dispersion = own_disp / to_single(next.back()->dispersion);
            samples = std::max(samples, next.back()->dispersion_samples);
        }
    } else if (auto it = std::find(next.begin(), next.end(), &interior); it != next.end()) {
        next.erase(it);
        ior = 1.0;  // leaving an overlap: no bending
        dispersion = 1.0;
    } else {
        ior = to_single(next.back()->ior) / own_ior;
        dispersion = to_single(next.back()->dispersion) / own_disp;
        next.push_back(&interior);
    }
    if (std::fabs(ior - 1.0) < kEpsilon && std::fabs(dispersion - 1.0) < kEpsilon) {
        // The same index on both sides: the ray goes on, at the same trace level.
        RayStart ray;
        ray.origin = c.point;
        ray.travelled = c.travelled;
        ray.direction = c.direction;
        colour = trace_ray(ray, weight, c.level, next, true, *c.counters, c.band);
        return false;
    }
    if (std::fabs(dispersion - 1.0) < kEpsilon) {
        return refract_ray(f, ior, normal, weight, next, c.band, c, colour);
    }
    if (c.band)
        return refract_ray(f, dispersion_ior(*c.band, ior, dispersion), normal, weight, next,
                           c.band, c, colour);
    // A dispersive surface splits the ray into spectral bands, each refracted with its own
    // index and carrying its own hue.
    glm::dvec3 sum(0.0);
    for (int i = 0; i < samples; ++i) {
        const SpectralBand band = spectral_band(i, samples);
        glm::dvec3 part(0.0);
        refract_ray(f, dispersion_ior(band, ior, dispersion), normal, weight, next, &band, c, part);
        sum += part * spectral_hue(band);
    }
    colour = sum / static_cast<double>(samples);
    return false;
}

bool Shader::refract_ray(const Finish& f, double ior, const glm::dvec3& normal, double weight,
                         const Interiors& next, const SpectralBand* band, Context& c,
                         glm::dvec3& colour) const {
    // TraceRefractionRay, with Heckbert's method.
    double n = glm::dot(c.direction, normal);
    glm::dvec3 local = normal;
    if (n <= 0.0) {
        n = -n;
    } else {
        local = -normal;
    }
    double t = 1.0 + ior * ior * (n * n - 1.0);
    if (t < 0.0) {
        // Total internal reflection, with the ray's own interiors.
        const SpectralBand* saved = c.band;
        c.band = band;
        colour += reflect(f, normal, weight, c);
        c.band = saved;
        return true;
    }
    t = ior * n - std::sqrt(t);
    RayStart ray;
    ray.origin = c.point;
    ray.travelled = c.travelled;
    ray.direction = glm::normalize(ior * c.direction + t * local);
    colour = trace_ray(ray, weight, c.level, next, false, *c.counters, band);
    return false;
}

glm::dvec3 Shader::shadow_texture(const Texture& texture, std::vector<const Pattern*>& warps,
                                  const glm::dvec3& ipoint, const glm::dvec3& raw_normal,
                                  const glm::dvec3& direction, double caustics) const {
    if (texture.pattern.kind != PatternKind::Solid) {
        warps.push_back(&texture.pattern);
        const glm::dvec3 tpoint = warp_point(texture.pattern, ipoint);
        double value = evaluate_pattern(texture.pattern, tpoint, pattern_context_);
        return blend_texture_map(texture.map, value, [&](const Texture& t) {
            return shadow_texture(t, warps, tpoint, raw_normal, direction, caustics);
        });
    }
    glm::dvec3 filter(1.0);
    const std::size_t layer_count = 1 + texture.layers_below.size();
    for (std::size_t i = 0; i < layer_count; ++i) {
        const Texture& layer = i == 0 ? texture : texture.layers_below[i - 1];
        PigmentColour pigment;
        if (compute_pigment(layer.pigment, ipoint, pattern_context_, pigment)) {
            filter *= pigment.rgb_transmit();
        }
        // Faked caustics: the light focused where the (perturbed) surface faces it.
        if (caustics != 0.0) {
            const glm::dvec3 n = layer_normal(layer, warps, ipoint, raw_normal);
            filter *= 1.0 + std::pow(std::fabs(glm::dot(n, direction)), caustics);
        }
    }
    return filter;
}

glm::dvec3 Shader::shadow_filter(const PointLight& light, const glm::dvec3& point,
                                 const glm::dvec3& direction, double depth,
                                 const glm::dvec3& colour, const Interiors& inside,
                                 TraceCounters& counters) const {
    if (light.area_light) return area_shadow(light, point, colour, inside, counters);
    ++counters.shadow_rays;
    // With media_attenuation the fogs dim the light on its way (ComputeShadowMedia), on the
    // stretches outside solid objects.
    const bool fogged = light.media_attenuation && light.media_interaction && !scene_->fogs.empty();
    auto hollow = [](const Interiors& list) {
        return std::all_of(list.begin(), list.end(), [](const Interior* i) { return i->hollow; });
    };
    if (!any_transparent_caster_ && !fogged) {
        return accel_->any_shadow_hit(point, direction, kShadowTolerance, depth - kShadowTolerance)
                   ? glm::dvec3(0.0)
                   : colour;
    }
    // TracePointLightShadowRay: through transparent objects, each filtering the light.  The
    // shadow ray starts with the eye ray's interiors and enters and leaves the objects it
    // passes (ComputeShadowMedia), which decides where their fade applies.
    glm::dvec3 filtered = colour;
    glm::dvec3 origin = point;
    double remaining = depth;
    Interiors within = inside;
    while (true) {
        double t_min = kShadowTolerance;
        std::optional<SurfaceHit> hit;
        while (true) {
            hit = accel_->closest_hit(origin, direction, t_min, remaining - kShadowTolerance);
            if (!hit || !scene_->primitives[hit->primitive].no_shadow) break;
            t_min = std::nextafter(hit->t, kPovBoundHuge);
        }
        if (!hit) break;
        if (opaque_[hit->primitive]) return glm::dvec3(0.0);
        const Primitive& blocker = scene_->primitives[hit->primitive];
        std::vector<const Pattern*> warps;
        glm::dvec3 raw = hit->normal;
        const bool from_inside = glm::dot(raw, direction) > 0.0;
        if (from_inside) raw = -raw;
        const Texture& texture =
            from_inside && blocker.interior_texture ? *blocker.interior_texture : blocker.texture;
        const Interior& interior = interior_of(hit->primitive);
        glm::dvec3 f = shadow_texture(texture, warps, hit->point, raw, direction,
                                      to_single(interior.caustics));
        // Fade inside the blocker, over the stretch since the last surface.
        const auto it = std::find(within.begin(), within.end(), &interior);
        if (it != within.end() && interior.fade_power > 0.0 &&
            std::fabs(interior.fade_distance) > kEpsilon) {
            const glm::dvec3 fade = to_single(interior.fade_colour);
            const double fd = to_single(interior.fade_distance);
            const double fp = to_single(interior.fade_power);
            if (fp >= 1000) {
                f *= glm::exp(-(glm::dvec3(1.0) - fade) * (hit->t / fd));
            } else {
                f *= fade + (glm::dvec3(1.0) - fade) / (1.0 + std::pow(hit->t / fd, fp));
            }
        }
        filtered *= f;
        if (is_black(filtered)) return glm::dvec3(0.0);
        if (fogged && hollow(within)) {
            filtered *= fog_attenuation(scene_->fogs, origin, direction, hit->t,
                                        pattern_context_.noise_generator);
        }
        if (it != within.end()) {
            within.erase(it);
        } else {
            within.push_back(&interior);
        }
        remaining -= hit->t;
        origin = hit->point;
    }
    if (fogged && remaining > kShadowTolerance && hollow(within)) {
        filtered *= fog_attenuation(scene_->fogs, origin, direction, remaining,
                                    pattern_context_.noise_generator);
    }
    return filtered;
}

glm::dvec3 Shader::area_shadow(const PointLight& light, const glm::dvec3& point,
                               const glm::dvec3& colour, const Interiors& inside,
                               TraceCounters& counters) const {
    // TraceAreaLightShadowRay: the grid's corners, subdivided where they differ (or down to
    // every sample, POV-Ray's default adaptive level), averaged region by region.  Jitter
    // is left out: the samples are the grid points.
    glm::dvec3 axis1, axis2;
    area_light_axes(light, point, false, axis1, axis2);
    const int n1 = std::max(1, light.size1), n2 = std::max(1, light.size2);
    std::vector<std::optional<glm::dvec3>> grid(static_cast<std::size_t>(n1) * n2);
    PointLight point_light = light;
    point_light.area_light = false;
    auto sample = [&](int u, int v) -> glm::dvec3 {
        auto& cell = grid[static_cast<std::size_t>(u) * n2 + v];
        if (!cell) {
            const LightRay r =
                light_ray(light, point, area_light_offset(light, u, v, axis1, axis2));
            cell =
                shadow_filter(point_light, point, r.direction, r.depth, colour, inside, counters);
        }
        return *cell;
    };
    auto distance = [](const glm::dvec3& a, const glm::dvec3& b) {
        return std::fabs(a.x - b.x) + std::fabs(a.y - b.y) + std::fabs(a.z - b.z);
    };
    std::function<glm::dvec3(int, int, int, int, int)> subset = [&](int u1, int v1, int u2, int v2,
                                                                    int level) -> glm::dvec3 {
        glm::dvec3 s[4] = {sample(u1, v1), sample(u2, v1), sample(u1, v2), sample(u2, v2)};
        if ((u2 - u1 > 1) || (v2 - v1 > 1)) {
            if (level < light.adaptive || distance(s[0], s[1]) > 0.1 ||
                distance(s[1], s[3]) > 0.1 || distance(s[3], s[2]) > 0.1 ||
                distance(s[2], s[0]) > 0.1) {
                const int um = static_cast<int>(std::floor((u1 + u2) / 2.0));
                const int uM = static_cast<int>(std::ceil((u1 + u2) / 2.0));
                const int vm = static_cast<int>(std::floor((v1 + v2) / 2.0));
                const int vM = static_cast<int>(std::ceil((v1 + v2) / 2.0));
                s[0] = subset(u1, v1, um, vm, level + 1);
                s[1] = subset(uM, v1, u2, vm, level + 1);
                s[2] = subset(u1, vM, um, v2, level + 1);
                s[3] = subset(uM, vM, u2, v2, level + 1);
            }
        }
        return (s[0] + s[1] + s[2] + s[3]) * 0.25;
    };
    return subset(0, 0, n1 - 1, n2 - 1, 0);
}

}  // namespace mirage
