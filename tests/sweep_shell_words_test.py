#!/usr/bin/python3
"""No string from data reaches a shell as syntax (docs/sweeps.md, "What runs"). Every hostile
string here, if it were run, would create a file named PWNED-* in the work folder; the test
fails if any appears. The cases:
- a sweep name holding shell syntax, a space, a quote, a newline, a slash or a leading dot is
  refused (exit 2, one line naming the file and key 'name'), and nothing is written;
- a sweep file, a scene file and a results folder whose paths hold all of these run a cell to
  the end, locally and through a generic cluster submit command (Snakemake's job scripts);
- a cfg value holding shell syntax is passed to ./simulate as one argument (refused by it);
- the Slurm submit and status commands, filled in as Snakemake fills them and run by bash with
  sbatch replaced by a function that prints its arguments, hand sbatch the exact paths."""
import contextlib
import io
import json
import os
import shutil
import subprocess
import sys
import tempfile
import types
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "analysis"))
from ncube import cluster_job, results, runner  # noqa: E402
from ncube.sweep import load as load_sweep  # noqa: E402
from snakemake.utils import format as snakemake_format  # noqa: E402

SWEEP = ["/usr/bin/python3", str(ROOT / "experiments" / "sweep")]
failures = []


def check(condition, what):
    print(("ok   " if condition else "FAIL ") + what, flush=True)
    if not condition:
        failures.append(what)


def hostile(work, tag, newline=True):
    """A file name (no slash) holding every kind of syntax; running any part of it makes a
    file PWNED-<tag>-* in the work folder (${PWNED} is that folder with its slash, set for every command)."""
    return (f"x $(touch ${{PWNED}}PWNED-{tag}-1) `touch ${{PWNED}}PWNED-{tag}-2`; "
            f"touch ${{PWNED}}PWNED-{tag}-3 ' \" {{rule}} %j" + ("\nnewline" if newline else "")
            + " & |")


def pwned(work):
    return sorted(p.name for p in Path(work).rglob("PWNED-*"))


def sweep(args, cwd=None):
    return subprocess.run(SWEEP + args, capture_output=True, text=True, cwd=cwd, timeout=240)


def sweep_in_process(args, cwd):
    """experiments/sweep's own entry (ncube.runner.main, which the script calls) run here in
    `cwd`, as a completed process: a refusal at validation without a Python started for each
    name (the script itself runs in the other cases)."""
    out, err, before = io.StringIO(), io.StringIO(), os.getcwd()
    os.chdir(cwd)
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            code = runner.main(args)
    finally:
        os.chdir(before)
    return subprocess.CompletedProcess(args, code, out.getvalue(), err.getvalue())


def refused_names(work):
    for i, name in enumerate(["a;touch PWNED-n", "$(touch PWNED-n)", "`touch PWNED-n`", "a b",
                              "a'b", 'a"b', "a\nb", "../up", ".hidden", "", "a{rule}b",
                              "x" * 101, "a/b"]):
        folder = work / f"names{i}"
        folder.mkdir()
        (folder / "s.yaml").write_text(f"name: {name!r}\ngrid: {{scene: [scene0], R: [1]}}\n"
                                       .replace("\n", "\n", 1) if "\n" not in name else
                                       'name: "a\\nb"\ngrid: {scene: [scene0], R: [1]}\n')
        run = sweep if i == 0 else sweep_in_process
        done = run([str(folder / "s.yaml"), "--results", str(folder / "results")], cwd=folder)
        lines = done.stderr.strip().splitlines()
        check(done.returncode == 2 and len(lines) == 1 and "key 'name'" in lines[0]
              and not (folder / "results").exists(),
              f"sweep name {name!r} refused with one line, nothing written "
              f"(exit {done.returncode}: {done.stderr.strip()[:200]})")
    check(not pwned(work), "no refused name ran anything")


def hostile_paths(work, safe_base):
    """A sweep file and a scene in a hostile folder, results in another; run, then resumed
    through the generic cluster mode (a rerun forced), then checked."""
    folder = work / hostile(work, "in")
    folder.mkdir()
    shutil.copy(ROOT / "scenes" / "scene0.json", folder / "my scene $(x).json")
    (folder / "study.yaml").write_text(
        "name: hostile-paths\nmeasure: total_seconds\n"
        "options: {iterations: 1, samples: 4}\n"
        "grid: {scene: ['my scene $(x).json'], R: [1]}\n")   # one cell: each is a job
    results_dir = work / hostile(work, "out", newline=False)
    # The tool itself in a hostile folder (a clone's path is the user's too): the rules' command
    # lines hold the repository's path.
    repo = work / hostile(work, "repo", newline=False)
    shutil.copytree(ROOT / "analysis" / "ncube", repo / "analysis" / "ncube",
                    ignore=shutil.ignore_patterns("__pycache__"))
    shutil.copytree(ROOT / "experiments", repo / "experiments", ignore=lambda d, names: [
        n for n in names if n not in ("sweep", "Snakefile")])
    shutil.copytree(ROOT / "platforms", repo / "platforms", ignore=shutil.ignore_patterns("*.py"))
    (repo / "scenes").mkdir()
    hostile_sweep = ["/usr/bin/python3", str(repo / "experiments" / "sweep")]
    # Refusals before Snakemake: experiments/sweep's entry run here (the script runs below).
    refused = sweep_in_process([str(folder / "study.yaml"), "--results",
                                str(work / hostile(work, "nl"))], work)
    check(refused.returncode == 2 and len(refused.stderr.strip().splitlines()) == 1
          and "control character" in refused.stderr
          and not (work / hostile(work, "nl")).exists(),
          f"a results path with a newline is refused with one line, nothing made (exit {refused.returncode}: {refused.stderr.strip()[:300]})")
    done = subprocess.run(hostile_sweep + [str(folder / "study.yaml"), "--results",
                                           str(results_dir), "--cores", "2"],
                          capture_output=True, text=True, timeout=240)
    cells = sorted((results_dir / "cells").glob("*.json"))
    check(done.returncode == 0 and len(cells) == 1
          and (results_dir / "sweeps" / "hostile-paths" / "cells.csv").exists(),
          f"a sweep tool, sweep file, scene and results folder in hostile paths run locally (exit {done.returncode}: "
          f"{done.stderr.strip()[-300:]})")
    local_submit = ["--cluster", str(ROOT / "tests" / "sweep_local_submit.sh"), "--jobs", "2"]
    refused = sweep_in_process([str(folder / "study.yaml"), "--results", str(results_dir)] +
                               local_submit, work)
    check(refused.returncode == 2 and len(refused.stderr.strip().splitlines()) == 1
          and "with a cluster" in refused.stderr,
          f"with a cluster, $ ` \" \\ in the results path are refused with one line "
          f"(exit {refused.returncode}: {refused.stderr.strip()[:300]})")
    cluster_results = Path(safe_base) / "r ' {rule} %j ; & | ( ) < > * ? ~ #"
    done = sweep([str(folder / "study.yaml"), "--results", str(cluster_results)] + local_submit)
    cells = sorted((cluster_results / "cells").glob("*.json"))
    check(done.returncode == 0 and len(cells) == 1,
          f"through a cluster submit command, a results path with the other syntax runs "
          f"(exit {done.returncode}: {done.stderr.strip()[-300:]})")
    # Snakemake's generic cluster mode (the suite's one run of it): the job went through the
    # submit command and made its cell's finished result.
    cell, = load_sweep(folder / "study.yaml").cells
    log = cluster_results / "logs" / "snakemake.log"
    check(results.mismatch(results.read(cluster_results / cell.file), cell) is None and
          "local-" in (log.read_text() if log.exists() else ""),
          "the cluster job went through the submit command (Snakemake's log) and its result is "
          "the cell's")
    check(not pwned(work), f"nothing in the paths ran: {pwned(work)}")


def hostile_cfg(work):
    folder = work / "cfg"
    folder.mkdir()
    (folder / "s.yaml").write_text(
        "name: cfg\noptions: {iterations: 1, samples: 4, "
        "cfg: {'network/model': '$(touch ${PWNED}PWNED-cfg)'}}\ngrid: {scene: [scene0], R: [1]}\n")
    done = sweep_in_process([str(folder / "s.yaml"), "--results", str(folder / "results")], folder)
    check(done.returncode == 2 and not pwned(work),
          f"a cfg value with shell syntax is one argument to ./simulate, refused "
          f"(exit {done.returncode}: {done.stderr.strip()[:200]})")


def submit_line(work):
    """runner.slurm_arguments' submit and status commands, filled in by Snakemake's own
    formatter as for a job, run by bash with sbatch and the status module replaced by functions
    that print their arguments one per line: the paths arrive whole, %j left for sbatch."""
    results_dir = work / hostile(work, "slurm", newline=False)
    arguments = runner.slurm_arguments(results_dir)
    submit = arguments[arguments.index("--cluster") + 1]
    status = arguments[arguments.index("--cluster-status") + 1]
    job = dict(rule="cell", wildcards=types.SimpleNamespace(name="scene0-R1"),
               resources=types.SimpleNamespace(mem_mb=100, runtime=5))
    filled = snakemake_format(submit, **job)
    printed = subprocess.run(["bash", "-c", 'sbatch() { printf "%s\\0" "$@"; }; ' + filled +
                              " JOBSCRIPT"], capture_output=True, text=True, cwd=work)
    words = printed.stdout.split("\0")
    check(f"--chdir={results_dir}" in words, "sbatch's --chdir is the results folder, whole")
    log = str(results_dir / "logs" / "slurm").replace("%", "%%") + "/%j.log"
    check(f"--output={log}" in words, "sbatch's --output is the log path, its % escaped for sbatch")
    env = subprocess.run(["bash", "-c", "env() { printf '%s\\n' \"$@\"; }; " + status + " 1"],
                         capture_output=True, text=True)
    check(f"PYTHONPATH={ROOT / 'analysis'}" in env.stdout.splitlines(),
          "the status command's PYTHONPATH is one word")
    # The job script: the sweep's template (its path from the repository, hostile too), filled
    # in by Snakemake's formatting, run by sh with exec replaced by a function that prints
    # PYTHONPATH and its arguments; ncube.cluster_job finds the cell in its properties line.
    results_dir.mkdir()
    runner.write_job_script(results_dir, results_dir / "plan.json")
    template = (results_dir / runner.SLURM_JOB_SCRIPT).read_text()
    script = results_dir / "job ' $x.sh"
    script.write_text(template.format(properties=json.dumps(
        {"rule": "cell", "output": ["cells/scene0-R1.json"], "wildcards": {"name": "scene0-R1"}})))
    printed = subprocess.run(["bash", "-c", 'exec() { printf "%s\\0" "$PYTHONPATH" "$@"; }; '
                              'source "$0"', str(script)], capture_output=True, text=True, cwd=work)
    check(printed.stdout.split("\0")[:-1] == [str(ROOT / "analysis"), "/usr/bin/python3", "-m",
                                             "ncube.cluster_job", str(script), "plan.json"],
          f"the job script hands ncube.cluster_job its own path and the plan, whole "
          f"({printed.stdout.split(chr(0))[:6]}, {printed.stderr.strip()[:200]})")
    check(cluster_job.cell_file(script) == "cells/scene0-R1.json",
          "ncube.cluster_job reads the cell from the job script's properties")
    check(not pwned(work), "the submit line ran nothing")


with tempfile.TemporaryDirectory(prefix="shell words ' $x ") as w, \
        tempfile.TemporaryDirectory(prefix="shell words ' ") as cluster_safe:
    work = Path(w)
    os.environ["PWNED"] = str(work) + "/"
    refused_names(work)
    hostile_paths(work, cluster_safe)
    hostile_cfg(work)
    submit_line(work)
if failures:
    print(f"{len(failures)} check(s) failed")
    sys.exit(1)
print("all checks passed")
