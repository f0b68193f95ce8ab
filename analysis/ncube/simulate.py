"""Running ./simulate for one configuration (calibration, probes, the regression test)."""
import subprocess
import tempfile
from pathlib import Path

from . import options as opts
from . import paths, results


class SimulateError(Exception):
    pass


def run(scene, options=None, platform=None, cost_model=None, cfg=None, timeout=None,
        accept_out_of_memory=True, threads=1):
    """Runs ./simulate on `scene` (a bare name or a path) with `options` (ncube.options names)
    and returns the result file as a dict, with "exit_code" added. `threads`: host threads
    (0: every core, for runs one at a time; results do not depend on it)."""
    scene = paths.find_input(str(scene), Path.cwd(), "scene") or scene
    with tempfile.TemporaryDirectory() as folder:
        out = Path(folder) / "result.json"
        command = opts.command(paths.simulate_binary(), scene, options or {}, platform,
                               cost_model, cfg, json_out=out, threads=threads)
        completed = subprocess.run(command, capture_output=True, text=True, timeout=timeout,
                                   env=paths.simulate_environment())
        allowed = (0, 3) if accept_out_of_memory else (0,)
        if completed.returncode not in allowed or not out.exists():
            raise SimulateError(f"{' '.join(command)}: exit {completed.returncode}: "
                                f"{completed.stderr.strip()}")
        result = results.read(out)
        result["exit_code"] = completed.returncode
        return result
