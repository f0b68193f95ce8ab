#!/usr/bin/env bash
# Nothing committed is lost to a script (issue 39 item 1, analysis/ncube/page.py): every script
# that writes a committed page or figure runs in a clean copy of the repository (its tracked
# files as they are now, no results/, no build/) and leaves the tree as it was. Those that need
# results or the simulator refuse with exit 2 and one line naming what is missing; the docs'
# table generators, which need neither, rewrite their tables unchanged (exit 0). About 5 s.
root="$2"
work=$(mktemp -d /tmp/page_scripts_test.XXXXXX)
trap 'rm -rf "$work"' EXIT
failed=0
fail() { echo "FAIL: $*"; failed=1; }

clone="$work/clone"
# --shared: the clone reads the repository's objects in place (copying them is 0.4 s of CPU); what
# the test commits and the scripts write stays in the clone.
git clone --quiet --shared "$root" "$clone" 2>/dev/null || { echo "FAIL: git clone $root"; exit 1; }
# The working tree's tracked files, committed changes or not, so the test sees what it tests
# (a tracked file deleted in the working tree is left out), and its new files in analysis,
# tests, docs and experiments: one tar, not a copy per file (about 700 files).
(cd "$root" && { git ls-files -z | while IFS= read -r -d '' f; do [ -f "$f" ] && printf '%s\0' "$f"; done
                 git ls-files -z --others --exclude-standard -- analysis tests docs experiments; } |
   tar --null --files-from=- -cf - | tar -C "$clone" -xf -) ||
  { echo "FAIL: copying the working tree into $clone"; exit 1; }
git -C "$clone" add -A && git -C "$clone" -c user.name=test -c user.email=test@localhost \
  commit --quiet --allow-empty -m "the tree under test"
[ -z "$(git -C "$clone" status --porcelain)" ] || fail "the clone is not clean to begin with"

unset NCUBE_SIMULATE NCUBE_ROOT
said=""
refuses() {   # SCRIPT [ARGS...]: exit 2, one line, the tree unchanged (the line kept in $said)
  local out code
  out=$(cd "$clone" && timeout 300 /usr/bin/python3 "$@" 2>&1); code=$?
  said=$out
  [ "$code" = 2 ] || fail "$1 exited $code, not 2: $out"
  [ "$(printf '%s\n' "$out" | wc -l)" = 1 ] || fail "$1 said more than one line: $out"
  case "$out" in *"nothing written"*) ;; *) fail "$1 does not say it wrote nothing: $out";; esac
  local changed
  changed=$(git -C "$clone" status --porcelain)
  [ -z "$changed" ] || { fail "$1 changed the tree: $changed"; git -C "$clone" checkout --quiet -- . ; git -C "$clone" clean -qfdx; }
}
unchanged() {   # SCRIPT [ARGS...]: exit 0, the tree unchanged
  local out code
  out=$(cd "$clone" && timeout 120 /usr/bin/python3 "$@" 2>&1); code=$?
  [ "$code" = 0 ] || fail "$1 exited $code: $out"
  local changed
  changed=$(git -C "$clone" status --porcelain)
  [ -z "$changed" ] || { fail "$1 changed the tree: $changed"; git -C "$clone" checkout --quiet -- . ; git -C "$clone" clean -qfdx; }
}

# No results: the pages made from results refuse (report.py names the 42 cells it lacks).
refuses analysis/report.py
[[ $said == *"no result of its"* ]] || fail "report.py does not name the missing results: $said"
refuses analysis/machines.py
# No simulator built: the scripts that run their own cells refuse (before running anything).
refuses analysis/unknowns.py
for script in predictions claims claims_schemes adaptive calibrate memory_sensitivity patch_order \
              headline; do
  refuses "analysis/$script.py"
  [[ $script != claims || $said == *"build/simulate, which is not built"* ]] ||
    fail "claims.py does not name the simulator it lacks: $said"
done
refuses analysis/machines.py --run
# The docs' table generators, the platform and scene generators and the pages' openings
# (analysis/openings.py, from each page's own tables) write committed files from committed
# inputs: run in the clean clone, they change nothing. scenes/generate.py (7 CPU seconds: the
# 51,200 patches of scene4) is tests/scenes_reproducible_test.sh's: what it writes is the
# committed scenes byte for byte, and its default folder is the committed one.
for script in analysis/openings.py docs/model_tables.py docs/options_table.py docs/platform_tables.py \
              docs/machines/index_table.py platforms/generate.py platforms/machines/generate.py; do
  unchanged "$script"
done
# docs/machines/loop_profile.py's tables of docs/machines/probe.md, made again from the committed
# measurements (--from, no run), are the committed ones.
unchanged docs/machines/loop_profile.py --from docs/machines/loop_profile.json --page
# docs/machines/hemicube_profile.py's section of the same page, likewise.
unchanged docs/machines/hemicube_profile.py --from docs/machines/hemicube_profile.json --page

# A page of an incomplete run never replaces the committed one: --partial and --summary write
# only where they are told (--out-dir, --output/--figures), and every output is checked before
# any is written (not an input, not a folder).
empty="$work/empty"; mkdir -p "$empty"
refuses analysis/report.py --partial --results "$empty"
refuses analysis/machines.py --partial --results "$empty"
refuses analysis/unknowns.py --summary analysis/unknowns-worlds.json
refuses analysis/unknowns.py --summary analysis/unknowns-worlds.json --out-dir analysis
mkdir -p "$work/elsewhere"
out=$(cd "$clone" && /usr/bin/python3 analysis/report.py --partial --results "$empty" --out-dir "$work/elsewhere" 2>&1) ||
  fail "report.py --partial --out-dir: $out"
[ -s "$work/elsewhere/report.md" ] && [ -n "$(ls "$work/elsewhere/figures")" ] ||
  fail "report.py --partial --out-dir wrote no report or figures there"
expect_code() {  # CODE SCRIPT [ARGS...]: that exit, one line naming the case, the tree unchanged
  local want="$1" out code; shift
  out=$(cd "$clone" && timeout 60 /usr/bin/python3 "$@" 2>&1 </dev/null); code=$?
  [ "$code" = "$want" ] || fail "$* exited $code, not $want: $out"
  [ "$(printf '%s\n' "$out" | wc -l)" = 1 ] || fail "$* said more than one line: $out"
  [ -z "$(git -C "$clone" status --porcelain)" ] || { fail "$* changed the tree"; git -C "$clone" checkout --quiet -- . ; }
}
expect_code 2 analysis/machines.py --partial --results "$empty" --output experiments/machines/table4.yaml \
  --figures "$work/figures"
[ ! -e "$work/figures" ] || fail "machines.py wrote its figure before refusing its --output"
expect_code 5 analysis/machines.py --partial --results "$empty" --output "$work" --figures "$work/figures"
touch "$work/a-file"
expect_code 5 analysis/unknowns.py --summary analysis/unknowns-worlds.json --out-dir "$work/a-file"
# The summary through the input gate: a device, a FIFO, deep nesting, NaN, a negative cell.
/usr/bin/python3 - "$clone/analysis/unknowns-worlds.json" "$work" <<'PY'
import json, sys
summary = json.load(open(sys.argv[1]))
key = next(iter(summary["worlds"][1]["cells"]))
for name, value in (("nan", float("nan")), ("negative", -1.0)):
    summary["worlds"][1]["cells"][key] = value
    open(f"{sys.argv[2]}/{name}.json", "w").write(json.dumps(summary))
open(f"{sys.argv[2]}/deep.json", "w").write("[" * 100000 + "]" * 100000)
PY
mkfifo "$work/fifo"
for summary in /dev/zero "$work/fifo" "$work/deep.json" "$work/nan.json" "$work/negative.json"; do
  expect_code 2 analysis/unknowns.py --summary "$summary" --out-dir "$work/elsewhere"
done
[ ! -e "$work/elsewhere/unknowns.md" ] || fail "unknowns.py wrote a page from a refused summary"
[ "$failed" = 0 ] && echo "page_scripts_test: passed"
exit "$failed"
