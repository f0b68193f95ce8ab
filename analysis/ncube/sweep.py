"""Sweep files (docs/sweeps.md): a grid or a list of cells over scenes, R, V and any ./simulate
option, plus platform, cost model and a measure. Loading validates strictly: an unknown key, a
bad value or an impossible cell is refused at once, naming the file, the cell and the key.

A cell's identity is its complete configuration: every option (defaults written out), the
SimGrid settings, whether it is traced, and the content hashes of its scene, platform and
cost-model files. Its result file is named after the identity, so a changed option or input
file can never reuse a stale result."""
import functools
import hashlib
import itertools
import json
import math
import os
import re
import subprocess
from dataclasses import asdict, dataclass, field
from pathlib import Path

from . import cell_names, input_file, output_file, sweep_keys
from . import options as opts
from . import paths
from .results import MEASURES

SWEEP_KEYS = {
    "name": "the sweep's name (default: the file's name without extension)",
    "description": "free text",
    "measure": "seconds_per_iteration or total_seconds",
    "options": "cell keys applied to every cell (a cell's own keys win)",
    "grid": "cell keys with lists of values: every combination is a cell; any other name "
            "is a group of keys that vary together, a list of mappings (e.g. {R: 4, V: 15})",
    "cells": "a list of cells",
    "paper_table": "the paper table the sweep reproduces (for analysis/report.py)",
}
@functools.lru_cache(maxsize=None)
def _settings_problem(arguments):
    simulate = paths.simulate_binary()
    if not os.access(simulate, os.X_OK):
        return None   # no simulator to ask yet: the cell's own run would say it
    checked = subprocess.run([simulate, "--check-settings", *arguments], capture_output=True,
                             text=True, env=paths.simulate_environment())
    if checked.returncode == 0:
        # A sweep writes into its results folder only (docs/sweeps.md, "What runs"): settings
        # that would make SimGrid write a file (a trace: the cell key trace instead) are refused.
        written = [line.removeprefix("output: ") for line in checked.stdout.splitlines()
                   if line.startswith("output: ")]
        return (f"these settings would make SimGrid write {', '.join(written)}; a sweep writes "
                f"only into its results folder (a cell's trace: the key trace: true)"
                if written else None)
    return checked.stderr.strip().removeprefix("simulate: ") or f"exit {checked.returncode}"


def simgrid_settings_problem(cfg):
    """What SimGrid says against a cell's settings, asked of ./simulate --check-settings before
    anything runs (SimGrid would end a cell's run with an abort); None when it takes them."""
    if not cfg:
        return None
    return _settings_problem(tuple(f"--cfg={k}:{v}" for k, v in sorted(cfg.items())))


# The most cells one sweep file may describe, counted before any is made: each cell is checked,
# hashed and planned (about a millisecond and a few KB each), and each is one file of the results
# folder; a grid of 10^8 would take gigabytes before its first line of output.
MAX_CELLS = 100_000

# A sweep's name names a folder of the results (sweeps/<name>/) and a Snakemake wildcard; it is
# held to a set of characters no shell, file system or scheduler reads as syntax
# (docs/sweeps.md), so that no sweep file can make the sweep tool run a command.
SWEEP_NAME = re.compile(r"[A-Za-z0-9][A-Za-z0-9_.+-]{0,99}")
CELL_KEYS = dict({name: option.doc or name for name, option in opts.OPTIONS.items()},
                 scene="a scene or model file (.obj, .ply, .gltf, .glb): a path (relative to the sweep file) or a name in scenes/",
                 platform="a platform file (JSON or SimGrid XML): a path or a name in platforms/",
                 cost_model="a cost-model file: a path or a name in platforms/",
                 cfg="SimGrid settings, {name: value} (./simulate --cfg=name:value)",
                 trace="also write the per-node timeline (./simulate --trace)",
                 paper_row="the paper's row {R, V} this cell stands for (not part of its identity)")


class SweepError(Exception):
    """A sweep file that cannot be run; the message names the file, the cell and the key."""


def read_input(path, what, max_bytes, text=True):
    """PATH read through the sweep tool's input gate (ncube.input_file): a SweepError naming
    the file for anything but a regular file within MAX_BYTES."""
    try:
        if text:
            return input_file.read_input_text(path, what, max_bytes)
        return input_file.read_input_bytes(path, what, max_bytes)
    except input_file.InputFileError as e:
        raise SweepError(str(e)) from None


# While load() reads one sweep file: (kind, path) -> what was read of it, so that a scene,
# platform or cost model many cells name is read, parsed and hashed once per sweep file, not
# once per cell (scene4.json, 7 MB, for 24 cells: 20 s of a --check). Emptied after each load.
_this_load = {}
_loading = False


def _once(kind, path, compute):
    if not _loading:
        return compute()
    key = (kind, str(path))
    if key not in _this_load:
        _this_load[key] = compute()
    return _this_load[key]


def file_sha256(path, what="file"):
    def digest():
        data = read_input(path, what, input_file.SCENE_FILE_BYTES, text=False)
        return "sha256:" + hashlib.sha256(data).hexdigest()
    return _once("sha256", path, digest)


@dataclass
class Cell:
    sweep: str
    label: str                  # how the sweep file names it, for messages
    scene: str                  # the scene's name (its "name" field)
    scene_file: str
    scene_sha256: str
    platform_file: str
    platform_sha256: str
    cost_model_file: str
    cost_model_sha256: str
    options: dict               # every ./simulate option, defaults written out
    cfg: dict = field(default_factory=dict)
    trace: bool = False
    paper_row: dict = None
    scene_parts_sha256: str = ""  # a model's MTL and buffers (parts_sha256)
    nodes: int = 0              # the platform's

    @property
    def R(self):
        return self.options["R"]

    @property
    def V(self):
        return self.options["V"]

    def identity(self):
        identity = {"scene_sha256": self.scene_sha256, "platform_sha256": self.platform_sha256,
                    "cost_model_sha256": self.cost_model_sha256, "options": self.options,
                    "cfg": {k: str(v) for k, v in sorted(self.cfg.items())}, "trace": self.trace}
        if self.scene_parts_sha256:   # only models have parts: scene files keep their ids
            identity["scene_parts_sha256"] = self.scene_parts_sha256
        return identity

    @property
    def id(self):
        text = json.dumps(self.identity(), sort_keys=True, separators=(",", ":"))
        return hashlib.sha256(text.encode()).hexdigest()[:12]

    @property
    def file(self):
        """The result file, relative to the results folder."""
        return cell_names.file(self)

    @property
    def legacy_file(self):
        """The result file's name before the varied keys were in it (ncube.cell_names)."""
        return cell_names.legacy_file(self)

    @property
    def trace_file(self):
        return self.file[:-len(".json")] + ".trace.json" if self.trace else None

    def config_fields(self):
        return opts.config_fields(self.options)

    def command(self, json_out, trace_out=None, simulate=None):
        return opts.command(simulate or paths.simulate_binary(), self.scene_file, self.options,
                            self.platform_file, self.cost_model_file, self.cfg, json_out,
                            trace_out)

    def to_dict(self):
        return dict(asdict(self), id=self.id, file=self.file, trace_file=self.trace_file)

    @classmethod
    def from_dict(cls, d):
        return cls(**{k: v for k, v in d.items() if k not in ("id", "file", "trace_file")})


@dataclass
class Sweep:
    name: str
    file: str
    measure: str
    description: str
    cells: list
    paper_table: object = None

    def to_dict(self):
        return {"name": self.name, "file": self.file, "measure": self.measure,
                "description": self.description, "paper_table": self.paper_table,
                "cells": [c.to_dict() for c in self.cells]}

    @classmethod
    def from_dict(cls, d):
        return cls(d["name"], d["file"], d["measure"], d["description"],
                   [Cell.from_dict(c) for c in d["cells"]], d.get("paper_table"))


def read_document(path):
    text = read_input(path, "sweep file", input_file.SWEEP_FILE_BYTES)
    if Path(path).suffix in (".yaml", ".yml"):
        import yaml
        try:
            return yaml.safe_load(text)
        except yaml.YAMLError as e:
            raise SweepError(f"{path}: not valid YAML: {e}") from None
        except RecursionError:
            raise SweepError(f"{path}: nested too deeply to read (a sweep file is a few "
                             "levels of mappings and lists)") from None
    try:
        return json.loads(text)
    except ValueError as e:
        raise SweepError(f"{path}: not valid JSON: {e}") from None
    except RecursionError:
        raise SweepError(f"{path}: nested too deeply to read (a sweep file is a few levels of "
                         "mappings and lists)") from None


def _simulator_files():
    """The simulator's binary (the build behind ./simulate, or $NCUBE_SIMULATE and, when that
    is a wrapper, the build's binary too), resolved: what a node count depends on besides the
    platform file."""
    named = Path(paths.simulate_binary())
    build = (paths.ROOT / "build" / "simulate").resolve()
    files = [build] if named.resolve() == (paths.ROOT / "simulate").resolve() else [named.resolve()]
    if build not in files and build.exists():
        files.append(build)
    return files


def _node_count_file(path, text):
    """Where this build keeps the node count of the platform at `path` with content `text`:
    build/platform-nodes/<key>, the key a SHA-256 of the platform's absolute path and bytes and
    of each simulator file's identity (inode, size, modification time), so an edited platform
    or a rebuilt simulator asks ./simulate again. A sweep's every cell job is a process of its
    own that reads the sweep file again (a 32-cell sweep of 4 platforms asked ./simulate 128
    times, each a start of SimGrid: about 0.1 CPU-second); now each platform is asked once per
    build. None when the simulator's folder cannot hold the cache."""
    key = hashlib.sha256()
    for binary in _simulator_files():
        status = binary.stat()
        key.update(f"{binary}\0{status.st_ino}\0{status.st_size}\0{status.st_mtime_ns}\0".encode())
    key.update(f"{Path(path).resolve()}\0".encode())
    key.update(text.encode())
    return _simulator_files()[0].parent / "platform-nodes" / key.hexdigest()


@functools.lru_cache(maxsize=None)
def _platform_nodes(path, text):
    try:
        cached = _node_count_file(path, text)
    except OSError:
        cached = None
    if cached is not None and cached.is_file():
        try:   # through the gate, as every file read; a damaged entry is asked again
            return int(input_file.read_input_text(cached, "platform node count", 32))
        except (input_file.InputFileError, ValueError):
            pass
    run = subprocess.run([paths.simulate_binary(), "--platform", path, "--platform-nodes"],
                         capture_output=True, text=True, env=paths.simulate_environment())
    if run.returncode != 0:
        raise ValueError(run.stderr.strip().removeprefix("simulate: "))
    nodes = int(run.stdout)
    if cached is not None and (not os.path.lexists(cached) or
                               (cached.is_file() and not cached.is_symlink())):
        # Written by the output rule (a temporary file renamed into place), new or over a
        # damaged entry; never onto whatever else lies at its name (a FIFO would block).
        try:
            cached.parent.mkdir(exist_ok=True)
            output_file.write(cached, f"{nodes}\n")
        except OSError:
            pass   # a read-only build: asked again next time
    return nodes


ESTIMATE_MAX_DIMENSION = 30   # bounds the estimate's power only (./simulate's range is 0 to 13)


def platform_nodes(path):
    """Nodes of a platform file, as ./simulate counts them (--platform-nodes: the file read with
    every check and limit a run applies: one function for both). Without a simulator built yet
    (sweep files read by a page script in a fresh clone), an estimate that runs nothing: a JSON
    platform's 2^dimension, an XML one's node-k hosts and cluster radicals, counted by ranges;
    the cells' own runs then check the file."""
    return _once("nodes", path, lambda: _counted_nodes(path))


def _counted_nodes(path):
    text = read_input(path, "platform file", input_file.PLATFORM_FILE_BYTES)   # through the gate
    if _simulator_built():
        return _platform_nodes(str(path), text)
    if not text.lstrip().startswith("<"):
        dimension = json.loads(text)["parameters"]["dimension"]["value"]
        # Bounded before the power (1e9 would take 2^(10^9), 1e400 is infinite): far above
        # ./simulate's own range, which the cells' runs apply.
        whole = (isinstance(dimension, int) and not isinstance(dimension, bool)) or \
            (isinstance(dimension, float) and math.isfinite(dimension) and dimension.is_integer())
        if not whole or not 0 <= dimension <= ESTIMATE_MAX_DIMENSION:
            raise ValueError(f"{path}: parameters: dimension: {dimension!r} is not a whole number "
                             f"from 0 to {ESTIMATE_MAX_DIMENSION}")
        return 2 ** int(dimension)
    names = set(re.findall(r'<host\s[^>]*id="(node-\d+)"', text))
    count = len(names)
    for radical in re.findall(r'<cluster\s[^>]*radical="([\d,-]+)"', text):
        for part in radical.split(","):
            low, _, high = part.partition("-")
            count += max(0, int(high or low) - int(low) + 1)
    return count


def _simulator_built():
    """Whether the simulator can run: $NCUBE_SIMULATE, else the build behind ./simulate."""
    binary = Path(paths.simulate_binary())
    if binary.resolve() == (paths.ROOT / "simulate").resolve():
        binary = paths.ROOT / "build" / "simulate"
    return os.access(binary, os.X_OK)


MODEL_SUFFIXES = (".obj", ".ply", ".gltf", ".glb")   # models ./simulate imports


def is_model(path):
    return Path(path).suffix.lower() in MODEL_SUFFIXES


@functools.lru_cache(maxsize=None)
def _imported(path):
    """A model as ./simulate imports it (its scene JSON, written to stdout)."""
    run = subprocess.run([paths.simulate_binary(), path, "--iterations", "0", "--quiet",
                          "--export-scene", "-"], capture_output=True, text=True,
                         env=paths.simulate_environment())
    if run.returncode != 0:
        raise ValueError(run.stderr.strip().removeprefix("simulate: "))
    return json.loads(run.stdout)


def scene_summary(path):
    """(name, patches) of a scene file, or of a model as imported."""
    def summary():
        scene = (_imported(str(path)) if is_model(path)
                 else json.loads(read_input(path, "scene file", input_file.SCENE_FILE_BYTES)))
        return scene.get("name", Path(path).stem), len(scene.get("patches", []))
    return _once("summary", path, summary)


def _signature(file):
    """What tells a changed file without reading it (inode, size, modification time)."""
    try:
        info = os.stat(file)
    except OSError:
        return None
    return info.st_ino, info.st_size, info.st_mtime_ns


_listings = {}   # model path -> (the signature of every file listed, the listing)


def _listed_inputs(path):
    """Every file ./simulate reads for the model at `path`, as it reads them: its --list-inputs,
    ((role, file, sha256), ...), each file opened and hashed through its input gate (regular
    files only, in the model's folder, each kind's size limit: docs/cli.md, "Input files").
    The sweep never parses a model itself: Assimp's reading of a name (an mtllib with spaces
    is one file) is the only one. Asked again only when a file listed has changed."""
    cached = _listings.get(path)
    if cached and all(_signature(file) == signature for file, signature in cached[0]):
        return cached[1]
    run = subprocess.run([paths.simulate_binary(), path, "--list-inputs"], capture_output=True,
                         text=True, env=paths.simulate_environment())
    if run.returncode != 0:
        raise ValueError(run.stderr.strip().removeprefix("simulate: "))
    listing = tuple((entry["role"], entry["file"], entry["sha256"])
                    for entry in json.loads(run.stdout)["inputs"])
    _listings[path] = ([(file, _signature(file)) for _, file, _ in listing], listing)
    return listing


def model_parts(path):
    """The files a model reads besides itself (an OBJ's material libraries, a glTF's or a
    .glb's buffers), each (path, sha256), in the order ./simulate reads them."""
    return [(Path(file), sha256) for role, file, sha256 in _listed_inputs(str(path))
            if role == "model part"]


def parts_sha256(path):
    """One digest of every file a model reads besides itself ("" for a scene file or a model
    that reads nothing else): part of the cell's identity, so editing an MTL makes new cells."""
    parts = model_parts(path) if is_model(path) else []
    if not parts:
        return ""
    digest = hashlib.sha256()
    for part, sha256 in parts:
        digest.update(f"{part.name}\0{sha256}\0".encode())
    return "sha256:" + digest.hexdigest()


def _expand(document, where):
    """The sweep's cell specifications, each (label, keys)."""
    shared = document.get("options", {}) or {}
    if not isinstance(shared, dict):
        raise SweepError(f"{where}: \"options\": expected a mapping of cell keys")
    specs = []
    grid = document.get("grid")
    if grid is not None:
        if not isinstance(grid, dict) or not grid:
            raise SweepError(f"{where}: \"grid\": expected a mapping of cell keys to lists")
        for key, values in grid.items():
            if not isinstance(values, list) or not values:
                raise SweepError(f"{where}: grid: key {key!r}: expected a non-empty list")
        for key, values in grid.items():
            if key not in CELL_KEYS and not all(isinstance(v, dict) and v for v in values):
                raise SweepError(f"{where}: grid: key {key!r}: not a cell key (known: "
                                 + ", ".join(sorted(CELL_KEYS)) + "), nor a group of keys "
                                 "that vary together (a list of mappings, e.g. {R: 4, V: 15})")
        count = math.prod(len(values) for values in grid.values())
        listed = len(document.get("cells") or []) if isinstance(document.get("cells"), list) else 0
        if count + listed > MAX_CELLS:
            raise SweepError(f"{where}: \"grid\": {count:,} cells"
                             + (f" and {listed:,} listed" if listed else "")
                             + f", more than a sweep file may hold ({MAX_CELLS:,}); "
                             "split it into several sweep files")
        keys = list(grid)
        for combination in itertools.product(*(grid[k] for k in keys)):
            point = {}
            for key, value in zip(keys, combination):   # a group's entry adds its keys
                point.update(value if key not in CELL_KEYS else {key: value})
            label = "grid cell " + " ".join(f"{k}={v}" for k, v in point.items())
            specs.append((label, dict(shared, **point)))
    cells = document.get("cells")
    if cells is not None:
        if not isinstance(cells, list):
            raise SweepError(f"{where}: \"cells\": expected a list")
        if len(cells) > MAX_CELLS:
            raise SweepError(f"{where}: \"cells\": {len(cells):,} cells, more than a sweep file "
                             f"may hold ({MAX_CELLS:,}); split it into several sweep files")
        for k, cell in enumerate(cells, 1):
            if not isinstance(cell, dict):
                raise SweepError(f"{where}: cell {k}: expected a mapping")
            label = f"cell {k} (" + " ".join(f"{key}={cell[key]}" for key in ("scene", "R", "V")
                                             if key in cell) + ")"
            specs.append((label, dict(shared, **cell)))
    if not specs:
        raise SweepError(f"{where}: no cells: give \"grid\" or \"cells\"")
    return specs


def _cell(spec, label, sweep_name, base, where):
    def fail(key, reason):
        raise SweepError(f"{where}: {label}: key {key!r}: {reason}")

    for key in spec:
        if key not in CELL_KEYS:
            fail(key, "unknown key (known: " + ", ".join(sorted(CELL_KEYS)) + ")")
    if "scene" not in spec:
        fail("scene", "missing")
    files = {}
    # The one lookup rule of ./simulate (paths.find_input), relative to the sweep file's folder.
    for key, default, role in (("scene", None, "scene"),
                               ("platform", "ncube2.json", "platform"),
                               ("cost_model", "cost_model.json", "cost model")):
        name = spec.get(key, default)
        if not isinstance(name, str):
            fail(key, "must be a file name or path")
        files[key] = _once("input", (name, str(base), role),
                           lambda: paths.find_input(name, base, role))
        if files[key] is None:
            fail(key, f"no such {role} file: {name!r} ({paths.looked_for(name, base, role)})")
    options = {}
    for name, option in opts.OPTIONS.items():
        if name in spec:
            value = spec[name]
            error = opts.type_error(option, value) or (option.check(value) if option.check else None)
            if error:
                fail(name, f"{value!r} {error}")
            options[name] = float(value) if option.kind is float else value
    options = opts.complete(options)
    cfg = spec.get("cfg", {}) or {}
    if not isinstance(cfg, dict) or any(":" in str(k) or not isinstance(v, (str, int, float))
                                        for k, v in cfg.items()):
        fail("cfg", "expected a mapping {SimGrid setting: value}, e.g. {network/model: LV08}")
    problem = simgrid_settings_problem(cfg)
    if problem:
        fail("cfg", problem)
    trace = spec.get("trace", False)
    if not isinstance(trace, bool):
        fail("trace", f"{trace!r} must be true or false")
    paper_row = spec.get("paper_row")
    if paper_row is not None and (not isinstance(paper_row, dict) or set(paper_row) != {"R", "V"}):
        fail("paper_row", "expected {R: ..., V: ...}")
    try:
        scene_name, patches = scene_summary(files["scene"])
        scene_parts = parts_sha256(files["scene"])
    except (ValueError, AttributeError, OSError) as e:
        fail("scene", f"{files['scene']}: not a scene file ({e})")
    try:
        nodes = platform_nodes(files["platform"])
    except (ValueError, KeyError, TypeError) as e:
        fail("platform", f"{files['platform']}: not a platform file ({e})")
    R, V = options["R"], options["V"]
    if R * (V + 1) > nodes:
        fail("V" if "V" in spec else "R", f"R={R}, V={V} needs R x (V + 1) = {R * (V + 1)} "
             f"nodes; the platform {files['platform'].name} has {nodes}")
    if R > patches:
        fail("R", f"R={R}: more radiosity processors than the scene's {patches} patches")
    # The form-factor method's rules, as ./simulate's configuration check has them
    # (src/simulation/configuration_check.cpp): a method's options only with that method,
    # the hemicube with V = 0 and the rays' options at their defaults.
    for name, option in opts.OPTIONS.items():
        # The conditions on the other options (--hemicube-back-faces is recorded when it is
        # "pass", which is no condition on the cell); a condition may list several values.
        when = {k: v for k, v in (option.recorded_when or {}).items() if k != name}
        if when and any(options[k] not in (v if isinstance(v, list) else [v])
                        for k, v in when.items()) \
                and options[name] != option.default:
            fail(name, f"{options[name]!r} needs " + ", ".join(f"{k}: {v}" for k, v in when.items()))
    # The method's own rules, as its registration gives them (opts.FORM_FACTOR_METHODS).
    method_name = options["form_factors"]
    method = opts.FORM_FACTOR_METHODS[method_name]
    if V > 0 and not method["visibility_processors"]:
        fail("V" if "V" in spec else "form_factors",
             f"V={V}: form_factors {method_name} is defined with V = 0 only ({method['reason']})")
    if not method["traces_rays"]:
        for name in opts.RAY_OPTIONS:
            if options[name] != opts.OPTIONS[name].default:
                fail(name, f"{options[name]!r}: form_factors {method_name} traces no rays; leave "
                     f"{name} at {opts.OPTIONS[name].default!r}")
    # The shooter-centred scheme's rules, as its registration has them
    # (src/simulation/parallelisations.cpp, check_shooters).
    # (and check_circulation: the same rules).
    scheme = options["parallelisation"]
    if scheme in ("shooters", "circulation"):
        if V > 0:
            fail("V" if "V" in spec else "parallelisation",
                 f"V={V}: parallelisation {scheme} runs on R nodes with V = 0 (every node "
                 f"computes its shooter's form factors to the whole scene; docs/model.md, "
                 f"'The shooter-centred scheme')")
        for name in ("subdivide", "balance"):
            if options[name]:
                fail(name, f"{options[name]!r}: parallelisation {scheme} does not run it")
        if options["render_parallel"] != opts.OPTIONS["render_parallel"].default:
            fail("render_parallel", f"{options['render_parallel']!r}: parallelisation {scheme} does not run it")
        if options["shooters_per_iteration"] > R:
            fail("shooters_per_iteration", f"{options['shooters_per_iteration']}: at most one shooter per "
                 f"node, and R={R}")
    return Cell(sweep=sweep_name, label=label, scene=scene_name, scene_file=str(files["scene"]),
                scene_sha256=file_sha256(files["scene"]), platform_file=str(files["platform"]),
                platform_sha256=file_sha256(files["platform"]),
                cost_model_file=str(files["cost_model"]),
                cost_model_sha256=file_sha256(files["cost_model"]), options=options,
                cfg={str(k): v for k, v in cfg.items()}, trace=trace, paper_row=paper_row,
                nodes=nodes, scene_parts_sha256=scene_parts)


def protect_plan_inputs(plan_path, plan):
    """The plan and every file it names as read (ncube.input_file.protect): a job writes none of
    them, whatever link is planted among its outputs."""
    input_file.protect([plan_path] + [s["file"] for s in plan["sweeps"]] +
                       [c[key] for s in plan["sweeps"] for c in s["cells"]
                        for key in ("scene_file", "platform_file", "cost_model_file")])


def load(path):
    """Reads and validates a sweep file; raises SweepError naming the file, cell and key."""
    try:
        path = Path(path).resolve()
    except (RuntimeError, OSError):  # Python 3.11 says a link loop with RuntimeError
        raise SweepError(f"{path}: cannot open sweep file: a loop of symbolic links") from None
    where = str(path)
    if not path.exists():
        raise SweepError(f"{where}: no such file")
    document = read_document(path)
    if not isinstance(document, dict):
        raise SweepError(f"{where}: expected a mapping at the top")
    misspelt = sweep_keys.problem(document, where, SWEEP_KEYS, CELL_KEYS, path.parent)
    if misspelt:
        raise SweepError(misspelt)
    name = document.get("name", path.stem)
    if not isinstance(name, str) or not SWEEP_NAME.fullmatch(name):
        raise SweepError(f"{where}: key 'name': {name!r} must be a plain name: letters, digits "
                         f"and _ . + - (a letter or digit first, at most 100 characters)"
                         + ("; the file's name is the default, so give one" if "name" not in document
                            else ""))
    measure = document.get("measure", "seconds_per_iteration")
    if measure not in MEASURES:
        raise SweepError(f"{where}: key 'measure': {measure!r} must be one of "
                         + ", ".join(MEASURES))
    cells, seen = [], {}
    global _loading
    _loading = True
    try:
        for label, spec in _expand(document, where):
            cell = _cell(spec, label, name, path.parent, where)
            if cell.id in seen:
                raise SweepError(f"{where}: {label}: the same configuration as {seen[cell.id]}")
            seen[cell.id] = label
            cells.append(cell)
    finally:
        _loading = False
        _this_load.clear()
    return Sweep(name=name, file=where, measure=measure,
                 description=str(document.get("description", "")), cells=cells,
                 paper_table=document.get("paper_table"))


def load_all(paths_):
    """Several sweeps; their names must differ."""
    sweeps = [load(p) for p in paths_]
    names = {}
    for sweep in sweeps:
        if sweep.name in names:
            raise SweepError(f"{sweep.file}: sweep name {sweep.name!r} is also the name of "
                             f"{names[sweep.name]}")
        names[sweep.name] = sweep.file
    return sweeps
