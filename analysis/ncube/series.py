"""How a sweep's cells group into series and how a series is named, for the answer
(ncube.summary) and the plots (ncube.plotting) alike: plain Python, so that the printed answer
needs no plotting library.

A series is the cells equal in every key but R and V; it is named by the scene's label (unique
per file: ncube.summary.scene_labels) and the keys that vary between the series."""
import json

from . import options as opts

# What makes a cell's configuration, beside R: a line joins only cells equal in all of these.
# The scene is its file (two files may share a scene name); its label names it in the legend
# and comes first, so that series sort by what the legend shows.
CONFIGURATION = (["scene_label", "V"] + [name for name in opts.OPTIONS if name not in ("R", "V")] +
                 ["platform", "cost_model", "cfg", "scene_file"])
OTHER_KEYS = CONFIGURATION[2:-1]   # named in the legend when they vary between the series
# The keys of a series when the node count is fixed: all but R and V (the configuration).
# (The scene's label is unique per file, so it stands for the file.)
SERIES = ["scene_label"] + OTHER_KEYS
# How a key is named in a table's header or a sentence.
KEY_NAMES = {"scene_label": "scene"}


def hashable(value):
    return json.dumps(value, sort_keys=True) if isinstance(value, (dict, list)) else value


def shown(key, value):
    """A key's value as a label shows it: a platform or cost model by its file's stem."""
    if key in ("platform", "cost_model") and isinstance(value, str):
        for suffix in (".json", ".xml"):
            value = value.removesuffix(suffix)
    return value


def varied(table, keys):
    """The keys of `keys` whose value differs between the cells of `table`."""
    return [k for k in keys if len({hashable(row.get(k)) for row in table}) > 1]


def series_label(row, keys):
    """A series named by the scene's label and `keys` (those that vary): "scene2, platform=cm5"."""
    parts = [str(row["scene_label"])] if "scene_label" in keys or not keys else []
    parts += [f"{k}={shown(k, row.get(k))}" for k in keys if k not in ("scene_label", "scene_file")]
    return ", ".join(parts) or str(row["scene_label"])
