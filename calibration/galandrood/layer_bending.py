"""How stiff one of Galandrood's 0.3 m layers is in our discs (docs/cases/galandrood.md): a layer
``length`` m long, its discs those whose centres lie in a 0.3 m band of a packing four times as
high (as a joint pair cuts them out of the slope's), bonded as the slope's rock (Table 5-14, R
3.75-6 cm), held at one end, sagging under its own weight with local damping 0.7 until its tip rests.
Its tip's sag against a continuous beam of the bonds' modulus, q L^4 / (8 E I), gives the layer's
bending stiffness EI as a share of E t^3 / 12.

    ./yade -x -n -j1 calibration/galandrood/layer_bending.py [length=8] [seed=1]
"""
import statistics
import sys

from yade import O

from examples import params
from toppling.build import engines
from toppling.models import tilting_table
from toppling.run.steps import run_steps, steps_in

args = dict(a.split("=") for a in sys.argv[1:])
length, seed = float(args.get("length", 8.0)), int(args.get("seed", 1))
rock, discs_ = params.TABLE_5_14, params.TABLE_5_14_DISCS
t = params.FIG_5_44["thickness"]
rmin, rmax = discs_["rmin"], discs_["rmax"]

# The slope's layers are cut by joints out of one packing: so is this one, from a band 4 t high.
section = [(0.0, 0.0), (length, 0.0), (length, 4 * t), (0.0, 4 * t)]
packed = tilting_table.packed_discs(section, rmin, rmax, params.GALANDROOD["porosity"], seed, False)
discs = [(x, y - 1.5 * t, r) for x, y, r in packed if 1.5 * t <= y < 2.5 * t]
ids = tilting_table.bonded_rock(discs, rock, discs_["bond_gap"], [((0.0, 0.0), (0.0, t))], rmax, 0.7,
                                params.GALANDROOD["timestep_safety"])
tip = [i for i in ids if O.bodies[i].state.pos[0] > length - t]
span = length - rmax  # from the held discs' centres to the end
q = rock["density"] * engines.G * t * rock["thickness"]  # weight per metre of layer [N/m]
stiffness = rock["young"] * rock["thickness"] * t**3 / 12
beam = q * span**4 / (8 * stiffness)


def sag() -> float:
    return -statistics.median(O.bodies[i].state.displ()[1] for i in tip)


before = 0.0
for _ in range(200):
    run_steps(steps_in(0.1))
    now = sag()
    if abs(now - before) < 1e-3 * max(abs(now), 1e-6):
        break
    before = now
print(f"layer {length:g} x {t:g} m, seed {seed}: {len(ids)} discs, tip sag {1e3 * now:.1f} mm at t = {O.time:.1f} s; "
      f"beam of E {rock['young'] / 1e9:g} GPa: {1e3 * beam:.1f} mm; EI / (E t^3/12) = {beam / now:.3f}", flush=True)
