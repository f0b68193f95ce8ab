"""The threat model of ./simulate and experiments/sweep (issue 30): every file the process reads,
every file it writes, every kind of path such a file can be, every hostile content, and the
outcome the rules require of each cell. tests/robustness/run.py crosses them
(tests/robustness/threat_cases.py makes and checks each cell), so a new input or output joins
the suite by being listed here.

The rules (docs/cli.md, "Output files"; issue 30, "What to build" 1 and 2):
  reads    a file that is not a regular file (FIFO, device, folder, socket, an endless file
           behind a link), a dangling link, a loop of links, a file over the size limit, bad
           content: exit 2, one line naming the file (and for a file a model names, the model);
           never a hang, never the whole file in memory.
           A file a model names must resolve inside the model's folder: an absolute reference,
           a file: URI, a `..` out of the folder or a link out of it is refused (exit 2); one
           the run never opens (a glTF image) may also be ignored, but never read.
  writes   docs/cli.md's table: a new or regular file replaced whole, a link's target written
           (the link stays), a FIFO or character device streamed and never replaced, a folder
           or socket exit 5, a loop of links or a missing folder exit 2, an output that is any
           input of the run (the model and every file it names too) exit 2.
  always   nothing outside what the user named is read or written: the case folder holds
           afterwards only what it held plus the named outputs (none after a failure, no
           `.partial*`), the folder beside it is untouched and unread (access times), and no
           output holds the bytes, the hash or the path of a file the run was not allowed to read.

Outcomes: "ok" (exit 0), "error" (exit 2), "write" (exit 5).
"""
import json
import struct
import subprocess
from dataclasses import dataclass, field

# Larger than every per-kind size limit (scene and model files: 256 MiB, platform and cost
# model: 1 MiB); made sparse, so it costs no disk.
HUGE_BYTES = (256 << 20) + 4096
# Formats whose limit is larger: over it (analysis/ncube/accuracy.py's MESH_BYTES, REFERENCE_BYTES).
HUGE_BYTES_OF = {"solution": (1 << 30) + 4096, "reference": (512 << 20) + 4096}
# Peak memory of a run that reads an input (the tiny room: about 50 MiB as a scene, 70 MiB as
# a model; the sweep tool less): reading a huge or endless input whole goes far past it.
MAX_RSS_MB = 200


# ---------------------------------------------------------------------------------------------
# Inputs: every file a run reads. `run` is the base command that reads it
# (threat_cases.base_run), `file` its name in the case folder.

@dataclass(frozen=True)
class Input:
    id: str
    file: str               # its name in the case folder (relative)
    fmt: str                # its format, for the content classes below
    run: str                # the base run that reads it (threat_cases.base_run)
    named_by: str = ""      # the model file whose reference names it ("" : named by the user)
    ref: str = ""           # which reference of the model it is: "mtl", "buffer", "image"
    uri: bool = False       # the reference is a URI (glTF), so a file: URI applies
    read: bool = True       # the run opens it (a glTF image is only named: its kinds may be
                            # refused or ignored, but never followed out of the folder)
    absolute: bool = False  # the model named by its absolute path (on main 0f2337f a model's
                            # references were resolved differently for the two)


INPUTS = [
    Input("scene", "scene.json", "scene", "scene"),
    Input("model .obj", "model.obj", "obj", "obj"),
    Input("model .ply", "model.ply", "ply", "ply"),
    Input("model .gltf", "model.gltf", "gltf", "gltf"),
    Input("model .glb", "model.glb", "glb", "glb"),
    Input("OBJ mtllib", "lamp.mtl", "mtl", "obj", "model.obj", "mtl"),
    Input("glTF buffer", "mesh.bin", "buffer", "gltf", "model.gltf", "buffer", uri=True),
    Input("glTF image", "tex.png", "image", "gltf", "model.gltf", "image", uri=True, read=False),
    Input("OBJ mtllib, model by absolute path", "lamp.mtl", "mtl", "obj", "model.obj", "mtl",
          absolute=True),
    Input("glTF buffer, model by absolute path", "mesh.bin", "buffer", "gltf", "model.gltf",
          "buffer", uri=True, absolute=True),
    Input("--platform JSON", "platform.json", "platform", "scene"),
    Input("--platform SimGrid XML", "platform.xml", "xml", "xml"),
    Input("--cost-model", "cost.json", "cost", "scene"),
    # Environment: NCUBE_ROOT names the folder of the default platform and cost model
    # (NCUBE_RECORD_ACTIVITIES is an output below; NCUBE_ANSWER_CACHE_MB is a number, no file).
    Input("NCUBE_ROOT platform", "root/platforms/ncube2.json", "platform", "root"),
    Input("sweep file", "sweep.json", "sweep", "sweep-scene"),
    Input("sweep OBJ mtllib", "lamp.mtl", "mtl", "sweep-obj", "model.obj", "mtl"),
    Input("sweep glTF buffer", "mesh.bin", "buffer", "sweep-gltf", "model.gltf", "buffer",
          uri=True),
    Input("sweep glTF image", "tex.png", "image", "sweep-gltf", "model.gltf", "image", uri=True,
          read=False),
]

# The other programs and scripts (issue 37, item 6), each with the files it reads; a new tool
# or input joins by being listed here and given its base run in threat_cases.base_run. Their
# path kinds are a representative subset (TOOL_INPUT_KINDS): every tool opens through the one
# gate (src/util/input_file.h, analysis/ncube/input_file.py), which the full set above holds
# for ./simulate and the sweep tool.
TOOL_INPUTS = [
    Input("network_bench --platform JSON", "platform.json", "platform", "bench"),
    Input("network_bench --platform XML", "platform.xml", "xml", "bench-xml"),
    Input("network_bench --cost-model", "cost.json", "cost", "bench"),
    Input("reference_solution scene", "scene.json", "scene", "reference"),
    Input("machine_probe --network", "platform.xml", "xml", "probe"),
    Input("machine_probe --cost-model", "cost.json", "cost", "probe"),
    Input("accuracy.py solution", "solution.ply", "solution", "accuracy"),
    Input("accuracy.py reference", "reference.json", "reference", "accuracy"),
    Input("sweep --slurm sweep file", "sweep.json", "sweep", "sweep-slurm"),
]
TOOL_INPUTS_BY_ID = {surface.id: surface for surface in TOOL_INPUTS}
# The gate's branches (src/util/input_file.h, analysis/ncube/input_file.py: every kind of link
# is held for ./simulate above): a plain read, a FIFO, a folder, a huge file.
TOOL_INPUT_KINDS = ["regular", "fifo", "folder", "huge"]
# machine_probe times its kernels (about 2 s a run that gets that far): fewer kinds, so that
# robustness_test stays under about 90 s on the loaded machine.
PROBE_INPUT_KINDS = ["regular", "dangling link", "fifo", "huge"]
PROBE_OUTPUT_KINDS = ["new", "link", "fifo", "folder", "missing folder"]

# Every kind of path an input can be. Each is made in the case folder (devices with mknod
# there, never the machine's /dev). "reference" kinds change how the model names the file.
INPUT_KINDS = [
    "regular", "link", "dangling link", "link loop", "fifo", "char device", "folder", "socket",
    "endless via link", "huge",
    # files a model names only:
    "absolute reference", "escaping reference", "link out of the folder", "file URI",
]
MODEL_ONLY_KINDS = {"absolute reference", "escaping reference", "link out of the folder",
                    "file URI"}


# A file a model names, read for the sweep tool by ./simulate --list-inputs: through the same
# C++ gate and reference rule that every kind holds for ./simulate's own reads above, so the
# kinds that show the sweep asks it (not a reader of its own): a regular file, a FIFO and a
# huge file (which the sweep's own hashing of what is listed must not read) and one reference
# out of the folder (which the sweep must pass on as ./simulate's refusal; the other three
# reference kinds take the same way through the sweep, and each is held for ./simulate itself).
SWEEP_PART_KINDS = ["regular", "fifo", "huge", "escaping reference"]


# The C++ gate's branches for a file the user names (a dangling link, a loop of links, a
# character device, a socket, an endless device behind a link: src/util/input_file.h, one
# function whatever the input) are held through the scene; the other inputs ./simulate reads
# by their own names (a model, a platform, a cost model, the platform NCUBE_ROOT finds) meet
# the kinds that show the input goes through the gate at all, each of which a reader of its own
# would get wrong (a FIFO hangs it, a huge file fills its memory, a folder is no file), a
# plain file and a link to one (a model's references are resolved from the folder of the
# name given). The files a model names meet every kind (the model's reference rule decides
# first), and the sweep file every kind (the Python gate, analysis/ncube/input_file.py).
GATE_USE_KINDS = ["regular", "link", "fifo", "folder", "huge"]
ALL_KINDS_INPUTS = {"scene", "sweep file"}


def input_kinds(surface):
    if surface in TOOL_INPUTS:
        if surface.run == "probe" and surface is not TOOL_INPUTS_BY_ID["machine_probe --network"]:
            # Its plain run is the --network cell's very command (both files regular).
            return [k for k in PROBE_INPUT_KINDS if k != "regular"]
        return PROBE_INPUT_KINDS if surface.run == "probe" else TOOL_INPUT_KINDS
    kinds = [k for k in INPUT_KINDS if surface.named_by or k not in MODEL_ONLY_KINDS]
    if surface.run.startswith("sweep-") and surface.named_by:
        kinds = [k for k in kinds if k in SWEEP_PART_KINDS]
    if surface.absolute:   # only where the model's own path matters
        kinds = ["regular", "link", *MODEL_ONLY_KINDS]
    elif not surface.named_by and surface.id not in ALL_KINDS_INPUTS:
        kinds = [k for k in kinds if k in GATE_USE_KINDS]
    elif not surface.read:
        # Named, never opened: a FIFO (an open would hang) and a huge file (a read would fill
        # memory) show it is not read; the other kinds of path are only other things not to
        # open. The references out of the folder are the model's rule's.
        kinds = [k for k in kinds if k in ("regular", "fifo", "huge") or k in MODEL_ONLY_KINDS]
    return [k for k in kinds if k != "file URI" or surface.uri]


def input_expect(surface, kind):
    """The outcomes the rules allow for `surface` made a path of `kind`."""
    if kind in ("regular", "link"):
        return {"ok"}
    if not surface.read:
        # Never opened (Assimp keeps an image's name only): refusing it is as good as ignoring
        # it, even out of the folder (exported models often name absolute texture paths), as
        # long as nothing beside the case folder is read (threat_cases.secret_reads).
        return {"ok", "error"}
    return {"error"}


# Hostile content, by format: (class, content maker, outcome). The file stays a regular file
# named as usual; a content class that does not apply to a format is not listed for it.
def _nested_json(depth):
    return ("[" * depth + "]" * depth).encode()


def _garbage():
    # Fixed bytes (no randomness: the same cells every run): NUL, invalid UTF-8, control bytes.
    return bytes((i * 151 + 7) % 256 for i in range(4096))


CONTENTS = {
    "empty": lambda good: b"",
    "garbage": lambda good: _garbage(),
    "truncated": lambda good: good[:len(good) // 2],
    "deep nesting": None,   # per format, below
}
NESTING = {
    "scene": lambda good: _nested_json(100000),
    "platform": lambda good: _nested_json(100000),
    "cost": lambda good: _nested_json(100000),
    "sweep": lambda good: _nested_json(100000),
    "reference": lambda good: _nested_json(100000),
    # A glTF that is valid but for 100,000 levels of `extras` (Assimp recurses on them).
    "gltf": lambda good: good.replace(b'"asset":{', b'"asset":{"extras":' + b'{"a":' * 100000 +
                                      b'1' + b'}' * 100000 + b',', 1),
    # "glb": the glTF's nesting inside the container (threat_cases.hostile_content)
    "xml": lambda good: good.replace(b"<platform version=\"4.1\">",
                                     b"<platform version=\"4.1\">" + b"<zone>" * 100000, 1),
}
# Which classes apply to which format. Every one must be refused (exit 2): an empty or cut
# file, bytes that are no such file, nesting past any parser's stack.
CONTENT_CLASSES = {
    "scene": ["empty", "garbage", "truncated", "deep nesting"],
    "obj": ["empty", "garbage"],              # half an OBJ is still an OBJ
    "ply": ["empty", "garbage", "truncated"],
    "gltf": ["empty", "garbage", "truncated", "deep nesting"],
    "glb": ["empty", "garbage", "truncated", "deep nesting"],
    "mtl": ["empty", "garbage"],              # the model's materials then name nothing
    "buffer": ["empty", "truncated"],         # any 4 bytes are a float
    "image": [],                              # never decoded
    "platform": ["empty", "garbage", "truncated", "deep nesting"],
    "xml": ["empty", "garbage", "truncated", "deep nesting"],
    "cost": ["empty", "garbage", "truncated", "deep nesting"],
    "sweep": ["empty", "garbage", "truncated", "deep nesting"],
    "solution": ["empty", "garbage", "truncated"],    # a solution mesh (PLY) for accuracy.py
    "reference": ["empty", "garbage", "truncated", "deep nesting"],   # reference_solution's file
}


# ---------------------------------------------------------------------------------------------
# Outputs: every file a run writes. The options come from `simulate --describe-options`
# (kind "output"), so a new output option joins by being described; the others are here.

@dataclass(frozen=True)
class Output:
    id: str
    suffix: str             # the file name's ending (--mesh writes PLY and says so by name)
    model_only: bool        # applies to model files only (--export-scene)
    args: tuple = ()        # the command-line words, PATH standing for the path
    env: tuple = ()         # (variable, value) pairs, PATH standing for the path
    content: bool = True    # a run always writes bytes to it (a log may stay empty)
    run: str = ""           # the base run (threat_cases.base_run) of another tool; "": ./simulate
    inputs: tuple = ()      # another tool's inputs an output may not be (OUTPUT_IS_INPUT's)


SUFFIXES = {"--mesh": ".ply", "--image": ".png"}

EXTRA_OUTPUTS = [
    Output("NCUBE_RECORD_ACTIVITIES", ".act", False, env=(("NCUBE_RECORD_ACTIVITIES", "PATH"),)),
    Output("--log file appender", ".log", False, args=("--log=root.app:file:PATH",),
           content=False),
    Output("--cfg tracing/filename", ".paje", False,
           args=("--cfg=tracing:yes", "--cfg=tracing/filename:PATH")),
]


# The other tools' outputs (issue 37, item 6), under the same rule: args with PATH for the
# path, `inputs` the files of its base run it must refuse to write onto.
TOOL_OUTPUTS = [
    Output("network_bench --json", ".json", False, ("--json", "PATH"), run="bench",
           inputs=("platform.json", "cost.json")),
    Output("reference_solution --out", ".json", False, ("--out", "PATH"), run="reference",
           inputs=("scene.json",)),
    Output("reference_solution --mesh", ".ply", False, ("--out", "out.json", "--mesh", "PATH"),
           run="reference", inputs=("scene.json",)),
    Output("machine_probe --out", ".xml", False, ("--out", "PATH"), run="probe",
           inputs=("platform.xml", "cost.json")),
    Output("accuracy.py --json", ".json", False, ("--json", "PATH"), run="accuracy",
           inputs=("solution.ply", "reference.json")),
]
# The page scripts (analysis/*.py with a main): each either runs under ncube.page's output rule
# (page.refusing_outputs: an output onto an input is one line and exit 2), which
# tests/page_outputs_test.sh holds for report.py end to end and checks every script listed
# "held" declares, or is listed open with why. They run simulations or need finished results,
# so they get no cells here; a new page script joins by being listed (the test fails on one
# that is not).
PAGE_SCRIPTS = {
    "report.py": "held", "predictions.py": "held", "adaptive.py": "held",
    "patch_order.py": "held", "memory_sensitivity.py": "held", "calibrate.py": "held",
    "claims.py": "held", "claims_schemes.py": "held", "claims_hemicube.py": "held", "machines.py": "held", "unknowns.py": "held",
    "headline.py": "held", "openings.py": "held",
}


def outputs(simulate):
    described = json.loads(subprocess.run([str(simulate), "--describe-options"], check=True,
                                          capture_output=True, text=True).stdout)
    listed = [Output(o["flag"], SUFFIXES.get(o["flag"], ".out"),
                     o.get("applies_to") == "model files", args=(o["flag"], "PATH"))
              for o in described if o["kind"] == "output"]
    assert len(listed) >= 5, "simulate --describe-options lists fewer outputs than expected"
    return listed + EXTRA_OUTPUTS


# Every kind of output path and what the run must end with (docs/cli.md, "Output files"):
# (outcome, what the path must still be afterwards, whether a file must hold the output).
OUTPUT_KINDS = {
    "new": ("ok", "file", True),
    "regular": ("ok", "file", True),
    "link": ("ok", "link", True),
    "dangling link": ("ok", "link", True),
    "link loop": ("error", "link", False),
    "fifo": ("ok", "fifo", False),
    "null device": ("ok", "char", False),
    "full device": ("write", "char", False),
    "endless device via link": ("ok", "link", False),
    "folder": ("write", "folder", False),
    "socket": ("write", "socket", False),
    "missing folder": ("error", None, False),
}
# The kinds and inputs an output option of ./simulate other than --json meets (cells()).
SHARED_RULE_KINDS = ["new", "link", "dangling link", "fifo", "null device", "full device",
                     "folder", "missing folder"]
SHARED_RULE_INPUTS = ["scene.json", "model.obj", "lamp.mtl", "platform.json"]
# An output named as one of the run's inputs: exit 2 (which inputs: threat_cases.base_run).
OUTPUT_IS_INPUT = ["scene.json", "model.obj", "lamp.mtl", "model.gltf", "mesh.bin", "tex.png",
                   "platform.json", "platform.xml", "cost.json"]


# ---------------------------------------------------------------------------------------------
# The issue's classes: the rows of the table run.py prints.

def issue_class(kind, direction):
    if direction == "content":
        return "hostile content"
    if direction == "write":
        return "output is an input" if kind.startswith("is ") else "outputs under the output rule"
    if kind in MODEL_ONLY_KINDS:
        return "model reads outside its folder"
    if kind in ("regular", "link"):
        return "plain inputs run"
    return "input not a regular file, endless, huge"


@dataclass
class Cell:
    id: str                 # unique, stable: what KNOWN_OPEN lists
    direction: str          # "read", "content" or "write"
    surface: object         # an Input or an Output
    kind: str               # the path kind, content class or "is <input>"
    expect: set = field(default_factory=set)

    @property
    def klass(self):
        return issue_class(self.kind, self.direction)


# machine_probe times its kernels on a shared host: a fit that the host disturbed ends in exit 4
# with nothing written (docs/cli.md, "machine_probe"), as clean an end as 0 for a run that gets
# that far; and its runs get PROBE_TIME_FACTOR times the cell timeout (about 2.5 s of CPU each
# on an idle core, several of them at once beside the rest of the suite).
PROBE_TIME_FACTOR = 5


def probe_expect(expect):
    return expect | {"failed"} if "ok" in expect else expect


def time_factor(cell):
    return PROBE_TIME_FACTOR if getattr(cell.surface, "run", "") == "probe" else 1


def cells(simulate):
    found = []
    for surface in INPUTS + TOOL_INPUTS:
        for kind in input_kinds(surface):
            expect = input_expect(surface, kind)
            found.append(Cell(f"read {surface.id} / {kind}", "read", surface, kind,
                              probe_expect(expect) if surface.run == "probe" else expect))
        contents = CONTENT_CLASSES[surface.fmt] if not surface.absolute else []
        if surface.run.startswith("sweep-") and surface.named_by:
            contents = contents[:1]   # its content is ./simulate's to read (held above)
        for content in contents if surface.run != "probe" else ["garbage", "deep nesting"]:
            found.append(Cell(f"content {surface.id} / {content}", "content", surface, content,
                              {"error"}))
    for output in TOOL_OUTPUTS:
        for kind in PROBE_OUTPUT_KINDS if output.run == "probe" else SHARED_RULE_KINDS:
            expect = {OUTPUT_KINDS[kind][0]}
            found.append(Cell(f"write {output.id} / {kind}", "write", output, kind,
                              probe_expect(expect) if output.run == "probe" else expect))
        for name in output.inputs:
            found.append(Cell(f"write {output.id} / is {name}", "write", output, f"is {name}",
                              {"error"}))
    for output in outputs(simulate):
        # Every output of ./simulate writes through the one output rule
        # (src/tools/output_files.cpp): --json meets every kind of path and every input, each
        # other output the kinds that take each branch of the rule and four inputs (a scene, a
        # model, a file a model names, a platform). SimGrid's own writers (EXTRA_OUTPUTS) and
        # the activity record get their paths from a setting or the environment
        # (src/machine/simgrid_outputs.h), then the same rule's temporary files: they too meet
        # each branch, the others being the rule's own, held through --json.
        whole = output.id == "--json"
        for kind, (outcome, _, _) in OUTPUT_KINDS.items():
            if not whole and kind not in SHARED_RULE_KINDS:
                continue
            # A full device refuses bytes, not the lack of them: an output that may stay empty
            # (a log with nothing to say) ends well there.
            if kind == "full device" and not output.content:
                outcome = "ok"
            found.append(Cell(f"write {output.id} / {kind}", "write", output, kind, {outcome}))
        for name in OUTPUT_IS_INPUT:
            if output.model_only and name in ("scene.json",):
                continue
            if not whole and name not in SHARED_RULE_INPUTS:
                continue
            found.append(Cell(f"write {output.id} / is {name}", "write", output, f"is {name}",
                              {"error"}))
    ids = [c.id for c in found]
    assert len(ids) == len(set(ids)), "cell ids must be unique"
    return found


# A glb: the glTF JSON and its binary chunk in one container (glTF 2.0, "GLB File Format").
def glb_bytes(text, binary):
    text += b" " * (-len(text) % 4)
    binary += b"\0" * (-len(binary) % 4)
    chunks = (struct.pack("<I4s", len(text), b"JSON") + text +
              struct.pack("<I4s", len(binary), b"BIN\0") + binary)
    return struct.pack("<4sII", b"glTF", 2, 12 + len(chunks)) + chunks


def glb(document, binary):
    return glb_bytes(json.dumps(document, separators=(",", ":")).encode(), binary)
