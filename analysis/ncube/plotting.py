"""The plots of any sweep (ncube.summary), chosen by the sweep's shape (docs/sweeps.md,
"Results layout"):

* the node count R x (V + 1) the same in every cell: by_configuration.png, the measure per
  configuration (R and V), one series per value of every other key that varies (platform,
  scene, an option), each cell out of memory or failed marked where its point would be;
* the node count varying: time_vs_R.png (the measure against R, one series per configuration
  but R), and speedup.png and efficiency.png for the series that ran on more than one node
  count, against the smallest node count that ran in the series, named in its legend entry;
* node_breakdown.png either way: compute, message overhead and waiting per cell and role, each
  cell named by every key that varies.

Every series has its own colour and its own marker, a line joins a series' cells, and the
legend sits outside the axes. Series are named by the scene's label (unique per file:
ncube.summary.scene_labels) and the keys that vary. Deterministic output (no dates in the
PNGs)."""
import io

import matplotlib

from . import page
from .series import (CONFIGURATION, OTHER_KEYS, SERIES,
                     hashable as _hashable, series_label, shown, varied)

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib import colormaps  # noqa: E402
from matplotlib.transforms import blended_transform_factory  # noqa: E402


def save(fig, path):
    picture = io.BytesIO()
    fig.savefig(picture, format="png", dpi=100, bbox_inches="tight", metadata={"Software": None})
    plt.close(fig)
    return page.write(path, picture.getvalue())   # the output rule, one line on refusal


MARKERS = ["o", "s", "^", "D", "v", "P", "X", "<", ">", "p", "h", "*", "d", "8", "H"]
NOT_RUN = {"out_of_memory": "out of memory", "failed": "failed", "missing": "failed"}


def styles(count):
    """`count` (colour, marker) pairs: no two series share a colour, none shares a marker while
    there are markers left (15); tab10, tab20, then a continuous map for more."""
    if count <= 10:
        colours = [colormaps["tab10"](k) for k in range(count)]
    elif count <= 20:
        colours = [colormaps["tab20"](k) for k in range(count)]
    else:
        colours = [colormaps["turbo"](k / (count - 1)) for k in range(count)]
    return [(colours[k], MARKERS[k % len(MARKERS)]) for k in range(count)]


def _series(table, y):
    """{configuration: [(R, nodes, y)]} over the cells with a value: one series per value of
    every configuration key (scene file, V and every option), so that no line joins cells that
    differ in anything but R."""
    groups = {}
    for row in table:
        if row.get(y) is None:
            continue
        key = tuple((k, _hashable(row.get(k))) for k in CONFIGURATION)
        groups.setdefault(key, []).append((row["R"], row["nodes"], row[y]))
    return groups


def _label(key, all_keys):
    """The scene's label and V, then every other key whose value differs between the series."""
    values = dict(key)
    varying = [k for k in OTHER_KEYS if len({dict(o).get(k) for o in all_keys}) > 1]
    return f"{values['scene_label']} V={values['V']}" + "".join(f", {k}={shown(k, values[k])}"
                                                                  for k in varying)


def _legend(ax, title=None):
    ax.legend(fontsize=8, title=title, title_fontsize=8, loc="upper left",
              bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0)


def _mark_not_run(ax, x, status, colour, marker, shift):
    """A cell without a value where its point would be: its series' marker, open, at the foot
    of the axes, with what happened written above it."""
    foot = blended_transform_factory(ax.transData, ax.transAxes)
    ax.plot([x], [0.03], marker=marker, markerfacecolor="white", markeredgecolor=colour,
            markeredgewidth=1.5, linestyle="none", transform=foot, clip_on=False,
            label="_" + NOT_RUN[status])
    ax.text(x, 0.07 + shift, NOT_RUN[status], transform=foot, rotation=90, fontsize=7,
            color=colour, ha="center", va="bottom")


def by_configuration(table, ylabel, title, path):
    """The measure per configuration (R, V), one series per value of every other key that
    varies; cells out of memory or failed marked at the foot of the axes."""
    if not table:
        return None
    configurations = sorted({(row["R"], row["V"]) for row in table})
    where = {c: k for k, c in enumerate(configurations)}
    keys = varied(table, SERIES)
    series = {}
    for row in table:
        series.setdefault(series_label(row, keys), []).append(row)
    fig, ax = plt.subplots(figsize=(7.5, 4.6))
    for k, ((label, rows), (colour, marker)) in enumerate(zip(series.items(), styles(len(series)))):
        rows = sorted(rows, key=lambda r: (r["R"], r["V"]))
        ran = [r for r in rows if r.get("value") is not None]
        ax.plot([where[(r["R"], r["V"])] for r in ran], [r["value"] for r in ran], "-",
                color=colour, marker=marker, label=label)
        if ran:   # the series' fastest cell named where it is
            best = min(ran, key=lambda r: r["value"])
            ax.annotate("fastest", (where[(best["R"], best["V"])], best["value"]),
                        textcoords="offset points", xytext=(0, -14), ha="center", fontsize=7,
                        color=colour)
        for row in rows:
            if row.get("value") is None:   # series side by side where several did not run
                _mark_not_run(ax, where[(row["R"], row["V"])] + 0.12 * (k - (len(series) - 1) / 2),
                              row["status"], colour, marker, 0.0)
    ax.set_xticks(range(len(configurations)), [f"R={R}\nV={V}" for R, V in configurations])
    ax.set_xlim(-0.5, len(configurations) - 0.5)
    ax.set_ylim(bottom=0)
    ax.set_xlabel("configuration: R radiosity processors, V visibility processors each")
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=9)
    ax.grid(True, axis="y", alpha=0.3)
    _legend(ax, ", ".join(keys) if keys else None)
    return save(fig, path)


def time_vs_R(table, ylabel, path, title=None):
    groups = _series(table, "value")
    if not groups:
        return None
    fig, ax = plt.subplots(figsize=(7, 4.8))
    ordered = sorted(groups.items(), key=lambda kv: str(kv[0]))
    series_of = {}
    for ((key, points), (colour, marker)) in zip(ordered, styles(len(ordered))):
        points.sort()
        ax.plot([p[0] for p in points], [p[2] for p in points], "-", color=colour, marker=marker,
                label=_label(key, groups))
        series_of[key] = (colour, marker)
    for row in table:   # cells without a value, in their series' style when it has one
        if row.get("value") is None:
            key = tuple((k, _hashable(row.get(k))) for k in CONFIGURATION)
            colour, marker = series_of.get(key, ("black", "x"))
            _mark_not_run(ax, row["R"], row["status"], colour, marker, 0.0)
    ax.set_xscale("log", base=2)
    ax.set_yscale("log")
    ax.set_xlabel("R, radiosity processors")
    ax.set_ylabel(ylabel)
    if title:
        ax.set_title(title, fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    _legend(ax)
    return save(fig, path)


def ratio_vs_nodes(table, y, path):
    """Speedup or efficiency against the nodes, for the series with more than one node count;
    each legend entry names its reference (ncube.summary.rows: the smallest node count that
    ran in the series)."""
    groups = {key: points for key, points in _series(table, y).items()
              if len({p[1] for p in points}) > 1}
    if not groups:
        return None
    references = {}
    for row in table:
        if row.get("reference"):
            references[tuple((k, _hashable(row.get(k))) for k in CONFIGURATION)] = row["reference"]
    fig, ax = plt.subplots(figsize=(7, 4.8))
    ordered = sorted(groups.items(), key=lambda kv: str(kv[0]))
    for ((key, points), (colour, marker)) in zip(ordered, styles(len(ordered))):
        points.sort(key=lambda p: p[1])
        reference = references.get(key)
        label = _label(key, groups) + (f" (against {reference})" if reference else "")
        ax.plot([p[1] for p in points], [p[2] for p in points], "-", color=colour, marker=marker,
                label=label)
    nodes = sorted({p[1] for points in groups.values() for p in points})
    if y == "speedup" and nodes:
        base = min(nodes)
        ax.plot(nodes, [n / base for n in nodes], "k:", lw=1, label="linear")
    ax.set_xscale("log", base=2)
    if y == "speedup":
        ax.set_yscale("log", base=2)
    ax.set_xlabel("nodes, R x (V + 1)")
    ax.set_ylabel(y + " (against the smallest node count that ran)")
    ax.grid(True, which="both", alpha=0.3)
    _legend(ax)
    return save(fig, path)


def node_breakdown(loaded, names, path):
    """Per cell: the mean share of compute, message overhead and waiting of its radiosity and
    of its visibility processors; a cell named by `names` ({cell id: its scene's label and
    every key that varies, then R and V})."""
    bars = []
    for cell, result in loaded:
        if not result or result.get("status") != "ok":
            continue
        for role in ("radiosity", "visibility"):
            nodes = [n for n in result["nodes"] if n["role"] == role]
            total = sum(n["compute_seconds"] + n["overhead_seconds"] + n["waiting_seconds"] for n in nodes)
            if nodes and total > 0:
                bars.append((f"{names[cell.id]} {role[:3]}",
                             [sum(n[f"{k}_seconds"] for n in nodes) / total
                              for k in ("compute", "overhead", "waiting")]))
    if not bars:
        return None
    fig, ax = plt.subplots(figsize=(7, 0.25 * len(bars) + 1.2))
    left = [0.0] * len(bars)
    for k, (what, colour) in enumerate((("compute", "tab:green"), ("message overhead", "tab:red"),
                                        ("waiting", "lightgrey"))):
        shares = [b[1][k] for b in bars]
        ax.barh(range(len(bars)), shares, left=left, color=colour, label=what)
        left = [a + b for a, b in zip(left, shares)]
    ax.set_yticks(range(len(bars)), [b[0] for b in bars], fontsize=7)
    ax.invert_yaxis()
    ax.set_xlim(0, 1)
    ax.set_xlabel("share of the nodes' time (mean over the nodes of the role)")
    _legend(ax)
    return save(fig, path)
