"""Element subdivision with an exact total."""

import heapq
import math

from .targets import MAX_SUBDIVISION
from .vectors import vcross, vlen, vsub


def edge_lengths(p):
    v = p["v"]
    e1 = vsub(v[1], v[0])
    lu = vlen(e1)
    if len(v) == 4:
        return lu, vlen(vsub(v[3], v[0]))
    return lu, vlen(vcross(e1, vsub(v[2], v[0]))) / lu


def fit_elements(patches, target, cap=None, size_factors=None):
    """Sets every patch's nu, nv so that elements are about h x h for one h over the whole
    scene (so element counts follow patch areas), then refines the coarsest directions one
    step at a time until the total is exactly `target`; a refinement never takes a patch
    beyond `cap` elements. `size_factors` (one a patch; None: all 1) makes a patch's elements
    that many times larger than h (scenes/generator/choices.py, piece_element_size).
    Deterministic."""
    lengths = [edge_lengths(p) for p in patches]
    if size_factors is not None:
        lengths = [(lu / f, lv / f) for (lu, lv), f in zip(lengths, size_factors)]

    def capped(nu, nv):
        # A patch over the cap keeps its shape but gets coarser elements.
        if cap is None or nu * nv <= cap:
            return nu, nv
        f = math.sqrt(cap / float(nu * nv))
        nu, nv = max(1, int(nu * f)), max(1, int(nv * f))
        while nu * nv > cap:
            nu, nv = (nu - 1, nv) if nu >= nv else (nu, nv - 1)
        return nu, nv

    def grid(h, lu, lv):
        return capped(min(MAX_SUBDIVISION, max(1, math.ceil(lu / h - 1e-9))),
                      min(MAX_SUBDIVISION, max(1, math.ceil(lv / h - 1e-9))))

    def counts(h):
        return [grid(h, lu, lv) for lu, lv in lengths]

    # The bisection only needs totals: each distinct patch shape once, times its number
    # (scene4 repeats the same rooms many times).
    shapes = {}
    for lu_lv in lengths:
        shapes[lu_lv] = shapes.get(lu_lv, 0) + 1

    def total_at(h):
        total = 0
        for (lu, lv), n in shapes.items():
            nu, nv = grid(h, lu, lv)
            total += n * nu * nv
        return total

    def total(cs):
        return sum(nu * nv for nu, nv in cs)

    lo, hi = 1e-4, 1e4  # total_at(lo) > target >= total_at(hi)
    if total_at(lo) <= target or total_at(hi) > target:
        raise SystemExit("fit_elements: target %d out of reach" % target)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if not lo < mid < hi:
            break  # lo and hi are neighbouring floats: nothing changes any more
        if total_at(mid) <= target:
            hi = mid
        else:
            lo = mid
    cs = [list(c) for c in counts(hi)]
    remaining = target - total(cs)
    # Greedy refinement: always split the longest element edge whose extra elements still fit.
    heap = []

    def push(i):
        nu, nv = cs[i]
        lu, lv = lengths[i]
        if nu < MAX_SUBDIVISION:
            heapq.heappush(heap, (-(lu / nu), i, 0, nu, nv))
        if nv < MAX_SUBDIVISION:
            heapq.heappush(heap, (-(lv / nv), i, 1, nu, nv))

    for i in range(len(patches)):
        push(i)
    while remaining > 0:
        if not heap:
            raise SystemExit("fit_elements: cannot reach exactly %d elements" % target)
        _, i, direction, nu, nv = heapq.heappop(heap)
        if [nu, nv] != cs[i]:
            continue  # stale entry
        delta = nv if direction == 0 else nu
        if delta > remaining or (cap is not None and nu * nv + delta > cap):
            continue  # only grows: never usable again
        cs[i][direction] += 1
        remaining -= delta
        push(i)
    for p, (nu, nv) in zip(patches, cs):
        p["nu"], p["nv"] = nu, nv
