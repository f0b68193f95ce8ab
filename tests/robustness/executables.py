#!/usr/bin/python3
"""Every program and script the repository ships, and the tests that try it as a user would
(tests/shipped_executables_test.sh). Shipped means: a target of CMakeLists.txt's
add_executable (but the test binaries unit_tests and simulate_server), or a tracked file
outside tests/ that is executable or starts with "#!"; tests/slurm_cluster.sh too, which users
run. A new one fails the test until it is listed here with the tests that try it (each must
name it), or as open with why.

usage: executables.py ROOT   (prints what is shipped and not listed, listed and gone,
                              listed tests that do not name their program, and whether
                              docs/threat-model.md's table is this list; exit 1 if any)
       executables.py [ROOT] --page   (rewrites docs/threat-model.md's table)"""
import os
import re
import subprocess
import sys
from pathlib import Path

# program -> the tests that try it (file names under tests/), or "open: why".
COVERED = {
    # The C++ programs.
    "simulate": ["cli_test.sh", "input_files_test.sh", "robustness/run.py"],
    "reference_solution": ["reference_solution_options_test.sh", "reference_solution_test.sh"],
    "machine_probe": ["machine_probe_test.sh", "robustness/threat_model.py"],
    "network_bench": ["network_tables_test.sh", "platform_outputs_test.sh"],
    "simgrid_replay": ["simgrid_replay_test.sh"],
    "embree_floor": ["embree_floor_test.sh"],
    "simulate_throwaway": ["throwaway_methods_test.sh"],
    "simgrid_alone": "open: a benchmark's floor (bench/simgrid_alone.cpp), run by hand",
    "benchmarks": "open: Google Benchmark's own options; run by hand (bench/)",
    # The wrapper and the shell helpers.
    "simulate (wrapper)": ["sweep_failures_test.py", "readme_test.sh"],
    "tests/slurm_cluster.sh": ["slurm_cluster_test.sh", "sweep_slurm_test.sh"],
    ".ci/install-deps": "open: installs packages (root); measured on a fresh root (README.md)",
    ".ci/run": "open: CI itself (the build and the whole suite)",
    # The sweep tool and the study drivers.
    "experiments/sweep": ["sweep_test.py", "python_inputs_test.sh", "robustness/threat_model.py"],
    "experiments/reproduce": ["sweep_test.py"],
    "experiments/claims/references": ["reference_solution_test.sh"],
    "analysis/ncube/reference_manifest.py": ["reference_solution_test.sh"],
    "experiments/claims/cycles-answers": ["cycles_answers_test.sh"],
    # The page scripts.
    "analysis/report.py": ["page_scripts_test.sh", "page_outputs_test.sh"],
    "analysis/machines.py": ["page_scripts_test.sh", "machines_study_test.sh"],
    "analysis/unknowns.py": ["page_scripts_test.sh", "unknowns_test.py"],
    "analysis/claims.py": ["page_scripts_test.sh", "python_inputs_test.sh", "claims_test.sh"],
    "analysis/claims_hemicube.py": ["python_inputs_test.sh", "claims_hemicube_test.sh"],
    "analysis/claims_schemes.py": ["page_scripts_test.sh", "claims_schemes_test.sh"],
    "analysis/adaptive.py": ["page_scripts_test.sh"],
    "analysis/calibrate.py": ["page_scripts_test.sh"],
    "analysis/memory_sensitivity.py": ["page_scripts_test.sh"],
    "analysis/patch_order.py": ["page_scripts_test.sh"],
    "analysis/predictions.py": ["page_scripts_test.sh", "predictions_sweeps_test.sh"],
    "analysis/ncube/accuracy.py": ["structure_solution_file_test.sh", "robustness/threat_model.py"],
    "analysis/cycles/compare.py": ["python_inputs_test.sh", "cycles_reference_test.sh"],
    "analysis/cycles/cycles_answers.py": ["python_inputs_test.sh", "cycles_answers_test.sh"],
    # The generators of committed tables, platforms and scenes.
    "docs/model_tables.py": ["page_scripts_test.sh", "model_tables_test.sh"],
    "docs/options_table.py": ["page_scripts_test.sh", "options_description_test.sh"],
    "docs/platform_tables.py": ["page_scripts_test.sh", "platform_tables_test.sh"],
    "docs/machines/index_table.py": ["page_scripts_test.sh", "machines_platforms_test.sh"],
    "docs/machines/network_tables.py": ["network_tables_test.sh"],
    "docs/machines/prediction_table.py": ["machine_probe_test.sh"],
    "docs/machines/balance_table.py": "open: a table of docs/machines/ from finished runs, by hand",
    "docs/machines/loop_profile.py": "open: a study of minutes of cachegrind and timed runs, by hand; its tables again from the committed measurements (--from, --page) are page_scripts_test.sh's",
    "docs/machines/hemicube_profile.py": "open: a study of minutes of callgrind and timed runs, by hand; its tables again from the committed measurements (--from, --page) are page_scripts_test.sh's",
    "analysis/openings.py": ["page_scripts_test.sh"],
    "analysis/headline.py": "open: 45 what-if runs of ./simulate (about 5 minutes), run by hand; its committed analysis/headline.json is checked by openings_test.py",
    "platforms/generate.py": ["page_scripts_test.sh", "platforms_reproducible_test.sh"],
    "platforms/machines/generate.py": ["page_scripts_test.sh", "machines_platforms_test.sh"],
    "scenes/generate.py": ["scenes_reproducible_test.sh"],
    # Benchmarks: minutes of runs, outside the suite.
    "bench/hypercube_scale.py": "open: a benchmark (minutes), run by hand",
    "bench/long_runs.py": ["embree_floor_test.sh", "simgrid_replay_test.sh"],
    "bench/memory_fit.py": "open: a benchmark (minutes), run by hand",
    "bench/parallel_bench.sh": "open: a benchmark (minutes), run by hand",
    "bench/speed_report.py": "open: a benchmark's report, run by hand",
}


# program -> (what it reads, what it writes, what it runs): docs/threat-model.md's table is
# written from this and COVERED (executables.py ROOT --page; --check fails when it differs), so
# a program shipped and listed above is on the page too.
SURFACE = {
    "simulate": ("a scene or model (OBJ, PLY, glTF, .glb) and the files the model names, a platform (JSON or SimGrid XML), a cost model; found by the lookup rule (NCUBE_ROOT)",
                 "--json, --image, --mesh, --trace, --export-scene; SimGrid's log files and trace (--log, --cfg); NCUBE_RECORD_ACTIVITIES", "itself in a child for the SimGrid settings (one each when that child refuses; --check-settings)"),
    "reference_solution": ("a scene file", "--out, --mesh", "nothing"),
    "machine_probe": ("--network (SimGrid XML), --cost-model", "--out (a SimGrid platform)", "its own timing kernels"),
    "network_bench": ("--platform (JSON or XML), --cost-model", "--json", "nothing"),
    "simgrid_replay": ("a recording of a run's messages", "stdout", "nothing"),
    "embree_floor": ("a scene file", "stdout", "nothing"),
    "simulate_throwaway": ("as simulate", "as simulate", "as simulate (a test build with throwaway methods)"),
    "simgrid_alone": ("a recording", "stdout", "nothing"),
    "benchmarks": ("scenes of scenes/", "stdout", "nothing"),
    "simulate (wrapper)": ("build/simulate's arguments", "as build/simulate", "cmake (when build/simulate is missing), build/simulate"),
    "tests/slurm_cluster.sh": ("its folder's configuration and pid files; SLURM_CLUSTER_CPUS (a whole number from 1 to 9999)", "a Slurm configuration, logs and pid files in its folder", "slurmctld, slurmd; signals only the daemons it started"),
    ".ci/install-deps": ("nothing", "Debian packages (root)", "apt-get"),
    ".ci/run": ("the repository", "build/", "install-deps, cmake, ./simulate, ctest"),
    "experiments/sweep": ("sweep files (YAML or JSON), the scenes, platforms and cost models they name, result files, build/platform-nodes/ (its platforms' node counts)", "--results folder: plan.json, one result file per cell, sweeps/NAME/ summaries; with --slurm, slurm_job.sh (the job script's template); build/platform-nodes/KEY (a platform's node count, once per build)", "Snakemake, ./simulate per cell (locally, or through Slurm's sbatch, each job running ncube.cluster_job, no Snakemake of its own)"),
    "experiments/reproduce": ("experiments/table1-5.json, timeline.json", "--results folder", "experiments/sweep"),
    "analysis/ncube/reference_manifest.py": ("analysis/reference/*.json and manifest/, the scenes", "DIR/manifest/SCENE.json and fingerprint.json (each record written whole); with run, DIR/SCENE.json", "BUILD/reference_solution (run, fingerprint, check)"),
    "experiments/claims/references": ("scenes", "analysis/reference/SCENE.json", "build/reference_solution"),
    "experiments/claims/cycles-answers": ("scenes", "--out folder (default analysis/cycles/)", "analysis/cycles/cycles_answers.py"),
    "analysis/report.py": ("--results folder's result files, experiments/*.json", "--out-dir: report.md, figures/ (a committed page only from complete results)", "nothing"),
    "analysis/machines.py": ("--sweep, --results", "--output, --figures", "experiments/sweep (--run)"),
    "analysis/unknowns.py": ("experiments/unknowns/study.json, analysis/unknowns.json, --summary, --results", "--out-dir: unknowns.md, unknowns-worlds.json, figures/", "experiments/sweep (--run)"),
    "analysis/claims.py": ("--sweeps, --pictures, --results", "--out, --figure, --pictures-figure", "experiments/sweep, build/simulate"),
    "analysis/claims_hemicube.py": ("--sweep, --results", "its section of analysis/claims.md", "experiments/sweep"),
    "analysis/claims_schemes.py": ("--sweep, --results", "--figure and its section of analysis/claims.md", "experiments/sweep"),
    "analysis/adaptive.py": ("scenes", "--output and its figures", "--simulate"),
    "analysis/calibrate.py": ("analysis/calibration.json, platforms/cost_model.json", "platforms/cost_model.json, analysis/calibration-fit.json (not with --dry-run)", "build/simulate"),
    "analysis/memory_sensitivity.py": ("scenes, platforms", "analysis/memory-sensitivity.md, .json, its figure", "build/simulate"),
    "analysis/patch_order.py": ("--results", "analysis/patch-order.md, .json", "experiments/sweep"),
    "analysis/predictions.py": ("experiments/predictions/, --results", "analysis/predictions.md", "experiments/sweep"),
    "analysis/ncube/accuracy.py": ("a solution mesh (PLY), a reference file", "--json", "nothing"),
    "analysis/cycles/compare.py": ("a reference file, a Cycles answer file", "--json", "nothing"),
    "analysis/cycles/cycles_answers.py": ("a scene file; Blender's report and texels", "--out", "--blender (Debian's blender) in a scratch folder"),
    "docs/model_tables.py": ("platforms/cost_model.json", "docs/model.md's tables", "nothing"),
    "docs/options_table.py": ("analysis/ncube/simulate_options.json", "docs/cli.md's and docs/result-format.md's tables", "nothing"),
    "docs/platform_tables.py": ("src/machine/machine_parameters.h's list", "tables of docs/model.md, docs/platforms.md, docs/result-format.md", "nothing"),
    "docs/machines/index_table.py": ("platforms/machines/*.xml", "docs/machines/README.md's table", "nothing"),
    "docs/machines/network_tables.py": ("--published, platforms/machines/*.xml", "the machine pages' tables", "--bench (build/network_bench)"),
    "docs/machines/prediction_table.py": ("--platform (or a probe's)", "docs/machines/probe.md's table (not with --print)", "build/machine_probe, build/simulate"),
    "docs/machines/balance_table.py": ("platforms/", "docs/machines/'s balance table (not with --print)", "build/simulate"),
    "docs/machines/loop_profile.py": ("--from (JSON), platforms/machines/cluster-2024.xml, platforms/cost_model.json", "--out (JSON); docs/machines/probe.md's loop-profile tables (--page)", "build/machine_probe, build/simulate, valgrind, cg_annotate"),
    "docs/machines/hemicube_profile.py": ("--from (JSON), platforms/machines/cluster-2024.xml, platforms/cost_model.json", "--out (JSON); docs/machines/probe.md's hemicube-profile section and opening sentence (--page)", "build/machine_probe, build/simulate, valgrind, callgrind_annotate"),
    "analysis/openings.py": ("the pages named", "each page's opening", "nothing"),
    "analysis/headline.py": ("scene2, platforms", "analysis/headline.json", "build/simulate"),
    "platforms/generate.py": ("platforms/ncube2.json", "--out: ncube2-d7.json .. ncube2-d13.json", "nothing"),
    "platforms/machines/generate.py": ("its own table of machines", "--out: platforms/machines/*.xml", "nothing"),
    "scenes/generate.py": ("nothing", "--out: the scenes", "nothing"),
    "bench/hypercube_scale.py": ("--scene, platforms", "stdout", "--simulate, /usr/bin/time"),
    "bench/long_runs.py": ("--old, --new build folders", "stdout", "their simulate, simgrid_replay"),
    "bench/memory_fit.py": ("--scene, --platform", "stdout", "--simulate"),
    "bench/parallel_bench.sh": ("scene3", "stdout", "build/simulate"),
    "bench/speed_report.py": ("--old build folder", "bench/measured/", "simulate of both builds"),
}

PAGE = "docs/threat-model.md"


def page_rows(root):
    """The rows of docs/threat-model.md's table: every program COVERED lists, with SURFACE's
    reads, writes and runs and the tests that try it (or why none does)."""
    tried = sum(not isinstance(t, str) for t in COVERED.values())
    rows = [f"{len(COVERED)} programs and scripts: {tried} tried by the tests named, "
            f"{len(COVERED) - tried} open with why.", "",
            "| program | reads | writes | runs | tried by |", "|---|---|---|---|---|"]
    for program, tests in COVERED.items():
        reads, writes, runs = SURFACE[program]
        tried = (tests if isinstance(tests, str) else
                 ", ".join(f"`tests/{t}`" for t in tests))
        rows.append(f"| `{program}` | {reads} | {writes} | {runs} | {tried} |".replace("\n", " "))
    return rows


def page_text(root):
    """docs/threat-model.md as it should be: its text with the table between the markers."""
    text = (root / PAGE).read_text()
    begin, end = "<!-- programs begin -->\n", "<!-- programs end -->"
    if text.count(begin) != 1 or text.count(end) != 1:
        raise SystemExit(f"{PAGE}: needs one '{begin.strip()}' and one '{end}'")
    start = text.index(begin) + len(begin)
    return text[:start] + "\n".join(page_rows(root)) + "\n" + text[text.index(end):]


def shipped(root):
    """Every program the repository ships, by the rule of the module's doc."""
    cmake = (root / "CMakeLists.txt").read_text()
    programs = {name for name in re.findall(r"add_executable\((\w+)", cmake)
                if name not in ("unit_tests", "simulate_server")}
    listed = subprocess.run(["git", "-C", str(root), "ls-files", "-s"], capture_output=True,
                            text=True, check=True).stdout.splitlines()
    for line in listed:
        mode, _, _, path = line.split(None, 3)
        if path.startswith("tests/") or not (root / path).is_file():
            continue
        with open(root / path, "rb") as stream:
            bang = stream.read(2) == b"#!"
        if mode == "100755" or bang:
            programs.add("simulate (wrapper)" if path == "simulate" else path)
    programs.add("tests/slurm_cluster.sh")
    return programs


def problems(root):
    found = shipped(root)
    out = [f"{p}: shipped, not listed in tests/robustness/executables.py (add it with the tests "
           "that try it, or as open with why)" for p in sorted(found - set(COVERED))]
    out += [f"{p}: listed, no longer shipped" for p in sorted(set(COVERED) - found)]
    out += [f"{p}: listed, with no reads, writes and runs in SURFACE (docs/threat-model.md)"
            for p in sorted(set(COVERED) - set(SURFACE))]
    out += [f"{p}: in SURFACE, not in COVERED" for p in sorted(set(SURFACE) - set(COVERED))]
    if not out and page_text(root) != (root / PAGE).read_text():
        out.append(f"{PAGE}: its table differs from tests/robustness/executables.py; run: "
                   f"/usr/bin/python3 tests/robustness/executables.py --page")
    for program, tests in sorted(COVERED.items()):
        if isinstance(tests, str):
            if not tests.startswith("open: "):
                out.append(f"{program}: neither tests nor \"open: why\"")
            continue
        name = program.split(" ")[0]
        words = {name, Path(name).name, Path(name).stem}
        for test in tests:
            path = root / "tests" / test
            if not path.is_file():
                out.append(f"{program}: its test tests/{test} does not exist")
            elif not any(word in path.read_text(errors="replace") for word in words):
                out.append(f"{program}: tests/{test} does not name it")
    return out


if __name__ == "__main__":
    if any(a in ("-h", "--help") for a in sys.argv[1:]):
        print("usage: " + __doc__.split("usage:", 1)[1].strip())
        sys.exit(0)
    arguments = [a for a in sys.argv[1:] if a != "--page"]
    root = Path(arguments[0] if arguments else Path(__file__).resolve().parents[2])
    if "--page" in sys.argv[1:]:
        (root / PAGE).write_text(page_text(root))
        print(f"wrote the table of {PAGE}")
        sys.exit(0)
    found = problems(root)
    for line in found:
        print("FAIL " + line)
    covered = sum(not isinstance(t, str) for t in COVERED.values())
    print(f"{len(COVERED)} programs shipped: {covered} tried by tests, {len(COVERED) - covered} open")
    sys.exit(1 if found else 0)
