"""toppling: block-flexural toppling of jointed rock slopes with YADE.

Scene building (:mod:`toppling.scene`, :mod:`toppling.bonding`), monitoring
(:mod:`toppling.monitor`) and output (:mod:`toppling.output`). The C++ classes
(``ParallelBondMat``, ``Law2_ScGeom_ParallelBondPhys_ParallelBond``, ...) are ordinary
YADE classes, imported with ``from yade import *``.
"""
