#!/usr/bin/env python3
"""Generates the radiosity test scenes of the simulator (described in docs/scenes.md).

    python3 scenes/generate.py [--out DIR]

writes into DIR (default: the folder of this script)

    scene0.json .. scene3.json  furnished interiors with exactly the patch and element counts
                                of the four test scenes of Stuerzlinger & Wild 1994, section 5;
    cornell-box.json            the published Cornell box data (geometry in mm).

The output is byte-for-byte reproducible: no randomness, a fixed patch order, a fixed number
format (at most 4 decimals) and a fixed layout of one patch per line. Python 3 standard library
only. Every scene is validated from the very text that is written (planarity, convexity, size,
orientation, overlaps, exact counts); a failed check prints the problem and exits with 1
without writing anything.
"""

import argparse
import heapq
import json
import math
import os
import sys

# The paper's scene table: name -> (patches, elements).
TARGETS = {
    "scene0": (52, 1162),
    "scene1": (288, 4648),
    "scene2": (832, 18952),
    "scene3": (3328, 74368),
    # Not in the paper: the "scenes, where even the memory for the patches exceeds available
    # memory, i.e. >= 15000 patches" of its section 6 (docs/scenes.md, scene4).
    "scene4": (51200, 76800),
}

MAX_SUBDIVISION = 64  # largest nu or nv of any patch

# The simulator gives whole patches to up to 64 radiosity processors, each about the same
# number of elements (largest patches first, each to the processor with the fewest elements so
# far; paper, section 4). A patch cannot be split, so in the scenes run with up to 64 of them no
# patch may hold more than 1/64 of the scene's elements; the room surfaces are cut into panels
# of about half that, so that the 64-way partition balances within a few percent.
# scene0 (Table 5) is run with at most 52 processors, 32 of them with V = 0 besides R = 52 (one
# patch each); its patches hold at most 1/32 of its elements. scene4 is meant for hypercubes up
# to 8,192 nodes, e.g. 512 radiosity processors with 15 visibility processors each.
PARTITION_WAYS = {"scene0": 32, "scene1": 64, "scene2": 64, "scene3": 64, "scene4": 512}
# Largest / mean elements per processor of that partition; scene0's 36 elements per processor
# on average leave less room (a patch of up to 36 and a small one).
MAX_IMBALANCE = {"scene0": 1.15, "scene1": 1.10, "scene2": 1.10, "scene3": 1.10, "scene4": 1.10}
COMPACT = {"scene4"}  # scenes written without spaces (the file would be about 30 % larger)
LIGHT_EMISSION = (10.0, 10.0, 9.0)  # ceiling panels of scenes 0-3, slightly warm white

# ------------------------------------------------------------------------------------------
# Vectors (plain tuples).


def vsub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def vdot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def vcross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def vlen(a):
    return math.sqrt(vdot(a, a))


def vmean(points):
    n = float(len(points))
    return tuple(sum(p[i] for p in points) / n for i in range(3))


def clean(x):
    """Rounds a coordinate to 4 decimals (and turns -0.0 into 0.0)."""
    return round(x, 4) + 0.0


# ------------------------------------------------------------------------------------------
# Materials: diffuse reflectances (RGB, all within 0.1 .. 0.8).

OFF_WHITE = (0.74, 0.72, 0.66)
CEILING = (0.80, 0.80, 0.78)
OAK_FLOOR = (0.55, 0.40, 0.26)
LINOLEUM = (0.42, 0.46, 0.48)
CARPET = (0.36, 0.34, 0.40)
PALE_BLUE = (0.60, 0.66, 0.72)
WARM_WALL = (0.76, 0.70, 0.60)
WOOD = (0.62, 0.46, 0.30)
DARK_WOOD = (0.36, 0.25, 0.17)
BIRCH = (0.72, 0.64, 0.50)
STEEL = (0.45, 0.46, 0.48)
RED_FABRIC = (0.62, 0.18, 0.14)
BLUE_FABRIC = (0.22, 0.32, 0.55)
GREEN_FABRIC = (0.24, 0.46, 0.28)
GREY_FABRIC = (0.42, 0.42, 0.44)
ORANGE_PLASTIC = (0.78, 0.45, 0.15)
BLUE_PLASTIC = (0.20, 0.36, 0.62)
WHITE_PAINT = (0.78, 0.78, 0.76)
BLACK_TV = (0.10, 0.10, 0.11)
DOOR = (0.50, 0.34, 0.20)
WINDOW = (0.28, 0.36, 0.46)
BLACKBOARD = (0.12, 0.22, 0.16)
LEAVES = (0.20, 0.44, 0.16)
TERRACOTTA = (0.60, 0.32, 0.20)
LAMP = (0.80, 0.80, 0.80)  # reflectance of the emitting light panels
CONCRETE = (0.58, 0.57, 0.55)
STAGE = (0.45, 0.30, 0.22)
POSTERS = [(0.70, 0.30, 0.25), (0.25, 0.45, 0.65), (0.75, 0.65, 0.25), (0.35, 0.55, 0.35),
           (0.55, 0.35, 0.60), (0.70, 0.55, 0.45)]
BOOKS = [(0.55, 0.15, 0.15), (0.15, 0.25, 0.50), (0.20, 0.40, 0.22), (0.70, 0.60, 0.30),
         (0.40, 0.20, 0.40)]


# ------------------------------------------------------------------------------------------
# Scene builder.


class Builder:
    """Collects patches plus what the validation needs to know about them.

    Each patch records how its orientation is checked: ("in", c) for room surfaces and wall
    decorations (the normal must point towards the room centre c), ("out", c) for furniture
    (away from the piece's centre c) and ("dir", d) for light panels (along d).
    """

    def __init__(self, name, min_edge):
        self.name = name
        self.min_edge = min_edge
        self.patches = []
        self.boxes = []  # (lo, hi, label) of every solid piece, for the overlap check
        self.flats = []  # (axis, coord, lo, hi, label) of single-quad decorations and lights
        self.room = None  # (lo, hi)
        self.camera = None

    # -- patches

    def add(self, verts, refl, emis=None, check=None, elements=None):
        self.patches.append({
            "v": [tuple(clean(c) for c in p) for p in verts],
            "refl": refl,
            "emis": emis,
            "check": check,
            "nu": elements[0] if elements else 1,
            "nv": elements[1] if elements else 1,
        })

    def axis_rect(self, axis, sign, c, lo, hi, refl, emis=None, check=None):
        """Rectangle in the plane x[axis] == c spanning lo..hi in the two other axes, facing
        +axis (sign > 0) or -axis (sign < 0)."""
        b, d = (axis + 1) % 3, (axis + 2) % 3

        def point(u, v):
            p = [0.0, 0.0, 0.0]
            p[axis], p[b], p[d] = c, u, v
            return tuple(p)

        q = [point(lo[b], lo[d]), point(hi[b], lo[d]), point(hi[b], hi[d]), point(lo[b], hi[d])]
        if sign < 0:  # (e_b x e_d) = +e_axis, so reverse the winding to face -axis
            q = [q[0], q[3], q[2], q[1]]
        self.add(q, refl, emis, check)

    # -- building blocks

    def room_shell(self, size, nx, nz, floor, ceiling, walls, wx=None, wz=None, rows=1):
        """The room [0,W] x [0,H] x [0,D], all surfaces facing inwards. Floor and ceiling are
        cut into nx x nz panels; the walls along x (z = 0, z = D) into wx and those along z
        (x = 0, x = W) into wz vertical strips (default nx and nz), each strip into `rows`
        panels one above the other. Keeps every patch's element count small (see
        PARTITION_WAYS). walls: colours of the walls x=0, x=W, z=0, z=D."""
        W, H, D = size
        wx = nx if wx is None else wx
        wz = nz if wz is None else wz
        self.room = ((0.0, 0.0, 0.0), (W, H, D))
        chk = ("in", (W / 2.0, H / 2.0, D / 2.0))
        xs = [clean(W * i / nx) for i in range(nx + 1)]
        zs = [clean(D * k / nz) for k in range(nz + 1)]
        for i in range(nx):
            for k in range(nz):
                self.axis_rect(1, +1, 0.0, (xs[i], 0, zs[k]), (xs[i + 1], 0, zs[k + 1]), floor,
                               check=chk)
        for i in range(nx):
            for k in range(nz):
                self.axis_rect(1, -1, H, (xs[i], 0, zs[k]), (xs[i + 1], 0, zs[k + 1]), ceiling,
                               check=chk)
        xs = [clean(W * i / wx) for i in range(wx + 1)]
        zs = [clean(D * k / wz) for k in range(wz + 1)]
        ys = [clean(H * j / rows) for j in range(rows + 1)]
        for k in range(wz):
            for j in range(rows):
                self.axis_rect(0, +1, 0.0, (0, ys[j], zs[k]), (0, ys[j + 1], zs[k + 1]), walls[0],
                               check=chk)
        for k in range(wz):
            for j in range(rows):
                self.axis_rect(0, -1, W, (0, ys[j], zs[k]), (0, ys[j + 1], zs[k + 1]), walls[1],
                               check=chk)
        for i in range(wx):
            for j in range(rows):
                self.axis_rect(2, +1, 0.0, (xs[i], ys[j], 0), (xs[i + 1], ys[j + 1], 0), walls[2],
                               check=chk)
        for i in range(wx):
            for j in range(rows):
                self.axis_rect(2, -1, D, (xs[i], ys[j], 0), (xs[i + 1], ys[j + 1], 0), walls[3],
                               check=chk)

    def box(self, lo, hi, refl, omit=(), label=""):
        """Axis-aligned box, faces outwards; `omit` names faces that are hidden (touching the
        floor, a wall or another piece): '-x', '+x', '-y', '+y', '-z', '+z'."""
        lo = tuple(clean(c) for c in lo)
        hi = tuple(clean(c) for c in hi)
        centre = vmean([lo, hi])
        for axis in range(3):
            for sign in (-1, +1):
                if ("-" if sign < 0 else "+") + "xyz"[axis] in omit:
                    continue
                self.axis_rect(axis, sign, hi[axis] if sign > 0 else lo[axis], lo, hi, refl,
                               check=("out", centre))
        self.boxes.append((lo, hi, label))

    def light(self, cx, cz, sx, sz, drop=0.02, emission=LIGHT_EMISSION):
        """Emitting ceiling panel sx x sz centred at (cx, cz), `drop` below the ceiling,
        facing down."""
        y = clean(self.room[1][1] - drop)
        lo = (clean(cx - sx / 2.0), y, clean(cz - sz / 2.0))
        hi = (clean(cx + sx / 2.0), y, clean(cz + sz / 2.0))
        self.axis_rect(1, -1, y, lo, hi, LAMP, emis=emission, check=("dir", (0.0, -1.0, 0.0)))
        self.flats.append((1, y, lo, hi, "light"))

    def wall_panel(self, wall, u0, u1, y0, y1, refl, offset=0.005, label="decor"):
        """Flat decoration (door, window, board, picture) `offset` in front of a wall:
        wall 'x0' (x=0), 'xW' (x=W), 'z0' (z=0) or 'zD' (z=D); u runs along the wall."""
        W, H, D = self.room[1]
        chk = ("in", (W / 2.0, H / 2.0, D / 2.0))
        if wall in ("x0", "xW"):
            c = offset if wall == "x0" else W - offset
            lo, hi, axis, sign = (c, y0, u0), (c, y1, u1), 0, (+1 if wall == "x0" else -1)
        else:
            c = offset if wall == "z0" else D - offset
            lo, hi, axis, sign = (u0, y0, c), (u1, y1, c), 2, (+1 if wall == "z0" else -1)
        lo = tuple(clean(v) for v in lo)
        hi = tuple(clean(v) for v in hi)
        self.axis_rect(axis, sign, clean(c), lo, hi, refl, check=chk)
        self.flats.append((axis, clean(c), lo, hi, label))

    def rug(self, x0, x1, z0, z1, refl, height=0.005):
        W, H, D = self.room[1]
        lo, hi = (clean(x0), height, clean(z0)), (clean(x1), height, clean(z1))
        self.axis_rect(1, +1, height, lo, hi, refl, check=("in", (W / 2.0, H / 2.0, D / 2.0)))
        self.flats.append((1, height, lo, hi, "rug"))

    def place(self, pieces, frame, label):
        for lo, hi, refl, omit in pieces:
            wlo, whi = frame.box(lo, hi)
            self.box(wlo, whi, refl, [frame.face(f) for f in omit], label)


class Frame:
    """Local furniture coordinates -> world. A piece is modelled with its front towards -z
    (a chair: the way the sitter looks; a cabinet: its doors, its back at +z against the
    wall); the frame turns it by quarter turns about y so that its front faces `front`
    ('-z', '-x', '+z', '+x') and moves its origin to (ox, 0, oz)."""

    TURNS = {"-z": 0, "-x": 1, "+z": 2, "+x": 3}

    def __init__(self, ox, oz, front="-z"):
        self.ox, self.oz, self.k = ox, oz, self.TURNS[front]

    def turn(self, x, z):
        for _ in range(self.k):  # a quarter turn about +y: (x, z) -> (z, -x)
            x, z = z, -x
        return x, z

    def box(self, lo, hi):
        ax, az = self.turn(lo[0], lo[2])
        bx, bz = self.turn(hi[0], hi[2])
        return ((min(ax, bx) + self.ox, lo[1], min(az, bz) + self.oz),
                (max(ax, bx) + self.ox, hi[1], max(az, bz) + self.oz))

    def face(self, name):
        if name[1] == "y":
            return name
        s = 1.0 if name[0] == "+" else -1.0
        x, z = self.turn(s, 0.0) if name[1] == "x" else self.turn(0.0, s)
        if abs(x) > 0.5:
            return ("+" if x > 0 else "-") + "x"
        return ("+" if z > 0 else "-") + "z"


# ------------------------------------------------------------------------------------------
# Furniture, in local coordinates (origin on the floor under the piece's centre, front -z).
# Each returns a list of (lo, hi, reflectance, omitted faces); the patch count is noted.


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


# ------------------------------------------------------------------------------------------
# The four scenes.


def scene0():
    """A small living room: one table, a sofa, a sideboard, two ceiling lights."""
    b = Builder("scene0", min_edge=0.02)
    W, H, D = 6.0, 2.7, 5.0
    b.room_shell((W, H, D), 1, 1, OAK_FLOOR, CEILING, [OFF_WHITE, OFF_WHITE, OFF_WHITE,
                                                         PALE_BLUE])
    b.light(2.0, 2.5, 0.6, 0.6)
    b.light(4.0, 2.5, 0.6, 0.6)
    b.place(table(1.4, 0.8, 0.74, WOOD, DARK_WOOD), Frame(3.0, 2.4), "table")
    b.place(sofa(2.0, 0.9, BLUE_FABRIC, BLUE_FABRIC), Frame(3.0, D - 0.45, "-z"), "sofa")
    b.place(cabinet(1.2, 0.45, 0.8, BIRCH), Frame(0.225, 2.5, "+x"), "sideboard")
    b.rug(2.0, 4.0, 3.0, 3.9, RED_FABRIC)
    b.wall_panel("xW", 0.5, 1.4, 0.0, 2.05, DOOR)
    b.wall_panel("x0", 3.5, 4.6, 1.0, 2.2, WINDOW)
    b.wall_panel("zD", 2.5, 3.5, 1.2, 1.8, POSTERS[0])
    b.camera = ((5.4, 1.6, 0.5), (2.8, 0.7, 3.2), 55.0)
    return b


def scene1():
    """A furnished living and dining room."""
    b = Builder("scene1", min_edge=0.02)
    W, H, D = 8.0, 2.7, 6.0
    b.room_shell((W, H, D), 5, 5, OAK_FLOOR, CEILING, [WARM_WALL] * 4, wx=6, wz=4, rows=2)
    for x in (2.0, 6.0):
        for z in (1.8, 4.2):
            b.light(x, z, 0.6, 0.6)
    # Dining corner: table with four chairs, sideboard, bookshelf.
    table_with_chairs(b, 2.0, 3.0, 1.6, 0.9, WOOD, DARK_WOOD, upholstered_chair(RED_FABRIC), 2,
                      "dining")
    b.place(cabinet(1.6, 0.45, 0.85, DARK_WOOD), Frame(2.0, D - 0.225, "-z"), "sideboard")
    b.place(bookshelf(1.0, 0.35, 2.0, 3, BIRCH, books=2), Frame(0.175, 1.2, "+x"), "bookshelf")
    # Living corner: sofa, coffee table, armchair, television.
    b.place(sofa(2.2, 0.9, GREY_FABRIC, BLUE_FABRIC), Frame(6.0, D - 0.45, "-z"), "sofa")
    b.place(panel_table(1.0, 0.55, 0.42, BIRCH, BIRCH, board=0.03), Frame(6.0, 4.2),
            "coffee-table")
    b.place(sofa(0.9, 0.85, GREEN_FABRIC, GREEN_FABRIC, against_wall=False),
            Frame(4.5, 4.2, "+x"), "armchair")
    b.place(tv_on_stand(), Frame(6.0, 0.225, "+z"), "tv")
    # Writing desk by the right wall.
    b.place(panel_table(1.2, 0.6, 0.74, WOOD, DARK_WOOD), Frame(W - 0.32, 1.5, "-x"), "desk")
    b.place(chair(BLUE_FABRIC, DARK_WOOD), Frame(W - 0.88, 1.5, "+x"), "desk-chair")
    b.wall_panel("z0", 1.0, 1.9, 0.0, 2.05, DOOR)
    b.wall_panel("xW", 3.0, 4.4, 0.9, 2.2, WINDOW)
    b.wall_panel("x0", 3.5, 5.0, 0.9, 2.2, WINDOW)
    b.camera = ((0.6, 1.65, 0.4), (5.0, 0.6, 4.2), 58.0)
    return b


def scene2():
    """A classroom: fifteen desks with chairs, teacher's desk, blackboard, cabinets."""
    b = Builder("scene2", min_edge=0.02)
    W, H, D = 10.0, 3.2, 8.0
    b.room_shell((W, H, D), 6, 5, LINOLEUM, CEILING, [OFF_WHITE, OFF_WHITE, OFF_WHITE,
                                                        PALE_BLUE], rows=2)
    for z in (2.0, 4.3, 6.6):
        for x in (1.5, 3.8, 6.2, 8.5):
            b.light(x, z, 0.6, 1.2)
    seats = [ORANGE_PLASTIC, BLUE_PLASTIC, ORANGE_PLASTIC, BLUE_PLASTIC, ORANGE_PLASTIC]
    for row, z in enumerate((3.0, 4.6, 6.2)):
        for col, x in enumerate((1.6, 3.3, 5.0, 6.7, 8.4)):
            desk_and_chair(b, x, z, BIRCH, seats[(col + row) % len(seats)], panels=True)
    b.place(table(1.4, 0.7, 0.76, WOOD, DARK_WOOD), Frame(5.0, 1.4), "teacher-desk")
    b.place(chair(RED_FABRIC, STEEL), Frame(5.0, 0.79, "+z"), "teacher-chair")
    for i, x in enumerate((2.0, 5.0, 8.0)):  # cabinets with a poster over each
        b.place(cabinet(1.2, 0.45, 1.1, WHITE_PAINT), Frame(x, D - 0.225, "-z"), "cabinet")
        b.wall_panel("zD", x - 0.4, x + 0.4, 1.45, 2.25, POSTERS[3 + i])
    b.place(bookshelf(1.0, 0.35, 2.0, 3, BIRCH, books=1), Frame(3.5, D - 0.175, "-z"),
            "bookshelf")
    for u0, u1 in ((2.5, 4.15), (4.2, 5.8), (5.85, 7.5)):  # a blackboard in three panels
        b.wall_panel("z0", u0, u1, 0.9, 2.1, BLACKBOARD)
    b.wall_panel("x0", 0.6, 1.6, 0.0, 2.1, DOOR)
    for z0 in (1.5, 3.8, 6.1):
        b.wall_panel("xW", z0, z0 + 1.5, 0.9, 2.6, WINDOW)
    for i, z0 in enumerate((3.0, 4.6, 6.2)):
        b.wall_panel("x0", z0 - 0.4, z0 + 0.4, 1.3, 2.2, POSTERS[i])
    b.camera = ((9.4, 1.7, 7.7), (4.5, 0.8, 2.5), 58.0)
    return b


def scene3():
    """A large study hall: 48 desks with chairs, three group tables with six chairs each,
    a stage with a lectern, bookshelves, a lounge corner, four columns, 24 lights."""
    b = Builder("scene3", min_edge=0.02)
    W, H, D = 30.0, 5.0, 20.0
    b.room_shell((W, H, D), 6, 5, CARPET, CEILING, [OFF_WHITE, OFF_WHITE, PALE_BLUE,
                                                      OFF_WHITE], wz=4, rows=2)
    for k in range(4):
        for i in range(6):
            b.light(2.5 + 5.0 * i, 2.5 + 5.0 * k, 1.2, 1.2)
    for x in (10.0, 20.0):
        for z in (5.0, 15.0):
            b.box((x - 0.25, 0.0, z - 0.25), (x + 0.25, H, z + 0.25), CONCRETE,
                  ("-y", "+y"), "column")
    # Study area (x < 19): 8 x 6 desks facing the stage at z = 0.
    seats = [ORANGE_PLASTIC, BLUE_PLASTIC]
    for row, z in enumerate((3.0, 5.4, 7.8, 10.2, 12.6, 15.0)):
        for col, x in enumerate((1.8, 3.9, 6.0, 8.1, 11.9, 14.0, 16.1, 18.2)):
            desk_and_chair(b, x, z, BIRCH, seats[(col + row) % 2])
    b.box((6.0, 0.0, 0.0), (14.0, 0.4, 2.0), STAGE, ("-y", "-z"), "stage")
    b.box((9.7, 0.4, 1.0), (10.3, 1.5, 1.5), DARK_WOOD, ("-y",), "lectern")
    # Group area (x > 21): three long tables with six chairs each.
    for z in (4.0, 10.0, 16.0):
        table_with_chairs(b, 25.0, z, 2.4, 1.0, WOOD, DARK_WOOD, chair(GREEN_FABRIC, STEEL), 3,
                          "group")
    # Bookshelves along the back wall, the first with books.
    for i in range(9):
        b.place(bookshelf(1.0, 0.35, 2.0, 3, BIRCH, books=3 if i == 0 else 0),
                Frame(1.5 + 1.1 * i, D - 0.175, "-z"), "bookshelf")
    # Lounge corner.
    b.place(sofa(2.2, 0.9, BLUE_FABRIC, BLUE_FABRIC), Frame(24.0, D - 0.45, "-z"), "sofa")
    b.place(sofa(2.2, 0.9, RED_FABRIC, RED_FABRIC), Frame(27.0, D - 0.45, "-z"), "sofa")
    for x, z in ((29.5, 19.5), (15.0, 19.5)):
        b.place(plant(), Frame(x, z), "plant")
    b.wall_panel("x0", 0.6, 2.4, 0.0, 2.4, DOOR)
    b.wall_panel("xW", 8.0, 9.8, 0.0, 2.4, DOOR)
    for z0 in (4.0, 8.0, 12.0, 16.0):
        b.wall_panel("x0", z0, z0 + 2.5, 1.2, 3.8, WINDOW)
    for z0 in (1.5, 12.5):
        b.wall_panel("xW", z0, z0 + 3.0, 1.2, 3.8, WINDOW)
    b.wall_panel("z0", 7.5, 12.5, 1.6, 4.2, WHITE_PAINT)  # projection screen over the stage
    for i, x0 in enumerate((17.0, 19.5, 22.0)):
        b.wall_panel("z0", x0, x0 + 1.2, 1.5, 2.7, POSTERS[i])
    for z0 in (5.0, 10.3):
        b.wall_panel("xW", z0, z0 + 2.0, 0.9, 2.1, WHITE_PAINT)  # whiteboards
    b.camera = ((29.0, 2.5, 1.0), (15.0, 0.5, 12.0), 60.0)
    return b


def copy_room(b, room, ox, oz):
    """Copies every patch, piece and flat of the one-room scene `room` (built at the origin)
    into `b`, moved by (ox, 0, oz); its elements are fitted later for the whole scene."""
    def moved(p):
        return (clean(p[0] + ox), p[1], clean(p[2] + oz))

    for p in room.patches:
        kind, ref = p["check"]
        check = (kind, ref if kind == "dir" else (ref[0] + ox, ref[1], ref[2] + oz))
        b.add([moved(v) for v in p["v"]], p["refl"], p["emis"], check)
    for lo, hi, label in room.boxes:
        b.boxes.append((moved(lo), moved(hi), label))
    for axis, c, lo, hi, label in room.flats:
        c = clean(c + (ox if axis == 0 else oz if axis == 2 else 0.0))
        b.flats.append((axis, c, moved(lo), moved(hi), label))


SCENE4_WALL = 0.3  # gap between neighbouring rooms (the wall between them, not modelled)


def scene4():
    """A floor of a school building: eight study halls (scene3), twenty-four classrooms
    (scene2) and sixteen staff flats' living rooms (scene1), each room a closed box as in
    those scenes (doors shut), side by side with walls of 0.3 m between them."""
    b = Builder("scene4", min_edge=0.02)
    z = 0.0
    rows = [(scene3, 30.0, 20.0, 4, 2), (scene2, 10.0, 8.0, 12, 2), (scene1, 8.0, 6.0, 8, 2)]
    width = 0.0
    for make, room_w, room_d, per_row, row_count in rows:
        for row in range(row_count):
            for i in range(per_row):
                copy_room(b, make(), clean(i * (room_w + SCENE4_WALL)), clean(z))
            width = max(width, per_row * room_w + (per_row - 1) * SCENE4_WALL)
            z += room_d + SCENE4_WALL
    b.room = ((0.0, 0.0, 0.0), (clean(width), 5.0, clean(z - SCENE4_WALL)))
    b.camera = scene3().camera  # in the first study hall, at the origin
    return b


# ------------------------------------------------------------------------------------------
# The Cornell box (Cornell Program of Computer Graphics, "Cornell Box Data"; mm).

CB_WHITE = (0.725, 0.71, 0.68)
CB_RED = (0.63, 0.065, 0.05)
CB_GREEN = (0.14, 0.45, 0.091)
CB_LIGHT_EMISSION = (17.0, 12.0, 4.0)
CB_ELEMENT = 45.0  # target element edge, mm

CB_SHORT_BLOCK = [
    [(130.0, 165.0, 65.0), (82.0, 165.0, 225.0), (240.0, 165.0, 272.0), (290.0, 165.0, 114.0)],
    [(290.0, 0.0, 114.0), (290.0, 165.0, 114.0), (240.0, 165.0, 272.0), (240.0, 0.0, 272.0)],
    [(130.0, 0.0, 65.0), (130.0, 165.0, 65.0), (290.0, 165.0, 114.0), (290.0, 0.0, 114.0)],
    [(82.0, 0.0, 225.0), (82.0, 165.0, 225.0), (130.0, 165.0, 65.0), (130.0, 0.0, 65.0)],
    [(240.0, 0.0, 272.0), (240.0, 165.0, 272.0), (82.0, 165.0, 225.0), (82.0, 0.0, 225.0)],
]
CB_TALL_BLOCK = [
    [(423.0, 330.0, 247.0), (265.0, 330.0, 296.0), (314.0, 330.0, 456.0), (472.0, 330.0, 406.0)],
    [(423.0, 0.0, 247.0), (423.0, 330.0, 247.0), (472.0, 330.0, 406.0), (472.0, 0.0, 406.0)],
    [(472.0, 0.0, 406.0), (472.0, 330.0, 406.0), (314.0, 330.0, 456.0), (314.0, 0.0, 456.0)],
    [(314.0, 0.0, 456.0), (314.0, 330.0, 456.0), (265.0, 330.0, 296.0), (265.0, 0.0, 296.0)],
    [(265.0, 0.0, 296.0), (265.0, 330.0, 296.0), (423.0, 330.0, 247.0), (423.0, 0.0, 247.0)],
]


def cb_elements(verts):
    """nu x nv for an edge of about CB_ELEMENT mm: nu along v0->v1, nv along v0->v3 (for a
    triangle: its height over the edge v0 v1)."""
    e1 = vsub(verts[1], verts[0])
    lu = vlen(e1)
    if len(verts) == 4:
        lv = vlen(vsub(verts[3], verts[0]))
    else:
        lv = vlen(vcross(e1, vsub(verts[2], verts[0]))) / lu
    return (max(1, int(round(lu / CB_ELEMENT))), max(1, int(round(lv / CB_ELEMENT))))


def cornell_box():
    b = Builder("cornell-box", min_edge=20.0)
    b.room = ((0.0, 0.0, 0.0), (556.0, 548.8, 559.2))
    inside = ("in", (278.0, 274.4, 279.6))

    def add(verts, refl, check, emis=None):
        b.add(verts, refl, emis, check, cb_elements(verts))

    add([(552.8, 0.0, 0.0), (0.0, 0.0, 0.0), (0.0, 0.0, 559.2), (549.6, 0.0, 559.2)],
        CB_WHITE, inside)  # floor
    add([(556.0, 548.8, 0.0), (556.0, 548.8, 559.2), (0.0, 548.8, 559.2), (0.0, 548.8, 0.0)],
        CB_WHITE, inside)  # ceiling (without the hole for the light)
    add([(549.6, 0.0, 559.2), (0.0, 0.0, 559.2), (0.0, 548.8, 559.2), (556.0, 548.8, 559.2)],
        CB_WHITE, inside)  # back wall
    add([(0.0, 0.0, 559.2), (0.0, 0.0, 0.0), (0.0, 548.8, 0.0), (0.0, 548.8, 559.2)],
        CB_GREEN, inside)  # right wall
    # The published left wall (552.8,0,0) (549.6,0,559.2) (556,548.8,559.2) (556,548.8,0) is
    # not planar: its 4th vertex is 3.2 mm off the plane of the first three. It is split along
    # the diagonal (552.8,0,0)-(556,548.8,559.2) into two triangles, each listed from a floor
    # or ceiling edge so that its grid runs along that edge.
    a, bb, c, d = (552.8, 0.0, 0.0), (549.6, 0.0, 559.2), (556.0, 548.8, 559.2), (556.0, 548.8, 0.0)
    add([a, bb, c], CB_RED, inside)
    add([c, d, a], CB_RED, inside)
    # The light (published at y = 548.8, 343..213 x 227..332), lowered 0.1 mm below the
    # ceiling so that it does not coincide with it; faces down.
    add([(343.0, 548.7, 227.0), (343.0, 548.7, 332.0), (213.0, 548.7, 332.0),
         (213.0, 548.7, 227.0)], (0.78, 0.78, 0.78), ("dir", (0.0, -1.0, 0.0)),
        emis=CB_LIGHT_EMISSION)
    b.flats.append((1, 548.7, (213.0, 548.7, 227.0), (343.0, 548.7, 332.0), "light"))
    for block, height in ((CB_SHORT_BLOCK, 165.0), (CB_TALL_BLOCK, 330.0)):
        top = block[0]
        centre = (sum(p[0] for p in top) / 4.0, height / 2.0, sum(p[2] for p in top) / 4.0)
        for face in block:
            add(face, CB_WHITE, ("out", centre))
    b.camera = ((278.0, 273.0, -800.0), (278.0, 273.0, 0.0), 39.3)
    return b


# ------------------------------------------------------------------------------------------
# Element subdivision with an exact total.


def edge_lengths(p):
    v = p["v"]
    e1 = vsub(v[1], v[0])
    lu = vlen(e1)
    if len(v) == 4:
        return lu, vlen(vsub(v[3], v[0]))
    return lu, vlen(vcross(e1, vsub(v[2], v[0]))) / lu


def fit_elements(patches, target, cap=None):
    """Sets every patch's nu, nv so that elements are about h x h for one h over the whole
    scene (so element counts follow patch areas), then refines the coarsest directions one
    step at a time until the total is exactly `target`; a refinement never takes a patch
    beyond `cap` elements. Deterministic."""
    lengths = [edge_lengths(p) for p in patches]

    def capped(nu, nv):
        # A patch over the cap keeps its shape but gets coarser elements.
        if cap is None or nu * nv <= cap:
            return nu, nv
        f = math.sqrt(cap / float(nu * nv))
        nu, nv = max(1, int(nu * f)), max(1, int(nv * f))
        while nu * nv > cap:
            nu, nv = (nu - 1, nv) if nu >= nv else (nu, nv - 1)
        return nu, nv

    def grid(h, lu, lv):
        return capped(min(MAX_SUBDIVISION, max(1, math.ceil(lu / h - 1e-9))),
                      min(MAX_SUBDIVISION, max(1, math.ceil(lv / h - 1e-9))))

    def counts(h):
        return [grid(h, lu, lv) for lu, lv in lengths]

    # The bisection only needs totals: each distinct patch shape once, times its number
    # (scene4 repeats the same rooms many times).
    shapes = {}
    for lu_lv in lengths:
        shapes[lu_lv] = shapes.get(lu_lv, 0) + 1

    def total_at(h):
        total = 0
        for (lu, lv), n in shapes.items():
            nu, nv = grid(h, lu, lv)
            total += n * nu * nv
        return total

    def total(cs):
        return sum(nu * nv for nu, nv in cs)

    lo, hi = 1e-4, 1e4  # total_at(lo) > target >= total_at(hi)
    if total_at(lo) <= target or total_at(hi) > target:
        raise SystemExit("fit_elements: target %d out of reach" % target)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if not lo < mid < hi:
            break  # lo and hi are neighbouring floats: nothing changes any more
        if total_at(mid) <= target:
            hi = mid
        else:
            lo = mid
    cs = [list(c) for c in counts(hi)]
    remaining = target - total(cs)
    # Greedy refinement: always split the longest element edge whose extra elements still fit.
    heap = []

    def push(i):
        nu, nv = cs[i]
        lu, lv = lengths[i]
        if nu < MAX_SUBDIVISION:
            heapq.heappush(heap, (-(lu / nu), i, 0, nu, nv))
        if nv < MAX_SUBDIVISION:
            heapq.heappush(heap, (-(lv / nv), i, 1, nu, nv))

    for i in range(len(patches)):
        push(i)
    while remaining > 0:
        if not heap:
            raise SystemExit("fit_elements: cannot reach exactly %d elements" % target)
        _, i, direction, nu, nv = heapq.heappop(heap)
        if [nu, nv] != cs[i]:
            continue  # stale entry
        delta = nv if direction == 0 else nu
        if delta > remaining or (cap is not None and nu * nv + delta > cap):
            continue  # only grows: never usable again
        cs[i][direction] += 1
        remaining -= delta
        push(i)
    for p, (nu, nv) in zip(patches, cs):
        p["nu"], p["nv"] = nu, nv


# ------------------------------------------------------------------------------------------
# Output.


def fmt(x):
    s = "%.4f" % x
    if s.startswith("-") and float(s) == 0.0:
        s = s[1:]
    s = s.rstrip("0")
    return s + "0" if s.endswith(".") else s


def fmt_vec(v):
    return "[" + ", ".join(fmt(c) for c in v) + "]"


def fmt_compact(x):
    s = fmt(x)
    return s[:-2] if s.endswith(".0") else s


def to_text(b, compact=False):
    """The scene file: one patch per line. `compact` (the large scene4) leaves out the spaces
    of a patch line and writes whole numbers without ".0"."""
    eye, look_at, fov = b.camera
    lines = ['{"name": %s,' % json.dumps(b.name),
             ' "camera": {"eye": %s, "look_at": %s, "up": [0.0, 1.0, 0.0], "fov_deg": %s},'
             % (fmt_vec(eye), fmt_vec(look_at), fmt(fov)),
             ' "patches": [']
    rows = []
    if compact:
        def vec(v):
            return "[" + ",".join(fmt_compact(c) for c in v) + "]"
        for p in b.patches:
            s = '{"vertices":[%s],"reflectance":%s' % (",".join(vec(v) for v in p["v"]),
                                                        vec(p["refl"]))
            if p["emis"] is not None:
                s += ',"emission":%s' % vec(p["emis"])
            s += ',"elements":[%d,%d]}' % (p["nu"], p["nv"])
            rows.append(s)
        lines.append(",\n".join(rows))
        lines.append(" ]}")
        return "\n".join(lines) + "\n"
    for p in b.patches:
        s = '  {"vertices": [%s], "reflectance": %s' % (
            ", ".join(fmt_vec(v) for v in p["v"]), fmt_vec(p["refl"]))
        if p["emis"] is not None:
            s += ', "emission": %s' % fmt_vec(p["emis"])
        s += ', "elements": [%d, %d]}' % (p["nu"], p["nv"])
        rows.append(s)
    lines.append(",\n".join(rows))
    lines.append(" ]}")
    return "\n".join(lines) + "\n"


# ------------------------------------------------------------------------------------------
# Validation of the written text.


def patch_cap(name):
    """Most elements a patch of the scene may have (None: no limit)."""
    if name not in PARTITION_WAYS:
        return None
    return TARGETS[name][1] // PARTITION_WAYS[name]


def partition_imbalance(counts, processors):
    """Largest / mean elements per processor when whole patches with these element counts are
    dealt out as the simulator does: largest first, each to the processor with the fewest
    elements so far (the first such)."""
    heap = [(0, r) for r in range(processors)]
    for c in sorted(counts, reverse=True):
        load, r = heapq.heappop(heap)
        heapq.heappush(heap, (load + c, r))
    return max(load for load, _ in heap) * processors / float(sum(counts))


def validate(b, text, target):
    """Returns a list of problems (empty when the scene is fine)."""
    problems = []
    try:
        data = json.loads(text)
    except ValueError as e:
        return ["not valid JSON: %s" % e]
    if set(data) - {"name", "camera", "patches"}:
        problems.append("unknown top-level keys")
    patches = data["patches"]
    if len(patches) != len(b.patches):
        return problems + ["patch count changed in output"]
    room_lo, room_hi = b.room
    elements = 0
    emitters = 0
    for index, (p, meta) in enumerate(zip(patches, b.patches)):
        where = "%s patch %d" % (b.name, index)
        if set(p) - {"vertices", "reflectance", "emission", "elements"}:
            problems.append(where + ": unknown keys")
        v = [tuple(float(c) for c in q) for q in p["vertices"]]
        if len(v) not in (3, 4):
            problems.append(where + ": %d vertices" % len(v))
            continue
        refl = p["reflectance"]
        emis = p.get("emission", [0.0, 0.0, 0.0])
        if not all(0.0 <= c < 1.0 for c in refl):
            problems.append(where + ": reflectance out of [0,1)")
        if not all(c >= 0.0 for c in emis):
            problems.append(where + ": negative emission")
        if sum(emis) > 0.0:
            emitters += 1
        nu, nv = p["elements"]
        if not (1 <= nu <= MAX_SUBDIVISION and 1 <= nv <= MAX_SUBDIVISION):
            problems.append(where + ": elements %d x %d out of range" % (nu, nv))
        elements += nu * nv
        # Size: no degenerate or sliver patches.
        edges = [vsub(v[(i + 1) % len(v)], v[i]) for i in range(len(v))]
        if min(vlen(e) for e in edges) < b.min_edge:
            problems.append(where + ": edge shorter than %g" % b.min_edge)
        n = vcross(vsub(v[1], v[0]), vsub(v[2], v[0]))
        if vlen(n) <= 0.0:
            problems.append(where + ": zero area")
            continue
        n = tuple(c / vlen(n) for c in n)
        diameter = max(vlen(vsub(a, c)) for a in v for c in v)
        # Planarity, with the loader's tolerance.
        for q in v[3:]:
            if abs(vdot(n, vsub(q, v[0]))) > 1e-6 * diameter:
                problems.append(where + ": not planar")
        # Convexity: every turn goes the same way as the normal.
        for i in range(len(v)):
            if vdot(vcross(edges[i], edges[(i + 1) % len(v)]), n) <= 0.0:
                problems.append(where + ": not convex (or collinear vertices)")
                break
        # Orientation.
        centre = vmean(v)
        kind, ref = meta["check"]
        if kind == "in":
            ok = vdot(n, vsub(ref, centre)) > 0.0
        elif kind == "out":
            ok = vdot(n, vsub(centre, ref)) > 0.0
        else:
            ok = vdot(n, ref) > 0.99
        if not ok:
            problems.append(where + ": faces the wrong way (%s)" % kind)
        # Inside the room.
        for q in v:
            if any(q[i] < room_lo[i] - 1e-9 or q[i] > room_hi[i] + 1e-9 for i in range(3)):
                problems.append(where + ": outside the room")
                break
    if emitters == 0:
        problems.append(b.name + ": no emitter")
    cap = patch_cap(b.name)
    if cap is not None:
        counts = [p["elements"][0] * p["elements"][1] for p in patches]
        for index, c in enumerate(counts):
            if c > cap:
                problems.append("%s patch %d: %d elements, more than 1/%d of the scene (%d)"
                                % (b.name, index, c, PARTITION_WAYS[b.name], cap))
        imbalance = partition_imbalance(counts, PARTITION_WAYS[b.name])
        if imbalance > MAX_IMBALANCE[b.name]:
            problems.append("%s: the %d-way partition by elements is off by %.3f"
                            % (b.name, PARTITION_WAYS[b.name], imbalance))
    if target is not None and (len(patches), elements) != target:
        problems.append("%s: %d patches / %d elements, want %d / %d"
                        % (b.name, len(patches), elements, target[0], target[1]))
    # Camera inside the room (the Cornell box camera is in front of its open side).
    cam = data["camera"]
    if b.name != "cornell-box":
        eye = cam["eye"]
        if not all(room_lo[i] < eye[i] < room_hi[i] for i in range(3)):
            problems.append(b.name + ": camera outside the room")
        for lo, hi, label in b.boxes:
            if all(lo[i] <= eye[i] <= hi[i] for i in range(3)):
                problems.append(b.name + ": camera inside " + label)
    problems += check_overlaps(b, patches)
    return problems


def check_overlaps(b, patches):
    """No two solid pieces interpenetrate, no flat decoration or light cuts a piece, and no
    two axis-aligned patches lie on top of each other (a hidden face that should have been
    omitted, or a duplicate)."""
    problems = []
    eps = 1e-9
    boxes = b.boxes
    order = sorted(range(len(boxes)), key=lambda i: boxes[i][0][0])
    for a_pos, i in enumerate(order):  # sweep along x
        lo_a, hi_a, label_a = boxes[i]
        for j in order[a_pos + 1:]:
            lo_b, hi_b, label_b = boxes[j]
            if lo_b[0] >= hi_a[0] - eps:
                break
            if all(min(hi_a[k], hi_b[k]) - max(lo_a[k], lo_b[k]) > eps for k in range(3)):
                problems.append("%s: %s %s overlaps %s %s" % (b.name, label_a, (lo_a, hi_a),
                                                              label_b, (lo_b, hi_b)))
    # Only boxes whose x extent meets the flat's can be cut by it: look them up in 1 m cells
    # along x (scene4 has thousands of both).
    cells = {}
    for index, (blo, bhi, _) in enumerate(boxes):
        for cell in range(math.floor(blo[0]), math.floor(bhi[0]) + 1):
            cells.setdefault(cell, []).append(index)
    for axis, c, lo, hi, label in b.flats:
        near = set()
        for cell in range(math.floor(lo[0] - 1.0), math.floor(hi[0] + 1.0) + 1):
            near.update(cells.get(cell, ()))
        for blo, bhi, blabel in (boxes[index] for index in sorted(near)):
            if not (blo[axis] + eps < c < bhi[axis] - eps):
                continue
            if all(min(hi[k], bhi[k]) - max(lo[k], blo[k]) > eps for k in range(3) if k != axis):
                problems.append("%s: %s cuts %s" % (b.name, label, blabel))
    # Coplanar overlapping axis-aligned patches.
    buckets = {}
    for index, p in enumerate(patches):
        v = p["vertices"]
        if len(v) != 4:
            continue
        for axis in range(3):
            if all(q[axis] == v[0][axis] for q in v):
                buckets.setdefault((axis, v[0][axis]), []).append(index)
    for (axis, c), members in sorted(buckets.items()):
        rects = []
        for index in members:
            v = patches[index]["vertices"]
            rects.append((index, [min(q[k] for q in v) for k in range(3)],
                          [max(q[k] for q in v) for k in range(3)]))
        rects.sort(key=lambda r: r[1][(axis + 1) % 3])
        u = (axis + 1) % 3
        w = (axis + 2) % 3
        for pos, (i, lo_a, hi_a) in enumerate(rects):
            for j, lo_b, hi_b in rects[pos + 1:]:
                if lo_b[u] >= hi_a[u] - eps:
                    break
                if min(hi_a[w], hi_b[w]) - max(lo_a[w], lo_b[w]) > eps:
                    problems.append("%s: patches %d and %d overlap in the plane %s = %s"
                                    % (b.name, i, j, "xyz"[axis], c))
    return problems


# ------------------------------------------------------------------------------------------


def build_all():
    scenes = []
    for make in (scene0, scene1, scene2, scene3, scene4):
        b = make()
        target = TARGETS[b.name]
        if len(b.patches) != target[0]:
            raise SystemExit("%s: %d patches, want %d" % (b.name, len(b.patches), target[0]))
        fit_elements(b.patches, target[1], patch_cap(b.name))
        scenes.append((b, target))
    scenes.append((cornell_box(), None))
    return scenes


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", default=os.path.dirname(os.path.abspath(__file__)),
                        help="output folder (default: the folder of this script)")
    args = parser.parse_args()
    outputs = []
    failed = False
    for b, target in build_all():
        text = to_text(b, compact=b.name in COMPACT)
        problems = validate(b, text, target)
        for problem in problems:
            print("error: " + problem, file=sys.stderr)
        failed = failed or bool(problems)
        outputs.append((b.name + ".json", text))
    if failed:
        return 1
    os.makedirs(args.out, exist_ok=True)
    for filename, text in outputs:
        with open(os.path.join(args.out, filename), "w", encoding="utf-8", newline="\n") as f:
            f.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
