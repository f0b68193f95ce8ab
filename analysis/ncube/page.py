"""What every script that writes a committed page (analysis/*.md, analysis/figures/*.png,
platforms/cost_model.json) does before it writes anything, so that no committed page is
overwritten by an empty or partial one (README.md, "Reproducing the paper's tables"):

* a page made from results it does not run itself (analysis/report.py, analysis/machines.py
  without --run) refuses with one line naming what is missing, writing nothing (exit 2),
  when a cell the page needs has no result; --partial asks for the page anyway, with the
  missing cells shown as not run (for a page written elsewhere, or on purpose);
* a page whose script runs its own cells (the others) says so in one line first, and refuses
  the same way when there is no simulator to run them with.

tests/page_scripts_test.sh runs every page script in a clean clone and checks that the tree
is unchanged."""
import functools
import os
import sys
from pathlib import Path

from . import output_file, paths

REFUSED = 2   # as a missing input file: ./simulate's and experiments/sweep's "bad input"


def shown(path):
    """A path as a message names it: relative to the repository when inside it."""
    path = Path(path).resolve()
    try:
        return str(path.relative_to(paths.ROOT))
    except ValueError:
        return str(path)


def refuse(script, line):
    """One line on stderr, `script: line; nothing written`, and exit REFUSED."""
    print(f"{script}: {line}; nothing written", file=sys.stderr, flush=True)
    sys.exit(REFUSED)


def check_outputs(script, outputs, committed=(), complete=True, how="name another place",
                  folders_made=True, replace_committed=True):
    """Before anything is written, every output under the output rule (ncube.output_file: not
    an input of this script, not a folder, a socket or a block device), and, for a page of an
    incomplete run (a --partial page with cells missing, a small study), none of them a
    committed page (`committed`: the script's default outputs): one line and exit 2 (5 for a
    path that cannot be a file; unless `folders_made`, 2 for a path in a missing folder too;
    unless `replace_committed`, 2 for a file the repository tracks), nothing written."""
    for path in outputs:
        try:
            output_file.check(path, folders_made, replace_committed)
        except output_file.OutputIsInputError as e:   # refusing_outputs' own line
            print(f"{script}: an output {e}; not written", file=sys.stderr, flush=True)
            sys.exit(REFUSED)
        except output_file.OutputPathError as e:
            print(f"{script}: {e}; nothing written", file=sys.stderr, flush=True)
            sys.exit(REFUSED if "symbolic links" in str(e) or
                     isinstance(e, (output_file.MissingFolderError,
                                    output_file.CommittedFileError)) else CANNOT_WRITE)
    if complete:
        return
    pages = {Path(c).resolve() for c in committed}
    for path in outputs:
        if Path(path).resolve() in pages:
            refuse(script, f"a page of an incomplete run would replace the committed "
                           f"{shown(path)}: {how}")


def require_results(script, missing, total, results_dir, how):
    """Refuses unless every one of the page's `total` cells has a result: `missing` are the
    result files (relative to `results_dir`) it lacks, `how` what gives them."""
    if not missing:
        return
    if len(missing) == total:
        what = f"no result of its {total} cells in {shown(results_dir)}/"
    else:
        listed = ", ".join(missing[:3]) + (f" and {len(missing) - 3} more"
                                           if len(missing) > 3 else "")
        what = (f"{len(missing)} of its {total} cells have no result in "
                f"{shown(results_dir)}/ ({listed})")
    refuse(script, f"{what}: {how} (or add --partial for a page showing them as not run)")


def simulator(binary=None):
    """The binary a script's runs use: `binary` (its own --simulate), else $NCUBE_SIMULATE,
    else what ./simulate runs (build/simulate)."""
    return binary or os.environ.get("NCUBE_SIMULATE") or str(paths.ROOT / "build" / "simulate")


def will_run(script, what, binary=None, announce=True):
    """A script that runs its own cells says so before it starts (unless not `announce`: a
    check before its other checks); without a simulator built, it refuses."""
    binary = simulator(binary)
    if not (os.path.isfile(binary) and os.access(binary, os.X_OK)):
        refuse(script, f"it runs {what} with {shown(binary)}, which is not built (cmake -S . "
                       f"-B build -DCMAKE_BUILD_TYPE=Release && cmake --build build -j2)")
    if announce:
        print(f"{script}: runs {what} (a cell with a finished result is not run again)",
              file=sys.stderr, flush=True)


CANNOT_WRITE = 5   # as ./simulate's: an output that cannot be written


class PageWriteError(OSError):
    """A page or figure that could not be written; `code` the exit it ends in (docs/cli.md,
    "Output files": a loop of links or a missing folder 2, anything else 5)."""

    def __init__(self, message, code):
        super().__init__(message)
        self.code = code


def write(path, data, replace_committed=True):
    """Writes a page or figure under the output rule (ncube.output_file): never onto a file
    this script read (its results, its sweep files: ncube.results and ncube.sweep read them
    through the gate), whatever link leads there. Under refusing_outputs, a refusal is one
    line and exit 2 (onto an input, a loop of links, a missing folder) or 5."""
    try:
        return output_file.write(path, data, replace_committed)
    except output_file.OutputIsInputError:
        raise
    except output_file.OutputPathError as e:
        refused = "symbolic links" in str(e) or isinstance(
            e, (output_file.MissingFolderError, output_file.CommittedFileError))
        raise PageWriteError(str(e), REFUSED if refused else CANNOT_WRITE) from None
    except FileNotFoundError:
        raise PageWriteError(f"{path}: its folder does not exist", REFUSED) from None
    except OSError as e:
        raise PageWriteError(f"{path}: cannot be written: {e.strerror or e}", CANNOT_WRITE) \
            from None


def write_output(script, option, path, data, replace_committed=False):
    """Writes a tool's output (`option`, e.g. --json) by page.write, never onto a committed file
    unless `replace_committed` (a tool's output is not a page); a refusal is one line
    `script: option path: why` on stderr. Returns the exit: 0, 2 (onto an input or a committed
    file, a loop of links, a missing folder) or 5 (a folder, a socket, a full disk)."""
    try:
        write(path, data, replace_committed)
    except output_file.OutputIsInputError as e:
        print(f"{script}: {option} {e}; not written", file=sys.stderr, flush=True)
        return REFUSED
    except PageWriteError as e:
        print(f"{script}: {option} {e}", file=sys.stderr, flush=True)
        return e.code
    return 0


def refusing_outputs(script):
    """Decorates a page script's main(): an output onto one of its inputs ends it with one line
    and exit 2 (nothing replaced), a page that cannot be written (page.write) with one line and
    its code, as ./simulate's (docs/cli.md, "Output files"), instead of a traceback or a
    replaced input."""
    def decorate(main):
        @functools.wraps(main)
        def guarded(*args, **kwargs):
            try:
                return main(*args, **kwargs)
            except output_file.OutputIsInputError as e:
                # The check comes as each file is written: those written before it stay.
                print(f"{script}: an output {e}; not written", file=sys.stderr, flush=True)
                sys.exit(REFUSED)
            except PageWriteError as e:
                print(f"{script}: {e}", file=sys.stderr, flush=True)
                sys.exit(e.code)
        return guarded
    return decorate
