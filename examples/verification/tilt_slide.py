"""Tilt test: a flat bonded block on a smooth joint starts to slide at atan(mu_j).

The table (base + block b x h, one packing cut by a joint, see toppling.models.incline) is tilted
to `phi - 4` degrees and settled with damping, then tilted in steps of `step` degrees, each
stage lasting `stage_time` seconds, undamped. The block
slides at the first of two successive stages in which its toe moves more than 1e-4 b: elastic
creep of the joint under one tilt step is ~1e-6 b, sliding at 0.25 deg above atan(mu) already
moves ~3e-4 b, and a single local slip event (seen once, 1.25 deg early) does not continue. `phi` is atan(mu_j) in degrees; the block is flat (b/h = 4) so it cannot
topple before it slides.

    ./yade -x -n examples/verification/tilt_slide.py
    ./yade-batch examples/verification/tilt_slide.table examples/verification/tilt_slide.py
"""
import math

from yade import O
from yade.utils import readParamsFromTable

from examples import params
from toppling.build import jcfpm
from toppling.io import output
from toppling.io.params import check
from toppling.load import tilting
from toppling.models import incline
from toppling.run.steps import run_steps, steps_in

readParamsFromTable(phi=math.degrees(math.atan(0.4)), rmax=0.012, porosity=0.2, step=0.25, stage_time=0.05, seed=1, model="ours",
                    out="results/tilt_slide", noTableOk=True)
from yade.params import table  # noqa: E402  (filled by readParamsFromTable)

check(table, phi="[4, 86)", rmax="(0, inf)", porosity="(0, 1)", step="(0, 4]", stage_time="(0, inf)")

B, H = 0.2, 0.05
setup = incline.build(B, H, table.rmax / params.PACKING_R_RATIO, table.rmax, params.TABLE_5_6_ROCK, table.phi, porosity=table.porosity, seed=table.seed)
jcfpm.use(table.model)  # ours, or the same scene in JCFpm (examples/jcfpm)

tilting.set_tilt(table.phi - 4)  # first tilt well below atan(mu), then settle there (damped)
incline.settle(4 * table.stage_time)
alpha, slide_tilt, history = table.phi - 4 + table.step, None, []
while alpha < table.phi + 4 and slide_tilt is None:
    tilting.set_tilt(alpha)
    x0 = O.bodies[setup.toe].state.pos[0]
    run_steps(steps_in(table.stage_time))
    history.append((alpha, incline.toe_translation(setup, x0)))
    if len(history) > 1 and min(m for _, m in history[-2:]) > 1e-4 * B:  # sustained, not a slip event
        slide_tilt = history[-2][0]
    alpha += table.step
if slide_tilt is None:
    raise RuntimeError(f"the block did not slide up to {alpha:.2f} deg")

result = output.comparison(slide_tilt, table.phi, "deg")
output.write_summary(table.out, output.table_inputs(table), **result, slide_tilt_deg=slide_tilt, history=history,
                     abs_error_deg=slide_tilt - table.phi, discs=len(setup.block) + len(setup.base))
fig, ax = output.figure("tilt (deg)", "toe movement per stage / b", f"Tilt test, atan(mu) = {table.phi:.1f} deg")
ax.semilogy([a for a, _ in history], [max(abs(m) / B, 1e-9) for _, m in history], "o-")
ax.axvline(table.phi, color="k", ls="--")
output.save_figure(fig, table.out, "tilt")
print(f"slides at {slide_tilt:.2f} deg (atan mu = {table.phi:.2f} deg, {len(setup.block)} block discs)")
