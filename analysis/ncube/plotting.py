"""The plots of any sweep (ncube.summary). One line per configuration: scene file, V and every
other option that varies in the sweep (named in the legend by the scene's label, unique per
file: ncube.summary.scene_labels); deterministic output (no dates in the PNGs)."""
import io
import json

import matplotlib

from . import options as opts
from . import output_file

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def save(fig, path):
    picture = io.BytesIO()
    fig.savefig(picture, format="png", dpi=100, bbox_inches="tight", metadata={"Software": None})
    plt.close(fig)
    return output_file.write(path, picture.getvalue())


# What makes a cell's configuration, beside R: a line joins only cells equal in all of these.
# The scene is its file (two files may share a scene name); its label names it in the legend
# and comes first, so that series sort by what the legend shows.
CONFIGURATION = (["scene_label", "V"] + [name for name in opts.OPTIONS if name not in ("R", "V")] +
                 ["platform", "cost_model", "cfg", "scene_file"])
OTHER_KEYS = CONFIGURATION[2:-1]   # named in the legend when they vary between the series


def _hashable(value):
    return json.dumps(value, sort_keys=True) if isinstance(value, (dict, list)) else value


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
    return f"{values['scene_label']} V={values['V']}" + "".join(f", {k}={values[k]}"
                                                                  for k in varying)


def time_vs_R(table, ylabel, path):
    groups = _series(table, "value")
    if not groups:
        return None
    fig, ax = plt.subplots(figsize=(7, 4.8))
    for key, points in sorted(groups.items(), key=lambda kv: str(kv[0])):
        points.sort()
        ax.plot([p[0] for p in points], [p[2] for p in points], "-o", label=_label(key, groups))
    ax.set_xscale("log", base=2)
    ax.set_yscale("log")
    ax.set_xlabel("R, radiosity processors")
    ax.set_ylabel(ylabel)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    return save(fig, path)


def ratio_vs_nodes(table, y, path):
    groups = _series(table, y)
    if not groups:
        return None
    fig, ax = plt.subplots(figsize=(7, 4.8))
    for key, points in sorted(groups.items(), key=lambda kv: str(kv[0])):
        points.sort(key=lambda p: p[1])
        ax.plot([p[1] for p in points], [p[2] for p in points], "-o", label=_label(key, groups))
    nodes = sorted({row["nodes"] for row in table})
    if y == "speedup" and nodes:
        base = min(nodes)
        ax.plot(nodes, [n / base for n in nodes], "k:", lw=1, label="linear")
    ax.set_xscale("log", base=2)
    if y == "speedup":
        ax.set_yscale("log", base=2)
    ax.set_xlabel("nodes, R x (V + 1)")
    ax.set_ylabel(y + " (against the cell with the fewest nodes)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    return save(fig, path)


def node_breakdown(loaded, scene_labels, path):
    """Per cell: the mean share of compute, message overhead and waiting of its radiosity and
    of its visibility processors; a cell named by its scene's label ({scene file: label})."""
    bars = []
    for cell, result in loaded:
        if not result or result.get("status") != "ok":
            continue
        for role in ("radiosity", "visibility"):
            nodes = [n for n in result["nodes"] if n["role"] == role]
            total = sum(n["compute_seconds"] + n["overhead_seconds"] + n["waiting_seconds"] for n in nodes)
            if nodes and total > 0:
                bars.append((f"{scene_labels[cell.scene_file]} R={cell.R} V={cell.V} {role[:3]}",
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
    ax.legend(fontsize=8, loc="lower right")
    return save(fig, path)
