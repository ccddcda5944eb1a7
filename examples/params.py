"""Every thesis number the examples use, once, with its unit. The thesis: Amini, *Numerical
Simulation of Toppling Failure for Jointed Rock Masses* (HDPAC); tables as numbered there.

Rock dictionaries hold ParallelBondMat's keyword arguments (SI units: Pa, kg/m3, m, rad).
"""
import math

# ---- Chapter 4: verification ----
TABLE_4_1 = dict(radius=50.0, density=1000.0, kn=1.35e9, kn_boundary=1.35e11, drop=1.0, g=9.81,
                 dt=3e-4)  # m, kg/m3, N/m, N/m, m, m/s2, s
TABLE_4_1_IMPACT_VELOCITY = 4.4307  # [m/s] HDPAC
INCH = 0.0254  # [m]
TABLE_4_2 = dict(length=200 * INCH, thickness=1 * INCH, depth=16 * INCH, young=68.95e9, shear_modulus=26e9,
                 density=2700.0)  # cantilever [m, Pa, kg/m3]
TABLE_4_3 = dict(force=4448.0, moment=11300.0, hdpac_tip_mm=34.715)  # [N, N m, mm]
TABLE_4_4 = dict(density=2630.0, young=69.9e9, knKs=1.5, frictionAngle=math.atan(0.5), bondRadiusMultiplier=1.0,
                 bondYoung=69.9e9, bondKnKs=1.5, bondTensileStrength=145e6, bondCohesion=155e6, thickness=1.0)
LAC_DU_BONNET_SPECIMEN = (0.062, 0.155)  # width, height [m] (the laboratory sample, §4.3)
LAC_DU_BONNET_DISCS = dict(d_avg=0.745e-3, d_ratio=1.66)  # mean diameter [m], Dmax/Dmin (Table 4-4)
TABLE_4_5 = {"thesis_hdpac": dict(young_modulus=62e9, poisson_ratio=0.231, ucs=187.5e6),  # [Pa, -, Pa]
             "pfc2d": dict(young_modulus=70.9e9, poisson_ratio=0.237, ucs=199.1e6)}
TABLE_4_6 = dict(b=0.11, h=0.32, alpha=26.0, phi=26.5)  # block on an incline [m, m, deg, deg]
# the blocks of §4.4: Table 5-6's stiffnesses and damping (bonds unbreakable)
TABLE_5_6_ROCK = dict(young=15e6, knKs=1.4, density=2340.0, bondYoung=15.9e6, bondKnKs=1.8, normalDamping=0.13,
                      bondNormalDamping=0.2)
PACKING_R_RATIO = 2.5  # Rmax / Rmin of §5.2.3 (R 1-2.5 mm)

# ---- Chapter 5: the block material (Table 5-1) ----
TABLE_5_1 = {  # tests 1-3
    1: dict(young=12.05e6, knKs=1.3, bondYoung=12e6, bondKnKs=1.8, bondTensileStrength=19.7e3, bondCohesion=25e3,
            bondFrictionAngle=math.radians(10)),
    2: dict(young=7.05e6, knKs=1.8, bondYoung=7.0e6, bondKnKs=1.8, bondTensileStrength=13.5e3, bondCohesion=29e3,
            bondFrictionAngle=math.radians(15)),
    3: dict(young=13.05e6, knKs=1.3, bondYoung=13e6, bondKnKs=1.8, bondTensileStrength=19.7e3, bondCohesion=25e3,
            bondFrictionAngle=math.radians(15)),
}
TABLE_5_1_COMMON = dict(density=2880.0, frictionAngle=math.atan(0.45), bondNormalDamping=0.2, normalDamping=0.13)
UCS_SPECIMEN = (0.047, 0.10)  # width, height [m]
UCS_TEST = dict(rmin=1e-3, rmax=2.5e-3, velocity=0.01)  # disc radii [m], platen speed [m/s] (§5.2.3)
LAB_UCS = 56.7e3  # [Pa] mean of the laboratory tests
BLOCK_TENSILE_STRENGTH = 31.37e3  # [Pa] §5.2.1

# ---- Tilting table (§5.2; Tables 5-2, 5-3) ----
TILTING_TABLE_OUTLINE = dict(width=0.05, columns=15, face_deg=47.0, top_deg=27.0, crest=0.350)  # m, -, deg, deg, m
BLOCK_LENGTH = 0.10  # [m]
BLOCK_THICKNESS = 0.047  # [m] the disc thickness t
DESIGN_PLANE_DEG = 15.0  # the ideal arrangement's base joints lie on this plane (reconstruction)
TABLE_5_2 = {  # what differs between the two models
    "ideal": dict(young=15.05e6, knKs=1.3, bondTensileStrength=209e3),
    "random": dict(young=15.9e6, knKs=1.8, bondTensileStrength=159e3),
}
TABLE_5_2_COMMON = dict(density=2900.0, frictionAngle=math.atan(0.45), bondYoung=15.9e6, bondKnKs=1.8,
                        bondCohesion=50e3, bondFrictionAngle=math.radians(15), bondNormalDamping=0.2,
                        normalDamping=0.13, thickness=BLOCK_THICKNESS)
TABLE_5_2_BOND_GAP = 1.05e-3  # [m]
TABLE_5_2_POROSITY = 0.12  # ours is 0.18: the packer does not lock in overlap (docs/model.md)
TABLE_5_3 = {  # main joints, base joints: (kn = ks [N/m3], mu); gap [m]
    "ideal": dict(main=(12e11, 0.17), base=(12e10, 0.23), gap=1e-4),
    "random": dict(main=(12e11, 0.15), base=(12e10, 0.20), gap=1e-4),
}
TILTING_TABLE_RESULTS = {"ideal": dict(failure_tilt_deg=35, phi_deg=[15]),  # §5.2.4
                         "random": dict(failure_tilt_deg=19, phi_deg=[14, 24])}
# Calibration within the thesis' ranges: bond tensile strength 13.5-209 kPa (Tables 5-1, 5-2),
# joint friction 0.15-0.23 (Table 5-3); the calibrated values (docs/cases/tilting_table.md).
CALIBRATION_RANGES = {"bond_tensile_strength": (13.5e3, 209e3), "main_joint_friction": (0.15, 0.23),
                      "base_joint_friction": (0.15, 0.23)}
CALIBRATED_BOND_TENSILE_STRENGTH = {"ideal": 95e3, "random": 65e3}  # [Pa]
# The calibration's rule: a mean failure tilt within 3 deg of the thesis', and the finer packing's
# within 2 deg of the coarser one's, each by two standard errors.
TARGET_TOLERANCE_DEG = 3.0
SIZE_TOLERANCE_DEG = 2.0
# The calibrated ideal case at R 1-4 mm: the defaults of examples/tilting_table/run.py (its
# parameters: toppling.models.tilting_table.from_params, toppling.run.tilt_run.TiltProtocol,
# toppling.load.tilting.StageCriteria). 0 for a thesis value: the table's.
TILTING_TABLE_IDEAL = dict(
    arrangement="ideal", rmin=1e-3, rmax=4e-3, porosity=0.18, seed=1, layout_seed=1,  # m, m, -
    bond_tensile_strength=CALIBRATED_BOND_TENSILE_STRENGTH["ideal"], main_joint_friction=0.0,
    base_joint_friction=0.0, joint_stiffness_scale=0.01, bond_gap=0.0, cut_rules=1, joint_pieces=1, z_order=0,
    face_closure=0,  # 1: joint contacts made after installation start with their faces' closure (JointSystem.faceClosure)
    disc_path=1,  # 1: DiscInteractionLoop, DiscNewtonIntegrator; 0: YADE's generic engines (the same results)
    model="ours",  # 'jcfpm': the same scene in YADE's JCFpm (docs/jcfpm.md)
    timestep_safety=0.8, damping=0.0, settle_damping=0.7,  # local damping while tilting, on the level table
    start_tilt=26.0, step=2.0, max_tilt=45.0, tilt_rate=50.0, stage_rate=10.0,  # deg, deg, deg, deg/s, deg/s
    chunk=0.02, rest_speed=1e-3, fail_displacement=0.05, max_stage_time=2.0, fail_columns=2,  # s, m/s, m, s, -
    arrest_time=0.0, post_failure_time=0.3, resume=-1, checkpoint_every=600.0,  # s, s, -, wall s
    max_wall_time=0.0, exact_resume=0)  # wall s (0: no limit), 1: resumed runs bit for bit (slower)

# ---- Equivalent slope (§5.3; Tables 5-5, 5-6) ----
EQUIVALENT_SLOPE_SHAPE = dict(height=0.475, joint_dip_deg=55.0, face_deg=98.0, top_deg=8.0, spacing=0.047)  # m, deg x3, m
TABLE_5_5 = dict(density=3000.0, young=15.05e6, knKs=1.4, frictionAngle=math.atan(0.45), bondYoung=15.9e6,
                 bondKnKs=1.8, bondTensileStrength=125e3, bondCohesion=30.9e3, bondFrictionAngle=math.radians(10),
                 bondNormalDamping=0.2, normalDamping=0.13, thickness=BLOCK_THICKNESS)
TABLE_5_5_BOND_GAP = 1.05e-3  # [m]
TABLE_5_6 = dict(main=(12e11, 0.12), base=(12e10, 0.23), gap=0.5e-3)  # (kn = ks [N/m3], mu); gap [m]
EQUIVALENT_SLOPE_RESULTS = dict(failure_tilt_deg=35, phi_deg=[15], s_over_h=0.79, t_over_h=0.20,
                                stable_zone_columns=(9, 13),  # §5.3.2, Fig 5-19
                                monitoring_points=["C-3", "D-4", "G-7", "H-8", "I-9", "M-13", "N-14", "O-15"])  # Fig 5-20
# The base model (examples/equivalent_slope/run.py's defaults): Table 5-5's discs at the packer's
# porosity; joints x0.01 stiff as in the tilting table (the time step); base joints on the tilting
# table's design plane; calibrated (docs/cases/equivalent_slope.md): Table 5-5's bond strengths x 1.62
# (cohesion 50 kPa, the tilting table's), main joints' friction 0.20 (Table 5-6: 0.12).
EQUIVALENT_SLOPE = dict(
    rmin=1.5e-3, rmax=3.5e-3, porosity=0.18, seed=1, spacing=0.0, strength_factor=1.62,  # m, m, -, -, m (0: 0.047), -
    main_joint_friction=0.20, joint_stiffness_scale=0.01, base_joints="every_other", base_plane_deg=DESIGN_PLANE_DEG,
    merged_pair=0,
    joints_into_foundation=0, joint_gap=TABLE_5_6["gap"], z_order=0,  # joint_gap [m]: the joints' aperture when installed
    face_closure=0,  # as the tilting table's
    timestep_safety=0.8, damping=0.0, settle_damping=0.7,
    chunk=0.02, rest_speed=1e-3, fail_displacement=0.05, max_stage_time=2.0, fail_columns=2,  # s, m/s, m, s, -
    rest_window=0.2,  # [s] a standing slope rings without local damping: its speed is judged over this window
    model="ours",  # 'jcfpm': the same scene in YADE's JCFpm (docs/jcfpm.md)
    settled_dir="",  # a folder: runs that differ only in joints or laws share the settled rock kept there
    post_failure_time=0.3, resume=-1, checkpoint_every=600.0, max_wall_time=0.0, exact_resume=0)  # s, -, wall s x2

# ---- §5.4.2: Galandrood mine, BFTOP's input and result (Fig 5-44) ----
FIG_5_44 = dict(face_deg=81.0, layers_deg=39.0, failure_plane_deg=58.0, top_deg=32.0, height=16.5, thickness=0.3,
                friction_columns_deg=26.0, friction_base_deg=26.0, base_cohesion=0.01e6, friction_rock_deg=45.0,
                cohesion_rock=1.11e6, unit_weight=27e3, tensile_strength=5e6)  # deg, m, Pa, N/m3
FIG_5_44_RESULT = dict(toe_force=-0.112e3, factor_of_safety=1.3802)  # [N per m, -] block-flexure (BFTOP)
# ---- §5.4.2: Galandrood mine, the DEM model (Tables 5-14 ... 5-16) ----
TABLE_5_14 = dict(density=3000.0, young=6.55e9, knKs=1.5, frictionAngle=math.atan(0.05), bondYoung=6.55e9, bondKnKs=1.5,
                  bondTensileStrength=149.9e6, bondCohesion=114.2e6, bondFrictionAngle=math.radians(8.1),
                  bondNormalDamping=0.2, normalDamping=0.25, thickness=1.0)  # ParallelBondMat [kg/m3, Pa, -, rad, m]
TABLE_5_14_DISCS = dict(rmin=0.0375, rmax=0.06, bond_gap=0.06)  # [m]
TABLE_5_15 = dict(kn=12e7, ks=12e8, friction=0.5, gap=0.01)  # [N/m3, N/m3, -, m] as printed (ks = 10 kn)
TABLE_5_16_FACTOR = 1.62  # the bonds' tensile strength and cohesion / 1.62 (92.5, 70.5 MPa), their friction 8.1° / 1.62 = 5°
GALANDROOD_RESULT = dict(stable_unreduced=True, fails_at_factor=TABLE_5_16_FACTOR)  # §5.4.2.2, Fig 5-48
# Our reconstruction of the section (the text gives Fig 5-44's slope and "40951 particles"; the
# sketch, Fig 5-45, is not in the text): the slope of Fig 5-44 built as the equivalent slope's
# model (toppling.models.equivalent_slope), its columns standing on the plane through the toe normal
# to the layers and running on into the rock below it; 80 columns (24 m along that plane) make a
# section of 341 m², about what the thesis' 40,951 discs at n ≈ 0.12 fill (354 m²; docs/cases/galandrood.md).
GALANDROOD_SHAPE = dict(height=FIG_5_44["height"], joint_dip_deg=FIG_5_44["layers_deg"], face_deg=FIG_5_44["face_deg"],
                        top_deg=FIG_5_44["top_deg"], spacing=FIG_5_44["thickness"], columns=80)
GALANDROOD = dict(**TABLE_5_14_DISCS, columns=GALANDROOD_SHAPE["columns"], porosity=0.18, seed=1, joint_gap=0.0,
                  joint_kn=TABLE_5_15["kn"], joint_ks=TABLE_5_15["ks"], joint_friction=TABLE_5_15["friction"],
                  joints_into_foundation=1,
                  reduction_factor=TABLE_5_16_FACTOR,
                  timestep_safety=0.8, damping=0.0, settle_damping=0.7,
                  chunk=0.05, rest_speed=1e-3, fail_displacement=0.5, max_stage_time=2.0, fail_columns=2,
                  post_failure_time=0.2, resume=-1, checkpoint_every=600.0, max_wall_time=0.0, exact_resume=0)
# m, m, m (Table 5-14), -, -, -; joint_gap [m]: 0, Table 5-15's 1 cm read as the distance within which discs across a joint are paired (our bond
# gap, 6 cm, pairs them), not as an aperture; joint_kn, joint_ks [N/m3], joint_friction [-]; joints_into_foundation 1: the layers cut down to the held base, 0: rooted on the plane through the toe; s, m/s, m, s, -, s, -, wall s x2

# ---- §5.4.1: Ihlara Valley (Tables 5-12, 5-13; Figs 5-33 ... 5-37) ----
_IHLARA_COMMON = dict(normalDamping=0.25, bondNormalDamping=0.2, thickness=1.0)  # per metre of valley
TABLE_5_12 = {  # ParallelBondMat keyword arguments [kg/m3, Pa, -, rad]
    "ash": dict(density=1820.0, young=0.6e9, knKs=1.0, frictionAngle=math.atan(0.36), bondYoung=0.6e9, bondKnKs=1.1,
                bondTensileStrength=17.6e6, bondCohesion=17.6e6, bondFrictionAngle=math.radians(20), **_IHLARA_COMMON),
    "ignimbrite": dict(density=2160.0, young=5.28e9, knKs=1.2, frictionAngle=math.atan(0.45), bondYoung=5.28e9,
                       bondKnKs=1.3, bondTensileStrength=45e6, bondCohesion=37e6, bondFrictionAngle=math.radians(25),
                       **_IHLARA_COMMON),
    "tuff": dict(density=1950.0, young=1e9, knKs=1.2, frictionAngle=math.atan(0.3), bondYoung=1e9, bondKnKs=1.1,
                 bondTensileStrength=23.5e6, bondCohesion=17.6e6, bondFrictionAngle=math.radians(16), **_IHLARA_COMMON),
    "weathered": dict(density=1700.0, young=0.33e9, knKs=1.2, frictionAngle=math.atan(0.3), bondYoung=0.33e9,
                      bondKnKs=1.1, bondTensileStrength=3.75e6, bondCohesion=2.44e6, bondFrictionAngle=math.radians(14),
                      **_IHLARA_COMMON),
}
TABLE_5_12_DISCS = dict(rmin=0.15, rmax=0.25, bond_gap=0.025)  # [m]
TABLE_5_13 = dict(bedding=(12e8, 12e6, 0.53), vertical=(12e8, 12e6, 0.55), gap=0.1e-3)  # (kn, ks [N/m3], mu), gap [m]
IHLARA_BACK_ANALYSIS = 1.27  # the weathered tuff's bond strengths divided by it: 2.95 / 1.92 MPa (§5.4.1.4)
# Our reconstruction of the section (the text gives 40 x 38 m, 25 m of ignimbrite, 3.5 m columns, and a
# weathered zone under the first column and half the second; the rest is ours, docs/cases/ihlara.md).
IHLARA_SECTION = dict(width=38.0, tuff=10.0, ignimbrite=25.0, ash=5.0, face_x=31.5, column_width=3.5,
                      weathered_depth=2.5)  # [m]
IHLARA = dict(case="weathered", weathered_strength_factor=1.0, joint_gap=TABLE_5_13["gap"], joint_shear_stiffness=0.0,
              **TABLE_5_12_DISCS, porosity=0.18, seed=1, timestep_safety=0.8,
              damping=0.0, settle_damping=0.7, chunk=0.1, rest_speed=0.01, fail_displacement=0.5,
              max_stage_time=10.0, fail_columns=1, post_failure_time=5.0, resume=-1, checkpoint_every=600.0,
              max_wall_time=0.0, exact_resume=0)  # case: intact | weathered | eroded; m, N/m3 (0: Table 5-13's); rmin, rmax, bond_gap m; s, m/s, m, s, -, s
