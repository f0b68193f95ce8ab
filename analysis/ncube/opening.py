"""A results page's opening: what it found, right under its title, before its details.

Every page under analysis/ opens so (README.md, "Results"): three to six sentences, each with its
figure and how sure it is (its interval, or "built into the model" where the result is an input
of the model rather than something it found). The sentences are computed from the page's own
tables, never typed: a page script renders its body, reads its own tables back (tables()), and
its opening(tables) function writes the sentences from them; analysis/openings.py does the same
on a committed page without its results. tests/openings_test.py checks each committed opening
against the page's tables.

    sentence = Sentence("scene2's fastest split is R=64 V=0 (198.2 s)", "one deterministic run")
    text = with_opening(body, [sentence, ...], "analysis/report.py")
"""
import re
from dataclasses import dataclass

HEADING = "**What was found**"
END = "<!-- end of the opening -->"


@dataclass
class Sentence:
    text: str      # the finding with its figure, no final full stop
    sureness: str  # its interval, or why it has none ("built into the model: ...")


def render(sentences, script):
    """The opening's lines: a heading line, one numbered line a sentence, an end mark."""
    if not 3 <= len(sentences) <= 6:
        raise ValueError(f"an opening has three to six sentences, not {len(sentences)}")
    lines = [f"{HEADING} (written by `{script}` from this page's own tables; how sure each is "
             "follows it in italics):", ""]
    lines += [f"{i}. {s.text}. *{s.sureness}.*" for i, s in enumerate(sentences, 1)]
    return lines + ["", END, ""]


def split(text):
    """(title lines, opening lines, the rest) of a page; the opening empty when it has none."""
    lines = text.split("\n")
    if not lines or not lines[0].startswith("# "):
        raise ValueError("a page starts with its title, '# ...'")
    title, rest = lines[:2], lines[2:]
    if rest and rest[0].startswith(HEADING) and END in rest:
        end = rest.index(END) + 2   # the mark and the blank line after it
        return title, rest[:end], rest[end:]
    return title, [], rest


def with_opening(text, sentences, script):
    """The page with its opening (replacing the one it has) right under its title."""
    title, _, rest = split(text)
    return "\n".join(title + render(sentences, script) + rest)


def sentences_of(text):
    """The numbered sentences of a page's opening, as written."""
    _, opening, _ = split(text)
    return [line.split(". ", 1)[1] for line in opening if re.match(r"^\d+\. ", line)]


def tables(text):
    """Every markdown table of a page after its opening, in order: (label, rows), rows a list of
    {column header: cell text}; the label is the nearest heading or bold line above the table
    ("## 1. Seconds per iteration", "**scene2, brute-force**")."""
    _, _, rest = split(text)
    found, label, i = [], "", 0
    while i < len(rest):
        line = rest[i]
        if line.startswith("#") or (line.startswith("**") and line.rstrip().endswith("**")):
            label = line.strip("#* ").strip()
        if line.startswith("|") and i + 1 < len(rest) and re.match(r"^\|[-:| ]+\|$", rest[i + 1]):
            header = cells(line)
            # A repeated header ("still outside" after two fits) gets its place: "still outside 2".
            header = [h if header[:i].count(h) == 0 else f"{h} {header[:i].count(h) + 1}"
                      for i, h in enumerate(header)]
            rows, i = [], i + 2
            while i < len(rest) and rest[i].startswith("|"):
                rows.append(dict(zip(header, cells(rest[i]))))
                i += 1
            found.append((label, rows))
            continue
        i += 1
    return found


def cells(line):
    """A table row's cells. A separating bar has a space (or the line's end) on both sides, so
    the bars of "median |error|" stay in their cell."""
    return [c.strip() for c in re.split(r"(?:^|(?<=\s))\|(?=\s|$)", line.strip())[1:-1]]


def table(found, label_start, column=None):
    """The rows of the first table whose label starts with label_start (and that has `column`)."""
    for label, rows in found:
        if label.startswith(label_start) and rows and (column is None or column in rows[0]):
            return rows
    raise KeyError(f"no table under '{label_start}'" + (f" with column '{column}'" if column else ""))


def number(text):
    """The first number in a cell ("2,728.00", "**14.5**", "13.1 %", "0.0 %"), or None."""
    match = re.search(r"-?\d[\d,]*(?:\.\d+)?(?:e[-+]?\d+)?", text.replace("\u2212", "-"))
    return float(match.group(0).replace(",", "")) if match else None
