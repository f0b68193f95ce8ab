"""Every ./simulate option a sweep may set (docs/cli.md): its flag, its default and the field of
the result file that records it. The one place the ./simulate command line is assembled."""
import math
from dataclasses import dataclass


@dataclass(frozen=True)
class Option:
    flag: str
    kind: type           # int, float, str or bool (bool: a flag without value)
    default: object
    config_field: str    # where the result file records it ("config" object)
    check: object = None  # value -> error text or None
    doc: str = ""


def _at_least(low):
    return lambda v: None if v >= low else f"must be at least {low}"


def _samples(v):
    root = math.isqrt(v) if v > 0 else 0
    return None if 1 <= v <= 64 and root * root == v else "must be a perfect square from 1 to 64"


def _fraction(v):
    return None if 0 < v < 1 and math.isfinite(v) else "must be between 0 and 1 (exclusive)"


def _one_of(*values):
    return lambda v: None if v in values else "must be " + " or ".join(values)


def _ray_test(v):
    return None if v in ("all", "first-blocker") else "must be all or first-blocker"


OPTIONS = {
    "R": Option("--R", int, 1, "R", _at_least(1), "radiosity processors"),
    "V": Option("--V", int, 0, "V", _at_least(0), "visibility processors per radiosity processor"),
    "samples": Option("--samples", int, 64, "samples", _samples, "parts of the shooter"),
    "iterations": Option("--iterations", int, -1, "max_iterations", _at_least(-1),
                         "stop after N shots (-1: until converged)"),
    "convergence": Option("--convergence", float, 1e-4, "convergence_fraction", _fraction,
                          "converged below this fraction of the emitted power"),
    "ray_test": Option("--ray-test", str, "all", "ray_test", _ray_test, "all or first-blocker"),
    "visibility": Option("--visibility", str, "brute-force", "visibility",
                         _one_of("brute-force", "octree"), "brute-force or octree (section 6)"),
    "skip_facing_away": Option("--skip-facing-away", bool, False, "skip_facing_away"),
    "block_size": Option("--block-size", int, 100, "block_size", _at_least(1),
                         "visibility points per message"),
    "pipelined": Option("--pipelined", bool, False, "pipelined"),
    "unlimited_memory": Option("--unlimited-memory", bool, False, "memory_cap"),
    # Adaptive subdivision and load balancing (sections 4.1, 4.2).
    "subdivide": Option("--subdivide", bool, False, "subdivide"),
    "subdivide_contrast": Option("--subdivide-contrast", float, 0.5, "subdivide_contrast",
                                 _fraction, "cut above this corner contrast"),
    "subdivide_max_level": Option("--subdivide-max-level", int, 3, "subdivide_max_level",
                                  _at_least(0), "deepest element level"),
    "subdivide_min_area": Option("--subdivide-min-area", float, 0.0, "subdivide_min_area", None,
                                 "smallest element area"),
    "balance": Option("--balance", bool, False, "balance"),
    "balance_threshold": Option("--balance-threshold", float, 0.2, "balance_threshold", None,
                                "significantly more than the mean: (1 + this) x"),
    # The rendering phase (section 2.3).
    "render_parallel": Option("--render-parallel", str, "off", "render_parallel",
                              _one_of("off", "blocks", "scanlines"), "off, blocks or scanlines"),
    "render_distribution": Option("--render-distribution", str, "hypercube",
                                  "render_distribution", _one_of("ring", "hypercube"),
                                  "ring or hypercube"),
    "image_width": Option("--image-width", int, 800, "image_width", _at_least(16),
                          "picture width (the rendering phase)"),
    "image_height": Option("--image-height", int, 600, "image_height", _at_least(16),
                           "picture height (the rendering phase)"),
    "outline_elements": Option("--outline-elements", bool, False, "outline_elements", None,
                               "draw the element edges in the picture"),
}
# Not options of a cell's configuration but of how it is run or what it writes.
FILE_OPTIONS = ("platform", "cost_model")
OTHER_CELL_KEYS = ("cfg", "trace")


def type_error(option, value):
    """Error text when `value` is not of the option's type (bool is not an int here)."""
    if option.kind is bool:
        return None if isinstance(value, bool) else "must be true or false"
    if option.kind is int:
        return None if isinstance(value, int) and not isinstance(value, bool) else "must be a whole number"
    if option.kind is float:
        ok = isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)
        return None if ok else "must be a number"
    return None if isinstance(value, str) else "must be a string"


def complete(options):
    """Every option with its value: the given ones, the defaults for the others."""
    return {name: options.get(name, option.default) for name, option in OPTIONS.items()}


def config_fields(options):
    """What the result file's "config" records for these options."""
    full = complete(options)
    fields = {}
    for name, option in OPTIONS.items():
        value = full[name]
        fields[option.config_field] = (not value) if name == "unlimited_memory" else value
    return fields


def command(simulate, scene, options, platform=None, cost_model=None, cfg=None, json_out=None,
            trace_out=None, quiet=True, threads=1):
    """The ./simulate command line: every option written out, defaults included, so that the
    command says the whole configuration. `threads`: host threads of the run (not part of the
    configuration: results do not depend on it); 1 for sweeps, which run a cell per core."""
    args = [str(simulate), str(scene)]
    for name, value in complete(options).items():
        option = OPTIONS[name]
        if value is None:
            continue
        if option.kind is bool:
            args += [option.flag] if value else []
        else:
            args += [option.flag, repr(value) if option.kind is float else str(value)]
    if platform:
        args += ["--platform", str(platform)]
    if cost_model:
        args += ["--cost-model", str(cost_model)]
    for name, value in sorted((cfg or {}).items()):
        args.append(f"--cfg={name}:{value}")
    if json_out:
        args += ["--json", str(json_out)]
    if trace_out:
        args += ["--trace", str(trace_out)]
    if quiet:
        args.append("--quiet")
    return args + ["--threads", str(threads)]
