#!/usr/bin/env bash
# Names as typed (docs/cli.md, "Names corrected" and "Names in messages"): a mistyped option,
# choice, scene, platform, machine or cost-model name is one line naming what was typed and the
# nearest right names, exit 2, nothing written; names echoed in messages have their control
# characters escaped and long ones cut; --platform-nodes finds its platform by the lookup rule
# from any folder. Each case but one stops before any simulation: about 2 s in all.
# Usage: names_test.sh SIMULATE SOURCE_DIR
simulate=$(realpath "$1")
root=$(realpath "$2")
export NCUBE_ROOT="$root"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# The cases that stop before any simulation run in one batch, each forked from
# build/simulate_server (tests/forked_batch.py: about 85 ms of CPU less a case than a new
# ./simulate; the binary's own start is tests/cli_test.sh's and the --model-folder run's below).
# Each case is queued here and checked after the batch; case K writes its streams to io/K.out
# and io/K.err and runs in the folder run/, which must stay empty.
mkdir io run
n=0
json=""
json_string() {   # TEXT: $json, TEXT as a JSON string (the control characters the cases use escaped)
  local s="$1"
  s=${s//\\/\\\\}; s=${s//\"/\\\"}; s=${s//$'\n'/\\n}; s=${s//$'\t'/\\t}
  s=${s//$'\e'/\\u001b}; s=${s//$'\a'/\\u0007}
  [[ $s != *[[:cntrl:]]* ]] || { echo "FAIL: names_test cannot quote a case's argument"; exit 1; }
  json="\"$s\""
}
queue() {   # ARGS...: case $n; its streams io/$n.out and io/$n.err
  local a sep="" args=""
  for a in "$@"; do json_string "$a"; args+="$sep$json"; sep=", "; done
  printf '{"args": [%s], "stdout": "%s", "stderr": "%s", "timeout": 60}\n' \
    "$args" "$work/io/$n.out" "$work/io/$n.err" >> "$work/cases.jsonl"
  n=$((n + 1))
}
declare -a wanted what refusal
# refused WANTED -- ARGS...: exit 2, exactly one line on stderr holding WANTED (a fixed
# string), no result file, nothing new in the folder. Sets $k to the case's number.
refused() {
  wanted[n]="$1"; shift 2
  local w="simulate $*"
  what[n]=${w:0:200}
  refusal[n]=1
  k=$n
  queue "$@" --json "out-$n.json"
}
# other ARGS...: a case checked by the lines after the batch. Sets $k to the case's number.
other() { what[n]="simulate $*"; what[n]=${what[n]:0:200}; k=$n; queue "$@"; }
# Options: the one meant, not CLI11's "arguments were not expected: 5 --iteration".
refused "unknown option --iteration; did you mean --iterations?" -- scene2.json --iteration 5
refused "unknown option --iteration; did you mean --iterations?" -- scene2.json --iteration=5
refused "unknown option --visibilty; did you mean --visibility?" -- scene0 --visibilty octree
refused "unknown option -R; did you mean --R?" -- scene0 -R 4
refused "unknown option --trace-node; did you mean --trace-nodes?" -- scene0 --trace-node 1
refused "unknown option --imag; did you mean --image, --image-width or --image-height?" -- scene0 --imag x.png
refused "unknown option --bogus (see simulate --help)" -- scene0 --bogus
refused "unexpected argument scene1" -- scene0 scene1

# Choices: the names the method and parallelisation registries list.
refused "--visibility: 'octre' is not one of brute-force, octree; did you mean octree?" -- scene0 --visibility octre
refused "did you mean hemicube?" -- scene0 --form-factors hemicub
refused "did you mean shooters?" -- scene0 --parallelisation shooter
refused "did you mean first-blocker?" -- scene0 --ray-test first
refused "did you mean scanlines?" -- scene0 --render-parallel scanline
refused "did you mean ring?" -- scene0 --render-distribution rign
refused "did you mean elements?" -- scene0 --hemicube-placement element
# Scenes, platforms, machines, cost models: the names in scenes/, platforms/, platforms/machines/.
refused "scen2: no such scene file; did you mean scene2? (looked for" -- scen2
refused "cornell.json: no such scene file; did you mean cornell-box?" -- cornell.json
refused "cm-5: no such platform file; did you mean cm5?" -- scene0 --platform cm-5
refused "paragn.xml: no such platform file; did you mean paragon?" -- scene0 --platform paragn.xml
refused "no such cost model file; did you mean cost_model?" -- scene0 --cost-model cost-model
refused "no such platform file; did you mean cm5?" -- --platform cm-5 --platform-nodes
refused "xyzzy: no such platform file; the nearest names in platforms/ and platforms/machines/:" -- scene0 --platform xyzzy
k_xyzzy=$k

# --platform-nodes by the lookup rule, from a folder that is not the repository.
other --platform cm5 --platform-nodes; k_cm5=$k
other --platform "$root/platforms/machines/cm5.xml" --platform-nodes; k_cm5_file=$k
other --platform ncube2 --platform-nodes; k_ncube2=$k

# Names in messages: a terminal's escape sequence is shown escaped, never raw; a long name cut.
refused 'no such scene file' -- $'\e[31mred\e[0m'; k_red=$k
refused 'no such platform file' -- scene0 --platform $'a\nb'; k_newline=$k
long=$(head -c 100000 /dev/zero | tr '\0' 'x')
refused 'scene file' -- "$long"; k_long=$k
refused "unknown option --$(head -c 148 /dev/zero | tr '\0' 'y')[... 99802 characters ...]" -- scene0 "--$(head -c 100000 /dev/zero | tr '\0' 'y')"
k_long_option=$k
refused "is not a decimal integer" -- scene0 --R $'4\e[2J'; k_value=$k
refused "is not one of" -- scene0 --visibility $'\e]0;title\a'; k_choice=$k

# --check-settings lists the files SimGrid would write as every other message names a file:
# control characters escaped, a long name cut (the sweep tool shows these lines).
other --check-settings $'--cfg=tracing/filename:t\e[2J.paje' --cfg=tracing:yes; k_trace=$k
other --check-settings "--cfg=tracing/filename:$(head -c 100000 /dev/zero | tr '\0' 'z')" --cfg=tracing:yes
k_long_trace=$k

# The batch, from run/.
mapfile -t codes < <(cd run && /usr/bin/python3 "$root/tests/forked_batch.py" "$simulate" "$work/cases.jsonl")
[ "${#codes[@]}" = "$n" ] || fail "the batch ran ${#codes[@]} of its $n cases"
for ((i = 0; i < n; i++)); do
  [ -n "${refusal[i]}" ] || continue
  err="io/$i.err"
  [ "${codes[i]}" = 2 ] || fail "${what[i]}: exit ${codes[i]}, expected 2 ($(head -c 300 "$err"))"
  [ "$(wc -l <"$err")" -eq 1 ] || fail "${what[i]}: $(wc -l <"$err") lines on stderr, expected 1: $(head -c 600 "$err")"
  grep -qF -- "${wanted[i]}" "$err" || fail "${what[i]}: the message does not say '${wanted[i]}': $(head -c 600 "$err")"
  [ -e "run/out-$i.json" ] && fail "${what[i]}: wrote a result file"
done
[ -z "$(ls -A run)" ] || fail "the refusals left files: $(ls -A run)"

grep -q "(looked for: xyzzy, " "io/$k_xyzzy.err" || fail "the places tried are no longer listed: $(cat "io/$k_xyzzy.err")"

nodes=$(cat "io/$k_cm5.out"); expected=$(cat "io/$k_cm5_file.out")
[ "${codes[k_cm5]}" = 0 ] || fail "--platform cm5 --platform-nodes from another folder: $(cat "io/$k_cm5.err")"
[ "${codes[k_cm5_file]}" = 0 ] || fail "--platform .../cm5.xml --platform-nodes: $(cat "io/$k_cm5_file.err")"
[ -n "$nodes" ] && [ "$nodes" = "$expected" ] || fail "--platform cm5 --platform-nodes gives '$nodes', the file itself '$expected'"
[ "${codes[k_ncube2]}" = 0 ] && [ "$(cat "io/$k_ncube2.out")" = 64 ] || fail "--platform ncube2 --platform-nodes is not 64"

err="io/$k_red.err"
grep -q $'\e' "$err" && fail "an escape character reached the terminal: $(od -c "$err" | head -3)"
grep -qF '\e[31mred\e[0m: no such scene file' "$err" || fail "the escaped name is not shown: $(cat "$err")"
err="io/$k_newline.err"
grep -qF 'a\nb: no such platform file' "$err" || fail "a newline in a name is not shown as \\n: $(cat "$err")"
err="io/$k_long.err"
size=$(wc -c <"$err")
[ "$size" -lt 1000 ] || fail "a 100,000-character name gives a message of $size bytes"
grep -qF "[... 998" "$err" || fail "the long name is not cut: $(head -c 300 "$err" | cut -c 1-300)"
[ "$(wc -c <"io/$k_long_option.err")" -lt 4096 ] || fail "a 100,000-character option gives a message of $(wc -c <"io/$k_long_option.err") bytes"
grep -q $'\e' "io/$k_value.err" && fail "an escape character in a value reached the terminal"
grep -q $'[\e\a]' "io/$k_choice.err" && fail "an escape character in a choice reached the terminal"

out="io/$k_trace.out"
[ "${codes[k_trace]}" = 0 ] || fail "--check-settings with a trace file: exit ${codes[k_trace]}: $(cat "io/$k_trace.err")"
grep -q $'\e' "$out" && fail "--check-settings printed an escape character raw: $(od -c "$out" | head -3)"
grep -qF 'output: t\e[2J.paje' "$out" || fail "--check-settings does not show the escaped name: $(cat "$out")"
out="io/$k_long_trace.out"
[ "${codes[k_long_trace]}" = 0 ] || fail "--check-settings with a long trace name: exit ${codes[k_long_trace]}: $(head -c 300 "io/$k_long_trace.err")"
[ "$(wc -c <"$out")" -lt 1000 ] || fail "--check-settings printed a 100,000-character name whole ($(wc -c <"$out") bytes)"
grep -qF "[... " "$out" || fail "--check-settings does not cut a long name: $(head -c 300 "$out")"

# The other tools parse alike; an unknown option is named before a required one is missed.
bench="$(dirname "$simulate")/network_bench"
"$bench" --platfrom cm5 >stdout 2>stderr
[ $? -eq 2 ] && [ "$(wc -l <stderr)" -eq 1 ] &&
  grep -qF "network_bench: unknown option --platfrom; did you mean --platform? (see network_bench --help)" stderr ||
  fail "network_bench --platfrom cm5: $(cat stderr)"
rm -f stdout stderr

# --model-folder: as given, else from the repository. A model here whose MTL lies in the
# repository's tests/models/ reads it when that folder is allowed by its repository path.
# (Started anew: this test also tries the binary's own start.)
mkdir m
sed "s|^mtllib room.mtl|mtllib $(realpath --relative-to=m "$root/tests/models")/room.mtl|" \
  "$root/tests/models/room.obj" >m/room.obj
(cd m && "$simulate" room.obj --model-folder tests/models --iterations 1 --quiet 2>../stderr) ||
  fail "--model-folder tests/models from another folder: $(cat stderr)"
rm -rf m stderr

[ "$failures" -eq 0 ] && echo "names_test: all passed"
exit "$failures"
