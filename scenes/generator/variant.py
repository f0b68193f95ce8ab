"""A scene of the paper built with other free choices (scenes/generator/choices.py): the same
patch and element counts, another room, furniture, element split or patch order. With the
default choices this is exactly the committed scene (tests/scenes_reproducible_test.sh)."""

import random

from .choices import DEFAULT, ORDERS
from .elements import fit_elements
from .interiors import scene0, scene1, scene2, scene3
from .targets import TARGETS, patch_cap
from .text import to_text
from .validation import validate
from .vectors import clean

MAKERS = {"scene0": scene0, "scene1": scene1, "scene2": scene2, "scene3": scene3}


def scale_scene(b, scale):
    """Every coordinate of the built scene (patches, pieces, flats, room, camera) scaled along
    x, y, z: an affine map, so touching pieces keep touching and none starts to overlap."""
    def point(p):
        return tuple(clean(p[i] * scale[i]) for i in range(3))

    for p in b.patches:
        p["v"] = [point(v) for v in p["v"]]
        kind, ref = p["check"]
        if kind != "dir":
            p["check"] = (kind, tuple(ref[i] * scale[i] for i in range(3)))
    b.boxes = [(point(lo), point(hi), label) for lo, hi, label in b.boxes]
    b.flats = [(axis, clean(c * scale[axis]), point(lo), point(hi), label)
               for axis, c, lo, hi, label in b.flats]
    b.room = (point(b.room[0]), point(b.room[1]))
    eye, look_at, fov = b.camera
    b.camera = (point(eye), point(look_at), fov)


def is_piece(patch):
    """A face of a solid piece (furniture, column, stage), checked to face out of it."""
    return patch["check"][0] == "out"


def reorder(patches, choices):
    if choices.order == "generator":
        return patches
    if choices.order == "pieces-first":
        return [p for p in patches if is_piece(p)] + [p for p in patches if not is_piece(p)]
    if choices.order == "random":
        shuffled = list(patches)
        random.Random(choices.order_seed).shuffle(shuffled)
        return shuffled
    raise ValueError("order %r: not one of %s" % (choices.order, ", ".join(ORDERS)))


def build_scene(name, choices=DEFAULT):
    """The scene `name` (scene0 .. scene3) with these choices, its elements fitted to the
    paper's exact count and its patches in the chosen order."""
    b = MAKERS[name](choices)
    patches, elements = TARGETS[name]
    if len(b.patches) != patches:
        raise SystemExit("%s: %d patches, want %d" % (name, len(b.patches), patches))
    if tuple(choices.room_scale) != (1.0, 1.0, 1.0):
        scale_scene(b, choices.room_scale)
    factors = None
    if choices.piece_element_size != 1.0:
        factors = [choices.piece_element_size if is_piece(p) else 1.0 for p in b.patches]
    fit_elements(b.patches, elements, patch_cap(name), factors)
    b.patches = reorder(b.patches, choices)
    return b


def scene_text(name, choices=DEFAULT):
    """(text, problems): the scene file's text and what the validation finds against it
    (an empty list when the scene is fine; then its counts are the paper's exactly)."""
    b = build_scene(name, choices)
    text = to_text(b)
    return text, validate(b, text, TARGETS[name])
