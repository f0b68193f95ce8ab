"""Cells of tests/robustness/threat_model.py known not to be clean yet (issue 30, measured on
main 0f2337f and 4b97f7b): tests/robustness/run.py reports them as OPEN and does not fail on
them. Every entry is one exact cell id (run.py --list --only threats prints them all); shrink
the list to empty as the fixes land: run.py names each entry whose cell is now clean ("now
clean: ..."), and with --strict fails on it."""


def _cross(surfaces, kinds):
    return [f"{surface} / {kind}" for surface in surfaces for kind in kinds]


_IS_INPUT = ["is " + name for name in ("scene.json", "model.obj", "lamp.mtl", "model.gltf",
                                         "mesh.bin", "tex.png", "platform.json", "platform.xml",
                                         "cost.json")]

KNOWN_OPEN = [
    # One read gate: FIFOs block the open, a device or folder reads as empty, a link loop is an
    # internal error (exit 7), an endless or huge file is read up to (or past) its limit.
    *_cross(["read scene", "read --platform JSON", "read --platform SimGrid XML",
             "read --cost-model", "read NCUBE_ROOT platform", "read OBJ mtllib",
             "read glTF buffer", "read sweep OBJ mtllib", "read sweep glTF buffer",
             "read sweep glTF image"], ["fifo"]),
    *_cross(["read scene", "read model .obj", "read model .ply", "read model .gltf",
             "read model .glb", "read sweep file"], ["link loop"]),
    *_cross(["read OBJ mtllib", "read glTF buffer", "read sweep OBJ mtllib",
             "read sweep glTF buffer"], ["char device", "endless via link"]),
    *_cross(["read OBJ mtllib", "read sweep OBJ mtllib"], ["folder"]),
    "read scene / endless via link", "read scene / huge", "read sweep file / huge",
    "read sweep glTF image / endless via link", "read sweep glTF image / huge",
    # Files a model names resolve inside the model's folder (absolute, file: and `..` refused);
    # the sweep tool hashes a glTF's images wherever they are.
    *_cross(["read OBJ mtllib", "read glTF buffer"],
            ["absolute reference", "escaping reference", "link out of the folder"]),
    *_cross(["read OBJ mtllib, model by absolute path", "read glTF buffer, model by absolute path"],
            ["escaping reference", "link out of the folder"]),
    *_cross(["read sweep OBJ mtllib", "read sweep glTF buffer", "read sweep glTF image"],
            ["escaping reference", "link out of the folder"]),
    "read sweep glTF image / absolute reference",
    # The sweep tool's own file: a traceback (exit 1) on bytes that are not YAML or JSON.
    "content sweep file / garbage", "content sweep file / deep nesting",
    # A nesting limit for models, checked before Assimp parses.
    "content model .gltf / deep nesting", "content model .glb / deep nesting",
    # No output may be a file a model names.
    *_cross(["write --json", "write --trace", "write --image", "write --mesh",
             "write --export-scene"], ["is lamp.mtl", "is mesh.bin", "is tex.png"]),
    # NCUBE_RECORD_ACTIVITIES, a --log file appender and SimGrid's tracing file under the output
    # rule (tracing also writes simgrid.trace in the working folder and crashes on a bad path).
    *_cross(["write NCUBE_RECORD_ACTIVITIES"],
            ["link", "dangling link", "link loop", "fifo", "null device", "full device",
             "endless device via link", "socket", "missing folder", *_IS_INPUT]),
    *_cross(["write --log file appender"], ["fifo", "full device", "folder", "socket",
                                            *_IS_INPUT]),
    *_cross(["write --cfg tracing/filename"],
            ["new", "regular", "link", "dangling link", "link loop", "fifo", "null device",
             "full device", "endless device via link", "folder", "socket", "missing folder",
             *_IS_INPUT]),
]
