#!/usr/bin/python3
"""Writes the machine-parameter tables of docs/model.md, docs/platforms.md and
docs/result-format.md from the one list of machine parameters.

    /usr/bin/python3 docs/platform_tables.py          # rewrites the tables
    /usr/bin/python3 docs/platform_tables.py --check  # exit 1 if a table is not up to date

The list is src/machine/machine_parameters.h: NCUBE_MACHINE_PARAMETERS (name, C++ type, unit,
range, whole number, XML form, doc) and NCUBE_NETWORK_MODEL (the SimGrid settings a JSON
platform gets by default). The nCube2's values and their sources come from
platforms/ncube2.json. Each table goes between the marker comments

    <!-- platform-tables:NAME begin ... -->  ...  <!-- platform-tables:NAME end -->

(`machine` and `network` in docs/model.md, `forms` in docs/platforms.md, `values` in
docs/result-format.md); the rest of each document is left as it is. tests/robustness/cases.py
reads the list through `machine_parameters()` too. Python 3 standard library only.
"""

import argparse
import json
import re
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from model_tables import Problem, cell, rewritten  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
LIST = Path("src") / "machine" / "machine_parameters.h"
NCUBE2 = Path("platforms") / "ncube2.json"
TAG = "platform-tables"

# How a SimGrid XML platform file gives a parameter (enum XmlForm), in words.
XML_FORMS = {
    "kInterconnect": "no value: the file's links and routes are the interconnect",
    "kHostSpeed": "the `speed` of every node host",
    "kProperty": "`<prop id=\"NAME\" value=\"…\"/>` of every node host or of its zone",
}


def _macro_body(text, name):
    """The text of `#define name(X)`, its line continuations joined."""
    found = re.search(r"#define\s+%s\(X\)\s*\\\n((?:[^\n]*\\\n)*[^\n]*)" % name, text)
    if not found:
        raise Problem("%s: no '#define %s(X)'" % (LIST, name))
    return found.group(1).replace("\\\n", " ")


def _entries(body):
    """The argument lists of the X(...) entries of a macro body: each argument the literal
    text, adjacent C string literals joined into one Python string."""
    entries, at = [], 0
    while True:
        start = body.find("X(", at)
        if start < 0:
            return entries
        args, current, depth, i = [], [], 0, start + 2
        strings = []
        while True:
            c = body[i]
            if c == '"':
                end = i + 1
                while body[end] != '"':
                    end += 2 if body[end] == "\\" else 1
                strings.append(json.loads(body[i:end + 1]))
                i = end + 1
                continue
            if c == "(":
                depth += 1
            elif c in ",)" and depth == 0:
                args.append("".join(strings) if strings else "".join(current).strip())
                current, strings = [], []
                if c == ")":
                    break
            elif c == ")":
                depth -= 1
            else:
                current.append(c)
            i += 1
        entries.append(args)
        at = i + 1


def _number(literal):
    return float.fromhex(literal) if literal.lower().startswith(("0x", "-0x")) else float(literal)


def machine_parameters(root=ROOT):
    """[{name, type, unit, low, high, whole, xml, doc, low_text, high_text}] in the list's
    order, read from src/machine/machine_parameters.h under `root`."""
    body = _macro_body((Path(root) / LIST).read_text(encoding="utf-8"), "NCUBE_MACHINE_PARAMETERS")
    entries = _entries(body)
    if len(entries) != body.count("X("):
        raise Problem("%s: read %d of the %d entries of NCUBE_MACHINE_PARAMETERS"
                      % (LIST, len(entries), body.count("X(")))
    parameters = []
    for args in entries:
        if len(args) != 8:
            raise Problem("%s: an entry of NCUBE_MACHINE_PARAMETERS has %d fields, not 8: %s"
                          % (LIST, len(args), args[:1]))
        name, ctype, unit, low, high, whole, xml, doc = args
        if xml not in XML_FORMS or whole not in ("true", "false"):
            raise Problem("%s: %s: unknown XML form %r or whole %r" % (LIST, name, xml, whole))
        parameters.append({"name": name, "type": ctype, "unit": unit, "low": _number(low),
                           "high": _number(high), "whole": whole == "true", "xml": xml,
                           "doc": doc, "low_text": low, "high_text": high})
    return parameters


def network_model(root=ROOT):
    """[(SimGrid setting, value, why)] of NCUBE_NETWORK_MODEL."""
    body = _macro_body((Path(root) / LIST).read_text(encoding="utf-8"), "NCUBE_NETWORK_MODEL")
    entries = _entries(body)
    if len(entries) != body.count("X(") or any(len(e) != 3 for e in entries):
        raise Problem("%s: NCUBE_NETWORK_MODEL's entries are not X(setting, value, why)" % LIST)
    return [tuple(e) for e in entries]


def shown(literal):
    """A range end as the C++ list writes it; a hexadecimal power of two as 2^n."""
    value = _number(literal)
    if literal.lower().startswith("0x") and value >= 2 ** 10 and value == 2 ** (int(value).bit_length() - 1):
        return "2^%d" % (int(value).bit_length() - 1)
    return literal


def value_text(value):
    """A machine's value as a reader writes it: 2.5e6, 1e-6, 4194304."""
    if isinstance(value, int) or (value == int(value) and abs(value) < 1e5):
        return str(int(value))
    if value != 0 and (abs(value) >= 1e5 or abs(value) < 1e-3):
        mantissa, exponent = ("%.12e" % value).split("e")
        mantissa = mantissa.rstrip("0").rstrip(".")
        return "%se%d" % (mantissa, int(exponent))
    return "%.12g" % value


def unit_of(p):
    return p["unit"] if p["unit"] else "—"


def accepted(p):
    return "%s … %s%s" % (shown(p["low_text"]), shown(p["high_text"]),
                          ", whole" if p["whole"] else "")


def machine_table(parameters, ncube2):
    rows = ["| parameter | unit | nCube2 | accepted | what it is | source of the nCube2 value |",
            "|---|---|--:|---|---|---|"]
    for p in parameters:
        if p["name"] not in ncube2:
            raise Problem("%s has no parameter %s" % (NCUBE2, p["name"]))
        given = ncube2[p["name"]]
        rows.append("| `%s` | %s | %s | %s | %s | %s |" % (
            p["name"], unit_of(p), value_text(given["value"]), accepted(p), cell(p["doc"]),
            cell(given.get("source", ""))))
    extra = sorted(set(ncube2) - {p["name"] for p in parameters})
    if extra:
        raise Problem("%s has parameters the list does not: %s" % (NCUBE2, ", ".join(extra)))
    return rows


def network_table(settings):
    rows = ["| SimGrid setting | value | why |", "|---|---|---|"]
    rows += ["| `%s` | `%s` | %s |" % (name, value, cell(why)) for name, value, why in settings]
    return rows


def forms_table(parameters):
    rows = ["| parameter | unit | accepted | JSON file (`\"parameters\"`) | SimGrid XML file |",
            "|---|---|---|---|---|"]
    for p in parameters:
        rows.append("| `%s` | %s | %s | `\"%s\": {\"value\": …}` | %s |" % (
            p["name"], unit_of(p), accepted(p), p["name"],
            XML_FORMS[p["xml"]].replace("NAME", p["name"])))
    return rows


def values_table(parameters):
    rows = ["| key | unit | in `json` | in `simgrid-xml` | what it is |", "|---|---|:-:|:-:|---|",
            "| `nodes` | — | yes | yes | the machine's nodes: 2^dimension, or the XML file's hosts "
            "node-0 … node-(n−1) |"]
    for p in parameters:
        rows.append("| `%s` | %s | yes | %s | %s |" % (
            p["name"], unit_of(p), "no" if p["xml"] == "kInterconnect" else "yes", cell(p["doc"])))
    return rows


def documents(root=ROOT):
    """{document: {table name: rows}}."""
    parameters = machine_parameters(root)
    with open(Path(root) / NCUBE2, encoding="utf-8") as f:
        ncube2 = json.load(f)["parameters"]
    return {
        "docs/model.md": {"machine": machine_table(parameters, ncube2),
                          "network": network_table(network_model(root))},
        "docs/platforms.md": {"forms": forms_table(parameters)},
        "docs/result-format.md": {"values": values_table(parameters)},
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--check", action="store_true",
                        help="do not write: exit 1 if a table differs from %s" % LIST)
    args = parser.parse_args()
    try:
        changes = {}
        for document, tables in documents().items():
            current = (ROOT / document).read_text(encoding="utf-8")
            wanted = rewritten(current, tables, tag=TAG, document=document)
            if wanted != current:
                changes[document] = wanted
    except (Problem, OSError, ValueError, KeyError) as e:
        print("docs/platform_tables.py: %s" % e, file=sys.stderr)
        return 2
    if args.check:
        if changes:
            print("%s: the machine-parameter tables disagree with %s; run: /usr/bin/python3 "
                  "docs/platform_tables.py" % (", ".join(changes), LIST), file=sys.stderr)
            return 1
        print("the machine-parameter tables agree with %s" % LIST)
        return 0
    for document, text in changes.items():
        (ROOT / document).write_text(text, encoding="utf-8")
        print("wrote the machine-parameter tables of %s" % document)
    return 0


if __name__ == "__main__":
    sys.exit(main())
