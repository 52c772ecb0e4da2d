// POV-Ray's user functions (function { ... }): an expression over named parameters (x, y, z
// by default) compiled to a small tree, evaluated in doubles as POV-Ray's function VM does,
// with the operators and built-ins of its function syntax (fnsyntax.cpp) and the internal
// functions of functions.inc that mirage knows.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace mirage {

struct Pigment;  // scene/scene.h

struct FunctionCode {
    enum class Op {
        Constant,
        Parameter,  // index
        Add,
        Sub,
        Mul,
        Div,
        Neg,
        Lt,
        Le,
        Eq,
        Ne,
        Ge,
        Gt,
        And,
        Or,
        Builtin,  // name in `builtin`, arguments in `args`
        Call,     // another function, arguments in `args`
        Sum,      // sum(i, from, to, f): slot `index`, args {from, to, f}
        Prod,     // prod(i, from, to, f)
    };
    struct Node {
        Op op = Op::Constant;
        double value = 0.0;  // Constant
        int index = 0;       // Parameter; Call of a pigment function: the component
                             // (0 to 4 red green blue filter transmit, 5 gray)
        int a = -1, b = -1;  // operands
        std::vector<int> args;
        int builtin = 0;
        std::shared_ptr<const FunctionCode> callee;
    };
    std::vector<std::string> parameters{"x", "y", "z"};
    std::vector<std::string> locals;  // sum's and prod's variables, in slots after the parameters
    std::vector<Node> nodes;
    int root = -1;
    int internal = -1;  // function { internal(n) }: one of functions.inc's
    std::shared_ptr<const Pigment> pigment;  // function { pigment { ... } }: a colour of x, y, z

    /// How many arguments a call passes (an internal function: x, y, z and its own).
    int arity() const;
};

/// The built-in function `name` takes (its index, and how many arguments: -1 any), or -1.
/// sum and prod are not built-ins here (they declare a variable).
int function_builtin(const std::string& name, int* arity);

/// What evaluating a function may need from the tracer: POV-Ray's solid noise, for f_noise3d
/// and f_noise_generator, and its pigments, for pigment functions (they live in trace/; the
/// scene module does not link it).
struct FunctionEnv {
    /// POV-Ray's Noise(p, generator), a value in [0, 1]; null: noise cannot be evaluated.
    double (*noise)(double x, double y, double z, int generator) = nullptr;
    /// POV-Ray's Compute_Pigment at (x, y, z) into red, green, blue, filter, transmit.
    void (*pigment)(const Pigment& pigment, double x, double y, double z, double* rgbft) = nullptr;
    int noise_generator = 2;  // the scene's (global_settings), for f_noise3d
};

/// Whether mirage evaluates functions.inc's internal function number `n`.  Its name and how
/// many parameters it takes after x, y and z are given for any of POV-Ray's (0 to 78).
bool internal_function_known(int n, std::string* name = nullptr, int* extra = nullptr);

/// Whether the internal function `n` needs FunctionEnv's noise (f_noise3d, f_noise_generator).
bool internal_function_needs_noise(int n);

/// Whether `f` and everything it calls can be evaluated (noise and pigment functions only
/// `with_tracer`, the tracer's FunctionEnv); if not, `why` names the first function it cannot
/// (e.g. "f_noise3d (internal 76)").
bool function_evaluable(const FunctionCode& f, std::string* why, bool with_tracer = false);

/// The function's value for these arguments (missing ones are 0).  Calls nest at most 64
/// deep (a recursive function is refused at parse time; this guards evaluation).  Noise
/// functions and pigment functions give 0 without an `env` that has them.
double evaluate_function(const FunctionCode& f, const double* args, int count,
                         const FunctionEnv* env = nullptr);

}  // namespace mirage
