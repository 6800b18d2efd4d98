"""loci: a geometric constraint solver for CAD.

Three layers, each usable on its own:

* :class:`System` -- the SolveSpace model: parameters, entities and constraints in groups,
  ``solve(group, dragged=...)`` and ``check(group)``.
* :class:`Sketch` -- a 2D sketcher: shapes, user and soft constraints, dragging.
* :class:`Assembly` -- rigid components, mates and joints, solved at once or stepped.

``loci.slvs`` is a drop-in for SolveSpace's ``slvs`` Python module, and :func:`load` reads
loci JSON problems, sketch and assembly files and SolveSpace ``.slvs`` files.
"""

from ._loci import (
    Arc,
    Assembly,
    AssemblyResult,
    CheckResult,
    Circle,
    Cubic,
    DragResult,
    FileError,
    Line,
    LociError,
    ModelError,
    Point,
    Sketch,
    SketchConstraint,
    SketchResult,
    SolveError,
    SolveResult,
    System,
    __version__,
    load,
    loads,
)

__all__ = [
    "Arc",
    "Assembly",
    "AssemblyResult",
    "CheckResult",
    "Circle",
    "Cubic",
    "DragResult",
    "FileError",
    "Line",
    "LociError",
    "ModelError",
    "Point",
    "Sketch",
    "SketchConstraint",
    "SketchResult",
    "SolveError",
    "SolveResult",
    "System",
    "__version__",
    "load",
    "loads",
]
