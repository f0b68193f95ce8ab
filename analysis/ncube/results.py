"""Result files (docs/result-format.md): reading them, the measures a sweep reports, and
whether a result file is a finished result of a given cell."""

from . import input_file

SCHEMA_VERSION = 2
FINISHED = ("ok", "out_of_memory")   # out of memory is a finished cell too

# The measures a sweep may name. "seconds_per_iteration" is the simulator's own figure (the one
# definition, src/simulation/iteration_time.h: the mean of the first 20 iterations, or of all
# when fewer ran); "total_seconds" is the simulated time from the start to the end of the run.
MEASURES = {
    "seconds_per_iteration": "mean simulated seconds of the first 20 iterations (all, when fewer ran)",
    "total_seconds": "simulated seconds from the start to the end of the run",
}


# A result file holds every patch's radiosity (a few MiB for the largest scenes); a trace every
# event of a run (hundreds of MiB for long ones): far below these, which bound what a bad file
# (a device, an endless link) costs.
RESULT_FILE_BYTES = input_file.SCENE_FILE_BYTES
TRACE_FILE_BYTES = 1 << 30


def read(path):
    """The result file as a dict, None when it is missing, not a regular file within its limit,
    or not strict JSON (ncube.input_file's gate: never a hang on a FIFO, never a device read
    whole, no NaN). A file read counts as an input of this process (ncube.input_file.protect):
    no page is written onto it."""
    try:
        result = input_file.read_json(path, "result file", RESULT_FILE_BYTES)
    except input_file.InputFileError:
        return None
    return result


def measure(result, name):
    """The sweep's measure of a result, None without a value (out of memory, no iteration)."""
    if result is None or result.get("status") != "ok":
        return None
    if name == "seconds_per_iteration":
        return result["seconds_per_iteration"]
    if name == "total_seconds":
        return result["simulated_seconds"]
    raise ValueError(f"unknown measure {name!r}")


def mismatch(result, cell):
    """Why `result` is not a finished result of `cell` (a ncube.sweep.Cell), None when it is."""
    if not isinstance(result, dict):
        return "not a result file"
    provenance = result.get("provenance")
    if result.get("schema_version") != SCHEMA_VERSION or not isinstance(provenance, dict):
        return f"schema version {result.get('schema_version')!r}, expected {SCHEMA_VERSION}"
    if result.get("status") not in FINISHED:
        return f"status {result.get('status')!r}"
    for item, expected in (("scene", cell.scene_sha256), ("platform", cell.platform_sha256),
                           ("cost_model", cell.cost_model_sha256)):
        got = (provenance.get(item) or {}).get("sha256")
        if got != expected:
            return f"{item} content {got} differs from the cell's {expected}"
    config = result.get("config", {})
    for name, value in cell.config_fields().items():
        if config.get(name) != value:
            return f"config {name} = {config.get(name)!r}, the cell has {value!r}"
    used = provenance.get("platform", {}).get("simgrid_config", {})
    for name, value in cell.cfg.items():
        if used.get(name) != str(value):
            return f"SimGrid setting {name} = {used.get(name)!r}, the cell has {value!r}"
    needed = ("iterations", "simulated_seconds", "seconds_per_iteration", "nodes", "counts")
    missing = [key for key in needed if key not in result]
    if missing:
        return f"incomplete: no {', '.join(missing)}"
    return None


def trace_mismatch(path):
    """Why the trace file is not complete, None when it is."""
    try:
        trace = input_file.read_json(path, "trace file", TRACE_FILE_BYTES)
    except input_file.InputFileError:
        return "trace missing or not JSON"
    return None if isinstance(trace, dict) and "traceEvents" in trace else "not a trace-event file"
