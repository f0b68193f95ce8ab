"""Furniture, in local coordinates (origin on the floor under the piece's centre, front -z).
Each returns a list of (lo, hi, reflectance, omitted faces); the patch count is noted."""

from .builder import Frame
from .materials import BLACK_TV, BOOKS, DARK_WOOD, LEAVES, STEEL, TERRACOTTA


def table(w, d, h, top, legs, t=0.04, leg=0.05, inset=0.04):
    """Top slab (6 faces) on four legs (4 sides each): 22 patches. w along x, d along z."""
    pieces = [((-w / 2, h - t, -d / 2), (w / 2, h, d / 2), top, ())]
    for sx in (-1, 1):
        for sz in (-1, 1):
            x0 = -w / 2 + inset if sx < 0 else w / 2 - inset - leg
            z0 = -d / 2 + inset if sz < 0 else d / 2 - inset - leg
            pieces.append(((x0, 0.0, z0), (x0 + leg, h - t, z0 + leg), legs, ("-y", "+y")))
    return pieces


def panel_table(w, d, h, top, sides, t=0.04, board=0.04, inset=0.04):
    """Top slab (6 faces) on two end boards (4 sides each) instead of legs: 14 patches. w along
    x, d along z; the boards stand across the ends, `inset` in from the top's edges."""
    pieces = [((-w / 2, h - t, -d / 2), (w / 2, h, d / 2), top, ())]
    for x0 in (-w / 2 + inset, w / 2 - inset - board):
        pieces.append(((x0, 0.0, -d / 2 + inset), (x0 + board, h - t, d / 2 - inset), sides,
                       ("-y", "+y")))
    return pieces


def chair(seat, frame_colour, sw=0.44, sd=0.42, sh=0.46, t=0.04, leg=0.035, bh=0.44, bt=0.03):
    """Seat slab (6) on four legs (4 each) with a backrest at +z (5): 27 patches."""
    pieces = [((-sw / 2, sh - t, -sd / 2), (sw / 2, sh, sd / 2), seat, ())]
    for sx in (-1, 1):
        for sz in (-1, 1):
            x0 = -sw / 2 + 0.015 if sx < 0 else sw / 2 - 0.015 - leg
            z0 = -sd / 2 + 0.015 if sz < 0 else sd / 2 - 0.015 - leg
            pieces.append(((x0, 0.0, z0), (x0 + leg, sh - t, z0 + leg), frame_colour,
                           ("-y", "+y")))
    pieces.append(((-sw / 2, sh, sd / 2 - bt), (sw / 2, sh + bh, sd / 2), seat, ("-y",)))
    return pieces


def upholstered_chair(colour, sw=0.46, sd=0.46, sh=0.46, bh=0.44, bt=0.06):
    """Skirted seat block down to the floor (5 faces) with a backrest at +z (5): 10 patches."""
    return [((-sw / 2, 0.0, -sd / 2), (sw / 2, sh, sd / 2), colour, ("-y",)),
            ((-sw / 2, sh, sd / 2 - bt), (sw / 2, sh + bh, sd / 2), colour, ("-y",))]


def sofa(w, d, colour, cushion, against_wall=True, seat_h=0.42, back_h=0.82, arm_w=0.18,
         arm_h=0.62, back_t=0.22):
    """Backrest (5, or 4 against a wall), two arms (4 each), seat (2): 15 or 14 patches."""
    zb = d / 2 - back_t
    back_omit = ("-y", "+z") if against_wall else ("-y",)
    return [
        ((-w / 2, 0.0, zb), (w / 2, back_h, d / 2), colour, back_omit),
        ((-w / 2, 0.0, -d / 2), (-w / 2 + arm_w, arm_h, zb), colour, ("-y", "+z")),
        ((w / 2 - arm_w, 0.0, -d / 2), (w / 2, arm_h, zb), colour, ("-y", "+z")),
        ((-w / 2 + arm_w, 0.0, -d / 2), (w / 2 - arm_w, seat_h, zb), cushion,
         ("-y", "+z", "-x", "+x")),
    ]


def cabinet(w, d, h, colour, against_wall=True):
    """Closed box on the floor: 4 patches against a wall, else 5."""
    omit = ("-y", "+z") if against_wall else ("-y",)
    return [((-w / 2, 0.0, -d / 2), (w / 2, h, d / 2), colour, omit)]


def bookshelf(w, d, h, shelves, colour, books=0, b=0.025):
    """Open shelf unit against a wall: two sides (4 each), top board (3), plinth (2),
    `shelves` boards (3 each) and `books` rows of books (5 each):
    13 + 3 * shelves + 5 * books patches."""
    inner = (-w / 2 + b, w / 2 - b)
    pieces = [
        ((-w / 2, 0.0, -d / 2), (-w / 2 + b, h, d / 2), colour, ("-y", "+z")),
        ((w / 2 - b, 0.0, -d / 2), (w / 2, h, d / 2), colour, ("-y", "+z")),
        ((inner[0], h - b, -d / 2), (inner[1], h, d / 2), colour, ("-x", "+x", "+z")),
        ((inner[0], 0.0, -d / 2), (inner[1], 0.08, d / 2), colour, ("-x", "+x", "+z", "-y")),
    ]
    step = (h - b - 0.08) / (shelves + 1)
    levels = [0.08] + [0.08 + step * (i + 1) for i in range(shelves)]
    for y in levels[1:]:
        pieces.append(((inner[0], y - b, -d / 2), (inner[1], y, d / 2), colour,
                       ("-x", "+x", "+z")))
    # Rows of books: one block per row, standing on a level, clear of sides and wall.
    span = inner[1] - inner[0]
    for i in range(books):
        y = levels[i % len(levels)]
        part = i // len(levels)
        x0 = inner[0] + 0.03 + part * span / 2
        x1 = x0 + span / 2 - 0.06
        height = min(step - b - 0.05, 0.20 + 0.03 * (i % 3))
        pieces.append(((x0, y, -d / 2 + 0.05), (x1, y + height, d / 2 - 0.04),
                       BOOKS[i % len(BOOKS)], ("-y",)))
    return pieces


def tv_on_stand(w=1.6, d=0.45, h=0.5):
    """Low cabinet against a wall (4) with a television on it (5): 9 patches."""
    return cabinet(w, d, h, DARK_WOOD) + [
        ((-0.6, h, -0.03), (0.6, h + 0.7, 0.05), BLACK_TV, ("-y",))]


def plant():
    """Pot (4 sides) under a block of foliage (6): 10 patches."""
    return [((-0.15, 0.0, -0.15), (0.15, 0.35, 0.15), TERRACOTTA, ("-y", "+y")),
            ((-0.3, 0.35, -0.3), (0.3, 1.1, 0.3), LEAVES, ())]


def desk_and_chair(b, x, z, desk_colour, seat_colour, front="-z", panels=False):
    """A student's desk (0.7 x 0.5) on four steel legs (22 patches), or on two steel end
    panels if `panels` (14), with the chair behind it, the sitter looking `front`: 49 or 41
    patches. (x, z) is the desk centre."""
    f = Frame(x, z, front)
    if panels:
        desk = panel_table(0.7, 0.5, 0.72, desk_colour, STEEL, board=0.03)
    else:
        desk = table(0.7, 0.5, 0.72, desk_colour, STEEL, leg=0.04)
    b.place(desk, f, "desk")
    cx, cz = f.turn(0.0, 0.25 + 0.06 + 0.21)
    b.place(chair(seat_colour, STEEL), Frame(x + cx, z + cz, front), "chair")


def table_with_chairs(b, x, z, w, d, top, legs, chair_pieces, per_side, label):
    """A table w (x) by d (z) on four legs with `per_side` chairs (chair_pieces: a chair's
    pieces, front -z) along each long side: 22 + 2 * per_side * (a chair's patches)."""
    b.place(table(w, d, 0.74, top, legs), Frame(x, z), label)
    for side, front in ((-1, "+z"), (1, "-z")):
        for i in range(per_side):
            cx = x - w / 2 + w * (i + 0.5) / per_side
            cz = z + side * (d / 2 + 0.06 + 0.21)
            b.place(chair_pieces, Frame(cx, cz, front), label + "-chair")
