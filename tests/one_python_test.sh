#!/usr/bin/env bash
# One Python (issue 39 item 2, analysis/ncube/interpreter.py): every script the docs tell a user
# to run works as written on a machine whose `python3` on PATH lacks the project's packages
# (numpy, matplotlib, yaml), such as a pyenv shim or a virtual environment. A fake `python3`
# first on PATH runs Debian's without its site packages (python3 -S); each script the docs name
# is run with `python3 SCRIPT --help`, and directly when executable, and must print its usage
# (exit 0) without an ImportError, two scripts at a time.
root="$2"
work=$(mktemp -d /tmp/one_python_test.XXXXXX)
trap 'rm -rf "$work"' EXIT
failed=0
fail() { echo "FAIL: $*"; failed=1; }

mkdir "$work/bin"
printf '#!/bin/sh\nexec /usr/bin/python3 -S "$@"\n' > "$work/bin/python3"
chmod +x "$work/bin/python3"
export PATH="$work/bin:$PATH"
# The fake really lacks the packages (else this test proves nothing).
if python3 -c 'import numpy' 2>/dev/null; then fail "the fake python3 imports numpy"; fi

# The scripts the docs name: README.md, docs/ and the analysis pages, every path of a Python
# file with an entry point (a `__main__` guard or a python3 shebang) but Blender's (bpy) and
# ctest's own (tests/*_test.py).
candidates=$(cd "$root" && grep -rhoE '(^|[^A-Za-z0-9_/.-])(analysis|bench|docs|experiments|platforms|scenes|tests)/[A-Za-z0-9_./-]+' \
                README.md docs analysis/*.md --include='*.md' | sed -E 's/^[^a-z]//; s/[.]$//' | sort -u |
              while read -r f; do
                [ -f "$f" ] || continue
                case "$f" in tests/*_test.py) continue;; esac
                echo "$f"
              done)
# One awk over the candidates, not a head and two greps for each of its 300-odd paths (7 s).
scripts=$(cd "$root" && awk '
  FNR == 1 && /^#!.*python3/ { entry[FILENAME] = 1 }
  /^if __name__ == "__main__"/ { entry[FILENAME] = 1 }
  /^import bpy/ { blender[FILENAME] = 1 }
  END { for (f in entry) if (!(f in blender)) print f }' $candidates | sort)
count=$(echo "$scripts" | wc -w)
[ "$count" -ge 25 ] || fail "only $count scripts found in the docs: $scripts"
cd "$root"
# One script: its failures on stdout, one line each. Run two at a time.
check() {
  local script="$1" out code
  out=$(timeout 60 python3 "$script" --help 2>&1); code=$?
  [ "$code" = 0 ] || echo "python3 $script --help: exit $code: $(echo "$out" | tail -n 2)"
  case "$out" in *Error*|*Traceback*) echo "python3 $script --help: $(echo "$out" | tail -n 2)";; esac
  case "$out" in *usage*|*Usage*) ;; *) echo "python3 $script --help prints no usage: $(echo "$out" | head -n 2)";; esac
  # Run directly, an executable script is that same command (its shebang `/usr/bin/env
  # python3`: the python3 on PATH) or the one the restart makes (`/usr/bin/python3`): its first
  # line is checked, not run again.
  if [ -x "$script" ]; then
    case "$(head -n 1 "$script")" in
      '#!/usr/bin/env python3' | '#!/usr/bin/python3') ;;
      *) echo "$script: executable, but its first line is not #!/usr/bin/python3 or #!/usr/bin/env python3";;
    esac
  fi
}
export -f check
problems=$(printf '%s\n' $scripts | xargs -P 2 -I{} bash -c 'check "$1"' _ {})
[ -z "$problems" ] || fail "$problems"
# The restart is the one rule's: a package-less python3 runs a script under /usr/bin/python3.
got=$(python3 -c 'import sys; sys.argv = ["x"]; sys.path.insert(0, "analysis")
from ncube import interpreter; print(interpreter.PYTHON)')
[ "$got" = /usr/bin/python3 ] || fail "ncube.interpreter.PYTHON is $got"
[ "$failed" = 0 ] && echo "one_python_test: passed ($count scripts)"
exit "$failed"
