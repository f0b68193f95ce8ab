#!/usr/bin/env bash
# build/reference_solution's options bounded and its outputs named honestly (issue 37, items 4
# and 6): --threads outside 0..64 (a huge count ended in SIGSEGV) and a --mesh name promising
# another format than PLY (it wrote PLY under it) are exit 2 with one line, nothing written.
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
[ "$failures" = 0 ] && echo "reference_solution_options_test: all checks passed" && exit 0
echo "reference_solution_options_test: $failures check(s) failed"
exit 1
