#!/usr/bin/env bash
# Platform files are untrusted input (issue 37, items 3, 4 and 6; docs/platforms.md, "What a
# platform file may hold"): each hostile or careless file below, a few bytes to 200 KB, is
# refused with exit 2 and one line naming the file, within 10 s and 2 GB of address space, where
# SimGrid crashed, aborted, ran out of memory or ran with absurd values; the sweep tool counts
# a platform's nodes with the same function (./simulate --platform-nodes), so it refuses the
# same files before any cell runs. Every shipped platform still loads, with its node count.
# Called by ctest as: platform_shape_test.sh SIMULATE REPO_ROOT
set -u
simulate="$(realpath "$1")"
root="$2"
export NCUBE_ROOT="$root"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
cd "$work" || exit 1
base="$root/docs/examples/fat-tree-64.xml"
fat='topology="FAT_TREE" topo_parameters="2;4,16;1,4;1,1"'
make() { sed "s|$2|$3|" "$base" > "$1.xml"; grep -qF "$3" "$1.xml" || fail "$1.xml was not made"; }
make torus-huge "$fat" 'topology="TORUS" topo_parameters="1000,1000"'
make torus-mismatch "$fat" 'topology="TORUS" topo_parameters="2,2"'
make radical-huge 'radical="0-63"' 'radical="0-99999999"'
make radical-bad 'radical="0-63"' 'radical="63-0"'
make fat-tree-huge 'topo_parameters="2;4,16;1,4;1,1"' 'topo_parameters="3;100,100,100;1,4,4;1,1,1"'
make fat-tree-bad 'topo_parameters="2;4,16;1,4;1,1"' 'topo_parameters="2;4,16;1;1,1"'
make dragonfly-bad "$fat" 'topology="DRAGONFLY" topo_parameters="1,2;3"'
make bandwidth-nan 'bw="2.2MBps"' 'bw="nanBps"'
make bandwidth-inf 'bw="2.2MBps"' 'bw="infBps"'
make bandwidth-tiny 'bw="2.2MBps"' 'bw="1e-300Bps"'
make latency-huge 'lat="1us"' 'lat="1e300s"'
make latency-nan 'lat="1us"' 'lat="NaNs"'
make speed-negative 'speed="2.5Mf"' 'speed="-2.5Mf"'
make trace '  <cluster' '  <trace id="off" periodicity="1">0 0 1 1</trace><cluster'
/usr/bin/python3 - <<'PY'
depth = 3000   # about 200 KB: SimGrid's parser crashed on it
open("deep.xml", "w").write('<?xml version="1.0"?>\n<platform version="4.1">'
                            + "".join(f'<zone id="z{i}" routing="Full">' for i in range(depth))
                            + "</zone>" * depth + "</platform>\n")
PY
# The cases run in one batch, each forked from build/simulate_server (tests/forked_batch.py:
# about 85 ms of CPU less a case than a new ./simulate, 59 cases), then checked in order.
names=(torus-huge torus-mismatch radical-huge radical-bad fat-tree-huge fat-tree-bad
       dragonfly-bad bandwidth-nan bandwidth-inf bandwidth-tiny latency-huge latency-nan
       speed-negative trace deep)
platforms=("$root"/platforms/ncube2*.json "$root"/platforms/*.xml "$root"/platforms/machines/*.xml
           "$root"/docs/examples/*.xml)
{
  for name in "${names[@]}"; do
    # 10 s and 2 GB of address space: a file that builds what it asks for runs past either.
    printf '{"args": ["%s", "--R", "1", "--iterations", "1", "--platform", "%s", "--quiet"], "stdout": "out-%s.txt", "stderr": "err-%s.txt", "as_kib": 2000000, "timeout": 10}\n' \
      "$root/scenes/scene0.json" "$name.xml" "$name" "$name"
    printf '{"args": ["--platform", "%s", "--platform-nodes"], "stdout": null, "stderr": "nodes-err-%s.txt"}\n' "$name.xml" "$name"
  done
  k=0
  for platform in "${platforms[@]}"; do
    printf '{"args": ["--platform", "%s", "--platform-nodes"], "stdout": "shipped-%d.txt", "stderr": "shipped-err-%d.txt"}\n' "$platform" $k $k
    k=$((k + 1))
  done
} > cases.jsonl
mapfile -t codes < <(/usr/bin/python3 "$root/tests/forked_batch.py" "$simulate" cases.jsonl)
[ "${#codes[@]}" = $((2 * ${#names[@]} + ${#platforms[@]})) ] ||
  fail "the batch ran ${#codes[@]} of its $((2 * ${#names[@]} + ${#platforms[@]})) cases"
k=0
for name in "${names[@]}"; do
  code=${codes[k]}
  [ "$code" = 2 ] || fail "$name: exit $code, expected 2: $(head -c 300 "err-$name.txt")"
  [ "$(wc -l < "err-$name.txt")" = 1 ] && grep -q "^simulate: $name.xml: " "err-$name.txt" \
    || fail "$name: not one line naming the file: $(head -c 300 "err-$name.txt")"
  [ "${codes[k + 1]}" = 2 ] || fail "$name: --platform-nodes did not refuse it"
  k=$((k + 2))
done
grep -q "builds 4 hosts, but radical=\"0-63\" names 64" nodes-err-torus-mismatch.txt \
  || fail "torus-mismatch: the message does not give both counts"

# The sweep tool refuses the same files at validation (one function: --platform-nodes).
printf "name: shapes\noptions: {iterations: 1}\ngrid: {scene: [scene0], R: [1], platform: [torus-mismatch.xml]}\n" > s.yaml
NCUBE_SIMULATE="$simulate" /usr/bin/python3 "$root/experiments/sweep" s.yaml --check > out.txt 2> err.txt
code=$?
[ "$code" = 2 ] && grep -q "key 'platform'.*builds 4 hosts" err.txt \
  || fail "the sweep tool's --check took the mismatched torus (exit $code): $(head -c 300 err.txt)"

# Every shipped platform loads; its node count is what its name or file says.
j=0
for platform in "${platforms[@]}"; do
  nodes="$(cat "shipped-$j.txt")"
  [ "${codes[k + j]}" = 0 ] || { fail "$(basename "$platform"): refused: $(cat "shipped-err-$j.txt")"; j=$((j + 1)); continue; }
  j=$((j + 1))
  case "$(basename "$platform")" in
    *-n[0-9]*.xml) expected="${platform##*-n}"; expected="${expected%.xml}" ;;
    ncube2-d[0-9]*.json) d="${platform##*-d}"; expected=$((1 << ${d%.json})) ;;
    *) expected=64 ;;
  esac
  [ "$nodes" = "$expected" ] || fail "$(basename "$platform"): $nodes nodes, expected $expected"
done

[ "$failures" = 0 ] && echo "platform_shape_test: all checks passed" && exit 0
echo "platform_shape_test: $failures check(s) failed"
exit 1
