"""Makes and checks the cells of tests/robustness/threat_model.py: each cell gets a folder of its
own, `<cell>/in` (the folder the user names: the run's inputs and outputs, its working
directory) beside `<cell>/outside` (files the run was never allowed to read or write, one of
them a valid secret of every format a model can name). The run's outcome, what the folders hold
afterwards and the run's peak memory are checked against the rules."""
import hashlib
import json
import os
import signal
import socket
import stat
import struct
import subprocess
import threading
import time
from pathlib import Path

import forked_runs
import threat_model as tm

ITERATIONS = ["--iterations", "1"]
# A picture (--image) and a mesh's exposure (--mesh) drawn at 64 x 48, not 800 x 600: what a
# cell shows is where its files go, not their pixels (0.6 s of CPU a run at the default size).
SMALL_PICTURE = ["--image-width", "64", "--image-height", "48"]

# The tiny room: a light facing down over a floor facing up (2 patches), as a scene, an OBJ
# with its MTL, a PLY, a glTF with an external buffer and an image, and a .glb.
ROOM_SCENE = {
    "name": "room",
    "patches": [
        {"vertices": [[0, 2, 0], [1, 2, 0], [1, 2, 1], [0, 2, 1]],
         "reflectance": [0.5, 0.5, 0.5], "emission": [10, 8, 6], "elements": [2, 2]},
        {"vertices": [[0, 0, 0], [0, 0, 1], [1, 0, 1], [1, 0, 0]],
         "reflectance": [0.6, 0.5, 0.4], "elements": [2, 2]},
    ],
}
CORNERS = [c for p in ROOM_SCENE["patches"] for c in p["vertices"]]
OBJ = ("mtllib {mtl}\n" + "".join(f"v {x} {y} {z}\n" for x, y, z in CORNERS) +
       "usemtl light\nf 1 2 3 4\nusemtl floor\nf 5 6 7 8\n")
MTL = "newmtl light\nKd 0.5 0.5 0.5\nKe 10 8 6\nnewmtl floor\nKd 0.6 0.5 0.4\n"
PLY = ("ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\n"
       "property float z\nelement face 2\nproperty list uchar int vertex_indices\n"
       "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n" +
       "".join(f"{x} {y} {z}\n" for x, y, z in CORNERS) +
       "4 0 1 2 3 128 128 128\n4 4 5 6 7 153 128 102\n")


def mesh_buffer(corners):
    """The room's corners (float32) then its two quads' indices (uint16), as a glTF buffer."""
    data = b"".join(struct.pack("<3f", *c) for c in corners)
    return data + struct.pack("<12H", 0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7)


BUFFER = mesh_buffer(CORNERS)


def gltf_document(buffer_uri, image_uri=None, length=len(BUFFER)):
    floor = {"name": "floor", "pbrMetallicRoughness": {"baseColorFactor": [0.6, 0.5, 0.4, 1]}}
    document = {
        "asset": {"version": "2.0"},
        "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [
            {"attributes": {"POSITION": 0}, "indices": 1, "material": 0},
            {"attributes": {"POSITION": 0}, "indices": 2, "material": 1}]}],
        "materials": [{"name": "light", "emissiveFactor": [1, 0.8, 0.6],
                       "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1]}}, floor],
        "buffers": [{"byteLength": length} | ({"uri": buffer_uri} if buffer_uri else {})],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 96},
                        {"buffer": 0, "byteOffset": 96, "byteLength": 24}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 8, "type": "VEC3",
             "min": [0, 0, 0], "max": [1, 2, 1]},
            {"bufferView": 1, "byteOffset": 0, "componentType": 5123, "count": 6,
             "type": "SCALAR"},
            {"bufferView": 1, "byteOffset": 12, "componentType": 5123, "count": 6,
             "type": "SCALAR"}],
    }
    if image_uri:
        document["images"] = [{"uri": image_uri}]
        document["textures"] = [{"source": 0}]
        floor["pbrMetallicRoughness"]["baseColorTexture"] = {"index": 0}
    return document


def gltf_text(document):
    return json.dumps(document, separators=(",", ":")).encode()


# 1x1 grey PNG, written out byte for byte (signature, IHDR, IDAT, IEND).
PNG = bytes.fromhex("89504e470d0a1a0a0000000d4948445200000001000000010800000000376ef9240000000a"
                    "49444154789c636800000082008177cd72b60000000049454e44ae426082")

# The secrets beside the case folder: each a valid file of the format a reference names, so a
# run that follows a reference out of the folder succeeds and shows it (the wrong exit, and
# the secret's bytes, hash or path in an output).
SECRET_TAG = b"secret-3f9c2e71"
SECRETS = {
    "mtl": ("secret.mtl", MTL.replace("Kd 0.6 0.5 0.4", "Kd 0.31 0.27 0.23").encode() +
            b"# " + SECRET_TAG + b"\n"),
    "buffer": ("secret.bin", mesh_buffer([[x * 0.8125, y * 0.8125, z * 0.8125]
                                          for x, y, z in CORNERS])),
    "image": ("secret.png", PNG + SECRET_TAG),
}


# The files accuracy.py reads, made once per run of the suite (prepare_tool_files): the room's
# solution as ./simulate --mesh writes it and its reference from build/reference_solution.
_TOOL_FILES = {}
_TOOL_FILES_LOCK = threading.Lock()


def prepare_tool_files(simulate, root):
    with _TOOL_FILES_LOCK:
        if _TOOL_FILES:
            return
        import tempfile
        with tempfile.TemporaryDirectory() as folder:
            folder = Path(folder)
            (folder / "scene.json").write_bytes(json.dumps(ROOM_SCENE).encode())
            subprocess.run([str(simulate), "scene.json", "--quiet", "--mesh", "solution.ply"],
                           cwd=folder, check=True, capture_output=True)
            subprocess.run([str(Path(simulate).parent / "reference_solution"), "scene.json",
                            "--samples", "4", "--refine", "1", "--threads", "1", "--quiet",
                            "--out", "reference.json"], cwd=folder, check=True,
                           capture_output=True)
            _TOOL_FILES["solution"] = (folder / "solution.ply").read_bytes()
            _TOOL_FILES["reference"] = (folder / "reference.json").read_bytes()


def good_content(fmt, root):
    if fmt in _TOOL_FILES:
        return _TOOL_FILES[fmt]
    return {
        "scene": json.dumps(ROOM_SCENE).encode(),
        "obj": OBJ.format(mtl="lamp.mtl").encode(),
        "ply": PLY.encode(),
        "gltf": gltf_text(gltf_document("mesh.bin", "tex.png")),
        "glb": tm.glb(gltf_document(None), BUFFER),
        "mtl": MTL.encode(),
        "buffer": BUFFER,
        "image": PNG,
        "platform": (root / "platforms" / "ncube2.json").read_bytes(),
        "xml": (root / "platforms" / "ncube2.xml").read_bytes(),
        "cost": (root / "platforms" / "cost_model.json").read_bytes(),
        "sweep": json.dumps({"cells": [{"scene": "scene.json", "iterations": 1,
                                        "platform": "platform.json",
                                        "cost_model": "cost.json"}]}).encode(),
    }[fmt]


def hostile_content(fmt, content_class, root):
    good = good_content(fmt, root)
    if content_class != "deep nesting":
        return tm.CONTENTS[content_class](good)
    if fmt == "glb":
        return tm.glb_bytes(tm.NESTING["gltf"](gltf_text(gltf_document(None))), BUFFER)
    return tm.NESTING[fmt](good)


# ---------------------------------------------------------------------------------------------
# The base runs: every file valid, every input a regular file in the case folder.

def base_run(name, folder, root, simulate, refs=None, outputs=True):
    """Writes the files of base run `name` into `folder` and returns (argv, env additions).
    `refs` changes how a model names its files ({"mtl": ..., "buffer": ..., "image": ...});
    `outputs` adds the result file, and for a model the exported scene, so that
    a run that read what it must not is seen in what it wrote."""
    if name in TOOL_RUNS:
        return tool_run(name, folder, root, simulate, outputs)
    refs = {"mtl": "lamp.mtl", "buffer": "mesh.bin", "image": "tex.png", **(refs or {})}
    files = {"platform.json": good_content("platform", root),
             "cost.json": good_content("cost", root)}
    machine = ["--platform", "platform.json", "--cost-model", "cost.json"]
    env = {}
    model = {"scene": "scene.json", "xml": "scene.json", "root": "scene.json", "obj": "model.obj",
             "ply": "model.ply", "gltf": "model.gltf", "glb": "model.glb",
             "sweep-scene": "scene.json", "sweep-obj": "model.obj",
             "sweep-gltf": "model.gltf"}[name]
    files["scene.json"] = good_content("scene", root)
    if model == "model.obj":
        files["model.obj"] = OBJ.format(mtl=refs["mtl"]).encode()
        files["lamp.mtl"] = good_content("mtl", root)
    elif model == "model.ply":
        files["model.ply"] = good_content("ply", root)
    elif model == "model.gltf":
        files["model.gltf"] = gltf_text(gltf_document(refs["buffer"], refs["image"]))
        files["mesh.bin"] = BUFFER
        files["tex.png"] = PNG
    elif model == "model.glb":
        files["model.glb"] = good_content("glb", root)
    if name == "xml":
        files["platform.xml"] = good_content("xml", root)
        machine = ["--platform", "platform.xml", "--cost-model", "cost.json"]
    if name == "root":
        (folder / "root" / "platforms").mkdir(parents=True)
        files["root/platforms/ncube2.json"] = good_content("platform", root)
        files["root/platforms/cost_model.json"] = good_content("cost", root)
        env["NCUBE_ROOT"] = str(folder / "root")
        machine = []
    for path, content in files.items():
        (folder / path).write_bytes(content)
    if name.startswith("sweep"):
        files["sweep.json"] = json.dumps({"cells": [{"scene": model, "iterations": 1,
                                                     "platform": "platform.json",
                                                     "cost_model": "cost.json"}]}).encode()
        (folder / "sweep.json").write_bytes(files["sweep.json"])
        env.update(NCUBE_SIMULATE=str(simulate), NCUBE_ROOT=str(root))
        return ["/usr/bin/python3", str(root / "experiments" / "sweep"), "sweep.json",
                "--check"], env
    argv = [str(simulate), model, *ITERATIONS, *SMALL_PICTURE, *machine]
    if model == "model.ply":
        argv += ["--light", "model"]
    if outputs:
        argv += ["--json", "out.json"]
        if model.startswith("model."):
            argv += ["--export-scene", "out.scene.json"]
    return argv, env


TOOL_RUNS = {"bench", "bench-xml", "reference", "probe", "accuracy", "sweep-slurm"}


def tool_run(name, folder, root, simulate, outputs):
    """The base run `name` of another tool (threat_model.TOOL_INPUTS, TOOL_OUTPUTS): its files
    written into `folder`; returns (argv, env additions). `outputs` adds its usual output."""
    build = Path(simulate).parent
    files, env = {}, {}
    if name in ("bench", "bench-xml"):
        platform = "platform.json" if name == "bench" else "platform.xml"
        files = {platform: good_content("platform" if name == "bench" else "xml", root),
                 "cost.json": good_content("cost", root)}
        argv = [str(build / "network_bench"), "--platform", platform, "--cost-model", "cost.json",
                "--max-bytes", "64", "--round-trips", "1", "--stream-messages", "1", "--quiet"]
        argv += ["--json", "out.json"] if outputs else []
    elif name == "reference":
        files = {"scene.json": good_content("scene", root)}
        argv = [str(build / "reference_solution"), "scene.json", "--samples", "4", "--refine", "1",
                "--threads", "1", "--quiet"]
        argv += ["--out", "out.json"] if outputs else []
    elif name == "probe":
        files = {"platform.xml": (root / "platforms" / "machines" / "cluster-2024.xml").read_bytes(),
                 "cost.json": good_content("cost", root)}
        argv = [str(build / "machine_probe"), "--network", "platform.xml", "--cost-model",
                "cost.json", "--repeats", "3"]
        argv += ["--out", "out.xml"] if outputs else []
    elif name == "accuracy":
        prepare_tool_files(simulate, root)
        # The scene beside the reference: accuracy.py reads which patches emit from the scene
        # the reference names (its scene_sha256), found by the lookup rule.
        files = {"solution.ply": good_content("solution", root),
                 "reference.json": good_content("reference", root),
                 "scene.json": json.dumps(ROOM_SCENE).encode()}
        argv = ["/usr/bin/python3", str(root / "analysis" / "ncube" / "accuracy.py"),
                "solution.ply", "reference.json"]
        argv += ["--json", "out.json"] if outputs else []
    elif name == "sweep-slurm":
        files = {"scene.json": good_content("scene", root),
                 "platform.json": good_content("platform", root),
                 "cost.json": good_content("cost", root),
                 "sweep.json": good_content("sweep", root)}
        env.update(NCUBE_SIMULATE=str(simulate), NCUBE_ROOT=str(root))
        argv = ["/usr/bin/python3", str(root / "experiments" / "sweep"), "sweep.json", "--check",
                "--slurm"]
    else:
        raise ValueError(name)
    for path, content in files.items():
        (folder / path).write_bytes(content)
    return argv, env


# ---------------------------------------------------------------------------------------------
# Path kinds.

def _mknod(path, minor):
    """A character device like /dev/null (3), /dev/zero (5) or /dev/full (7), in the case
    folder; False where the machine does not allow it (not root)."""
    try:
        os.mknod(path, 0o666 | stat.S_IFCHR, os.makedev(1, minor))
        return True
    except PermissionError:
        return False


def _socket(path):
    with socket.socket(socket.AF_UNIX) as s:
        s.bind(str(path))


def make_input(cell, folder, outside, root, simulate):
    """The case folder of an input cell; returns (argv, env, names the message must hold)
    or None when the machine cannot make the kind (devices without root)."""
    surface, kind = cell.surface, cell.kind
    refs = {}
    secret_name = SECRETS.get(surface.ref, ("", b""))[0]
    if kind == "absolute reference":
        refs[surface.ref] = str(outside / secret_name)
    elif kind == "escaping reference":
        refs[surface.ref] = "../outside/" + secret_name
    elif kind == "file URI":
        refs[surface.ref] = "file://" + str(outside / secret_name)
    argv, env = base_run(surface.run, folder, root, simulate, refs)
    if surface.absolute:
        argv[1] = str(folder / argv[1])
    target = folder / surface.file
    good = target.read_bytes()
    names = [Path(surface.file).name] + ([surface.named_by] if surface.named_by else [])
    if kind in ("absolute reference", "escaping reference", "file URI"):
        names = [secret_name, surface.named_by]   # the reference as the model spells it
    if cell.direction == "content":
        # Bad content in a file a model names is told by the model and the item that uses it
        # ("model.obj: line 10: usemtl light: ..."): the model is what the user named.
        names = [surface.named_by or Path(surface.file).name]
        target.write_bytes(hostile_content(surface.fmt, kind, root))
        return argv, env, names
    if kind in ("regular", "absolute reference", "escaping reference", "file URI"):
        return argv, env, names
    target.unlink()
    real = target.with_name(target.name + ".real")
    if kind == "link":
        real.write_bytes(good)
        target.symlink_to(real.name)
    elif kind == "dangling link":
        target.symlink_to(real.name)
    elif kind == "link loop":
        target.symlink_to(target.name + ".loop")
        target.with_name(target.name + ".loop").symlink_to(target.name)
    elif kind == "link out of the folder":
        target.symlink_to(outside / secret_name)
    elif kind == "fifo":
        os.mkfifo(target)
    elif kind == "char device":
        if not _mknod(target, 3):
            return None
    elif kind == "folder":
        target.mkdir()
    elif kind == "socket":
        _socket(target)
    elif kind == "endless via link":
        if not _mknod(real, 5):
            return None
        target.symlink_to(real.name)
    elif kind == "huge":
        with open(target, "wb") as f:
            f.write(good)
            f.truncate(tm.HUGE_BYTES_OF.get(surface.fmt, tm.HUGE_BYTES))
    else:
        raise ValueError(kind)
    return argv, env, names


def make_output(cell, folder, root, simulate):
    """The case folder of an output cell; returns (argv, env, the path named, what it must be
    afterwards, the file that must hold the output) or None (devices without root)."""
    output, kind = cell.surface, cell.kind
    if output.run:   # another tool's output (threat_model.TOOL_OUTPUTS)
        argv, env = base_run(output.run, folder, root, simulate, outputs=False)
        return _output_path(cell, folder, argv, env)
    base = "scene"
    if output.model_only or kind in ("is model.obj", "is lamp.mtl"):
        base = "obj"
    if kind in ("is model.gltf", "is mesh.bin", "is tex.png"):
        base = "gltf"
    if kind == "is platform.xml":
        base = "xml"
    if output.model_only and base == "xml":
        base = "obj"   # the OBJ run with the XML platform written beside it
    argv, env = base_run(base, folder, root, simulate, outputs=False)
    if kind == "is platform.xml":
        (folder / "platform.xml").write_bytes(good_content("xml", root))
        if base == "obj":
            argv[argv.index("platform.json")] = "platform.xml"
    return _output_path(cell, folder, argv, env)


def _output_path(cell, folder, argv, env):
    """Makes the output path of `cell` in `folder`; adds it to the base run's argv and env."""
    output, kind = cell.surface, cell.kind
    name = "out" + output.suffix
    path, after, holder = folder / name, tm.OUTPUT_KINDS.get(kind, (None, None, False))[1], None
    if kind.startswith("is "):
        name = kind[3:]
        path, after = folder / name, "file"
    elif kind == "new":
        holder = path
    elif kind == "regular":
        path.write_text("old")
        holder = path
    elif kind in ("link", "dangling link"):
        real = folder / (name + ".real")
        if kind == "link":
            real.write_text("old")
        path.symlink_to(real.name)
        holder = real
    elif kind == "link loop":
        path.symlink_to(name + ".loop")
        (folder / (name + ".loop")).symlink_to(name)
    elif kind == "fifo":
        os.mkfifo(path)
    elif kind in ("null device", "full device"):
        if not _mknod(path, 3 if kind == "null device" else 7):
            return None
    elif kind == "endless device via link":
        if not _mknod(folder / (name + ".zero"), 5):
            return None
        path.symlink_to(name + ".zero")
    elif kind == "folder":
        path.mkdir()
    elif kind == "socket":
        _socket(path)
    elif kind == "missing folder":
        name = "nowhere/" + name
        path = folder / name
    else:
        raise ValueError(kind)
    argv += [a.replace("PATH", name) for a in output.args]
    env.update({k: v.replace("PATH", name) for k, v in output.env})
    return argv, env, path, after, holder


# ---------------------------------------------------------------------------------------------
# What a folder holds: checked before and after the run.

def snapshot(folder):
    """{relative path: identity} of everything under `folder`, links not followed: a regular
    file by its bytes' hash (by size and time when over 1 MiB: the sparse huge files), a link by
    its target, anything else by its type."""
    seen = {}
    for dirpath, dirnames, filenames in os.walk(folder):
        for name in dirnames + filenames:
            path = Path(dirpath) / name
            info = os.lstat(path)
            key = str(path.relative_to(folder))
            if stat.S_ISLNK(info.st_mode):
                seen[key] = ("link", os.readlink(path))
            elif stat.S_ISREG(info.st_mode):
                if info.st_size > (1 << 20):
                    seen[key] = ("file", info.st_size, info.st_mtime_ns)
                else:
                    seen[key] = ("file", hashlib.sha256(path.read_bytes()).hexdigest())
            else:
                seen[key] = (stat.S_IFMT(info.st_mode),)
    return seen


KIND_TESTS = {"link": stat.S_ISLNK, "char": stat.S_ISCHR, "fifo": stat.S_ISFIFO,
              "socket": stat.S_ISSOCK, "folder": stat.S_ISDIR, "file": stat.S_ISREG}


def leak_markers(outside):
    """What an output must never hold: each secret's bytes, their SHA-256 and their path."""
    markers = [SECRET_TAG]
    for name, content in SECRETS.values():
        markers += [content, hashlib.sha256(content).hexdigest().encode(),
                    str(outside / name).encode()]
    return markers


def _atime_tells_reads():
    """Whether this file system notes a read in the access time of a file whose access time is
    older than its change (relatime, strictatime; not noatime)."""
    probe = Path(os.environ.get("TMPDIR", "/tmp")) / f"robustness-atime-{os.getpid()}"
    probe.write_bytes(b"x")
    try:
        os.utime(probe, (time.time() - 10000, time.time()))
        before = os.stat(probe).st_atime_ns
        probe.read_bytes()
        return os.stat(probe).st_atime_ns != before
    finally:
        probe.unlink()


ATIME_TELLS_READS = _atime_tells_reads()


def secret_reads(outside):
    """Sets the secrets' access times in the past; returns a function naming those read since
    (reading, not stat or open, moves the access time), or none where the file system does not
    tell (noatime)."""
    if not ATIME_TELLS_READS:
        return lambda: []
    times = {}
    for name, _ in SECRETS.values():
        os.utime(outside / name, (time.time() - 10000, os.stat(outside / name).st_mtime))
        times[name] = os.stat(outside / name).st_atime_ns
    return lambda: [n for n, t in times.items() if os.stat(outside / n).st_atime_ns != t]


def _drain(path, received):
    with open(path, "rb") as f:
        received.append(len(f.read()))


def _release(path):
    """Unblocks a reader still waiting on a FIFO nobody opened for writing."""
    try:
        os.close(os.open(path, os.O_WRONLY | os.O_NONBLOCK))
    except OSError:
        pass


EXIT = {"ok": 0, "error": 2, "failed": 4, "write": 5}
# A line of the summary ./simulate prints once the simulation has run.
RUN_SUMMARY = "simulated seconds"


def refused_before_run(cell, outcome):
    """Bad input (exit 2) and an output path that can never be written (a folder, a socket)
    are refused before the simulation starts (docs/cli.md, "Output files")."""
    return outcome == "error" or (outcome == "write" and cell.kind in ("folder", "socket"))


def _blocked_on_fifo(session):
    """Whether a process of `session` waits in the kernel for the other end of a FIFO (wchan
    wait_for_partner): with nobody to open that end, it would wait forever."""
    for entry in os.scandir("/proc"):
        if not entry.name.isdigit():
            continue
        try:
            fields = Path(f"/proc/{entry.name}/stat").read_text().rsplit(")", 1)[1].split()
            if int(fields[3]) == session and \
                    Path(f"/proc/{entry.name}/wchan").read_text() == "wait_for_partner":
                return True
        except (OSError, ValueError, IndexError):
            continue
    return False


def execute(argv, env, cwd, timeout, memory_bytes):
    """Runs argv; returns (exit code or None when it hangs, stderr text or why it hangs, peak
    RSS in MiB, seconds, stdout text). A run hangs when still running at `timeout`, or as soon
    as it has waited a second for the other end of a FIFO (a hang costs about 2 s, not the
    timeout). ./simulate's runs are forked from build/simulate_server (forked_runs.py), the
    other programs' started anew."""
    start = time.monotonic()
    if forked_runs.server_binary(argv[0]):
        run = forked_runs.Run(argv[0], argv[1:], cwd=cwd, env={**os.environ, **env},
                              as_bytes=memory_bytes, fsize_bytes=1 << 30,
                              stdin=None, capture_stdout=True)
        pid, ended = run.pid, run.wait
    else:
        # The limits set by util-linux's prlimit, which then execs the program: no preexec_fn,
        # so the run is spawned without a fork of this process (run.py's note).
        limits = ["/usr/bin/prlimit", f"--as={memory_bytes}", "--core=0", f"--fsize={1 << 30}",
                  "--"]
        run = subprocess.Popen([*limits, *argv], cwd=cwd, env={**os.environ, **env},
                               stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, start_new_session=True)
        pid, ended = run.pid, _started_waiter(run)
    # The look at /proc reads every process's stat (hundreds on a shared host): a run that ends
    # within a second, as nearly every cell does, costs none; a hang costs about 2 s.
    blocked_since, next_look = None, start + 1.0
    while not ended(0.01):
        now = time.monotonic()
        if now >= next_look:
            next_look = now + 0.5
            blocked = _blocked_on_fifo(pid)
            blocked_since = (blocked_since or now) if blocked else None
        why = (f"still running after {timeout:g} s" if now - start > timeout else
               "waits forever for the other end of a FIFO"
               if blocked_since and now - blocked_since > 1 else None)
        if why:
            os.killpg(pid, signal.SIGKILL)
            ended(None)
            return None, why, 0, time.monotonic() - start, ""
    try:
        os.killpg(pid, signal.SIGKILL)   # anything it left running
    except ProcessLookupError:
        pass
    return (run.code, run.stderr.decode(errors="replace"), run.maxrss_kb / 1024,
            time.monotonic() - start, run.stdout.decode(errors="replace"))


def _started_waiter(process):
    """For a Popen: wait(timeout) as forked_runs.Run's (True once ended; then code, maxrss_kb,
    stdout and stderr set on `process`)."""
    chunks, printed = [], []
    readers = [threading.Thread(target=lambda: chunks.append(process.stderr.read()), daemon=True),
               threading.Thread(target=lambda: printed.append(process.stdout.read()), daemon=True)]
    for reader in readers:
        reader.start()

    def ended(timeout):
        deadline = None if timeout is None else time.monotonic() + timeout
        while True:
            pid, status, usage = os.wait4(process.pid, os.WNOHANG)
            if pid:
                break
            if deadline is not None and time.monotonic() >= deadline:
                return False
            time.sleep(0.01 if timeout is None else min(0.01, timeout))
        process.returncode = process.code = os.waitstatus_to_exitcode(status)
        process.maxrss_kb = usage.ru_maxrss
        for reader in readers:
            reader.join(timeout=5)
        process.stdout, process.stderr = b"".join(printed), b"".join(chunks)
        return True
    return ended


# What machine_probe says when a fit gave no rate (exit 4): the host too disturbed to measure,
# as under the suite's other jobs. The cell then runs again, up to this many times in all: its
# question is where the output goes, not whether this host can be measured now.
PROBE_DISTURBED = "the host was too disturbed"
PROBE_ATTEMPTS = 3


def run_cell(cell, work, root, simulate, timeout, memory_bytes, attempt=1):
    """Makes the cell's folders, runs it and checks it: (clean, detail, seconds), or None when
    the machine cannot make the cell's kind."""
    case = work / (cell.id.replace("/", "_").replace(" ", "_").replace(":", "")
                   + (f".attempt{attempt}" if attempt > 1 else ""))
    folder, outside = case / "in", case / "outside"
    folder.mkdir(parents=True)
    outside.mkdir()
    for name, content in SECRETS.values():
        (outside / name).write_bytes(content)
    before_outside = snapshot(outside)
    secrets_read = secret_reads(outside)
    after_kind, holder, reader, received = None, None, None, []
    if cell.direction == "write":
        made = make_output(cell, folder, root, simulate)
        if made is None:
            return None
        argv, env, named, after_kind, holder = made
        names = [named.name]
        if stat.S_ISFIFO(os.lstat(named).st_mode) if os.path.lexists(named) else False:
            reader = threading.Thread(target=_drain, args=(named, received), daemon=True)
            reader.start()
    else:
        made = make_input(cell, folder, outside, root, simulate)
        if made is None:
            return None
        argv, env, names = made
        named = None
    before = snapshot(folder)

    code, message, rss, seconds, printed = execute(argv, env, folder, timeout, memory_bytes)
    if reader:
        reader.join(timeout=2)
        if reader.is_alive():
            _release(named)
            reader.join(timeout=2)

    if code is None:
        return False, message, seconds
    if (code == EXIT.get("failed", 4) and PROBE_DISTURBED in message
            and getattr(cell.surface, "run", None) == "probe" and attempt < PROBE_ATTEMPTS):
        return run_cell(cell, work, root, simulate, timeout, memory_bytes, attempt + 1)
    outcome = {v: k for k, v in EXIT.items()}.get(code)
    problems = []
    if outcome not in cell.expect:
        want = " or ".join(f"{EXIT[e]}" for e in sorted(cell.expect))
        problems.append(f"exit {code}, expected {want}: {message.strip()[:160]!r}")
    if outcome in cell.expect and refused_before_run(cell, outcome) and RUN_SUMMARY in printed:
        problems.append("refused only after the simulation ran (its summary was printed)")
    if cell.direction != "write" and rss > tm.MAX_RSS_MB:
        problems.append(f"peak memory {rss:.0f} MiB")
    now = snapshot(folder)
    allowed = set()
    if code == 0:
        allowed = {str(p.relative_to(folder)) for p in folder.glob("out*")
                   if not os.path.lexists(p) or not p.is_symlink()}
        if holder is not None:
            allowed.add(str(holder.relative_to(folder)))
    changed = sorted(k for k in set(before) | set(now)
                     if before.get(k) != now.get(k) and k not in allowed)
    partial = sorted(k for k in now if ".partial" in k)
    if partial:
        problems.append("left " + ", ".join(partial))
    changed = [k for k in changed if k not in partial]
    if changed:
        problems.append("changed or created " + ", ".join(changed[:4]))
    read = secrets_read()
    if read:
        problems.append("read " + ", ".join(read) + " beside the case folder")
    if snapshot(outside) != before_outside:
        problems.append("changed the folder beside the case folder")
    markers = leak_markers(outside)
    for key in now:
        path = folder / key
        if key in before and before[key] == now[key] or not path.is_file() or path.is_symlink():
            continue
        if path.stat().st_size < (64 << 20):
            data = path.read_bytes()
            leaked = [m for m in markers if m in data]
            if leaked:
                problems.append(f"{key} holds a secret's bytes, hash or path")
    if cell.direction == "write" and after_kind and named is not None:
        info = os.lstat(named) if os.path.lexists(named) else None
        if info is None or not KIND_TESTS[after_kind](info.st_mode):
            problems.append(f"{named.name} is no longer a {after_kind}")
        if code == 0 and holder is not None:
            data = holder.read_bytes() if holder.is_file() else None
            if data is None or data == b"old" or (cell.surface.content and not data):
                problems.append(f"{holder.name} was not written")
        if code == 0 and reader and cell.surface.content and not sum(received):
            problems.append("nothing reached the FIFO's reader")
    if code not in (0, None) and outcome in cell.expect:
        lines = message.strip().splitlines()
        if not lines or len(lines) > 2 or len(message) > 2000:
            problems.append(f"message of {len(lines)} lines, {len(message)} bytes")
        # A measurement that failed (machine_probe's 4) is about the host, not about a file.
        missing = [n for n in names if n not in message] if outcome != "failed" else []
        if missing:
            problems.append(f"the message does not name {', '.join(missing)}")
    if problems:
        return False, "; ".join(problems), seconds
    return True, message.strip()[:160], seconds
