#!/usr/bin/python3
"""Every Python program the repository ships, tried from its own argparse options, as a careless
or hostile user would (docs/threat-model.md, "How the suite tries them").

usage: options_harness.py ROOT SIMULATE [--jobs N] [--timeout S] [--only PROGRAM] [--list]

The programs are those tests/robustness/executables.py lists; each one's options are read from
its own parser (argparse_options.describe: the program runs until it parses its arguments).
In a copy of the tracked tree (no results/, no build/: a fresh clone, so a program that runs
the simulator refuses once its own checks pass, and nothing a case does can touch the
repository), each option is tried alone, beside the program's base arguments (BASE):

  path option    a FIFO (nobody at the other end: a blocking read would wait forever),
                 /dev/zero, a folder, a link to a committed file, a committed file, a path in
                 a missing folder;
  number option  0, -1, nan, 1e400 and 0x10;
  JSON input     (a positional the base names) nested 100,000 deep, a NaN, every number
                 negated, every number made a string, the document made a list.

Every case must end in a documented exit (0 ok, 2 bad input, 3 out of memory, 4 simulation
failed, 5 output not writable, 6 host memory, 7 internal), a refusal in one line (argparse's
usage lines apart) with no traceback, within the timeout (a wait for the other end of a FIFO
counts as a hang after a second) and the address-space limit; after each program's cases the
copy's `git status` must be what it was. Some cases must be refused (exit 2, or any documented
refusal): a count given nan, 1e400 or 0x10, a number given nan or 1e400, a positional input
given a FIFO, /dev/zero, a folder or a missing file, a JSON input nested deeply, with a NaN or
of the wrong type. A program listed open in executables.py (a benchmark, minutes of runs) gets
only the cases its parser must refuse.

Each case is a fork of this process, which has imported numpy, matplotlib and yaml once: a case
costs the program's own work, not its imports (0.1 to 0.9 s of CPU each otherwise).
Exit status 0 when every case holds, 1 otherwise."""
import os
import sys

# Debian's /usr/bin/python3 (README.md, "Use"), which has numpy, matplotlib and yaml: started
# by another python3, restart under it. Not through analysis/ncube/interpreter.py: this process
# runs the programs of a copied tree, and the real tree's ncube on sys.path would stand in for
# the copy's (its build/ and its files).
import importlib.util  # noqa: E402
if (any(importlib.util.find_spec(m) is None for m in ("numpy", "matplotlib", "yaml"))
        and not os.environ.get("NCUBE_PYTHON_RESTARTED") and os.access("/usr/bin/python3", os.X_OK)):
    os.environ["NCUBE_PYTHON_RESTARTED"] = "1"
    os.execv("/usr/bin/python3", ["/usr/bin/python3"] + sys.argv)
os.environ.pop("NCUBE_PYTHON_RESTARTED", None)

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")   # no BLAS threads in a process that forks
os.environ["MPLBACKEND"] = "Agg"
# No bytecode written, here or by the Pythons the cases start: a __pycache__ folder in the copied
# tree would change its `git status --ignored`, which each program's cases must leave as it was
# (the copy's modules are compiled once, in this process, before it forks: preload, compiled).
sys.dont_write_bytecode = True
os.environ["PYTHONDONTWRITEBYTECODE"] = "1"

import argparse  # noqa: E402
import gc  # noqa: E402
import json  # noqa: E402
import re  # noqa: E402
import resource  # noqa: E402
import runpy  # noqa: E402
import shutil  # noqa: E402
import signal  # noqa: E402
import subprocess  # noqa: E402
import sys  # noqa: E402
import tempfile  # noqa: E402
import time  # noqa: E402
import traceback  # noqa: E402
from dataclasses import dataclass, field  # noqa: E402
from pathlib import Path  # noqa: E402


HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
import executables  # noqa: E402
import threat_cases  # noqa: E402

DOCUMENTED = {0, 2, 3, 4, 5, 6, 7}
COUNT_TYPES = {"int", "whole_number"}
NUMBER_TYPES = COUNT_TYPES | {"float"}
NUMBERS = ["0", "-1", "nan", "1e400", "0x10"]
PATH_KINDS = ["fifo", "/dev/zero", "folder", "link to a committed file", "committed file",
              "missing folder"]
JSON_KINDS = ["deep nesting", "NaN", "negated", "numbers as strings", "a list"]
# Options whose value is not a path: a command, a list of names, a label (their content is the
# program's own to check; control characters in names are held by tests/names_test.sh).
TEXT_OPTIONS = {"cluster", "only", "set", "label", "runs", "dimensions", "V"}
# Path kinds a folder option takes as it should (a folder, one it makes), left out where the
# run they start is minutes of work (scenes/generate.py builds every scene).
VALID_AND_SLOW = {("scenes/generate.py", "--out"): {"folder", "missing folder"}}
# Options naming what the program writes (the rest of the path options it reads).
OUTPUT_OPTIONS = {"out", "output", "json", "figure", "figures", "pictures_figure", "out_dir",
                  "results"}

# The base arguments of a program whose positionals need a file (paths relative to the copy of
# the tree are written "{tree}/...", to the case folder plain): with them and no hostile
# option the program gets as far as it can without results or a simulator.
SWEEP = {"cells": [{"scene": "scene.json", "iterations": 1, "platform": "platform.json",
                    "cost_model": "cost.json"}]}
BASE = {
    "experiments/sweep": ["sweep.json", "--check"],
    "analysis/ncube/accuracy.py": ["solution.ply", "reference.json"],
    "analysis/cycles/compare.py": ["{tree}/analysis/reference/scene0.json",
                                   "{tree}/analysis/cycles/scene0.json"],
    "analysis/cycles/cycles_answers.py": ["{tree}/scenes/scene0.json", "--out", "out.json",
                                          "--blender", "no-blender-here"],
}
# JSON positionals of the base, by index in BASE, that get the JSON cases.
JSON_POSITIONALS = {
    "experiments/sweep": [0],
    "analysis/ncube/accuracy.py": [1],
    "analysis/cycles/compare.py": [0, 1],
    "analysis/cycles/cycles_answers.py": [0],
}


@dataclass
class Case:
    program: str
    name: str
    argv: list
    must_refuse: bool = False       # exit 2 (or another documented refusal), never 0
    fifo_reader: bool = False       # a reader at the FIFO's other end (an output)
    files: dict = field(default_factory=dict)    # name in the case folder -> bytes
    fifo: bool = False
    link_to: str = ""               # "link" in the case folder -> this path
    no_nan_out: bool = False        # an exit 0 may not print "nan"
    names: str = ""                 # a refusal must name this (the file at fault)


def programs(open_too=True):
    """The Python programs executables.py lists: (path, open)."""
    found = []
    for program, tests in executables.COVERED.items():
        if "/" in program and not program.startswith((".ci/", "tests/")) and \
                (program.endswith(".py") or program.startswith("experiments/")) and \
                not program.startswith("experiments/claims/"):
            found.append((program, isinstance(tests, str)))
    return [f for f in found if open_too or not f[1]]


# ------------------------------------------------------------------------------------------
# Forked runs.

def _describe_child(path, out_fd):
    """In a fork: the program's options as argparse_options.py prints them, onto out_fd."""
    import argparse_options
    argparse_options.install()
    os.dup2(out_fd, 1)
    devnull = os.open(os.devnull, os.O_RDWR)
    os.dup2(devnull, 0)
    os.dup2(devnull, 2)
    sys.argv = [path]
    sys.path.insert(0, str(Path(path).parent))
    code = 0
    try:
        runpy.run_path(path, run_name="__main__")
        print("null")
    except argparse_options.Parsed:
        pass
    except SystemExit:
        print("null")
    except BaseException:
        code = 1
    sys.stdout.flush()
    os._exit(code)


def describe(path, cwd):
    """The options of the program at `path` ([] when it parses none), read in a fork."""
    read, write = os.pipe()
    sys.stdout.flush()
    sys.stderr.flush()
    pid = os.fork()
    if pid == 0:
        os.close(read)
        os.chdir(cwd)
        os.setsid()
        _describe_child(path, write)
    os.close(write)
    chunks = []
    deadline = time.monotonic() + 60
    with os.fdopen(read, "rb") as stream:
        chunks.append(stream.read())
    while time.monotonic() < deadline:
        done, _status = os.waitpid(pid, os.WNOHANG)
        if done:
            break
        time.sleep(0.01)
    else:
        os.killpg(pid, signal.SIGKILL)
        os.waitpid(pid, 0)
    lines = b"".join(chunks).decode(errors="replace").strip().splitlines()
    if not lines:
        raise RuntimeError(f"{path}: its options could not be read")
    options = json.loads(lines[-1])
    return options or []


def preload(tree):
    """Imports the tree's own shared library (analysis/ncube and its subpackages: the same files
    the programs import, so their paths are the tree's) once, before any fork: a case then
    compiles and runs none of it again (PYTHONDONTWRITEBYTECODE leaves no bytecode to reuse;
    ncube.paper alone was half of a small case's CPU)."""
    import importlib
    sys.path.insert(0, str(tree / "analysis"))
    package = tree / "analysis" / "ncube"
    for module in sorted(package.rglob("*.py")):   # its subpackages too (ncube.paper)
        name = ".".join(("ncube",) + module.relative_to(package).with_suffix("").parts)
        try:
            importlib.import_module(name.removesuffix(".__init__"))
        except Exception:   # a module that needs what a case gives it: imported there
            pass
    # The modules a program imports from its own folder (docs/machines/prediction_records.py
    # and the like): each case imported them again (half of a small case of
    # hemicube_profile.py). A name two folders share is left to the cases.
    beside = {}
    for program, _ in programs():
        path = tree / program
        if not path.is_file():
            continue
        for name in re.findall(r"^(?:import|from) (\w+)", path.read_text(errors="replace"), re.M):
            if (path.parent / f"{name}.py").is_file() and name not in sys.modules:
                beside.setdefault(name, set()).add(path.parent)
    for name, folders in sorted(beside.items()):
        if len(folders) == 1:
            sys.path.insert(0, str(folders.pop()))
            try:
                importlib.import_module(name)
            except Exception:
                pass
            finally:
                sys.path.pop(0)


def compiled(path):
    """The program's code, compiled once for all its cases."""
    return compile(Path(path).read_bytes(), path, "exec")


def run_as_main(path, code):
    """What runpy.run_path does, with `code` compiled once: the program as __main__."""
    import types
    module = types.ModuleType("__main__")
    module.__file__ = path
    module.__builtins__ = __builtins__
    sys.modules["__main__"] = module
    exec(code, module.__dict__)


def _run_child(path, program_code, argv, folder, out, err, memory_bytes, cpu_seconds):
    os.setsid()
    resource.setrlimit(resource.RLIMIT_AS, (memory_bytes, memory_bytes))
    resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
    resource.setrlimit(resource.RLIMIT_CPU, (cpu_seconds, cpu_seconds + 1))
    resource.setrlimit(resource.RLIMIT_FSIZE, (1 << 30, 1 << 30))
    signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
    os.chdir(folder)
    devnull = os.open(os.devnull, os.O_RDONLY)
    os.dup2(devnull, 0)
    os.dup2(os.open(out, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o644), 1)
    os.dup2(os.open(err, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o644), 2)
    sys.argv = [path, *argv]
    sys.path.insert(0, str(Path(path).parent))
    code = 0
    try:
        run_as_main(path, program_code)
    except SystemExit as e:
        if e.code is None:
            code = 0
        elif isinstance(e.code, int):
            code = e.code & 0xFF
        else:
            print(e.code, file=sys.stderr)
            code = 1
    except BaseException:
        traceback.print_exc()
        code = 1
    try:
        sys.stdout.flush()
        sys.stderr.flush()
    except BaseException:
        pass
    os._exit(code)


PR_SET_CHILD_SUBREAPER = 36


def adopt_orphans():
    """Makes this process the parent of every orphan of its cases (a Snakemake started in a
    session of its own, a daemon), so that none outlives the case that started it."""
    import ctypes
    ctypes.CDLL(None, use_errno=True).prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0)


def _children():
    """This process's children: each of its threads' /proc/self/task/TID/children (Linux 3.5
    and later), not every process's stat read at each case's end (4 s of the harness's CPU);
    where the kernel has no such file, the scan."""
    try:
        found = []
        for task in os.scandir("/proc/self/task"):
            found += [int(pid) for pid in Path(task.path, "children").read_text().split()]
        return found
    except FileNotFoundError:
        pass
    mine = os.getpid()
    found = []
    for entry in os.scandir("/proc"):
        if entry.name.isdigit():
            try:
                fields = Path(f"/proc/{entry.name}/stat").read_text().rsplit(")", 1)[1].split()
            except (OSError, IndexError):
                continue
            if int(fields[1]) == mine:
                found.append(int(entry.name))
    return found


def end_strays(keep):
    """Kills and reaps every child of this process but `keep` (what the cases left running,
    adopted by adopt_orphans); returns how many."""
    ended = 0
    for _ in range(50):
        strays = [pid for pid in _children() if pid not in keep]
        if not strays:
            break
        for pid in strays:
            try:
                os.kill(pid, signal.SIGKILL)
                os.waitpid(pid, 0)
                ended += 1
            except (ProcessLookupError, ChildProcessError):
                pass
        time.sleep(0.05)
    return ended


def _waits_on_fifo(pid):
    """Whether the case's own process waits in the kernel for the other end of a FIFO (one
    file read: scanning every process's would cost more than the cases)."""
    try:
        return Path(f"/proc/{pid}/wchan").read_text() == "wait_for_partner"
    except OSError:
        return False


def _address_space():
    for line in Path("/proc/self/status").read_text().splitlines():
        if line.startswith("VmSize:"):
            return int(line.split()[1]) << 10
    return 1 << 30


def _rss_mib():
    for line in Path("/proc/self/status").read_text().splitlines():
        if line.startswith("VmRSS:"):
            return int(line.split()[1]) / 1024
    return 0.0


# ------------------------------------------------------------------------------------------
# The cases of one program.

def committed_file(program, base):
    """The committed file a link or an output names: the base's first committed input (the
    output-onto-input rule), else a page nobody writes (README.md)."""
    for word in base:
        if word.startswith("{tree}/"):
            return word
    return "{tree}/README.md"


def json_variants(data):
    """The hostile JSON cases of a valid document: {kind: bytes}."""
    document = json.loads(data)

    def first_number(value, change):
        if isinstance(value, bool):
            return value, False
        if isinstance(value, (int, float)):
            return change(value), True
        if isinstance(value, list):
            for i, item in enumerate(value):
                value[i], done = first_number(item, change)
                if done:
                    return value, True
        if isinstance(value, dict):
            for key in value:
                value[key], done = first_number(value[key], change)
                if done:
                    return value, True
        return value, False

    def all_numbers(value):
        if isinstance(value, bool):
            return value
        if isinstance(value, (int, float)):
            return -value
        if isinstance(value, list):
            return [all_numbers(v) for v in value]
        if isinstance(value, dict):
            return {k: all_numbers(v) for k, v in value.items()}
        return value

    def strings(value):
        if isinstance(value, bool):
            return value
        if isinstance(value, (int, float)):
            return str(value)
        if isinstance(value, list):
            return [strings(v) for v in value]
        if isinstance(value, dict):
            return {k: strings(v) for k, v in value.items()}
        return value

    nan, _ = first_number(json.loads(data), lambda v: float("nan"))
    text = strings(json.loads(data))
    return {
        "deep nesting": ("[" * 100000 + "]" * 100000).encode(),
        "NaN": json.dumps(nan).encode(),
        "negated": json.dumps(all_numbers(document)).encode(),
        "numbers as strings": json.dumps(text).encode(),
        "a list": json.dumps([document]).encode(),
    }


def cases_of(program, is_open, options, tree, base_files):
    base = BASE.get(program, [])
    found = []
    for option in options:
        flags, dest, kind = option["flags"], option["dest"], option["type"]
        if option["nargs"] == 0 or option["choices"]:
            continue
        positional = not flags
        where = flags[-1] if flags else None

        def argv_with(value):
            if positional:
                index = positional_index(options, dest)
                words = list(base)
                if index is None or index >= len(words):
                    return None
                words[index] = value
                return words
            words = list(base)
            if where in words:   # the base sets it: replace its value
                words[words.index(where) + 1] = value
                return words
            return words + [where, value]

        if kind in NUMBER_TYPES:
            for value in NUMBERS:
                refused = value in ("nan", "1e400") or (kind in COUNT_TYPES and value == "0x10")
                if is_open and not refused:
                    continue
                argv = argv_with(value)
                if argv is not None:
                    found.append(Case(program, f"{where or dest} {value}", argv, must_refuse=refused))
            continue
        if kind not in (None, "str", "Path"):
            raise RuntimeError(f"{program}: option {where or dest} of type {kind}: add it to "
                               "NUMBER_TYPES or the path options")
        if is_open or dest in TEXT_OPTIONS:
            continue
        output = dest in OUTPUT_OPTIONS
        committed = committed_file(program, base)
        for path_kind in PATH_KINDS:
            if path_kind in VALID_AND_SLOW.get((program, where), ()):
                continue
            value = {"fifo": "fifo", "/dev/zero": "/dev/zero", "folder": "folder",
                     "link to a committed file": "link", "committed file": committed,
                     "missing folder": "nowhere/file.json"}[path_kind]
            argv = argv_with(value)
            if argv is None:
                continue
            case = Case(program, f"{where or dest} {path_kind}", argv,
                        fifo=path_kind == "fifo", fifo_reader=path_kind == "fifo" and output,
                        link_to=committed if path_kind == "link to a committed file" else "",
                        must_refuse=positional and path_kind in ("fifo", "/dev/zero", "folder",
                                                                 "missing folder"))
            found.append(case)
    for index in JSON_POSITIONALS.get(program, []):
        word = base[index]
        source = Path(word.replace("{tree}", str(tree))) if word.startswith("{tree}") else None
        data = source.read_bytes() if source else base_files[word]
        for kind, content in json_variants(data).items():
            argv = list(base)
            argv[index] = "hostile.json"
            found.append(Case(program, f"{Path(word).name} {kind}", argv,
                              files={"hostile.json": content}, must_refuse=kind != "negated",
                              no_nan_out=True, names="hostile.json"))
    if base:
        found.append(Case(program, "base", list(base)))
    return found


def positional_index(options, dest):
    index = 0
    for option in options:
        if not option["flags"]:
            if option["dest"] == dest:
                return index
            index += 1
    return None


def base_files_of(program, simulate, root):
    """Files the base arguments name in the case folder."""
    if program == "experiments/sweep":
        return {"sweep.json": json.dumps(SWEEP).encode(),
                "scene.json": json.dumps(threat_cases.ROOM_SCENE).encode(),
                "platform.json": (root / "platforms" / "ncube2.json").read_bytes(),
                "cost.json": (root / "platforms" / "cost_model.json").read_bytes()}
    if program == "analysis/ncube/accuracy.py":
        threat_cases.prepare_tool_files(simulate, root)
        return {"solution.ply": threat_cases.good_content("solution", root),
                "reference.json": threat_cases.good_content("reference", root)}
    return {}


# ------------------------------------------------------------------------------------------
# Running and judging.

USAGE_LINE = re.compile(r"^(usage: |\s{2,})")
ERROR_LINE = re.compile(r"^\S+: error: ")


def message_lines(stderr):
    """The lines of a refusal, argparse's usage lines apart."""
    lines = [line for line in stderr.splitlines() if line.strip()]
    if any(ERROR_LINE.match(line) for line in lines) and lines and lines[0].startswith("usage: "):
        lines = [line for line in lines if not USAGE_LINE.match(line)]
    return lines


def judge(case, code, stderr, stdout, seconds, hang):
    problems = []
    if hang:
        return [hang]
    if code is None or code < 0:
        return [f"killed by signal {-(code or 0)}"]
    if code not in DOCUMENTED:
        problems.append(f"exit {code}, not a documented one")
    if "Traceback (most recent call last)" in stderr:
        problems.append("a traceback")
    if code != 0:
        lines = message_lines(stderr)
        if len(lines) != 1 or len(stderr) > 4000:
            problems.append(f"a message of {len(lines)} lines, {len(stderr)} bytes")
    if case.must_refuse and code == 0:
        problems.append("exit 0, not a refusal")
    if case.names and case.must_refuse and code not in (0, None) and case.names not in stderr:
        problems.append(f"the message does not name {case.names}")
    if case.no_nan_out and code == 0 and re.search(r"\bnan\b", stdout, re.I):
        problems.append("exit 0 with nan in its output")
    if problems:
        problems.append(f"stderr: {stderr.strip()[-300:]!r}")
    return problems


def prepare(case, folder, tree, files):
    folder.mkdir(parents=True)
    for name, content in {**files, **case.files}.items():
        (folder / name).write_bytes(content)
    (folder / "folder").mkdir()
    if case.fifo:
        os.mkfifo(folder / "fifo")
    if case.link_to:
        (folder / "link").symlink_to(case.link_to.replace("{tree}", str(tree)))
    return [word.replace("{tree}", str(tree)) for word in case.argv]


def run_program(program, cases, tree, work, files, args, memory_bytes, results):
    """Runs `cases` of one program, `args.jobs` at once; appends (case, problems, seconds)."""
    path = str(tree / program)
    program_code = compiled(path)
    pending = list(enumerate(cases))
    running = {}
    while pending or running:
        while pending and len(running) < args.jobs:
            number, case = pending.pop(0)
            folder = work / f"{program.replace('/', '_')}-{number}"
            argv = prepare(case, folder, tree, files)
            reader = None
            if case.fifo_reader:
                reader = subprocess.Popen(["cat", str(folder / "fifo")], stdout=subprocess.DEVNULL,
                                          stderr=subprocess.DEVNULL)
            out, err = str(folder) + ".out", str(folder) + ".err"
            sys.stdout.flush()
            sys.stderr.flush()
            pid = os.fork()
            if pid == 0:
                _run_child(path, program_code, argv, folder, out, err, memory_bytes,
                           int(args.timeout))
            running[pid] = (case, time.monotonic(), out, err, reader, None)
        time.sleep(0.02)
        for pid in list(running):
            case, start, out, err, reader, blocked_since = running[pid]
            done, status, usage = os.wait4(pid, os.WNOHANG)
            now = time.monotonic()
            hang = None
            if not done:
                blocked = _waits_on_fifo(pid) if now - start > 0.3 else False
                blocked_since = (blocked_since or now) if blocked else None
                running[pid] = (case, start, out, err, reader, blocked_since)
                if now - start > args.timeout:
                    hang = f"still running after {args.timeout:g} s"
                elif blocked_since and now - blocked_since > 1:
                    hang = "waits forever for the other end of a FIFO"
                if not hang:
                    continue
                os.killpg(pid, signal.SIGKILL)
                os.waitpid(pid, 0)
            else:
                try:
                    os.killpg(pid, signal.SIGKILL)   # anything it left running
                except ProcessLookupError:
                    pass
            del running[pid]
            if reader:
                reader.kill()
                reader.wait()
            end_strays({p for p in running} | {r[4].pid for r in running.values() if r[4]})
            code = None if hang else os.waitstatus_to_exitcode(status)
            stderr = Path(err).read_text(errors="replace")
            stdout = Path(out).read_text(errors="replace")
            cpu = usage.ru_utime + usage.ru_stime if done else 0.0
            results.append((case, judge(case, code, stderr, stdout, now - start, hang),
                            cpu, code, stderr))


def copy_tree(root, tree):
    """The tracked files of `root` as they are now, in a git repository of their own."""
    listed = subprocess.run(["git", "-C", str(root), "ls-files", "-z"], capture_output=True,
                            check=True).stdout.decode().split("\0")
    for name in listed:
        source = root / name
        if name and source.is_file() and not source.is_symlink():
            (tree / name).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(source, tree / name)
        elif name and source.is_symlink():
            (tree / name).parent.mkdir(parents=True, exist_ok=True)
            (tree / name).symlink_to(os.readlink(source))
    quiet = dict(capture_output=True, check=True, cwd=tree)
    # Stored uncompressed: the copy lives for one run, and zlib over its 22 MB took half the
    # harness's set-up.
    stored = ["-c", "core.compression=0", "-c", "core.looseCompression=0", "-c", "gc.auto=0"]
    subprocess.run(["git", "init", "-q"], **quiet)
    subprocess.run(["git", *stored, "add", "-A"], **quiet)
    subprocess.run(["git", *stored, "-c", "user.name=test", "-c", "user.email=test@localhost",
                    "commit", "-q", "-m", "the tree under test"], **quiet)


def status(tree, ignored=True):
    """`git status` of `tree`, its ignored files too (a results/ folder made in the copy);
    the repository's own without them (other tests' build outputs come and go meanwhile)."""
    return subprocess.run(["git", "status", "--porcelain"] + (["--ignored"] if ignored else []),
                          capture_output=True, text=True, cwd=tree).stdout


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("root")
    parser.add_argument("simulate")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--timeout", type=float, default=20.0, help="seconds per case")
    parser.add_argument("--only", help="one program (as executables.py names it)")
    parser.add_argument("--list", action="store_true", help="print every case")
    args = parser.parse_args()
    # Imported once here, before any fork, for every case (after the arguments: --help needs
    # none of them).
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot  # noqa: F401
    import numpy  # noqa: F401
    import yaml  # noqa: F401
    root, simulate = Path(args.root).resolve(), Path(args.simulate).resolve()
    for variable in ("NCUBE_SIMULATE", "NCUBE_ROOT"):
        os.environ.pop(variable, None)
    root_status = status(root, ignored=False)
    adopt_orphans()
    # The address space of this process (numpy's and matplotlib's mappings) plus 1 GiB each.
    memory_bytes = _address_space() + (1 << 30)
    failures, total, started = 0, 0, time.monotonic()
    with tempfile.TemporaryDirectory(prefix="options_harness.") as scratch:
        tree, work = Path(scratch) / "tree", Path(scratch) / "cases"
        tree.mkdir()
        work.mkdir()
        copy_tree(root, tree)
        before = status(tree)
        preload(tree)
        # Every object imported so far into the permanent generation: a case's collections then
        # leave them alone, so its fork does not copy every page of them (copy-on-write).
        gc.freeze()
        for program, is_open in programs():
            if args.only and program != args.only:
                continue
            options = describe(str(tree / program), str(work))
            files = base_files_of(program, simulate, root)
            cases = cases_of(program, is_open, options, tree, files)
            results = []
            run_program(program, cases, tree, work, files, args, memory_bytes, results)
            for case, problems, seconds, code, stderr in results:
                total += 1
                if args.list or problems:
                    print(f"{'FAIL' if problems else 'ok  '} {seconds:5.2f}s CPU exit {code} "
                          f"{program} {case.name}" + (f": {'; '.join(problems)}" if problems
                                                      else f": {stderr.strip()[-120:]!r}"), flush=True)
                failures += bool(problems)
            cpu = sum(r[2] for r in results)
            if args.list:
                print(f"# {program}: {len(results)} cases, {cpu:.1f} s CPU", flush=True)
            now = status(tree)
            if now != before:
                failures += 1
                print(f"FAIL {program}: the tree changed: {now.strip()[:500]}")
                subprocess.run(["git", "checkout", "-q", "--", "."], cwd=tree)
                subprocess.run(["git", "clean", "-qfdx"], cwd=tree)
    if status(root, ignored=False) != root_status:
        failures += 1
        print("FAIL: the repository's own tree changed")
    print(f"options_harness: {total} cases of {len(programs())} programs, {failures} failed, "
          f"{time.monotonic() - started:.0f} s")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
