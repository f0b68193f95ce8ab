#!/usr/bin/python3
"""Writes the option table of docs/cli.md, and docs/result-format.md's table of the counters
each form-factor method alone counts, from what ./simulate says of its options.

    /usr/bin/python3 docs/options_table.py          # rewrites the table in docs/cli.md
    /usr/bin/python3 docs/options_table.py --check  # exit 1 if docs/cli.md is not up to date

The description is analysis/ncube/simulate_options.json, the output of
`./simulate --describe-options` (src/tools/option_table.cpp registers each option once, with
its default and range, for the parser and the description alike). The table goes between the
marker comments `<!-- options:all begin -->` and `<!-- options:all end -->`; the rest of
docs/cli.md is left as it is. Python 3 standard library only.
"""

import json
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from model_tables import cell, generate, rewritten  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
DESCRIPTION = ROOT / "analysis" / "ncube" / "simulate_options.json"
CLI_DOC = ROOT / "docs" / "cli.md"
RESULT_DOC = ROOT / "docs" / "result-format.md"

PLACEHOLDERS = {"integer": "N", "number": "X", "file": "FILE", "output": "FILE",
                "setting": "SETTING"}


def number(value):
    return "%g" % value if isinstance(value, float) else str(value)


def usage(option):
    flag, kind = option["flag"], option["kind"]
    if option.get("positional"):
        return "`%s`" % flag.upper()
    if kind == "flag":
        return "`%s`" % flag
    if kind == "choice":
        return "`%s %s`" % (flag, "\\|".join(option["values"]))
    if kind == "setting":
        return "`%s=%s`" % (flag, option.get("value_name", PLACEHOLDERS[kind]))
    if kind == "text":
        return "`%s %s`" % (flag, option["value_name"])
    return "`%s %s`" % (flag, PLACEHOLDERS[kind])


def default(option):
    if "default" not in option:
        return "—"
    value = option["default"]
    if isinstance(value, bool):
        return "on" if value else "off"
    if option["kind"] == "file":
        return "`%s`" % value
    return number(value)


def allowed(option):
    if "range" in option:
        r = option["range"]
        text = "%s%s … %s%s" % ("[" if r["low_included"] else "(", number(r["low"]),
                                 number(r["high"]), "]" if r["high_included"] else ")")
        if option.get("perfect_square"):
            text += ", a perfect square"
        if option.get("even"):
            text += ", even"
        if option["kind"] == "number":
            text += ", finite"
        return text
    if "values" in option:
        return ", ".join(option["values"])
    if option["kind"] == "setting":
        return "repeatable"
    if option["kind"] in ("file", "output"):
        return "a file name, not empty"
    return ""


def table(options):
    rows = ["| option | default | allowed | result file `config` | meaning |",
            "|---|---|---|---|---|"]
    for option in options:
        field = "`%s`" % option["field"] if "field" in option else ""
        rows.append("| %s | %s | %s | %s | %s |" % (usage(option), default(option),
                                                   allowed(option), field, cell(option["help"])))
    return rows


def counters_table(options):
    """docs/result-format.md's table of the counters each form-factor method alone counts, from
    the methods' registrations as --form-factors describes them."""
    methods = next(o for o in options if o["flag"] == "--form-factors")["methods"]
    rows = ["| method | counter | what it counts |", "|---|---|---|"]
    for name, rule in methods.items():
        for counter in rule.get("counters", []):
            rows.append("| `%s` | `%s` | %s |" % (name, counter["counter"], cell(counter["counts"])))
    if len(rows) == 2:
        raise ValueError("no form-factor method describes counters of its own")
    return rows


def main():
    def rewrite():
        options = json.loads(DESCRIPTION.read_text(encoding="utf-8"))
        current = CLI_DOC.read_text(encoding="utf-8")
        return current, rewritten(current, {"all": table(options)}, "options", "docs/cli.md")

    def rewrite_counters():
        options = json.loads(DESCRIPTION.read_text(encoding="utf-8"))
        current = RESULT_DOC.read_text(encoding="utf-8")
        return current, rewritten(current, {"methods": counters_table(options)},
                                  "result-counters", "docs/result-format.md")
    status = generate("docs/options_table.py", "docs/cli.md", "the option table",
                      "analysis/ncube/simulate_options.json", rewrite)
    return status or generate("docs/options_table.py", "docs/result-format.md",
                              "the table of each form-factor method's counters",
                              "analysis/ncube/simulate_options.json", rewrite_counters)


if __name__ == "__main__":
    sys.exit(main())
