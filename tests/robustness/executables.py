#!/usr/bin/python3
"""Every program and script the repository ships, and the tests that try it as a user would
(tests/shipped_executables_test.sh). Shipped means: a target of CMakeLists.txt's
add_executable (but the test binary), or a tracked file outside tests/ that is executable or
starts with "#!"; tests/slurm_cluster.sh too, which users run. A new one fails the test until it
is listed here with the tests that try it (each must name it), or as open with why.

usage: executables.py ROOT   (prints what is shipped and not listed, listed and gone, and
                              listed tests that do not name their program; exit 1 if any)"""
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
    "analysis/openings.py": ["page_scripts_test.sh"],
    "analysis/headline.py": "open: 45 what-if runs of ./simulate (about 5 minutes), run by hand; its committed analysis/headline.json is checked by openings_test.py",
    "platforms/generate.py": ["page_scripts_test.sh", "platforms_reproducible_test.sh"],
    "platforms/machines/generate.py": ["page_scripts_test.sh", "machines_platforms_test.sh"],
    "scenes/generate.py": ["page_scripts_test.sh", "scenes_reproducible_test.sh"],
    # Benchmarks: minutes of runs, outside the suite.
    "bench/hypercube_scale.py": "open: a benchmark (minutes), run by hand",
    "bench/long_runs.py": ["embree_floor_test.sh", "simgrid_replay_test.sh"],
    "bench/memory_fit.py": "open: a benchmark (minutes), run by hand",
    "bench/parallel_bench.sh": "open: a benchmark (minutes), run by hand",
    "bench/speed_report.py": "open: a benchmark's report, run by hand",
}


def shipped(root):
    """Every program the repository ships, by the rule of the module's doc."""
    cmake = (root / "CMakeLists.txt").read_text()
    programs = {name for name in re.findall(r"add_executable\((\w+)", cmake) if name != "unit_tests"}
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
    root = Path(sys.argv[1] if len(sys.argv) > 1 else Path(__file__).resolve().parents[2])
    found = problems(root)
    for line in found:
        print("FAIL " + line)
    covered = sum(not isinstance(t, str) for t in COVERED.values())
    print(f"{len(COVERED)} programs shipped: {covered} tried by tests, {len(COVERED) - covered} open")
    sys.exit(1 if found else 0)
