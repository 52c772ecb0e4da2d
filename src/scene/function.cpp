// Evaluating POV-Ray user functions (see function.h); built-ins after POV-Ray's fnsyntax.cpp
// and fnpovfpu.cpp, internal functions after its fnintern.cpp.
#include "scene/function.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "scene/scene.h"

namespace mirage {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2.0 * kPi;

struct Builtin {
    const char* name;
    int arity;  // -1: any number (min, max)
};
constexpr Builtin kBuiltins[] = {
    {"abs", 1},   {"acos", 1},  {"acosh", 1}, {"asin", 1},    {"asinh", 1},   {"atan", 1},
    {"atan2", 2}, {"atanh", 1}, {"ceil", 1},  {"cos", 1},     {"cosh", 1},    {"degrees", 1},
    {"exp", 1},   {"floor", 1}, {"int", 1},   {"ln", 1},      {"log", 1},     {"max", -1},
    {"min", -1},  {"mod", 2},   {"pow", 2},   {"radians", 1}, {"select", -1}, {"sin", 1},
    {"sinh", 1},  {"sqrt", 1},  {"tan", 1},   {"tanh", 1},    {"div", 2},     {"sqr", 1},
};

// functions.inc's internal functions (POV-Ray's POVFPU_TrapTable): number, name, parameters
// after x, y and z, and whether mirage evaluates it.
struct Internal {
    int number;
    const char* name;
    int extra;
    bool known;
};
constexpr Internal kInternals[] = {
    {0, "f_algbr_cyl1", 5, true},
    {1, "f_algbr_cyl2", 5, false},
    {2, "f_algbr_cyl3", 5, false},
    {3, "f_algbr_cyl4", 5, false},
    {4, "f_bicorn", 2, false},
    {5, "f_bifolia", 2, false},
    {6, "f_blob", 5, false},
    {7, "f_blob2", 4, false},
    {8, "f_boy_surface", 2, false},
    {9, "f_comma", 1, false},
    {10, "f_cross_ellipsoids", 4, false},
    {11, "f_crossed_trough", 1, false},
    {12, "f_cubic_saddle", 1, false},
    {13, "f_cushion", 1, false},
    {14, "f_devils_curve", 1, false},
    {15, "f_devils_curve_2d", 6, false},
    {16, "f_dupin_cyclid", 6, false},
    {17, "f_ellipsoid", 3, true},
    {18, "f_enneper", 1, false},
    {19, "f_flange_cover", 4, false},
    {20, "f_folium_surface", 3, false},
    {21, "f_folium_surface_2d", 6, false},
    {22, "f_glob", 1, false},
    {23, "f_heart", 1, false},
    {24, "f_helical_torus", 10, false},
    {25, "f_helix1", 7, true},
    {26, "f_helix2", 7, false},
    {27, "f_hex_x", 1, false},
    {28, "f_hex_y", 1, false},
    {29, "f_hetero_mf", 6, false},
    {30, "f_hunt_surface", 1, false},
    {31, "f_hyperbolic_torus", 3, false},
    {32, "f_isect_ellipsoids", 4, false},
    {33, "f_kampyle_of_eudoxus", 3, false},
    {34, "f_kampyle_of_eudoxus_2d", 6, false},
    {35, "f_klein_bottle", 1, false},
    {36, "f_kummer_surface_v1", 1, false},
    {37, "f_kummer_surface_v2", 4, false},
    {38, "f_lemniscate_of_gerono", 1, false},
    {39, "f_lemniscate_of_gerono_2d", 6, false},
    {40, "f_mesh1", 5, false},
    {41, "f_mitre", 1, false},
    {42, "f_nodal_cubic", 1, false},
    {43, "f_odd", 1, false},
    {44, "f_ovals_of_cassini", 4, false},
    {45, "f_paraboloid", 1, true},
    {46, "f_parabolic_torus", 3, false},
    {47, "f_ph", 0, true},
    {48, "f_pillow", 1, false},
    {49, "f_piriform", 1, false},
    {50, "f_piriform_2d", 7, false},
    {51, "f_poly4", 5, false},
    {52, "f_polytubes", 6, false},
    {53, "f_quantum", 1, false},
    {54, "f_quartic_paraboloid", 1, false},
    {55, "f_quartic_saddle", 1, false},
    {56, "f_quartic_cylinder", 3, false},
    {57, "f_r", 0, true},
    {58, "f_ridge", 6, false},
    {59, "f_ridged_mf", 6, false},
    {60, "f_rounded_box", 4, true},
    {61, "f_sphere", 1, true},
    {62, "f_spikes", 5, false},
    {63, "f_spikes_2d", 4, false},
    {64, "f_spiral", 6, false},
    {65, "f_steiners_roman", 1, false},
    {66, "f_strophoid", 4, false},
    {67, "f_strophoid_2d", 7, false},
    {68, "f_superellipsoid", 2, true},
    {69, "f_th", 0, true},
    {70, "f_torus", 2, true},
    {71, "f_torus2", 3, true},
    {72, "f_torus_gumdrop", 1, false},
    {73, "f_umbrella", 1, false},
    {74, "f_witch_of_agnesi", 2, false},
    {75, "f_witch_of_agnesi_2d", 6, false},
    {76, "f_noise3d", 0, true},
    {77, "f_pattern", 0, false},
    {78, "f_noise_generator", 1, true},
};

// fnintern.cpp's ROT2D(p, d, ang) for the algebraic cylinders: with p > 0 the curve in the
// x-y plane is turned into a surface of revolution about y (x becomes the distance from the
// axis less d), turned by ang degrees in that plane; x2 and y2 are the squares after it.
void rot2d(double& X, double& Y, double Z, double& x2, double& y2, double p, double d,
           double ang_deg) {
    if (!(p > 0.0)) return;
    x2 = std::sqrt(x2 + Z * Z) - d;
    const double th = ang_deg * kPi / 180.0;
    if (th != 0.0) {
        X = x2 * std::cos(th) - Y * std::sin(th);
        Y = x2 * std::sin(th) + Y * std::cos(th);
    } else {
        X = x2;
    }
    x2 = X * X;
    y2 = Y * Y;
}

double internal_value(int n, const double* p, const FunctionEnv* env) {
    // p[0..2] = x, y, z; p[3 + i] = PARAM(i).
    const double X = p[0], Y = p[1], Z = p[2];
    const double* P = p + 3;
    switch (n) {
        case 0: {  // f_algbr_cyl1
            double x = X, y = Y, x2 = X * X, y2 = Y * Y;
            rot2d(x, y, Z, x2, y2, P[2], P[3], P[4]);
            x = std::abs(x);
            const double r = -(x2 * x - x2 + y2);
            return -std::min(P[1], std::max(P[0] * r, -P[1]));
        }
        case 25: {  // f_helix1
            double x = X, z = Z;
            const double r = std::sqrt(x * x + z * z);
            if (x == 0.0 && z == 0.0) x = 0.000001;
            double th = std::atan2(z, x);
            th = std::fmod(th * P[0] + Y * P[1] * P[0], kTwoPi);
            if (th < 0.0) th += kTwoPi;
            z = (th - kPi) / P[4] / (P[1] * P[0]);
            x = r - P[3];
            double r2;
            if (P[5] == 1.0) {
                r2 = std::sqrt(x * x + z * z);
            } else {
                if (P[6] != 0.0) {
                    const double c = std::cos(P[6] * kPi / 180.0), s = std::sin(P[6] * kPi / 180.0);
                    const double xr = x * c - z * s;
                    z = x * s + z * c;
                    x = xr;
                }
                if (P[5] != 0.0) {
                    const double e = 2.0 / P[5];
                    r2 = std::pow(std::pow(std::abs(x), e) + std::pow(std::abs(z), e), P[5] * .5);
                } else {
                    r2 = std::max(std::abs(x), std::abs(z));
                }
            }
            return -P[2] + std::min(P[3] + r, r2);
        }
        case 76:
        case 78:
            if (!env || !env->noise) return 0.0;
            return env->noise(X, Y, Z,
                              n == 76 ? env->noise_generator : (static_cast<int>(P[0]) & 0x03));
        case 17:
            return std::sqrt(X * X * P[0] * P[0] + Y * Y * P[1] * P[1] + Z * Z * P[2] * P[2]);
        case 45:
            return std::min(10.0, std::max(P[0] * -(X * X - Y + Z * Z), -10.0));
        case 47:
            return std::atan2(std::sqrt(X * X + Z * Z), Y);
        case 57:
            return std::sqrt(X * X + Y * Y + Z * Z);
        case 60: {
            double x2 = P[1] - P[0], y2 = P[2] - P[0], z2 = P[3] - P[0];
            const double x3 = X < x2 ? 0 : X - x2, y3 = Y < y2 ? 0 : Y - y2,
                         z3 = Z < z2 ? 0 : Z - z2;
            x2 = P[0] - P[1];
            y2 = P[0] - P[2];
            z2 = P[0] - P[3];
            double px = X > x2 ? 0 : x2 - X, py = Y > y2 ? 0 : y2 - Y, pz = Z > z2 ? 0 : z2 - Z;
            px = std::max(px, x3);
            py = std::max(py, y3);
            pz = std::max(pz, z3);
            return -P[0] + std::sqrt(px * px + py * py + pz * pz) - 1e-6;
        }
        case 61:
            return -P[0] + std::sqrt(X * X + Y * Y + Z * Z);
        case 68: {
            const double e = 2 / P[0], m = 1 / P[1];
            return 1 - std::pow(
                           std::pow(std::pow(std::abs(X), e) + std::pow(std::abs(Y), e), P[0] * m) +
                               std::pow(std::abs(Z), 2 * m),
                           P[1] * .5);
        }
        case 69:
            return std::atan2(X, Z);
        case 70: {
            const double r = std::sqrt(X * X + Z * Z) - P[0];
            return -P[1] + std::sqrt(r * r + Y * Y);
        }
        case 71: {
            const double x2 = X * X, y2 = Y * Y, z2 = Z * Z;
            const double ph = P[1] * P[1], th = P[2] * P[2];
            const double r = -(x2 * x2 + y2 * y2 + z2 * z2 + 2 * x2 * y2 + 2 * x2 * z2 +
                               2 * y2 * z2 - 2 * (ph + th) * x2 + 2 * (ph - th) * y2 -
                               2 * (ph + th) * z2 + (ph - th) * (ph - th));
            return std::min(10., std::max(P[0] * r, -10.));
        }
    }
    return 0.0;
}

double builtin_value(int b, const double* a, int n) {
    switch (b) {
        case 0:
            return std::abs(a[0]);
        case 1:
            return std::acos(a[0]);
        case 2:
            return std::acosh(a[0]);
        case 3:
            return std::asin(a[0]);
        case 4:
            return std::asinh(a[0]);
        case 5:
            return std::atan(a[0]);
        case 6:
            return std::atan2(a[0], a[1]);
        case 7:
            return std::atanh(a[0]);
        case 8:
            return std::ceil(a[0]);
        case 9:
            return std::cos(a[0]);
        case 10:
            return std::cosh(a[0]);
        case 11:
            return a[0] * 180.0 / kPi;
        case 12:
            return std::exp(a[0]);
        case 13:
            return std::floor(a[0]);
        case 14:
            return std::trunc(a[0]);
        case 15:
            return std::log(a[0]);
        case 16:
            return std::log10(a[0]);
        case 17:
            return *std::max_element(a, a + n);
        case 18:
            return *std::min_element(a, a + n);
        case 19:
            return std::fmod(a[0], a[1]);
        case 20:
            return std::pow(a[0], a[1]);
        case 21:
            return a[0] * kPi / 180.0;
        case 22:  // select(a, b, c[, d]): a < 0 -> b; with d: a = 0 -> c, a > 0 -> d; else c
            if (n == 3) return a[0] < 0.0 ? a[1] : a[2];
            return a[0] < 0.0 ? a[1] : (a[0] == 0.0 ? a[2] : a[3]);
        case 23:
            return std::sin(a[0]);
        case 24:
            return std::sinh(a[0]);
        case 25:
            return std::sqrt(a[0]);
        case 26:
            return std::tan(a[0]);
        case 27:
            return std::tanh(a[0]);
        case 28:
            return std::trunc(a[0] / a[1]);
        case 29:
            return a[0] * a[0];
    }
    return 0.0;
}

constexpr int kMaxSlots = 64;

double eval(const FunctionCode& f, int node, double* args, int count, int depth,
            const FunctionEnv* env);

double call(const FunctionCode& f, const double* args, int count, int depth,
            const FunctionEnv* env) {
    if (depth > 64) return 0.0;
    double frame[kMaxSlots] = {};
    std::memcpy(frame, args, sizeof(double) * static_cast<std::size_t>(std::min(count, kMaxSlots)));
    if (f.internal >= 0) return internal_value(f.internal, frame, env);
    if (f.root < 0) return 0.0;
    const int slots = std::min(kMaxSlots, static_cast<int>(f.parameters.size() + f.locals.size()));
    return eval(f, f.root, frame, slots, depth, env);
}

double eval(const FunctionCode& f, int i, double* args, int count, int depth,
            const FunctionEnv* env) {
    const FunctionCode::Node& n = f.nodes[static_cast<std::size_t>(i)];
    using Op = FunctionCode::Op;
    switch (n.op) {
        case Op::Constant:
            return n.value;
        case Op::Parameter:
            return n.index < count ? args[n.index] : 0.0;
        case Op::Neg:
            return -eval(f, n.a, args, count, depth, env);
        case Op::Sum:
        case Op::Prod: {
            // POV-Ray's compile_seq_op: for i = from; i <= to; i += 1.
            const double from = eval(f, n.args[0], args, count, depth, env);
            const double to = eval(f, n.args[1], args, count, depth, env);
            double r = n.op == Op::Sum ? 0.0 : 1.0;
            if (n.index >= count) return r;
            for (double k = from; k <= to; k += 1.0) {
                args[n.index] = k;
                const double v = eval(f, n.args[2], args, count, depth, env);
                r = n.op == Op::Sum ? r + v : r * v;
            }
            return r;
        }
        case Op::Builtin:
        case Op::Call: {
            double a[kMaxSlots] = {};
            const int k = std::min(static_cast<int>(n.args.size()), kMaxSlots);
            for (int j = 0; j < k; ++j)
                a[j] = eval(f, n.args[static_cast<std::size_t>(j)], args, count, depth, env);
            if (n.op == Op::Builtin) return builtin_value(n.builtin, a, k);
            if (n.callee->pigment) {
                double c[5] = {};
                if (env && env->pigment) env->pigment(*n.callee->pigment, a[0], a[1], a[2], c);
                return n.index == 5 ? greyscale(glm::dvec3(c[0], c[1], c[2]))
                                    : c[std::clamp(n.index, 0, 4)];
            }
            return call(*n.callee, a, k, depth + 1, env);
        }
        default:
            break;
    }
    const double x = eval(f, n.a, args, count, depth, env);
    const double y = eval(f, n.b, args, count, depth, env);
    switch (n.op) {
        case Op::Add:
            return x + y;
        case Op::Sub:
            return x - y;
        case Op::Mul:
            return x * y;
        case Op::Div:
            return x / y;
        case Op::Lt:
            return x < y ? 1.0 : 0.0;
        case Op::Le:
            return x <= y ? 1.0 : 0.0;
        case Op::Eq:
            return x == y ? 1.0 : 0.0;
        case Op::Ne:
            return x != y ? 1.0 : 0.0;
        case Op::Ge:
            return x >= y ? 1.0 : 0.0;
        case Op::Gt:
            return x > y ? 1.0 : 0.0;
        case Op::And:
            return (x != 0.0 && y != 0.0) ? 1.0 : 0.0;
        case Op::Or:
            return (x != 0.0 || y != 0.0) ? 1.0 : 0.0;
        default:
            return 0.0;
    }
}

}  // namespace

int function_builtin(const std::string& name, int* arity) {
    for (std::size_t i = 0; i < sizeof(kBuiltins) / sizeof(kBuiltins[0]); ++i) {
        if (name == kBuiltins[i].name) {
            if (arity) *arity = kBuiltins[i].arity;
            return static_cast<int>(i);
        }
    }
    return -1;
}

bool internal_function_known(int n, std::string* name, int* extra) {
    for (const Internal& i : kInternals) {
        if (i.number == n) {
            if (name) *name = i.name;
            if (extra) *extra = i.extra;
            return i.known;
        }
    }
    return false;
}

int FunctionCode::arity() const {
    if (internal >= 0) {
        int extra = 0;
        internal_function_known(internal, nullptr, &extra);
        return 3 + extra;
    }
    return static_cast<int>(parameters.size());
}

bool internal_function_needs_noise(int n) { return n == 76 || n == 78; }

bool function_evaluable(const FunctionCode& f, std::string* why, bool with_tracer) {
    if (f.pigment) {
        if (with_tracer) return true;
        if (why) *why = "a pigment function";
        return false;
    }
    if (f.internal >= 0) {
        std::string name = "internal function";
        if (internal_function_known(f.internal, &name) &&
            (with_tracer || !internal_function_needs_noise(f.internal))) {
            return true;
        }
        if (why) *why = name + " (internal " + std::to_string(f.internal) + ")";
        return false;
    }
    for (const FunctionCode::Node& n : f.nodes) {
        if (n.callee && !function_evaluable(*n.callee, why, with_tracer)) return false;
    }
    return true;
}

double evaluate_function(const FunctionCode& f, const double* args, int count,
                         const FunctionEnv* env) {
    return call(f, args, count, 0, env);
}

}  // namespace mirage
