"""The inputs that tests/robustness/run.py tries on ./simulate: malformed scenes, bad option
sets, output-path cases and bad machine files, each with the outcome it must have.

Every case is a dict:
  group     "scene", "options", "outputs" or "machine" (the rows of the table)
  name      short description, unique
  args      the command line after the simulate binary (paths already in the work folder)
  expect    "error" (exit 2), "ok" (exit 0), "oom" (exit 3), "write" (exit 5: an output
            could not be written), "help" (exit 0, no simulation)
  outputs   output files the command names: none may exist after a failure
  inputs    input files that must not change
  fsize     optional file-size limit in bytes for the run (a "full disk")
  same_as   optional name of an "ok" case whose patch radiosities the result must equal
  memory_mb optional address-space limit of this case, instead of the script's
  names     optional text the error message must contain (the option's name)
  kinds     optional {path: kind} each path must still be after the run ("link", "char",
            "fifo", "socket", "folder", "file"): nothing that is not a regular file is replaced
  written   optional paths that must hold new content after an "ok" run (a link's target)
  reader    optional FIFO that a reader drains while the case runs
"""
import copy
import json
import math
import os
import re
import socket
import stat
import subprocess
import sys
from pathlib import Path

# A light square at y = 2 facing down, a floor facing up and a wall: small enough that a
# simulation takes milliseconds.
ROOM = {
    "name": "room",
    "camera": {"eye": [0.5, 1, 3], "look_at": [0.5, 1, 0], "up": [0, 1, 0], "fov_deg": 55},
    "patches": [
        {"vertices": [[0, 2, 0], [1, 2, 0], [1, 2, 1], [0, 2, 1]],
         "reflectance": [0.5, 0.5, 0.5], "emission": [10, 8, 6], "elements": [2, 2]},
        {"vertices": [[0, 0, 0], [0, 0, 1], [1, 0, 1], [1, 0, 0]],
         "reflectance": [0.6, 0.5, 0.4], "elements": [3, 3]},
        {"vertices": [[0, 0, 0], [1, 0, 0], [1, 2, 0], [0, 2, 0]],
         "reflectance": [0.7, 0.7, 0.7], "elements": [2, 3]},
    ],
}

QUICK = ["--iterations", "3"]
# Where a case writes a picture or a mesh, drawn at 64 x 48 (the exposure too), not 800 x 600:
# the case is about where its files go (0.6 s of CPU a run at the default size).
SMALL_PICTURE = ["--image-width", "64", "--image-height", "48"]


def room(**changes):
    """ROOM with top-level keys replaced; patch fields as patch<i>_<key>; None deletes."""
    scene = copy.deepcopy(ROOM)
    for key, value in changes.items():
        target, field = scene, key
        if key.startswith("patch") and "_" in key:
            index, field = key[5:].split("_", 1)
            target = scene["patches"][int(index)]
        elif key.startswith("camera_"):
            target, field = scene["camera"], key[7:]
        if value is None:
            target.pop(field, None)
        else:
            target[field] = value
    return scene


def scaled(scene, factor):
    scene = copy.deepcopy(scene)
    for patch in scene["patches"]:
        patch["vertices"] = [[c * factor for c in v] for v in patch["vertices"]]
    if "camera" in scene:
        for key in ("eye", "look_at"):
            scene["camera"][key] = [c * factor for c in scene["camera"][key]]
    return scene


def nested(depth, inner="1"):
    return "[" * depth + inner + "]" * depth


def scene_texts(root):
    """(name, text, expect, extra args) of the scene cases."""
    light = ROOM["patches"][0]
    cases = [
        ("empty file", "", "error"),
        ("only whitespace", " \n\t ", "error"),
        ("unterminated object", '{"name": "x", "patches": [', "error"),
        ("top-level array", "[]", "error"),
        ("top-level null", "null", "error"),
        ("top-level number", "1", "error"),
        ("top-level string", '"scene"', "error"),
        ("trailing comma", json.dumps(ROOM)[:-1] + ",}", "error"),
        ("NaN literal", json.dumps(ROOM).replace("0.5, 0.5, 0.5", "NaN, 0.5, 0.5", 1), "error"),
        ("Infinity literal", json.dumps(ROOM).replace("[10, 8, 6]", "[Infinity, 8, 6]"), "error"),
        ("number 1e999", json.dumps(ROOM).replace("[10, 8, 6]", "[1e999, 8, 6]"), "error"),
        ("invalid UTF-8", json.dumps(ROOM).replace('"room"', '"ro\xffm"').encode("latin-1"), "error"),
        ("control character in string", json.dumps(ROOM).replace('"room"', '"ro\x01m"'), "error"),
        ("trailing garbage", json.dumps(ROOM) + " x", "error"),
        ("two documents", json.dumps(ROOM) + json.dumps(ROOM), "error"),
        ("missing name", room(name=None), "error"),
        ("name is a number", room(name=3), "error"),
        ("empty name", room(name=""), "error"),
        ("unknown top-level key", room(patchs=[]), "error"),
        ("duplicate top-level key", json.dumps(ROOM)[:-1] + ', "name": "again"}', "error"),
        ("duplicate patch key", json.dumps(ROOM).replace('"elements": [2, 2]',
                                                         '"elements": [2, 2], "elements": [1, 1]'),
         "error"),
        ("duplicate camera key", json.dumps(ROOM).replace('"fov_deg": 55', '"fov_deg": 55, "up": [0, 1, 0]'),
         "error"),
        ("patches missing", room(patches=None), "error"),
        ("patches an object", room(patches={}), "error"),
        ("patches empty", room(patches=[]), "error"),
        ("patch a string", room(patches=[light, "wall"]), "error"),
        ("no light", room(patch0_emission=None), "error"),
        ("camera a string", room(camera="front"), "error"),
        ("camera unknown key", room(camera_fov=40), "error"),
        ("camera up missing", room(camera_up=None), "error"),
        ("camera eye 2 coordinates", room(camera_eye=[0, 1]), "error"),
        ("camera coordinate a string", room(camera_look_at=[0, "1", 0]), "error"),
        ("camera fov 0", room(camera_fov_deg=0), "error"),
        ("camera fov 180", room(camera_fov_deg=180), "error"),
        ("camera look_at equals eye", room(camera_look_at=[0.5, 1, 3]), "error"),
        ("camera up zero", room(camera_up=[0, 0, 0]), "error"),
        ("camera up along view", room(camera_up=[0, 0, 1]), "error"),
        ("camera eye at 1e308", room(camera_eye=[1e308, 1e308, 1e308]), "error"),
        ("camera eye and look_at at +-1e308", room(camera_eye=[1e308, 0, 0],
                                                   camera_look_at=[-1e308, 0, 0]), "error"),
        ("camera up 1e308", room(camera_up=[1e308, 1e308, 0]), "ok"),
        ("camera up 1e-300", room(camera_up=[0, 1e-300, 0]), "ok"),
        ("vertices 2 points", room(patch1_vertices=[[0, 0, 0], [1, 0, 0]]), "error"),
        ("vertices 5 points", room(patch1_vertices=[[0, 0, 0], [0, 0, 1], [1, 0, 1], [1, 0, 0], [0.5, 0, 0]]),
         "error"),
        ("vertex 2 coordinates", room(patch1_vertices=[[0, 0], [0, 0, 1], [1, 0, 0]]), "error"),
        ("vertex coordinate a string", room(patch1_vertices=[[0, 0, "0"], [0, 0, 1], [1, 0, 0]]), "error"),
        ("vertices an object", room(patch1_vertices={"a": 1}), "error"),
        ("coincident vertices", room(patch1_vertices=[[0, 0, 0], [0, 0, 0], [1, 0, 0]]), "error"),
        ("collinear triangle", room(patch1_vertices=[[0, 0, 0], [0, 0, 1], [0, 0, 2]]), "error"),
        ("non-planar quad", room(patch1_vertices=[[0, 0, 0], [0, 0, 1], [1, 0.5, 1], [1, 0, 0]]), "error"),
        ("bow-tie quad", room(patch1_vertices=[[0, 0, 0], [1, 0, 1], [0, 0, 1], [1, 0, 0]]), "error"),
        ("reflex quad", room(patch1_vertices=[[0, 0, 0], [0, 0, 1], [0.2, 0, 0.2], [1, 0, 0]]), "error"),
        ("straight corner", room(patch1_vertices=[[0, 0, 0], [0, 0, 1], [0, 0, 2], [1, 0, 0]]), "error"),
        ("vertex at 1e308", room(patch1_vertices=[[0, 0, 0], [0, 0, 1e308], [1e308, 0, 0]]), "error"),
        ("vertices 1e-320 apart", room(patch1_vertices=[[0, 0, 0], [0, 0, 1e-320], [1e-320, 0, 0]]), "error"),
        ("patch 1e-200 in a room of size 1", room(patch1_vertices=[[0, 0, 0], [0, 0, 1e-200], [1e-200, 0, 0]]),
         "error"),
        ("reflectance 1", room(patch1_reflectance=[1, 0.5, 0.5]), "error"),
        ("reflectance negative", room(patch1_reflectance=[-0.1, 0.5, 0.5]), "error"),
        ("reflectance a string", room(patch1_reflectance="grey"), "error"),
        ("reflectance 2 channels", room(patch1_reflectance=[0.5, 0.5]), "error"),
        ("reflectance null channel", room(patch1_reflectance=[0.5, None, 0.5]), "error"),
        ("reflectance missing", room(patch1_reflectance=None), "error"),
        ("emission negative", room(patch0_emission=[-1, 8, 6]), "error"),
        ("emission 1e305", room(patch0_emission=[1e305, 1e305, 1e305]), "error"),
        ("emission 1e308", room(patch0_emission=[1e308, 0, 0]), "error"),
        ("emission 1e-300", room(patch0_emission=[1e-300, 0, 0]), "error"),
        ("elements 1 number", room(patch1_elements=[4]), "error"),
        ("elements fraction", room(patch1_elements=[2.5, 2]), "error"),
        ("elements 2.0", room(patch1_elements=[2.0, 2]), "error"),
        ("elements zero", room(patch1_elements=[0, 2]), "error"),
        ("elements negative", room(patch1_elements=[-1, 2]), "error"),
        ("elements a string", room(patch1_elements=["2", 2]), "error"),
        ("elements 2000 x 2000", room(patch1_elements=[2000, 2000]), "error"),
        ("elements 2^64 - 1", room(patch1_elements=[18446744073709551615, 1]), "error"),
        ("elements -2^63", room(patch1_elements=[-9223372036854775808, 1]), "error"),
        ("elements nested 100 deep", json.dumps(ROOM).replace('"elements": [3, 3]',
                                                              '"elements": ' + nested(100)), "error"),
        ("elements nested 70000 deep", json.dumps(ROOM).replace('"elements": [3, 3]',
                                                                '"elements": ' + nested(70000)), "error"),
        ("vertices nested 70000 deep", json.dumps(ROOM).replace('"elements": [3, 3]',
                                                                '"vertices": ' + nested(70000)), "error"),
        ("top level nested 70000 deep", nested(70000), "error"),
        ("object nested 70000 deep", '{"a":' * 70000 + "1" + "}" * 70000, "error"),
        ("unknown key of 1 MB", room(**{"x" * 1000000: 1}), "error"),
        ("unknown key with a newline", room(**{"bad\nkey": 1}), "error"),
        ("elements a 1 MB string", room(patch1_elements="x" * 1000000), "error"),
        ("17 patches of 1024 x 1024 elements",
         room(patches=[light] + [ROOM["patches"][1] | {"elements": [1024, 1024]}] * 17), "error"),
    ]
    # Within the documented limits, but far beyond the 4 MB of a node: exit 3, fast.
    cases.append(("16 patches of 1024 x 1024 elements",
                  room(patches=[light] + [ROOM["patches"][1] | {"elements": [1024, 1024]}] * 15), "oom"))
    # Many patches (34 MB): loading must be linear (the memory plan then refuses them).
    # Linear loading takes about 2.5 s of CPU here, the quadratic one of main c39b79f
    # about 70 s: the timeout tells them apart.
    many = room(patches=[light] + [ROOM["patches"][1]] * 300000)
    cases.append(("300000 patches", many, "oom"))
    scene0 = json.loads((root / "scenes" / "scene0.json").read_text())
    cases.append(("scene0", scene0, "ok"))
    for factor in (1e75, 1e-100, 1e150, 1e-150):
        cases.append((f"scene0 scaled by {factor:g}", scaled(scene0, factor), "ok"))
    # Scaling by a power of two is exact: the radiosities must be the same.
    for exponent in (250, -250):
        cases.append((f"scene0 scaled by 2^{exponent}", scaled(scene0, 2.0 ** exponent), "ok"))
    return cases


def scene_cases(root, work):
    cases = []
    for index, (name, content, expect) in enumerate(scene_texts(root)):
        path = work / f"scene{index:03d}.json"
        if isinstance(content, dict):
            content = json.dumps(content)
        path.write_bytes(content if isinstance(content, bytes) else content.encode())
        out = work / f"scene{index:03d}.out.json"
        case = {"group": "scene", "name": name, "args": [str(path), *QUICK, "--json", str(out)],
                "expect": expect, "outputs": [out], "inputs": [path]}
        if name.startswith("scene0 scaled by 2^"):
            case["same_as"] = "scene0"
        if name == "300000 patches":
            case["memory_mb"] = 2048  # the JSON document of 34 MB takes about 500 MB
        cases.append(case)
    cases += [
        {"group": "scene", "name": "scene is /dev/zero", "args": ["/dev/zero", "--json", str(work / "z.json")],
         "expect": "error", "outputs": [work / "z.json"]},
        {"group": "scene", "name": "scene is a directory", "args": [str(work), "--json", str(work / "d.json")],
         "expect": "error", "outputs": [work / "d.json"]},
        {"group": "scene", "name": "scene missing", "args": [str(work / "missing.json")], "expect": "error"},
        {"group": "scene", "name": "scene path empty", "args": [""], "expect": "error"},
    ]
    return cases


def option_cases(root, work):
    scene = "scene0.json"
    out = work / "options.out.json"
    sets = [
        (["--bogus"], "error"), (["--R", "2.5"], "error"), (["--R", "0"], "error"),
        (["--R", "-1"], "error"), (["--R", "010"], "error"), (["--R", "0x10"], "error"),
        (["--R", "0b11"], "error"), (["--R", "1e3"], "error"), (["--R", ""], "error"),
        (["--R", "99999999999"], "error"), (["--R", "2147483647"], "error"), (["--R", " 4"], "error"),
        (["--R"], "error"), (["--V", "-1"], "error"), (["--V", "1.5"], "error"),
        (["--R", "2", "--V", "2147483647"], "error"), (["--R", "2147483647", "--V", "2147483647"], "error"),
        (["--V", "64"], "error"), (["--R", "8", "--V", "8"], "error"), (["--R", "53"], "error"),
        (["--samples", "20"], "error"), (["--samples", "0"], "error"), (["--samples", "65"], "error"),
        (["--samples", "-4"], "error"), (["--samples", "100"], "error"), (["--samples", "016"], "error"),
        (["--iterations", "-5"], "error"), (["--iterations", "-2"], "error"),
        (["--iterations", "abc"], "error"), (["--iterations", "1.5"], "error"),
        (["--convergence", "0"], "error"), (["--convergence", "nan"], "error"),
        (["--convergence", "1e-300"], "error"), (["--convergence", "-1"], "error"),
        (["--convergence", "2"], "error"), (["--convergence", "inf"], "error"),
        (["--convergence", "abc"], "error"), (["--convergence", "1e-400"], "error"),
        (["--block-size", "0"], "error"), (["--block-size", "-1"], "error"),
        (["--block-size", "1000001"], "error"), (["--block-size", "abc"], "error"),
        (["--ray-test", "some"], "error"), (["--image-width", "15", "--image", str(work / "w.png")], "error"),
        (["--image-height", "8193", "--image", str(work / "h.png")], "error"),
        (["--platform", str(work / "none.json")], "error"),
        (["--cost-model", str(work / "none.json")], "error"),
        (["scene1.json"], "error"),  # a second scene
        (["--mesh", str(work / "m.obj")], "error"),  # the mesh is PLY, not what the name says
        (["--mesh", str(work / "m.ply")], "ok"),
        (["--R", "4", "--V", "3"], "ok"), (["--R", "5", "--V", "2", "--pipelined", "--block-size", "7"], "ok"),
        (["--iterations", "0"], "ok"), (["--convergence", "1"], "ok"),
    ]
    cases = [{"group": "options", "name": " ".join(a) or "(none)",
              "args": [scene, *([] if "--iterations" in a else QUICK), *a, "--json", str(out)],
              "expect": expect, "outputs": [out] + [Path(x) for x in a if x.endswith((".png", ".ply", ".obj"))],
              "option_words": a}
             for a, expect in sets]
    cases.append({"group": "options", "name": "no scene", "args": ["--R", "2"], "expect": "error"})
    cases.append({"group": "options", "name": "--help", "args": ["--help"], "expect": "help"})
    cases.append({"group": "options", "name": "--iterations -1 converges", "expect": "ok",
                  "args": [str(work / "conv.json"), "--iterations", "-1", "--json", str(out)],
                  "outputs": [out]})
    (work / "conv.json").write_text(json.dumps(ROOM))
    return cases


def output_cases(root, work):
    scene, platform, costs = work / "input.json", work / "platform.json", work / "costs.json"
    # Written again before every case, in case an earlier one overwrote them.
    files = {scene: json.dumps(ROOM).encode(),
             platform: (root / "platforms" / "ncube2.json").read_bytes(),
             costs: (root / "platforms" / "cost_model.json").read_bytes()}
    for path, content in files.items():
        path.write_bytes(content)
    (work / "a-file").write_text("")
    (work / "link.json").symlink_to(scene)
    base = [str(scene), *QUICK, *SMALL_PICTURE, "--platform", str(platform), "--cost-model",
            str(costs)]
    j, t, i = work / "o.json", work / "o.trace.json", work / "o.png"
    inputs = [scene, platform, costs]
    sets = [
        ("--json empty", ["--json", ""], "error", []),
        ("--image empty", ["--json", str(j), "--image", ""], "error", [j]),
        ("--trace empty", ["--json", str(j), "--trace", ""], "error", [j]),
        # An output in a missing folder, a folder, the scene, the platform: cells of the threat
        # model for every output option ("write --json / missing folder", "... / is scene.json").
        ("--image under a file", ["--json", str(j), "--image", str(work / "a-file" / "o.png")], "error", [j]),
        ("--json ends with /", ["--json", str(work / "o.json") + "/"], "error", []),
        ("--json is the scene through a symlink", ["--json", str(work / "link.json")], "error", []),
        ("--json is the scene by another spelling", ["--json", str(work / "." / "input.json")], "error", []),
        ("--trace is the cost model", ["--trace", str(costs)], "error", []),
        ("--json and --trace the same", ["--json", str(j), "--trace", str(j)], "error", [j]),
        ("--json and --image the same", ["--json", str(j), "--image", str(j)], "error", [j]),
        ("--trace and --image the same", ["--trace", str(t), "--image", str(t)], "error", [t]),
        ("all three outputs", ["--json", str(j), "--trace", str(t), "--image", str(i)], "ok", [j, t, i]),
    ]
    cases = [{"group": "outputs", "name": name, "args": base + a, "expect": expect,
              "outputs": outputs, "inputs": inputs, "files": files} for name, a, expect, outputs in sets]
    # A full disk: the result file fits, the trace does not. Nothing may remain.
    cases.append({"group": "outputs", "name": "disk full while writing the trace", "expect": "write",
                  "args": [str(root / "scenes" / "scene0.json"), "--R", "4", "--V", "3", "--iterations", "3",
                           "--json", str(j), "--trace", str(t)], "outputs": [j, t], "fsize": 32 * 1024})
    cases.append({"group": "outputs", "name": "disk full while writing the picture", "expect": "write",
                  "args": base + ["--json", str(j), "--image", str(i)], "outputs": [j, i],
                  "fsize": 4 * 1024, "files": files})
    return cases


def machine_cases(root, work):
    ncube2 = json.loads((root / "platforms" / "ncube2.json").read_text())
    model = json.loads((root / "platforms" / "cost_model.json").read_text())
    scene = work / "machine-scene.json"
    scene.write_text(json.dumps(ROOM))
    out = work / "m.json"
    cases = []

    def platform_with(name, value, expect="error"):
        p = copy.deepcopy(ncube2)
        p["parameters"].setdefault(name, {})["value"] = value  # an optional one added
        path = work / f"platform-{len(cases)}.json"
        path.write_text(json.dumps(p))
        cases.append({"group": "machine", "name": f"platform {name} {value}", "expect": expect,
                      "args": [str(scene), *QUICK, "--platform", str(path), "--json", str(out)],
                      "outputs": [out], "names": f'"{name}"'})

    xml = (root / "platforms" / "ncube2.xml").read_text()

    def xml_with(name, form, value, optional=False):
        """platforms/ncube2.xml with the parameter's speed or <prop> given `value` (None: the
        <prop> left out)."""
        if form == "kHostSpeed":
            pattern, text = r'(<cluster [^>]*?\bspeed=")[^"]*(")', f"{value}f"
        else:
            pattern, text = r'(<prop id="%s" value=")[^"]*("/>)' % re.escape(name), str(value)
        if not re.search(pattern, xml) and optional and value is not None:
            # An optional <prop> ncube2.xml leaves out: added beside node_memory.
            base = xml.replace('<prop id="node_memory"', '<prop id="%s" value="%s"/>\n    '
                               '<prop id="node_memory"' % (name, value), 1)
        else:
            base = xml
        if not re.search(pattern, base):
            raise ValueError(f"platforms/ncube2.xml does not give {name} "
                             f"(src/machine/machine_parameters.h: {form})")
        changed = (re.sub(pattern, lambda m: m.group(1) + text + m.group(2), base, count=1)
                   if value is not None else re.sub(r'\s*' + pattern, "", base, count=1))
        path = work / f"platform-{len(cases)}.xml"
        path.write_text(changed)
        what = "left out" if value is None else value
        cases.append({"group": "machine", "name": f"platform XML {name} {what}", "expect": "error",
                      "args": [str(scene), *QUICK, "--platform", str(path), "--json", str(out)],
                      "outputs": [out], "names": name})

    def costs_with(name, value, expect="error"):
        m = copy.deepcopy(model)
        m["parameters"][name]["value"] = value
        path = work / f"costs-{len(cases)}.json"
        path.write_text(json.dumps(m))
        cases.append({"group": "machine", "name": f"cost model {name} {value}", "expect": expect,
                      "args": [str(scene), *QUICK, "--cost-model", str(path), "--json", str(out)],
                      "outputs": [out]})

    # The bounds come from the one list of machine parameters (docs/platform_tables.py reads
    # it): each parameter just past both ends of its range, and fractional where it must be
    # whole, in the JSON file and (where the XML form carries it) in platforms/ncube2.xml; a
    # <prop> left out. A whole one also far past both ends (1e300 is no integer a conversion
    # can hold); for a real one those take the same comparison as just past the end, so they
    # are not tried again. Every refusal names the parameter.
    sys.path.insert(0, str(root / "docs"))
    import platform_tables  # noqa: E402
    parameters = platform_tables.machine_parameters(root)
    assert len(parameters) >= 7, "fewer machine parameters than the nCube2's seven"
    for p in parameters:
        below = p["low"] - 1 if p["whole"] else math.nextafter(p["low"], -math.inf)
        above = p["high"] + 1 if p["whole"] else math.nextafter(p["high"], math.inf)
        far_below = 1e-300 if p["low"] > 0 else -1e300
        values = [below, above] + ([far_below, 1e300, p["low"] + 0.5] if p["whole"] else [])
        for value in values:
            platform_with(p["name"], int(value) if value == int(value) and abs(value) < 2 ** 53 else value)
        if p["xml"] != "kInterconnect":
            xml_with(p["name"], p["xml"], repr(above), p["optional"])
            xml_with(p["name"], p["xml"], repr(below), p["optional"])
        if p["xml"] == "kProperty" and not p["optional"]:  # an optional one may be left out
            xml_with(p["name"], p["xml"], None)
    platform_with("node_speed", 0)
    costs_with("flops_per_ray", 1e300)
    costs_with("flops_per_ray", -1)
    costs_with("element_bytes", 1e300)
    for name, text in [("platform /dev/zero", None), ("platform nested 70000 deep", nested(70000)),
                       ("platform empty", ""), ("platform with a duplicate key", None)]:
        path = work / f"platform-text-{len(cases)}.json"
        if text is None and "duplicate" in name:
            raw = json.dumps(ncube2)
            text = raw[:-1] + ', "parameters": {}}'
        if text is None:
            path = Path("/dev/zero")
        else:
            path.write_text(text)
        cases.append({"group": "machine", "name": name, "expect": "error",
                      "args": [str(scene), *QUICK, "--platform", str(path), "--json", str(out)],
                      "outputs": [out]})
    return cases


# The values every numeric option is tried with, besides its range's ends and one step past
# them: not numbers, the infinities, a negative zero, the smallest subnormal, overflow.
SPECIAL_VALUES = ["nan", "NaN", "inf", "-inf", "infinity", "-0", "4.9e-324", "1e999", "0x10", ""]
# In range, but refused by the configuration check (exit 2 all the same): the room has 3
# patches and the platform 64 nodes; the paper's program (the default parallelisation) takes
# no --shooters-per-iteration but 0.
CONFIGURATION_LIMITS = {"--R": lambda v: v <= 3, "--V": lambda v: v <= 63,
                        "--shooters-per-iteration": lambda v: v == 0}
# How the configuration check names the count it refuses ("R=2147483647"); the others by flag.
CONFIGURATION_NAMES = {"--R": "R=", "--V": "V="}


def _accepts(option, text):
    """Whether ./simulate must accept `text` for `option` (described by --describe-options),
    worked out here from the description: a decimal number, finite, in the range, whole for
    an integer option (decimal digits only), a perfect square where asked."""
    try:
        value = float(text)
    except ValueError:
        return False
    if not math.isfinite(value) or "x" in text.lower() or "n" in text.lower():
        return False
    if option["kind"] == "integer":
        digits = text[1:] if text.startswith("-") else text
        if not digits.isdigit() or (len(digits) > 1 and digits[0] == "0"):
            return False
        if option.get("even") and int(value) % 2 != 0:
            return False
        if option.get("perfect_square") and (value < 0 or math.isqrt(int(value)) ** 2 != value):
            return False
    r = option["range"]
    above = value >= r["low"] if r["low_included"] else value > r["low"]
    below = value <= r["high"] if r["high_included"] else value < r["high"]
    limit = CONFIGURATION_LIMITS.get(option["flag"], lambda v: True)
    return above and below and limit(value)


def _named(option, text):
    """What the refusal must name: the option, or for an in-range count the configuration
    check refuses, the count as that check names it ("R=2147483647")."""
    limit = CONFIGURATION_LIMITS.get(option["flag"])
    if limit and _accepts({**option, "flag": ""}, text):
        return CONFIGURATION_NAMES.get(option["flag"], option["flag"])
    return option["flag"]


def _past(end, step, kind):
    if kind == "integer":
        return str(int(end) + step)
    return repr(end * (1 + 1e-9 * step) if end else 1e-300 * step)


# Model-file options run on tests/models/room.obj: what they must end with beyond the range
# (a grid so fine that the elements do not fit a 4 MB node is out of memory, exit 3).
MODEL_OUTCOMES = {"--element-size": lambda v: "ok" if v == 0 or v >= 0.05 else "oom",
                  "--element-budget": lambda v: "ok" if v <= 10000 else "oom",
                  # The hemicube's table and face buffer: 20 bytes x N^2 on a 4 MB node.
                  "--hemicube-resolution": lambda v: "ok" if v <= 400 else "oom"}


# Special values per option: every option goes through the one parser of numbers
# (src/tools/option_table.cpp), which reads an integer and a number by two branches, so the
# values are dealt round the options of each kind in turn (per_kind values each, as few as let
# every value meet an option of each kind: 1 each for the 13 integer options, 2 for the 5
# number ones); each option's own range ends are all tried.
def special_values(numeric):
    """{flag: the special values its option is tried with}; every value meets at least one
    option of each kind."""
    dealt, met = {}, {}
    for kind in ("integer", "number"):
        options = [o for o in numeric if o["kind"] == kind]
        per_kind = -(-len(SPECIAL_VALUES) // len(options)) if options else 0
        for index, option in enumerate(options):
            dealt[option["flag"]] = [SPECIAL_VALUES[(per_kind * index + k) % len(SPECIAL_VALUES)]
                                     for k in range(per_kind)]
            for value in dealt[option["flag"]]:
                met.setdefault(value, set()).add(kind)
    kinds = {o["kind"] for o in numeric}
    missed = [v for v in SPECIAL_VALUES if met.get(v) != kinds]
    assert not missed, f"special values meeting no option of some kind: {missed}"
    return dealt


def number_cases(simulate, work):
    """Every numeric option that `simulate --describe-options` lists (so a new option is tried
    without a new line here) x its share of the special values (special_values), its range's
    ends and one past each end."""
    described = json.loads(subprocess.run([str(simulate), "--describe-options"], check=True,
                                          capture_output=True, text=True).stdout)
    scene, out = work / "numbers.json", work / "numbers.out.json"
    scene.write_text(json.dumps(ROOM))
    models = Path(__file__).resolve().parents[1] / "models"
    model_scene = work / "numbers-room.obj"
    model_scene.write_bytes((models / "room.obj").read_bytes())
    (work / "room.mtl").write_bytes((models / "room.mtl").read_bytes())
    cases = []
    numeric = [o for o in described if o["kind"] in ("integer", "number")]
    specials = special_values(numeric)
    for option in numeric:
        r = option["range"]
        ends = [r["low"], r["high"]]
        texts = list(specials[option["flag"]])
        for end, step in ((r["low"], -1), (r["high"], 1)):
            texts += [str(end) if option["kind"] == "integer" else repr(float(end)),
                      _past(end, step, option["kind"])]
        model = option.get("applies_to") == "model files"
        for text in dict.fromkeys(texts):
            ok = _accepts(option, text)
            expect = "ok" if ok else "error"
            if ok and option["flag"] in MODEL_OUTCOMES:
                expect = MODEL_OUTCOMES[option["flag"]](float(text))
            iterations = [] if option["flag"] == "--iterations" else QUICK
            # An option of one method only (the hemicube's) is tried with that method chosen.
            method = [a for key, value in option.get("recorded_when", {}).items()
                      for a in ("--" + key.replace("_", "-"),
                                value[0] if isinstance(value, list) else value)]
            cases.append({"group": "numbers", "name": f"{option['flag']} {text!r}",
                          "args": [str(model_scene if model else scene), *iterations, *method,
                                   option["flag"], text, "--json", str(out)],
                          "expect": expect, "outputs": [out],
                          "names": None if ok else _named(option, text)})
        assert ends
    return cases


def _make_kind(path, kind):
    """Makes a path of `kind` in the test's own folder (never the machine's /dev); False when
    this machine does not allow it (character devices need root)."""
    if kind in ("file", "link"):
        target = path.with_name(path.name + ".target") if kind == "link" else path
        target.write_text("old")
        if kind == "link":
            path.symlink_to(target.name)
    elif kind == "dangling link":
        path.symlink_to(path.name + ".made")
    elif kind == "fifo":
        os.mkfifo(path)
    elif kind in ("null device", "full device"):
        try:
            os.mknod(path, 0o666 | stat.S_IFCHR, os.makedev(1, 3 if kind == "null device" else 7))
        except PermissionError:
            return False
    elif kind == "standard output link":
        path.symlink_to("/proc/self/fd/1")
    elif kind == "folder":
        path.mkdir()
    elif kind == "socket":
        with socket.socket(socket.AF_UNIX) as s:
            s.bind(str(path))
    return True


# The kinds of output path the threat model does not give every output option (docs/cli.md,
# "Output files"): what the run must end with, what the path must still be after it and which
# file must hold the output. A new file, a link, a dangling link, a FIFO with a reader, a null
# and a full device and a folder are cells of tests/robustness/threat_model.py for every output
# option --describe-options lists (SHARED_RULE_KINDS, with the same checks: the exit, the kind
# kept, the link's target written, the reader fed, nothing else left), so they are not tried
# again here.
PATH_KINDS = {
    "file": ("ok", "file", ""),
    "standard output link": ("ok", "link", None),
    "socket": ("write", "socket", None),
}


# The file name's ending an output option needs (--mesh writes PLY and says so by name).
OUTPUT_SUFFIXES = {"--mesh": ".ply"}


def path_kind_cases(work, simulate):
    """Every output option that `simulate --describe-options` lists (kind "output", so a new
    output is tried without a new line here) x every kind of path, each made afresh in a folder
    of its own; an option for model files runs on tests/models/room.obj."""
    described = json.loads(subprocess.run([str(simulate), "--describe-options"], check=True,
                                          capture_output=True, text=True).stdout)
    options = [o for o in described if o["kind"] == "output"]
    assert len(options) >= 5, "--describe-options lists fewer outputs than --json, --trace, " \
        "--image, --mesh and --export-scene"
    scene = work / "kinds-scene.json"
    scene.write_text(json.dumps(ROOM))
    models = Path(__file__).resolve().parents[1] / "models"
    model = work / "kinds-room.obj"
    model.write_bytes((models / "room.obj").read_bytes())
    (work / "room.mtl").write_bytes((models / "room.mtl").read_bytes())
    cases = []
    for described_option in options:
        option = described_option["flag"]
        source = model if described_option.get("applies_to") == "model files" else scene
        folder = work / ("kinds" + option)
        folder.mkdir()
        for kind, (expect, after, written) in PATH_KINDS.items():
            path = folder / (kind.replace(" ", "-") + OUTPUT_SUFFIXES.get(option, ""))
            if not _make_kind(path, kind):
                print(f"skipped {option} x {kind}: mknod needs root")
                continue
            cases.append({"group": "path kinds", "name": f"{option} x {kind}",
                          "args": [str(source), *QUICK, *SMALL_PICTURE, option, str(path)],
                          "expect": expect,
                          "kinds": {str(path): after} if after else {},
                          "written": [str(path) + written] if written is not None else [],
                          "reader": str(path) if kind == "fifo" else None,
                          "outputs": [] if after else [path]})
    cases.append({"group": "path kinds", "name": "--json and --trace both -", "expect": "error",
                  "args": [str(scene), *QUICK, "--json", "-", "--trace", "-"]})
    cases.append({"group": "path kinds", "name": "- with the summary", "expect": "ok",
                  "args": [str(scene), *QUICK, "--json", "-"], "kinds": {}})
    return cases


def settings_cases(root, work):
    """Every pass-through SimGrid setting (--cfg, --log, a platform file's simgrid_config) x an
    unknown name, an unknown value and a missing value: exit 2 and one line naming the setting,
    never SimGrid's abort."""
    scene, out = work / "settings.json", work / "settings.out.json"
    scene.write_text(json.dumps(ROOM))
    base = [str(scene), *QUICK, "--json", str(out)]
    bad = {"--cfg": {"unknown name": "bogus/name:1", "unknown value": "network/model:bogus",
                     "missing value": "network/model", "empty value": "network/model:",
                     "missing name": ":CM02"},
           "--log": {"unknown name": "ncube_messages.bogus:debug",
                     "unknown value": "ncube_messages.thresh:loud",
                     "missing value": "ncube_messages.thresh:", "malformed": ":::"}}
    cases = []
    for flag, settings in bad.items():
        for what, setting in settings.items():
            argument = f"{flag}={setting}"
            cases.append({"group": "settings", "name": f"{flag} {what}", "expect": "error",
                          "args": base + [argument], "outputs": [out], "names": argument})
    platform = json.loads((root / "platforms" / "ncube2.json").read_text())
    for what, (name, value) in {"unknown name": ("bogus/name", "1"),
                                "unknown value": ("network/model", "bogus"),
                                "missing value": ("network/model", "")}.items():
        changed = copy.deepcopy(platform)
        changed["simgrid_config"][name] = value
        path = work / f"platform-{what.replace(' ', '-')}.json"
        path.write_text(json.dumps(changed))
        cases.append({"group": "settings", "name": f"platform simgrid_config {what}",
                      "expect": "error", "args": base + ["--platform", str(path)],
                      "outputs": [out], "names": f'"{name}"'})
    for flag, setting in (("--cfg", "network/model:CM02"), ("--log", "ncube_messages.thresh:info")):
        cases.append({"group": "settings", "name": f"{flag} good", "expect": "ok",
                      "args": base + [f"{flag}={setting}"], "outputs": [out]})
    return cases


def model_cases(root, work):
    """Bad model files through the whole command line: exit 2 with one message, no output
    file (tests/model_import_test.cpp checks each message), and the good ones beside them."""
    work = work / "models"
    work.mkdir(exist_ok=True)
    light = "mtllib lamp.mtl\nusemtl lamp\n"
    (work / "lamp.mtl").write_text("newmtl lamp\nKd 0.5 0.5 0.5\nKe 1 1 1\nnewmtl white\nKd 1 1 1\n")
    triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
    ply = ("ply\nformat ascii 1.0\nelement vertex {n}\nproperty float x\nproperty float y\n"
           "property float z\nelement face 1\nproperty list uchar int vertex_indices\n{extra}"
           "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2{colour}\n")
    gltf = ('{"asset":{"version":"2.0"},"buffers":[{"uri":"gone.bin","byteLength":36}],'
            '"bufferViews":[{"buffer":0,"byteLength":36}],"accessors":[{"bufferView":0,'
            '"componentType":5126,"count":3,"type":"VEC3","max":[1,1,0],"min":[0,0,0]}],'
            '"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[{"mesh":0}],'
            '"scenes":[{"nodes":[0]}],"scene":0}')
    files = [  # name, file, content, expect, extra arguments
        ("OBJ triangle with a light", "ok.obj", light + triangle + "f 1 2 3\n", "ok", []),
        ("OBJ index out of range", "index.obj", light + triangle + "f 1 2 9\n", "error", []),
        ("OBJ NaN coordinate", "nan.obj", light + "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "error", []),
        ("OBJ missing MTL", "mtl.obj", "mtllib gone.mtl\nusemtl lamp\n" + triangle + "f 1 2 3\n", "error", []),
        ("OBJ face of 2 corners", "line.obj", light + triangle + "f 1 2\n", "error", []),
        ("OBJ face of 1 corner", "point.obj", light + triangle + "f 1\n", "error", []),
        ("OBJ white Kd", "white.obj", light + triangle + "f 1 2 3\nusemtl white\nf 1 3 2\n", "error", []),
        ("OBJ usemtl naming nothing", "typo.obj", light + triangle + "f 1 2 3\nusemtl lamb\nf 1 3 2\n",
         "error", []),
        ("OBJ face before usemtl", "early.obj", "mtllib lamp.mtl\n" + triangle + "f 1 2 3\nusemtl lamp\nf 1 3 2\n",
         "error", []),
        ("OBJ without a light", "dark.obj", triangle + "f 1 2 3\n", "error", []),
        ("OBJ --light NAME", "dark2.obj", triangle + "f 1 2 3\n", "ok", ["--light", "DefaultMaterial"]),
        ("OBJ --light naming nothing", "dark3.obj", light + triangle + "f 1 2 3\n", "error",
         ["--light", "lamb"]),
        ("OBJ without faces", "empty.obj", triangle, "error", []),
        ("glTF missing buffer", "gone.gltf", gltf, "error", []),
        ("PLY shorter than its header", "short.ply", ply.format(n=9, extra="", colour=""), "error",
         ["--light", "short"]),
        ("PLY face colour of 255", "bright.ply",
         ply.format(n=3, extra="property uchar red\nproperty uchar green\nproperty uchar blue\n",
                    colour=" 255 0 0"), "error", ["--light", "bright"]),
        ("PLY cut in its header", "cut.ply", "ply\nformat ascii 1.0\ncomment cut", "error",
         ["--light", "cut"]),
        ("FBX refused by extension", "model.fbx", "; FBX 7.4.0 project file\n", "error", []),
    ]
    cases = []
    for name, file, content, expect, extra in files:
        (work / file).write_text(content)
        out, export = work / (file + ".out.json"), work / (file + ".scene.json")
        cases.append({"group": "model", "name": name, "expect": expect,
                      "args": [str(work / file), *QUICK, *extra, "--json", str(out),
                               "--export-scene", str(export)],
                      "outputs": [out, export], "inputs": [work / file]})
    return cases


# The two parts of the cases (run.py --only options, --only files): the command line's words,
# and the files a run reads.
PARTS = {"options": ("options", "numbers", "outputs", "path kinds"),
         "files": ("scene", "settings", "machine", "model")}


def all_cases(root, work, simulate, part=None):
    """Every case (of PARTS[part] only, when given), each group's files in a folder of its own
    (case["work"]): the groups can run at once, a run's temporary files looked for in its own
    group's folder only."""
    root, work = Path(root), Path(work)
    groups = {"scene": lambda w: scene_cases(root, w), "options": lambda w: option_cases(root, w),
              "numbers": lambda w: number_cases(simulate, w),
              "outputs": lambda w: output_cases(root, w),
              "path kinds": lambda w: path_kind_cases(w, simulate),
              "settings": lambda w: settings_cases(root, w),
              "machine": lambda w: machine_cases(root, w), "model": lambda w: model_cases(root, w)}
    if part:
        groups = {name: make for name, make in groups.items() if name in PARTS[part]}
    cases = []
    for name, make in groups.items():
        folder = work / name.replace(" ", "-")
        folder.mkdir()
        for case in make(folder):
            case["work"] = folder
            cases.append(case)
    return without_repeats(cases)


def without_repeats(cases):
    """The cases but an option set of one option and its value refused (exit 2) that the
    numbers group tries already, with the same outcome (the same words reach the same parser;
    the numbers group's refusal must also name the option)."""
    numbers = {(c["args"][c["args"].index("--json") - 2], c["args"][c["args"].index("--json") - 1])
               for c in cases if c["group"] == "numbers" and c["expect"] == "error"}
    return [c for c in cases if not (c["group"] == "options" and c["expect"] == "error" and
                                     len(c.get("option_words", ())) == 2 and
                                     tuple(c["option_words"]) in numbers)]
