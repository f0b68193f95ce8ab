"""The sweep tool's gate for the files it reads itself (sweep files, scene and platform files,
the files it hashes): the same rule as ./simulate's (src/util/input_file.h, docs/cli.md "Input
files"). Opened without blocking (a FIFO never waits for a writer), the descriptor checked to be
a regular file, and read at most one byte past the limit, so a device, a folder, a link loop or
an endless file is one clear SweepError instead of a hang, a traceback or gigabytes of memory."""
import errno
import json
import os
import re
import stat

MIB = 1 << 20
SWEEP_FILE_BYTES = 1 * MIB       # a sweep file: a few hundred lines of YAML or JSON
SCENE_FILE_BYTES = 256 * MIB     # as ./simulate's kSceneFile
PLATFORM_FILE_BYTES = 64 * MIB   # as ./simulate's kSimgridPlatformFile (the larger platform limit)

_KINDS = {stat.S_IFIFO: "a FIFO", stat.S_IFCHR: "a character device", stat.S_IFBLK: "a block device",
          stat.S_IFDIR: "a folder", stat.S_IFSOCK: "a socket"}


# Every file read through this gate, by identity (device, inode) -> the path read: the output
# rule (ncube.output_file) never writes onto one of them, whatever link or name leads there.
_READ = {}


def files_read():
    """{(st_dev, st_ino): path} of every regular file this process read through the gate."""
    return dict(_READ)


def protect(paths):
    """Counts PATHS (files another process of the sweep read: the sweep files, scenes, platform
    and cost-model files a plan names) as read, so that nothing here writes onto them."""
    for path in paths:
        try:
            status = os.stat(path)
        except OSError:
            continue
        if stat.S_ISREG(status.st_mode):
            _READ.setdefault((status.st_dev, status.st_ino), str(path))


class InputFileError(ValueError):
    """A file that cannot be read under the rule; the message names the file and why."""


def read_input_bytes(path, what, max_bytes):
    """The bytes of regular file PATH (a WHAT, e.g. "sweep file"), at most MAX_BYTES."""
    try:
        descriptor = os.open(path, os.O_RDONLY | os.O_NONBLOCK | os.O_NOCTTY | os.O_CLOEXEC)
    except OSError as e:
        reason = "a loop of symbolic links" if e.errno == errno.ELOOP else e.strerror
        raise InputFileError(f"{path}: cannot open {what}: {reason}") from None
    try:
        status = os.fstat(descriptor)
        mode = status.st_mode
        if not stat.S_ISREG(mode):
            raise InputFileError(f"{path}: {what} is {_KINDS.get(stat.S_IFMT(mode), 'not a file')}, "
                                 "not a regular file")
        _READ.setdefault((status.st_dev, status.st_ino), str(path))
        # Refused by the size it has, not read up to the limit first (a file of a few hundred
        # MiB over accuracy.py's limit took as much memory); what it gives is still counted
        # below (a kernel file claims a size of 0).
        if status.st_size > max_bytes:
            raise InputFileError(f"{path}: {what} is larger than {max_bytes} bytes (the limit)")
        pieces, size = [], 0
        while size <= max_bytes:
            piece = os.read(descriptor, min(MIB, max_bytes + 1 - size))
            if not piece:
                break
            pieces.append(piece)
            size += len(piece)
        if size > max_bytes:
            raise InputFileError(f"{path}: {what} is larger than {max_bytes} bytes (the limit)")
        return b"".join(pieces)
    except OSError as e:
        raise InputFileError(f"{path}: cannot read {what}: {e.strerror}") from None
    finally:
        os.close(descriptor)


def read_input_text(path, what, max_bytes):
    """The text of PATH as UTF-8; bytes that are not UTF-8 are an InputFileError."""
    data = read_input_bytes(path, what, max_bytes)
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as e:
        raise InputFileError(f"{path}: {what} is not UTF-8 text (byte {e.start})") from None


# Far deeper than any file of the project (a scene, a result, a summary: under 10 levels), and
# far below where Python's parser would recurse out of its stack (about 1,000 levels).
MAX_JSON_DEPTH = 100


_JSON_TOKENS = re.compile(r'"(?:[^"\\]|\\.)*"|[\[\]{}]')


def json_depth_problem(text, max_depth=MAX_JSON_DEPTH):
    """Where TEXT's arrays and objects nest deeper than MAX_DEPTH ("line L: nesting deeper than
    N levels"), else "": a scan of its brackets (strings skipped), before a parser recurses."""
    depth = 0
    for token in _JSON_TOKENS.finditer(text):
        bracket = token.group()
        if bracket in "[{":
            depth += 1
            if depth > max_depth:
                line = text.count("\n", 0, token.start()) + 1
                return f"line {line}: nesting deeper than {max_depth} levels"
        elif bracket in "]}":
            depth -= 1
    return ""


_JSON_CONSTANTS = re.compile(r'"(?:[^"\\]|\\.)*"|NaN|-?Infinity')


def _constant_problem(text):
    """"line L: NaN is not a number JSON allows" for the first NaN or Infinity outside a
    string (Python's parser takes them), else ""."""
    for token in _JSON_CONSTANTS.finditer(text):
        if not token.group().startswith('"'):
            line = text.count("\n", 0, token.start()) + 1
            return f"line {line}: {token.group()} is not a number JSON allows"
    return ""


def _refuse_constant(name):
    raise ValueError(f"{name} is not a number JSON allows")


def read_json(path, what, max_bytes):
    """The JSON value of PATH (a WHAT) through the gate: a regular file within MAX_BYTES, UTF-8,
    nested at most MAX_JSON_DEPTH levels, and strict JSON (NaN and Infinity, which Python's
    parser takes, are refused). Any problem is an InputFileError naming the file."""
    text = read_input_text(path, what, max_bytes)
    problem = json_depth_problem(text) or _constant_problem(text)
    if problem:
        raise InputFileError(f"{path}: {what}: {problem}")
    try:
        return json.loads(text, parse_constant=_refuse_constant)
    except ValueError as e:
        raise InputFileError(f"{path}: {what} is not valid JSON: {e}") from None
