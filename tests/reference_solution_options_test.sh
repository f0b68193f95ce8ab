#!/usr/bin/env bash
# build/reference_solution's options bounded and its outputs named honestly (issue 37, items 4
# and 6): --threads outside 0..64 (a huge count ended in SIGSEGV) and a --mesh name promising
# another format than PLY (it wrote PLY under it) are exit 2 with one line, nothing written.
# Its budget: an estimate first, --max-rays and the host's memory (below).
# Called by ctest as: reference_solution_options_test.sh SIMULATE REPO_ROOT
set -u
reference="$(dirname "$(realpath "$1")")/reference_solution"
root="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
for options in "--threads 100000000" "--threads 65" "--threads -1" "--mesh $work/x.obj" \
               "--mesh $work/x.GLTF"; do
  # shellcheck disable=SC2086
  "$reference" "$root/scenes/cornell-box.json" --out "$work/r.json" $options > /dev/null 2> "$work/err.txt"
  code=$?
  [ "$code" = 2 ] || fail "$options: exit $code, expected 2"
  [ "$(wc -l < "$work/err.txt")" = 1 ] && grep -q "^reference_solution: --" "$work/err.txt" \
    || fail "$options: not one line naming the option: $(cat "$work/err.txt")"
  [ -z "$(ls -A "$work" | grep -v err.txt)" ] || fail "$options: wrote $(ls -A "$work")"
done

# The budget (issue 37, item 4): the estimate comes first, is an upper bound of the rays the
# run took, and a run beyond --max-rays (the default 1e11) or the host's memory is refused at
# once with one line, nothing written: --samples 1024 on cornell-box cut 4 x 4 (2.2e11 rays
# at most) ran for hours without a word.
"$reference" "$root/scenes/cornell-box.json" --samples 16 --refine 1 --out "$work/r.json" \
  > "$work/out.txt" 2> "$work/err.txt" || fail "the small run: exit $?: $(cat "$work/err.txt")"
head -1 "$work/out.txt" | grep -q "^estimate: 1078 parts, .* at most [0-9.e+]* rays" \
  || fail "no estimate first: $(head -1 "$work/out.txt")"
/usr/bin/python3 - "$work/out.txt" "$work/r.json" <<'PY' || fail "the estimate is not an upper bound"
import json, re, sys
bound = float(re.search(r"at most ([0-9.e+]+) rays", open(sys.argv[1]).readline()).group(1))
run = json.load(open(sys.argv[2]))
# The estimate is printed to two digits: an upper bound within its rounding.
assert run["rays"] + run["check_rays"] <= bound * 1.05, (bound, run["rays"], run["check_rays"])
assert bound < 3 * (run["rays"] + run["check_rays"]), "the bound says nothing"
PY
rm -f "$work/r.json" "$work/out.txt"
budget_refused() {  # expected exit, what the line must hold, options...
  local code_wanted=$1 holds=$2
  shift 2
  start=$(date +%s)
  timeout 20 "$reference" "$root/scenes/cornell-box.json" --out "$work/r.json" "$@" > /dev/null 2> "$work/err.txt"
  code=$?
  [ "$code" = "$code_wanted" ] || fail "$*: exit $code, expected $code_wanted: $(cat "$work/err.txt")"
  [ "$(wc -l < "$work/err.txt")" = 1 ] && grep -q "$holds" "$work/err.txt" \
    || fail "$*: not one line holding '$holds': $(cat "$work/err.txt")"
  [ $(( $(date +%s) - start )) -le 10 ] || fail "$*: refused only after $(( $(date +%s) - start )) s"
  [ -z "$(ls -A "$work" | grep -v err.txt)" ] || fail "$*: wrote $(ls -A "$work")"
}
budget_refused 2 "^reference_solution: --max-rays 1e+11: the run would take 17248 parts" \
  --samples 1024 --refine 4
budget_refused 2 "^reference_solution: --max-rays 1000: the run would take 1078 parts" \
  --samples 4 --refine 1 --max-rays 1000
for value in 0 -1 nan inf 1e16; do
  budget_refused 2 "^reference_solution: --max-rays .*: must be from 1 to 1e15" --max-rays "$value"
done
# The memory: 4 x 4 parts need about 1.6 GB (each pair held once, 12 bytes), more than an
# address space of 1 GB.
(ulimit -v 1000000; budget_refused 6 "^reference_solution: the form factors of 17248 parts .* need about .* GB, the host has" \
  --refine 4 --samples 4; exit "$failures") || failures=$((failures + 1))
[ "$failures" = 0 ] && echo "reference_solution_options_test: all checks passed" && exit 0
echo "reference_solution_options_test: $failures check(s) failed"
exit 1
