"""One accuracy knob: ``relight.solve(scene, accuracy="fine")``.

Each level sets the four settings that decide what a solve costs and how close it comes:
the element size (a multiple of the size given or suggested for the scene), the mesher's
LampGrading (finer elements by the lamps), the final gather's GatherRays and the clustered
method's ClusterSeparation. "default" is the filters' own defaults (TestAccuracyLevels holds
them to it). What each level measured on the FZK-Haus and the rooms, error against time:
``./relight bench accuracy house`` and docs/benchmarks.md.
"""

from collections import namedtuple

Level = namedtuple("Level", "element_scale lamp_grading gather_rays cluster_separation")

LEVELS = {
    "preview": Level(2.0, 0.0, 16, 2.0),     # elements twice as large, a light gather
    "draft": Level(1.0, 0.3, 64, 2.0),
    "default": Level(1.0, 0.2, 256, 3.0),    # the filters' defaults
    "fine": Level(0.5, 0.2, 256, 3.0),       # elements half as large
    "reference": Level(0.5, 0.15, 1024, 4.0),
}


def level(name):
    """The Level called `name` (a key of LEVELS); ValueError naming the levels otherwise."""
    try:
        return LEVELS[name]
    except (KeyError, TypeError):
        raise ValueError(f"accuracy {name!r} is not a level; choose one of {', '.join(LEVELS)}") from None
