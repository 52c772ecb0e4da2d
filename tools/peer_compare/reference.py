#!/usr/bin/python3
"""The high-precision reference of tools/peer_compare.sh, and the error of each tracer against it.

    reference.py --jobs 2 PROFILE.json RAYS.csv TRACED.csv [TRACED.csv ...] > ERRORS.csv

PROFILE.json is a profile spec of tools/gen_general_paths.py (here the peer's own models, kind
'peer_model'); RAYS.csv has rows `case_id, y0, elevation_rad, d`; every TRACED.csv (one tracer
at one setting) has rows `case_id, valid, x, y, slope`: whether the tracer says the ray reaches
the distance above the ground, the horizontal distance x of the point it returned (the peer
stops a little past d), the height and the slope dy/dx there.  For each traced point the exact
height and slope at the same x come from gen_general_paths.height_at_distance (mpmath at 24
digits: turning points by bisection of n^2 - beta^2, distances by tanh-sinh quadrature, Newton on
the distance), and for each ray whether it reaches d at all.  The output has one row per file:
the rays both agree reach d, the rays whose fate differs, and the largest and median absolute
errors of height (m) and slope.
"""
import argparse
import csv
import json
import multiprocessing
import os
import statistics
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..'))
import gen_general_paths as g  # noqa: E402

mp = g.mp


def exact(args):
    spec, y0, elevation, x = args
    mp.mp.dps = 24
    prof = g.Profile(spec)
    ray = g.Ray(prof, y0, mp.pi / 2 - mp.mpf(elevation))
    y, s = g.height_at_distance(ray, mp.mpf(x))
    return (None, None) if y is None else (float(y), float(s), mp.nstr(y, 20), mp.nstr(s, 20))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--jobs', type=int, default=2)
    ap.add_argument('--points', help='also write every traced point with its reference here')
    ap.add_argument('profile')
    ap.add_argument('rays')
    ap.add_argument('traced', nargs='+')
    a = ap.parse_args()
    with open(a.profile) as f:
        spec = json.load(f)
    with open(a.rays) as f:
        rays = {r['case_id']: r for r in csv.DictReader(f)}
    traced = {}
    for path in a.traced:
        with open(path) as f:
            rows = list(csv.DictReader(f))
        if set(r['case_id'] for r in rows) != set(rays):
            sys.exit('reference.py: %s does not trace the rays of %s' % (path, a.rays))
        traced[path] = rows
    # Every distinct point once: the nominal distance d of every ray (its fate), and every x a
    # tracer returned.
    todo = set()
    for cid, r in rays.items():
        todo.add((cid, r['d']))
    for rows in traced.values():
        for r in rows:
            if r['valid'] == '1':
                todo.add((r['case_id'], r['x']))
    todo = sorted(todo)
    tasks = [(spec, float(rays[c]['y0']), float(rays[c]['elevation_rad']), float(x)) for c, x in todo]
    with multiprocessing.Pool(a.jobs) as pool:
        res = dict(zip(todo, pool.map(exact, tasks, chunksize=1)))
    out = csv.writer(sys.stdout, lineterminator='\n')
    out.writerow(['file', 'rays', 'reach_d', 'fate_differs', 'max_height_err_m',
                  'median_height_err_m', 'max_slope_err', 'median_slope_err', 'max_overshoot_m'])
    pts = csv.writer(open(a.points, 'w'), lineterminator='\n') if a.points else None
    if pts:
        pts.writerow(['file', 'case_id', 'valid', 'x', 'y', 'slope', 'y_exact', 'slope_exact'])
    for path, rows in traced.items():
        dh, ds, over, differs, reach = [], [], [], 0, 0
        for r in rows:
            ref_reaches = res[(r['case_id'], rays[r['case_id']]['d'])][0] is not None
            if (r['valid'] == '1') != ref_reaches:
                differs += 1
            if pts:
                e = res.get((r['case_id'], r['x'])) if r['valid'] == '1' else None
                pts.writerow([os.path.basename(path), r['case_id'], r['valid'], r['x'], r['y'],
                              r['slope'], e[2] if e and e[0] is not None else 'nan',
                              e[3] if e and e[0] is not None else 'nan'])
            if r['valid'] != '1' or not ref_reaches:
                continue
            e = res[(r['case_id'], r['x'])]
            if e[0] is None:
                differs += 1
                continue
            reach += 1
            dh.append(abs(float(r['y']) - e[0]))
            ds.append(abs(float(r['slope']) - e[1]))
            over.append(float(r['x']) - float(rays[r['case_id']]['d']))
        f = lambda v: '%.3g' % v
        out.writerow([os.path.basename(path), len(rows), reach, differs,
                      f(max(dh)) if dh else 'nan', f(statistics.median(dh)) if dh else 'nan',
                      f(max(ds)) if ds else 'nan', f(statistics.median(ds)) if ds else 'nan',
                      f(max(over)) if over else 'nan'])


if __name__ == '__main__':
    sys.exit(main())
