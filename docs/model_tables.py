#!/usr/bin/python3
"""Writes the cost-model tables of docs/model.md from platforms/cost_model.json.

    /usr/bin/python3 docs/model_tables.py          # rewrites the tables in docs/model.md
    /usr/bin/python3 docs/model_tables.py --check  # exit 1 if docs/model.md is not up to date

The JSON is the one description of every parameter: its value, unit, `doc` (what one counted
operation or one record is) and `source` (how the value was obtained). The tables go between
the marker comments

    <!-- model-tables:NAME begin ... -->  ...  <!-- model-tables:NAME end -->

for NAME `flops` (flops per counted operation) and `sizes` (modeled bytes); everything else
in docs/model.md is left as it is. The counter of each flops parameter (its name in a result
file's `counts`) is read from the X-macro lists of the simulator (NCUBE_WORK_COUNTERS,
NCUBE_RENDER_COUNTERS), wherever under src/ they live. Python 3 standard library only.
"""

import argparse
import json
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
COST_MODEL = ROOT / "platforms" / "cost_model.json"
MODEL_DOC = ROOT / "docs" / "model.md"
SOURCES = ROOT / "src"

# Where a counter list's counts appear in a result file (docs/result-format.md).
COUNTER_LISTS = {"NCUBE_WORK_COUNTERS": "counts", "NCUBE_HEMICUBE_COUNTERS": "counts",
                 "NCUBE_HOST_WORK_COUNTERS": "counts",
                 "NCUBE_RENDER_COUNTERS": "render.counts"}


class Problem(Exception):
    pass


def counters_by_parameter():
    """{flops parameter: result-file path of its counter}, from the X-macro lists."""
    found = {}
    seen_lists = set()
    define = re.compile(r"#define\s+(NCUBE_\w+_COUNTERS)\(X\)((?:[^\n]*\\\n)*[^\n]*)")
    entry = re.compile(r"X\(\s*(\w+)\s*,\s*(flops_per_\w+)\s*,")
    for header in sorted(SOURCES.rglob("*.h")):
        for name, body in define.findall(header.read_text(encoding="utf-8")):
            if name not in COUNTER_LISTS:
                continue
            seen_lists.add(name)
            for counter, parameter in entry.findall(body):
                found[parameter] = "%s.%s" % (COUNTER_LISTS[name], counter)
    missing = sorted(set(COUNTER_LISTS) - seen_lists)
    if missing:
        raise Problem("no #define of %s under src/" % ", ".join(missing))
    return found


def cell(text):
    """A table cell: one line, no column separator."""
    return " ".join(str(text).split()).replace("|", "\\|")


def number(value):
    return json.dumps(value)


def flops_table(parameters, counters):
    rows = ["| parameter | counted operation (result file) | flops | what one operation is | "
            "source of the value |",
            "|---|---|--:|---|---|"]
    for name, p in parameters.items():
        if p["unit"] != "flop":
            continue
        if name not in counters:
            raise Problem("%s has no counter in NCUBE_WORK_COUNTERS or NCUBE_RENDER_COUNTERS"
                          % name)
        value = number(p["value"])
        if p["source"].startswith("fitted"):
            value = "**%s** (fitted)" % value
        rows.append("| `%s` | `%s` | %s | %s | %s |" % (
            name, counters[name], value, cell(p["doc"]), cell(p["source"])))
    unused = sorted(set(counters) - {n for n, p in parameters.items() if p["unit"] == "flop"})
    if unused:
        raise Problem("counters without a flops parameter in cost_model.json: %s"
                      % ", ".join(unused))
    return rows


def sizes_table(parameters):
    rows = ["| parameter | bytes | what it is | layout (source of the value) |",
            "|---|--:|---|---|"]
    for name, p in parameters.items():
        if p["unit"] != "byte":
            continue
        rows.append("| `%s` | %s | %s | %s |" % (name, number(p["value"]), cell(p["doc"]),
                                                 cell(p["source"])))
    return rows


def tables():
    with open(COST_MODEL, encoding="utf-8") as f:
        parameters = json.load(f)["parameters"]
    other = sorted(n for n, p in parameters.items() if p.get("unit") not in ("flop", "byte"))
    if other:
        raise Problem("parameters neither in flop nor in byte: %s" % ", ".join(other))
    for name, p in parameters.items():
        for key in ("doc", "source"):
            if not str(p.get(key, "")).strip():
                raise Problem("%s has no %s" % (name, key))
    return {"flops": flops_table(parameters, counters_by_parameter()),
            "sizes": sizes_table(parameters)}


def rewritten(text, generated, tag="model-tables", document="docs/model.md"):
    """`text` with the rows of each generated table between its marker comments
    (docs/options_table.py uses it too, with its own tag and document)."""
    for name, rows in generated.items():
        begin = re.compile(r"<!-- %s:%s begin[^>]*-->\n" % (tag, name))
        end = "<!-- %s:%s end -->" % (tag, name)
        found = list(begin.finditer(text))
        if len(found) != 1 or text.count(end) != 1:
            raise Problem("%s needs exactly one '<!-- %s:%s begin -->' and one '%s'"
                          % (document, tag, name, end))
        start = found[0].end()
        stop = text.index(end, start) if end in text[start:] else -1
        if stop < 0:
            raise Problem("%s: '%s' comes before its begin marker" % (document, end))
        text = text[:start] + "\n".join(rows) + "\n" + text[stop:]
    return text


def generate(script, document, what, source, rewrite):
    """The command line of a table generator: `rewrite()` gives the document's current and
    wanted text; --check compares them (exit 1 when they differ), else the document is
    rewritten. docs/options_table.py uses it too."""
    parser = argparse.ArgumentParser(description="Writes %s of %s from %s." % (what, document, source))
    parser.add_argument("--check", action="store_true",
                        help="do not write: exit 1 if %s differs from %s" % (document, source))
    args = parser.parse_args()
    try:
        current, wanted = rewrite()
    except (Problem, OSError, ValueError, KeyError) as e:
        print("%s: %s" % (script, e), file=sys.stderr)
        return 2
    if args.check:
        if wanted != current:
            print("%s: %s disagree with %s; run: /usr/bin/python3 %s" % (document, what, source, script),
                  file=sys.stderr)
            return 1
        print("%s: %s agree with %s" % (document, what, source))
        return 0
    if wanted != current:
        (ROOT / document).write_text(wanted, encoding="utf-8")
        print("wrote %s of %s" % (what, document))
    return 0


def main():
    def rewrite():
        current = MODEL_DOC.read_text(encoding="utf-8")
        return current, rewritten(current, tables())
    return generate("docs/model_tables.py", "docs/model.md", "the cost-model tables",
                    "platforms/cost_model.json", rewrite)


if __name__ == "__main__":
    sys.exit(main())
