"""Every ./simulate option a sweep may set (docs/cli.md): its flag, its default and the field of
the result file that records it. The one place the ./simulate command line is assembled.

The options, their defaults and ranges are not written here: they are read from
simulate_options.json, which is what `./simulate --describe-options` prints (regenerate it with
`build/simulate --describe-options > analysis/ncube/simulate_options.json`;
tests/options_description_test.sh fails when the two differ)."""
import json
import math
from dataclasses import dataclass
from pathlib import Path

DESCRIPTION = Path(__file__).resolve().parent / "simulate_options.json"


@dataclass(frozen=True)
class Option:
    flag: str
    kind: type           # int, float, str or bool (bool: a flag without value)
    default: object
    config_field: str    # where the result file records it ("config" object)
    check: object = None  # value -> error text or None
    doc: str = ""
    # {option: value}: the result file records the field only when those options have those
    # values (the hemicube's options: hemicube runs only, so the paper's runs keep their files);
    # a list of values: any of them (the shooter-centred parallelisations)
    recorded_when: object = None
    # Whether it shapes the rays (--visibility, --ray-test, --samples): a form-factor method
    # that traces no rays leaves it at its default.
    shapes_rays: bool = False

    def recorded(self, options):
        """Whether the result file records this option's field for these (complete) options."""
        return not self.recorded_when or all(
            options[k] in (v if isinstance(v, list) else [v])
            for k, v in self.recorded_when.items())


def _show(value):
    return f"{value:g}" if isinstance(value, float) else str(value)


def _range_check(described):
    """The range of a described option as a check: the same ends, included or not, as the
    parser of ./simulate (src/tools/option_table.cpp)."""
    low, high = described["low"], described["high"]
    low_in, high_in = described["low_included"], described["high_included"]
    words = (("from " if low_in else "above ") + _show(low) +
             (" to " if high_in else " and below ") + _show(high))

    def check(value):
        above = value >= low if low_in else value > low
        below = value <= high if high_in else value < high
        return None if above and below else "must be " + words
    return check


def _square_check(value):
    root = math.isqrt(value) if value > 0 else 0
    return None if root * root == value else "must be a perfect square"


def _even_check(value):
    return None if value % 2 == 0 else "must be even"


def _both(first, second):
    return lambda value: first(value) or second(value)


def _choice_check(values):
    return lambda v: None if v in values else "must be " + " or ".join(values)


_KINDS = {"integer": int, "number": float, "choice": str, "flag": bool}


def _option(described):
    kind = _KINDS[described["kind"]]
    check = None
    if "range" in described:
        check = _range_check(described["range"])
    if described.get("perfect_square"):
        check = _both(check, _square_check)
    if described.get("even"):
        check = _both(check, _even_check)
    if "values" in described:
        check = _choice_check(described["values"])
    default = described["default"]
    return Option(described["flag"], kind, float(default) if kind is float else default,
                  described["field"], check, described["help"], described.get("recorded_when"),
                  bool(described.get("shapes_rays")))


def _load():
    """The options a sweep cell may set: those the result file's "config" records."""
    described = json.loads(DESCRIPTION.read_text())
    return {d["flag"][2:].replace("-", "_"): _option(d) for d in described
            if "field" in d and d["kind"] in _KINDS}


OPTIONS = _load()
# The options that shape the rays, which a form-factor method that traces none leaves alone.
RAY_OPTIONS = tuple(name for name, option in OPTIONS.items() if option.shapes_rays)
# What the method registry says of each form-factor method (src/radiosity/form_factor_methods.h,
# exported under --form-factors' "methods"): {name: {"visibility_processors": whether it is
# defined with V > 0, "reason": why not, "traces_rays": ..., "options": its own options}}.
FORM_FACTOR_METHODS = next(d for d in json.loads(DESCRIPTION.read_text())
                           if d["flag"] == "--form-factors")["methods"]
# --threads is no part of a cell's configuration (results do not depend on it), but the command
# line still has to hold a value ./simulate takes: the same range, from the same description.
_THREADS_CHECK = _range_check(next(d for d in json.loads(DESCRIPTION.read_text())
                                   if d["flag"] == "--threads")["range"])
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
        if not option.recorded(full):
            continue
        # --unlimited-memory is recorded inverted, as memory_cap.
        fields[option.config_field] = (not value) if name == "unlimited_memory" else value
    return fields


def command(simulate, scene, options, platform=None, cost_model=None, cfg=None, json_out=None,
            trace_out=None, quiet=True, threads=1):
    """The ./simulate command line: every option written out, defaults included, so that the
    command says the whole configuration. `threads`: host threads of the run (not part of the
    configuration: results do not depend on it); 1 for sweeps, which run a cell per core."""
    error = (None if isinstance(threads, int) and not isinstance(threads, bool)
             else "must be a whole number") or _THREADS_CHECK(threads)
    if error:
        raise ValueError(f"threads: {threads!r} {error}")
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
