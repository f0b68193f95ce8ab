"""The scene generator behind scenes/generate.py (described in docs/scenes.md), one module
per concern:

    targets      the paper's patch and element counts, the partition every scene keeps to
    vectors      3-vectors as tuples, rounding of coordinates
    materials    reflectances and emissions
    builder      Builder (patches, pieces, lights, decorations) and Frame (furniture placement)
    furniture    tables, chairs, sofas, shelves ... as lists of boxes
    interiors    scene0 .. scene3 (section 5 of the paper) and scene4 (section 6)
    choices      the free choices the paper leaves open (defaults: the committed scenes)
    variant      a scene of the paper built with other choices, at the exact counts
    cornell_box  the published Cornell box
    elements     fit_elements: nu x nv per patch with an exact scene total
    text         the file's text (number format, one patch per line)
    validation   checks of the very text that is written
    cli          build, validate, write all or nothing

Python 3 standard library only; no randomness in the committed scenes (a random patch order
is a seeded choice of variant), so the output is the same bytes every run.
"""
