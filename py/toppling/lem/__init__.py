"""Limit equilibrium for toppling slopes, in plain Python (no YADE needed).

* :mod:`toppling.lem.goodman_bray`: block toppling on a stepped base (Goodman and Bray 1976, as in
  Hoek and Bray 1981 and Wyllie and Mah 2004): modes, forces, toe force, limiting friction,
  factor of safety, toe support for a required factor.
* :mod:`toppling.lem.flexural`: flexural toppling (Aydan and Kawamoto 1992, thesis eq. 2-4).
* :mod:`toppling.lem.geometry`: a slope and the columns each method cuts it into; a
  ``toppling.models`` slope's shape as LEM input.

Block-flexure toppling (Amini et al. 2012, the thesis' BFTOP) is not here: its equations are
not in the thesis and could not be found in the references available to us.

Command line: ``python3 -m toppling.lem {goodman-bray,flexural} INPUT.json``.
"""
from toppling.lem.flexural import Rock
from toppling.lem.geometry import SlopeGeometry
from toppling.lem.goodman_bray import Blocks, analyse, factor_of_safety, limiting_friction

__all__ = ["Blocks", "Rock", "SlopeGeometry", "analyse", "factor_of_safety", "limiting_friction"]
