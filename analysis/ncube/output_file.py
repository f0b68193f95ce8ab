"""Every file the sweep tool writes follows ./simulate's rule per kind of path (docs/cli.md,
"Output files"): a new path or a regular file is written to a temporary file in its folder and
renamed onto it (atomic replacement is for files); a symbolic link is followed and its target
written that way (the link stays); a character device or a FIFO is written where it points;
anything else (a folder, a socket, a block device) is refused. Nothing that is not a regular
file is ever replaced, and no file this process read through its input gate (ncube.input_file)
is ever written, whichever name or link leads to it."""
import os
import stat
import tempfile
from pathlib import Path

from . import input_file, paths

MAX_LINKS = 40   # as ./simulate (src/tools/output_files.cpp) and Linux


class OutputPathError(OSError):
    """A path that names something that cannot be written as a file."""


class OutputIsInputError(OutputPathError):
    """A path that leads to a file this process read: bad input (exit 2, as ./simulate)."""


class MissingFolderError(OutputPathError):
    """A path whose folder does not exist: bad input (exit 2, as ./simulate)."""


class CommittedFileError(OutputPathError):
    """A path that leads to a file the repository tracks, for an output that is never one of
    its pages (a tool's --json): bad input (exit 2)."""


def committed(final):
    """Whether `final` (a path with its links followed) is a file the repository's git tracks;
    False outside the repository or without git (a tarball)."""
    try:
        relative = Path(os.path.abspath(final)).relative_to(paths.ROOT)
    except ValueError:
        return False
    if not (paths.ROOT / ".git").exists():
        return False
    import subprocess
    try:
        listed = subprocess.run(["git", "-C", str(paths.ROOT), "ls-files", "--error-unmatch",
                                 "--", str(relative)], capture_output=True, timeout=60)
    except (OSError, subprocess.TimeoutExpired):
        return False
    return listed.returncode == 0


def _refuse_committed(path, final, replace_committed):
    if not replace_committed and committed(final):
        raise CommittedFileError(f"{path}: is a committed file of the repository "
                                 f"({Path(os.path.abspath(final)).relative_to(paths.ROOT)}); "
                                 "name another place")


def target(path):
    """`path` with the symbolic links of its last component followed (a dangling link gives its
    missing target)."""
    current = Path(path)
    for _ in range(MAX_LINKS + 1):
        if not current.is_symlink():
            return current
        link = Path(os.readlink(current))
        current = link if link.is_absolute() else current.parent / link
    raise OutputPathError(f"{path}: more than {MAX_LINKS} symbolic links")


def _status(path, final):
    """os.stat of `final` (the path's target), None when there is none; a path under something
    that is not a folder (README.md/page.md) is bad input, as ./simulate says it."""
    try:
        return os.stat(final)
    except FileNotFoundError:
        return None
    except NotADirectoryError:
        folder = final.parent
        while folder != folder.parent and not folder.exists():
            folder = folder.parent
        raise MissingFolderError(f"{path}: folder {folder} is not a folder") from None


def _refuse_inputs(path, final):
    """An OutputPathError when `final` (the path's target) is a file this process read."""
    status = _status(path, final)
    if status is None:
        return
    read = input_file.files_read().get((status.st_dev, status.st_ino))
    if read is not None:
        raise OutputIsInputError(f"{path}: is the input file {read}")


def check(path, folder_made=True, replace_committed=True):
    """Raises what write(path) would for a path it refuses (an input of this process, a folder,
    a socket, a block device, a loop of links; unless `folder_made`, a path whose folder does
    not exist, which the script will not make; unless `replace_committed`, a file the
    repository tracks) without writing anything: a script checks every output first, so that a
    refusal leaves none of them written."""
    final = target(path)
    _refuse_inputs(path, final)
    _refuse_committed(path, final, replace_committed)
    status = _status(path, final)
    if status is None:
        if not folder_made and not final.parent.is_dir():
            raise MissingFolderError(f"{path}: its folder does not exist")
        return
    mode = status.st_mode
    if not (stat.S_ISREG(mode) or stat.S_ISCHR(mode) or stat.S_ISFIFO(mode)):
        kind = "a folder" if stat.S_ISDIR(mode) else "a socket" if stat.S_ISSOCK(mode) else \
            "a block device" if stat.S_ISBLK(mode) else "not a file"
        raise OutputPathError(f"{path}: cannot be written: it is {kind}")


def write(path, data, replace_committed=True):
    """Writes `data` (str or bytes) to `path` by the rule above (unless `replace_committed`,
    never onto a file the repository tracks: a tool's output is never one of its pages);
    returns `path`."""
    data = data.encode() if isinstance(data, str) else bytes(data)
    final = target(path)
    _refuse_inputs(path, final)
    _refuse_committed(path, final, replace_committed)
    status = _status(path, final)
    mode = status.st_mode if status is not None else None
    if mode is not None and (stat.S_ISCHR(mode) or stat.S_ISFIFO(mode)):
        with open(final, "wb") as stream:
            stream.write(data)
        return path
    if mode is not None and not stat.S_ISREG(mode):
        kind = "a folder" if stat.S_ISDIR(mode) else "a socket" if stat.S_ISSOCK(mode) else \
            "a block device" if stat.S_ISBLK(mode) else "not a file"
        raise OutputPathError(f"{path}: cannot be written: it is {kind}")
    descriptor, temporary = tempfile.mkstemp(prefix=final.name + ".partial-", dir=final.parent)
    try:
        with os.fdopen(descriptor, "wb") as out:
            out.write(data)
        os.chmod(temporary, 0o666 & ~_umask())
        os.replace(temporary, final)
    except BaseException:
        Path(temporary).unlink(missing_ok=True)
        raise
    return path


def move(written, path):
    """Puts the finished file `written` (a temporary file in the same folder) at `path` by the
    rule above: renamed onto a file in its folder, else copied (a link's target elsewhere, a
    device or a FIFO)."""
    final = target(path)
    _refuse_inputs(path, final)
    try:
        mode = os.stat(final).st_mode
    except FileNotFoundError:
        mode = None
    if (mode is None or stat.S_ISREG(mode)) and final.parent.resolve() == Path(written).parent.resolve():
        os.replace(written, final)
        return path
    write(path, Path(written).read_bytes())
    Path(written).unlink()
    return path


def _umask():
    mask = os.umask(0)
    os.umask(mask)
    return mask
