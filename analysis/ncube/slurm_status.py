"""Snakemake's --cluster-status command for Slurm (docs/sweeps.md, "Running on a cluster"):
prints "running", "success" or "failed" for a job id, from `scontrol show job` (slurmctld's
own view: no accounting database needed), else from `sacct` where a site has one.

usage: python3 -m ncube.slurm_status JOBID[;CLUSTER]     (in the results folder)

A job that ended in any state but COMPLETED is "failed", and its state is noted in
logs/slurm/states.tsv (job id, state, reason) for experiments/sweep's plain line (an
OUT_OF_MEMORY or TIMEOUT cell says so). A job neither tool knows any more (purged after
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
    """(state, reason) of the job, or None when Slurm does not know it."""
    text = _run(["scontrol", "show", "job", "--oneliner", job])
    if text:
        fields = dict(item.split("=", 1) for item in text.split() if "=" in item)
        if "JobState" in fields:
            return fields["JobState"], fields.get("Reason", "None")
    text = _run(["sacct", "-X", "-P", "-n", "--format=State", "-j", job])
    if text and text.strip():
        return text.split()[0].rstrip("+"), "None"
    return None


def main():
    job = sys.argv[1].split(";")[0]
    found = state(job)
    if found is None:
        print("success")
        return 0
    job_state, reason = found
    if job_state in RUNNING:
        print("running")
    elif job_state == "COMPLETED":
        print("success")
    else:
        noted = STATES.read_text().splitlines() if STATES.exists() else []
        if not any(line.split("\t")[0] == job for line in noted):
            STATES.parent.mkdir(parents=True, exist_ok=True)
            with open(STATES, "a") as stream:
                stream.write(f"{job}\t{job_state}\t{reason}\n")
        print("failed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
