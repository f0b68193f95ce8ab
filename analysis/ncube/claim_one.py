"""The first claim's verdicts and sentences, generated from intervals through these functions
only (docs/accuracy.md, "Deciding the first claim"; tests/claims_sentences_test.py holds every
sentence against its interval).

The claim (the paper's section 6): ray-traced form factors are "much more accurate than the
hemicube method". Its quantity is the form-factor error (b): a method's error on the one error
measure (analysis/ncube/error_measure.py: the area-weighted RMS of the symmetric relative
difference (Y - T) / ((Y + T) / 2), items darker than the dark floor left out) against the
exact solution of its own structure (analysis/ncube/own_structure.py; the receiver-centred one
for the rays); the same rule decides the total error (a) per patch against Cycles. For a
hemicube setting against the paper's
method (its largest M) on one scene and one measure (per element, per patch), the ratio
q = RMS_hemicube / RMS_rays and its 95 % interval [low, high] (analysis/ncube/error_parts.py)
decide, against THRESHOLD fixed before the runs:

* holds:          q >= THRESHOLD and low >= THRESHOLD;
* does not hold:  high < THRESHOLD;
* undecided:      otherwise (the interval straddles THRESHOLD).

And, apart from "much": the hemicube is less accurate (low > 1), more accurate (high < 1), or
neither can be told (the interval holds 1)."""

THRESHOLD = 2.0


def verdict(ratio, low, high, threshold=THRESHOLD):
    if ratio >= threshold and low >= threshold:
        return "holds"
    if high < threshold:
        return "does not hold"
    return "undecided"


def direction(low, high):
    if low > 1.0:
        return "hemicube less accurate"
    if high < 1.0:
        return "hemicube more accurate"
    return "not distinguishable"


def figure(value, low, high, percent=False):
    """A value with its interval, as every table and sentence writes it."""
    top = "∞" if high == float("inf") else (f"{100 * high:.2f}" if percent else f"{high:.2f}")
    if percent:
        return f"{100 * value:.2f} % [{100 * low:.2f}, {top}]"
    return f"{value:.2f} [{low:.2f}, {top}]"


SAYS = {"holds": "holds", "undecided": "is undecided", "does not hold": "does not hold"}

PLACEMENTS = {"centre": "one hemicube at the shooter's centre",
              "elements": "one hemicube at each shooter element's centre"}


def claim_sentence(decisions, threshold=THRESHOLD):
    """One paragraph from decisions [{scene, measure, placement, resolution, ratio, low,
    high}]: the verdict over all of them, then per placement which (scene, measure, N) hold,
    are undecided, or do not hold, with the range of the intervals' low and high ends."""
    if not decisions:
        return ("**not measured**: no scene has both methods' converged cells and an exact "
                "structure.")
    verdicts = [verdict(d["ratio"], d["low"], d["high"], threshold) for d in decisions]
    if all(v == "holds" for v in verdicts):
        head = "**holds**"
    elif all(v == "does not hold" for v in verdicts):
        head = "**does not hold**"
    elif not any(v == "holds" for v in verdicts):
        head = "**is not shown to hold**"
    else:
        head = "**holds only in part**"
    scenes = sorted({d["scene"] for d in decisions})
    parts = []
    for placement in ("centre", "elements"):
        mine = [(d, v) for d, v in zip(decisions, verdicts) if d["placement"] == placement]
        if not mine:
            continue
        groups = []
        for word in ("holds", "undecided", "does not hold"):
            these = [d for d, v in mine if v == word]
            if not these:
                continue
            where = "; ".join(
                f"{scene} {measure} at N = " + ", ".join(
                    str(n) for n in sorted(d["resolution"] for d in these
                                           if d["scene"] == scene and d["measure"] == measure))
                for scene in scenes for measure in ("element", "patch")
                if any(d["scene"] == scene and d["measure"] == measure for d in these))
            highs = [d["high"] for d in these]
            top = "∞" if max(highs) == float("inf") else f"{max(highs):.2f}"
            groups.append(f"{SAYS[word]} on {where} (intervals' low ends "
                          f"{min(d['low'] for d in these):.2f} to {max(d['low'] for d in these):.2f}, "
                          f"high ends {min(highs):.2f} to {top})")
        parts.append(f"against {PLACEMENTS[placement]}, it " + "; it ".join(groups))
    return (f"{head} (\"much\": the hemicube's form-factor error at least {threshold:g} times "
            f"the paper's method's, the ratio and its 95 % interval's low end both at least "
            f"{threshold:g}; scenes {', '.join(scenes)}): " + "; ".join(parts) + ".")


def decision_rows(decisions, threshold=THRESHOLD):
    """The table behind the sentence, one row per decision."""
    out = ["| scene | measure | hemicube | paper's method (b) | hemicube (b) | ratio [95 %] | "
           "verdict | direction |", "|---|---|---|---:|---:|---:|---|---|"]
    for d in decisions:
        out.append(f"| {d['scene']} | {d['measure']} | {d['placement']} N={d['resolution']} | "
                   f"{figure(*d['rays'], percent=True)} | {figure(*d['hemicube'], percent=True)} | "
                   f"{figure(d['ratio'], d['low'], d['high'])} | "
                   f"{verdict(d['ratio'], d['low'], d['high'], threshold)} | "
                   f"{direction(d['low'], d['high'])} |")
    return out
