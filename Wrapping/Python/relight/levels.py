"""One accuracy knob: ``relight.solve(scene, accuracy="fine")`` (in ParaView: the mesher's
Accuracy, which the solver follows).

Each level sets the settings that decide what a solve costs and how close it comes: the
element size (a multiple of the size given or suggested for the scene), the mesher's
LampGrading (finer elements by the lamps) and ShadowGrading (finer where a shadow's edge
crosses a patch), the final gather's GatherRays and GatherSweeps
and the clustered method's ClusterSeparation. "default" is the filters' own defaults (TestAccuracyLevels holds
them to it). What each level measured on the FZK-Haus and the rooms, error against time:
``./relight bench accuracy house`` and docs/benchmarks.md.
"""

from collections import namedtuple

from .vtkRadiosityFilters import vtkRadiosityMesher

Level = namedtuple("Level", "element_scale lamp_grading shadow_grading gather_rays cluster_separation gather_sweeps")

# The table is the C++ one (Base/AccuracyLevels.h), which the mesher's Accuracy uses too.
LEVELS = {vtkRadiosityMesher.GetAccuracyName(i): Level(vtkRadiosityMesher.GetAccuracyElementScale(i),
                                                       vtkRadiosityMesher.GetAccuracyLampGrading(i),
                                                       vtkRadiosityMesher.GetAccuracyShadowGrading(i),
                                                       vtkRadiosityMesher.GetAccuracyGatherRays(i),
                                                       vtkRadiosityMesher.GetAccuracyClusterSeparation(i),
                                                       vtkRadiosityMesher.GetAccuracyGatherSweeps(i))
          for i in range(5)}


def level(name):
    """The Level called `name` (a key of LEVELS); ValueError naming the levels otherwise."""
    try:
        return LEVELS[name]
    except (KeyError, TypeError):
        raise ValueError(f"accuracy {name!r} is not a level; choose one of {', '.join(LEVELS)}") from None
