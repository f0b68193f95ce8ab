"""Snakemake's --cluster-status command for Slurm (docs/sweeps.md, "Running on a cluster"):
prints "running", "success" or "failed" for a job id, from `scontrol show job` (slurmctld's
own view: no accounting database needed), else from `sacct` where a site has one.

usage: python3 -m ncube.slurm_status JOBID[;CLUSTER]     (in the results folder)

A job that ended in any state but COMPLETED is "failed", and its state is noted in
logs/slurm/states.tsv (job id, state, reason) for experiments/sweep's plain line (an
OUT_OF_MEMORY or TIMEOUT cell says so: report). A job neither tool knows any more (purged after
slurmctld's MinJobAge, no accounting) is "success": Snakemake then checks the result file, and a
cell whose verified file is missing fails."""
import subprocess
import sys
from pathlib import Path

RUNNING = {"PENDING", "CONFIGURING", "RUNNING", "COMPLETING", "SUSPENDED", "RESIZING",
           "REQUEUED", "REQUEUE_FED", "REQUEUE_HOLD", "SIGNALING", "STAGE_OUT", "STOPPED",
           "RESV_DEL_HOLD"}
STATES = Path("logs") / "slurm" / "states.tsv"


def _run(command):
    try:
        done = subprocess.run(command, capture_output=True, text=True, timeout=60, check=False)
    except (OSError, subprocess.SubprocessError):
        return None
    return done.stdout if done.returncode == 0 else None


def state(job):
    """(state, reason, job name) of the job, or None when Slurm does not know it."""
    text = _run(["scontrol", "show", "job", "--oneliner", job])
    if text:
        fields = dict(item.split("=", 1) for item in text.split() if "=" in item)
        if "JobState" in fields:
            return fields["JobState"], fields.get("Reason", "None"), fields.get("JobName", "")
    text = _run(["sacct", "-X", "-P", "-n", "--format=State,JobName", "-j", job])
    if text and text.strip():
        state_, _, name = text.splitlines()[0].partition("|")
        return state_.split()[0].rstrip("+"), "None", name
    return None


def job_name(cell_file):
    """The name experiments/sweep gives a cell's job (ncube.runner.slurm_arguments)."""
    path = Path(cell_file)
    rule = "traced_cell" if path.parent.name == "traced" else "cell"
    return f"ncube-{rule}-{path.stem}"


def noted_states(results_dir, since=0):
    """{job name: (job id, state, reason)} noted from byte `since` of the states file on."""
    path = Path(results_dir) / STATES
    if not path.exists():
        return {}
    with open(path) as stream:
        stream.seek(since)
        rows = [line.rstrip("\n").split("\t") for line in stream]
    return {row[3]: tuple(row[:3]) for row in rows if len(row) == 4}


def states_size(results_dir):
    path = Path(results_dir) / STATES
    return path.stat().st_size if path.exists() else 0


# What Slurm's job step writes into the job's log when it kills a job over its --mem by
# sampling (jobacct_gather, no cgroups): the job then ends FAILED or CANCELLED, not OUT_OF_MEMORY
# (seen on Slurm 22.05.8, docs/sweeps.md).
OVER_MEMORY = "Exceeded job memory limit"


def _over_memory(log):
    try:
        return OVER_MEMORY in log.read_text(errors="replace")
    except OSError:
        return False


def report(results_dir, missing, requests, since, say):
    """One plain line per failed cell whose Slurm job ended badly in this run: the job, its
    state, what it means, and its log. `requests`: each cell's mem_mb and runtime as planned
    (Snakemake's --set-resources can change them: then the line says "its request")."""
    noted = noted_states(results_dir, since)
    for cell_file in missing:
        found = noted.get(job_name(cell_file))
        if not found:
            continue
        job, job_state, reason = found
        log = Path(results_dir) / "logs" / "slurm" / f"{job}.log"
        asked = requests.get(cell_file, {})
        meaning = {
            "OUT_OF_MEMORY": f"it used more than its memory request ({asked.get('mem_mb')} MB)",
            "TIMEOUT": f"it ran longer than its time request ({asked.get('runtime')} min)",
            "CANCELLED": "it was cancelled (scancel, or by an administrator)",
            "NODE_FAIL": "its node failed",
            "PREEMPTED": "it was preempted",
        }.get(job_state, f"reason {reason}")
        if job_state != "OUT_OF_MEMORY" and _over_memory(log):
            meaning = "it used more than its memory request (Slurm: Exceeded job memory limit)"
        say(f"{cell_file}: Slurm job {job} ended {job_state}: {meaning}; its log: {log}")


def main():
    job = sys.argv[1].split(";")[0]
    found = state(job)
    if found is None:
        print("success")
        return 0
    job_state, reason, name = found
    if job_state in RUNNING:
        print("running")
    elif job_state == "COMPLETED":
        print("success")
    else:
        noted = STATES.read_text().splitlines() if STATES.exists() else []
        if not any(line.split("\t")[0] == job for line in noted):
            STATES.parent.mkdir(parents=True, exist_ok=True)
            with open(STATES, "a") as stream:
                stream.write(f"{job}\t{job_state}\t{reason}\t{name}\n")
        print("failed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
