#!/usr/bin/env bash
# An OBJ that names its material library again and again (issue 37, item 5): Assimp opens and
# parses the library at every mtllib line. Each file a model names is read through the gate
# once (src/models/recording_io.h); what is handed again is bounded (kBytesNamedAgain, 64 MiB),
# past which the model is refused with exit 2 naming its line. Also: 20,000 missing libraries
# are one quick refusal naming the first, as missing (it was "outside the folder, through a
# symbolic link" after 10 s), and a name of 180,000 characters is shown cut in one short line.
# Called by ctest as: obj_libraries_test.sh SIMULATE REPO_ROOT
set -u
simulate=$(realpath "$1")
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
/usr/bin/python3 - <<'PY'
corners = [[0, 2, 0], [1, 2, 0], [1, 2, 1], [0, 2, 1], [0, 0, 0], [0, 0, 1], [1, 0, 1], [1, 0, 0]]
tail = ("".join(f"v {x} {y} {z}\n" for x, y, z in corners) +
        "usemtl light\nf 1 2 3 4\nusemtl floor\nf 5 6 7 8\n")
lamp = "newmtl light\nKd 0.5 0.5 0.5\nKe 10 8 6\nnewmtl floor\nKd 0.6 0.5 0.4\n"
open("lamp.mtl", "w").write(lamp)
open("again.obj", "w").write("mtllib lamp.mtl\n" * 100000 + tail)
# A library of 1 MiB (comments), named 100 times: every naming after the first hands it again.
open("big.mtl", "w").write(lamp + ("#" * 1023 + "\n") * 1024)
open("big.obj", "w").write("mtllib big.mtl\n" * 100 + tail)
open("missing.obj", "w").write("".join(f"mtllib m{i}.mtl\n" for i in range(20000)) + tail)
open("long.obj", "w").write("mtllib " + " ".join(["lamp.mtl"] * 20000) + "\n" + tail)
PY
big=$(stat -c %s big.mtl)
# The naming that passes 64 MiB handed again: the first is free, the k-th again passes it.
again=$(( (64 * 1048576) / big + 1 ))
line=$(( again + 1 ))

start=$(date +%s.%N)
"$simulate" again.obj --list-inputs > listing.json 2> err.txt || fail "again.obj: exit $?: $(cat err.txt)"
seconds=$(echo "$(date +%s.%N) - $start" | bc)
# Before: 2.5 s for 20,000 namings, so about 12 s for these 100,000; now about 0.5 s.
[ "$(echo "$seconds < 5" | bc)" = 1 ] || fail "again.obj: $seconds s for 100,000 namings of one library"
[ "$(grep -c lamp.mtl listing.json)" = 1 ] || fail "again.obj: the listing does not name lamp.mtl once"

refused() {  # model, what the one line must hold
  "$simulate" "$1" --list-inputs > /dev/null 2> err.txt
  code=$?
  [ "$code" = 2 ] || fail "$1: exit $code, expected 2: $(head -c 300 err.txt)"
  [ "$(wc -l < err.txt)" = 1 ] && [ "$(wc -c < err.txt)" -lt 1000 ] && grep -q -- "$2" err.txt \
    || fail "$1: not one short line holding '$2': $(head -c 300 err.txt)"
}
refused big.obj "^simulate: big.obj: line $line: names big.mtl again: more than 64 MiB of files named again"
refused missing.obj "^simulate: missing.obj: names m0.mtl: cannot open model part: No such file"
refused long.obj "^simulate: long.obj: names lamp.mtl lamp.mtl .*\.\.\. (179999 characters)"
[ "$failures" = 0 ] && echo "obj_libraries_test: all checks passed" && exit 0
echo "obj_libraries_test: $failures check(s) failed"
exit 1
