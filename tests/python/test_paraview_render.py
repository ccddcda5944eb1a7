"""A run's ParaView series renders headless with real ParaView (pvbatch under xvfb-run): the
picture shows discs coloured by displacement, bonds, cracks and joints, not a blank page."""
import os
import subprocess

import matplotlib.image
import numpy as np
from conftest import REPO
from yade import O
from yade.wrapper import JointSetGeometry, SmoothJointMat
from lattice import R, material, pull_until_broken

from toppling.build import bonding, engines, joints
from toppling.build.discs import disc
from toppling.io import paraview

RENDER = os.path.join(REPO, "py", "pvbatch", "render_series.py")


def test_the_series_renders_to_a_picture_that_is_not_blank(empty_scene, tmp_path):
    rock = material(bondTensileStrength=1e4)
    for k in range(6):  # a row of bonded pairs, one joint between pairs 2 and 3, pair 0 pulled apart
        O.bodies.append([disc((4 * k * R, 0), R, rock, fixed=True), disc((4 * k * R, 2 * R), R, rock, fixed=k > 0)])
    O.engines = engines.engines(gravity=(0, 0, 0))
    bonding.bond_within_gap(1e-9)
    joint = JointSetGeometry(segmentStarts=[(7 * R, R)], segmentEnds=[(9 * R, R)])
    joints.install_joints([(joint, SmoothJointMat())], lo=(-R, -R), hi=(30 * R, 4 * R))
    series = paraview.ParaViewSeries(str(tmp_path / "paraview"))
    pull_until_broken(1)
    series.snapshot()
    png = tmp_path / "picture.png"
    paraview_python = dict(os.environ, PYTHONPATH=os.environ["TOPPLING_PARAVIEW_PYTHON"])  # scripts/env.sh
    # Two suites at once (a clone's CI beside a working tree's) both asked xvfb-run -a for display
    # 99 and one lost: start the search at a display of this process's own, and retry a window
    # that could not be made (Xvfb not ready on a loaded machine)
    command = ["xvfb-run", "-a", "-n", str(100 + os.getpid() % 30000), "pvbatch", RENDER, str(tmp_path / "paraview"),
               str(png)]
    for _ in range(3):
        proc = subprocess.run(command, capture_output=True, text=True, timeout=300, env=paraview_python)
        if proc.returncode == 0 or "CreateAWindow" not in proc.stderr:
            break
    assert proc.returncode == 0 and png.exists(), proc.stdout[-2000:] + proc.stderr[-2000:]
    pixels = matplotlib.image.imread(str(png))[..., :3]
    drawn = np.any(pixels < 0.95, axis=-1)  # anything but the white background
    assert drawn.mean() > 0.02  # twelve discs fill a visible share of the frame
    colourful = pixels.max(axis=-1) - pixels.min(axis=-1) > 0.2  # the colour map, the cracks, the joints
    assert colourful.sum() > 100
