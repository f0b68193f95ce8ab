#!/usr/bin/env bash
# The committed platforms/ncube2-d7.json .. ncube2-d13.json are exactly what
# platforms/generate.py writes from platforms/ncube2.json (their one source).
# Usage: bash tests/platforms_reproducible_test.sh <path-to-simulate-binary> <repo-root>
set -euo pipefail

root="${2:-$(cd "$(dirname "$0")/.." && pwd)}"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

/usr/bin/python3 "$root/platforms/generate.py" --out "$tmp"
status=0
for d in 7 8 9 10 11 12 13; do
  f="ncube2-d$d.json"
  if [[ ! -f "$root/platforms/$f" ]]; then
    echo "FAIL: platforms/$f is missing (run: /usr/bin/python3 platforms/generate.py)" >&2
    status=1
  elif ! cmp "$tmp/$f" "$root/platforms/$f"; then
    echo "FAIL: platforms/$f differs from what platforms/generate.py writes from ncube2.json" >&2
    status=1
  fi
done
[[ $status -eq 0 ]] && echo "PASS: 7 platform files reproduced from ncube2.json"
exit $status
