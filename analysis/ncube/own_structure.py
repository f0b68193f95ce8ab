"""Each method against the exact solution of its own structure, and error against cost
(docs/accuracy.md, "Each method against its own structure" and "Error against cost").

The form-factor error (b) of analysis/ncube/error_parts.py holds every method against the
receiver-centred exact structure (receivers at element centres). That is the paper's rays'
own structure; it is not the hemicube's: the hemicube reads a receiver off by the cells its
whole polygon covers, seen from an eye on the shooter, and turns that point factor around by
reciprocity. Its own exact structures (build/reference_solution --structure
hemicube-centre | hemicube-elements, analysis/reference/structure/<scene>-hemicube-*.json)
have exact point-to-element factors from the same eyes with the same reciprocity, so that a
hemicube run's difference from its own structure is its form factors' error alone: aliasing,
the cells' midpoint rule, and nothing of the eye's placement.

Which measure decides what (chosen before the runs, docs/accuracy.md):

* the first claim, about form factors: (b) against each method's own structure (the hemicube
  at the centre against hemicube-centre, at the elements against hemicube-elements, the rays
  against the receiver-centred structure), per element and per patch;
* what a user sees: (a), the total error per patch against Cycles, which no structure enters.

Both are decided by analysis/ncube/claim_one.py's rule (ratio and its interval's low end at
least 2: "much", the project's convention), with the paired bootstrap over patches of
error_parts.py; a ratio of two errors against two different truths uses the same draws of
patches for both.

Error against cost: per scene and measure, every converged cell's error against its simulated
and its host seconds; a cell is on the front when no other cell is at most as costly and has
a lower error (the cheapest setting for its error). At equal cost: for each of the rays' cells,
the hemicube's best error among its cells that cost at most as much, against the rays' error,
decided by the same rule."""

import math

# numpy (0.1 s of CPU a start) is imported by the functions that use it: --help and refusals need none.

from ncube import claim_one, error_parts

PLACEMENTS = ("centre", "elements")


def structure_path(root, scene, placement):
    return root / "analysis" / "reference" / "structure" / f"{scene}-hemicube-{placement}.json"


class OwnTruths:
    """A scene's hemicube structures as truths of (b) (per element and per patch), widened by
    their own error (half their self-agreement, as error_parts does for the structure)."""

    def __init__(self, root, scene, scene_sha256, emission):
        self.data, self.solution, self.element, self.patch = {}, {}, {}, {}
        for placement in PLACEMENTS:
            path = structure_path(root, scene, placement)
            if not path.exists():
                continue
            data = error_parts.read_json(path, "the hemicube's exact structure")
            if data.get("scene_sha256") != scene_sha256:
                raise ValueError(f"{path} is of another {scene} (its scene_sha256 differs): "
                                 "run experiments/claims/references --structures again")
            solution = error_parts.reference_solution(data)
            own_element, own_patch = error_parts.self_agreement(data, emission)
            self.data[placement] = data
            self.solution[placement] = solution
            self.element[placement] = error_parts.element_truth(
                solution, emission, widen=error_parts.own_error(own_element))
            self.patch[placement] = error_parts.patch_truth(
                solution.patch_y, solution.patch_area, emission,
                widen=error_parts.own_error(own_patch))


def truth_of(row, own, scene_truths, measure):
    """The (b) truth of a row's own structure for `measure` ("element", "patch"): the hemicube's
    for a hemicube cell (None when not committed), the receiver-centred one for the rays."""
    if row["form_factors"] == "hemicube":
        table = own.element if measure == "element" else own.patch
        return table.get(row["placement"])
    return scene_truths.b_element if measure == "element" else scene_truths.b_patch


def values(solution, measure):
    return solution.y if measure == "element" else solution.patch_y


def ratio_interval(y_top, truth_top, y_bottom, truth_bottom):
    """RMS(top against its truth) / RMS(bottom against its truth), paired over the same draws
    of patches, each widened by its own truth's error: (ratio, low, high)."""
    import numpy as np
    if truth_top.patches != truth_bottom.patches:
        raise ValueError("the two truths have different patches")
    counts = error_parts._draws(truth_top.patches)
    top = error_parts._replicates(y_top, truth_top, counts)
    bottom = error_parts._replicates(y_bottom, truth_bottom, counts)
    tail = (1 - error_parts.LEVEL) / 2
    low = np.maximum(top - truth_top.widen, 0.0) / (bottom + truth_bottom.widen)
    with np.errstate(divide="ignore"):
        high = np.where(bottom - truth_bottom.widen > 0,
                        (top + truth_top.widen) / np.maximum(bottom - truth_bottom.widen, 1e-300),
                        np.inf)
    return (error_parts.rms(y_top, truth_top) / error_parts.rms(y_bottom, truth_bottom),
            float(np.quantile(low, tail)), float(np.quantile(high, 1 - tail)))


def own_errors(rows, solutions, own, truths):
    """Adds to every row "b_own_element" and "b_own_patch": (rms, low, high) against its own
    structure, or None (a hemicube placement whose structure is not committed)."""
    for r in rows:
        for measure in ("element", "patch"):
            truth = truth_of(r, own[r["scene"]], truths[r["scene"]], measure)
            r[f"b_own_{measure}"] = None if truth is None else error_parts.interval(
                values(solutions[r["id"]], measure), truth)
    return rows


def decidable(rows, scene):
    """The scene's converged cells at V = 0: (rays under receivers, hemicube cells)."""
    mine = [r for r in rows if r["scene"] == scene and r["V"] == 0 and r["status"] == "ok"
            and r["converged"]]
    rays = [r for r in mine if r["form_factors"] == "ray-traced" and r["parallelisation"] == "receivers"]
    return rays, [r for r in mine if r["form_factors"] == "hemicube"]


MEASURES = (("b_own_element", "form-factor error (b), own structure, per element"),
            ("b_own_patch", "form-factor error (b), own structure, per patch"),
            ("a_patch", "total error (a) per patch against Cycles"))


def decide(rows, solutions, own, truths):
    """Every converged hemicube cell against the paper's method at its largest M on the same
    scene, on each measure of MEASURES: [{scene, measure, placement, resolution, samples,
    rays, hemicube, ratio, low, high, verdict}]."""
    out = []
    for scene in sorted({r["scene"] for r in rows}):
        rays, hemicube = decidable(rows, scene)
        if not rays or not hemicube:
            continue
        best = max(rays, key=lambda r: r["value"])
        for key, _ in MEASURES:
            for h in sorted(hemicube, key=lambda r: (r["placement"], r["value"])):
                if h.get(key) is None or best.get(key) is None:
                    continue
                ratio, low, high = pair_ratio(h, best, key, solutions, own, truths)
                out.append({"scene": scene, "measure": key, "placement": h["placement"],
                            "resolution": h["value"], "samples": best["value"],
                            "rays": best[key], "hemicube": h[key], "ratio": ratio, "low": low,
                            "high": high, "verdict": claim_one.verdict(ratio, low, high)})
    return out


def pair_ratio(top, bottom, key, solutions, own, truths):
    """(ratio, low, high) of top's error over bottom's on measure `key`, paired."""
    scene = top["scene"]
    if key == "a_patch":
        truth = truths[scene].a_patch
        return error_parts.ratio_interval(solutions[top["id"]].patch_y,
                                          solutions[bottom["id"]].patch_y, truth)
    measure = "element" if key == "b_own_element" else "patch"
    return ratio_interval(values(solutions[top["id"]], measure),
                          truth_of(top, own[scene], truths[scene], measure),
                          values(solutions[bottom["id"]], measure),
                          truth_of(bottom, own[scene], truths[scene], measure))


def front(points):
    """The indices of `points` [(cost, error)] on the front: no other point at most as costly
    with a lower error (ties in both: the first kept)."""
    keep = []
    for i, (cost, error) in enumerate(points):
        beaten = any((c <= cost and e < error) or (c < cost and e <= error) or
                     (c == cost and e == error and j < i)
                     for j, (c, e) in enumerate(points) if j != i)
        if not beaten:
            keep.append(i)
    return keep


def cost_rows(rows, scene, key, cost):
    """The scene's converged V = 0 cells with the measure, each with "on_front" for `cost`
    ("simulated_seconds" or "host_seconds")."""
    rays, hemicube = decidable(rows, scene)
    cells = [r for r in rays + hemicube if r.get(key) is not None]
    on = set(front([(r[cost], r[key][0]) for r in cells]))
    return [dict(r, on_front=(i in on)) for i, r in enumerate(cells)]


def at_equal_cost(rows, solutions, own, truths, key, cost="simulated_seconds"):
    """For each scene and each of the rays' cells: the hemicube's best error among its cells
    costing at most as much (None when none does), and the ratio hemicube / rays with its
    interval and verdict."""
    out = []
    for scene in sorted({r["scene"] for r in rows}):
        rays, hemicube = decidable(rows, scene)
        for ray in sorted(rays, key=lambda r: r["value"]):
            if ray.get(key) is None:
                continue
            within = [h for h in hemicube if h[cost] <= ray[cost] and h.get(key) is not None]
            if not within:
                out.append({"scene": scene, "rays": ray, "hemicube": None})
                continue
            h = min(within, key=lambda r: (r[key][0], r[cost]))
            ratio, low, high = pair_ratio(h, ray, key, solutions, own, truths)
            out.append({"scene": scene, "rays": ray, "hemicube": h, "ratio": ratio, "low": low,
                        "high": high, "verdict": claim_one.verdict(ratio, low, high)})
    return out


def above_one(run_result):
    """The run's count of receivers whose reciprocal form factor came out above 1 (its result
    file's counts; None for a run that does not write it)."""
    return run_result.get("counts", {}).get("hemicube_reciprocal_above_one")


def polygon_centroid(vertices):
    """Area centroid of a planar polygon (a fan of triangles from its first corner)."""
    import numpy as np
    v = np.asarray(vertices, dtype=float)
    total, centre = 0.0, np.zeros(3)
    for k in range(1, len(v) - 1):
        area = np.linalg.norm(np.cross(v[k] - v[0], v[k + 1] - v[0])) / 2
        total += area
        centre += area * (v[0] + v[k] + v[k + 1]) / 3
    return centre / total


def normal_of(vertices):
    import numpy as np
    v = np.asarray(vertices, dtype=float)
    n = np.cross(v[1] - v[0], v[2] - v[0])
    return n / np.linalg.norm(n)


def proximity(scene, structure_data, placement):
    """The scene's proximity accidents, from a hemicube structure's "above_one" (every
    (element, shooter) whose exact factor by reciprocity is above 1): grouped by (shooter,
    receiving patch), with the distance from the nearest of the shooter's eyes to the
    receiver's plane. [{shooter, receiver, elements, largest, distance}], nearest first."""
    import numpy as np
    patches = scene["patches"]
    element_patch = [int(e[0]) for e in structure_data["elements"]]
    groups = {}
    for element, shooter, factor in structure_data.get("above_one", []):
        key = (int(shooter), element_patch[int(element)])
        count, top = groups.get(key, (0, 0.0))
        groups[key] = (count + 1, max(top, factor))
    out = []
    for (shooter, receiver), (count, top) in groups.items():
        v = np.asarray(patches[receiver]["vertices"], dtype=float)
        n_r = normal_of(v)
        distance = min(float(np.dot(n_r, eye - v[0])) for eye in eyes(patches[shooter], placement))
        out.append({"shooter": shooter, "receiver": receiver, "elements": count,
                    "largest": top, "distance": distance})
    return sorted(out, key=lambda g: (g["distance"], g["shooter"], g["receiver"]))


def eyes(patch, placement):
    """The eyes of a shooter, as src/radiosity/hemicube.cpp places them: its centroid, or the
    centroids of its nu x nv grid's cells (bilinear)."""
    import numpy as np
    v = np.asarray(patch["vertices"], dtype=float)
    if placement == "centre" or len(v) != 4:
        return [polygon_centroid(v)]
    nu, nv = patch.get("elements", [1, 1])
    out = []
    for j in range(nv):
        for i in range(nu):
            corners = [bilinear(v, (i + a) / nu, (j + b) / nv) for a, b in ((0, 0), (1, 0), (1, 1), (0, 1))]
            out.append(polygon_centroid(corners))
    return out


def bilinear(v, s, t):
    return (1 - s) * (1 - t) * v[0] + s * (1 - t) * v[1] + s * t * v[2] + (1 - s) * t * v[3]


def polygon_area(vertices):
    import numpy as np
    v = np.asarray(vertices, dtype=float)
    return float(sum(np.linalg.norm(np.cross(v[k] - v[0], v[k + 1] - v[0])) / 2
                     for k in range(1, len(v) - 1)))


def inside(point, vertices, normal):
    """Whether `point` (in the polygon's plane) lies inside the convex polygon."""
    import numpy as np
    v = np.asarray(vertices, dtype=float)
    signs = [np.dot(np.cross(v[(k + 1) % len(v)] - v[k], point - v[k]), normal) for k in range(len(v))]
    return all(x >= 0 for x in signs) or all(x <= 0 for x in signs)
