#!/usr/bin/env bash
# Snakemake's --cluster-status command (analysis/ncube/slurm_status.py) on what Slurm prints for
# a job that ran past its time limit: "failed", its state and reason noted for the sweep, and the
# sweep's line saying it ran longer than its time request. The job records are the ones Slurm
# 22.05 printed for a `sbatch --time=1 --wrap 'sleep 300'` on tests/slurm_cluster.sh's cluster
# (JobState=TIMEOUT Reason=TimeLimit ExitCode=0:15), given by stand-in scontrol and sacct on
# PATH, so no cluster is needed; a completed, a running and a forgotten job beside them.
set -u
root="$2"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/bin" "$work/results"
# The stand-ins print the record of the job named by FAKE_SCONTROL / FAKE_SACCT, or fail as the
# tools do for a job they do not know.
cat > "$work/bin/scontrol" <<'EOF'
#!/bin/sh
[ -n "${FAKE_SCONTROL:-}" ] || { echo "slurm_load_jobs error: Invalid job id specified" >&2; exit 1; }
printf '%s\n' "$FAKE_SCONTROL"
EOF
cat > "$work/bin/sacct" <<'EOF'
#!/bin/sh
[ -n "${FAKE_SACCT:-}" ] || exit 0
printf '%s\n' "$FAKE_SACCT"
EOF
chmod +x "$work/bin/scontrol" "$work/bin/sacct"
failures=0
check() {  # check STATUS WHAT
  if [ "$1" = 0 ]; then echo "ok   $2"; else echo "FAIL $2"; failures=$((failures + 1)); fi
}
status_of() {  # status_of JOB: what the status command prints, run in the results folder
  (cd "$work/results" && PATH="$work/bin:$PATH" PYTHONPATH="$root/analysis" \
     /usr/bin/python3 -m ncube.slurm_status "$1")
}
job() {  # job ID STATE REASON: a `scontrol show job --oneliner` record as Slurm 22.05 prints it
  echo "JobId=$1 JobName=ncube-cell-scene0-R1-V0 UserId=root(0) GroupId=root(0) Priority=1" \
       "Nice=0 Account=(null) QOS=(null) JobState=$2 Reason=$3 Dependency=(null) Requeue=1" \
       "Restarts=0 BatchFlag=1 Reboot=0 ExitCode=0:15 RunTime=00:01:16 TimeLimit=00:01:00" \
       "TimeMin=N/A Partition=test NodeList=vm Command=(null) WorkDir=/tmp/results"
}

got=$(FAKE_SCONTROL="$(job 41 TIMEOUT TimeLimit)" status_of "41;ncubetest")
[ "$got" = failed ]; check $? "a job past its time limit (scontrol: TIMEOUT, TimeLimit) is failed (got \"$got\")"
grep -qxF "$(printf '41\tTIMEOUT\tTimeLimit\tncube-cell-scene0-R1-V0')" "$work/results/logs/slurm/states.tsv"
check $? "  its state and reason are noted for the sweep ($(tr '\t' ' ' < "$work/results/logs/slurm/states.tsv" 2>/dev/null))"
FAKE_SCONTROL="$(job 41 TIMEOUT TimeLimit)" status_of 41 >/dev/null
[ "$(grep -c '^41	' "$work/results/logs/slurm/states.tsv")" = 1 ]
check $? "  once, however often Snakemake asks"

got=$(FAKE_SACCT="TIMEOUT|ncube-cell-scene0-R2-V0" status_of 42)
[ "$got" = failed ]; check $? "a job past its time limit known only to sacct (TIMEOUT) is failed (got \"$got\")"

line=$(cd "$work/results" && PYTHONPATH="$root/analysis" /usr/bin/python3 -c '
import sys
from ncube import slurm_status
cell = "cells/scene0-R1-V0.json"
slurm_status.report(".", [cell], {cell: {"mem_mb": 512, "runtime": 1}}, 0, print)')
expected="cells/scene0-R1-V0.json: Slurm job 41 ended TIMEOUT: it ran longer than its time request (1 min); its log: logs/slurm/41.log"
[ "$line" = "$expected" ]; check $? "the sweep's line names the job, its state and its time request: $line"

got=$(FAKE_SCONTROL="$(job 43 COMPLETED None)" status_of 43)
[ "$got" = success ]; check $? "a completed job is success (got \"$got\")"
got=$(FAKE_SCONTROL="$(job 44 RUNNING None)" status_of 44)
[ "$got" = running ]; check $? "a running job is running (got \"$got\")"
got=$(status_of 45)
[ "$got" = success ]; check $? "a job Slurm forgot is left to Snakemake's check of its file (success, got \"$got\")"
! grep -qE '^4[345]	' "$work/results/logs/slurm/states.tsv"; check $? "  none of those is noted as failed"

exit $((failures > 0))
