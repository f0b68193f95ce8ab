"""Formatting of the paper report: seconds, percentages, megabytes, Markdown tables."""
from pathlib import Path

from ..paths import ROOT

MB = 2 ** 20


def seconds(value):
    if value is None:
        return "–"
    if value >= 100:
        return f"{value:.0f}"
    if value >= 10:
        return f"{value:.1f}"
    return f"{value:.2f}"


def percent(fraction, signed=True, digits=1):
    if fraction is None:
        return "–"
    value = round(100 * fraction, digits) + 0.0   # + 0.0: no "-0.0"
    return f"{value:+.{digits}f} %" if signed else f"{value:.{digits}f} %"


def megabytes(count):
    return f"{count / MB:.2f} MB"


def out_of_memory_text(oom):
    return (f"out of memory (node {oom['node']}, {oom['role']}, needs "
            f"{megabytes(oom['needed_bytes'])} of {megabytes(oom['available_bytes'])})")


def markdown_table(header, rows, align=None):
    align = align or ["---"] * len(header)
    lines = ["| " + " | ".join(header) + " |", "|" + "|".join(align) + "|"]
    lines += ["| " + " | ".join(str(item) for item in row) + " |" for row in rows]
    return "\n".join(lines)


def relative(path):
    try:
        return str(Path(path).resolve().relative_to(ROOT))
    except ValueError:
        return str(path)
