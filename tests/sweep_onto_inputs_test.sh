#!/usr/bin/env bash
# The sweep tool never writes onto one of its inputs (issue 37, item 3; docs/sweeps.md,
# "What runs"): a link planted in the results folder where the tool writes its own files and
# pointing at the sweep file or the scene is refused with exit 2 and one line, as ./simulate
# refuses an output onto an input (plan.json); the input is unchanged (a sweep's cells.csv,
# which Snakemake replaces). tests/sweep_output_paths_test.sh has the rule's own cases.
# Usage: bash tests/sweep_onto_inputs_test.sh <path-to-simulate-binary> <repo-root>
set -u
simulate="$(realpath "$1")"
root="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
cd "$work" || exit 1
cp "$root/scenes/scene0.json" scene.json
printf "name: onto\nmeasure: total_seconds\noptions: {iterations: 1, samples: 4}\ngrid: {scene: [scene.json], R: [1]}\n" > s.yaml
cp s.yaml s.orig
cp scene.json scene.orig
sweep() { NCUBE_SIMULATE="$simulate" /usr/bin/python3 "$root/experiments/sweep" s.yaml --results r > out.txt 2> err.txt; }

mkdir r && ln -s ../s.yaml r/plan.json
sweep; code=$?
[ "$code" = 2 ] || fail "plan.json linked to the sweep file: exit $code, expected 2"
grep -q "plan.json: is the input file .*s.yaml" err.txt || fail "plan.json: no line naming both: $(cat err.txt)"
cmp -s s.yaml s.orig || fail "the sweep file was overwritten through plan.json"

# Two sweeps of the same cell in one run (one Snakemake): one sweep's cells.csv linked to the
# sweep file, the other's to the scene.
sed 's/^name: onto$/name: onto2/' s.yaml > t.yaml
rm -rf r && mkdir -p r/sweeps/onto r/sweeps/onto2
ln -s ../../../s.yaml r/sweeps/onto/cells.csv
ln -s ../../../scene.json r/sweeps/onto2/cells.csv
NCUBE_SIMULATE="$simulate" /usr/bin/python3 "$root/experiments/sweep" s.yaml t.yaml --results r > out.txt 2> err.txt
code=$?
# Snakemake removes a job's existing outputs (the links) before the job runs; were it to
# leave one, the summary's output rule refuses it.
[ "$code" = 0 ] || grep -q "is the input file" err.txt \
  || fail "cells.csv linked to the sweep file and the scene: exit $code, not said: $(tail -3 err.txt)"
cmp -s s.yaml s.orig || fail "the sweep file was overwritten through cells.csv"
cmp -s scene.json scene.orig || fail "the scene was overwritten through cells.csv"

[ "$failures" = 0 ] && echo "sweep_onto_inputs_test: all checks passed" && exit 0
echo "sweep_onto_inputs_test: $failures check(s) failed"
exit 1
