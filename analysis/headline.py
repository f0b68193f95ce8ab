#!/usr/bin/python3
"""What the model would need for the paper's headline to hold again on scene2 (what-if runs).

Writes analysis/headline.json, which analysis/report.py reads (its section "The paper's
headline").

usage: /usr/bin/python3 analysis/headline.py [--jobs N]

In the simulation scene2's naive parallelisation (R=64 V=0) beats every Table 4 configuration
with visibility processors, where the paper has R=8 V=7 ahead (ncube.headline). This sizes, for
each of three model parameters alone, the factor on it at which the fastest configuration with
visibility processors would overtake R=64 V=0 again, without changing the model: each run is a
what-if with a scaled copy of platforms/ncube2.json or platforms/cost_model.json in a temporary
folder (the committed files and every committed result stay as they are).

The parameters: the per-message software overhead (send_overhead and receive_overhead alike),
the time to move a byte over a link (1 / link_bandwidth) and the cost of one ray-patch test
(flops_per_ray_patch_test, one of the two fitted costs). Seconds per iteration are close to
affine in each (a message costs its overhead at both ends, a byte its transfer, a test its
flops; what moves is only which node waits for which), so one run of every Table 4
configuration at the committed value and one at PROBE times it give each configuration's slope;
the crossing of the fastest V > 0 line with R=64 V=0's is the factor sized. It is then checked
by running every configuration at 10 % past it (must flip) and 10 % short of it (must not):
the check is the factor's uncertainty. 15 runs per parameter, about 25 s of host time each
five; the whole study about 4 minutes on two cores."""

from ncube.interpreter import use_project_python  # noqa: E402

use_project_python()   # Debian's /usr/bin/python3 (README.md, "Use")

import argparse
import concurrent.futures
import json
import tempfile
from pathlib import Path

from ncube import headline, page, simulate  # noqa: E402
from ncube.paths import ANALYSIS, ROOT  # noqa: E402

OUTPUT = ANALYSIS / "headline.json"
SCENE, TABLE, ROWS = "scene2", 4, headline.TABLE4_ROWS
OPTIONS = {"samples": 64, "iterations": 20}   # experiments/table4.json's
PROBE = 2.0          # the factor of the slope run
CHECK = 1.1          # the check runs at the sized factor times / divided by this
# name: (file, its parameters scaled, how a factor k applies to the value)
PARAMETERS = {
    "message overhead": ("ncube2.json", ["send_overhead", "receive_overhead"], "times"),
    "time per byte on a link": ("ncube2.json", ["link_bandwidth"], "divided"),
    "ray-patch test cost": ("cost_model.json", ["flops_per_ray_patch_test"], "times"),
}


def scaled_file(folder, file, names, how, factor):
    """A copy of platforms/<file> with `names` scaled by `factor` (how: "times" multiplies,
    "divided" divides), in `folder`; None for factor 1 (the committed file)."""
    if factor == 1:
        return None
    data = json.loads((ROOT / "platforms" / file).read_text())
    for name in names:
        value = data["parameters"][name]["value"]
        data["parameters"][name]["value"] = value * factor if how == "times" else value / factor
    path = Path(folder) / f"{'-'.join(names)}-{factor:.6g}-{file}"
    path.write_text(json.dumps(data, indent=1))
    return path


def times_at(pool, folder, parameter, factor):
    """{(R, V): seconds per iteration} of scene2's Table 4 configurations at `factor`."""
    file, names, how = PARAMETERS[parameter]
    path = scaled_file(folder, file, names, how, factor)
    where = {"platform": path} if file == "ncube2.json" else {"cost_model": path}
    jobs = {rv: pool.submit(simulate.run, SCENE, dict(OPTIONS, R=rv[0], V=rv[1]),
                            accept_out_of_memory=False, **where) for rv in ROWS}
    return {rv: job.result()["seconds_per_iteration"] for rv, job in jobs.items()}


def crossing(base, probe):
    """The factor k at which the fastest V > 0 configuration's affine line meets R=64 V=0's
    (each line through its value at 1 and at PROBE), and that configuration; None when no
    positive k brings one below it."""
    naive = (64, 0)
    slope = {rv: (probe[rv] - base[rv]) / (PROBE - 1) for rv in base}
    best = None
    for rv in base:
        if rv[1] == 0 or slope[naive] == slope[rv]:
            continue
        k = 1 + (base[rv] - base[naive]) / (slope[naive] - slope[rv])
        beyond = k * 1.01
        ahead = base[rv] + slope[rv] * (beyond - 1) < base[naive] + slope[naive] * (beyond - 1)
        if k > 0 and ahead and (best is None or abs(k - 1) < abs(best[0] - 1)):
            best = (k, rv)
    return best, slope


def table(times):
    return {headline.row_text(rv): t for rv, t in sorted(times.items())}


@page.refusing_outputs("headline.py")
def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--jobs", type=int, default=2, help="simulations run at once")
    args = parser.parse_args()
    page.will_run("headline.py", "what-if runs", announce=False)
    print(f"headline.py: runs up to {len(PARAMETERS) * 3 * len(ROWS)} what-if runs of {SCENE} "
          "(none is kept: the study starts afresh each time)", flush=True)
    study = {"scene": SCENE, "table": TABLE, "options": OPTIONS, "probe_factor": PROBE,
             "check_factor": CHECK, "parameters": {}}
    with tempfile.TemporaryDirectory() as folder, \
            concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        base = times_at(pool, folder, next(iter(PARAMETERS)), 1)
        study["committed"] = table(base)
        for parameter, (file, names, how) in PARAMETERS.items():
            probe = times_at(pool, folder, parameter, PROBE)
            found, slope = crossing(base, probe)
            entry = {"file": f"platforms/{file}", "scaled": names, "applied": how,
                     "at_probe": table(probe),
                     "slope_seconds_per_unit_factor": table(slope)}
            if found:
                k, rv = found
                # Toward the flip: past it is k * CHECK when the flip lies above 1, else k / CHECK.
                past, short = (k * CHECK, k / CHECK) if k > 1 else (k / CHECK, k * CHECK)
                checks = {}
                for label, factor in (("past", past), ("short", short)):
                    decision = headline.decide(times_at(pool, folder, parameter, factor))
                    checks[label] = {"factor": factor, "holds": decision.holds,
                                     "best_visibility": headline.row_text(decision.best_visibility),
                                     "visibility_seconds": decision.visibility_seconds,
                                     "naive_seconds": decision.naive_seconds}
                entry.update({"flip_factor": k, "overtaking": headline.row_text(rv),
                              "checks": checks})
            else:
                entry["flip_factor"] = None
            study["parameters"][parameter] = entry
            said = (f"flips at x{found[0]:.3g} ({headline.row_text(found[1])})" if found
                    else "no positive factor flips it")
            print(f"headline.py: {parameter}: {said}", flush=True)
    page.write(OUTPUT, json.dumps(study, indent=1, sort_keys=True) + "\n")
    print(f"headline.py: wrote {OUTPUT.relative_to(ROOT)}")


if __name__ == "__main__":
    main()
