"""What each Ihlara column stands on: the bedding's joint pairs under it once the cliff is built,
bonded and jointed (no step run), and how far the frontmost and backmost lie from its sides.

    ./yade -x -n -j1 calibration/ihlara/bedding_pairs.py [seed]
"""
import sys
from types import SimpleNamespace

from yade import O

from examples import params
from toppling.models import layered_cliff

seed = int(sys.argv[1]) if len(sys.argv) > 1 else 1
cliff = layered_cliff.ihlara_from_params(SimpleNamespace(**{**params.IHLARA, "case": "intact", "seed": seed}), params)
cliff.build()
cliff.settled()
spans = [cliff.layout.span(k) for k in range(1, cliff.layout.count + 1)]
under: list[list[float]] = [[] for _ in spans]
for i in O.interactions:
    if i.isReal and getattr(i.phys, "jointSet", -1) == 1:  # set 1: the bedding
        x = 0.5 * (O.bodies[i.id1].state.pos[0] + O.bodies[i.id2].state.pos[0])
        for pairs, (lo, hi) in zip(under, spans):
            if lo <= x <= hi:
                pairs.append(x)
for k, (pairs, (lo, hi)) in enumerate(zip(under, spans), start=1):
    xs = sorted(pairs)
    gaps = [b - a for a, b in zip(xs, xs[1:])]
    where = (f", the frontmost {hi - xs[-1]:.2f} m behind its face, the backmost {xs[0] - lo:.2f} m in front of its "
             f"back, widest gap between {max(gaps, default=0):.2f} m") if xs else ""
    print(f"seed {seed}, column {k}: {len(xs)} pairs{where}")
