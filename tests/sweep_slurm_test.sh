#!/usr/bin/env bash
# ctest entry for tests/sweep_slurm_test.py: a sweep on a real one-node Slurm cluster
# (tests/slurm_cluster.sh), started here and always stopped. Skipped (exit 77, ctest's
# SKIP_RETURN_CODE) only when the daemons cannot start, with one line saying why.
source "$2/tests/slurm_cluster.sh"
work=$(mktemp -d /tmp/sweep_slurm_test.XXXXXX)
trap 'slurm_cluster_stop "$work/cluster"; rm -rf "$work"' EXIT
# Six job slots on the one node (the first run's six jobs at once; the machine's two cores would
# start them in three waves, each a round of Slurm's scheduling and of Snakemake's status checks).
if ! SLURM_CLUSTER_CPUS=6 slurm_cluster_start "$work/cluster"; then
  echo "SKIP sweep_slurm_test: the Slurm daemons cannot start: $SLURM_CLUSTER_WHY"
  exit 77
fi
# Snakemake's built-in executor would need $USER; the sweep's path must not (CI has none).
# CI=true: Snakemake 7's cluster executors sleep 10 s between rounds of status checks,
# 1 s with CI=true (snakemake/executors/__init__.py, sleep()); nothing else reads it.
CI=true NCUBE_SIMULATE="$1" SLURM_TEST_WORK="$work" env -u USER /usr/bin/python3 "$2/tests/sweep_slurm_test.py"
