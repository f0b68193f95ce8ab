"""Cells of tests/robustness/threat_model.py known not to be clean yet (issue 30):
tests/robustness/run.py reports them as OPEN and does not fail on them. Every entry is one
exact cell id (run.py --list --only threats prints them all); shrink the list to empty as the
fixes land: run.py names each entry whose cell is now clean ("now
clean: ..."), and with --strict fails on it."""


def _cross(surfaces, kinds):
    return [f"{surface} / {kind}" for surface in surfaces for kind in kinds]


_IS_INPUT = ["is " + name for name in ("scene.json", "model.obj", "lamp.mtl", "model.gltf",
                                         "mesh.bin", "tex.png", "platform.json", "platform.xml",
                                         "cost.json")]

KNOWN_OPEN = [
    # Issue 37, item 6: the other tools, not clean on h37 (tests/robustness/README.md).
    # accuracy.py (h38err's file) ends a --json path that is a loop of links or lies in a
    # missing folder with exit 5; docs/cli.md's rule says 2 (as ./simulate).
    "write accuracy.py --json / link loop",
    "write accuracy.py --json / missing folder",
    # machine_probe (h40's) takes a network file nested 100,000 zones deep and writes a
    # platform (exit 0): it reads the figures it keeps and never checks the rest.
    "content machine_probe --network / deep nesting",
]
