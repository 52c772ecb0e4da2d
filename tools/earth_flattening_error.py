#!/usr/bin/python3
"""How far the conformal Earth-flattening map is from the sphere over a wide field of view.

The map y = R ln(1 + h/R), x = R phi, n* = n (R + h)/R is exact in every plane through the
Earth's centre, so it is exact for every ray from the eye (each stays in the vertical plane of
its azimuth, which contains the centre).  A flat 3D scene traced through the flattened profile
puts the point at distance s along the ground in azimuth psi at (s cos psi, s sin psi): the
azimuthal equidistant map of the sphere about the eye's foot.  What that approximates, measured
here with exact spherical geometry (double precision vectors):

1. The scene's shapes across the view: a circle of radius s on the map is 2 pi R sin(s/R) long on
   the sphere, so transverse lengths are scaled by sin(s/R) / (s/R) = 1 - s^2 / (6 R^2); a point
   at azimuth psi off the view's centre is displaced across by s psi (1 - sin(s/R)/(s/R)).
2. Rays that do not start at the eye (reflected and shadow rays): each follows its own great
   circle, which the map draws as a curve, not as the straight line a flat tracer follows; the
   table gives the largest sideways distance between them over the ray's length, for a ray
   starting s from the eye across the line of sight (the worst direction).
3. Heights: exact through y = R ln(1 + h/R) when the scene's heights are mapped; left unmapped, a
   height h is off by h^2 / (2R) (7.9 cm at 1 km, 7.9 um at 10 m).

Usage: /usr/bin/python3 tools/earth_flattening_error.py
"""
import math

R = 6371000.0


def unit(v):
    n = math.sqrt(sum(c * c for c in v))
    return [c / n for c in v]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def on_sphere(s, psi):
    """The ground point at arc distance s, azimuth psi from the eye's foot (north pole (0,0,1),
    azimuth 0 along +x)."""
    a = s / R
    return [math.sin(a) * math.cos(psi), math.sin(a) * math.sin(psi), math.cos(a)]


def azimuthal_equidistant(p):
    """Flat map coordinates of the unit-sphere point p about the pole."""
    a = math.acos(max(-1.0, min(1.0, p[2])))
    psi = math.atan2(p[1], p[0])
    return [R * a * math.cos(psi), R * a * math.sin(psi)]


def great_circle_offset(s, length, steps=400):
    """Largest distance, on the map, between the great circle that leaves the ground point at
    distance s (azimuth 0) across the line of sight (heading +y on the map) and the straight
    line a flat tracer follows from there with the same map direction."""
    p = on_sphere(s, 0.0)
    east = unit(cross([0.0, 0.0, 1.0], p))  # the local direction of increasing azimuth
    x0 = azimuthal_equidistant(p)
    # The map's direction of that heading at p: along +y (the map's azimuth direction at psi = 0).
    worst = 0.0
    for k in range(1, steps + 1):
        t = length * k / steps / R
        q = [math.cos(t) * p[i] + math.sin(t) * east[i] for i in range(3)]
        m = azimuthal_equidistant(q)
        # The flat line: x = x0, y = distance travelled (scaled by the map's transverse scale at
        # the start, so that both start with the same map speed).
        scale = (s / R) / math.sin(s / R)
        line = [x0[0], x0[1] + length * k / steps * scale]
        worst = max(worst, math.hypot(m[0] - line[0], m[1] - line[1]))
    return worst


def main():
    print('1. Transverse scale of the flat scene (azimuthal equidistant about the eye)')
    print('   distance s   1 - sin(s/R)/(s/R)   sideways shift at 30 deg off the centre')
    for s in (1e3, 5e3, 10e3, 30e3, 50e3, 100e3):
        d = 1.0 - math.sin(s / R) / (s / R)
        print('   %7.0f m    %.3e            %.3g m' % (s, d, s * math.radians(30.0) * d))
    print()
    print('2. Rays not from the eye: sideways distance between the great circle and the flat line')
    print('   start s      length 100 m   1 km        5 km        20 km')
    for s in (1e3, 10e3, 30e3, 50e3):
        row = ['%.3g m' % great_circle_offset(s, L) for L in (100.0, 1e3, 5e3, 20e3)]
        print('   %7.0f m    ' % s + '   '.join('%-9s' % r for r in row))
    print()
    print('3. Heights left unmapped: h - R ln(1 + h/R) = h^2/(2R) - ...')
    for h in (1.0, 10.0, 100.0, 1000.0):
        print('   h = %6.0f m: %.3g m' % (h, h - R * math.log1p(h / R)))


if __name__ == '__main__':
    main()
