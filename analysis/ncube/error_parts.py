"""The error of a solution taken apart, with 95 % intervals (docs/accuracy.md, "The error taken
apart").

For a solution of the scene's elements (./simulate's --mesh of a run without --subdivide, or any
file of the reference's layout):

(a) total error: per element against the reference (analysis/reference/<scene>.json), per
    patch against Cycles' answers (analysis/cycles/<scene>.json);
(b) form-factor error: against the exact solution of the same structure (same mesh, receivers
    at element centres, a patch shooting its elements' mean; exact form factors:
    analysis/reference/structure/<scene>-patches.json, build/reference_solution --structure);
(c) the structure's own error: the exact structures (patches, and every element its own patch)
    against the truth, as in (a);
(d) the power balance: the emitted power against what the patches absorb,
    sum A (1 - rho) H with H = (B - E) / rho per element and colour (every reflectance of the
    scenes is > 0), and where the rest goes.

The error of an element or a patch, its dark floor and the RMS are the one measure of
analysis/ncube/error_measure.py (docs/accuracy.md, "The error measure"): the symmetric relative
difference (Y - Y_t) / ((Y + Y_t) / 2), area-weighted RMS, an item whose truth is below FLOOR of
the area-weighted mean luminance of the truth's non-emitting ones left out (`left_out`, counted
on the page), the same as analysis/ncube/accuracy.py's.

Intervals (the methods are deterministic: the paper's rays go to the parts' centroids, the
hemicube has no random element, so there are no seeds to repeat): a paired bootstrap over
patches, BOOTSTRAP draws of the scene's patches with replacement (a patch with all its
elements), the same draws for every solution of a scene (so ratios are paired), seed SEED;
each RMS is further widened in every draw by the error of its truth: the exact structure's
self-agreement (K/4 against K, halved: own_error) for (b); for (a) per patch, Cycles' standard
error drawn as normal noise on its answers in every draw; for (a) per element, the reference's
halved self-agreement (element RMS) plus its patch RMS against Cycles, added to the ends (a triangle inequality of
RMS errors, with the reference's element error estimated, not bounded). The 95 % interval is
the 2.5th percentile of the draws' low ends to the 97.5th of their high ends."""

import json
import math

# numpy (0.1 s of CPU a start) is imported by the functions that use it: --help and refusals need none.

from ncube import error_measure, input_file
from ncube.accuracy import LUMINANCE, solution_from_ply

FLOOR = error_measure.FLOOR
BOOTSTRAP = 2000      # draws of the patches
SEED = 1994
LEVEL = 0.95
_BYTES = 512 << 20


class Solution:
    """Per element: patch, area, rgb (n x 3), from a reference-layout file or a mesh."""

    def __init__(self, patch, area, rgb):
        import numpy as np
        self.patch = np.asarray(patch, dtype=int)
        self.area = np.asarray(area, dtype=float)
        self.rgb = np.asarray(rgb, dtype=float).reshape(-1, 3)
        self.y = self.rgb @ _luma()
        self.patches = int(self.patch.max()) + 1
        self.patch_area = np.bincount(self.patch, self.area, self.patches)
        self.patch_rgb = np.stack([np.bincount(self.patch, self.area * self.rgb[:, c], self.patches)
                                   for c in range(3)], axis=1) / self.patch_area[:, None]
        self.patch_y = self.patch_rgb @ _luma()


def _luma():
    import numpy as np
    return np.array(LUMINANCE)


def read_json(path, what):
    return json.loads(input_file.read_input_text(path, what, _BYTES))


def reference_solution(data):
    """A Solution from a reference-layout file's parsed JSON (the reference, a structure)."""
    import numpy as np
    e = np.array(data["elements"], dtype=float)
    return Solution(e[:, 0].astype(int), e[:, 1], e[:, 2:5])


def mesh_solution(path, like):
    """A Solution from ./simulate's --mesh, with the areas of `like` (same element grid)."""
    import numpy as np
    faces = solution_from_ply(path)
    patch = np.array([p for p, _ in faces], dtype=int)
    if len(faces) != len(like.area) or not np.array_equal(patch, like.patch):
        raise ValueError(f"{path}: not the element grid of the reference")
    return Solution(patch, like.area, np.array([rgb for _, rgb in faces]))


def scene_materials(path):
    """Per patch: emission (p x 3) and reflectance (p x 3) from the scene file."""
    import numpy as np
    scene = read_json(path, "scene file")
    emission = np.array([p.get("emission", [0.0, 0.0, 0.0]) for p in scene["patches"]], dtype=float)
    reflectance = np.array([p["reflectance"] for p in scene["patches"]], dtype=float)
    return emission, reflectance


class Truth:
    """What a measure compares against: per element or per patch luminances, the floor, and
    how it is uncertain (`noise`: a standard error per patch drawn in every bootstrap draw;
    `widen`: added to the RMS's ends)."""

    def __init__(self, y, weight, patch_of, patches, emitting, noise=None, widen=0.0):
        import numpy as np
        self.y = np.asarray(y, dtype=float)
        self.weight = np.asarray(weight, dtype=float)
        self.patch_of = np.asarray(patch_of, dtype=int)
        self.patches = patches
        self.floor = error_measure.dark_floor(self.y, self.weight, emitting)
        # Darker than the floor: no relative error of its own, left out of the RMS (the one
        # measure: error_measure.kept).
        self.left_out = ~error_measure.kept(self.y, self.floor)
        self.weight = np.where(self.left_out, 0.0, self.weight)
        self.noise = None if noise is None else np.asarray(noise, dtype=float)
        self.widen = widen


def element_truth(solution, emission, widen=0.0):
    return Truth(solution.y, solution.area, solution.patch, solution.patches,
                 (emission[solution.patch] @ _luma()) > 0, widen=widen)


def patch_truth(y, area, emission, noise=None, widen=0.0):
    import numpy as np
    n = len(y)
    return Truth(y, area, np.arange(n), n, (emission[:n] @ _luma()) > 0, noise=noise, widen=widen)


def _draws(patches):
    import numpy as np
    rng = np.random.default_rng(SEED)
    return rng.multinomial(patches, np.full(patches, 1.0 / patches), size=BOOTSTRAP)


def relative(y, truth):
    """Per item the measure's difference (error_measure.difference)."""
    return error_measure.difference(y, truth.y)


def rms(y, truth):
    import numpy as np
    r = relative(y, truth)
    return float(math.sqrt(np.sum(truth.weight * r * r) / np.sum(truth.weight)))


def _replicates(y, truth, counts):
    """The RMS in every bootstrap draw (counts: draws x patches)."""
    import numpy as np
    if truth.noise is None:
        r = relative(y, truth)
        per_patch = np.bincount(truth.patch_of, truth.weight * r * r, truth.patches)
        weight = np.bincount(truth.patch_of, truth.weight, truth.patches)
        return np.sqrt(counts @ per_patch / (counts @ weight))
    rng = np.random.default_rng(SEED + 1)
    noisy = truth.y[None, :] + truth.noise[None, :] * rng.standard_normal((len(counts), len(truth.y)))
    r = error_measure.difference(np.asarray(y)[None, :], np.maximum(noisy, 0.0))
    return np.sqrt(np.sum(counts * truth.weight * r * r, axis=1) / (counts @ truth.weight))


def interval(y, truth):
    """(RMS, low, high): the 95 % interval of the module's docstring."""
    import numpy as np
    draws = _replicates(y, truth, _draws(truth.patches))
    tail = (1 - LEVEL) / 2
    return (rms(y, truth), float(np.quantile(np.maximum(draws - truth.widen, 0.0), tail)),
            float(np.quantile(draws + truth.widen, 1 - tail)))


def ratio_interval(y_numerator, y_denominator, truth):
    """RMS(numerator) / RMS(denominator) against one truth, paired (the same draws), each RMS
    widened by the truth's own error: (ratio, low, high)."""
    import numpy as np
    counts = _draws(truth.patches)
    top = _replicates(y_numerator, truth, counts)
    bottom = _replicates(y_denominator, truth, counts)
    w = truth.widen
    tail = (1 - LEVEL) / 2
    low = np.maximum(top - w, 0.0) / (bottom + w)
    with np.errstate(divide="ignore"):
        high = np.where(bottom - w > 0, (top + w) / np.maximum(bottom - w, 1e-300), np.inf)
    return (rms(y_numerator, truth) / rms(y_denominator, truth),
            float(np.quantile(low, tail)), float(np.quantile(high, 1 - tail)))


def own_error(agreement):
    """The error of a solution of K points a pair estimated from its self-agreement (its K/4
    solution against it): half of it. The K/4 solution's sampling error is twice the K one's at
    the Monte Carlo rate 1/sqrt(K) (stratified points converge faster, so this overestimates),
    and the two differ by about sqrt(2^2 + 1) = 2.2 times the K one's when independent."""
    return agreement / 2.0


def self_agreement(structure_data, emission):
    """The exact structure's own error under this module's measure: its K/4 solution against
    its K solution (element RMS, patch RMS)."""
    import numpy as np
    main = reference_solution(structure_data)
    check_y = np.asarray(structure_data["check_luminance"], dtype=float)
    patch_check = np.bincount(main.patch, main.area * check_y, main.patches) / main.patch_area
    return (rms(check_y, element_truth(main, emission)),
            rms(patch_check, patch_truth(main.patch_y, main.patch_area, emission)))


def balance(solution, emission, reflectance, delivery=None, shooter_of=None):
    """The power balance of a solution (luminance-weighted power, scene units): emitted,
    absorbed (sum A (1 - rho) H, H = (B - E) / rho), and, with the exact structure's `delivery`
    (per shooter: the share of what it sends that the element centres receive), what the
    structure's centre form factors fail to deliver of what this solution's shooters hold:
    lost = sum_s A_s Y(Bbar_s) (1 - s_s). `shooter_of`: per element its shooter (the patch, or
    itself when every element is its own patch). Returns a dict of powers and shares."""
    import numpy as np
    e = emission[solution.patch]
    rho = reflectance[solution.patch]
    emitted = float(np.sum(solution.area * (e @ _luma())))
    irradiance = (solution.rgb - e) / rho
    absorbed = float(np.sum(solution.area * (((1 - rho) * irradiance) @ _luma())))
    out = {"emitted": emitted, "absorbed": absorbed, "absorbed_share": absorbed / emitted,
           "deficit_share": 1 - absorbed / emitted}
    if delivery is not None:
        delivery = np.asarray(delivery, dtype=float)
        if shooter_of is None:
            sent = solution.patch_area * solution.patch_y
        else:
            sent = np.bincount(shooter_of, solution.area * solution.y, len(delivery))
        lost = float(np.sum(sent * (1 - delivery)))
        out["structure_lost_share"] = lost / emitted
        out["rest_share"] = out["deficit_share"] - lost / emitted
    return out


def cycles_balance(cycles, emission, reflectance):
    """Cycles' balance per patch: absorbed share and its standard error (the channels' standard
    errors taken independent)."""
    import numpy as np
    rows = np.array(cycles["patches"], dtype=float)
    area, rgb, se = rows[:, 1], rows[:, 2:5], rows[:, 5:8]
    e, rho = emission[: len(rows)], reflectance[: len(rows)]
    emitted = float(np.sum(area * (e @ _luma())))
    per = area[:, None] * (1 - rho) / rho * _luma()[None, :]
    absorbed = float(np.sum(per * (rgb - e)))
    se_absorbed = float(math.sqrt(np.sum((per * se) ** 2)))
    return {"emitted": emitted, "absorbed": absorbed, "absorbed_share": absorbed / emitted,
            "absorbed_share_se": se_absorbed / emitted}


def leaving_share(cycles, emission, reflectance):
    """The share of the emitted power that leaves the scene, as the truth has it: what Cycles'
    patches do not absorb, 1 - absorbed share, with its 95 % interval (+-1.96 se). In a closed
    scene it is 0 but for Cycles' own error; in the open Cornell box it is the light through the
    open front. Taken as the same for every answer of the scene (an answer that sends its light
    in other proportions loses another share through the opening: docs/accuracy.md)."""
    c = cycles_balance(cycles, emission, reflectance)
    share, se = 1 - c["absorbed_share"], c["absorbed_share_se"]
    return share, share - 1.96 * se, share + 1.96 * se


def split_loss(balance_, leaving):
    """The structure's loss taken apart: what leaves the scene (`leaving`, a share) and the
    structure's own loss, the rest of it (what exact centre form factors would fail to deliver
    that the truth delivers)."""
    if leaving is None or "structure_lost_share" not in balance_:
        return None, None
    return leaving, balance_["structure_lost_share"] - leaving
