"""The paper's headline comparison, decided: "for certain processor configurations the method
also outperforms the naive parallelization of the progressive radiosity method" (section 6,
the conclusion).

Per scene of Tables 4 and 5: the fastest configuration with visibility processors (V > 0)
against the fastest naive one (V = 0 on more than one node), over the table's configurations
(Table 4: the five splits of 64 nodes; Table 5: scene0's parallel rows, up to 64 nodes). It
holds when the first is faster. Decided on the paper's values, on the simulation's (the default
world, analysis/report.md) and in each world of the unknowns study (analysis/unknowns.md,
analysis/unknowns-worlds.json), whose share of worlds is the finding's frequency.

Used by analysis/report.py (its section and opening) and analysis/headline.py (what the model
would need to flip scene2 back)."""
from dataclasses import dataclass

# (table, scene): the rows (R, V) compared, as the paper prints them (scene3's R=4 V=15 is run
# as R=5 V=11 in the paper and in the simulation: the table's note).
TABLE4_ROWS = [(4, 15), (8, 7), (16, 3), (32, 1), (64, 0)]
TABLE5_ROWS = [(4, 7), (4, 15), (8, 3), (8, 7), (16, 3), (32, 0), (52, 0)]
SCENES = [(4, "scene1", TABLE4_ROWS), (4, "scene2", TABLE4_ROWS), (4, "scene3", TABLE4_ROWS),
          (5, "scene0", TABLE5_ROWS)]


@dataclass
class Decision:
    best_visibility: tuple      # (R, V) fastest with V > 0
    visibility_seconds: float
    best_naive: tuple           # (R, V) fastest with V = 0
    naive_seconds: float

    @property
    def holds(self):
        return self.visibility_seconds < self.naive_seconds

    @property
    def winner(self):
        return self.best_visibility if self.holds else self.best_naive

    @property
    def factor(self):
        """How many times as fast the winner is as the other side's best."""
        low, high = sorted((self.visibility_seconds, self.naive_seconds))
        return high / low


def decide(times):
    """The decision on {(R, V): seconds} (None: no value, e.g. out of memory); None when one
    side has no value at all."""
    known = {rv: t for rv, t in times.items() if t is not None}
    visibility = [rv for rv in known if rv[1] > 0]
    naive = [rv for rv in known if rv[1] == 0 and rv[0] > 1]
    if not visibility or not naive:
        return None
    v, n = min(visibility, key=known.get), min(naive, key=known.get)
    return Decision(v, known[v], n, known[n])


def paper_times(paper, table, scene, rows):
    """{(R, V): the paper's value} of analysis/paper_tables.json."""
    printed = next(t for t in paper["tables"] if t["table"] == table)
    by_row = {(r["R"], r["V"]): r.get(scene) for r in printed["rows"]}
    return {rv: by_row.get(rv) for rv in rows}


def world_times(world, table, scene, rows):
    """{(R, V): seconds} of one world of analysis/unknowns-worlds.json. Its cells are keyed
    "T<table> <scene> R=<R> V=<V>", a configuration in several tables under one of them."""
    by_row = {}
    for key, value in world["cells"].items():
        _, cell_scene, r, v = key.split()
        if cell_scene == scene:
            by_row[(int(r[2:]), int(v[2:]))] = value
    return {rv: by_row.get(rv) for rv in rows}


def frequency(summary, table, scene, rows):
    """(worlds where it holds, worlds where it is decided, drawn worlds) over the unknowns
    study's drawn worlds (the default world, the first, is not one of them)."""
    drawn = summary["worlds"][1:]
    decisions = [decide(world_times(w, table, scene, rows)) for w in drawn]
    decided = [d for d in decisions if d is not None]
    return sum(d.holds for d in decided), len(decided), len(drawn)


def row_text(rv):
    return f"R={rv[0]} V={rv[1]}"
