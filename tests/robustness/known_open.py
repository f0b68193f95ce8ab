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
]
