#!/usr/bin/python3
"""The figures the docs quote, held to the code and the cheap commands that give them.

    /usr/bin/python3 tests/docs_figures.py build/simulate   # exit 1 naming each figure that differs

Each check names a doc, the sentence that quotes the figures (a regular expression over the
doc's text with every run of white space, line breaks included, read as one space; each
quoted figure is a group) and what gives each figure: a short ./simulate run's result file,
`--describe-options`, a scene file, a source line. A figure is compared at the precision the
doc writes it: "248.86" against the value rounded to two decimals, "1,162" against the exact
count, "1e-4" against the number. A sentence that is no longer found fails as well, so
rewording one means updating its check here; a figure quoted in new prose from a cheap command
gets a check here too (choice: exact sentences rather than markers, so the docs read as before).

Besides the listed sentences, every "`--option ...` (default X)" in docs/*.md and README.md is
compared with the option's default in `--describe-options`, and every "sceneN (X patches",
"sceneN's X elements" and the like with the scene file. docs/performance-log.md is left out:
it is a dated record of what was measured then. Host times are not checked (they depend on
the host); every figure here is simulated or counted, so deterministic. The figures of a run
tests/goldens_test.sh pins (scene0 to convergence, scene2 at R = 4, V = 15) are read from its
record, whose command is checked to be the same run, not run again. About 20 s of CPU time,
every run on one host thread, so about as long on an idle machine; the runs are forked from
build/simulate_server when it is built (tests/robustness/forked_runs.py). Python 3 standard library
only.
"""

import sys  # noqa: E402
from pathlib import Path  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "analysis"))
from ncube.interpreter import use_project_python  # noqa: E402

use_project_python()   # Debian's /usr/bin/python3 (README.md, "Use")

import functools
import json
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "tests" / "robustness"))
import forked_runs  # noqa: E402
DOCS = sorted((ROOT / "docs").glob("*.md")) + [ROOT / "README.md"]
DATED = {"performance-log.md"}
WORDS = {"one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7, "eight": 8,
         "nine": 9, "ten": 10, "eleven": 11, "twelve": 12}


# Runs whose figures tests/goldens_test.sh pins to the last digit: read from the golden record
# (its command checked to be this one) instead of run again (5 CPU seconds).
GOLDEN = {("scene2.json", "--R", "4", "--V", "15", "--iterations", "20"):
          "calibration-table3-scene2-R4-V15",
          ("scene0.json",): "scene0-converged"}


class Probe:
    """Runs ./simulate once per distinct command and keeps its result file."""

    def __init__(self, simulate, work):
        self.simulate = simulate
        self.work = Path(work)
        self.results = {}
        self._options = None

    def run(self, *args):
        if args not in self.results and args in GOLDEN:
            pinned = self.golden(GOLDEN[args], args)
            if pinned is not None:
                self.results[args] = pinned
        if args not in self.results:
            out = self.work / ("run%d.json" % len(self.results))
            self.simulate_run([*args, "--threads", "1", "--quiet", "--json", str(out)])
            self.results[args] = json.loads(out.read_text())
        return self.results[args]

    def simulate_run(self, args):
        """./simulate ARGS in the source folder; its stdout (forked_runs.check_output)."""
        return forked_runs.check_output(self.simulate, args, cwd=ROOT,
                                        env=dict(os.environ, NCUBE_ROOT=str(ROOT))).decode()

    def golden(self, name, args):
        """The figures of a run tests/goldens_test.sh pins to the last digit, from its record
        tests/goldens/NAME.json, when the record's command is ARGS with every other option at
        its default (checked here); else None, and the run is made."""
        record = json.loads((ROOT / "tests" / "goldens" / (name + ".json")).read_text())
        words = record["command"].split()
        given = dict(zip(args[1::2], args[2::2]))
        same = words[:2] == ["./simulate", "scenes/" + args[0]]
        k = 2
        while same and k < len(words):
            flag = words[k]
            if flag not in self.options():
                same = False
            elif k + 1 < len(words) and not words[k + 1].startswith("--"):
                value, k = words[k + 1], k + 2
                wanted = given.pop(flag, None)
                if wanted is None:
                    default = self.default(flag)
                    wanted = str(default).lower() if isinstance(default, bool) else default
                    same = (flag == "--threads" and value == "1") or value == str(wanted) \
                        or (not isinstance(wanted, str) and float(value) == wanted)
                else:
                    same = value == wanted
            else:
                k += 1
                same = flag == "--quiet"
        if not same or given:
            return None
        pinned = record["pinned"]
        seconds = pinned["times"]["iteration_seconds"]
        measured = pinned["iterations_measured"]
        # src/simulation/iteration_time.cpp: the mean of the first iterations_measured, summed
        # in order as std::accumulate does.
        total = 0.0
        for value in seconds[:measured]:
            total += value
        return {"iterations": pinned["iterations"],
                "simulated_seconds": pinned["times"]["simulated_seconds"],
                "seconds_per_iteration": total / measured if measured else None}

    def options(self):
        if self._options is None:
            text = self.simulate_run(["--describe-options"])
            self._options = {o["flag"]: o for o in json.loads(text)}
        return self._options

    def default(self, flag):
        return self.options()[flag]["default"]


def mib(result, role_prefix):
    """The largest peak of the nodes of one role, in MiB (2^20 bytes)."""
    return max(n["peak_memory_bytes"] for n in result["nodes"]
               if n["role"].startswith(role_prefix)) / 2**20


@functools.lru_cache(maxsize=None)
def scene_patches(name):
    """The patches of scenes/NAME (read once)."""
    return json.loads((ROOT / "scenes" / name).read_text())["patches"]


def patch_grids(name):
    """Each patch's element grid [nu, nv] in scenes/NAME."""
    return [p.get("elements", [1, 1]) for p in scene_patches(name)]


def scene_counts(name):
    """(patches, elements, lights) of scenes/NAME, counted from the file."""
    patches = scene_patches(name)
    elements = sum(a * b for a, b in patch_grids(name))
    lights = sum(1 for p in patches if any(p.get("emission", [0, 0, 0])))
    return len(patches), elements, lights


def machine_parameters():
    """{name: value} of platforms/ncube2.json, the machine the docs' tables describe."""
    parameters = json.loads((ROOT / "platforms/ncube2.json").read_text())["parameters"]
    return {name: entry["value"] for name, entry in parameters.items()}


def cost(name):
    """A parameter's value in platforms/cost_model.json."""
    return json.loads((ROOT / "platforms/cost_model.json").read_text())["parameters"][name]["value"]


def paper(table, R, V, scene):
    """The paper's figure for a cell of one of its tables (analysis/paper_tables.json)."""
    tables = json.loads((ROOT / "analysis/paper_tables.json").read_text())["tables"]
    rows = next(t["rows"] for t in tables if t["table"] == table)
    return next(row[scene] for row in rows if row["R"] == R and row["V"] == V)


def table_cells(table):
    """The cells of experiments/tableN.json, each with the sweep's options written out."""
    sweep = json.loads((ROOT / "experiments" / ("table%d.json" % table)).read_text())
    return [json.dumps(dict(sweep.get("options", {}), **{k: v for k, v in cell.items()
                                                         if k != "paper_row"}), sort_keys=True)
            for cell in sweep["cells"]]


def source_value(path, pattern):
    found = re.search(pattern, (ROOT / path).read_text())
    if not found:
        raise LookupError("%s: no match for %r" % (path, pattern))
    return float(found.group(1))


def constant(name):
    """The value of the constexpr NAME under src/ (an integer, shift or decimal expression)."""
    definition = re.compile(r"constexpr [\w:]+ (?:\w+ = [^,;]+, )*%s = ([^,;]+)[,;]" % name)
    for path in sorted((ROOT / "src").rglob("*.h")) + sorted((ROOT / "src").rglob("*.cpp")):
        found = definition.search(path.read_text())
        if found:
            expression = found.group(1).strip()
            kind = re.fullmatch(r"(\w+)\.max_bytes", expression)
            if kind:  # a limit of the input gate's (src/util/input_file.h): its InputKind's bytes
                return input_limit(kind.group(1))
            expression = re.sub(r"std::size_t\((\d+)\)", r"\1", expression)
            expression = re.sub(r"(\d)L\b", r"\1", expression)
            if not re.fullmatch(r"[\d\s<>*+().e-]+", expression):
                raise LookupError("%s: %s = %s is not a plain number" % (path, name, expression))
            return float(eval(expression))  # digits and operators only, checked above
    raise LookupError("no constexpr %s under src/" % name)


def input_limit(kind):
    """The byte limit of the input gate's InputKind KIND (src/util/input_file.h)."""
    text = (ROOT / "src/util/input_file.h").read_text()
    found = re.search(r"InputKind %s\{\"[^\"]*\", ([^}]+)\}" % kind, text)
    if not found:
        raise LookupError("no InputKind %s in src/util/input_file.h" % kind)
    expression = found.group(1).replace("kMiB", str(2**20)).replace("kGiB", str(2**30))
    if not re.fullmatch(r"[\d\s*+()]+", expression):
        raise LookupError("InputKind %s: %s is not a plain number" % (kind, expression))
    return float(eval(expression))  # digits and operators only, checked above


def scene2(probe, R, V):
    return probe.run("scene2.json", "--R", str(R), "--V", str(V), "--iterations", "20")


def scene2_scale(probe, samples):
    """docs/performance-scale.md's 64-node row: simulated seconds per iteration of 2."""
    result = probe.run("scene2.json", "--R", "4", "--V", "15", "--iterations", "2", "--samples",
                       str(samples))
    return result["simulated_seconds"] / 2


def checks(p):
    """(doc, sentence with one group per figure, one function per group giving its value)."""
    scene0 = lambda: p.run("scene0.json")
    cornell = lambda: p.run("cornell-box.json")
    plan = lambda scene, R, V: p.run(scene, "--R", str(R), "--V", str(V), "--iterations", "0",
                                     "--unlimited-memory")
    octree_plan = lambda scene, R, V: p.run(scene, "--R", str(R), "--V", str(V), "--iterations",
                                            "0", "--unlimited-memory", "--visibility", "octree")
    monkey = lambda: p.run("docs/examples/monkey-room.obj", "--iterations", "0",
                           "--unlimited-memory")
    monkey_faces = lambda: len(re.findall(r"^f ", (ROOT / "docs/examples/monkey-room.obj")
                                          .read_text(), re.M))
    scene4_plan = lambda: plan("scene4.json", 8, 7)
    scene3_memory = lambda R, V: mib(plan("scene3.json", R, V), "radiosity")
    return [
        ("model.md", r"With this default scene0 converges in \*\*(\d+) iterations\*\*",
         [lambda: scene0()["iterations"]]),
        ("reproduce.md", r"scene0 takes (\d+) iterations with 64 samples",
         [lambda: scene0()["iterations"]]),
        ("reproduce.md", r"On one node the simulation takes ([\d.]+) s per iteration against the "
         r"paper's [\d.]+ s and needs (\d+) iterations",
         [lambda: scene0()["simulated_seconds"] / scene0()["iterations"],
          lambda: scene0()["iterations"]]),
        ("cli.md", r"cornell-box\.png # to convergence \((\d+) iterations\)",
         [lambda: cornell()["iterations"]]),
        ("model.md", r"the Cornell box to convergence \((\d+) iterations; ([\d,]+) elements "
         r"uniform, ([\d,]+) adaptive\)",
         [lambda: cornell()["iterations"], lambda: cornell()["scene"]["elements"],
          lambda: p.run("cornell-box.json", "--subdivide")["elements_at_end"]]),
        ("model.md", r"\| Cornell box, R=16 V=3 \| ([\d.]+) \(([\d.]+) s to convergence, (\d+) "
         r"iterations\)",
         [lambda: p.run("cornell-box.json", "--R", "16", "--V", "3")["seconds_per_iteration"],
          lambda: p.run("cornell-box.json", "--R", "16", "--V", "3")["simulated_seconds"],
          lambda: p.run("cornell-box.json", "--R", "16", "--V", "3")["iterations"]]),
        ("platforms.md", r"\| `platforms/ncube2\.json` \(hypercube\) \| ([\d.]+) \|",
         [lambda: scene2(p, 8, 7)["seconds_per_iteration"]]),
        ("platforms.md", r"\| `docs/examples/fat-tree-64\.xml` \(fat tree\) \| ([\d.]+) \|",
         [lambda: p.run("scene2.json", "--R", "8", "--V", "7", "--iterations", "20", "--platform",
                        "docs/examples/fat-tree-64.xml")["seconds_per_iteration"]]),
        ("model.md", r"\| 4 x 15 \| ([\d.]+) \| [\d.]+ \|",
         [lambda: scene2(p, 4, 15)["seconds_per_iteration"]]),
        ("model.md", r"\| 8 x 7 \| ([\d.]+) \| [\d.]+ \|",
         [lambda: scene2(p, 8, 7)["seconds_per_iteration"]]),
        ("model.md", r"\| 16 x 3 \| ([\d.]+) \| [\d.]+ \|",
         [lambda: scene2(p, 16, 3)["seconds_per_iteration"]]),
        ("model.md", r"\| 64 x 0 \| ([\d.]+) \| [\d.]+ \|",
         [lambda: scene2(p, 64, 0)["seconds_per_iteration"]]),
        ("reproduce.md", r"the simulation's order for scene2 is R=64,V=0 (\d+) s, R=8,V=7 (\d+), "
         r"R=4,V=15 (\d+), R=16,V=3 (\d+), R=32,V=1 (\d+) ",
         [lambda R=R, V=V: scene2(p, R, V)["seconds_per_iteration"]
          for R, V in ((64, 0), (8, 7), (4, 15), (16, 3), (32, 1))]),
        ("reproduce.md", r"\(paper: R=8,V=7 (\d+), R=16,V=3 (\d+), R=64,V=0 (\d+), R=4,V=15 (\d+), "
         r"R=32,V=1 (\d+)\)",
         [lambda R=R, V=V: paper(4, R, V, "scene2")
          for R, V in ((8, 7), (16, 3), (64, 0), (4, 15), (32, 1))]),
        ("README.md",
         r"--iterations 20 # ([\d.]+) s per iteration; the paper's (\d+) s",
         [lambda: scene2(p, 8, 7)["seconds_per_iteration"], lambda: paper(4, 8, 7, "scene2")]),
        ("reproduce.md", r"scene3 needs ([\d.]+) MB \(V=3\) and ([\d.]+) MB \(V=15\) on a "
         r"radiosity processor at R=4, ([\d.]+) MB at R=5, V=11, ([\d.]+) MB at R=64, V=0",
         [lambda: scene3_memory(4, 3), lambda: scene3_memory(4, 15), lambda: scene3_memory(5, 11),
          lambda: scene3_memory(64, 0)]),
        ("performance-scale.md", r"\| 64 \| 4 \| 15 \| [\d.]+ \| [\d.]+ \| \d+ \| ([\d.]+) \|",
         [lambda: scene2_scale(p, 16)]),
        ("performance-scale.md", r"\(64 nodes: ([\d.]+) s per iteration against ([\d.]+)\)",
         [lambda: scene2_scale(p, 64), lambda: scene2_scale(p, 16)]),
        ("performance-scale.md", r"scene2's largest patch \((\d+) elements, while the mean share "
         r"is (\d+) elements at R = 256\)",
         [lambda: max(a * b for a, b in patch_grids("scene2.json")),
          lambda: scene_counts("scene2.json")[1] / 256]),
        ("scenes.md", r"\| 8 \| 7 \| 64 \| ([\d,]+) \| ([\d,]+) \| yes \|",
         [lambda: mib(scene4_plan(), "radiosity") * 2**20,
          lambda: mib(scene4_plan(), "visibility") * 2**20]),
        ("scene-format.md", r"\(`docs/examples/make_monkey_room\.py`\): (\d+) faces, of which the "
         r"monkey's (\d+) bent quads are cut in two, (\d+) patches",
         [lambda: monkey_faces(), lambda: monkey()["scene"]["patches"] - monkey_faces(),
          lambda: monkey()["scene"]["patches"]]),
        ("model.md", r"scene1 \(288 patches\) whole scene \d+ cells, about (\d+) KB;",
         [lambda: (octree_plan("scene1.json", 1, 0)["nodes"][0]["peak_memory_bytes"]
                   - plan("scene1.json", 1, 0)["nodes"][0]["peak_memory_bytes"]) / 1000]),
        ("model.md", r"largest node holds ([\d.]+) MB for scene2, ([\d.]+) MB for scene3; "
         r"MB = 2\^20 bytes here\)",
         [lambda: mib(octree_plan("scene2.json", 64, 0), "radiosity"),
          lambda: mib(octree_plan("scene3.json", 64, 0), "radiosity")]),
        ("model.md", r"a visibility processor's octree over a 1/7 share \(([\d,]+) patches, "
         r"[^)]*\) takes about ([\d.]+) MB, so R = 8, V = 7 needs ([\d.]+) MB on a visibility "
         r"processor \(brute force: ([\d.]+) MB\), and 16 x 3 and 21 x 2 need ([\d.]+) and "
         r"([\d.]+) MB",
         [lambda: scene_counts("scene4.json")[0] / 7,
          lambda: mib(octree_plan("scene4.json", 8, 7), "visibility")
          - mib(plan("scene4.json", 8, 7), "visibility"),
          lambda: mib(octree_plan("scene4.json", 8, 7), "visibility"),
          lambda: mib(plan("scene4.json", 8, 7), "visibility"),
          lambda: mib(octree_plan("scene4.json", 16, 3), "visibility"),
          lambda: mib(octree_plan("scene4.json", 21, 2), "visibility")]),
        ("scenes.md", r"\*\*Elements: ([\d,]+)\*\*, ([\d.]+) per patch, .*?: ([\d,]+) patches "
         r"\(chair legs, books, seats, light panels\) have one element",
         [lambda: scene_counts("scene4.json")[1],
          lambda: scene_counts("scene4.json")[1] / scene_counts("scene4.json")[0],
          lambda: sum(1 for a, b in patch_grids("scene4.json") if a * b == 1)]),
        ("scenes.md", r"no patch may hold more than 1/512 of the elements \((\d+)\); the largest "
         r"holds (\d+),",
         [lambda: scene_counts("scene4.json")[1] / 512,
          lambda: max(a * b for a, b in patch_grids("scene4.json"))]),
        ("model.md", r"scene1 \(288 patches\) whole scene (\d+) cells",
         [lambda: octree_plan("scene1.json", 1, 0)["counts"]["octree_cells_built"]]),
        # One default for M (docs/model.md, "Options"): the code's and simulate's.
        ("model.md", r"The shooter's part count M has one default, (\d+)",
         [lambda: source_value("src/radiosity/radiosity_engine.h", r"int samples = (\d+);")]),
        ("model.md", r"The shooter's part count M has one default, (\d+)",
         [lambda: p.default("--samples")]),
        ("model.md", r"\(`--samples M`, a perfect square 1\.\.64, default (\d+)",
         [lambda: p.default("--samples")]),
        ("model.md",
         r"\(1 \+ `--balance-threshold`\) × the mean element count \(default ([\d.]+)\)",
         [lambda: p.default("--balance-threshold")]),
        ("README.md", r"The defaults are the calibrated setup \((\d+) samples per shooter\)",
         [lambda: p.default("--samples")]),
        # Limits and constants quoted with their names.
        ("scene-format.md", r"`kMaxElementsPerPatch` = 2\^20 = ([\d,]+) per patch",
         [lambda: constant("kMaxElementsPerPatch")]),
        ("scene-format.md", r"`kMaxElementsPerScene` = 2\^24 = ([\d,]+);",
         [lambda: constant("kMaxElementsPerScene")]),
        ("scene-format.md", r"`kMaxSceneFileBytes` = (\d+) MiB",
         [lambda: constant("kMaxSceneFileBytes") / 2**20]),
        ("scene-format.md", r"the paper's largest scene, scene3, is ([\d.]+) MB\)",
         [lambda: (ROOT / "scenes/scene3.json").stat().st_size / 2**20]),
        ("scene-format.md", r"`kMaxNestingDepth` = (\d+) deep",
         [lambda: constant("kMaxNestingDepth")]),
        ("scene-format.md", r"A model file over (\d+) MiB \(`kMaxSceneFileBytes`\)",
         [lambda: constant("kMaxSceneFileBytes") / 2**20]),
        ("scene-format.md", r"must lie in \[([\de.+-]+), ([\de.+-]+)\] \(`kMinEmission`, "
         r"`kMaxEmission`",
         [lambda: constant("kMinEmission"), lambda: constant("kMaxEmission")]),
        ("cli.md", r"Scene files: at most (\d+) MiB \(`kMaxSceneFileBytes`",
         [lambda: constant("kMaxSceneFileBytes") / 2**20]),
        ("cli.md", r"JSON nesting at most (\d+) arrays and objects deep",
         [lambda: constant("kMaxNestingDepth")]),
        ("cli.md", r"Platform and cost-model files: at most (\d+) MiB each",
         [lambda: input_limit("kPlatformFile") / 2**20]),
        ("cli.md", r"Platform and cost-model files: at most (\d+) MiB each",
         [lambda: input_limit("kCostModelFile") / 2**20]),
        ("performance.md", r"`kEndGap` = ([\d.]+) pad past its point",
         [lambda: constant("kEndGap")]),
        ("performance.md", r"`kNearRadius` = ([\d.]+) pads holds the end",
         [lambda: constant("kNearRadius")]),
        ("performance.md", r"Choice: pad = ([\de.-]+) S, band = ([\de.-]+) S",
         [lambda: constant("kPad"), lambda: constant("kBand")]),
        ("sweeps.md", r"the five sweeps of the paper's tables list (\d+) cells, (\d+) of them "
         r"distinct: Tables 2 and 4 share (\w+)\)",
         [lambda: sum(len(table_cells(k)) for k in range(1, 6)),
          lambda: len(set().union(*(table_cells(k) for k in range(1, 6)))),
          lambda: len(set(table_cells(2)) & set(table_cells(4)))]),
        ("reproduce.md", r"\*\*30 s wall time\*\* for the (\d+) distinct cells",
         [lambda: len(set().union(*(table_cells(k) for k in range(1, 6))))]),
        ("reproduce.md", r"`element_bytes` [\d.]+ \(current (\d+), [^)]*\), `node_reserve_bytes` "
         r"[\d,.]+ \(current ([\d,]+)\)",
         [lambda: cost("element_bytes"), lambda: cost("node_reserve_bytes")]),
        ("scenes.md", r"a node has ([\d,]+) bytes, ([\d,]+) of them reserved and (\d+) for two "
         r"shooter records, leaving \*\*([\d,]+) bytes\*\*",
         [lambda: machine_parameters()["node_memory"], lambda: cost("node_reserve_bytes"),
          lambda: 2 * cost("shooter_record_bytes"),
          lambda: machine_parameters()["node_memory"] - cost("node_reserve_bytes")
          - 2 * cost("shooter_record_bytes")]),
        ("performance.md", r"a memo of the last (\d+) blocks",
         [lambda: constant("kMemoBlocks")]),
        ("performance.md", r"\*\*Budget, choice: (\d+) MiB per scene in the process\*\*",
         [lambda: source_value("src/host/answer_cache.cpp", r"std::size_t megabytes = (\d+);")]),
        ("architecture.md", r"`tests/seam_test\.sh` holds (\w+) whole runs",
         [lambda: len(re.findall(r"^check ", (ROOT / "tests/seam_test.sh").read_text(), re.M))]),
        ("reproduce.md", r"compares (\d+) speedup ratios",
         [lambda: len(json.loads((ROOT / "tests/expected_speedups.json").read_text())["ratios"])]),
    ] + [
        (doc, r"\| (?:`\w+`, )?`%s`(?:, `\w+`)? \| ([\d.e,+-]+) " % name,
         [lambda value=value: value])
        # docs/model.md's machine table is written from the file (tests/platform_tables_test.sh)
        for doc in ("ncube2-sources.md",)
        for name, value in machine_parameters().items()
    ] + [
        ("scenes.md", r"\| `%s` \| [^|]+\| ([\d,]+) \| ([\d,]+) \| ([\d,]+) \|" % re.escape(name),
         [lambda name=name, k=k: scene_counts(name)[k] for k in range(3)])
        for name in ("scene0.json", "scene1.json", "scene2.json", "scene3.json", "scene4.json",
                     "cornell-box.json")
    ]


def number(text):
    text = text.replace(",", "")
    return WORDS[text] if text in WORDS else float(text)


def agrees(quoted, value):
    """Whether the doc's figure is the value at the precision the doc writes it."""
    text = quoted.replace(",", "")
    if text in WORDS or "e" in text:
        return abs(number(text) - value) <= 1e-12 * abs(value)
    decimals = len(text.split(".")[1]) if "." in text else 0
    return "%.*f" % (decimals, value) == text


def flat(doc):
    return " ".join((ROOT / "docs" / doc if doc != "README.md" else ROOT / doc).read_text().split())


def generic_checks(probe):
    """Defaults and scene counts wherever prose quotes them: (doc, quoted, value, what)."""
    found = []
    option_default = re.compile(r"`(--[a-z][a-z-]*)(?: [A-Z]+)?` \(default:? (-?\d[\d.e+-]*)")
    scene_count = re.compile(r"\b(scene[0-4])(?: \(|'s |: )([\d,]+) (patches|elements)\b")
    scene_both = re.compile(r"\b(scene[0-4]) \(([\d,]+) patches, ([\d,]+) elements\)")
    for path in DOCS:
        if path.name in DATED:
            continue
        text = flat(path.name)
        for flag, quoted in option_default.findall(text):
            default = probe.default(flag)
            found.append((path.name, quoted.rstrip(".e+-"), float(default),
                          "the default of %s" % flag))
        for scene, quoted, kind in scene_count.findall(text):
            value = scene_counts(scene + ".json")[0 if kind == "patches" else 1]
            found.append((path.name, quoted, value, "%s's %s" % (scene, kind)))
        for scene, patches, elements in scene_both.findall(text):
            found.append((path.name, elements, scene_counts(scene + ".json")[1],
                          "%s's elements" % scene))
    return found


def main():
    if sys.argv[1:] in (["-h"], ["--help"]):
        print("usage: docs_figures.py SIMULATE\n" + __doc__)
        return 0
    if len(sys.argv) != 2:
        sys.exit("usage: docs_figures.py SIMULATE")
    failures = []
    compared = 0
    with tempfile.TemporaryDirectory() as work:
        probe = Probe(sys.argv[1], work)
        for doc, sentence, values in checks(probe):
            found = re.search(sentence, flat(doc))
            if not found:
                failures.append("%s: no sentence matches %r (reworded? update "
                                "tests/docs_figures.py)" % (doc, sentence))
                continue
            for k, value in enumerate(values):
                compared += 1
                quoted = found.group(k + 1)
                try:
                    got = value()
                except (LookupError, StopIteration, subprocess.CalledProcessError) as error:
                    failures.append("%s: %r: the figure's source failed: %s"
                                    % (doc, found.group(0), error))
                    continue
                if not agrees(quoted, got):
                    failures.append("%s: %r quotes %s where the code gives %r"
                                    % (doc, found.group(0), quoted, got))
        generic = generic_checks(probe)
        kinds = {what.split("'s ")[-1].split(" of ")[0] for _, _, _, what in generic}
        if len(generic) < 10 or not {"patches", "elements", "the default"} <= kinds:
            failures.append("the generic checks found only %d figures (%s): their patterns no "
                            "longer match the docs" % (len(generic), sorted(kinds)))
        for doc, quoted, value, what in generic:
            compared += 1
            if not agrees(quoted, value):
                failures.append("%s: %s is quoted as %s, the code gives %r"
                                % (doc, what, quoted, value))
    for failure in failures:
        print("FAIL:", failure)
    print("docs figures: %d compared, %d differ" % (compared, len(failures)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
