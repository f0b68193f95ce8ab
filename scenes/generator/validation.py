"""Validation of the written text: format, size, planarity, convexity, orientation, the
partition by elements, exact counts, camera and overlaps."""

import heapq
import json
import math

from .targets import MAX_IMBALANCE, MAX_SUBDIVISION, PARTITION_WAYS, patch_cap
from .vectors import vcross, vdot, vlen, vmean, vsub


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
