"""The generator's free choices: what the paper does not give about a scene beyond its patch
and element counts (analysis/unknowns.json lists them with their ranges and reasons). The
defaults are the committed scenes, byte for byte; analysis/ncube/worlds.py draws others.

Every choice keeps the paper's patch and element counts exactly: the room and the furniture
change size, not their number of surfaces; the floor and ceiling panels may be turned (nx x nz
becomes nz x nx, and so the walls' strips), which keeps every count; the elements are fitted
to the exact total whatever their split between solid pieces and room surfaces; the order only
permutes the patches after the elements are fitted."""

from dataclasses import dataclass

ORDERS = ("generator", "pieces-first", "random")


@dataclass(frozen=True)
class SceneChoices:
    # The room (and everything in it) scaled along x (width), y (height), z (depth).
    room_scale: tuple = (1.0, 1.0, 1.0)
    # Each piece of furniture placed through a Frame scaled about its own origin: width (its
    # local x) and height; its depth is kept, so that pieces against a wall stay inside.
    furniture_width: float = 1.0
    furniture_height: float = 1.0
    # The element edge on solid pieces (furniture, columns, stage) over that on the room's
    # surfaces, lights and flat decorations (1: one element size for the whole scene).
    piece_element_size: float = 1.0
    # The room shell's panels turned: floor and ceiling nx x nz -> nz x nx, wall strips too.
    turn_panels: bool = False
    # The patch order of the file: "generator" (each room's surfaces, lights, then furniture
    # and decorations), "pieces-first" (the solid pieces first, then the rest, each in the
    # generator's order), "random" (a seeded shuffle with order_seed).
    order: str = "generator"
    order_seed: int = 0

    def is_default(self):
        return self == DEFAULT


DEFAULT = SceneChoices()
