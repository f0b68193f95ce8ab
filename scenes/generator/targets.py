"""What each scene must be: the paper's patch and element counts, and the shape of the
partition of whole patches over the radiosity processors that the element fitting keeps to.

The counts are the paper's (section 5). The partition's shape is our choice, made by looking
at the paper (section 4's distribution of whole patches, Tables 1 and 4 up to R = 64), and is
counted as such in analysis/model_choices.json."""

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


def patch_cap(name):
    """Most elements a patch of the scene may have (None: no limit)."""
    if name not in PARTITION_WAYS:
        return None
    return TARGETS[name][1] // PARTITION_WAYS[name]
