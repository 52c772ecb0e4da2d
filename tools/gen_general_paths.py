#!/usr/bin/python3
"""Reference rays for the general exact-path engine, by high-precision integration.

Writes tests/data/general_profiles.json (the profiles) and tests/data/general_paths.csv (the
rays), independent of the C++ code: every profile form is evaluated from its definition
(temperature forms, the hydrostatic equation, Gladstone-Dale or Ciddor 1996, the conformal
Earth-flattening map, the soundings' C^1 quadratic spline), and every ray from the ray
equation in a stratified medium at 32 significant digits (mpmath):

    beta = n(y0) sin i,   dz/dy = beta / sqrt(n(y)^2 - beta^2),

turning points where n(y) = beta (roots of Q = n^2 - beta^2 found on the profile's grid and
refined by bisection), horizontal distances by tanh-sinh quadrature with the substitution
y = y_t +- s^2 at turning points (which removes the integrable 1/sqrt singularity), split at
the profile's breakpoints.  A ray trapped between two turning heights is periodic; points after
its third turning point are placed with the period.

Each row gives the ray's fate, its turning points, its ground hit, and points (d, y, dy/dz)
on the exact path; d is computed from the chosen height y, so no inversion is needed.

Usage (Debian's python3 with python3-mpmath; a few minutes on two cores):
    /usr/bin/python3 tools/gen_general_paths.py [--out-dir tests/data] [--jobs 2]
    /usr/bin/python3 tools/gen_general_paths.py --heights RAYS.csv PROFILE.json OUT.csv
The second form (for comparisons with other tracers) reads rows `case_id, y0, i_rad, d` and
writes the exact height and slope at horizontal distance d for the one profile in
PROFILE.json.
"""
import argparse
import csv
import json
import math
import multiprocessing
import os
import random
import sys

import mpmath as mp

mp.mp.dps = 32

G = mp.mpf('9.80665')
M_AIR = mp.mpf('0.0289644')
R_GAS = mp.mpf('8.314462618')
HYDRO = G * M_AIR / R_GAS  # K/m


# ---------------------------------------------------------------------------------------
# The C^1 shape-preserving quadratic spline of the soundings (sounding.h), exactly.

def shape_preserving_spline(x, f):
    """Knots, values and per-piece (slope, curvature) of the spline through (x, f)."""
    n = len(x)
    h = [x[j + 1] - x[j] for j in range(n - 1)]
    d = [(f[j + 1] - f[j]) / h[j] for j in range(n - 1)]
    m = [mp.mpf(0)] * n
    m[0] = d[0]
    m[n - 1] = d[n - 2]
    for j in range(1, n - 1):
        if d[j - 1] * d[j] <= 0:
            m[j] = mp.mpf(0)
            continue
        w1 = 2 * h[j] + h[j - 1]
        w2 = h[j] + 2 * h[j - 1]
        m[j] = (w1 + w2) / (w1 / d[j - 1] + w2 / d[j])
    scale = [mp.mpf(1)] * n
    for j in range(n - 1):
        s_sum = m[j] + m[j + 1]
        s = mp.mpf(1)
        if d[j] == 0:
            s = mp.mpf(0)
        elif s_sum / d[j] > 4:
            s = 4 * d[j] / s_sum
        scale[j] = min(scale[j], s)
        scale[j + 1] = min(scale[j + 1], s)
    m = [m[j] * scale[j] for j in range(n)]
    knots, values, slopes, curv = [], [], [], []
    for j in range(n - 1):
        mid_slope = 2 * d[j] - (m[j] + m[j + 1]) / 2
        cl = (mid_slope - m[j]) / h[j]
        cr = (m[j + 1] - mid_slope) / h[j]
        half = h[j] / 2
        knots += [x[j], x[j] + half]
        values += [f[j], f[j] + (m[j] + cl * half) * half]
        slopes += [m[j], mid_slope]
        curv += [cl, cr]
    knots.append(x[n - 1])
    values.append(f[n - 1])
    return knots, values, slopes, curv


class Spline:
    def __init__(self, x, f):
        self.k, self.v, self.s, self.c = shape_preserving_spline(x, f)

    def piece(self, y):
        lo, hi = 0, len(self.k) - 1
        while hi - lo > 1:
            mid = (lo + hi) // 2
            if self.k[mid] <= y:
                lo = mid
            else:
                hi = mid
        return lo

    def value(self, y):
        if y <= self.k[0]:
            return self.v[0]
        if y >= self.k[-1]:
            return self.v[-1]
        j = self.piece(y)
        u = y - self.k[j]
        return self.v[j] + (self.s[j] + self.c[j] * u) * u

    def slope(self, y):
        if y < self.k[0] or y > self.k[-1]:
            return mp.mpf(0)
        j = min(self.piece(y), len(self.s) - 1)
        return self.s[j] + 2 * self.c[j] * (y - self.k[j])


# ---------------------------------------------------------------------------------------
# The index of air.

def saturation_vapour_pressure(T):
    """IAPWS-IF97 over water, at every temperature (humidity relative to water)."""
    K = [mp.mpf(v) for v in ('1.16705214528e3', '-7.24213167032e5', '-1.70738469401e1',
                             '1.20208247025e4', '-3.23255503223e6', '1.49151086135e1',
                             '-4.82326573616e3', '4.05113405421e5', '-2.38555575678e-1',
                             '6.50175348448e2')]
    om = T + K[8] / (T - K[9])
    A = om * om + K[0] * om + K[1]
    B = K[2] * om * om + K[3] * om + K[4]
    C = K[5] * om * om + K[6] * om + K[7]
    X = -B + mp.sqrt(B * B - 4 * A * C)
    return mp.mpf(10) ** 6 * (2 * C / X) ** 4


def compressibility(T, p, xv):
    a0, a1, a2 = mp.mpf('1.58123e-6'), mp.mpf('-2.9331e-8'), mp.mpf('1.1043e-10')
    b0, b1 = mp.mpf('5.707e-6'), mp.mpf('-2.051e-8')
    c0, c1 = mp.mpf('1.9898e-4'), mp.mpf('-2.376e-6')
    d, e = mp.mpf('1.83e-11'), mp.mpf('-0.765e-8')
    t = T - mp.mpf('273.15')
    pt = p / T
    return 1 - pt * (a0 + a1 * t + a2 * t * t + (b0 + b1 * t) * xv + (c0 + c1 * t) * xv * xv) + \
        pt * pt * (d + e * xv * xv)


def ciddor(lam_nm, T, p, h, co2):
    S = 1 / (mp.mpf(lam_nm) / 1000) ** 2
    r_as = mp.mpf('1e-8') * (mp.mpf(5792105) / (mp.mpf('238.0185') - S) +
                            mp.mpf(167917) / (mp.mpf('57.362') - S))
    r_vs = mp.mpf('1.022e-8') * (mp.mpf('295.235') + mp.mpf('2.6422') * S -
                                 mp.mpf('0.032380') * S ** 2 + mp.mpf('0.004028') * S ** 3)
    r_axs = r_as * (1 + mp.mpf('0.534e-6') * (co2 - 450))
    t = T - mp.mpf('273.15')
    f = mp.mpf('1.00062') + mp.mpf('3.14e-8') * p + mp.mpf('5.6e-7') * t * t
    xv = f * h * saturation_vapour_pressure(T) / p
    Za = compressibility(mp.mpf('288.15'), mp.mpf(101325), 0)
    Zw = compressibility(mp.mpf('293.15'), mp.mpf(1333), 1)
    Zm = compressibility(T, p, xv)
    dry = (1 - xv) * p * mp.mpf('288.15') * Za / (101325 * T * Zm)
    vap = xv * p * mp.mpf('293.15') * Zw / (1333 * T * Zm)
    return dry * r_axs + vap * r_vs


# ---------------------------------------------------------------------------------------
# The temperature models of the GSL tracer Wigner-GPU-Lab/numerical-simulate-mirage (its
# Eikonal.h, getRefract: n = 1 + 7.86e-4 * 101 kPa / T), written from their published formulas
# for tools/peer_compare.sh: water (ambient T_a over water at T_b), conventional and porous
# asphalt (ambient T_a).  Heights in m, temperatures in degC.

PEER_DECAY = {'water': mp.mpf('20.1'), 'conventional': mp.mpf('10.08'), 'porous': mp.mpf('8.35')}


def peer_temperature_c(model, t_amb, t_base, h):
    if model == 'water':
        return t_amb + (t_base - t_amb) * (mp.mpf('0.011') + mp.mpf('1.05') * mp.exp(-mp.mpf('20.1') * h))
    if model == 'conventional':
        return t_amb + mp.mpf('0.018') + mp.mpf('6.37') * mp.exp(-mp.mpf('10.08') * h)
    if model == 'porous':
        return t_amb + (mp.mpf('-66.8') + mp.mpf('1.9') * t_amb) * \
            (mp.mpf('0.002') + mp.mpf('0.994') * mp.exp(-mp.mpf('8.35') * h))
    raise ValueError('unknown peer model %r' % model)


def peer_refractivity(model, t_amb, t_base, h):
    return mp.mpf('7.86e-4') * 101 / (peer_temperature_c(model, t_amb, t_base, h) + mp.mpf('273.15'))


# ---------------------------------------------------------------------------------------
# Profiles: n^2(y) over heights above the ground, then flattened when R > 0.

GL_X, GL_W = None, None


def gauss_legendre(n=12):
    global GL_X, GL_W
    if GL_X is None:
        xs, ws = [], []
        for k in range(1, n + 1):
            x = mp.cos(mp.pi * (k - mp.mpf(1) / 4) / (n + mp.mpf(1) / 2))
            for _ in range(100):
                p0, p1 = mp.mpf(1), x
                for j in range(2, n + 1):
                    p0, p1 = p1, ((2 * j - 1) * x * p1 - (j - 1) * p0) / j
                dp = n * (x * p1 - p0) / (x * x - 1)
                dx = p1 / dp
                x -= dx
                if abs(dx) < mp.mpf(10) ** (-(mp.mp.dps + 2)):
                    break
            xs.append(x)
            ws.append(2 / ((1 - x * x) * dp * dp))
        GL_X, GL_W = xs, ws
    return GL_X, GL_W


def gl_integral(f, a, b):
    xs, ws = gauss_legendre()
    c, h = (a + b) / 2, (b - a) / 2
    return h * mp.fsum(w * f(c + h * x) for x, w in zip(xs, ws))


class Profile:
    """The true profile of a spec (the dict written to general_profiles.json)."""

    def __init__(self, spec):
        self.spec = spec
        kind = spec['kind']
        self.R = mp.mpf(spec.get('earth_radius_m', 0))
        self.breaks = []
        if kind == 'exponential':
            self.eta0 = mp.mpf(spec['eta0'])
            self.eta1 = mp.mpf(spec['eta1'])
            self.alpha = mp.mpf(spec['alpha'])
            self.sign = 1 if spec['profile'] == 'inferior' else -1
            self.top = mp.mpf(spec['top_m'])
            self.n0_sq = self.eta0 ** 2
        elif kind == 'peer_model':
            self.model = spec['model']
            self.t_amb = mp.mpf(spec['temp_amb_c'])
            self.t_base = mp.mpf(spec.get('temp_base_c', spec['temp_amb_c']))
            self.top = mp.mpf(spec['top_m'])
            self.n0_sq = self.n_sq_phys(mp.mpf(0))
        elif kind == 'n_sounding':
            hs = [mp.mpf(v) for v in spec['height_m']]
            ns = [mp.mpf(v) for v in spec['n']]
            n0 = ns[0]
            self.n0_sq = n0 * n0
            self.spline = Spline(hs, [(n - n0) * (n + n0) for n in ns])
            self.breaks = list(self.spline.k)
            self.top = hs[-1]
        else:
            self.setup_air(spec)
        # Grid for scans (and the hydrostatic table): breakpoints and steps resolving the
        # features.
        self.grid = self.make_grid()
        if kind in ('column', 't_sounding'):
            self.setup_pressure()
            self.m0 = self.refractivity(mp.mpf(0))
            self.n0_sq = (1 + self.m0) ** 2
        if self.R > 0:
            self.ytop_model = self.flat(self.top + mp.mpf(spec.get('earth_extension_m', 10000)))
            self.ytop_phys = self.flat(self.top)
        else:
            self.ytop_model = self.top

    # -- air
    def setup_air(self, spec):
        ix = spec['index']
        self.formula = ix['formula']
        self.gd = mp.mpf(ix.get('gladstone_dale', '2.93e-4'))
        self.lam = mp.mpf(ix.get('wavelength_nm', 550))
        self.co2 = mp.mpf(ix.get('co2_ppm', 450))
        self.p0 = mp.mpf(spec.get('ground_pressure_pa', 101325))
        self.hydro = spec.get('hydrostatic', True)
        rh = spec.get('relative_humidity', 0)
        self.rh0 = mp.mpf(0) if isinstance(rh, list) else mp.mpf(rh)
        self.lnp = None
        self.rh = None
        if spec['kind'] == 'column':
            self.T0 = mp.mpf(spec['ground_temperature_k'])
            self.lapse = mp.mpf(spec.get('lapse_k_per_m', 0))
            self.layers = [(mp.mpf(a), mp.mpf(b)) for a, b in spec.get('layers', [])]
            self.invs = [tuple(mp.mpf(v) for v in inv) for inv in spec.get('inversions', [])]
            self.top = mp.mpf(spec['top_m'])
            for bot, top, dt, sig in self.invs:
                if sig == 0:
                    self.breaks += [bot, top]
            self.Tf = self.column_T
        else:
            hs = [mp.mpf(v) for v in spec['height_m']]
            self.top = hs[-1]
            self.Ts = Spline(hs, [mp.mpf(v) + mp.mpf('273.15') for v in spec['temperature_c']])
            self.breaks = list(self.Ts.k)
            self.Tf = self.Ts.value
            if 'pressure_hpa' in spec:
                self.lnp = Spline(hs, [mp.log(100 * mp.mpf(v)) for v in spec['pressure_hpa']])
            if isinstance(spec.get('relative_humidity'), list):
                self.rh = Spline(hs, [mp.mpf(v) / 100 for v in spec['relative_humidity']])

    def column_T(self, y):
        T = self.T0 - self.lapse * y
        for dt, H in self.layers:
            T += dt * mp.exp(-y / H)
        for bot, top, dt, sig in self.invs:
            w = top - bot
            if sig == 0:
                r = min(max((y - bot) / w, mp.mpf(0)), mp.mpf(1))
            else:
                F = lambda x: x * mp.ncdf(x / sig) + sig * mp.npdf(x / sig)
                r = (F(y - bot) - F(y - top)) / w
            T += dt * r
        return T

    def feature_scale(self):
        s = []
        k = self.spec['kind']
        if k == 'column':
            s += [H for _, H in self.layers]
            s += [sig for _, _, _, sig in self.invs if sig > 0]
            s += [(top - bot) for bot, top, _, _ in self.invs]
        if k == 'exponential':
            s.append(1 / self.alpha)
        if k == 'peer_model':
            s.append(1 / PEER_DECAY[self.model])
        return min(s) if s else None

    def make_grid(self):
        pts = set([mp.mpf(0), self.top] + [b for b in self.breaks if 0 < b < self.top])
        sc = self.feature_scale()
        step_fine = sc / 4 if sc else self.top / 200
        y = mp.mpf(0)
        while y < self.top:
            pts.add(y)
            # Finer near the features, coarser above them.
            far = 30 * (sc if sc else self.top)
            feat_top = max([mp.mpf(0)] + [top + 8 * sig for _, top, _, sig in getattr(self, 'invs', [])])
            if y < far or y < feat_top + 8 * step_fine:
                y += step_fine
            else:
                y += max(step_fine, min(mp.mpf(10), self.top / 100))
        if self.spec['kind'] in ('n_sounding', 't_sounding'):
            # Subdivide every piece of the spline.
            ks = self.spline.k if self.spec['kind'] == 'n_sounding' else self.Ts.k
            for a, b in zip(ks[:-1], ks[1:]):
                for q in range(1, 8):
                    pts.add(a + (b - a) * q / 8)
        return sorted(pts)

    def setup_pressure(self):
        # int_0^y dy / T tabulated at the grid (Gauss-Legendre, 12 points per cell; the cells
    # resolve the temperature's features, so the rule is exact to the working precision).
        self.cum = [mp.mpf(0)]
        for a, b in zip(self.grid[:-1], self.grid[1:]):
            self.cum.append(self.cum[-1] + gl_integral(lambda s: 1 / self.Tf(s), a, b))

    def inv_T_integral(self, y):
        if y <= 0:
            return mp.mpf(0)
        if y >= self.top:
            return self.cum[-1] + (y - self.top) / self.Tf(self.top)
        lo, hi = 0, len(self.grid) - 1
        while hi - lo > 1:
            mid = (lo + hi) // 2
            if self.grid[mid] <= y:
                lo = mid
            else:
                hi = mid
        return self.cum[lo] + gl_integral(lambda s: 1 / self.Tf(s), self.grid[lo], y)

    def pressure(self, y):
        if self.lnp is not None:
            return mp.exp(self.lnp.value(y))
        if self.hydro:
            return self.p0 * mp.exp(-HYDRO * self.inv_T_integral(y))
        return self.p0

    def refractivity(self, y):
        y = min(y, self.top)
        T = self.Tf(y)
        p = self.pressure(y)
        h = min(max(self.rh.value(y), mp.mpf(0)), mp.mpf(1)) if self.rh is not None else self.rh0
        if self.formula == 'ciddor':
            return ciddor(self.lam, T, p, h, self.co2)
        return self.gd * (p / 101325) * (mp.mpf('288.15') / T)

    # -- n^2 over heights above the ground
    def n_sq_phys(self, h):
        h = min(h, self.top)
        k = self.spec['kind']
        if k == 'exponential':
            return self.n0_sq + self.sign * self.eta1 ** 2 * (1 - mp.exp(-self.alpha * h))
        if k == 'n_sounding':
            return self.n0_sq + self.spline.value(h)
        if k == 'peer_model':
            return (1 + peer_refractivity(self.model, self.t_amb, self.t_base, h)) ** 2
        return (1 + self.refractivity(h)) ** 2

    def flat(self, h):
        return self.R * mp.log1p(h / self.R) if self.R > 0 else h

    def unflat(self, y):
        return self.R * mp.expm1(y / self.R) if self.R > 0 else y

    # -- the model: n^2 over the engine's heights (flattened with an Earth radius)
    def n_sq(self, y):
        if self.R > 0:
            y = min(y, self.ytop_model)
            return self.n_sq_phys(self.unflat(y)) * mp.exp(2 * y / self.R)
        return self.n_sq_phys(y)

    def model_breaks(self):
        b = [self.flat(x) for x in self.breaks]
        if self.R > 0:
            b.append(self.flat(self.top))
        return sorted(set(x for x in b if 0 < x < self.ytop_model))

    def model_grid(self):
        g = [self.flat(x) for x in self.grid]
        if self.R > 0:
            y = g[-1]
            while y < self.ytop_model:
                y = min(self.ytop_model, y + 100)
                g.append(y)
        return g


# ---------------------------------------------------------------------------------------
# Rays.

class Ray:
    def __init__(self, prof, y0, i):
        self.p = prof
        self.y0 = mp.mpf(y0)
        self.i = mp.mpf(i)
        self.N0 = prof.n_sq(self.y0)
        self.beta2 = self.N0 * mp.sin(self.i) ** 2
        self.beta = mp.sqrt(self.beta2)
        self.sg = -1 if mp.cos(self.i) < 0 else 1
        self.grid = prof.model_grid()
        self.breaks = prof.model_breaks()

    def Q(self, y):
        return self.p.n_sq(y) - self.beta2

    def first_end(self, y_from, direction):
        """Where the monotone run from y_from in `direction` ends: ('vertex', y), ('ground', 0)
        or ('top', top)."""
        top = self.p.ytop_model
        nodes = [g for g in self.grid if (g > y_from if direction > 0 else g < y_from)]
        nodes = nodes if direction > 0 else list(reversed(nodes))
        prev = y_from
        for g in nodes:
            qg = self.Q(g)
            if qg < 0:
                a, b = prev, g
                for _ in range(200):
                    mid = (a + b) / 2
                    if self.Q(mid) >= 0:
                        a = mid
                    else:
                        b = mid
                    if abs(b - a) < mp.mpf(10) ** (-(mp.mp.dps - 4)) * (1 + abs(a)):
                        break
                return ('vertex', a)  # the side where Q >= 0
            prev = g
        return ('top', top) if direction > 0 else ('ground', mp.mpf(0))

    def distance(self, ya, yb, turn_a=False, turn_b=False):
        """Horizontal distance along a monotone run from height ya to yb (ya, yb may be turning
        points: then y = y_t +- s^2)."""
        if ya == yb:
            return mp.mpf(0)
        lo, hi = min(ya, yb), max(ya, yb)
        pts = [lo] + [b for b in self.breaks if lo < b < hi] + [hi]
        total = mp.mpf(0)
        for a, b in zip(pts[:-1], pts[1:]):
            # Which ends of [a, b] are turning points.
            a_turn = (a == ya and turn_a) or (a == yb and turn_b)
            b_turn = (b == ya and turn_a) or (b == yb and turn_b)
            if a_turn and b_turn:
                m = (a + b) / 2
                total += self.piece(a, m, True, False) + self.piece(m, b, False, True)
            else:
                total += self.piece(a, b, a_turn, b_turn)
        return total

    def piece(self, a, b, a_turn, b_turn):
        # At a turning point Q vanishes; mp.quad works a little above the working precision,
        # where Q within rounding of the root may come out negative: |Q| keeps the integrand
        # real (the nodes so close to the root carry no weight at this precision).
        beta = self.beta
        if a_turn:
            f = lambda s: 2 * s * beta / mp.sqrt(abs(self.Q(a + s * s)))
            return mp.quad(f, [0, mp.sqrt(b - a)])
        if b_turn:
            f = lambda s: 2 * s * beta / mp.sqrt(abs(self.Q(b - s * s)))
            return mp.quad(f, [0, mp.sqrt(b - a)])
        return mp.quad(lambda y: beta / mp.sqrt(abs(self.Q(y))), [a, b])

    def slope_at_height(self, y, direction):
        return direction * mp.sqrt(self.Q(y) / self.beta2)

    def solve(self, rng):
        """The ray's fate, turning points, ground hit and points on the path."""
        out = {}
        top = self.p.ytop_model
        end1 = self.first_end(self.y0, self.sg)
        points = []
        if end1[0] == 'vertex':
            yv1 = end1[1]
            t1 = self.distance(self.y0, yv1, False, True)
            end2 = self.first_end(self.y0, -self.sg)
            run = self.distance(yv1, end2[1], True, end2[0] == 'vertex')
            out['turn1'] = (t1, yv1)
            # a point before the turn, and one after it (beyond the start height)
            yb = self.y0 + (yv1 - self.y0) * mp.mpf(rng.uniform(0.2, 0.9))
            points.append((self.distance(self.y0, yb), yb, self.slope_at_height(yb, self.sg)))
            ya = yv1 + (end2[1] - yv1) * mp.mpf(rng.uniform(0.3, 0.95))
            points.append((t1 + self.distance(yv1, ya, True, False), ya,
                           self.slope_at_height(ya, -self.sg)))
            if end2[0] == 'vertex':
                out['fate'] = 'ducted'
                out['turn2'] = (t1 + run, end2[1])
                out['half_period'] = run
                # after the third turning point (at t1 + 2 run, back at yv1), rising again
                yc = yv1 + (end2[1] - yv1) * mp.mpf(rng.uniform(0.1, 0.9))
                points.append((t1 + 2 * run + self.distance(yv1, yc, True, False), yc,
                               self.slope_at_height(yc, -self.sg)))
                # after the fifth: descending from the second turning height
                yd = end2[1] + (yv1 - end2[1]) * mp.mpf(rng.uniform(0.1, 0.9))
                points.append((t1 + 5 * run + self.distance(end2[1], yd, True, False), yd,
                               self.slope_at_height(yd, self.sg)))
            elif end2[0] == 'ground':
                out['fate'] = 'ground'
                out['dz_ground'] = t1 + run
            else:
                out['fate'] = 'escape'
                out['dz_top'] = t1 + run
                out['end_slope'] = self.slope_at_height(top, -self.sg)
        else:
            run = self.distance(self.y0, end1[1])
            yb = self.y0 + (end1[1] - self.y0) * mp.mpf(rng.uniform(0.2, 0.9))
            points.append((self.distance(self.y0, yb), yb, self.slope_at_height(yb, self.sg)))
            if end1[0] == 'ground':
                out['fate'] = 'ground'
                out['dz_ground'] = run
            else:
                out['fate'] = 'escape'
                out['dz_top'] = run
                out['end_slope'] = self.slope_at_height(top, self.sg)
        if out['fate'] == 'escape':
            # Beyond the top the path is straight.
            d_extra = mp.mpf(rng.uniform(1, 50))
            points.append((out['dz_top'] + d_extra, top + out['end_slope'] * d_extra,
                           out['end_slope']))
        out['points'] = points
        return out


def ray_families(prof_name, spec, prof, rng):
    """(description, y0, i) for the profile's rays."""
    fams = spec['rays']
    rays = []
    for fam in fams:
        for _ in range(fam['count']):
            y_lo, y_hi = fam['y0']
            if fam.get('log_y0'):
                y0 = y_lo * (y_hi / y_lo) ** rng.random()
            else:
                y0 = rng.uniform(y_lo, y_hi)
            e_lo, e_hi = fam['elevation_rad']
            if fam.get('log_elevation'):
                mag = e_lo * (e_hi / e_lo) ** rng.random()
                elev = -mag if rng.random() < fam.get('down_share', 0.6) else mag
            else:
                elev = rng.uniform(e_lo, e_hi)
            if spec.get('earth_radius_m', 0) > 0:
                y0 = float(prof.flat(mp.mpf(y0)))
            i = math.pi / 2 - elev
            rays.append((fam['name'], y0, i))
    return rays


def fmt(v):
    if v is None:
        return 'nan'
    if isinstance(v, mp.mpc):
        raise ValueError('complex value %s' % v)
    return mp.nstr(v, 20, min_fixed=-5, max_fixed=5) if isinstance(v, mp.mpf) else repr(v)


COLUMNS = ['case_id', 'profile', 'family', 'y0', 'i_rad', 'fate', 'turns', 'dz_turn1', 'y_turn1',
           'dz_turn2', 'y_turn2', 'half_period', 'dz_ground', 'dz_top', 'end_slope'] + \
          ['%s%d' % (c, k) for k in range(1, 5) for c in ('d', 'y_d', 'dydz_d')]


def solve_row(args):
    case_id, pname, spec, fam, y0, i, seed = args
    mp.mp.dps = 32
    prof = Profile(spec)
    ray = Ray(prof, y0, i)
    rng = random.Random(seed)
    out = ray.solve(rng)
    row = {'case_id': case_id, 'profile': pname, 'family': fam, 'y0': repr(y0), 'i_rad': repr(i),
           'fate': out['fate']}
    row['turns'] = {'ducted': '-1'}.get(out['fate'], '1' if 'turn1' in out else '0')
    for key in ('dz_turn1', 'y_turn1', 'dz_turn2', 'y_turn2'):
        row[key] = 'nan'
    if 'turn1' in out:
        row['dz_turn1'], row['y_turn1'] = fmt(out['turn1'][0]), fmt(out['turn1'][1])
    if 'turn2' in out:
        row['dz_turn2'], row['y_turn2'] = fmt(out['turn2'][0]), fmt(out['turn2'][1])
    row['half_period'] = fmt(out.get('half_period'))
    row['dz_ground'] = fmt(out.get('dz_ground'))
    row['dz_top'] = fmt(out.get('dz_top'))
    row['end_slope'] = fmt(out.get('end_slope'))
    for k in range(4):
        if k < len(out['points']):
            d, y, s = out['points'][k]
            row['d%d' % (k + 1)] = fmt(d)
            row['y_d%d' % (k + 1)] = fmt(y)
            row['dydz_d%d' % (k + 1)] = fmt(s)
        else:
            for c in ('d', 'y_d', 'dydz_d'):
                row['%s%d' % (c, k + 1)] = 'nan'
    return row


# ---------------------------------------------------------------------------------------
# The profiles of the test data.

def road_n_sounding():
    hs = ['0', '0.02', '0.05', '0.1', '0.2', '0.35', '0.5', '0.75', '1', '1.5', '2', '3', '5', '10']
    ns = []
    for h in hs:
        T = 300 + 20 * math.exp(-float(h) / 0.3)
        ns.append('%.15g' % (1 + 2.93e-4 * 288.15 / T))
    return hs, ns


def duct_n_sounding():
    # A warm ground under an elevated cold layer and an inversion: n peaks near 2 m.
    hs = ['0', '0.1', '0.3', '0.6', '1', '1.5', '2', '2.5', '3', '3.5', '4', '5', '6', '8', '12']
    ns = []
    for h in hs:
        y = float(h)
        T = 290 + 12 * math.exp(-y / 0.5) + 6 / (1 + math.exp(-(y - 3) / 0.4)) - 0.0065 * y
        ns.append('%.15g' % (1 + 2.93e-4 * 288.15 / T))
    return hs, ns


def profiles():
    P = {}
    common_air = {'index': {'formula': 'gladstone-dale', 'gladstone_dale': 2.93e-4},
                  'ground_pressure_pa': 101325, 'hydrostatic': True}
    hs, ns = road_n_sounding()
    P['nsnd_road'] = {'kind': 'n_sounding', 'height_m': hs, 'n': ns, 'rays': [
        {'name': 'road', 'count': 14, 'y0': [0.05, 3.0], 'log_y0': True,
         'elevation_rad': [1e-6, 0.02], 'log_elevation': True},
        {'name': 'steep', 'count': 4, 'y0': [0.1, 8.0], 'elevation_rad': [-0.6, 0.6]}]}
    hs, ns = duct_n_sounding()
    P['nsnd_duct'] = {'kind': 'n_sounding', 'height_m': hs, 'n': ns, 'rays': [
        {'name': 'trapped', 'count': 10, 'y0': [1.2, 2.8], 'elevation_rad': [-2e-3, 2e-3]},
        {'name': 'mixed', 'count': 10, 'y0': [0.1, 6.0], 'log_y0': True,
         'elevation_rad': [1e-6, 0.01], 'log_elevation': True}]}
    P['nsnd_paper'] = {'kind': 'n_sounding',
                       'height_m': ['0', '0.25', '0.5', '1', '1.5', '2', '3', '4', '6'],
                       'n': ['1.000233', '1.03', '1.05', '1.075', '1.088', '1.094', '1.0985',
                             '1.0997', '1.1003'],
                       'rays': [{'name': 'paper', 'count': 14, 'y0': [0.05, 5.0], 'log_y0': True,
                                 'elevation_rad': [1e-5, 0.4], 'log_elevation': True}]}
    P['ktg_paper'] = {'kind': 'exponential', 'profile': 'inferior', 'eta0': '1.000233',
                      'eta1': '0.4584', 'alpha': '2.303', 'top_m': 17,
                      'rays': [{'name': 'paper', 'count': 12, 'y0': [0.1, 5.0], 'log_y0': True,
                                'elevation_rad': [1e-4, 0.4], 'log_elevation': True}]}
    P['road_t'] = dict(common_air, kind='column', ground_temperature_k=300,
                       layers=[[20, 0.3]], top_m=100, rays=[
                           {'name': 'road', 'count': 16, 'y0': [0.05, 3.0], 'log_y0': True,
                            'elevation_rad': [1e-5, 0.02], 'log_elevation': True}])
    P['lapse'] = dict(common_air, kind='column', ground_temperature_k=288.15,
                      lapse_k_per_m=0.0065, top_m=1000, rays=[
                          {'name': 'any', 'count': 10, 'y0': [1, 300], 'log_y0': True,
                           'elevation_rad': [1e-4, 0.1], 'log_elevation': True}])
    young = dict(kind='column', ground_temperature_k=288.15, lapse_k_per_m=0.0065, top_m=1000,
                 index={'formula': 'ciddor', 'wavelength_nm': 550, 'co2_ppm': 450},
                 ground_pressure_pa=101325, hydrostatic=True, earth_radius_m=6371000)
    duct_rays = [{'name': 'duct', 'count': 10, 'y0': [46.5, 58.0], 'elevation_rad': [-1e-3, 1e-3]},
                 {'name': 'mixed', 'count': 8, 'y0': [5.0, 120.0], 'log_y0': True,
                  'elevation_rad': [1e-5, 0.01], 'log_elevation': True}]
    P['young_zigzag'] = dict(young, inversions=[[50, 60, 2, 0]], rays=duct_rays)
    P['young_smooth'] = dict(young, inversions=[[50, 60, 2, 0.85]], rays=duct_rays)
    P['road_duct'] = dict(common_air, kind='column', ground_temperature_k=300,
                          layers=[[15, 0.2]], inversions=[[1.0, 2.5, 6, 0.2]], top_m=100, rays=[
                              {'name': 'trapped', 'count': 10, 'y0': [0.6, 1.6],
                               'elevation_rad': [-1.5e-3, 1.5e-3]},
                              {'name': 'mixed', 'count': 8, 'y0': [0.05, 4.0], 'log_y0': True,
                               'elevation_rad': [1e-6, 0.01], 'log_elevation': True}])
    P['cold_sea_ciddor'] = dict(kind='column', ground_temperature_k=278.15, lapse_k_per_m=0.0065,
                                layers=[[-8, 4]], top_m=1000,
                                index={'formula': 'ciddor', 'wavelength_nm': 589, 'co2_ppm': 420},
                                relative_humidity=0.8, ground_pressure_pa=102000, hydrostatic=True,
                                earth_radius_m=6371000, rays=[
                                    {'name': 'sea', 'count': 12, 'y0': [1, 40], 'log_y0': True,
                                     'elevation_rad': [1e-5, 0.01], 'log_elevation': True}])
    P['tsnd_full'] = dict(common_air, kind='t_sounding',
                          height_m=['0', '0.5', '1', '2', '4', '7', '12', '20', '35', '60', '100'],
                          temperature_c=['24.5', '21.0', '19.8', '18.9', '18.4', '18.6', '19.6',
                                         '20.1', '19.9', '19.7', '19.4'],
                          pressure_hpa=['1012.0', '1011.94', '1011.88', '1011.76', '1011.53',
                                        '1011.18', '1010.59', '1009.65', '1007.89', '1004.95',
                                        '1000.27'],
                          relative_humidity=['60', '62', '63', '64', '65', '66', '67', '68', '69',
                                             '70', '70'],
                          index={'formula': 'ciddor', 'wavelength_nm': 550, 'co2_ppm': 450},
                          rays=[{'name': 'any', 'count': 14, 'y0': [0.2, 60], 'log_y0': True,
                                 'elevation_rad': [1e-5, 0.02], 'log_elevation': True}])
    P['tsnd_hydro'] = dict(common_air, kind='t_sounding',
                           height_m=['0', '0.3', '0.8', '1.5', '3', '6', '10', '25', '50'],
                           temperature_c=['8.0', '9.5', '11.0', '12.2', '13.0', '13.4', '13.2',
                                          '12.9', '12.7'],
                           rays=[{'name': 'any', 'count': 14, 'y0': [0.1, 30], 'log_y0': True,
                                  'elevation_rad': [1e-5, 0.02], 'log_elevation': True}])
    return P


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--out-dir', default=os.path.join(os.path.dirname(__file__), '..', 'tests', 'data'))
    ap.add_argument('--jobs', type=int, default=2)
    ap.add_argument('--heights', nargs=3, metavar=('RAYS', 'PROFILE', 'OUT'))
    args = ap.parse_args()
    if args.heights:
        return heights_mode(*args.heights, jobs=args.jobs)
    P = profiles()
    tasks = []
    rng = random.Random(20260601)
    for pname in sorted(P):
        spec = P[pname]
        prof = Profile(spec)
        for k, (fam, y0, i) in enumerate(ray_families(pname, spec, prof, rng)):
            tasks.append(('%s_%02d' % (pname, k + 1), pname, spec, fam, y0, i, rng.randrange(1 << 30)))
    with multiprocessing.Pool(args.jobs) as pool:
        rows = pool.map(solve_row, tasks, chunksize=1)
    specs = {name: {k: v for k, v in spec.items() if k != 'rays'} for name, spec in P.items()}
    with open(os.path.join(args.out_dir, 'general_profiles.json'), 'w') as f:
        json.dump(specs, f, indent=1, sort_keys=True)
        f.write('\n')
    with open(os.path.join(args.out_dir, 'general_paths.csv'), 'w', newline='') as f:
        w = csv.DictWriter(f, fieldnames=COLUMNS, lineterminator='\n')
        w.writeheader()
        for r in rows:
            w.writerow(r)
    print('%d rays of %d profiles' % (len(rows), len(P)))


# ---------------------------------------------------------------------------------------
# Heights at given distances (for comparisons with other tracers).

def height_at_distance(ray, d):
    """The exact height and slope at horizontal distance d (root of the distance function)."""
    d = mp.mpf(d)
    end1 = ray.first_end(ray.y0, ray.sg)
    runs = []  # (start height, end height, start is turn, end is turn, direction, distance)
    if end1[0] == 'vertex':
        runs.append((ray.y0, end1[1], False, True, ray.sg))
        end2 = ray.first_end(ray.y0, -ray.sg)
        runs.append((end1[1], end2[1], True, end2[0] == 'vertex', -ray.sg))
        if end2[0] == 'vertex':
            for k in range(200):
                a, b = (end2[1], end1[1]) if k % 2 == 0 else (end1[1], end2[1])
                runs.append((a, b, True, True, ray.sg if k % 2 == 0 else -ray.sg))
        last = end2
    else:
        runs.append((ray.y0, end1[1], False, False, ray.sg))
        last = end1
    z = mp.mpf(0)
    for ya, yb, ta, tb, direction in runs:
        L = ray.distance(ya, yb, ta, tb)
        if z + L >= d:
            # Newton on z(y) = target (dz/dy = 1 / slope), kept inside the run's bracket.
            target = d - z
            lo, hi = (ya, yb) if ya < yb else (yb, ya)
            y = ya + (yb - ya) * (target / L)
            for _ in range(60):
                f = ray.distance(ya, y, ta, False) - target
                s = abs(ray.slope_at_height(y, 1))
                step = f * s * (1 if yb > ya else -1)
                y_new = y - step
                if not (lo < y_new < hi):
                    y_new = (y + (hi if (yb > ya) == (f < 0) else lo)) / 2
                if abs(y_new - y) < mp.mpf(10) ** (-(mp.mp.dps - 6)) * (1 + abs(y)):
                    y = y_new
                    break
                y = y_new
            return y, ray.slope_at_height(y, direction)
        z += L
    # Beyond the end: straight (top) or not defined (ground).
    if last[0] == 'top':
        s = ray.slope_at_height(ray.p.ytop_model, runs[-1][4])
        return ray.p.ytop_model + s * (d - z), s
    return None, None


def heights_row(args):
    spec, row = args
    mp.mp.dps = 24
    prof = Profile(spec)
    ray = Ray(prof, float(row['y0']), float(row['i_rad']))
    y, s = height_at_distance(ray, row['d'])
    h = prof.unflat(y) if y is not None else None
    return {'case_id': row['case_id'], 'y': fmt(y), 'height': fmt(h), 'slope': fmt(s)}


def heights_mode(rays_path, profile_path, out_path, jobs):
    with open(profile_path) as f:
        spec = json.load(f)
    with open(rays_path) as f:
        rows = list(csv.DictReader(f))
    with multiprocessing.Pool(jobs) as pool:
        out = pool.map(heights_row, [(spec, r) for r in rows], chunksize=1)
    with open(out_path, 'w', newline='') as f:
        w = csv.DictWriter(f, fieldnames=['case_id', 'y', 'height', 'slope'], lineterminator='\n')
        w.writeheader()
        for r in out:
            w.writerow(r)


if __name__ == '__main__':
    sys.exit(main())
