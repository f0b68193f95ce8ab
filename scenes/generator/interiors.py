"""The four scenes of the paper (furnished interiors) and scene4, a floor of a school
building made of copies of them.

The order in which a scene adds its patches is the order of the scene file, and so decides
which patches each visibility processor holds (an even 1/V run of them, section 3): each room
adds its surfaces, then its lights, then its furniture and wall decorations. The paper gives
no order; the fitted plane-crossing cost and finding F4 rest on this one
(analysis/patch-order.md), so it is counted in analysis/model_choices.json. Changing the order
of the calls below changes the scenes and the calibration."""

from .builder import Builder, Frame
from .choices import DEFAULT
from .furniture import (bookshelf, cabinet, chair, desk_and_chair, panel_table, plant, sofa,
                        table, table_with_chairs, tv_on_stand, upholstered_chair)
from .materials import (BIRCH, BLACKBOARD, BLUE_FABRIC, BLUE_PLASTIC, CARPET, CEILING,
                        CONCRETE, DARK_WOOD, DOOR, GREEN_FABRIC, GREY_FABRIC, LINOLEUM,
                        OAK_FLOOR, OFF_WHITE, ORANGE_PLASTIC, PALE_BLUE, POSTERS, RED_FABRIC,
                        STAGE, STEEL, WARM_WALL, WHITE_PAINT, WINDOW, WOOD)
from .vectors import clean


def scene0(choices=DEFAULT):
    """A small living room: one table, a sofa, a sideboard, two ceiling lights."""
    b = Builder("scene0", min_edge=0.02, choices=choices)
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


def scene1(choices=DEFAULT):
    """A furnished living and dining room."""
    b = Builder("scene1", min_edge=0.02, choices=choices)
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


def scene2(choices=DEFAULT):
    """A classroom: fifteen desks with chairs, teacher's desk, blackboard, cabinets."""
    b = Builder("scene2", min_edge=0.02, choices=choices)
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


def scene3(choices=DEFAULT):
    """A large study hall: 48 desks with chairs, three group tables with six chairs each,
    a stage with a lectern, bookshelves, a lounge corner, four columns, 24 lights."""
    b = Builder("scene3", min_edge=0.02, choices=choices)
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
