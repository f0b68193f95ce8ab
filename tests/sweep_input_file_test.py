#!/usr/bin/env python3
"""The sweep tool's input gate (analysis/ncube/input_file.py) says what each kind of path is,
as ./simulate's does (docs/cli.md, "Input files"): every case below is made in a scratch folder
and its message compared with the one the rule gives. The robustness suite only sees exit 2
for these (an empty read of a FIFO also ends in a refusal), so the kinds are pinned here."""
import os
import re
import socket
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "analysis"))
from ncube import input_file  # noqa: E402

failures = []

# The sweep tool's limits are ./simulate's (one rule): held to src/util/input_file.h here.
header = (Path(__file__).resolve().parents[1] / "src/util/input_file.h").read_text()
for python_limit, kind in ((input_file.SCENE_FILE_BYTES, "kSceneFile"),
                           (input_file.PLATFORM_FILE_BYTES, "kSimgridPlatformFile")):
    found = re.search(r"InputKind %s\{\"[^\"]*\", (\d+) \* kMiB\}" % kind, header)
    if not found or int(found.group(1)) << 20 != python_limit:
        failures.append(f"input_file.py's limit {python_limit} is not {kind}'s in input_file.h")


def expect(path, needle, max_bytes=64):
    try:
        input_file.read_input_text(str(path), "sweep file", max_bytes)
    except input_file.InputFileError as error:
        if str(path) not in str(error) or needle not in str(error):
            failures.append(f"{path}: {error!r} does not say {needle!r}")
        return
    failures.append(f"{path}: read, but should be refused ({needle})")


with tempfile.TemporaryDirectory() as scratch:
    work = Path(scratch)
    regular = work / "sweep.yaml"
    regular.write_text("name: s\n")
    assert input_file.read_input_text(str(regular), "sweep file", 64) == "name: s\n"
    exact = work / "exact.yaml"
    exact.write_bytes(b"x" * 64)  # exactly the limit is read, one byte more is not
    assert input_file.read_input_bytes(str(exact), "sweep file", 64) == b"x" * 64
    expect(exact, "larger than 63 bytes (the limit)", max_bytes=63)
    fifo = work / "fifo.yaml"
    os.mkfifo(fifo)
    expect(fifo, "sweep file is a FIFO, not a regular file")
    expect("/dev/null", "sweep file is a character device, not a regular file")
    expect(work, "sweep file is a folder, not a regular file")
    listening = socket.socket(socket.AF_UNIX)
    listening.bind(str(work / "socket.yaml"))
    expect(work / "socket.yaml", "cannot open sweep file")  # a socket cannot be opened
    loop = work / "loop.yaml"
    loop.symlink_to(loop)
    expect(loop, "cannot open sweep file: a loop of symbolic links")
    endless = work / "endless.yaml"
    endless.symlink_to("/dev/zero")
    expect(endless, "sweep file is a character device, not a regular file")
    binary = work / "binary.yaml"
    binary.write_bytes(b"name: \xff\xfe\n")
    expect(binary, "is not UTF-8 text (byte 6)")
    expect(work / "missing.yaml", "cannot open sweep file: No such file or directory")

for failure in failures:
    print("FAIL:", failure)
print(f"sweep input gate: {len(failures)} failures")
sys.exit(1 if failures else 0)
