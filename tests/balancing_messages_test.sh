#!/usr/bin/env bash
# Load balancing (section 4.2): a transfer is one message (kPatches) with its patches' bytes,
# and the master's orders travel with the shooter to the R - 1 other radiosity processors.
# Against the same run without balancing (same cuts and shooters, the same loads sent with
# the candidates since subdivision is on), the messages and bytes sent differ by exactly that.
# Called by ctest as: balancing_messages_test.sh SIMULATE REPO_ROOT
set -u
simulate="$1"
root="$2"
export NCUBE_ROOT="$root"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

for balance in on off; do
  extra=(); [ "$balance" = on ] && extra=(--balance)
  "$simulate" scene1.json --R 4 --V 0 --subdivide --iterations 8 "${extra[@]}" --quiet \
    --json "$work/$balance.json" || { echo "FAIL: simulate exited $? (balance $balance)"; exit 1; }
done

/usr/bin/python3 - "$work/on.json" "$work/off.json" <<'PY'
import json, sys
on, off = (json.load(open(f)) for f in sys.argv[1:3])
costs = on["provenance"]["cost_model"]["values"]
R = on["config"]["R"]
failures = []
def check(ok, what):
    if not ok:
        failures.append(what)
check(on["shooters"] == off["shooters"], "balancing changed the shooters")
check(off["transfers"]["messages"] == 0, "a run without balancing sent transfers")
n = on["transfers"]["messages"]
check(n > 0, "the run with balancing moved nothing (the test needs a transfer)")
check(on["patches_moved"] >= n, "an order moved no patch")
sent = lambda r: (sum(x["messages_sent"] for x in r["nodes"]), sum(x["bytes_sent"] for x in r["nodes"]))
(m_on, b_on), (m_off, b_off) = sent(on), sent(off)
check(m_on - m_off == n, f"messages: {m_on - m_off} more with balancing, {n} transfers")
expected = (on["transfers"]["payload_bytes"] + n * costs["message_header_bytes"]
            + (R - 1) * n * costs["transfer_order_bytes"])
check(abs((b_on - b_off) - expected) < 1e-6, f"bytes: {b_on - b_off} more with balancing, expected {expected}")
check(on["transfers"]["payload_bytes"] >=
      on["patches_moved"] * (costs["patch_radiosity_bytes"] + costs["element_bytes"]),
      "a moved patch weighs less than its radiosity data and one element record")
for f in failures:
    print("FAIL:", f)
if not failures:
    print(f"PASS: {n} transfers, {on['patches_moved']} patches, {on['transfers']['payload_bytes']:.0f} bytes")
sys.exit(1 if failures else 0)
PY
