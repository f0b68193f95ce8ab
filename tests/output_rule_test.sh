#!/bin/bash
# Every output of ./simulate under the one output rule (docs/cli.md, "Output files"), whole
# commands: --json, --trace, --image, --mesh, --export-scene, NCUBE_RECORD_ACTIVITIES, a --log
# file appender and SimGrid's trace (tracing/filename), each pointed at
#   the model                                            -> exit 2, the file unchanged
#   a folder                                             -> exit 5
# with another output (aside.json) beside it, which neither refusal may write, and at
#   a new file beside a link planted at <path>.partial   -> exit 0, the link's target untouched
# and after every run no temporary file (*.partial*) is left. Then runs killed by SIGSEGV,
# SIGABRT, SIGTERM and SIGINT while their outputs are open leave none either.
# Each output at the model's MTL, at the scene of a JSON run, at a null device and at a FIFO
# with a reader are cells of the threat model (tests/robustness_threats_test.sh: "write --log
# file appender / is lamp.mtl", "... / is scene.json", "... / null device", "... / fifo", with
# the file unchanged, the device or FIFO kept and the reader fed).
# Usage: output_rule_test.sh SIMULATE_BINARY SOURCE_DIR
simulate=$(realpath "$1")
root=$(realpath "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

cp "$root/tests/models/room.obj" "$root/tests/models/room.mtl" "$root/scenes/scene0.json" .
mkdir folder

# The command-line words (or environment) that send output $1 to path $2. The picture and the
# mesh (whose colours take the picture's exposure) at 16 x 16 pixels: at the default 800 x 600
# rendering costs 1.4 CPU s a picture and 0.2 s a mesh, and the size has no part in where or how
# the file is written.
output_words() {
  case $1 in
    json | trace | export-scene) echo "--$1 $2" ;;
    image | mesh) echo "--$1 $2 --image-width 16 --image-height 16" ;;
    log) echo "--log=ncube_radiosity.app:file:$2 --log=ncube_radiosity.thresh:verbose" ;;
    tracing) echo "--cfg=tracing:yes --cfg=tracing/filename:$2" ;;
  esac
}

# Runs the model room.obj (2 iterations) with output $1 at path $2, and another output,
# aside.json, beside it; sets $status.
run_with() {
  local aside=--json
  [ "$1" = json ] && aside=--trace
  if [ "$1" = record ]; then
    NCUBE_RECORD_ACTIVITIES=$2 timeout 60 "$simulate" room.obj --iterations 2 --quiet $aside aside.json \
      2>"$work/stderr"
  else
    # shellcheck disable=SC2046
    timeout 60 "$simulate" room.obj --iterations 2 --quiet $aside aside.json $(output_words "$1" "$2") \
      2>"$work/stderr"
  fi
  status=$?
}

no_temporaries() {
  local left
  left=$(find "$work" -name '*.partial*' ! -type l)
  [ -z "$left" ] || fail "$1: temporary files left: $left"
}

sum() { md5sum < "$1"; }
before_model=$(sum room.obj) before_mtl=$(sum room.mtl) before_scene=$(sum scene0.json)

for output in json trace image mesh export-scene record log tracing; do
  run_with $output room.obj
  [ $status -eq 2 ] || fail "$output at the input room.obj: exit $status, expected 2"
  [ -e aside.json ] && fail "$output at the input room.obj: another output was written"
  rm -f aside.json
  [ "$(sum room.obj)" = "$before_model" ] || fail "$output changed the model"
  [ "$(sum room.mtl)" = "$before_mtl" ] || fail "$output changed the model's MTL"
  cp "$root/tests/models/room.obj" "$root/tests/models/room.mtl" .  # one failure, not a cascade

  run_with $output folder
  [ $status -eq 5 ] || fail "$output at a folder: exit $status, expected 5"
  [ -d folder ] || fail "$output replaced the folder"
  [ -e aside.json ] && fail "$output at a folder: another output was written"

  ln -s victim out.partial
  run_with $output out
  [ $status -eq 0 ] || fail "$output beside a planted link: exit $status: $(cat stderr)"
  [ -e victim ] && fail "$output wrote through the link planted at out.partial"
  [ -f out ] || fail "$output: the output was not written"
  rm -f out out.partial victim aside.json
  no_temporaries "$output"
done

"$simulate" --check-settings --log=root.app:file:scene0.json --cfg=tracing:yes 2>/dev/null \
  || fail "--check-settings with a log file: exit $?"
[ "$(sum scene0.json)" = "$before_scene" ] || fail "the settings check truncated the log file"
[ -e simgrid.trace ] && fail "the settings check wrote simgrid.trace"

# A platform file that turns tracing on: a JSON one's trace is an output like the others (here
# aimed at the scene: exit 2); a SimGrid XML one's <config> cannot name the trace: none is written.
/usr/bin/python3 - "$root/platforms/ncube2.json" > traced.json <<'PY'
import json, sys
platform = json.load(open(sys.argv[1]))
platform.setdefault("simgrid_config", {}).update({"tracing": "yes", "tracing/filename": "scene0.json"})
print(json.dumps(platform))
PY
"$simulate" scene0.json --iterations 2 --quiet --platform traced.json 2>/dev/null
status=$?
[ $status -eq 2 ] || fail "a JSON platform's trace at the scene: exit $status, expected 2"
[ "$(sum scene0.json)" = "$before_scene" ] || fail "a JSON platform's trace changed the scene"
cp "$root/scenes/scene0.json" .
sed 's|<platform version="4.1">|&<config><prop id="tracing" value="yes"/></config>|' \
  "$root/platforms/ncube2.xml" > traced.xml
grep -q 'id="tracing"' traced.xml || fail "the XML platform was not given a <config> tag"
"$simulate" scene0.json --iterations 2 --quiet --platform traced.xml 2>/dev/null \
  || fail "an XML platform turning tracing on: exit $?"
[ -e simgrid.trace ] && fail "an XML platform's <config> wrote simgrid.trace"
no_temporaries "platform tracing"

# Killed while its outputs are open: once the process holds a temporary file of this folder
# (an open file whose name, if any, is here), the signal comes; nothing may be left.
for signal in SEGV ABRT TERM INT; do
  NCUBE_RECORD_ACTIVITIES=run.act "$simulate" "$root/scenes/scene3.json" --R 8 --V 7 --quiet \
    --json r.json --log=root.app:file:run.log --cfg=tracing:yes 2>/dev/null &
  pid=$!
  for _ in $(seq 200); do
    ls -l /proc/$pid/fd 2>/dev/null | grep -q "$work" && break
    sleep 0.05
  done
  sleep 0.3
  if kill -$signal $pid 2>/dev/null; then
    wait $pid
    status=$?
    [ $status -ne 0 ] || fail "SIG$signal: the run ended with exit 0"
  else
    fail "SIG$signal: the run ended before the signal"
    wait $pid
  fi
  no_temporaries "SIG$signal"
  for file in r.json run.act run.log simgrid.trace; do
    [ -e $file ] && fail "SIG$signal: $file was written"
  done
done

[ "$failures" -eq 0 ] && echo "output_rule_test: all checks passed"
exit $((failures > 0))
