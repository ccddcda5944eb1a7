"""Ihlara Valley (thesis §5.4.1): ignimbrite columns 3.5 m wide on Selime tuff, under Hasandagi
ash; the tuff under the front column and half the second weathered (case "weathered") or washed
out (case "eroded"), or neither (case "intact", the control). Built, bonded and settled at rest, jointed, then left to stand or topple.

    ./yade -x -n -j1 examples/field/ihlara.py                        # case 1, weathered
    ./yade-batch -j2 --job-threads 1 examples/field/cases.table examples/field/ihlara.py

The section is our reconstruction (examples/params.py, IHLARA_SECTION; docs/cases/ihlara.md).
"""
from yade.utils import readParamsFromTable

from examples import params
from toppling.io import output, tilt_report
from toppling.io.params import check
from toppling.load import tilting
from toppling.models import tilting_table
from toppling.models.layered_cliff import Layer, LayeredCliff, Zone
from toppling.models.tilting_table import JointMaterial
from toppling.run import tilt_run

readParamsFromTable(**params.IHLARA, out="results/ihlara/weathered", noTableOk=True)
from yade.params import table  # noqa: E402  (filled by readParamsFromTable)

if table.case not in ("intact", "weathered", "eroded"):
    raise ValueError(f"case = {table.case!r} is invalid: it must be 'intact', 'weathered' or 'eroded'")
check(table, weathered_strength_factor="(0, inf)", joint_gap="[0, inf)", joint_shear_stiffness="[0, inf)")
criteria = tilting.StageCriteria(table.chunk, table.rest_speed, table.fail_displacement, table.max_stage_time,
                                 table.fail_columns)
section, rocks, discs = params.IHLARA_SECTION, params.TABLE_5_12, params.TABLE_5_12_DISCS
weathered = dict(rocks["weathered"])
for key in ("bondTensileStrength", "bondCohesion"):
    weathered[key] /= table.weathered_strength_factor
zone_box = (section["face_x"] - 1.5 * section["column_width"], section["width"], -section["weathered_depth"], 0.0)
joint = params.TABLE_5_13
kn, ks = joint["vertical"][0], table.joint_shear_stiffness or joint["vertical"][1]  # the two sets share them
cliff = LayeredCliff(
    width=section["width"], foundation=Layer(section["tuff"], rocks["tuff"]),
    layers=[Layer(section["ignimbrite"], rocks["ignimbrite"]),
            Layer(section["ignimbrite"] + section["ash"], rocks["ash"])],
    face_x=section["face_x"], column_width=section["column_width"],
    vertical=JointMaterial(kn, joint["vertical"][2], ks), bedding=JointMaterial(kn, joint["bedding"][2], ks),
    zone=None if table.case == "intact" else Zone(zone_box, weathered if table.case == "weathered" else None),
    joint_gap=table.joint_gap,
    bond_gap=discs["bond_gap"], rmin=discs["rmin"], rmax=discs["rmax"], porosity=table.porosity, seed=table.seed,
    timestep_safety=table.timestep_safety, damping=table.damping)
protocol = tilt_run.TiltProtocol(start_tilt=0.0, step=1.0, max_tilt=0.0, tilt_rate=1.0, stage_rate=0.0,
                                 damping=table.damping, settle_damping=table.settle_damping, arrest_time=0.0,
                                 post_failure_time=table.post_failure_time, checkpoint_every=table.checkpoint_every,
                                 max_wall_time=table.max_wall_time, exact_resume=table.exact_resume)
run = tilting_table.start(cliff, protocol, criteria, output.table_inputs(table), table.out, table.resume)
run.run()
tilt_report.report(run, table.out, dict(failure_tilt_deg=0, phi_deg=[], s_over_h=None, t_over_h=None,
                                        stable_zone_columns=None), f"Ihlara, {table.case}")
