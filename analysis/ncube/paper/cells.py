"""The paper's table cells next to the simulated cells that stand for them: the inputs of the
report (analysis/paper_tables.json, the paper sweeps, the result files, platforms/)."""
import json
from dataclasses import dataclass, field
from pathlib import Path

from .. import results
from ..paths import ANALYSIS, EXPERIMENTS, PLATFORMS
from ..sweep import Sweep, load as load_sweep

PAPER_SWEEPS = ["table1", "table2", "table3", "table4", "table5", "timeline"]

@dataclass
class Cell:
    """One cell of a paper table next to the simulated run that stands for it."""
    table: int
    quantity: str
    scene: str
    R: int                      # the paper's row
    V: int
    T: int
    paper: float = None         # None: no value printed
    printed: str = None         # how the paper printed the cell when not as a plain number
    paper_measured_with: dict = None   # the paper's own substitution (Table 4 scene3)
    sim_R: int = None           # the simulated configuration (differs for a substitution)
    sim_V: int = None
    key: str = None             # result file, relative to the results folder; None when no
                                # sweep has this cell
    result: dict = None         # the result file, None when not run
    iterations: int = None      # the sweep's iteration limit (-1: to convergence)
    trace_file: str = None      # the timeline, for a traced cell
    calibration: bool = False

    @property
    def status(self):
        if self.key is None:
            return "not in sweep"
        if self.result is None:
            return "not run"
        return self.result["status"]

    @property
    def sim(self):
        """Simulated seconds comparable with the paper's value, None when there are none."""
        if self.status != "ok":
            return None
        return results.measure(self.result, self.quantity)

    @property
    def error(self):
        """(sim - paper) / paper, None without both values."""
        if self.sim is None or self.paper is None:
            return None
        return (self.sim - self.paper) / self.paper

    @property
    def row(self):
        """The paper's row, with the configuration actually run when it differs."""
        text = f"R={self.R},V={self.V}"
        if (self.sim_R, self.sim_V) != (self.R, self.V):
            text += f" (run as R={self.sim_R},V={self.sim_V})"
        return text

    @property
    def label(self):
        return f"{self.scene} R={self.R} V={self.V}"


@dataclass
class Inputs:
    paper: dict
    sweeps: dict                # sweep name -> ncube.sweep.Sweep
    results_dir: Path
    platform_files: dict        # file name -> parameters
    calibration: dict = None
    cells: list = field(default_factory=list)
    timeline: Cell = None


def read_json(path):
    return json.loads(Path(path).read_text())


def table_scenes(table):
    """Scene columns in the order of the paper table (every row names the same scenes)."""
    return [name for name in table["rows"][0] if name.startswith("scene")]


def sweep_cell(sweep, scene, R, V):
    """The sweep's cell standing for the paper's row (R, V): its own or a paper_row stand-in."""
    for cell in sweep.cells:
        row = cell.paper_row or {"R": cell.R, "V": cell.V}
        if cell.scene == scene and (row["R"], row["V"]) == (R, V):
            return cell
    return None


def is_calibration(calibration, table, scene, R, V, sim_R, sim_V):
    """A calibration entry may name the paper's row or the simulated configuration."""
    if not calibration:
        return False
    return any(c["table"] == table and c["scene"] == scene and
               (c["R"], c["V"]) in ((R, V), (sim_R, sim_V)) for c in calibration["cells"])


def comparison(cell):
    """What makes two table cells the same comparison: the same run and the same paper value."""
    return cell.quantity, cell.key or cell.label, cell.paper


def build_cells(inputs):
    for table in inputs.paper["tables"]:
        number = table["table"]
        sweep = inputs.sweeps.get(f"table{number}")
        printed = table.get("printed", {})
        substitutions = {(s["row"]["R"], s["row"]["V"], s["scene"]): s["measured_with"]
                         for s in table.get("substitutions", [])}
        for scene in table_scenes(table):
            for row in table["rows"]:
                R, V = row["R"], row["V"]
                cell = Cell(table=number, quantity=table["quantity"], scene=scene, R=R, V=V,
                            T=row["T"], paper=row[scene],
                            printed=printed.get(f"R={R},V={V},{scene}"),
                            paper_measured_with=substitutions.get((R, V, scene)))
                simulated = sweep_cell(sweep, scene, R, V) if sweep else None
                if simulated:
                    cell.sim_R, cell.sim_V = simulated.R, simulated.V
                    cell.key = simulated.file
                    cell.result = results.read(inputs.results_dir / cell.key)
                    cell.iterations = simulated.options["iterations"]
                else:
                    cell.sim_R, cell.sim_V = R, V
                cell.calibration = is_calibration(inputs.calibration, number, scene, R, V,
                                                  cell.sim_R, cell.sim_V)
                inputs.cells.append(cell)
    # A calibration cell repeated in another table (same run, same paper value) is the same
    # data point the fit saw: it is no prediction there either.
    fitted = {comparison(c) for c in inputs.cells if c.calibration}
    for cell in inputs.cells:
        cell.calibration = comparison(cell) in fitted
    timeline = inputs.sweeps.get("timeline")
    if timeline:
        spec = timeline.cells[0]
        inputs.timeline = Cell(table=0, quantity="trace", scene=spec.scene, R=spec.R, V=spec.V,
                               T=0, sim_R=spec.R, sim_V=spec.V, key=spec.file,
                               result=results.read(inputs.results_dir / spec.file),
                               iterations=spec.options["iterations"], trace_file=spec.trace_file)


def paper_sweeps(results_dir):
    """The paper sweeps as run into `results_dir` (its plan.json, which holds what-if changes),
    else as in experiments/."""
    sweeps = {}
    plan = results.read(results_dir / "plan.json")
    for document in (plan or {}).get("sweeps", []):
        if document["name"] in PAPER_SWEEPS:
            sweeps[document["name"]] = Sweep.from_dict(document)
    for name in PAPER_SWEEPS:
        if name not in sweeps:
            sweeps[name] = load_sweep(EXPERIMENTS / f"{name}.json")
    return sweeps


def load_inputs(results_dir):
    sweeps = paper_sweeps(results_dir)
    platform_files = {path.name: read_json(path)["parameters"]
                      for path in sorted(PLATFORMS.glob("*.json"))}
    calibration_path = ANALYSIS / "calibration.json"
    calibration = read_json(calibration_path) if calibration_path.exists() else None
    inputs = Inputs(paper=read_json(ANALYSIS / "paper_tables.json"), sweeps=sweeps,
                    results_dir=results_dir, platform_files=platform_files,
                    calibration=calibration)
    build_cells(inputs)
    return inputs


def find(cells, table, scene, R, V):
    """The cell of a paper table by the paper's row."""
    for cell in cells:
        if (cell.table, cell.scene, cell.R, cell.V) == (table, scene, R, V):
            return cell
    return None


def unique_cells(cells):
    """Tables 3 and 4 repeat rows of Tables 1 and 2 (same run, same paper value): count each
    comparison once so repeated rows do not weigh double."""
    unique = {}
    for cell in cells:
        unique.setdefault(comparison(cell), cell)
    return list(unique.values())
