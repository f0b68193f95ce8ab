#!/usr/bin/env bash
# The sweep tool writes its files (result files, plan, summary CSV, plots) by ./simulate's rule
# per kind of path (analysis/ncube/output_file.py, docs/cli.md "Output files"): each kind is
# made in a temporary folder, never in the machine's /dev.
# Usage: bash tests/sweep_output_paths_test.sh <path-to-simulate-binary> <repo-root>
set -euo pipefail
root="${2:-$(cd "$(dirname "$0")/.." && pwd)}"
exec /usr/bin/python3 - "$root" <<'PY'
import os, socket, stat, sys, tempfile, threading
from pathlib import Path
sys.path.insert(0, sys.argv[1] + "/analysis")
from ncube import output_file

problems = []
def expect(condition, what):
    if not condition:
        problems.append(what)

with tempfile.TemporaryDirectory() as work:
    w = Path(work)
    # A new path and a regular file: written, no temporary file left.
    output_file.write(w / "new.csv", "a")
    (w / "old.csv").write_text("old")
    output_file.write(w / "old.csv", "b")
    expect((w / "new.csv").read_text() == "a" and (w / "old.csv").read_text() == "b", "files")
    # A link (relative, to a link) and a dangling link: followed, the links stay.
    (w / "target.csv").write_text("old")
    (w / "link.csv").symlink_to("target.csv")
    (w / "link2.csv").symlink_to(w / "link.csv")
    output_file.write(w / "link2.csv", "via links")
    expect((w / "link.csv").is_symlink() and (w / "link2.csv").is_symlink(), "links replaced")
    expect((w / "target.csv").read_text() == "via links", "link target not written")
    (w / "dangling.csv").symlink_to("made.csv")
    output_file.write(w / "dangling.csv", "made")
    expect((w / "dangling.csv").is_symlink() and (w / "made.csv").read_text() == "made", "dangling")
    # move(): a finished temporary file onto a link: the link stays.
    (w / "done.partial").write_text("moved")
    output_file.move(w / "done.partial", w / "link.csv")
    expect((w / "link.csv").is_symlink() and (w / "target.csv").read_text() == "moved", "move")
    # A FIFO: written where it points, with a reader draining it.
    os.mkfifo(w / "fifo")
    got = []
    reader = threading.Thread(target=lambda: got.append((w / "fifo").read_bytes()))
    reader.start()
    output_file.write(w / "fifo", b"x" * 200000)
    reader.join(10)
    expect(got == [b"x" * 200000] and stat.S_ISFIFO(os.lstat(w / "fifo").st_mode), "fifo")
    # Character devices made here (root only): null works, full fails; neither is replaced.
    try:
        os.mknod(w / "null", 0o666 | stat.S_IFCHR, os.makedev(1, 3))
        os.mknod(w / "full", 0o666 | stat.S_IFCHR, os.makedev(1, 7))
    except PermissionError:
        print("skipped: character devices need root for mknod")
    else:
        output_file.write(w / "null", "discarded")
        try:
            output_file.write(w / "full", "x" * 10000)
            problems.append("writing a full device did not fail")
        except OSError:
            pass
        for d in ("null", "full"):
            expect(stat.S_ISCHR(os.lstat(w / d).st_mode), f"{d} device replaced")
    # A folder and a socket: refused, not replaced.
    (w / "folder").mkdir()
    with socket.socket(socket.AF_UNIX) as s:
        s.bind(str(w / "socket"))
    for name, test in (("folder", stat.S_ISDIR), ("socket", stat.S_ISSOCK)):
        try:
            output_file.write(w / name, "x")
            problems.append(f"writing a {name} did not fail")
        except output_file.OutputPathError as e:
            expect(name in str(e), f"message does not say {name}")
        expect(test(os.lstat(w / name).st_mode), f"{name} replaced")
    # A path under a regular file (README.md/page.md): bad input naming that file, as ./simulate
    # says it (exit 2), by each entry of the rule, not an OSError of the host's.
    (w / "plain").write_text("plain")
    for how, call in (("check", lambda p: output_file.check(p)),
                      ("write", lambda p: output_file.write(p, "x")),
                      ("move", lambda p: output_file.move(w / "plain", p))):
        try:
            call(w / "plain" / "deeper" / "page.md")
            problems.append(f"{how} under a regular file did not fail")
        except output_file.MissingFolderError as e:
            expect("plain is not a folder" in str(e), f"{how} under a file: message {e}")
    expect((w / "plain").read_text() == "plain", "the file above was written")
    # A file read through the input gate, and one protected: never written, by any name or link.
    from ncube import input_file
    (w / "input.yaml").write_text("read")
    input_file.read_input_text(w / "input.yaml", "sweep file", 100)
    (w / "protected.json").write_text("named")
    input_file.protect([w / "protected.json"])
    (w / "to-input").symlink_to("input.yaml")
    os.link(w / "protected.json", w / "hard-link.json")
    for name in ("input.yaml", "to-input", "protected.json", "hard-link.json"):
        for how in ("write", "move"):
            try:
                if how == "write":
                    output_file.write(w / name, "overwritten")
                else:
                    (w / "done.partial").write_text("overwritten")
                    output_file.move(w / "done.partial", w / name)
                problems.append(f"{how} onto the input {name} did not fail")
            except output_file.OutputIsInputError as e:
                expect("is the input file" in str(e), f"{how} {name}: message {e}")
            (w / "done.partial").unlink(missing_ok=True)
    expect((w / "input.yaml").read_text() == "read" and
           (w / "protected.json").read_text() == "named", "an input was written")
    left = [p.name for p in w.iterdir() if ".partial-" in p.name]
    expect(not left, f"temporary files left: {left}")

if problems:
    print("FAIL: " + "; ".join(problems), file=sys.stderr)
    sys.exit(1)
print("PASS: the sweep tool's files follow the rule per kind of path")
PY
