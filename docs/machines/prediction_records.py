"""The records of the prediction's runs (docs/machines/prediction_table.py, 5 runs
at a time by default) and the page's tables made from all of them.

One JSON object a line in RECORDS, one line a run: when, on what machine (the CPU's name and a
hash of its machine id), the load average before and after, the probe's rates and each row's
simulated and host seconds. The page's tables are made from every record: each row's median,
least and worst miss over the runs, per machine and over machines, and the bound held against
the worst run.
"""
import json
import os
import statistics
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(HERE)), "analysis"))
from ncube import output_file  # noqa: E402

RECORDS = os.path.join(HERE, "prediction_records.jsonl")
RATES = ["test_speed", "ray_speed", "blocked_ray_speed", "arithmetic_speed", "edge_term_speed",
         "projection_speed", "raster_speed"]


# The allocator build/machine_probe runs with (CMakeLists.txt): gperftools' tcmalloc, as
# ./simulate, since 2026-11-29. The records before carry no "probe_allocator": their probe ran
# under glibc's malloc, which mapped and faulted in a hemicube's face buffers anew at every face
# (4 times ./simulate's time for them at 400 x 400 cells), so their hemicube rates measured a
# cost the predicted runs never pay. The page's tables are made from the current probe's records.
PROBE_ALLOCATOR = "tcmalloc"
# How the host's seconds are measured (prediction_table.py's run_pair): since 2026-11-29 02:52
# UTC the repeats of the two processes alternate. The records before ran each process's repeats
# in a row, so that a disturbance of a few seconds could fall on all of one process's repeats
# and shrink the difference (scene0's hemicube: 0.066 s where the other runs measured 0.18 to
# 0.19 s, with the probe before and after within 2 %).
MEASUREMENT = "interleaved"


def current(records):
    """The records of the current probe and measurement; the others (earlier runs) are kept in
    the file and counted on the page, not tabulated."""
    return [r for r in records if r.get("probe_allocator", "glibc") == PROBE_ALLOCATOR
            and r.get("measurement", "in a row") == MEASUREMENT]


def earlier_note(records):
    """One sentence naming the records left out of the tables, or nothing."""
    glibc = sum(r.get("probe_allocator", "glibc") != PROBE_ALLOCATOR for r in records)
    in_a_row = len(records) - len(current(records)) - glibc
    parts = []
    if glibc:
        parts.append("%d of probes run under glibc's malloc before the probe was linked with "
                     "./simulate's allocator (\"The allocator\" below)" % glibc)
    if in_a_row:
        parts.append("%d whose host seconds were measured with each process's repeats in a row "
                     "(\"A quiet guest\" below)" % in_a_row)
    if not parts:
        return ""
    left = glibc + in_a_row
    return ("%d earlier record%s (%s) %s kept in the records file and left out of these tables."
            % (left, "" if left == 1 else "s", "; ".join(parts), "is" if left == 1 else "are"))


def load(path):
    """Every record of `path` (none when it does not exist); a line that is not a record is a
    SystemExit naming the file and line."""
    try:
        with open(path, encoding="utf-8") as f:
            lines = f.read().splitlines()
    except FileNotFoundError:
        return []
    records = []
    for number, line in enumerate(lines, 1):
        if not line.strip():
            continue
        try:
            record = json.loads(line)
            if not isinstance(record, dict) or not isinstance(record.get("rows"), list):
                raise ValueError("not a record")
        except ValueError as e:
            raise SystemExit("%s: line %d: %s" % (path, number, e)) from None
        records.append(record)
    return records


def append(path, record):
    """`path` written again with `record` as its last line (the whole file, by the output rule,
    so that an interrupted run leaves the records as they were)."""
    try:
        with open(path, encoding="utf-8") as f:
            text = f.read()
    except FileNotFoundError:
        text = ""
    if text and not text.endswith("\n"):
        text += "\n"
    output_file.write(path, text + json.dumps(record, sort_keys=True) + "\n")


def miss(row):
    return row["simulated"] / row["host"] - 1


def label(row):
    if row["kind"] == "hemicube":
        options = row["options"] if row["options"] not in ("", "(default)") else ""
        return "%s, hemicube %s" % (row["scene"], "`%s`" % options if options else "(default)")
    return row["scene"]


def machine_label(record):
    return "%s, id %s" % (record["cpu"], record["machine"])


def pct(x):
    return ("%+.1f %%" % (100 * x)).replace("-", "−")


def drift(record, rate="test_speed"):
    """How far the host's speed moved within a run: the rate of the probe made after the
    table over the one the prediction used, minus 1 (None for a record without it)."""
    after, before = record.get("rates_after", {}).get(rate), record.get("rates", {}).get(rate)
    return after / before - 1 if after and before else None


def spread_rows(records, tolerance):
    """[(row label, [misses in record order])] in the order the rows first appear."""
    order, misses = [], {}
    for record in records:
        for row in record["rows"]:
            key = label(row)
            if key not in misses:
                order.append(key)
                misses[key] = []
            misses[key].append(miss(row))
    return [(key, misses[key]) for key in order]


def summary_line(key, values, tolerance, machines=None):
    within = sum(abs(v) <= tolerance for v in values)
    least = min(values, key=abs)
    worst = max(values, key=abs)
    cells = [key] + ([machines] if machines is not None else []) + [
        "%d" % len(values), pct(statistics.median(values)), pct(min(values)) + " to " + pct(max(values)),
        pct(least), pct(worst), "%d of %d" % (within, len(values)),
        "yes" if within == len(values) else "**no**"]
    return "| " + " | ".join(cells) + " |"


def opening(records, tolerance):
    """The page's opening, between its prediction-opening markers: what a user gets, from all
    the records (the rates' spread over probes, each row's worst miss over runs and machines,
    where the bound holds)."""
    note = earlier_note(records)
    records = current(records)
    if not records:
        return ("No runs of the prediction recorded yet with the current probe "
                "(`docs/machines/prediction_table.py`). " + note).rstrip() + "\n"
    bound = round(100 * tolerance)
    machines = sorted({machine_label(r) for r in records})
    rows = spread_rows(records, tolerance)
    loads = [r["load_before"][0] for r in records] + [r["load_after"][0] for r in records]
    spreads = []
    for rate in RATES:
        values = [r["rates"][rate] for r in records if rate in r.get("rates", {})]
        if values:
            spreads.append((100 * (max(values) - min(values)) / statistics.median(values), rate))
    held = [k for k, v in rows if all(abs(x) <= tolerance for x in v)]
    missed = [k for k, v in rows if any(abs(x) > tolerance for x in v)]
    out = ["**What a user gets.** The prediction run %d times on %d machine%s (each run a fresh "
           "`build/machine_probe` and then the table below; load average %.1f to %.1f on 2 "
           "cores, before or after a run%s):" % (
               len(records), len(machines), "" if len(machines) == 1 else "s", min(loads),
               max(loads), ", other sessions' builds and runs beside them" if max(loads) > 2 else ""),
           "",
           "* **The probe's rates** spread over those probes (largest − least over the median) "
           "from %.1f %% (`%s`) to %.1f %% (`%s`); `test_speed`, which carries nearly all of a "
           "long-ray scene's time, %.1f %%." % (
               min(spreads)[0], min(spreads)[1], max(spreads)[0], max(spreads)[1],
               next(x for x, r in spreads if r == "test_speed")),
           "* **The prediction's miss** (simulated over the host's CPU seconds, minus 1), median "
           "and worst over the runs: " + "; ".join(
               "%s %s, worst %s" % (k, pct(statistics.median(v)), pct(max(v, key=abs)))
               for k, v in rows) + ".",
           "* **The bound, %d %%, held against the worst run**: " % bound +
           ("it holds for every row in every run." if not missed else
            ("it holds in every run for %s; " % "; ".join(held) if held else "") +
            "it does **not** hold for %s." % "; ".join(missed))]
    quiet = [r for r in records if max(r["load_before"][0], r["load_after"][0]) <= r["cores"]]
    if len(quiet) < len(records):
        out.append("* **Load**: %d of the %d runs had a load average above the cores' count "
                   "before or after; how much of the spread that makes, and how much is the "
                   "model's, is measured below (\"Why the runs spread\")." % (
                       len(records) - len(quiet), len(records)))
    drifts = [(drift(r, rate), rate) for r in records for rate in RATES if drift(r, rate) is not None]
    if drifts:
        tests = [d for d, rate in drifts if rate == "test_speed"]
        largest = max(drifts, key=lambda x: abs(x[0]))
        out.append("* **The host's own drift within a run** (a second probe after the table, "
                   "over the one the prediction used, in %d of the %d runs): `test_speed` moved by "
                   "%s to %s, the largest move of any rate %s (`%s`); a miss of that size can be "
                   "the host's, not the model's." % (
                       len(tests), len(records), pct(min(tests)), pct(max(tests)),
                       pct(largest[0]), largest[1]))
    if note:
        out.append("* **Earlier probes**: " + note)
    return "\n".join(out) + "\n"


def section(records, tolerance):
    """The page's text between its prediction-table markers, from all records."""
    note = earlier_note(records)
    records = current(records)
    if not records:
        return ("No runs recorded yet with the current probe. " + note).rstrip() + "\n"
    bound = round(100 * tolerance)
    machines = sorted({machine_label(r) for r in records})
    rows = spread_rows(records, tolerance)
    held = [k for k, v in rows if all(abs(x) <= tolerance for x in v)]
    missed = [(k, max(v, key=abs), sum(abs(x) > tolerance for x in v), len(v))
              for k, v in rows if any(abs(x) > tolerance for x in v)]
    loads = [r["load_before"][0] for r in records] + [r["load_after"][0] for r in records]
    dates = sorted(r["date"] for r in records)
    out = []
    out.append("**%d runs on %d machine%s** (%s to %s; load average %.1f to %.1f on %s cores, "
               "before or after a run), each a fresh probe and then the table: the bound, %d %% "
               "stated before measuring, held against each row's worst run. " % (
                   len(records), len(machines), "" if len(machines) == 1 else "s", dates[0], dates[-1],
                   min(loads), max(loads), "/".join(sorted({str(r["cores"]) for r in records})), bound))
    if not missed:
        out[-1] += "It holds in every run for every row."
    else:
        out[-1] += ("It holds in every run for %s; it does **not** hold for %s." % (
            ", ".join(held) if held else "no row",
            "; ".join("%s (worst %s, outside in %d of %d runs)" % (k, pct(w), n, m)
                      for k, w, n, m in missed)))
    out += ["", "Over all runs and machines (a miss is simulated over host seconds, minus 1; "
            "least and worst by size):", "",
            "| row | machines | runs | median | range | least | worst | runs within %d %% | "
            "holds in the worst run |" % bound,
            "|---|--:|--:|--:|--:|--:|--:|--:|:-:|"]
    for key, values in rows:
        n = len({machine_label(r) for r in records if any(label(x) == key for x in r["rows"])})
        out.append(summary_line(key, values, tolerance, "%d" % n))
    if len(machines) > 1:
        out += ["", "Per machine:", ""]
    for m in machines:
        mine = [r for r in records if machine_label(r) == m]
        out += ["", "%s (%d runs):" % (m, len(mine)), "",
                "| row | runs | median | range | least | worst | runs within %d %% | "
                "holds in the worst run |" % bound, "|---|--:|--:|--:|--:|--:|--:|:-:|"]
        for key, values in spread_rows(mine, tolerance):
            out.append(summary_line(key, values, tolerance))
    out += ["", "The probe's rates over the same runs (each run's own fresh probe; spread is "
            "largest − least over the median):", "",
            "| rate | machine | probes | median, flop/s | least | largest | spread |",
            "|---|---|--:|--:|--:|--:|--:|"]
    for rate in RATES:
        for m in machines:
            values = [r["rates"][rate] for r in records if machine_label(r) == m and rate in r.get("rates", {})]
            if not values:
                continue
            med = statistics.median(values)
            out.append("| `%s` | %s | %d | %.3g | %.3g | %.3g | %.1f %% |" % (
                rate, m, len(values), med, min(values), max(values),
                100 * (max(values) - min(values)) / med))
    keys = [k for k, _ in rows]
    out += ["", "Each run (load average, 1 minute, before → after; `--repeats` processes a "
            "measurement, the least taken; the binary's commit; host drift: `test_speed` of a second "
            "probe after the table over the first, minus 1):", "",
            "| date (UTC) | machine | commit | repeats | load | wall s | host drift | " +
            " | ".join(keys) + " |",
            "|---|---|---|--:|--:|--:|--:|" + "--:|" * len(keys)]
    for r in records:
        by = {label(x): pct(miss(x)) for x in r["rows"]}
        moved = drift(r)
        out.append("| %s | %s | %s | %d | %.1f → %.1f | %.0f | %s | %s |" % (
            r["date"], r["machine"], r["commit"], r["repeats"], r["load_before"][0],
            r["load_after"][0], r.get("wall_seconds", 0), "—" if moved is None else pct(moved),
            " | ".join(by.get(k, "") for k in keys)))
    last = records[-1]
    ray = [x for x in last["rows"] if x["kind"] == "ray-traced"]
    if ray:
        out += ["", "The scenes' features (the last run's counts) and the host's time a test "
                "beyond the simulated one, over the runs:", "",
                "| scene | ray-patch tests a ray | tests that cross the plane | host − simulated a "
                "test, median | range |", "|---|--:|--:|--:|--:|"]
        for x in ray:
            values = [y["host_minus_simulated_ns_a_test"] for r in records for y in r["rows"]
                      if y["kind"] == "ray-traced" and y["scene"] == x["scene"]]
            out.append("| %s | %.0f | %.0f %% | %+.2f ns | %+.2f to %+.2f ns |" % (
                x["scene"], x["tests_per_ray"], 100 * x["crossing_share"],
                statistics.median(values), min(values), max(values)))
    if note:
        out += ["", note]
    return "\n".join(out).replace("+-", "−") + "\n"
