#!/usr/bin/env bash
# The input gate (docs/cli.md, "Input files") from the command line: every kind of input
# (scene, model, the files a model names, platform, cost model, the folder $NCUBE_ROOT names)
# that is not a regular file, is too large, or (for a model's files) lies outside the model's
# folder ends promptly in exit 2 and one line naming it; --list-inputs lists what a run reads
# with hashes worked out here by sha256sum; the sweep tool hashes what ./simulate lists (an
# mtllib with spaces is one file); and no reader opens a file for input outside the gate.
# Usage: bash tests/input_files_test.sh <path-to-simulate-binary> <repo-root>
set -euo pipefail
simulate="$1"
root="${2:-$(cd "$(dirname "$0")/.." && pwd)}"
python=/usr/bin/python3
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }
export NCUBE_ROOT="$root"

# ---- No input opened outside the gate: no ifstream, no fopen for reading, no open(2) but
# the gate's (src/util/input_file.cpp) and the output files' (O_WRONLY).
raw=$(grep -rnE 'ifstream|fopen\(|[^_[:alnum:]]open\(' "$root/src" "$root/bench" \
        --include='*.cpp' --include='*.h' |
      grep -v '^[^:]*src/util/input_file\.cpp:' |
      grep -v '^[^:]*src/tools/temporary_file\.cpp:' |  # outputs' temporary files (read back to stream)
      grep -vE 'fopen\(.*"[wa]b?"\)|O_WRONLY|//|void open\(|OutputFiles::open\(|[[:space:]]open\((true|false|outputs)' || true)
[ -z "$raw" ] || fail "input opened outside src/util/input_file.h: $raw"

# ---- Hostile files. m/ holds the models; secret/ what they must not reach.
mkdir -p "$work/m" "$work/secret"
cd "$work/m"
printf 'newmtl light\nKe 1 1 1\nKd 0.5 0.5 0.5\n' > "sp ace.mtl"
cp "sp ace.mtl" "$work/secret/s.mtl"
square='v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nusemtl light\nf 1 2 3 4\n'
obj() { printf "mtllib %s\n$square" "$2" > "$1"; }
obj space.obj "sp ace.mtl"
obj fifo.obj fifo.mtl && mkfifo fifo.mtl
obj zero.obj zero.mtl && ln -s /dev/zero zero.mtl
obj absolute.obj "$work/secret/s.mtl"
obj dotdot.obj "../secret/s.mtl"
obj linkout.obj out.mtl && ln -s ../secret/s.mtl out.mtl
ln -s loop2.obj loop1.obj && ln -s loop1.obj loop2.obj
mkfifo fifo.obj.json
"$python" - <<'PY'
import json, struct
def gltf(uri, image=None):
    d = {"asset": {"version": "2.0"}, "buffers": [{"uri": uri, "byteLength": 36}],
         "bufferViews": [{"buffer": 0, "byteLength": 36}],
         "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                        "max": [1, 1, 0], "min": [0, 0, 0]}],
         "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
         "materials": [{"name": "light", "emissiveFactor": [1, 1, 1]}],
         "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0}
    if image:
        d["images"] = [{"uri": image}]
    return json.dumps(d)
open("tri.bin", "wb").write(struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0))
for name, uri, image in [("fifo-image", "tri.bin", "fifo.png"), ("fifo-buffer", "fifo.bin", None),
                         ("zero-buffer", "zero.bin", None), ("file-uri", "file:///etc/passwd", None),
                         ("absolute", "/etc/passwd", None)]:
    open(name + ".gltf", "w").write(gltf(uri, image))
PY
mkfifo fifo.png fifo.bin && ln -s /dev/zero zero.bin

# Exit 2 within 20 s, one line on stderr containing `expected`; named relatively and absolutely.
# The cases are queued and run in one batch from m/, each forked from build/simulate_server
# (tests/forked_batch.py: about 85 ms of CPU less a case than a new ./simulate; the binary's own
# start is tests/cli_test.sh's and the runs below); case K's stderr is $work/io/K.err.
mkdir "$work/io"
n=0
declare -a expected_of what_of
refused() {
  expected_of[n]="$1"; shift
  what_of[n]="$*"
  local a sep="" args=""
  for a in "$@" --iterations 1 --quiet; do
    a=${a//\\/\\\\}; a=${a//\"/\\\"}
    args+="$sep\"$a\""; sep=", "
  done
  printf '{"args": [%s], "stdout": null, "stderr": "%s", "timeout": 20}\n' "$args" "$work/io/$n.err" \
    >> "$work/cases.jsonl"
  n=$((n + 1))
}
for model in fifo.obj "$work/m/fifo.obj"; do
  refused "names fifo.mtl: model part is a FIFO, not a regular file" "$model"
done
for model in zero.obj "$work/m/zero.obj"; do
  refused "names zero.mtl, which lies outside the model's folder $work/m (through a symbolic link)" "$model"
done
for model in absolute.obj "$work/m/absolute.obj"; do
  refused "names $work/secret/s.mtl, which lies outside the model's folder $work/m (an absolute path)" "$model"
done
for model in dotdot.obj "$work/m/dotdot.obj"; do
  refused "names ../secret/s.mtl, which lies outside the model's folder $work/m (a .. path)" "$model"
done
refused "names out.mtl, which lies outside the model's folder $work/m (through a symbolic link)" linkout.obj
refused "loop1.obj: cannot open model file: a loop of symbolic links" loop1.obj
refused "names fifo.bin: model part is a FIFO, not a regular file" fifo-buffer.gltf
refused "names zero.bin, which lies outside the model's folder" zero-buffer.gltf
refused "names file:///etc/passwd, a file: URI" file-uri.gltf
refused "names /etc/passwd, which lies outside the model's folder $work/m (an absolute path)" absolute.gltf
refused "--model-folder $work/none: not a folder" dotdot.obj --model-folder "$work/none"
# The scene, the platform and the cost model, and what $NCUBE_ROOT names.
refused "fifo.obj.json: scene file is a FIFO, not a regular file" fifo.obj.json
refused "$work/m: scene file is a folder, not a regular file" "$work/m"
refused "fifo.bin: platform file is a FIFO, not a regular file" scene0.json --platform fifo.bin
refused "zero.bin: platform file is a character device, not a regular file" scene0.json --platform zero.bin
refused "fifo.bin: cost model is a FIFO, not a regular file" scene0.json --cost-model fifo.bin
head -c 1048577 /dev/zero | tr '\0' ' ' > big.json
refused "big.json: cost model is larger than 1048576 bytes (the limit)" scene0.json --cost-model big.json
# A SimGrid platform naming a file SimGrid would open itself (here a FIFO: it would wait).
cat > named.xml <<XML
<?xml version='1.0'?>
<platform version="4.1">
  <zone id="z" routing="Full">
    <host id="node-0" speed="1Mf" speed_file="$work/m/fifo.bin"/>
  </zone>
</platform>
XML
refused "named.xml: line 4: speed_file=: names a file, which SimGrid would read outside the input gate" \
  scene0.json --R 1 --platform named.xml
mapfile -t codes < <("$python" "$root/tests/forked_batch.py" "$simulate" "$work/cases.jsonl")
[ "${#codes[@]}" = "$n" ] || fail "the batch ran ${#codes[@]} of its $n cases"
for ((i = 0; i < n; i++)); do
  err="$work/io/$i.err"
  [ "${codes[i]:-none}" = 2 ] || { fail "${what_of[i]} exits ${codes[i]:-none}, not 2 ($(head -c 300 "$err"))"; continue; }
  [ "$(wc -l < "$err")" = 1 ] || fail "${what_of[i]}: not one line: $(cat "$err")"
  grep -qF -- "${expected_of[i]}" "$err" || fail "${what_of[i]}: '$(cat "$err")' lacks '${expected_of[i]}'"
done
mkdir -p "$work/root/platforms"
mkfifo "$work/root/platforms/ncube2.json"
# (Every input is looked up before any is read: the cost model must be there to reach the FIFO.)
cp "$root/platforms/cost_model.json" "$work/root/platforms/"
# (Started anew: the batch's cases share one environment.)
rc=0
NCUBE_ROOT="$work/root" timeout 20 "$simulate" "$root/scenes/scene0.json" --iterations 1 --quiet \
  > /dev/null 2> "$work/err" || rc=$?
[ "$rc" = 2 ] && [ "$(wc -l < "$work/err")" = 1 ] &&
  grep -qF "ncube2.json: platform file is a FIFO, not a regular file" "$work/err" ||
  fail "NCUBE_ROOT=$work/root: exit $rc: '$(cat "$work/err")' lacks 'ncube2.json: platform file is a FIFO, not a regular file'"

# A model may name files in a folder given with --model-folder.
timeout 20 "$simulate" dotdot.obj --model-folder "$work/secret" --iterations 1 --quiet ||
  fail "--model-folder does not let a model read its folder"

# ---- --list-inputs: every file, its role and a hash sha256sum agrees with.
timeout 20 "$simulate" space.obj --list-inputs > "$work/list.json" || fail "--list-inputs failed"
"$python" - "$work/list.json" "$root" <<'PY' || fail "--list-inputs: wrong listing"
import hashlib, json, sys
listed = json.load(open(sys.argv[1]))["inputs"]
root = sys.argv[2]
want = [("model", "space.obj"), ("model part", "sp ace.mtl"),
        ("platform", root + "/platforms/ncube2.json"), ("cost model", root + "/platforms/cost_model.json")]
got = [(e["role"], e["file"]) for e in listed]
assert got == want, got
for e in listed:
    assert e["sha256"] == "sha256:" + hashlib.sha256(open(e["file"], "rb").read()).hexdigest(), e
PY

# ---- The sweep tool: parts hashed from ./simulate's listing, promptly, an mtllib with spaces
# one file (the digest is worked out here from the file's bytes); a FIFO image (not read by
# ./simulate) does not hang it; a FIFO buffer is ./simulate's refusal.
cd "$root"
NCUBE_SIMULATE="$simulate" timeout 60 "$python" - "$work/m" <<'PY' || fail "the sweep's model parts"
import hashlib, sys
from pathlib import Path
from analysis.ncube import sweep
m = Path(sys.argv[1])
part = hashlib.sha256((m / "sp ace.mtl").read_bytes()).hexdigest()
expected = "sha256:" + hashlib.sha256(f"sp ace.mtl\0sha256:{part}\0".encode()).hexdigest()
assert sweep.parts_sha256(m / "space.obj") == expected, sweep.parts_sha256(m / "space.obj")
tri = hashlib.sha256((m / "tri.bin").read_bytes()).hexdigest()
assert sweep.parts_sha256(m / "fifo-image.gltf") == \
    "sha256:" + hashlib.sha256(f"tri.bin\0sha256:{tri}\0".encode()).hexdigest()
try:
    sweep.parts_sha256(m / "fifo-buffer.gltf")
    raise SystemExit("a FIFO buffer was hashed")
except ValueError as e:
    assert "fifo.bin: model part is a FIFO, not a regular file" in str(e), e
PY

[ "$failures" = 0 ] || { echo "$failures failures" >&2; exit 1; }
echo "input files: all refused or read as documented"
