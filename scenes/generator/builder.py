"""The scene builder (patches plus what the validation needs) and the furniture frame."""

from .choices import DEFAULT
from .materials import LAMP, LIGHT_EMISSION
from .vectors import clean, vmean


class Builder:
    """Collects patches plus what the validation needs to know about them.

    Each patch records how its orientation is checked: ("in", c) for room surfaces and wall
    decorations (the normal must point towards the room centre c), ("out", c) for furniture
    (away from the piece's centre c) and ("dir", d) for light panels (along d).
    """

    def __init__(self, name, min_edge, choices=DEFAULT):
        self.name = name
        self.choices = choices  # the free choices (scenes/generator/choices.py)
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
        if self.choices.turn_panels:  # the same counts, panels the other way round
            nx, nz, wx, wz = nz, nx, wz, wx
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
        fw, fh = self.choices.furniture_width, self.choices.furniture_height
        for lo, hi, refl, omit in pieces:
            # The piece's width and height scaled about its origin (x 1.0 is exact).
            lo = (lo[0] * fw, lo[1] * fh, lo[2])
            hi = (hi[0] * fw, hi[1] * fh, hi[2])
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
