"""Strength reduction on a bonded block across a smooth joint on an incline α, against the
closed form FS = (c A + W cos α tan φ) / (W sin α) (c = 0: tan φ / tan α), with W the block's
weight and A the joint's area as the model has them (the joint contacts' areas summed).

The block settles on the level table on a frictional joint (its weight spreads it; a joint
cemented before would take that spreading in shear), the joint is cemented with cohesion c (no
tensile limit), the block settles at α (local damping), the scene is saved, then each trial divides the joint's
cohesion and tan φ by F and runs until the block rests (not before 0.1 s) or its median moves
more than b/10 (toppling.load.strength_reduction). The mode at the first failing factor:
slide if the toe moved further than the block's turn would carry it (b × turn), else topple. A block that topples at F = 1 (b/h < tan α)
is reported with its mode: no strength holds it, so there is no factor of safety.

    ./yade -x -n examples/verification/strength_reduction.py
"""
import math
import os

from yade import O
from yade.utils import readParamsFromTable
from yade.wrapper import SmoothJointPhys

from examples import params
from toppling.build import engines, joints
from toppling.io import output
from toppling.io.params import check
from toppling.load import strength_reduction, tilting
from toppling.models import incline

readParamsFromTable(alpha=20.0, phi=30.0, cohesion=0.0, b=0.2, h=0.1, rmax=0.012, joint_stiffness_scale=1.0,
                    tolerance=0.02, seed=1,
                    out="results/strength_reduction", noTableOk=True)
from yade.params import table  # noqa: E402  (filled by readParamsFromTable)

check(table, joint_stiffness_scale="(0, inf)", alpha="(0, 90)", phi="[0, 90)", cohesion="[0, inf)", b="(0, inf)", h="(0, inf)", rmax="(0, inf)",
      tolerance="(0, 1)")
setup = incline.build(table.b, table.h, table.rmax / params.PACKING_R_RATIO, table.rmax, params.TABLE_5_6_ROCK,
                      table.phi, seed=table.seed, joint_stiffness_scale=table.joint_stiffness_scale)
incline.settle(0.05)  # on the level table: the block spreads under its weight, slipping on the joint
joints.bond_contacts(tensile_strength=1e12, cohesion=table.cohesion)  # then the joint is cemented
tilting.set_tilt(table.alpha)
incline.settle(0.2)
checkpoint = os.path.join(output.prepare_out(table.out), "equilibrium.yade.bz2")
O.save(checkpoint)
x_start = O.bodies[setup.toe].state.pos[0]

a = math.radians(table.alpha)
weight = sum(O.bodies[i].state.mass for i in setup.block) * engines.G
contacts = [i.phys for i in O.interactions if isinstance(i.phys, SmoothJointPhys)]
area = sum(c.area for c in contacts)
stresses = [c.jointNormalForce / c.area for c in contacts]  # compression positive [Pa]: how even the joint is loaded
closed = (table.cohesion * area + weight * math.cos(a) * math.tan(math.radians(table.phi))) / (weight * math.sin(a))

criteria = tilting.StageCriteria(chunk=0.02, rest_speed=1e-3, fail_displacement=0.1 * table.b, max_stage_time=1.0)
search = strength_reduction.Search(checkpoint, [setup.block], criteria, tolerance=table.tolerance,
                                   on_trial=lambda t: print(f"F = {t.factor:.4f}: {'failed' if t.failed else 'stable'}, "
                                                            f"moved {t.displacement * 1e3:.2f} mm"))
if search.trial(1.0).failed:
    bracket, fs = None, None
else:
    bracket = search.run()
    fs = sum(bracket) / 2
# the mode at the first failing factor, which may only creep: its toe slid further than its turn would carry it
translation, turn = O.bodies[setup.toe].state.pos[0] - x_start, math.radians(incline.mean_spin_deg(setup.block))
mode = "slide" if translation > table.b * abs(turn) else "topple"
match = output.comparison(fs, closed, "-") if fs is not None else {}
output.write_summary(table.out, output.table_inputs(table), **match, factor_of_safety=fs, bracket=bracket,
                     closed_form=closed, joint_contacts=len(contacts), joint_normal_stress=(min(stresses), max(stresses)),
                     mode_at_failure=mode, weight=weight, joint_area=area,
                     trials=[vars(t) for t in search.trials], discs=len(setup.block) + len(setup.base), steps=O.iter)
print(f"factor of safety {'none' if fs is None else f'{fs:.4f}'} (bracket {bracket}), closed form {closed:.4f}; "
      f"at failure the block {mode}s ({translation * 1e3:.2f} mm, {math.degrees(turn):.2f} deg); at rest on "
      f"{len(contacts)} joint contacts, normal stress {min(stresses):.0f} to {max(stresses):.0f} Pa")
