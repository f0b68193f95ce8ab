"""The one error measure of a solution against a truth, per element and per patch
(docs/accuracy.md, "The error measure"). Every study and tool takes its errors from here:
analysis/ncube/accuracy.py (the command and the claims' schemes), analysis/ncube/error_parts.py
(the claims' error taken apart, with intervals) and the claims scripts through them.

For luminances Y (a solution) and T (its truth, both Rec. 709), weights w (areas) and, per item,
whether it emits:

* the dark floor f = FLOOR x the w-weighted mean of T over the items that do not emit;
* an item whose truth is below the floor (T < f) is left out: in the dark (the ceiling above
  the Cornell box's light at 1e-7 of the walls, a floor element whose centre lies under a
  block) an error relative to the truth means nothing, and one such item would be most of
  the RMS;
* every other item's error is the symmetric relative difference
      d = (Y - T) / ((Y + T) / 2),
  between -2 (a black answer) and +2 (an answer infinitely bright);
* the figure is the w-weighted RMS of d over the items kept.

Why symmetric, not (Y - T) / T: the plain relative error costs an answer k times too bright
k - 1 and any answer too dark at most 1, so a solution with no light transport at all (every
reflector black, B = E) scored better than a converged method that overshoots a few elements
(measured: 0.99 against 1.29 per element on the Cornell box for the hemicube at the shooter's
centre). Symmetric, a black reflector costs the most any answer can (2), so B = E is worse than
every solution that carries light (tests/error_measure_test.py holds it on every scene with a
reference); for small errors d and the relative error agree to first order (d = r - r^2/2 + ...).
"""

# numpy (0.1 s of CPU a start) is imported by the functions that use it: --help and refusals need none.

FLOOR = 0.01          # of the mean luminance: an item darker has no relative error of its own


def dark_floor(truth, weight, emitting):
    """FLOOR x the weighted mean of the truth over the items that do not emit."""
    import numpy as np
    truth, weight = np.asarray(truth, dtype=float), np.asarray(weight, dtype=float)
    dark = ~np.asarray(emitting, dtype=bool)
    if not np.any(dark) or np.sum(weight[dark]) <= 0:
        dark = np.ones(len(truth), dtype=bool)
    return FLOOR * float(np.sum(weight[dark] * truth[dark]) / np.sum(weight[dark]))


def kept(truth, floor):
    """The items the measure counts: truth at or above the floor."""
    import numpy as np
    return np.asarray(truth, dtype=float) >= floor


def difference(y, truth):
    """The symmetric relative difference (Y - T) / ((Y + T) / 2); 0 where both are 0."""
    import numpy as np
    y, truth = np.asarray(y, dtype=float), np.asarray(truth, dtype=float)
    mean = (y + truth) / 2
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(mean > 0, (y - truth) / np.where(mean > 0, mean, 1.0), 0.0)


def rms(y, truth, weight, floor):
    """The weighted RMS of the difference over the items kept (0 when none is)."""
    import numpy as np
    w = np.where(kept(truth, floor), np.asarray(weight, dtype=float), 0.0)
    if np.sum(w) <= 0:
        return 0.0
    d = difference(y, truth)
    return float(np.sqrt(np.sum(w * d * d) / np.sum(w)))


def patch_means(values, area, patch, patches):
    """Per patch the area-weighted mean of its elements' values (a patch no element has: 0)."""
    import numpy as np
    area = np.asarray(area, dtype=float)
    total = np.bincount(patch, area, patches)
    sums = np.bincount(patch, area * np.asarray(values, dtype=float), patches)
    return np.where(total > 0, sums / np.where(total > 0, total, 1.0), 0.0), total


def measure(y, truth, area, patch, patch_emits):
    """Per element and per patch: {element_rms, patch_rms, patch_max, worst_patch, per_element,
    per_patch, element_floor, patch_floor, left_out_elements, left_out_patches}; per_element and
    per_patch hold None where an item is left out. patch: per element its patch index;
    patch_emits: per patch whether it emits."""
    import numpy as np
    patch = np.asarray(patch, dtype=int)
    patch_emits = np.asarray(patch_emits, dtype=bool)
    patches = len(patch_emits)
    area = np.asarray(area, dtype=float)
    y, truth = np.asarray(y, dtype=float), np.asarray(truth, dtype=float)
    e_floor = dark_floor(truth, area, patch_emits[patch])
    py, parea = patch_means(y, area, patch, patches)
    pt, _ = patch_means(truth, area, patch, patches)
    present = parea > 0
    p_floor = dark_floor(pt[present], parea[present], patch_emits[present])
    e_kept, p_kept = kept(truth, e_floor), kept(pt, p_floor) & present
    d_e, d_p = difference(y, truth), difference(py, pt)
    worst = int(np.argmax(np.where(p_kept, np.abs(d_p), -1.0))) if np.any(p_kept) else -1
    return {"element_rms": rms(y, truth, area, e_floor),
            "patch_rms": rms(py, pt, np.where(present, parea, 0.0), p_floor),
            "patch_max": float(abs(d_p[worst])) if worst >= 0 else 0.0, "worst_patch": worst,
            "per_element": [float(v) if k else None for v, k in zip(d_e, e_kept)],
            "per_patch": [float(v) if k else None for v, k in zip(d_p, p_kept)],
            "element_floor": e_floor, "patch_floor": p_floor,
            "left_out_elements": int(np.sum(~e_kept)),
            "left_out_patches": int(np.sum(~p_kept & present))}
