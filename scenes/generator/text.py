"""Output: the scene file's text, with a fixed number format and one patch per line."""

import json


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
