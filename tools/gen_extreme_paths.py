#!/usr/bin/python3
"""Generates tests/data/path_extreme.csv: exact rays of the stiff and extreme families
(tiny eta1, grazing rays, alpha y0 up to 2000, k^2 = 1 +/- 1e-12, k -> 0, kappa^2 = +/- 1e-8,
rays started on or near the ground) in the columns and with the scoring rule of
path_public.csv.

Independent of the C++ code: the paper's literal closed forms (acosh, the vertex forms),
evaluated at 110 significant digits with mpmath, where they are exact.  The condition number
of each case is measured by perturbing every input by a relative 1e-45 and taking the
largest relative change of any output (heights relative to max(y0, |y|), as the scoring
rule), so tol_rel = max(1e-14, 16 eps cond) as in the reference README.

Run with Debian's python3 and python3-mpmath:  /usr/bin/python3 tools/gen_extreme_paths.py
"""
import csv
import sys

import mpmath as mp

mp.mp.dps = 110
EPS = mp.mpf(2) ** -52


def classify_and_eval(prof, eta0, eta1, alpha, y0, i, ds):
    """Exact outputs for one ray; returns dict of mpf / str / bool values."""
    s = 1 if prof == "inferior" else -1
    eta_p = mp.sqrt(eta0 ** 2 + s * eta1 ** 2 * (1 - mp.exp(-alpha * y0)))
    beta = eta_p * mp.sin(i)
    sg = -1 if mp.cos(i) < 0 else 1
    P = eta_p * abs(mp.cos(i)) / eta1
    k2 = mp.exp(-alpha * y0) + s * P ** 2
    out = dict(k2=k2, k=mp.sqrt(k2) if k2 > 0 else mp.nan)
    nan = mp.nan
    if s > 0:
        k = mp.sqrt(k2)
        c = alpha * eta1 * k / (2 * beta)
        yt = -mp.log(k2) / alpha
        # literal turning distance: cosh(c (z0 - zt)) = k exp(alpha y0 / 2)
        a0 = mp.acosh(k * mp.exp(alpha * y0 / 2))
        dzt = -sg * a0 / c
        y = lambda dz: yt + (2 / alpha) * mp.log(mp.cosh(c * (dz - dzt)))
        sl = lambda dz: (eta1 * k / beta) * mp.tanh(c * (dz - dzt))
        if sg < 0:
            cls = "inf_turn" if k2 < 1 else "inf_ground"
            tk = "ahead" if k2 < 1 else "below_ground"
        else:
            cls = "inf_up"
            tk = "behind" if k2 < 1 else "below_ground"
        hits = cls == "inf_ground"
        dzg = (a0 - mp.acosh(k)) / c if hits else nan
        out.update(y_turn=yt, dz_turn=dzt)
    else:
        if k2 > 0:
            kap = mp.sqrt(k2)
            c = alpha * eta1 * kap / (2 * beta)
            yM = -mp.log(k2) / alpha
            a0 = mp.acos(kap * mp.exp(alpha * y0 / 2))
            dzM = sg * a0 / c
            y = lambda dz: yM + (2 / alpha) * mp.log(mp.cos(c * (dz - dzM)))
            sl = lambda dz: -(eta1 * kap / beta) * mp.tan(c * (dz - dzM))
            cls = "sup_trapped_up" if sg > 0 else "sup_trapped_down"
            tk = "ahead" if sg > 0 else "behind"
            hits = True
            dzg = dzM + mp.acos(kap) / c
            out.update(y_turn=yM, dz_turn=dzM)
        else:
            sig = mp.sqrt(-k2)
            c = alpha * eta1 * sig / (2 * beta)
            A = mp.asinh(sig * mp.exp(alpha * y0 / 2))
            y = lambda dz: (2 / alpha) * mp.log(mp.sinh(A + sg * c * dz) / sig)
            sl = lambda dz: sg * (eta1 * sig / beta) * mp.coth(A + sg * c * dz)
            cls = "sup_escape_up" if sg > 0 else "sup_escape_down"
            tk = "none"
            hits = sg < 0
            dzg = (A - mp.asinh(sig)) / c if hits else nan
            out.update(y_turn=nan, dz_turn=nan)
    out.update(ray_class=cls, turn_kind=tk, hits_ground=hits, dz_ground=dzg,
               eta_p=eta_p, beta=beta)
    for j, d in enumerate(ds):
        out["y_d%d" % (j + 1)] = y(d)
        out["dydz_d%d" % (j + 1)] = sl(d)
    out["_y"] = y
    out["_c"] = c
    return out


NUMERIC = ["k2", "y_turn", "dz_turn", "dz_ground", "y_d1", "y_d2", "y_d3",
           "dydz_d1", "dydz_d2", "dydz_d3"]
HEIGHTS = {"y_turn", "y_d1", "y_d2", "y_d3"}


def rel_change(name, a, b, y0):
    if mp.isnan(a) or mp.isnan(b):
        return mp.mpf(0)
    scale = max(y0, abs(a)) if name in HEIGHTS else abs(a)
    if scale == 0:
        return mp.mpf(0)
    return abs(b - a) / scale


def condition(prof, inputs, ds, base):
    h = mp.mpf(10) ** -45
    worst = mp.mpf(1)
    names = ["eta0", "eta1", "alpha", "y0", "i"]
    for n in range(len(names) + 3):
        args = list(inputs)
        dd = list(ds)
        if n < len(names):
            args[n] = args[n] * (1 + h)
        else:
            dd[n - len(names)] = dd[n - len(names)] * (1 + h)
        o = classify_and_eval(prof, *args, dd)
        if o["ray_class"] != base["ray_class"]:
            continue
        for name in NUMERIC:
            worst = max(worst, rel_change(name, base[name], o[name], inputs[3]) / h)
    return worst


def pick_distances(o, y0):
    """three distances before any ground hit, spread over the interesting part"""
    if o["hits_ground"]:
        L = o["dz_ground"]
        return [L * f for f in (mp.mpf("0.13"), mp.mpf("0.52"), mp.mpf("0.91"))]
    dzt = o.get("dz_turn", mp.nan)
    if not mp.isnan(dzt) and dzt > 0:
        return [dzt * f for f in (mp.mpf("0.37"), mp.mpf("1.41"), mp.mpf("2.9"))]
    L = 4 / o["_c"]
    return [L * f for f in (mp.mpf("0.05"), mp.mpf("0.4"), mp.mpf("1.7"))]


def f17(v):
    if isinstance(v, str):
        return v
    if isinstance(v, bool):
        return "1" if v else "0"
    if mp.isnan(v):
        return "nan"
    return mp.nstr(v, 17, min_fixed=1, max_fixed=0, strip_zeros=False).replace("e+", "e")


def d17(v):
    """an input as a binary64 value printed to round-trip"""
    return repr(float(v))


def angle_for_k2(prof, eta0, eta1, alpha, y0, k2, sg):
    """angle i giving the requested k2 (exactly rounded to binary64 afterwards)"""
    s = 1 if prof == "inferior" else -1
    eta_p = mp.sqrt(eta0 ** 2 + s * eta1 ** 2 * (1 - mp.exp(-alpha * y0)))
    P2 = s * (k2 - mp.exp(-alpha * y0))
    cosi = sg * mp.sqrt(P2) * eta1 / eta_p
    return mp.acos(cosi)


def cases():
    paper = ("inferior", "1.000233", "0.4584", "2.303")
    road = ("inferior", "1.00026383734375", "0.005931939247071331", "3.3333333333333335")
    mirror = ("superior", "1.1002711548927382", "0.4584", "2.303")
    sea = ("superior", "1.0002981739360763", "0.004510955280279839", "0.2")
    hp = mp.pi / 2
    out = []
    # paper profile: several heights and angles
    for y0, el in (("1.5", -0.3), ("0.3", -0.05), ("2.5", -0.6), ("1.5", 0.4), ("0.02", -0.01)):
        out.append(("X01", paper, y0, hp - mp.mpf(el), "paper profile"))
    # k^2 = 1 -/+ 1e-12 (just turns / just touches the ground)
    for k2, tag in (("0.999999999999", "k2=1-1e-12"), ("1.000000000001", "k2=1+1e-12")):
        out.append(("X02", paper, "1.5", ("k2", mp.mpf(k2), -1), tag))
    # k -> 0: high eye, nearly level
    for y0, el in (("10", "-1e-9"), ("15", "-1e-11"), ("12", "1e-10")):
        out.append(("X03", paper, y0, hp - mp.mpf(el), "k -> 0"))
    # realistic road, grazing rays down to 1e-8 rad
    for el in ("-1e-8", "1e-8", "-1e-6", "-3e-3", "-5.5e-3"):
        out.append(("X04", road, "1.5", hp - mp.mpf(el), "hot road grazing " + el))
    # stiff alpha y0 = 2000 and 1000
    for a, y0, el in (("1000", "2", "-1e-4"), ("1000", "2", "-3e-2"), ("2000", "1", "-2e-3"),
                      ("1000", "2", "5e-3")):
        out.append(("X05", ("inferior", "1.00026383734375", "0.005931939247071331", a), y0,
                    hp - mp.mpf(el), "stiff alpha y0 = %s" % (mp.mpf(a) * mp.mpf(y0))))
    # tiny eta1
    for e1, el in (("1e-6", "-2e-7"), ("1e-8", "-3e-9"), ("1e-8", "-5e-8"), ("1e-6", "1e-5")):
        out.append(("X06", ("inferior", "1.0003", e1, "2.303"), "1", hp - mp.mpf(el),
                    "eta1 = " + e1))
    # superior near the trapped/escaping boundary: kappa^2 = +/- 1e-8, both directions
    for k2, sg in (("1e-8", 1), ("-1e-8", 1), ("1e-8", -1), ("-1e-8", -1)):
        out.append(("X07", mirror, "1", ("k2", mp.mpf(k2), sg), "kappa^2 = %s sg %d" % (k2, sg)))
    # superior, cold sea
    for el in ("2e-3", "-2e-3", "4.4e-3", "-3e-2"):
        out.append(("X08", sea, "2", hp - mp.mpf(el), "cold sea " + el))
    # rays started near the ground (reflections off the ground plane)
    for prof, el in ((paper, "0.2"), (road, "1e-3"), (mirror, "0.05"), (sea, "1e-3")):
        out.append(("X09", prof, "1e-6", hp - mp.mpf(el), "start 1 um above ground"))
    return out


def main():
    rows = []
    n = 0
    for fam, (prof, e0, e1, a), y0s, ang, desc in cases():
        n += 1
        eta0, eta1, alpha, y0 = (mp.mpf(float(v)) for v in (e0, e1, a, y0s))
        if isinstance(ang, tuple):
            ang = angle_for_k2(prof, eta0, eta1, alpha, y0, ang[1], ang[2])
        i = mp.mpf(float(ang))  # the binary64 input, exactly
        o = classify_and_eval(prof, eta0, eta1, alpha, y0, i, [1, 1, 1])
        ds = [mp.mpf(float(d)) for d in pick_distances(o, y0)]
        o = classify_and_eval(prof, eta0, eta1, alpha, y0, i, ds)
        cond = condition(prof, [eta0, eta1, alpha, y0, i], ds, o)
        tol = max(mp.mpf("1e-14"), 16 * EPS * cond)
        rows.append(dict(case_id="%s_%02d" % (fam, n), profile=prof, eta0=d17(eta0),
                         eta1=d17(eta1), alpha=d17(alpha), y0=d17(y0), i_rad=d17(i),
                         d1=d17(ds[0]), d2=d17(ds[1]), d3=d17(ds[2]),
                         k2=f17(o["k2"]), k=f17(o["k"]), y_turn=f17(o["y_turn"]),
                         dz_turn=f17(o["dz_turn"]), turn_kind=o["turn_kind"],
                         ray_class=o["ray_class"],
                         **{key: f17(o[key]) for key in ("y_d1", "y_d2", "y_d3", "dydz_d1",
                                                         "dydz_d2", "dydz_d3")},
                         hits_ground=f17(o["hits_ground"]), dz_ground=f17(o["dz_ground"]),
                         cond=mp.nstr(cond, 3), tol_rel=mp.nstr(tol, 2), description=desc))
    w = csv.DictWriter(sys.stdout, fieldnames=list(rows[0].keys()), lineterminator="\n")
    w.writeheader()
    w.writerows(rows)


if __name__ == "__main__":
    main()
