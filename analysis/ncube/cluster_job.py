"""A cell's job on a Slurm node (experiments/sweep --slurm; docs/sweeps.md, "Running on a
cluster"): the job script Snakemake writes from the sweep's template (ncube.runner,
write_jobscript) names the job's rule and output on its properties line; this reads them and
runs the cell as the rule's own command does (ncube.run_cell), in the results folder sbatch
starts the job in. No Snakemake of its own runs on the node (Snakemake's default job script
starts one per job: seconds and about 100 MB each).

usage: python3 -m ncube.cluster_job JOB_SCRIPT PLAN     (in the results folder)"""
import json
import sys

from . import input_file, run_cell

RULES = ("cell", "traced_cell")   # the Snakefile's rules that run on the cluster
PROPERTIES = "# properties = "    # Snakemake's line in its job scripts
JOB_SCRIPT_BYTES = 1 << 20


def cell_file(script):
    """The cell's result file, the first output of the job's rule (a traced cell's second is
    its trace), as the job script's properties give it."""
    try:
        text = input_file.read_input_text(script, "job script", JOB_SCRIPT_BYTES)
    except input_file.InputFileError as e:
        raise SystemExit(f"cluster_job: {e}") from None
    for line in text.splitlines():
        if line.startswith(PROPERTIES):
            try:
                properties = json.loads(line[len(PROPERTIES):])
            except ValueError:
                break
            if isinstance(properties, dict) and properties.get("rule") in RULES and \
                    properties.get("output"):
                return properties["output"][0]
            break
    raise SystemExit(f"cluster_job: {script}: no properties line of a cell's job "
                     f"(rule {' or '.join(RULES)})")


def main():
    script, plan = sys.argv[1], sys.argv[2]
    cell, rerun_finished = run_cell.find_cell(plan, cell_file(script))
    return run_cell.run(cell, rerun_finished=rerun_finished)


if __name__ == "__main__":
    sys.exit(main())
