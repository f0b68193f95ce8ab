"""The Cornell box (Cornell Program of Computer Graphics, "Cornell Box Data"; mm)."""

from .builder import Builder
from .vectors import vcross, vlen, vsub

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
