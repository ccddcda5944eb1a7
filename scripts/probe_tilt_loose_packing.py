"""Probe of the open tilt-test problem: a loose packing (porosity 0.22), mu = 0.4, Rmax 16 mm.

Prints the tilt at which the block slides, atan(mu), and the largest rotation of a single
block disc. See README (smooth joints, open problem).

    ./yade -x -n scripts/probe_tilt_loose_packing.py
"""
import math
from yade import O
from toppling import incline
ROCK = dict(young=15e6, knKs=1.4, density=2340.0, bondYoung=15.9e6, bondKnKs=1.8, normalDamping=0.13, bondNormalDamping=0.2)
phi = math.degrees(math.atan(0.4)); B=0.2
setup = incline.build(B, 0.05, 0.016/2.5, 0.016, ROCK, phi, porosity=0.22, seed=1)
incline.tilt(phi-4); incline.settle(0.2)
alpha, hist = phi-4+0.25, []
while alpha < phi+4:
    incline.tilt(alpha); x0 = O.bodies[setup.toe].state.pos[0]
    O.run(max(1,int(0.05/O.dt)), True); hist.append((alpha, incline.toe_translation(setup, x0)))
    if len(hist)>1 and min(m for _,m in hist[-2:]) > 1e-4*B: break
    alpha += 0.25
print("SLIDE", hist[-2][0], "phi", phi, "maxrot", max(abs(incline.rotation_deg([i])) for i in setup.block))
