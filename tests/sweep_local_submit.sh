#!/usr/bin/env bash
# A "cluster" for the tests: Snakemake's generic cluster mode hands each job's script to this
# submit command, as it would to sbatch or qsub; here the job runs on this machine, detached.
jobscript="${!#}"
nohup bash "$jobscript" >/dev/null 2>&1 &
echo "local-$!"
