#!/usr/bin/env bash
# Names as typed (docs/cli.md, "Names corrected" and "Names in messages"): a mistyped option,
# choice, scene, platform, machine or cost-model name is one line naming what was typed and the
# nearest right names, exit 2, nothing written; names echoed in messages have their control
# characters escaped and long ones cut; --platform-nodes finds its platform by the lookup rule
# from any folder. Each case stops before any simulation: about 2 s in all.
# Usage: names_test.sh SIMULATE SOURCE_DIR
simulate=$(realpath "$1")
root=$(realpath "$2")
export NCUBE_ROOT="$root"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# refused WANTED -- ARGS...: exit 2, exactly one line on stderr holding WANTED (a fixed
# string), no result file, nothing new in the folder.
refused() {
  local wanted="$1"; shift 2
  rm -f out.json
  "$simulate" "$@" --json out.json >stdout 2>stderr
  local got=$?
  local what="simulate $*"
  what=${what:0:200}
  [ "$got" -eq 2 ] || fail "$what: exit $got, expected 2 ($(head -c 300 stderr))"
  [ "$(wc -l <stderr)" -eq 1 ] || fail "$what: $(wc -l <stderr) lines on stderr, expected 1: $(head -c 600 stderr)"
  grep -qF -- "$wanted" stderr || fail "$what: the message does not say '$wanted': $(head -c 600 stderr)"
  [ -e out.json ] && fail "$what: wrote a result file"
  [ "$(ls | sort | tr '\n' ' ')" = "stderr stdout " ] || fail "$what: left files: $(ls)"
}

# Options: the one meant, not CLI11's "arguments were not expected: 5 --iteration".
refused "unknown option --iteration; did you mean --iterations?" -- scene2.json --iteration 5
refused "unknown option --iteration; did you mean --iterations?" -- scene2.json --iteration=5
refused "unknown option --visibilty; did you mean --visibility?" -- scene0 --visibilty octree
refused "unknown option -R; did you mean --R?" -- scene0 -R 4
refused "unknown option --trace-node; did you mean --trace-nodes?" -- scene0 --trace-node 1
refused "unknown option --imag; did you mean --image, --image-width or --image-height?" -- scene0 --imag x.png
refused "unknown option --bogus (see simulate --help)" -- scene0 --bogus
refused "unexpected argument scene1" -- scene0 scene1
# The other tools parse alike; an unknown option is named before a required one is missed.
bench="$(dirname "$simulate")/network_bench"
"$bench" --platfrom cm5 >stdout 2>stderr
[ $? -eq 2 ] && [ "$(wc -l <stderr)" -eq 1 ] &&
  grep -qF "network_bench: unknown option --platfrom; did you mean --platform? (see network_bench --help)" stderr ||
  fail "network_bench --platfrom cm5: $(cat stderr)"
rm -f stdout stderr

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
grep -q "(looked for: xyzzy, " stderr || fail "the places tried are no longer listed: $(cat stderr)"

# --platform-nodes by the lookup rule, from a folder that is not the repository.
nodes=$("$simulate" --platform cm5 --platform-nodes 2>stderr) || fail "--platform cm5 --platform-nodes from another folder: $(cat stderr)"
expected=$("$simulate" --platform "$root/platforms/machines/cm5.xml" --platform-nodes 2>/dev/null)
[ -n "$nodes" ] && [ "$nodes" = "$expected" ] || fail "--platform cm5 --platform-nodes gives '$nodes', the file itself '$expected'"
[ "$("$simulate" --platform ncube2 --platform-nodes 2>/dev/null)" = 64 ] || fail "--platform ncube2 --platform-nodes is not 64"
rm -f stderr
# --model-folder: as given, else from the repository. A model here whose MTL lies in the
# repository's tests/models/ reads it when that folder is allowed by its repository path.
mkdir m
sed "s|^mtllib room.mtl|mtllib $(realpath --relative-to=m "$root/tests/models")/room.mtl|" \
  "$root/tests/models/room.obj" >m/room.obj
(cd m && "$simulate" room.obj --model-folder tests/models --iterations 1 --quiet 2>../stderr) ||
  fail "--model-folder tests/models from another folder: $(cat stderr)"
rm -rf m stderr

# Names in messages: a terminal's escape sequence is shown escaped, never raw; a long name cut.
refused 'no such scene file' -- $'\e[31mred\e[0m'
grep -q $'\e' stderr && fail "an escape character reached the terminal: $(od -c stderr | head -3)"
grep -qF '\e[31mred\e[0m: no such scene file' stderr || fail "the escaped name is not shown: $(cat stderr)"
refused 'no such platform file' -- scene0 --platform $'a\nb'
grep -qF 'a\nb: no such platform file' stderr || fail "a newline in a name is not shown as \\n: $(cat stderr)"
long=$(head -c 100000 /dev/zero | tr '\0' 'x')
refused 'scene file' -- "$long"
size=$(wc -c <stderr)
[ "$size" -lt 1000 ] || fail "a 100,000-character name gives a message of $size bytes"
grep -qF "[... 998" stderr || fail "the long name is not cut: $(head -c 300 stderr | cut -c 1-300)"
refused "unknown option --$(head -c 148 /dev/zero | tr '\0' 'y')[... 99802 characters ...]" -- scene0 "--$(head -c 100000 /dev/zero | tr '\0' 'y')"
[ "$(wc -c <stderr)" -lt 4096 ] || fail "a 100,000-character option gives a message of $(wc -c <stderr) bytes"
refused "is not a decimal integer" -- scene0 --R $'4\e[2J'
grep -q $'\e' stderr && fail "an escape character in a value reached the terminal"
refused "is not one of" -- scene0 --visibility $'\e]0;title\a'
grep -q $'[\e\a]' stderr && fail "an escape character in a choice reached the terminal"

# --check-settings lists the files SimGrid would write as every other message names a file:
# control characters escaped, a long name cut (the sweep tool shows these lines).
"$simulate" --check-settings $'--cfg=tracing/filename:t\e[2J.paje' --cfg=tracing:yes >stdout 2>stderr \
  || fail "--check-settings with a trace file: exit $?: $(cat stderr)"
grep -q $'\e' stdout && fail "--check-settings printed an escape character raw: $(od -c stdout | head -3)"
grep -qF 'output: t\e[2J.paje' stdout || fail "--check-settings does not show the escaped name: $(cat stdout)"
"$simulate" --check-settings "--cfg=tracing/filename:$(head -c 100000 /dev/zero | tr '\0' 'z')" \
  --cfg=tracing:yes >stdout 2>stderr || fail "--check-settings with a long trace name: exit $?: $(head -c 300 stderr)"
[ "$(wc -c <stdout)" -lt 1000 ] || fail "--check-settings printed a 100,000-character name whole ($(wc -c <stdout) bytes)"
grep -qF "[... " stdout || fail "--check-settings does not cut a long name: $(head -c 300 stdout)"
rm -f stdout stderr

[ "$failures" -eq 0 ] && echo "names_test: all passed"
exit "$failures"
