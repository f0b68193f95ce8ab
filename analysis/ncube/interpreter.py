"""The one rule for which Python runs the project's scripts (README.md, "Use"): Debian's
/usr/bin/python3, which has numpy, matplotlib and yaml (.ci/install-deps).

Every script that uses those packages calls use_project_python() before anything else it
imports (the scripts of the standard library alone, docs/*_table*.py and the generators, need
no rule: any python3 runs them, and tests copy them alone). Started by another
python3 that lacks those packages (a pyenv shim or a virtual environment first on PATH,
python3 -S), the script restarts itself under /usr/bin/python3 with the same arguments, so
`python3 SCRIPT`, `/usr/bin/python3 SCRIPT` and `SCRIPT` do the same thing. When
/usr/bin/python3 lacks them too, one line says which Debian packages to install (exit 2).
A script that goes on also ends quietly when its standard output is closed (exit 141).

Standard library only, and old syntax only, so that any python3 can read it."""
import importlib.util
import os
import sys

PYTHON = "/usr/bin/python3"
# The project's packages (module name: Debian package).
PACKAGES = {"numpy": "python3-numpy", "matplotlib": "python3-matplotlib", "yaml": "python3-yaml"}
# Set for the restarted process only: a second restart would loop.
RESTARTED = "NCUBE_PYTHON_RESTARTED"


def missing_packages():
    return [name for name in PACKAGES if importlib.util.find_spec(name) is None]


def _closed_pipe_ends_quietly(kind, value, trace, previous=sys.excepthook):
    """A closed standard output (`SCRIPT | head`) ends the script as a closed pipe ends any
    command: no traceback, exit 128 + SIGPIPE (141), as experiments/sweep does. The stack has
    unwound by now (every output rule's temporary file removed); the exit handlers still run."""
    if not issubclass(kind, BrokenPipeError):
        previous(kind, value, trace)
        return
    import atexit
    try:
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
    except (OSError, ValueError):
        pass
    atexit._run_exitfuncs()
    os._exit(141)


def use_project_python():
    lacking = missing_packages()
    if not lacking:
        os.environ.pop(RESTARTED, None)   # the scripts this one starts choose for themselves
        sys.excepthook = _closed_pipe_ends_quietly
        return
    if not os.environ.get(RESTARTED) and os.access(PYTHON, os.X_OK):
        os.environ[RESTARTED] = "1"
        sys.stdout.flush()
        sys.stderr.flush()
        os.execv(PYTHON, [PYTHON] + sys.argv)
    script = os.path.basename(sys.argv[0]) or "python3"
    print("%s: %s lacks the Python package(s) %s; install them with: apt-get install %s"
          % (script, PYTHON if os.environ.get(RESTARTED) else sys.executable,
             ", ".join(lacking), " ".join(PACKAGES[name] for name in lacking)), file=sys.stderr)
    sys.exit(2)
