"""A bonded block on an incline across a smooth joint: stable, slide, topple (thesis §4.4).

Geometry (axis-aligned; the incline is made by rotating gravity by `alpha`, as the thesis
tilts its table): slab and block are packed as one non-convex polygon and cut by a joint
along y = 0 (thesis Fig 3-4), so the interface is as rough as the packing; discs below it
form the fixed slab, discs above it the b x h block, bonded with strong bonds; pairs across
the joint get a smooth joint of friction `phi`. Thesis Table 4-6 (h = 32 cm,
b = 11 cm, alpha = 26 deg, phi = 26.5 deg): b/h = 0.34 < tan(alpha) = 0.49 and
tan(alpha) < tan(phi): it topples.

Mode, from the block's own motion when it has clearly failed (|rotation| > 30 deg or
translation > b) or after `duration` seconds: translation = displacement along the incline
of the block's toe (its disc nearest the downhill base corner, the pivot of toppling);
rotation = mean rotation of its discs about z.
  slide if translation > 0.1 b, topple if |rotation| > 5 deg (both: slide+topple), else stable.
The failure is judged as it starts: once a block has toppled over, its toe skids too.
With `smooth=0` the pairs across the joint are only unbonded (plain disc contacts of
friction phi): coarse discs interlock (thesis Figs 4-11, 4-12).

    ./yade -x -n examples/verification/block_on_incline.py
"""
import math

from yade import O
from yade.utils import readParamsFromTable

from examples import params
from toppling.build import engines, jcfpm
from toppling.io import output
from toppling.io.params import check
from toppling.load import tilting
from toppling.models import incline

readParamsFromTable(**params.TABLE_4_6, rmax=0.008, smooth=1, duration=0.6, seed=1, model="ours",
                    out="results/block_on_incline", noTableOk=True)
from yade.params import table  # noqa: E402  (filled by readParamsFromTable)

check(table, b="(0, inf)", h="(0, inf)", alpha="[0, 90)", phi="[0, 90)", rmax="(0, inf)", duration="(0, inf)")

setup = incline.build(table.b, table.h, table.rmax / params.PACKING_R_RATIO, table.rmax, params.TABLE_5_6_ROCK, table.phi, smooth=bool(table.smooth),
                      seed=table.seed)
jcfpm.use(table.model)  # ours, or the same scene in JCFpm (examples/jcfpm)
tilting.set_tilt(table.alpha)
a, t_tilt = math.radians(table.alpha), O.time
history = incline.run_to_mode(setup, table.duration)

_, translation, rotation = history[-1]
mode = incline.mode(translation, rotation, table.b)
t_end = history[-1][0] - t_tilt
# Sliding from rest at constant acceleration: x = a t^2 / 2 (closed form g (sin a - tan phi cos a)).
acceleration = output.comparison(2 * translation / t_end**2,
                                 engines.G * (math.sin(a) - math.tan(math.radians(table.phi)) * math.cos(a)), "m/s2")
output.write_summary(table.out, output.table_inputs(table), mode=mode, translation=translation, rotation_deg=rotation,
                     acceleration=acceleration,
                     discs=len(setup.block) + len(setup.base), steps=O.iter,
                     closed_form={"b_over_h": table.b / table.h, "tan_alpha": math.tan(a),
                                  "tan_phi": math.tan(math.radians(table.phi))})
fig, ax = output.figure("time (s)", "translation / b, rotation / 5 deg", "Block on an incline")
ax.plot([t for t, _, _ in history], [x / table.b for _, x, _ in history], label="translation / b")
ax.plot([t for t, _, _ in history], [r / 5 for _, _, r in history], label="rotation / 5 deg")
ax.legend()
output.save_figure(fig, table.out, "motion")
print(f"mode {mode}: translation {translation * 1e3:.1f} mm, rotation {rotation:.1f} deg, {len(setup.block)} block discs; "
      f"mean acceleration {acceleration['measured']:.4f} m/s2 (sliding closed form {acceleration['reference']:.4f})")
