"""Why a block on a JCFpm joint creeps below atan(mu): the lattice block of
tests/python/test_smooth_joint.py (8 bottom discs, 16 joint pairs) on a joint of friction `phi`,
handed to JCFpm and tilted to `phi - 2` and `phi - 1` degrees, then past `phi`: per tilt the
block's creep over 4000 steps, its mean acceleration against the closed form, and how many of
the 16 joint contacts are alive with their |Fs|/Fn (a contact JCFpm erased when it opened and
remade on touching starts at 0).

    ./yade -x -n -j1 calibration/jcfpm/joint_contacts.py [phi]
"""
import math
import sys

from yade import O

sys.path.insert(0, "tests/python")
from test_smooth_joint import acceleration, block_on_slab, mean_x, tilt  # noqa: E402  (the tests' scene)

from toppling.build import engines, jcfpm  # noqa: E402
from toppling.run.steps import run_steps  # noqa: E402

phi = float(sys.argv[1]) if len(sys.argv) > 1 else 30.0
for alpha in (phi - 2, phi - 1, phi + 4):
    O.reset()
    block, _ = block_on_slab(friction_deg=phi)
    pairs = [(i.id1, i.id2) for i in O.interactions if i.isReal and type(i.phys).__name__ == "SmoothJointPhys"]
    jcfpm.convert()
    tilt(alpha)
    x0 = mean_x(block)
    run_steps(4000)
    creep = mean_x(block) - x0
    alive = [O.interactions[p].phys for p in pairs if O.interactions.has(*p) and O.interactions[p].isReal]
    ratios = ", ".join(f"{p.shearForce.norm() / p.normalForce.norm():.2f}" for p in alive if p.normalForce.norm() > 0)
    a = math.radians(alpha)
    closed = engines.G * (math.sin(a) - math.tan(math.radians(phi)) * math.cos(a))
    print(f"tilt {alpha:.0f} deg (phi {phi:.0f}): crept {1e3 * creep:.3f} mm in 4000 steps, acceleration "
          f"{acceleration(block):.3f} m/s2 (closed form {max(closed, 0):.3f}); {len(alive)} of {len(pairs)} joint "
          f"contacts alive, |Fs|/Fn {ratios} (tan phi {math.tan(math.radians(phi)):.2f})")
