#!/usr/bin/python3
"""What porting the program would have meant: the paper's Table 4 on each machine; writes
analysis/machines.md and analysis/figures/machines_time_vs_R.png.

usage: python3 analysis/machines.py [--run] [--results DIR] [--sweep FILE] [--partial]
                                     [--output FILE] [--figures DIR]

The sweep file (default experiments/machines/table4.yaml) is the one list of the study: its
grid's `platform` entries are the machines (the first is the reference every figure is
normalised to), every other option that varies between its cells (but the iterations) makes a
method (the visibility: brute force, the octree; the hemicube; the shooter-centred scheme), and
R, V and the scene are Table 4's rows. A method whose cells all have V = 0 (the hemicube, the
shooter-centred scheme) is shown beside Table 4's V = 0 row in a section of its own, per shot
(seconds per iteration / shooters per iteration), with its communication share and the bytes
its nodes send an iteration; Table 4's tables, sentences and figure keep the other methods. With --run the cells without a finished result in DIR (default
results/machines/) run first through experiments/sweep; without it, what is in DIR is read.
A cell still without a result makes it refuse in one line, writing nothing (ncube.page);
with --partial the page is written and such a cell is shown as not run.

A cell out of simulated memory (./simulate exit 3, status "out_of_memory") is a finding, not a
failure: it is shown as such, with the node that did not fit. The share of time in
communication comes from the result's node breakdown (docs/result-format.md): over all nodes
of a run, message overhead (the CPU's per-message cost), waiting (blocked in a receive: on
messages in flight and on the other nodes' work) and compute, in node-seconds.

Every number and sentence of the output is computed from the result files (sorted, no dates,
no host times), so the same results give the same page, and other results other sentences."""

from ncube.interpreter import use_project_python  # noqa: E402

use_project_python()   # Debian's /usr/bin/python3 (README.md, "Use")

import argparse
import os
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path


from ncube import input_file  # noqa: E402
from ncube import opening as op  # noqa: E402
from ncube import page, results  # noqa: E402
from ncube.paths import ANALYSIS, ROOT  # noqa: E402
from ncube.sweep import SweepError, load  # noqa: E402

SWEEP_FILE = ROOT / "experiments" / "machines" / "table4.yaml"
OUTPUT = ANALYSIS / "machines.md"
FIGURES = ANALYSIS / "figures"
FIGURE = "machines_time_vs_R.png"
RESULTS = "results/machines"

# How a machine's platform file is named in the text; any other file by its name.
DISPLAY = {"ncube2": "nCube2", "transputer-t800": "T800 network", "ipsc860": "iPSC/860",
           "paragon": "Paragon", "paragon-sunmos": "Paragon under SUNMOS", "cm5": "CM-5",
           "cluster-2024": "cluster of 2024"}
# Factors of speed against the reference that differ by less than this ratio across a machine's
# configurations count as one factor (a port that only changes the node speed).
UNIFORM = 1.05
# Waiting shares of one configuration within this many percentage points of the reference's on
# every machine count as the same (the network does not show in them).
SAME_WAITING = 1.0
# The options a cell's method is made of even when they do not vary (so a study of one method
# still names it); any other option that varies between the cells joins them.
METHOD_OPTIONS = ("visibility",)
# Options that may differ between cells without making a method: fewer iterations for a costly
# cell change how many iterations are averaged, not the program.
NOT_METHOD = ("iterations",)
# The probed machine whose rates are one probe's, and the records of that probe repeated with
# the prediction held against the host each time (docs/machines/probe.md): the spread its
# conclusions carry.
PROBED = "cluster of 2024"
PROBED_PLATFORM = ROOT / "platforms" / "machines" / "cluster-2024.xml"
PREDICTION_RECORDS = ROOT / "docs" / "machines" / "prediction_records.jsonl"
# A share of node time in communication from which the page calls it a large share.
LARGE_SHARE = 0.25


def rel(path):
    return os.path.relpath(path, ROOT)


def shown(path):
    """A path as the page names it: relative to the repository when inside it."""
    path = Path(path).resolve()
    return rel(path) if path.is_relative_to(ROOT) else str(path)


@dataclass
class Entry:
    """One cell of the study and what its result says."""
    cell: object
    machine: str
    method: str
    status: str          # ok, out_of_memory, missing (no finished result), or another status
    value: float = None  # seconds per iteration
    oom: dict = None
    compute: float = 0.0   # node-seconds, summed over the nodes
    overhead: float = 0.0
    waiting: float = 0.0
    bytes_sent: float = 0.0   # over all nodes and iterations
    least_node_share: float = None   # the smallest (overhead + waiting) share of one node
    iterations: int = None
    rates: tuple = ()   # the rates per kind of work the platform gives (provenance), by name

    @property
    def shots_per_iteration(self):
        """Patches shot an iteration: one in the paper's program, R (or
        --shooters-per-iteration) in the shooter-centred scheme."""
        if self.cell.options.get("parallelisation") != "shooters":
            return 1
        return self.cell.options.get("shooters_per_iteration") or self.cell.R

    @property
    def per_shot(self):
        return self.value / self.shots_per_iteration if self.status == "ok" else None

    @property
    def bytes_per_iteration(self):
        return self.bytes_sent / self.iterations if self.status == "ok" and self.iterations else None

    @property
    def scene(self):
        return self.cell.scene

    @property
    def row(self):
        return (self.cell.R, self.cell.V)

    @property
    def communication_share(self):
        total = self.compute + self.overhead + self.waiting
        return (self.overhead + self.waiting) / total if total else None

    def share(self, part):
        total = self.compute + self.overhead + self.waiting
        return getattr(self, part) / total if total else None


def machine_name(platform_file):
    stem = Path(platform_file).stem
    return DISPLAY.get(stem, stem)


def method_keys(cells):
    varying = {name for name in cells[0].options if name not in ("R", "V") + NOT_METHOD
               and len({repr(c.options[name]) for c in cells}) > 1}
    return [name for name in cells[0].options if name in varying or name in METHOD_OPTIONS]


def method_of(cell, keys):
    """The cell's method: its METHOD_OPTIONS' values, then the other varying options' values
    where they differ from ./simulate's default ("brute-force hemicube", "octree shooters")."""
    from ncube import options as opts
    keys = [k for k in METHOD_OPTIONS if k in keys] + [k for k in keys if k not in METHOD_OPTIONS]
    return " ".join(str(cell.options[k]) if isinstance(cell.options[k], str)
                    else f"{k.replace('_', ' ')} {cell.options[k]}"   # "block size 1"
                    for k in keys
                    if k in METHOD_OPTIONS or cell.options[k] != opts.OPTIONS[k].default)


def entries(sweep, results_dir):
    keys = method_keys(sweep.cells)
    found = []
    for cell in sweep.cells:
        result = results.read(Path(results_dir) / cell.file)
        finished = result is not None and results.mismatch(result, cell) is None
        entry = Entry(cell=cell, machine=machine_name(cell.platform_file),
                      method=method_of(cell, keys),
                      status=result["status"] if finished else "missing")
        if finished:
            entry.value = results.measure(result, sweep.measure)
            entry.oom = result.get("out_of_memory")
            entry.iterations = result.get("iterations")
            values = result.get("provenance", {}).get("platform", {}).get("values", {})
            entry.rates = tuple(sorted(k for k in values if k.endswith("_speed")
                                       and k != "node_speed"))
            for node in result.get("nodes", []) if entry.status == "ok" else []:
                entry.compute += node["compute_seconds"]
                entry.overhead += node["overhead_seconds"]
                entry.waiting += node["waiting_seconds"]
                entry.bytes_sent += node.get("bytes_sent", 0)
                total = node["compute_seconds"] + node["overhead_seconds"] + node["waiting_seconds"]
                if total:
                    mine = (node["overhead_seconds"] + node["waiting_seconds"]) / total
                    entry.least_node_share = min(mine, entry.least_node_share or mine)
        found.append(entry)
    return found


def ordered(values):
    """The distinct values in the order of first appearance (the sweep file's order)."""
    return list(dict.fromkeys(values))


def seconds(value):
    """Four significant digits, whole seconds from 1,000 on (no exponents)."""
    return f"{value:,.0f}" if value >= 1000 else f"{value:.4g}"


def number(x):
    """Three significant digits, whole numbers from 100 on (no exponents)."""
    return f"{x:,.0f}" if x >= 100 else f"{x:.3g}"


def factor_text(factor):
    """How much faster: 'x times as fast' or, below 1, 'x times as slow'."""
    if abs(factor - 1) < 0.005:
        return "as fast"
    if factor >= 1:
        return f"{number(factor)} times as fast"
    return f"{number(1 / factor)} times as slow"


def cell_text(entry):
    if entry.status == "ok":
        return seconds(entry.value)
    if entry.status == "out_of_memory":
        return "out of memory"
    return "not run" if entry.status == "missing" else entry.status


def config_text(entry, with_method=True):
    return f"R={entry.cell.R} V={entry.cell.V}" + (f" {entry.method}" if with_method else "")


def percent(share):
    if share is None:
        return ""
    value = 100 * share
    if value < 0.001:
        return "< 0.001 %"
    return f"{value:.0f} %" if value >= 10 else f"{value:.1f} %" if value >= 1 else f"{value:.2g} %"


class Study:
    def __init__(self, sweep, found):
        self.sweep = sweep
        self.found = found
        self.machines = ordered(e.machine for e in found)
        self.reference = self.machines[0]
        self.methods = ordered(e.method for e in found)
        self.scenes = ordered(e.scene for e in found)
        self.by = {(e.machine, e.method, e.scene, e.row): e for e in found}

    def has(self, scene, method):
        """Whether the sweep has cells of `method` for `scene` (the fine-grained variant runs
        scene1 only)."""
        return any(e.scene == scene and e.method == method for e in self.found)

    def combinations(self):
        """(scene, method) pairs with cells, scene by scene."""
        return [(s, m) for s in self.scenes for m in self.methods if self.has(s, m)]

    def rows(self, scene):
        return ordered(e.row for e in self.found if e.scene == scene)

    def get(self, machine, method, scene, row):
        return self.by.get((machine, method, scene, row))

    def ok(self, **where):
        return [e for e in self.found if e.status == "ok"
                and all(getattr(e, k) == v for k, v in where.items())]

    def best(self, **where):
        """The fastest finished cell among those matching, None when none finished."""
        return min(self.ok(**where), key=lambda e: (e.value, e.cell.R), default=None)

    def normalised(self, entry):
        """The cell's seconds over the reference machine's for the same scene, row, method."""
        ref = self.get(self.reference, entry.method, entry.scene, entry.row)
        if entry.status != "ok" or ref is None or ref.status != "ok":
            return None
        return entry.value / ref.value

    def factors(self, machine):
        """How many times as fast as the reference, per configuration that runs on both."""
        return [1 / self.normalised(e) for e in self.found
                if e.machine == machine and self.normalised(e) is not None]

    def v_ratio(self, machine, method, scene):
        """The V = 0 time over the best V > 0 time, None unless both finished."""
        with_v, without = self.v_pays(machine, method, scene)
        if with_v is None or without is None or without.status != "ok":
            return None
        return without.value / with_v.value

    def waiting_spread(self):
        """(largest difference in percentage points between a cell's waiting share and the
        reference machine's for the same configuration, that cell), None without a pair."""
        pairs = []
        for e in self.found:
            ref = self.get(self.reference, e.method, e.scene, e.row)
            if e.machine != self.reference and e.status == "ok" and ref and ref.status == "ok":
                pairs.append((100 * abs(e.share("waiting") - ref.share("waiting")), e))
        return max(pairs, key=lambda p: p[0], default=None)

    def v_pays(self, machine, method, scene):
        """(best with V > 0, the V = 0 cell): whether visibility processors pay here."""
        with_v = min((e for e in self.ok(machine=machine, method=method, scene=scene)
                      if e.cell.V > 0), key=lambda e: e.value, default=None)
        without = [e for e in self.found if e.machine == machine and e.method == method
                   and e.scene == scene and e.cell.V == 0]
        return with_v, (without[0] if without else None)

    def pays(self, machine, method, scene):
        """True when the best V > 0 beats V = 0 (or V = 0 does not fit), False when V = 0 is at
        least as fast, None when there is nothing to compare."""
        with_v, without = self.v_pays(machine, method, scene)
        if with_v is None or without is None or without.status not in ("ok", "out_of_memory"):
            return None
        return without.status == "out_of_memory" or with_v.value < without.value


def header(study, args, missing, others=()):
    sweep_file = shown(study.sweep.file)
    lines = ["# What porting would have meant: the paper's Table 4 on other machines", "",
             f"Generated by `/usr/bin/python3 analysis/machines.py` from the sweep "
             f"`{sweep_file}`: Table 4's configurations (R x (V + 1) = 64 nodes, "
             f"64 samples, the mean of the first 20 iterations) of "
             + ", ".join(study.scenes) + " with " + " and ".join(study.methods)
             + (" (and at V = 0 only, with their own iterations: "
                + " and ".join(ordered(e.method for e in others)) + ", section 6)" if others else "")
             + " on "
             + ", ".join(study.machines) + " (their platform files and the start of their "
             "SHA-256: " + ", ".join(f"`{shown(f)}` {h.removeprefix('sha256:')[:12]}"
                                     for f, h in ordered((c.platform_file, c.platform_sha256)
                                                         for c in study.sweep.cells))
             + "; the machine pages: `docs/machines/`). Seconds are simulated seconds per "
             "iteration of each machine; every figure and sentence below is computed from the "
             "result files, so rerunning the study rewrites them.", "",
             "Run it all from an empty folder: `/usr/bin/python3 analysis/machines.py --run` "
             f"(the cells through `experiments/sweep {sweep_file} --results {RESULTS}`, then "
             f"this page; one cell's table: `{RESULTS}/sweeps/{study.sweep.name}/cells.csv`). "
             f"One cell by hand, e.g. the last: `{simulate_command(study.sweep.cells[-1])}`.",
             ""]
    if missing:
        lines += [f"**{missing} of {len(study.found) + len(others)} cells have no finished result in "
                  f"`{shown(args.results)}`** (shown as \"not run\"): run with `--run`.", ""]
    return lines


def tables_section(study):
    lines = ["## 1. Seconds per iteration", "",
             "\"out of memory\": the configuration does not fit the machine's memory per node "
             "(./simulate ends with exit 3 and says which node: section 5); a result, not a "
             "failure of the study."]
    stand_ins = ordered((e.scene, e.row, (e.cell.paper_row["R"], e.cell.paper_row["V"]))
                        for e in study.found if e.cell.paper_row)
    lines[-1] += "".join(f" {scene}'s R={row[0]} V={row[1]} stands for the paper's row "
                         f"R={paper[0]} V={paper[1]} where that does not fit (as in "
                         "`experiments/table4.json`); both run on every machine."
                         for scene, row, paper in stand_ins)
    lines.append("")
    for scene, method in study.combinations():
        lines += [f"**{scene}, {method}**", "",
                  "| R | V | " + " | ".join(study.machines) + " |",
                  "|---:|---:|" + "---:|" * len(study.machines)]
        for row in study.rows(scene):
            cells = [study.get(m, method, scene, row) for m in study.machines]
            lines.append(f"| {row[0]} | {row[1]} | "
                         + " | ".join(cell_text(e) if e else "" for e in cells) + " |")
        lines.append("")
    return lines


def best_section(study):
    lines = ["## 2. The best configuration per machine and scene", "",
             "The fastest finished configuration of each scene on each machine, over every "
             f"method, and in parentheses its speed against the {study.reference}'s best "
             "for the same scene.", "",
             "| machine | " + " | ".join(study.scenes) + " |",
             "|---|" + "---|" * len(study.scenes)]
    for machine in study.machines:
        cells = []
        for scene in study.scenes:
            best, ref = study.best(machine=machine, scene=scene), \
                study.best(machine=study.reference, scene=scene)
            if best is None:
                cells.append("nothing fits")
                continue
            text = f"{config_text(best)}: {seconds(best.value)} s"
            if ref is not None and machine != study.reference:
                text += f" ({factor_text(ref.value / best.value)})"
            cells.append(text)
        lines.append(f"| {machine} | " + " | ".join(cells) + " |")
    return lines + [""]


def communication_section(study):
    lines = ["## 3. The share of time in communication", "",
             "Per cell, over all its nodes: message overhead (the processor's own cost of "
             "sending and receiving) + waiting (blocked in a receive: on messages in flight "
             "and on the other nodes' work, the paper's \"communication overhead\") as a share "
             "of the nodes' time, from the result's `nodes[]` (`overhead_seconds`, "
             "`waiting_seconds`, `compute_seconds`); in parentheses the overhead alone.", ""]
    for scene in study.scenes:
        rows = study.rows(scene)
        lines += [f"**{scene}**", "",
                  "| machine | method | " + " | ".join(f"R={r} V={v}" for r, v in rows) + " |",
                  "|---|---|" + "---:|" * len(rows)]
        for machine in study.machines:
            for method in [m for m in study.methods if study.has(scene, m)]:
                cells = []
                for row in rows:
                    e = study.get(machine, method, scene, row)
                    cells.append(f"{percent(e.communication_share)} "
                                 f"({percent(e.share('overhead'))})"
                                 if e and e.status == "ok" else (cell_text(e) if e else ""))
                lines.append(f"| {machine} | {method} | " + " | ".join(cells) + " |")
        lines.append("")
    ok = [e for e in study.found if e.status == "ok"]
    if not ok:
        return lines
    top = max(ok, key=lambda e: e.share("overhead"))
    lines.append(f"The message overhead is at most {percent(top.share('overhead'))} of node "
                 f"time ({top.scene} {config_text(top)} on the {top.machine}).")
    spread = study.waiting_spread()
    if spread is not None:
        points, e = spread
        if points < SAME_WAITING:
            lines[-1] += (" A configuration waits the same share of its time on every machine "
                          f"(within {points:.2f} percentage points of the {study.reference}'s), "
                          "whatever the network: the waiting is on the other nodes' computing "
                          "(the busiest visibility processor, the other radiosity processors), "
                          "not on messages.")
        else:
            lines[-1] += (" The waiting share of one configuration differs by up to "
                          f"{points:.0f} percentage points between machines ({e.scene} "
                          f"{config_text(e)} on the {e.machine} against the "
                          f"{study.reference}): there the network shows.")
    return lines + [""]


def bottleneck_section(study):
    lines = ["## 4. Where visibility processors stop paying", "",
             "Whether the best configuration with visibility processors (V > 0) beats R=64 V=0 "
             "on the same machine: the ratio is the V = 0 time over the best V > 0 time "
             "(above 1: V > 0 pays; below 1: R=64 V=0 is faster, the radiosity processors "
             "waiting on their visibility processors longer than those save them; section 3 "
             "says how much of that waiting the network explains).", "",
             "| machine | " + " | ".join(f"{s} {m}" for s, m in study.combinations()) + " |",
             "|---|" + "---|" * len(study.combinations())]
    for machine in study.machines:
        cells = []
        for scene, method in study.combinations():
            with_v, without = study.v_pays(machine, method, scene)
            if with_v is None or without is None or without.status not in ("ok", "out_of_memory"):
                cells.append("")
            elif without.status == "out_of_memory":
                cells.append(f"V = 0 does not fit; best {config_text(with_v, False)}")
            else:
                ratio = without.value / with_v.value
                cells.append(f"{ratio:.2f} ({'pays' if ratio > 1 else 'does not pay'}; "
                             f"best {config_text(with_v, False)})")
        lines.append(f"| {machine} | " + " | ".join(cells) + " |")
    lines += ["", "**Where it changes** (against the " + study.reference + "):", ""]
    changes = []
    for scene in study.scenes:
        for method in study.methods:
            ref = study.pays(study.reference, method, scene)
            if ref is None:
                continue
            stops = [m for m in study.machines[1:] if study.pays(m, method, scene) is False
                     and ref]
            starts = [m for m in study.machines[1:] if study.pays(m, method, scene) is True
                      and not ref]
            same = [m for m in study.machines[1:] if study.pays(m, method, scene) == ref]
            text = (f"* {scene}, {method}: on the {study.reference} V > 0 "
                    + ("pays" if ref else "does not pay") + "; ")
            if stops:
                text += "it stops paying on " + join(stops)
            elif starts:
                text += "it starts to pay on " + join(starts)
            else:
                text += "the same on every other machine"
            if (stops or starts) and same:
                text += "; as on the " + study.reference + " on " + join(same)
            changes.append(text + ".")
    return lines + changes + [""]


def join(names):
    names = [f"the {n}" for n in names]
    return names[0] if len(names) == 1 else ", ".join(names[:-1]) + " and " + names[-1]


def memory_section(study):
    lines = ["## 5. What does not fit in memory", "",
             "Every cell that ended out of simulated memory, with the node that did not fit "
             "(needed and available bytes, from the result's `out_of_memory`).", ""]
    any_oom = False
    for machine in study.machines:
        ooms = [e for e in study.found if e.machine == machine and e.status == "out_of_memory"]
        if not ooms:
            lines.append(f"* {machine}: every configuration fits.")
            continue
        any_oom = True
        parts = []
        for e in ooms:
            text = f"{e.scene} R={e.cell.R} V={e.cell.V} {e.method}"
            if e.oom:
                text += (f" ({e.oom['role']} node {e.oom['node']} needs "
                         f"{e.oom['needed_bytes']:,.0f} of {e.oom['available_bytes']:,.0f} bytes)")
            parts.append(text)
        lines.append(f"* {machine}: " + "; ".join(parts) + ".")
    others = [e for e in study.found if e.status not in ("ok", "out_of_memory")]
    if others:
        lines.append(f"* Not run or without a finished result: {len(others)} cells ("
                     + ", ".join(sorted({e.machine for e in others})) + ").")
    return lines + ([""] if any_oom or others else ["", "Nothing runs out of memory.", ""])


def v0_methods(found):
    """The methods that run at V = 0 only (the hemicube, the shooter-centred scheme): they are
    shown beside Table 4's V = 0 row, not as Table 4's methods."""
    return [m for m in ordered(e.method for e in found)
            if all(e.cell.V == 0 for e in found if e.method == m)]


def megabytes(n):
    """Bytes as kB or MB, three significant digits."""
    return f"{number(n / 1e3)} kB" if n < 1e6 else f"{number(n / 1e6)} MB"


def v0_section(study, others):
    """The V = 0 methods beside the paper's program at the same R (Table 4's V = 0 row)."""
    if not others:
        return []
    methods = ordered(e.method for e in others)
    lines = ["## 6. At V = 0: the hemicube and the shooter-centred scheme", "",
             "Beside Table 4's V = 0 row, the methods that run with V = 0 only "
             "(`docs/model.md`, \"The hemicube\" and \"The shooter-centred scheme\"), each "
             "with the iterations its line of the sweep gives (fewer than Table 4's 20 where a "
             "cell is costly on the host; the sweep file says why the mean does not change). "
             "The paper's program shoots one patch an iteration; the shooter-centred scheme "
             "shoots R (one a node) and then sums every element's increment over the nodes, so "
             "the two are compared **per shot: seconds per shot = seconds per iteration / "
             "shooters per iteration** (1 for the paper's program and the hemicube, R for the "
             "scheme: the figure of an iteration where every node shoots; the first iteration "
             "shoots only the patches with light to shoot, the lights, fewer than R, in about "
             "the same time, so the result's own shots are fewer than iterations x R). Communication: overhead + waiting as a share of node time (in parentheses "
             "the overhead alone, then the share of the node that waited least), as in section 3; waiting includes waiting on the other nodes' work, which in the scheme is the slowest shot of the iteration; exchanged: the bytes all nodes send an "
             "iteration (`nodes[].bytes_sent`), which for the scheme is its increment exchange.",
             ""]
    for scene in ordered(e.scene for e in others):
        rows = ordered(e.row for e in others if e.scene == scene)
        for row in rows:
            paper = [m for m in study.methods if study.get(study.reference, m, scene, row)]
            lines += [f"**{scene} R={row[0]} V={row[1]}**", "",
                      "| machine | " + " | ".join(f"{m}: s a shot" for m in paper + methods)
                      + " | " + " | ".join(f"{m}: communication, exchanged an iteration"
                                           for m in methods) + " |",
                      "|---|" + "---:|" * (len(paper) + 2 * len(methods))]
            for machine in study.machines:
                got = [study.get(machine, m, scene, row) for m in paper]
                got += [next((e for e in others if e.machine == machine and e.method == m
                              and e.scene == scene and e.row == row), None) for m in methods]
                shots = [seconds(e.per_shot) if e and e.status == "ok"
                         else (cell_text(e) if e else "") for e in got]
                comm = [f"{percent(e.communication_share)} ({percent(e.share('overhead'))}; "
                        f"least node {percent(e.least_node_share)}), "
                        f"{megabytes(e.bytes_per_iteration)}" if e and e.status == "ok"
                        else (cell_text(e) if e else "") for e in got[len(paper):]]
                lines.append(f"| {machine} | " + " | ".join(shots + comm) + " |")
            lines.append("")
    lines += v0_sentences(study, others)
    return lines


def v0_sentences(study, others):
    text = []
    paper = study.methods[0]
    shooters = [e for e in others if e.status == "ok"
                and e.cell.options.get("parallelisation") == "shooters"]
    if shooters:
        spreads = []
        for scene in ordered(e.scene for e in shooters):
            shares = [e for e in shooters if e.scene == scene]
            hi = max(shares, key=lambda e: e.communication_share)
            lo = min(shares, key=lambda e: e.communication_share)
            if len(shares) > 1:
                spreads.append((100 * (hi.communication_share - lo.communication_share), hi, lo))
        same = bool(spreads) and max(p[0] for p in spreads) < SAME_WAITING
        if not same:
            top = max(shooters, key=lambda e: e.communication_share)
            low = min(shooters, key=lambda e: e.communication_share)
            large = [e for e in shooters if e.communication_share >= LARGE_SHARE]
            text.append(
                f"The shooter-centred scheme's share of node time in communication (overhead + "
                f"waiting) is largest on the {top.machine} with {top.scene}: "
                f"{percent(top.communication_share)} "
                f"({percent(top.share('overhead'))} overhead) for "
                f"{megabytes(top.bytes_per_iteration)} exchanged an iteration"
                + (f", and least on the {low.machine} with {low.scene}: "
                   f"{percent(low.communication_share)} for {megabytes(low.bytes_per_iteration)}."
                   if low is not top else "."))
            if large:
                text.append(
                    f"It is a large share (a quarter of node time or more) on "
                    + "; ".join(f"the {e.machine} with {e.scene} ({percent(e.communication_share)})"
                                for e in large)
                    + (f", and below a quarter in the other {len(shooters) - len(large)} of the "
                       f"{len(shooters)} cells that ran, where the scheme, like the paper's program, "
                       "is compute-bound." if len(large) < len(shooters) else
                       ": every cell of it that ran."))
            else:
                text.append(f"It stays below a quarter of node time on every machine and scene "
                            "that ran: the scheme, like the paper's program, is compute-bound.")
        if same:
            text.append(
                "The shooter-centred scheme's share of node time in communication (overhead + "
                "waiting) is the same on every machine for each scene, within "
                f"{max(p[0] for p in spreads):.2g} percentage points ("
                + ", ".join(f"{hi.scene} {100 * lo.communication_share:.2f} % to "
                            f"{100 * hi.communication_share:.2f} %" for _, hi, lo in spreads)
                + ", the overhead at most "
                f"{percent(max(e.share('overhead') for e in shooters))}): the nodes wait on the "
                "iteration's slowest shot (each shoots another patch), not on the exchange, which "
                "does not show on any machine, even at "
                f"{megabytes(max(e.bytes_per_iteration for e in shooters))} an iteration.")
        elif spreads:
            d, hi, lo = max(spreads, key=lambda p: p[0])
            text.append(f"The share differs between machines by up to {d:.0f} percentage "
                        f"points ({hi.scene}: {percent(hi.communication_share)} on the "
                        f"{hi.machine} against {percent(lo.communication_share)} on the "
                        f"{lo.machine}): there the network shows.")
        pairs = []
        for e in shooters:
            base = study.get(e.machine, paper, e.scene, e.row)
            if base and base.status == "ok":
                pairs.append((base.per_shot / e.per_shot, e))
        if pairs:
            best, worst = max(pairs, key=lambda p: p[0]), min(pairs, key=lambda p: p[0])
            text.append(
                f"Per shot, against the paper's program ({paper}) at the same R and V, the "
                f"scheme is {factor_text(best[0])} on the {best[1].machine} with "
                f"{best[1].scene} and {factor_text(worst[0])} on the {worst[1].machine} with "
                f"{worst[1].scene}.")
    oom = [e for e in others if e.status == "out_of_memory"]
    if oom:
        text.append("Out of memory (exit 3, a finding): " + "; ".join(
            f"{e.method} {e.scene} on the {e.machine}"
            + (f" (node {e.oom['node']} needs {e.oom['needed_bytes']:,.0f} of "
               f"{e.oom['available_bytes']:,.0f} bytes)" if e.oom else "")
            for e in oom) + ".")
    hemi = [e for e in others if e.status == "ok" and e.cell.options.get("form_factors") == "hemicube"]
    ratios = []
    for e in hemi:
        base = study.get(e.machine, paper, e.scene, e.row)
        if base and base.status == "ok":
            ratios.append(base.value / e.value)
    if ratios:
        text.append(f"The hemicube (N = {hemi[0].cell.options.get('hemicube_resolution')}) is "
                    f"{factors_range(ratios)} as the paper's ray-traced form factors ({paper}) "
                    f"a shot at R={hemi[0].cell.R} V={hemi[0].cell.V}, over every machine and "
                    "scene that ran both.")
    return [" ".join(text), ""] if text else []


def figure(study, folder):
    from matplotlib.ticker import NullLocator
    from ncube import plotting
    plt = plotting.plt
    fig, axes = plt.subplots(len(study.methods), len(study.scenes), squeeze=False,
                             figsize=(4.2 * len(study.scenes), 3.4 * len(study.methods)),
                             sharey=True)
    colours = {m: f"C{k}" for k, m in enumerate(study.machines)}   # one colour a machine
    for i, method in enumerate(study.methods):
        for j, scene in enumerate(study.scenes):
            ax = axes[i][j]
            for machine in study.machines:
                points = sorted((e.cell.R, study.normalised(e)) for e in study.found
                                if e.machine == machine and e.method == method
                                and e.scene == scene and study.normalised(e) is not None)
                if points:
                    ax.plot([p[0] for p in points], [p[1] for p in points], marker="o",
                            label=machine, color=colours[machine])
            ax.set_xscale("log", base=2)
            ax.set_yscale("log")
            ax.xaxis.set_minor_locator(NullLocator())
            ax.set_xlim(min(study.rows(scene))[0] / 1.2, max(study.rows(scene))[0] * 1.2)
            ax.set_xticks([r for r, _ in study.rows(scene)])
            ax.set_xticklabels([str(r) for r, _ in study.rows(scene)])
            ax.set_title(f"{scene}, {method}", fontsize=10)
            ax.grid(True, which="both", alpha=0.3)
            if i == len(study.methods) - 1:
                ax.set_xlabel("R (V = 64 / R - 1)")
            if j == 0:
                ax.set_ylabel(f"s per iteration / {study.reference}'s")
    shown_lines = {}
    for ax in axes.flat:
        for handle, label in zip(*ax.get_legend_handles_labels()):
            shown_lines.setdefault(label, handle)
    labels = [m for m in study.machines if m in shown_lines]
    fig.legend([shown_lines[m] for m in labels], labels, loc="lower center", ncol=len(study.machines),
               bbox_to_anchor=(0.5, -0.04))
    fig.tight_layout(rect=(0, 0.04, 1, 1))
    Path(folder).mkdir(parents=True, exist_ok=True)
    path = Path(folder) / FIGURE
    plotting.save(fig, path)
    return path


def figure_section(study, path, output):
    return ["## 7. Seconds per iteration against R, normalised to the " + study.reference, "",
            f"Each machine's seconds per iteration over the {study.reference}'s for the same "
            "scene, configuration and method (the " + study.reference + " is the flat line "
            "at 1; lower is faster; a missing point did not fit in memory on one of the two).",
            "", f"![seconds per iteration against R, normalised]"
            f"({os.path.relpath(path, Path(output).parent)})", ""]


def porting_section(study):
    """Plain sentences, each from the figures above."""
    lines = ["## 8. What porting would have meant", ""]
    ref = study.reference
    lines += summary_sentences(study)
    for machine in study.machines[1:]:
        factors = study.factors(machine)
        if not factors:
            lines += [f"* **{machine}**: no configuration finished on both it and the {ref}.", ""]
            continue
        text = (f"* **{machine}**: the same program runs Table 4's configurations "
                f"{factors_range(factors)} as on the {ref}")
        if max(factors) / min(factors) < UNIFORM:
            text += (f": every configuration that runs on both by the same factor (within "
                     f"{100 * (UNIFORM - 1):.0f} %), a change of node speed, not of the balance "
                     "between computing and communication.")
        else:
            text += (f": the factor differs {max(factors) / min(factors):.2f} times between "
                     "configurations, so the balance between computing and communication is "
                     f"not the {ref}'s.")
        for scene in study.scenes:
            best, ref_best = study.best(machine=machine, scene=scene), \
                study.best(machine=ref, scene=scene)
            if best is None or ref_best is None:
                continue
            same = best.row == ref_best.row and best.method == ref_best.method
            text += (f" Its best for {scene} is {config_text(best)} ({seconds(best.value)} s; "
                     f"{time_split(best)}), "
                     + ("the same as on the " + ref if same else
                        f"where the {ref} is best with {config_text(ref_best)} "
                        f"({time_split(ref_best)})") + ".")
        stops, starts = [], []
        for scene in study.scenes:
            for method in study.methods:
                here, there = study.pays(machine, method, scene), study.pays(ref, method, scene)
                if here is not None and there is not None and here != there:
                    (stops if there else starts).append(f"{scene} with {method}")
        if stops:
            text += f" Visibility processors stop paying for {', '.join(stops)}."
        if starts:
            text += f" Visibility processors start to pay for {', '.join(starts)}."
        if not stops and not starts:
            text += (" Whether visibility processors pay is the same as on the "
                     f"{ref} for every scene and method.")
        fits = [e for e in study.found if e.machine == machine and e.status == "ok"
                and (r := study.get(ref, e.method, e.scene, e.row)) is not None
                and r.status == "out_of_memory"]
        nofit = [e for e in study.found if e.machine == machine and e.status == "out_of_memory"
                 and (r := study.get(ref, e.method, e.scene, e.row)) is not None
                 and r.status == "ok"]
        if fits:
            text += (f" It holds {describe_cells(fits)}, which the {ref}'s memory does not.")
        if nofit:
            text += (f" Its memory does not hold {describe_cells(nofit)}, which the {ref} "
                     "runs.")
        lines += [text, ""]
    return lines


def summary_sentences(study):
    """The study in a few sentences: one factor or not, where V > 0 pays."""
    ref, others = study.reference, study.machines[1:]
    ported = [m for m in others if study.factors(m)]
    uniform = [m for m in ported if max(study.factors(m)) / min(study.factors(m)) < UNIFORM]
    varying = [m for m in ported if m not in uniform]
    text = []
    if uniform:
        text.append(f"On {join(uniform)} every configuration changes by one factor against the "
                    f"{ref} (within {100 * (UNIFORM - 1):.0f} %): in this model porting the "
                    "program there changes its speed, not the balance between its computing "
                    "and its communication.")
        one_rate = [m for m in uniform if not any(e.rates for e in study.found if e.machine == m)]
        if one_rate:
            text.append(f"For {join(one_rate)} that is built into the model rather than found by "
                        "it: their platform files give one rate for every kind of counted work "
                        "(docs/machines/README.md, \"Rates per kind of work\"), so a faster node "
                        "shortens every configuration's computing alike, and at these blocks "
                        "the messages are too small a share to move the balance; what the "
                        "simulation measures here is the share of communication, the best "
                        "configuration and what fits in memory (sections 3 to 5), and with "
                        "smaller blocks the balance does move (docs/machines/README.md, "
                        "\"Fine-grained messages\").")
    rated = [m for m in ported if any(e.rates for e in study.found if e.machine == m)]
    for m in rated:
        names = ordered(r for e in study.found if e.machine == m for r in e.rates)
        text.append(f"The {m} gives rates per kind of work ({', '.join(names)}): its factors "
                    "come from how its counted work divides between the kinds, not from one "
                    "speed ratio.")
    if varying:
        text.append(f"On {join(varying)} the factor differs between configurations: there the "
                    "balance between computing and communication is not the " + ref + "'s.")
    combos = [(m, sc, me) for m in study.machines for sc in study.scenes for me in study.methods]
    paying = [(m, sc, me) for m, sc, me in combos if study.pays(m, me, sc)]
    if not paying:
        text.append("Visibility processors (V > 0) beat R=64 V=0 on no machine, for no scene "
                    "and method.")
    else:
        text.append("Visibility processors (V > 0) beat R=64 V=0 on "
                    + "; ".join(f"the {m} for {sc} with {me}" for m, sc, me in paying) + ".")
    ratios = [(abs(study.v_ratio(m, me, sc) / study.v_ratio(ref, me, sc) - 1), m, sc, me)
              for m, sc, me in combos if m != ref and study.v_ratio(m, me, sc)
              and study.v_ratio(ref, me, sc)]
    if ratios:
        worst = max(ratios)
        text.append(f"The gain or loss of V > 0 (section 4's ratio) differs from the {ref}'s "
                    f"by at most {100 * worst[0]:.1f} % (the {worst[1]}, {worst[2]} with "
                    f"{worst[3]}).")
    return [" ".join(text), ""] if text else []


def time_split(entry):
    return (f"its nodes wait {percent(entry.share('waiting'))} of their time, "
            f"{percent(entry.share('overhead'))} in message overhead")


def describe_cells(found):
    configs = ordered(f"{e.scene} R={e.cell.R} V={e.cell.V}" for e in found)
    return ", ".join(configs)


def factors_range(factors):
    low, high = min(factors), max(factors)
    if number(low) == number(high):
        return factor_text(low)
    if low >= 1:
        return f"{number(low)} to {number(high)} times as fast"
    if high <= 1:
        return f"{number(1 / high)} to {number(1 / low)} times as slow"
    return f"between {number(1 / low)} times as slow and {number(high)} times as fast"


def simulate_command(cell):
    """A cell's ./simulate command: its R, V, scene, the options that differ from the defaults."""
    from ncube import options as opts
    args = ["./simulate", Path(cell.scene_file).stem, "--R", str(cell.R), "--V", str(cell.V)]
    for name, value in cell.options.items():
        option = opts.OPTIONS[name]
        if name not in ("R", "V") and value != option.default:
            args += [option.flag] if option.kind is bool else [option.flag, str(value)]
    if Path(cell.platform_file).name != "ncube2.json":
        args += ["--platform", shown(cell.platform_file)]
    return " ".join(args)


def run_sweep(sweep_file, results_dir):
    missing = [c for c in load(sweep_file).cells
               if results.mismatch(results.read(results_dir / c.file), c) is not None]
    if missing:
        page.will_run("machines.py", f"the {len(missing)} cells of {page.shown(sweep_file)} "
                      f"without a result in {page.shown(results_dir)}/ through experiments/sweep")
        code = subprocess.run([sys.executable, str(ROOT / "experiments" / "sweep"),
                               str(sweep_file), "--results", str(results_dir)]).returncode
        if code != 0:
            sys.exit(code)


SCRIPT = "analysis/machines.py"


def opening(found):
    """The page's opening, from its own tables (section 1's seconds, section 2's best, section
    4's ratios): the best split on the nCube2 and whether it is the same elsewhere, each
    machine's factor against the nCube2 and whether that factor is built into the model (one
    rate for every kind of work gives every split the same factor), what does not fit."""
    per_iteration = [(label, rows) for label, rows in found
                     if rows and "R" in rows[0] and "V" in rows[0] and "," in label]
    machines = [k for k in per_iteration[0][1][0] if k not in ("R", "V")]
    reference = machines[0]
    ratios = {m: [] for m in machines[1:]}
    out_of_memory = {m: 0 for m in machines}
    for label, rows in per_iteration:
        for row in rows:
            for m in machines:
                out_of_memory[m] += row[m].startswith("out of memory")
            base = op.number(row[reference]) if not row[reference].startswith("out") else None
            for m in machines[1:]:
                value = op.number(row[m]) if not row[m].startswith("out") else None
                if base and value:
                    ratios[m].append(base / value)
    cells = sum(len(rows) for _, rows in per_iteration)
    compared = [m for m in machines[1:] if ratios[m]]
    one_factor = [m for m in compared if max(ratios[m]) / min(ratios[m]) <= 1.05]
    balance = [m for m in compared if m not in one_factor]

    def shown(x):
        return f"{x:,.0f}" if x >= 100 else f"{x:.2f}"

    def span(m):
        low, high = min(ratios[m]), max(ratios[m])
        if high < 1:
            return f"{shown(1 / high)} to {shown(1 / low)} times as slow"
        return f"{shown(low)} to {shown(high)} times as fast"

    # The question a user asks first: scene2 with the paper's method (else the first table).
    label, first = next(((label, rows) for label, rows in per_iteration
                         if label == "scene2, brute-force"), per_iteration[0])
    timed = [r for r in first if op.number(r[reference]) is not None and
             not r[reference].startswith("out")]
    best2 = min(timed, key=lambda r: op.number(r[reference]))
    cm5 = "CM-5" if "CM-5" in one_factor else (one_factor[0] if one_factor else None)
    if cm5:
        on_cm5 = [r for r in first if op.number(r[cm5]) is not None and not r[cm5].startswith("out")]
        best_cm5 = min(on_cm5, key=lambda r: op.number(r[cm5]))
        same_split = (best_cm5["R"], best_cm5["V"]) == (best2["R"], best2["V"])
    best_cells = op.table(found, "2. The best configuration", "machine")
    scenes = [k for k in best_cells[0] if k != "machine"]
    same_best = all(r[s].split(":")[0] == best_cells[0][s].split(":")[0]
                    for r in best_cells for s in scenes)
    pays = op.table(found, "4. Where visibility processors stop paying", "machine")
    pay_columns = [k for k in pays[0] if k != "machine"]
    paying = sum("does not pay" not in r[c] for r in pays for c in pay_columns)
    ratio_values = [op.number(r[c]) for r in pays for c in pay_columns
                    if op.number(r[c]) is not None] or [float("nan")]
    cm5 = "CM-5" if "CM-5" in one_factor else (one_factor[0] if one_factor else None)
    sentences = [op.Sentence(
        f"On the {reference} the fastest of Table 4's splits for {label} is R={best2['R']} "
        f"V={best2['V']} ({best2[reference]} s per iteration)" +
        (f"; on the {cm5} it is {'the same split' if same_split else 'another split'}, every "
         f"split {span(cm5)} as on the {reference}" if cm5 else ""),
        (f"built into the model: the {', the '.join(one_factor)} differ from the {reference} by "
         "one speed factor for every kind of counted work (their platform files), so their best "
         "split is the same by construction, not found by the simulation") if cm5 else
        "one deterministic run per cell, no interval")]
    if balance:
        sentences.append(op.Sentence(
            f"Only the {' and the '.join(balance)} move the balance between computing and "
            "communication: " + "; ".join(f"{m} {span(m)}, the factor differing "
                                          f"{max(ratios[m]) / min(ratios[m]):.2f} times "
                                          "between splits" for m in balance),
            "their platform files give rates per kind of work, so this is "
            "the model's result; one deterministic run per cell" +
            ("".join(f"; the {PROBED}: " + probed_note(min(ratios[m]), max(ratios[m]))
                     for m in balance if m == PROBED) or ", no interval over the rates")))
    sentences.append(op.Sentence(
        f"The best configuration of each scene is {'the same' if same_best else 'not the same'} "
        f"on every machine ({best_cells[0][scenes[0]].split(':')[0]} for {scenes[0]} on the "
        f"{reference}), and visibility processors pay in {paying} of the "
        f"{len(pays) * len(pay_columns)} machine, scene and method cells of section 4 (the V = 0 "
        f"time over the best V > 0 time {min(ratio_values):.2f} to {max(ratio_values):.2f})",
        "from the tables' seconds; where a machine only rescales the nCube2, built into the "
        "model as above"))
    sentences.append(op.Sentence(
        f"Out of memory, of the {cells} Table 4 cells (both methods, scene3's R=4 V=15 and its "
        "stand-in R=5 V=11): " + ", ".join(f"{m} {out_of_memory[m]}" for m in machines),
        "exact for the model's record sizes against each machine's memory per node; how the "
        "sizes move it: analysis/memory-sensitivity.md"))
    return sentences


def probed_spread():
    """The spread of the probed machine's rates over the recorded probes, against the rates its
    platform file gives: (probes, machines, least and largest ratio over every rate, the same
    for test_speed, the worst miss of the prediction over the runs), or None without records."""
    import json
    import re
    try:
        lines = input_file.read_input_text(PREDICTION_RECORDS, "prediction records",
                                           16 * input_file.MIB).splitlines()
        platform = input_file.read_input_text(PROBED_PLATFORM, "platform file",
                                              input_file.PLATFORM_FILE_BYTES)
    except input_file.InputFileError:
        return None
    records = [json.loads(line) for line in lines if line.strip()]
    committed = {k: float(v) for k, v in re.findall(r'<prop id="(\w+_speed)" value="([^"]+)"',
                                                    platform)}
    ratios, test = [], []
    for record in records:
        for rate, value in record.get("rates", {}).items():
            if rate in committed:
                ratios.append(value / committed[rate])
                if rate == "test_speed":
                    test.append(value / committed[rate])
    if not ratios or not test:
        return None
    misses = [row["simulated"] / row["host"] - 1 for r in records for row in r["rows"]
              if row["kind"] == "ray-traced"]
    return {"probes": len(records), "machines": len({r["machine"] for r in records}),
            "low": min(min(ratios), 1.0), "high": max(max(ratios), 1.0),
            "test_low": min(test), "test_high": max(test),
            "worst_miss": max(misses, key=abs) if misses else None,
            "misses": (min(misses), max(misses)) if misses else None,
            "load": (min(r["load_before"][0] for r in records),
                     max(r["load_after"][0] for r in records))}


def probed_note(low_factor, high_factor):
    """What the probed machine's factors carry: its rates' spread over probes."""
    spread = probed_spread()
    if spread is None:
        return "one probe's rates, no spread recorded (docs/machines/probe.md)"

    def shown(x):
        return f"{x:,.0f}" if x >= 100 else f"{x:.2f}"
    text = (f"its rates are one probe of the host; over {spread['probes']} fresh probes on "
            f"{spread['machines']} machine{'s' if spread['machines'] != 1 else ''} "
            f"(load average {spread['load'][0]:.1f} to {spread['load'][1]:.1f}; "
            f"docs/machines/probe.md) each rate lay within {100 * (spread['low'] - 1):+.0f} to "
            f"{100 * (spread['high'] - 1):+.0f} % of the file's (test_speed, nearly all of a "
            f"brute-force split's computing, {100 * (spread['test_low'] - 1):+.1f} to "
            f"{100 * (spread['test_high'] - 1):+.1f} %), so its factors lie within "
            f"{shown(low_factor * spread['low'])} to {shown(high_factor * spread['high'])} times as fast (every "
            "rate at its least, or at its largest, alike)")
    if spread["misses"]:
        text += (f"; and a one-thread run of the host itself was predicted "
                 f"{100 * spread['misses'][0]:+.1f} to {100 * spread['misses'][1]:+.1f} % over "
                 "those runs")
    return text


@page.refusing_outputs("machines.py")
def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--run", action="store_true",
                        help="first run the cells without a finished result (experiments/sweep)")
    parser.add_argument("--results", type=Path, default=ROOT / RESULTS,
                        help=f"the results folder (default: {RESULTS}/)")
    parser.add_argument("--sweep", type=Path, default=SWEEP_FILE,
                        help=f"the study's sweep file (default: {rel(SWEEP_FILE)})")
    parser.add_argument("--output", type=Path, default=OUTPUT,
                        help=f"the page to write (default: {rel(OUTPUT)})")
    parser.add_argument("--figures", type=Path, default=FIGURES,
                        help=f"the folder of its figure (default: {rel(FIGURES)}/)")
    parser.add_argument("--partial", action="store_true",
                        help="write the page even when cells have no result (shown as not run; "
                             "then --output and --figures elsewhere than the committed page's)")
    args = parser.parse_args()
    results_dir = args.results.resolve()
    try:
        sweep = load(args.sweep)
    except SweepError as e:
        print(f"machines: {e}", file=sys.stderr)
        sys.exit(2)
    # The output rule's paths first: one that cannot be written is named before the results are
    # read or a sweep is run for it (the committed page's own rule needs the results: below).
    page.check_outputs("machines.py", [args.output, args.figures / FIGURE])
    if args.run:
        run_sweep(args.sweep, results_dir)
    found = entries(sweep, results_dir)
    if not args.partial:
        page.require_results("machines.py", [e.cell.file for e in found if e.status == "missing"],
                             len(found), results_dir,
                             "add --run to run them (experiments/sweep) first")
    v0_only = v0_methods(found)
    study = Study(sweep, [e for e in found if e.method not in v0_only])
    others = [e for e in found if e.method in v0_only]
    missing = sum(e.status == "missing" for e in found)
    page.check_outputs("machines.py", [args.output, args.figures / FIGURE],
                       committed=[OUTPUT, FIGURES / FIGURE], complete=missing == 0,
                       how="give --output and --figures elsewhere")
    path = figure(study, args.figures)
    lines = (header(study, args, missing, others) + tables_section(study) + best_section(study)
             + communication_section(study) + bottleneck_section(study)
             + memory_section(study) + v0_section(study, others)
             + figure_section(study, path, args.output)
             + porting_section(study))
    body = "\n".join(lines).rstrip() + "\n"
    page.write(args.output, op.with_opening(body, opening(op.tables(body)), SCRIPT))
    print(f"wrote {args.output}, {path}" + (f"; {missing} cells not run" if missing else ""))


if __name__ == "__main__":
    main()
