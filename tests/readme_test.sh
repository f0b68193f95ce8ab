#!/usr/bin/env bash
# Docs that keep up (issue 39 item 4), checked against the code and the tree:
# * README.md names every option of `./simulate --describe-options` (its capability lines),
#   every option group `--help` shows, every page analysis/*.md, and the things a newcomer must
#   find (listed below); its layout table lists every top-level folder and every src/ folder;
# * docs/sweeps.md's key table has a row for every option a sweep may set (ncube.options, read
#   from --describe-options' description);
# * docs/figures.md names every picture in the repository, every file it names exists, and
#   every row of its tables has its table's columns;
# * no doc cites a file outside the repository. About 2 s.
simulate=$1 root=$2
"$simulate" --describe-options > /tmp/readme_test.$$.json || { echo "FAIL: --describe-options"; exit 1; }
"$simulate" --help > /tmp/readme_test.$$.help || { echo "FAIL: --help"; exit 1; }
trap 'rm -f /tmp/readme_test.$$.json /tmp/readme_test.$$.help' EXIT
/usr/bin/python3 - "$root" /tmp/readme_test.$$.json /tmp/readme_test.$$.help <<'PY'
import json, re, subprocess, sys
from pathlib import Path
root, described, help_text = Path(sys.argv[1]), json.loads(Path(sys.argv[2]).read_text()), Path(sys.argv[3]).read_text()
sys.path.insert(0, str(root / "analysis"))
from ncube import options as opts
failures = []
readme = (root / "README.md").read_text()

# Every option, by its flag as written (`--subdivide` does not count for `--subdivide-contrast`).
for option in described:
    flag = option["flag"]
    if flag.startswith("--") and not re.search(re.escape(flag) + r"(?![\w-])", readme):
        failures.append(f"README.md does not name {flag}")
# Option groups of --help (CLI11 prints each group's name as a heading line).
for heading in re.findall(r"^([A-Z][^\n:]*):$", help_text, re.M):
    if heading not in ("Positionals", "Options") and heading not in readme:
        failures.append(f"README.md does not name the option group {heading!r} of --help")
for page in sorted((root / "analysis").glob("*.md")):
    if f"analysis/{page.name}" not in readme:
        failures.append(f"README.md does not name analysis/{page.name}")
for thing in ("--form-factors hemicube", "--parallelisation shooters", "platforms/machines/",
              "analysis/claims.md", "analysis/machines.md", "docs/accuracy.md", "docs/machines/",
              "tests/slurm_cluster.sh start", "ctest --test-dir build -L quick"):
    if thing not in readme:
        failures.append(f"README.md does not name {thing}")
# The layout table: every top-level folder and every folder of src/.
layout = readme.split("## Layout", 1)[-1]
rows = {m.group(1).rstrip("/") for m in re.finditer(r"^\| `([^`]+)` \|", layout, re.M)}
tracked = subprocess.run(["git", "-C", str(root), "ls-files"], capture_output=True, text=True).stdout.split()
folders = {f.split("/")[0] for f in tracked if "/" in f}
folders |= {"/".join(f.split("/")[:2]) for f in tracked if f.startswith("src/") and f.count("/") >= 2}
folders.discard("src")   # its folders have rows of their own
for folder in sorted(folders - rows):
    failures.append(f"README.md's layout table has no row for {folder}/")

# docs/sweeps.md: a row for every cell key a sweep may set.
sweeps = (root / "docs" / "sweeps.md").read_text()
table = "\n".join(line for line in sweeps.splitlines() if line.startswith("| `"))
first_cells = " ".join(line.split("|")[1] for line in table.splitlines())
for key in opts.OPTIONS:
    if f"`{key}`" not in first_cells:
        failures.append(f"docs/sweeps.md's key table has no row for `{key}` (--describe-options)")

# docs/figures.md against the figures on disk.
figures = (root / "docs" / "figures.md").read_text()
for png in sorted(f for f in tracked if f.endswith(".png")):
    if Path(png).name not in figures:
        failures.append(f"docs/figures.md does not name {png}")
for named in sorted(set(re.findall(r"`((?:analysis|docs|platforms|scenes|experiments|bench)/[\w./-]+\.(?:png|md|json|py|yaml))`", figures))):
    if not (root / named).exists():
        failures.append(f"docs/figures.md names {named}, which does not exist")
columns = None
for line in figures.splitlines():
    if not line.startswith("|"):
        columns = None
        continue
    cells = len(re.split(r"(?<!\\)\|", line.replace("\\|", ""))) - 2
    if columns is None:
        columns = cells
    elif cells != columns:
        failures.append(f"docs/figures.md: a row of {cells} columns in a table of {columns}: {line[:80]}")

# No doc cites a file outside the repository (paths in the docs are from the repository's root).
docs = [root / "README.md"] + sorted((root / "docs").rglob("*.md")) + sorted((root / "analysis").glob("*.md"))
all_folders = {str(Path(f).parent) for f in tracked}
for doc in docs:
    text = doc.read_text()
    for match in re.finditer(r"(/work/[\w./-]+|(?<![\w./])\.\./[\w./-]+|shared/notes[\w./-]*)", text):
        path = match.group(1)
        # A relative path may be read from any folder of the repository (a sweep file's
        # `../../platforms/...`): it cites outside when it leaves the repository from all.
        inside = any((root / folder / path).resolve().is_relative_to(root.resolve())
                     for folder in all_folders)
        if path.startswith("/work/") or "shared/notes" in path or not inside:
            failures.append(f"{doc.relative_to(root)} cites {path}, outside the repository")

for failure in failures:
    print("FAIL:", failure)
print("readme_test: passed" if not failures else f"readme_test: {len(failures)} failure(s)")
sys.exit(1 if failures else 0)
PY
