#include "atmosphere/general_profile.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "util/check.h"
#include "util/format.h"

namespace mirage {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double std_normal_cdf(double t) { return 0.5 * std::erfc(-t / std::sqrt(2.0)); }
double std_normal_pdf(double t) { return std::exp(-0.5 * t * t) / std::sqrt(2.0 * M_PI); }

// The inversion's ramp R(y) and its slope (see the header).
double ramp(const Inversion& v, double y) {
    const double w = v.top_m - v.bottom_m;
    if (v.smoothing_m == 0.0) return std::clamp((y - v.bottom_m) / w, 0.0, 1.0);
    const double s = v.smoothing_m;
    auto F = [&](double x) { return x * std_normal_cdf(x / s) + s * std_normal_pdf(x / s); };
    return (F(y - v.bottom_m) - F(y - v.top_m)) / w;
}

double ramp_slope(const Inversion& v, double y, int side) {
    const double w = v.top_m - v.bottom_m;
    if (v.smoothing_m == 0.0) {
        const bool inside =
            side > 0 ? (y >= v.bottom_m && y < v.top_m) : (y > v.bottom_m && y <= v.top_m);
        return inside ? 1.0 / w : 0.0;
    }
    const double s = v.smoothing_m;
    return (std_normal_cdf((y - v.bottom_m) / s) - std_normal_cdf((y - v.top_m) / s)) / w;
}

// Gauss-Legendre, 8 points on [-1, 1].
constexpr double kGLx[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                            0.9602898564975363};
constexpr double kGLw[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                            0.1012285362903763};

template <class F>
double gauss8(const F& f, double a, double b) {
    const double c = 0.5 * (a + b), h = 0.5 * (b - a);
    double s = 0.0;
    for (int k = 0; k < 4; ++k) s += kGLw[k] * (f(c - h * kGLx[k]) + f(c + h * kGLx[k]));
    return s * h;
}

// int_0^y dy' / T(y'), tabulated on cells that 8-point Gauss-Legendre integrates to rounding,
// split at the temperature's breakpoints; T(top) above the top.
class InverseTemperatureIntegral {
  public:
    InverseTemperatureIntegral(std::function<double(double)> T, std::vector<double> edges)
        : T_(std::move(T)), top_(edges.back()) {
        auto inv = [&](double y) { return 1.0 / T_(y); };
        double cum = 0.0;
        for (size_t k = 0; k + 1 < edges.size(); ++k) {
            std::vector<std::pair<double, double>> stack{{edges[k], edges[k + 1]}};
            while (!stack.empty()) {
                auto [a, b] = stack.back();
                stack.pop_back();
                const double m = 0.5 * (a + b);
                const double whole = gauss8(inv, a, b);
                const double halves = gauss8(inv, a, m) + gauss8(inv, m, b);
                if (std::fabs(whole - halves) <= 1e-15 * std::fabs(halves) || b - a < 1e-9) {
                    starts_.push_back(a);
                    cum_.push_back(cum);
                    cum += halves;
                    continue;
                }
                stack.push_back({m, b});
                stack.push_back({a, m});
            }
        }
        starts_.push_back(top_);
        cum_.push_back(cum);
        inv_top_ = 1.0 / T_(top_);
    }

    double operator()(double y) const {
        if (y <= 0.0) return 0.0;
        if (y >= top_) return cum_.back() + (y - top_) * inv_top_;
        const size_t j = std::upper_bound(starts_.begin(), starts_.end(), y) - starts_.begin() - 1;
        return cum_[j] + gauss8([&](double s) { return 1.0 / T_(s); }, starts_[j], y);
    }

  private:
    std::function<double(double)> T_;
    double top_;
    double inv_top_ = 0.0;
    std::vector<double> starts_, cum_;
};

std::vector<double> sorted_edges(std::vector<double> breakpoints, double top) {
    std::vector<double> e{0.0};
    for (double b : breakpoints)
        if (b > 0.0 && b < top) e.push_back(b);
    e.push_back(top);
    std::sort(e.begin(), e.end());
    e.erase(std::unique(e.begin(), e.end()), e.end());
    return e;
}

Status validate_column(const AirColumn& c) {
    if (!(std::isfinite(c.ground_temperature_k) && c.ground_temperature_k > 0.0))
        return make_error("air temperature " + shortest(c.ground_temperature_k - 273.15) +
                          " degC must be finite and above absolute zero");
    if (!std::isfinite(c.lapse_k_per_m))
        return make_error("lapse rate " + shortest(1000.0 * c.lapse_k_per_m) +
                          " K/km must be finite");
    for (const auto& l : c.layers)
        if (auto s = check_surface_layer(l); !s) return make_error("surface layer: " + s.message());
    for (const auto& v : c.inversions)
        if (auto s = check_inversion(v); !s) return make_error("inversion: " + s.message());
    return Ok{};
}

// Height above which the column's features have died away (for the default top).
double column_features_top(const AirColumn& c) {
    double h = 0.0;
    for (const auto& l : c.layers) h = std::max(h, 40.0 * l.scale_m);
    for (const auto& v : c.inversions) h = std::max(h, v.top_m + 8.0 * v.smoothing_m);
    return h;
}

}  // namespace

Status check_surface_layer(const SurfaceLayer& l) {
    const double dt = kMaxFormDeltaK, h = kMaxFormHeightM;
    if (!(std::abs(l.delta_k) <= dt))
        return make_error("temperature excess " + shortest(l.delta_k) + " K must be from " +
                          shortest(-dt) + " to " + shortest(dt) + " K");
    if (!(l.scale_m >= kMinScaleHeightM && l.scale_m <= h))
        return make_error("scale height " + shortest(l.scale_m) + " m must be from " +
                          shortest(kMinScaleHeightM) + " to " + shortest(h) + " m");
    return Ok{};
}

Status check_inversion(const Inversion& v) {
    const double dt = kMaxFormDeltaK, h = kMaxFormHeightM;
    if (!(v.bottom_m >= 0.0 && v.bottom_m < h))
        return make_error("bottom " + shortest(v.bottom_m) + " m must be >= 0 and below " +
                          shortest(h) + " m");
    if (!(v.top_m > v.bottom_m && v.top_m <= h))
        return make_error("top " + shortest(v.top_m) + " m must lie above its bottom " +
                          shortest(v.bottom_m) + " m and at most " + shortest(h) + " m");
    if (!(std::abs(v.delta_k) <= dt))
        return make_error("temperature rise " + shortest(v.delta_k) + " K must be from " +
                          shortest(-dt) + " to " + shortest(dt) + " K");
    if (!(v.smoothing_m >= 0.0 && v.smoothing_m <= kMaxSmoothingM))
        return make_error("smoothing " + shortest(v.smoothing_m) + " m must be from 0 to " +
                          shortest(kMaxSmoothingM) + " m");
    return Ok{};
}

double column_temperature(const AirColumn& c, double y) {
    double T = c.ground_temperature_k - c.lapse_k_per_m * y;
    for (const auto& l : c.layers) T += l.delta_k * std::exp(-y / l.scale_m);
    for (const auto& v : c.inversions) T += v.delta_k * ramp(v, y);
    return T;
}

double column_temperature_slope(const AirColumn& c, double y, int side) {
    double s = -c.lapse_k_per_m;
    for (const auto& l : c.layers) s -= l.delta_k / l.scale_m * std::exp(-y / l.scale_m);
    for (const auto& v : c.inversions) s += v.delta_k * ramp_slope(v, y, side);
    return s;
}

double flattened_height(double h, double R) { return R > 0.0 ? R * std::log1p(h / R) : h; }

double height_above_sphere(double y, double R) { return R > 0.0 ? R * std::expm1(y / R) : y; }

ProfileFunction flatten(const ProfileFunction& f, double R, double extension_m) {
    MIRAGE_CHECK(R > 0.0);
    ProfileFunction g;
    const double top = f.top;
    const double n0_sq = f.n0_sq;
    auto ex = f.excess;
    auto sl = f.excess_slope;
    g.n0_sq = n0_sq;
    g.earth_radius = R;
    g.top = flattened_height(top + extension_m, R);
    g.breakpoints.push_back(flattened_height(top, R));
    for (double b : f.breakpoints) g.breakpoints.push_back(flattened_height(b, R));
    // n*^2 - n0^2 = (n0^2 + e(h)) exp(2y/R) - n0^2 = e(h) exp(2y/R) + n0^2 expm1(2y/R).
    g.excess = [=](double y) {
        const double h = std::min(height_above_sphere(y, R), top);
        return ex(h) * std::exp(2.0 * y / R) + n0_sq * std::expm1(2.0 * y / R);
    };
    g.excess_slope = [=](double y, int side) {
        const double h_true = height_above_sphere(y, R);
        const double h = std::min(h_true, top);
        const bool above = side > 0 ? h_true >= top : h_true > top;
        const double dh_dy = std::exp(y / R);
        const double e2 = std::exp(2.0 * y / R);
        const double de = above ? 0.0 : sl(h, side) * dh_dy;
        return de * e2 + (n0_sq + ex(h)) * (2.0 / R) * e2;
    };
    return g;
}

namespace {

Status validate_air_spec(const AirSpec& spec) {
    if (auto s = validate(spec.index); !s) return s;
    if (!(std::isfinite(spec.ground_pressure_pa) && spec.ground_pressure_pa > 0.0))
        return make_error("pressure " + shortest(spec.ground_pressure_pa / 100.0) +
                          " hPa must be finite and > 0");
    if (!(spec.relative_humidity >= 0.0 && spec.relative_humidity <= 1.0))
        return make_error("relative humidity " + shortest(100.0 * spec.relative_humidity) +
                          " % must lie in [0, 100]");
    if (!(std::isfinite(spec.top_m) && spec.top_m >= 0.0))
        return make_error("profile top " + shortest(spec.top_m) + " m must be finite and > 0");
    if (!(std::isfinite(spec.earth_radius_m) && spec.earth_radius_m >= 0.0))
        return make_error("Earth radius " + shortest(spec.earth_radius_m) +
                          " m must be finite and >= 0 (0: flat)");
    return Ok{};
}

/// An exponential profile's closed form as a model of the air.
Result<AirModel> exponential_air_model(const Profile& p, double top_m) {
    if (auto s = validate(p); !s) return s.error();
    AirModel model;
    ProfileFunction& f = model.physical;
    f.earth_radius = 0.0;
    const int sign = profile_sign(p);
    const double a = sign * p.eta1 * p.eta1;
    f.n0_sq = p.eta0 * p.eta0;
    f.excess = [=](double y) { return a * -std::expm1(-p.alpha * y); };
    f.excess_slope = [=](double y, int) { return a * p.alpha * std::exp(-p.alpha * y); };
    // Above the top n^2 changes by less than 1e-17 more.
    const double natural =
        p.eta1 > 0.0 ? std::max(1.0, std::log(std::fabs(a) / 1e-17) / p.alpha) : 1.0;
    f.top = top_m > 0.0 ? top_m : natural;
    model.refractivity = [=](double y) {
        return std::sqrt(f.n0_sq + a * -std::expm1(-p.alpha * y)) - 1.0;
    };
    model.top = f.top;
    return model;
}

/// A sounding of the index itself: its shape-preserving spline is the profile.
AirModel index_sounding_model(const Sounding& s, double top) {
    AirModel model;
    ProfileFunction& f = model.physical;
    f.earth_radius = 0.0;
    const double n0 = s.index.front();
    std::vector<double> e;
    for (double n : s.index) e.push_back((n - n0) * (n + n0));
    auto sp = std::make_shared<QuadraticSpline>(make_shape_preserving_spline(s.height_m, e));
    f.n0_sq = n0 * n0;
    f.excess = [sp](double y) { return sp->value(y); };
    // The spline is C^1: one slope at every knot.
    f.excess_slope = [sp](double y, int) { return sp->slope(y); };
    f.breakpoints = sp->knots;
    f.top = top;
    model.refractivity = [sp, n0](double y) { return std::sqrt(n0 * n0 + sp->value(y)) - 1.0; };
    model.top = top;
    return model;
}

/// The air's state against height, from a described column or a sounding: temperature (with
/// its one-sided slopes), the log of the pressure where given, relative humidity where given.
struct AirState {
    std::function<double(double)> T, Tslope_r, Tslope_l, lnp, lnp_slope, rh, rh_slope;
    std::vector<double> breaks;  // heights where the smoothness may change
    double top = 0.0;
    bool have_pressure = false;
};

Result<AirState> column_state(const AirColumn& c, double top) {
    if (auto s = validate_column(c); !s) return s.error();
    AirState a;
    a.top = top == 0.0 ? std::max(1000.0, 2.0 * column_features_top(c)) : top;
    for (const auto& v : c.inversions) {
        if (v.top_m >= a.top)
            return make_error("inversion top " + shortest(v.top_m) +
                              " m must lie below the profile's top " + shortest(a.top) + " m");
        if (v.smoothing_m == 0.0) {
            a.breaks.push_back(v.bottom_m);
            a.breaks.push_back(v.top_m);
        }
    }
    a.T = [c](double y) { return column_temperature(c, y); };
    a.Tslope_r = [c](double y) { return column_temperature_slope(c, y, +1); };
    a.Tslope_l = [c](double y) { return column_temperature_slope(c, y, -1); };
    return a;
}

/// A sounding of temperature, and of pressure and humidity where it has them: splines.
AirState sounding_state(const Sounding& s, double top) {
    AirState a;
    a.top = top;
    auto spT = std::make_shared<QuadraticSpline>(
        make_shape_preserving_spline(s.height_m, s.temperature_k));
    a.T = [spT](double y) { return spT->value(y); };
    a.Tslope_r = [spT](double y) { return spT->slope(y); };
    a.Tslope_l = a.Tslope_r;
    a.breaks = spT->knots;
    if (!s.pressure_pa.empty()) {
        a.have_pressure = true;
        std::vector<double> lp;
        for (double p : s.pressure_pa) lp.push_back(std::log(p));
        auto spP = std::make_shared<QuadraticSpline>(make_shape_preserving_spline(s.height_m, lp));
        a.lnp = [spP](double y) { return spP->value(y); };
        a.lnp_slope = [spP](double y) { return spP->slope(y); };
    }
    if (!s.relative_humidity.empty()) {
        auto spH = std::make_shared<QuadraticSpline>(
            make_shape_preserving_spline(s.height_m, s.relative_humidity));
        a.rh = [spH](double y) { return std::clamp(spH->value(y), 0.0, 1.0); };
        a.rh_slope = [spH](double y) { return spH->slope(y); };
    }
    return a;
}

/// The temperature must stay physical over the whole profile.
Status check_temperature(const AirState& a) {
    const auto& T = a.T;
    const auto edges = sorted_edges(a.breaks, a.top);
    constexpr int kProbes = 4000;
    for (int k = 0; k <= kProbes; ++k) {
        const double y = a.top * k / kProbes;
        const double t = T(y);
        if (!(std::isfinite(t) && t > 0.0))
            return make_error("the temperature falls to " + shortest(t - 273.15) + " degC at " +
                              sig(y, 6) + " m: the profile is not physical");
    }
    for (double y : edges)
        if (!(T(y) > 0.0))
            return make_error("the temperature falls to " + shortest(T(y) - 273.15) + " degC at " +
                              sig(y, 6) + " m: the profile is not physical");
    return Ok{};
}

/// Pressure and its slope: given, hydrostatic or constant.
void pressure_of(const AirState& a, const AirSpec& spec, std::function<double(double)>& p,
                 std::function<double(double)>& p_slope) {
    const auto& T = a.T;
    if (a.have_pressure) {
        const auto& lnp = a.lnp;
        const auto& lnp_slope = a.lnp_slope;
        p = [lnp](double y) { return std::exp(lnp(y)); };
        p_slope = [lnp, lnp_slope](double y) { return std::exp(lnp(y)) * lnp_slope(y); };
    } else if (spec.hydrostatic) {
        auto I = std::make_shared<InverseTemperatureIntegral>(T, sorted_edges(a.breaks, a.top));
        const double p0 = spec.ground_pressure_pa;
        p = [I, p0](double y) { return p0 * std::exp(-kHydrostaticScale * (*I)(y)); };
        p_slope = [I, p0, T](double y) {
            return -p0 * std::exp(-kHydrostaticScale * (*I)(y)) * kHydrostaticScale / T(y);
        };
    } else {
        const double p0 = spec.ground_pressure_pa;
        p = [p0](double) { return p0; };
        p_slope = [](double) { return 0.0; };
    }
}

/// The index of the air's state by the spec's formula, and its profile.
AirModel air_state_model(const AirState& a, const AirSpec& spec) {
    AirModel model;
    ProfileFunction& f = model.physical;
    f.earth_radius = 0.0;
    const auto T = a.T, Tslope_r = a.Tslope_r, Tslope_l = a.Tslope_l, rh = a.rh,
               rh_slope = a.rh_slope;
    const double top = a.top;
    std::function<double(double)> p, p_slope;
    pressure_of(a, spec, p, p_slope);
    const IndexSettings index = spec.index;
    auto m_of = [index](double t, double pr, double h) { return refractivity(index, {t, pr, h}); };
    auto m_at = [=](double y) { return m_of(T(y), p(y), rh(y)); };
    const double m0 = m_at(0.0);
    f.n0_sq = (1.0 + m0) * (1.0 + m0);
    f.top = top;
    f.breakpoints = a.breaks;
    f.excess = [=](double y) {
        const double m = m_at(std::min(y, top));
        return (m - m0) * (2.0 + m + m0);
    };
    f.excess_slope = [=](double y, int side) {
        if (side > 0 ? y >= top : y > top) return 0.0;
        const double t = T(y), pr = p(y), h = rh(y);
        const double m = m_of(t, pr, h);
        const double dT = side > 0 ? Tslope_r(y) : Tslope_l(y);
        const double dp = p_slope(y);
        double dm;
        if (index.formula == IndexFormula::GladstoneDale) {
            dm = m * (dp / pr - dT / t);
        } else {
            const double dt_step = 1e-3, dp_step = 1e-4 * pr, dh_step = 1e-4;
            const double m_T =
                (m_of(t + dt_step, pr, h) - m_of(t - dt_step, pr, h)) / (2.0 * dt_step);
            const double m_p =
                (m_of(t, pr + dp_step, h) - m_of(t, pr - dp_step, h)) / (2.0 * dp_step);
            const double hl = std::max(0.0, h - dh_step), hh = std::min(1.0, h + dh_step);
            const double m_h = hh > hl ? (m_of(t, pr, hh) - m_of(t, pr, hl)) / (hh - hl) : 0.0;
            dm = m_T * dT + m_p * dp + m_h * rh_slope(y);
        }
        return 2.0 * (1.0 + m) * dm;
    };
    model.temperature_k = [T, top](double y) { return T(std::min(y, top)); };
    model.pressure_pa = [p, top](double y) { return p(std::min(y, top)); };
    model.refractivity = [m_at, top](double y) { return m_at(std::min(y, top)); };
    model.top = top;
    return model;
}

Result<AirModel> make_described_air_model(const AirSpec& spec) {
    if (auto s = validate_air_spec(spec); !s) return s.error();
    if (spec.source == AirSpec::Source::Exponential)
        return exponential_air_model(spec.exponential, spec.top_m);
    Result<AirState> state = AirState{};
    if (spec.source == AirSpec::Source::Column) {
        state = column_state(spec.column, spec.top_m);
    } else {
        const Sounding& s = spec.sounding;
        if (s.height_m.size() < 2)
            return make_error(s.source + ": a sounding needs at least 2 rows");
        const double last = s.height_m.back();
        const double top = spec.top_m == 0.0 ? last : spec.top_m;
        if (top != last)
            return make_error("profile top " + shortest(top) +
                              " m: a sounding's profile ends at its last row, " + shortest(last) +
                              " m");
        if (s.kind == Sounding::Kind::Index) return index_sounding_model(s, top);
        state = sounding_state(s, top);
    }
    if (!state) return state.error();
    if (!state->rh) {
        const double h = spec.relative_humidity;
        state->rh = [h](double) { return h; };
        state->rh_slope = [](double) { return 0.0; };
    }
    if (auto s = check_temperature(*state); !s) return s.error();
    return air_state_model(*state, spec);
}

}  // namespace

Result<AirModel> make_air_model(const AirSpec& spec) {
    auto model = make_described_air_model(spec);
    if (!model || spec.exaggeration == 1.0) return model;
    const double k = spec.exaggeration;
    if (!(k > 0.0 && std::isfinite(k)))
        return make_error("exaggeration " + shortest(k) + " must be a finite number > 0");
    ProfileFunction& f = model->physical;
    const double n0_sq = f.n0_sq;
    f.excess = [k, e = f.excess](double y) { return k * e(y); };
    f.excess_slope = [k, e = f.excess_slope](double y, int side) { return k * e(y, side); };
    model->refractivity = [k, n0_sq, m = model->refractivity](double y) {
        const double n = 1.0 + m(y);
        return std::sqrt(n0_sq + k * (n * n - n0_sq)) - 1.0;
    };
    return model;
}

std::function<double(double)> upper_air_refractivity(const AirSpec& spec, double top_m,
                                                     double temperature_top_k,
                                                     double pressure_top_pa,
                                                     double refractivity_top) {
    // The layers above the top: bottom (m), lapse (K per m), temperature and pressure there.
    struct Layer {
        double bottom, lapse, temperature, pressure;
    };
    constexpr double kTropopauseK = 216.65;
    std::vector<Layer> layers{{top_m, temperature_top_k > kTropopauseK ? -0.0065 : 0.0,
                               temperature_top_k, pressure_top_pa}};
    const double tropopause = top_m + std::max(0.0, temperature_top_k - kTropopauseK) / 0.0065;
    const std::pair<double, double> bounds[] = {{tropopause, 0.0}, {20000.0, 0.001},
                                                {32000.0, 0.0028}};
    auto temperature_at = [](const Layer& l, double h) {
        return l.temperature + l.lapse * (h - l.bottom);
    };
    auto pressure_at = [&temperature_at](const Layer& l, double h) {
        return l.lapse == 0.0 ? l.pressure * std::exp(-kHydrostaticScale * (h - l.bottom) /
                                                      l.temperature)
                              : l.pressure * std::pow(l.temperature / temperature_at(l, h),
                                                      kHydrostaticScale / l.lapse);
    };
    for (const auto& [bottom, lapse] : bounds) {
        const Layer& below = layers.back();
        if (bottom <= below.bottom) {
            if (bottom > top_m || lapse == 0.0) continue;
            layers.back().lapse = lapse;  // the top lies in this layer already
            continue;
        }
        layers.push_back({bottom, lapse, temperature_at(below, bottom), pressure_at(below, bottom)});
    }
    IndexSettings index = spec.index;
    auto dry = [index](double t, double p) {
        return refractivity(index, mirage::AirState{t, p, 0.0});
    };
    const double scale = refractivity_top / dry(temperature_top_k, pressure_top_pa);
    return [layers, dry, scale, temperature_at, pressure_at](double h) {
        std::size_t k = 0;
        while (k + 1 < layers.size() && h >= layers[k + 1].bottom) ++k;
        const Layer& l = layers[k];
        return scale * dry(temperature_at(l, h), pressure_at(l, h));
    };
}

namespace {

// The described air continued above its top by the upper air, to kUpperAirTopM.
Result<ProfileFunction> with_upper_air(const AirModel& model, const AirSpec& spec) {
    if (!model.temperature_k || !model.pressure_pa)
        return make_error("the upper air continues the air's temperature and pressure, which "
                          "an exponential profile or a sounding of n does not give");
    const double top = model.top;
    if (!(top < kUpperAirTopM))
        return make_error("profile top " + shortest(top) + " m must lie below the upper air's " +
                          shortest(kUpperAirTopM) + " m");
    const ProfileFunction& f = model.physical;
    const double m_top = model.refractivity(top);
    auto m = upper_air_refractivity(spec, top, model.temperature_k(top), model.pressure_pa(top),
                                    m_top);
    const double n0_sq = f.n0_sq, k = spec.exaggeration;
    // Continuous at the top: the excess the described air ends with, and the upper air's from
    // the same refractivity.
    const double n_top = 1.0 + m_top;
    const double offset = f.excess(top) - k * (n_top * n_top - n0_sq);
    ProfileFunction g = f;
    auto upper = [m, n0_sq, k, offset](double h) {
        const double n = 1.0 + m(h);
        return offset + k * (n * n - n0_sq);
    };
    g.excess = [lower = f.excess, upper, top](double h) {
        return h <= top ? lower(h) : upper(h);
    };
    g.excess_slope = [lower = f.excess_slope, upper, top](double h, int side) {
        if (side > 0 ? h < top : h <= top) return lower(h, side);
        // The upper air is smooth within its layers, whose bounds are breakpoints: a
        // one-sided difference of a centimetre on the side asked.
        constexpr double d = 0.01;
        return side > 0 ? (upper(h + d) - upper(h)) / d : (upper(h) - upper(h - d)) / d;
    };
    g.breakpoints.push_back(top);
    const double tropopause = top + std::max(0.0, model.temperature_k(top) - 216.65) / 0.0065;
    for (double b : {tropopause, 20000.0, 32000.0})
        if (b > top && b < kUpperAirTopM) g.breakpoints.push_back(b);
    std::sort(g.breakpoints.begin(), g.breakpoints.end());
    g.breakpoints.erase(std::unique(g.breakpoints.begin(), g.breakpoints.end()),
                        g.breakpoints.end());
    g.top = kUpperAirTopM;
    return g;
}

}  // namespace

Result<std::shared_ptr<const QuadraticProfile>> fit_air(const AirSpec& spec,
                                                        const FitSettings& settings,
                                                        FitReport* report) {
    auto model = make_air_model(spec);
    if (!model) return model.error();
    const double R = spec.earth_radius_m;
    if (spec.source == AirSpec::Source::Sounding && spec.sounding.kind == Sounding::Kind::Index &&
        R == 0.0) {
        // The spline of n^2 is the model itself.
        const auto& s = spec.sounding;
        const double n0 = s.index.front();
        std::vector<double> e;
        for (double n : s.index) e.push_back(spec.exaggeration * (n - n0) * (n + n0));
        const QuadraticSpline sp = make_shape_preserving_spline(s.height_m, e);
        auto q = QuadraticProfile::make(sp.knots, sp.slopes, sp.curvatures, n0 * n0, 0.0);
        if (!q) return q.error();
        if (report) {
            report->pieces = q->piece_count();
            report->max_error_n = 0.0;
            report->worst_height = 0.0;
        }
        return std::make_shared<const QuadraticProfile>(std::move(*q));
    }
    const bool upper = spec.upper_air && R > 0.0;
    ProfileFunction physical = model->physical;
    if (upper) {
        auto g = with_upper_air(*model, spec);
        if (!g) return g.error();
        physical = std::move(*g);
    }
    // Above the upper air (n - 1 about 3e-7) a kilometre of homogeneous air, as
    // astronomical_refraction.h's model has it; the sky is seen where rays leave it.
    ProfileFunction f =
        R > 0.0 ? flatten(physical, R, upper ? 1000.0 : spec.earth_extension_m) : physical;
    FitReport own_report;
    if (!report) report = &own_report;
    auto q = fit_quadratic_profile(f, settings, report);
    if (q) q->set_sky_at_top(upper);
    if (!q) {
        const Sounding& s = spec.sounding;
        if (spec.source != AirSpec::Source::Sounding || s.line.size() != s.height_m.size() ||
            !std::isfinite(report->failure_height))
            return q.error();
        // The sounding's rows around the height where the fit stopped.
        const double h = height_above_sphere(report->failure_height, R);
        const auto above = std::upper_bound(s.height_m.begin(), s.height_m.end(), h);
        const size_t k = std::clamp<size_t>(above - s.height_m.begin(), 1, s.height_m.size() - 1);
        return make_error(s.source + ":" + std::to_string(s.line[k - 1]) + ": the rows at " +
                          shortest(s.height_m[k - 1]) + " m (line " +
                          std::to_string(s.line[k - 1]) + ") and " + shortest(s.height_m[k]) +
                          " m (line " + std::to_string(s.line[k]) + "): " + q.message());
    }
    return std::make_shared<const QuadraticProfile>(std::move(*q));
}

}  // namespace mirage
