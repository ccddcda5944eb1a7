"""A bonded column on a fixed foot, tilted (gravity turned) until it breaks at its root, in our
parallel-bond model or in YADE's JCFpm (`model`), against beam theory.

The column b x h of Table 5-2's rock stands bonded on a fixed slab; each stage turns gravity by
`step` degrees and runs `stage_time` seconds with local damping 0.7 (quasi-static). It breaks at
the first stage in which its top moves more than b/5. Beam theory: the root's outer fibre
reaches the tensile strength σt when 3 γ h² sin α / b - γ h cos α = σt (γ = ρ g), with σt the
bond's: min(σ̄c, c̄ / tan φ̄), the strength a pulled bond has in both models (examples/jcfpm/bond.py).

    ./yade -x -n -j1 examples/jcfpm/column.py
"""
import math
import time

from yade import O
from yade.utils import readParamsFromTable
from yade.wrapper import ParallelBondMat

from examples import params
from toppling.build import boundary, engines, geometry, jcfpm, packing
from toppling.io import output
from toppling.io.params import check
from toppling.lem import flexural
from toppling.load import tilting
from toppling.models.tilting_table import bonded_rock
from toppling.run.steps import check_stable, run_steps, steps_in

readParamsFromTable(b=0.05, h=0.45, rmin=0.001, rmax=0.0025, seed=1, model="ours", step=1.0, stage_time=0.1,
                    out="results/jcfpm/column", noTableOk=True)
from yade.params import table  # noqa: E402  (filled by readParamsFromTable)

check(table, b="(0, inf)", h="(0, inf)", rmin="(0, inf)", rmax="(0, inf)", step="(0, 10]", stage_time="(0, inf)")
ROCK = {**params.TABLE_5_2_COMMON, **params.TABLE_5_2["ideal"]}
foot = 3 * table.rmax
section = [(-table.b, -foot), (2 * table.b, -foot), (2 * table.b, 0), (table.b, 0), (table.b, table.h), (0, table.h),
           (0, 0), (-table.b, 0)]
discs = packing.shrink_overlaps(packing.pack_polygon(geometry.region(section), table.rmin, table.rmax, 0.18,
                                                     seed=table.seed, keep=True).discs)
ids = bonded_rock(discs, ROCK, params.TABLE_5_2_BOND_GAP, [], table.rmax, 0.0, 0.5)
boundary.fix([i for i in ids if O.bodies[i].state.pos[1] < 0], "xy")
jcfpm.use(table.model)
engines.set_local_damping(0.7)
top = max((i for i in ids if abs(O.bodies[i].state.pos[0] - table.b / 2) < table.b / 4), key=lambda i: O.bodies[i].state.pos[1])

start, tilt, history = time.time(), 0.0, []
while tilt < 89:
    tilt = min(tilt + table.step, 89.0)
    tilting.set_tilt(tilt)
    x0 = O.bodies[top].state.pos[0]
    run_steps(steps_in(table.stage_time))
    check_stable()
    history.append((tilt, O.bodies[top].state.pos[0] - x0))
    if history[-1][1] > table.b / 5:
        break
wall = time.time() - start

strength = min(ROCK["bondTensileStrength"], ROCK["bondCohesion"] / math.tan(ROCK["bondFrictionAngle"]))
beam = flexural.breaking_tilt(ROCK["density"] * engines.G, table.b, table.h, strength)
output.write_summary(table.out, output.table_inputs(table), failure_tilt_deg=history[-1][0], beam_theory_deg=beam,
                     history=history, discs=len(ids), steps=O.iter, wall_time=wall)
print(f"{table.model}: breaks at {history[-1][0]:.1f} deg (beam theory {beam:.1f} deg), {len(ids)} discs, "
      f"{O.iter} steps, {wall:.0f} s")
