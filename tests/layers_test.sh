#!/usr/bin/env bash
# Layers that point down (docs/architecture.md, "Layers"): every `#include "folder/..."` of a
# file under src/ names its own folder or one its row of the page's table allows, and every
# folder under src/ has a row. The table is read from the page, so the rule is written once.
# Called by ctest as: layers_test.sh SIMULATE REPO_ROOT (SIMULATE unused). Well under 1 s.
set -u
root="$2"
page="$root/docs/architecture.md"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

declare -A allowed=()
in_table=0
while IFS= read -r line; do
  case "$line" in
    '<!-- layers:'*) in_table=1; continue ;;
    '<!-- end of layers -->') in_table=0; continue ;;
  esac
  [ "$in_table" = 1 ] || continue
  [[ "$line" =~ ^\|\ \`([a-z_]+)/\`\ \|(.*)\|$ ]] || continue
  folder="${BASH_REMATCH[1]}"
  allowed[$folder]=" $folder $(printf '%s' "${BASH_REMATCH[2]}" | tr -d '`/') "
done < "$page"
[ "${#allowed[@]}" -gt 0 ] || { echo "FAIL: no layers table in $page"; exit 1; }

for dir in "$root"/src/*/; do
  folder=$(basename "$dir")
  if [ -z "${allowed[$folder]+x}" ]; then
    fail "src/$folder has no row in docs/architecture.md's layers table"
    continue
  fi
  while IFS=: read -r file number target; do
    case "${allowed[$folder]}" in
      *" $target "*) ;;
      *) fail "${file#"$root"/}:$number includes $target/, which src/$folder may not (docs/architecture.md, \"Layers\")" ;;
    esac
  done < <(grep -rnoE '^#include "[a-z_]+/' "$dir" | sed -E 's/#include "([a-z_]+)\/$/\1/')
done

if [ "$failures" -gt 0 ]; then
  echo "$failures forbidden includes or folders without a row"
  exit 1
fi
echo "layers: every include under src/ points down (${#allowed[@]} folders)"
