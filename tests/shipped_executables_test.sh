#!/usr/bin/env bash
# Every program and script the repository ships is tried by a test (tests/robustness/
# executables.py: a new one fails here until it is listed with the tests that try it, or as
# open with why); and every Python one that takes argparse options is tried from its own
# option definitions (tests/robustness/argparse_options.py): each count option given "0x10"
# ends in exit 2 with argparse's message naming the option, no traceback, within 30 s, and the
# tree unchanged (git status). One hostile value a count: "1e400", "nan" and "-1" meet the same
# int() in argparse; the range each count must hold is the script's own (python_inputs_test).
# About 70 s on a loaded 2-core host, most of it the programs' imports.
root="$2"
failed=0
fail() { echo "FAIL: $*"; failed=1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
/usr/bin/python3 "$root/tests/robustness/executables.py" "$root" || failed=1
before=$(git -C "$root" status --porcelain)
programs=$(/usr/bin/python3 - "$root" <<'PY'
import sys
sys.path.insert(0, sys.argv[1] + "/tests/robustness")
import executables
for program, tests in executables.COVERED.items():
    if not isinstance(tests, str) and "/" in program and program.endswith((".py", "sweep", "reproduce")):
        print(program)
PY
)
tried=0
for program in $programs; do
  options=$(cd "$work" && timeout 30 /usr/bin/python3 "$root/tests/robustness/argparse_options.py" \
              "$root/$program" 2>"$work/err" </dev/null | tail -n 1)
  case "$options" in
    "["*) ;;
    null|"") continue ;;   # no argparse options
    *) fail "$program: its options could not be read: $options $(tail -n 3 "$work/err")"; continue ;;
  esac
  for flag in $(printf '%s' "$options" | /usr/bin/python3 -c '
import json, sys
for option in json.load(sys.stdin):
    if option["flags"] and option["type"] in ("int", "whole_number") and option["nargs"] is None:
        print(option["flags"][-1])'); do
    for value in 0x10; do
      (cd "$work" && timeout 30 /usr/bin/python3 "$root/$program" "$flag" "$value" \
         >/dev/null 2>"$work/err" </dev/null); code=$?
      tried=$((tried + 1))
      [ "$code" = 2 ] || fail "$program $flag $value: exit $code, not 2: $(head -c 300 "$work/err")"
      grep -q "Traceback" "$work/err" && fail "$program $flag $value: a traceback"
      grep -qF -- "argument $flag" "$work/err" || fail "$program $flag $value: the message does not name $flag: $(head -c 300 "$work/err")"
    done
  done
done
[ "$(git -C "$root" status --porcelain)" = "$before" ] || fail "the tree changed"
echo "shipped_executables_test: $tried count options tried with hex"
exit "$failed"
