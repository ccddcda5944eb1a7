"""One bond pulled and one sheared, in our parallel-bond model and in YADE's JCFpm, against the
closed form: the peak force (pulled min(σ̄c, c̄/tan φ̄) A, sheared c̄ A at zero normal force) and
the stiffness.

Two discs of Table 5-2's rock (the tilting table's), bonded, one fixed; the other is moved at a
constant velocity that brings the bond to its strength in about 2000 steps. The same pair is
built once per model (toppling.build.jcfpm hands it to JCFpm with our stiffness and strengths).

    ./yade -x -n -j1 examples/jcfpm/bond.py
"""
import math

from yade import O
from yade.utils import readParamsFromTable
from yade.wrapper import ParallelBondMat

from examples import params
from toppling.build import bonding, engines, jcfpm
from toppling.build.discs import disc
from toppling.io import output
from toppling.io.params import check
from toppling.run.steps import run_steps

readParamsFromTable(radius=0.002, steps_to_break=2000, out="results/jcfpm/bond", noTableOk=True)
from yade.params import table  # noqa: E402  (filled by readParamsFromTable)

check(table, radius="(0, inf)", steps_to_break="whole [10, inf)")
ROCK = {**params.TABLE_5_2_COMMON, **params.TABLE_5_2["ideal"], "normalDamping": 0.0, "bondNormalDamping": 0.0}  # JCFpm has no dashpots


def loaded_pair(model: str, load: str):
    """The bonded pair in a fresh scene of ``model``, the free disc moving; returns its state,
    the interaction and the closed-form peak force (pulled: Mohr-Coulomb's line meets σ̄ = 0 at
    c̄/tan φ̄ before the tension cut-off σ̄c here, PFC's criterion and JCFpm's)."""
    O.reset()
    mat = ParallelBondMat(**ROCK)
    a = O.bodies.append(disc((0, 0), table.radius, mat, fixed=True))
    b = O.bodies.append(disc((2 * table.radius, 0), table.radius, mat))
    O.engines = engines.engines(gravity=(0, 0, 0), timestepper=False)
    bonding.bond_within_gap(1e-9 * table.radius)
    phys = O.interactions[a, b].phys
    pulled = min(mat.bondTensileStrength, mat.bondCohesion / math.tan(mat.bondFrictionAngle))
    strength = (pulled if load == "pull" else mat.bondCohesion) * phys.bondArea
    slowest = (phys.bondKn if load == "pull" else phys.bondKs) * phys.bondArea  # the bond alone
    O.dt = 0.1 * math.sqrt(O.bodies[b].state.mass / phys.kn)
    jcfpm.use(model)
    moving = O.bodies[b].state
    moving.blockedDOFs = "xyzXYZ"
    speed = strength / slowest / (table.steps_to_break * O.dt)
    moving.vel = (speed, 0, 0) if load == "pull" else (0, speed, 0)
    return moving, O.interactions[a, b], strength


def peak(model: str, load: str) -> dict:
    """Peak force and stiffness of the pair until its bond breaks (a step's force is from the
    positions before its move)."""
    moving, interaction, strength = loaded_pair(model, load)
    axis = 0 if load == "pull" else 1
    start, history = moving.pos[axis], []
    while interaction.isReal and bonding.is_bond(interaction.phys) and O.iter < 20 * table.steps_to_break:
        before = abs(moving.pos[axis] - start)
        run_steps(1)
        history.append((before, abs(O.forces.f(interaction.id2)[axis])))
    if O.iter >= 20 * table.steps_to_break:
        raise RuntimeError(f"{model}, {load}: the bond did not break")
    moved, force = history[len(history) // 2]
    return {"peak_force": max(f for _, f in history), "closed_form": strength, "stiffness": force / moved}


rows = {load: {model: peak(model, load) for model in ("ours", "jcfpm")} for load in ("pull", "shear")}
output.write_summary(table.out, output.table_inputs(table), **rows)
print("| load | closed form (N) | ours (N) | JCFpm (N) | stiffness ours (N/m) | JCFpm (N/m) |")
print("|---|---|---|---|---|---|")
for load, r in rows.items():
    print(f"| {load} | {r['ours']['closed_form']:.5g} | {r['ours']['peak_force']:.5g} | {r['jcfpm']['peak_force']:.5g} | "
          f"{r['ours']['stiffness']:.4g} | {r['jcfpm']['stiffness']:.4g} |")
