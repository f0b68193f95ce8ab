"""3-vectors as plain tuples, and the rounding of every written coordinate."""

import math


def vsub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def vdot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def vcross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def vlen(a):
    return math.sqrt(vdot(a, a))


def vmean(points):
    n = float(len(points))
    return tuple(sum(p[i] for p in points) / n for i in range(3))


def clean(x):
    """Rounds a coordinate to 4 decimals (and turns -0.0 into 0.0)."""
    return round(x, 4) + 0.0
