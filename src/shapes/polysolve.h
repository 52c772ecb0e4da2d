// Real roots of polynomials as POV-Ray 3.7 finds them (math/polysolv.cpp): closed forms for
// orders 1 to 4 (Ferrari's quartic through its cubic resolvent), Sturm sequences with
// bisection and regula falsi above, and for quartics whose coefficients span too many orders
// of magnitude.  The same algorithm with the same tolerances, so that torus, quartic, poly,
// blob, lathe, prism and sor surfaces meet rays where POV-Ray's do, acne and all.
#pragma once

namespace mirage {

/// POV-Ray's MAX_ORDER: the highest order solved.
inline constexpr int kMaxPolynomialOrder = 35;

/// The real roots of c[0] x^n + c[1] x^(n-1) + ... + c[n] = 0, written to `roots` (room for n
/// of them); returns how many.  Leading coefficients below 1e-10 in magnitude are dropped.
/// `sturm` asks for the Sturm solver for cubics and quartics (it is always used above order
/// 4, and for quartics with difficult coefficients).  With `epsilon` > 0 a root smaller than
/// it (|c[n] / c[n-1]| < epsilon) is removed first by solving the polynomial one order lower:
/// POV-Ray's remedy against acne for rays leaving a surface.  The Sturm solver returns only
/// the roots in [0, 1e7] (POV-Ray's MAX_DISTANCE); the closed forms return every real root.
int solve_polynomial(int n, const double* c, double* roots, bool sturm, double epsilon);

}  // namespace mirage
