"""A bonded block on a fixed slab across a smooth joint: sliding against closed forms."""
import math

import numpy
import pytest
from lattice import R, material
from yade import O, Quaternion, utils
from yade.wrapper import JointSetGeometry, JointSystem, Law2_ScGeom_SmoothJointPhys_SmoothJoint, SmoothJointMat

from toppling.build import bonding, engines, joints
from toppling.build.discs import disc
from toppling.load import tilting
from toppling.run.steps import run_steps

G = tilting.G
ROWS_SLAB, ROWS_BLOCK, COLS = 3, 5, 24
Y_JOINT = math.sqrt(3) * R * (ROWS_SLAB - 0.5)  # between the slab's top row and the block's bottom row


def block_on_slab(friction_deg: float, smooth: bool = True, segment: bool = False, pieces: bool = True,
                  loaded: bool = False, face_closure: bool = False):
    """Fixed slab of discs, bonded block of discs on it, a horizontal joint between: a smooth
    joint (persistent, or with ``segment`` one explicit segment), or (smooth=False) plain disc
    contacts of the same friction. ``loaded``: the bonded scene saved and loaded before the
    joint is installed (as from a checkpoint or a shared settled rock). ``face_closure``: new
    joint contacts start with their faces' closure."""
    rock = material(frictionAngle=math.radians(30 if smooth else friction_deg))
    block = []
    for j in range(ROWS_SLAB + ROWS_BLOCK):
        for i in range(COLS):
            if j >= ROWS_SLAB and not 4 <= i < 12:
                continue
            x, y = 2 * R * i + (R if j % 2 else 0), math.sqrt(3) * R * j
            b = O.bodies.append(disc((x, y), R, rock, fixed=j < ROWS_SLAB))
            if j >= ROWS_SLAB:
                block.append(b)
    O.engines = engines.engines(gravity=(0, -G, 0), local_damping=0.5)
    if not smooth:
        bonding.bond_within_gap(1e-6 * R, ids=block)
        run_steps(2000)
        return block, None
    bonding.bond_within_gap(1e-6 * R)
    if loaded:
        O.saveTmp("bonded")
        O.loadTmp("bonded")
    joint = (JointSetGeometry(dip=0, segmentStarts=[(-R, Y_JOINT)], segmentEnds=[(2 * R * COLS, Y_JOINT)])
             if segment else JointSetGeometry(origin=(0, Y_JOINT), dip=0))
    mechanics = SmoothJointMat(normalStiffness=rock.bondYoung / (2 * R),
                               shearStiffness=rock.bondYoung / (2 * R), frictionAngle=math.radians(friction_deg))
    system = joints.install_joints([(joint, mechanics)], lo=(-R, -R), hi=(2 * R * COLS, 10 * R * ROWS_BLOCK),
                                   pieces=pieces, face_closure=face_closure)
    run_steps(2000)  # settle on the joint, damped
    return block, system


def tilt(alpha_deg: float) -> None:
    """Tilt the table by rotating gravity; no damping from here on."""
    tilting.set_tilt(alpha_deg)
    engines.set_local_damping(0.0)


def mean_x(ids) -> float:
    return sum(O.bodies[i].state.pos[0] for i in ids) / len(ids)


def acceleration(ids, steps=4000, samples=40) -> float:
    """Least-squares parabola through the block's mean x: the undamped block rings on its joint
    springs, so a velocity difference between two instants would measure the ringing too."""
    times, xs = [], []
    for _ in range(samples):
        run_steps(steps // samples)
        times.append(O.time)
        xs.append(mean_x(ids))
    return 2 * numpy.polyfit(times, xs, 2)[0]


def test_joint_pairs_lose_their_bonds(empty_scene):
    block, system = block_on_slab(friction_deg=20)
    assert len(system.pairId1) == 2 * 8  # each of the block's 8 bottom discs touches two slab discs
    for i, j in zip(system.pairId1, system.pairId2):
        phys = O.interactions[i, j].phys
        assert type(phys).__name__ == "SmoothJointPhys"
        assert phys.jointNormal[1] == pytest.approx(1.0)


def test_joints_are_installed_in_a_scene_just_loaded(empty_scene):
    """The joint pairs are made outside the interaction loop, which has not run in the loaded scene."""
    block, system = block_on_slab(friction_deg=20, loaded=True)
    assert len(system.pairId1) == 2 * 8
    assert all(type(O.interactions[i, j].phys).__name__ == "SmoothJointPhys"
               for i, j in zip(system.pairId1, system.pairId2))


def test_without_smooth_joint_coarse_discs_interlock(empty_scene):
    # Thesis §4.4: the block's bottom discs sit in the grooves between the slab's discs, so even a
    # frictionless interface holds it at 26°; the smooth joint removes the bumps (next test).
    block, _ = block_on_slab(friction_deg=0, smooth=False)
    tilt(26)
    assert abs(acceleration(block)) < 0.01 * G * math.sin(math.radians(26))


def test_frictionless_joint_slides_at_g_sin_alpha(empty_scene):
    block, _ = block_on_slab(friction_deg=0)
    tilt(26)
    assert acceleration(block) == pytest.approx(G * math.sin(math.radians(26)), rel=0.005)


@pytest.mark.parametrize("phi", [20.0, 30.0])
def test_friction_holds_below_and_slides_above_friction_angle(empty_scene, phi):
    block, _ = block_on_slab(friction_deg=phi)
    start = [O.bodies[i].state.pos[0] for i in block]
    tilt(phi - 2)
    run_steps(4000)
    creep = max(abs(O.bodies[i].state.pos[0] - x) for i, x in zip(block, start))
    assert creep < 0.01 * R  # elastic shear only
    tilt(phi + 4)
    # The sudden tilt is a step load: the block rings on its joint springs for the first few
    # thousand steps, which moves a parabola fitted then by up to 1.5 % either way depending on
    # the settling history alone (measured); the closed form is the sliding that follows.
    run_steps(4000)
    a = math.radians(phi + 4)
    expected = G * (math.sin(a) - math.tan(math.radians(phi)) * math.cos(a))
    assert acceleration(block) == pytest.approx(expected, rel=0.005)


def test_joint_normal_turns_with_rotating_blocks(empty_scene):
    # Spin the whole block-on-slab assembly rigidly by 30° about the origin (kinematically): the
    # joint normal must turn by 30° with it, and a rigid motion must load no joint.
    block, system = block_on_slab(friction_deg=20)
    engines.newton().gravity = (0, 0, 0)
    spin_rate, turn = 10.0, math.radians(30)
    for b in O.bodies:
        b.state.blockedDOFs = "xyzXYZ"
        b.dynamic = True
    forces_before = [O.interactions[i, j].phys.jointNormalForce for i, j in zip(system.pairId1, system.pairId2)]
    steps = int(turn / spin_rate / O.dt)
    O.dt = turn / spin_rate / steps
    for _ in range(steps):  # rigid rotation: v = w x r, updated each step
        for b in O.bodies:
            p = b.state.pos
            b.state.vel = (-spin_rate * p[1], spin_rate * p[0], 0)
            b.state.angVel = (0, 0, spin_rate)
        O.step()
    for (i, j), f0 in zip(zip(system.pairId1, system.pairId2), forces_before):
        phys = O.interactions[i, j].phys
        assert phys.jointNormal[0] == pytest.approx(-math.sin(turn), abs=2e-3)
        assert phys.jointNormal[1] == pytest.approx(math.cos(turn), abs=2e-3)
        assert phys.jointNormalForce == pytest.approx(f0, abs=0.02 * max(abs(f) for f in forces_before))


def test_joint_normal_ignores_the_spin_of_a_single_disc(empty_scene):
    # A disc's own orientation is not the rock's: spinning the two discs of a joint pair in place
    # (bonds unturned) must leave the joint normal alone; a disc loose in a pore spins freely.
    block, system = block_on_slab(friction_deg=20)
    i, j = system.pairId1[0], system.pairId2[0]
    for k in (i, j):
        O.bodies[k].state.ori = Quaternion((0, 0, 1), 1.0)
    O.step()
    assert O.interactions[i, j].phys.jointNormal[1] == pytest.approx(1.0, abs=1e-6)


@pytest.mark.parametrize("segment", [False, True])
def test_block_slides_diameters_with_load_passing_from_pair_to_pair(empty_scene, segment):
    # Large displacement: after sliding several disc diameters, every joint contact still joins
    # discs that touch (pairs that slid apart ended, new ones formed as smooth joints), and the
    # block keeps the closed-form acceleration g (sin a - tan phi cos a). A joint of explicit
    # segments gives no bands: the block and the slab are told apart as pieces of rock.
    block, _ = block_on_slab(friction_deg=10, segment=segment)
    tilt(20)
    start = mean_x(block)
    a = math.radians(20)
    expected = G * (math.sin(a) - math.tan(math.radians(10)) * math.cos(a))
    assert acceleration(block, steps=64000) == pytest.approx(expected, rel=0.005)
    assert mean_x(block) - start > 8 * R
    joint_contacts = [I for I in O.interactions if type(I.phys).__name__ == "SmoothJointPhys"]
    assert 0 < len(joint_contacts) <= 2 * 8
    assert min(I.geom.penetrationDepth for I in joint_contacts) > -0.05 * R


def test_without_pieces_a_block_sliding_on_segments_interlocks(empty_scene):
    # The same block on an explicit-segment joint with blocks told apart by persistent bands only
    # (there are none): once it has slid a disc spacing, its new contacts with the slab are plain
    # disc contacts, whose grooves stop it (as in the interlocking test above): measured, it
    # stops 2.0 R on, where the closed form (the test above) takes it past 9 R.
    block, _ = block_on_slab(friction_deg=10, segment=True, pieces=False)
    tilt(20)
    start = mean_x(block)
    run_steps(64000)
    assert mean_x(block) - start < 3 * R


def test_each_joint_disc_records_its_distance_to_the_joint_it_faces_and_a_saved_scene_keeps_it(empty_scene):
    block, system = block_on_slab(friction_deg=20, loaded=True)
    O.saveTmp("jointed")
    O.loadTmp("jointed")
    system = joints.rock_functor().joints
    faces = list(zip(system.faceBody, system.faceSide, system.faceDistance))
    assert len(faces) == 2 * COLS + 2 * 8  # the two rows on either side within reach (3 R): the slab's, the block's
    for body, side, distance in faces:
        assert side == (1 if body in block else 0)
        assert min(abs(distance - k * math.sqrt(3) * R / 2) for k in (1, 3)) < 1e-9 * R


@pytest.mark.parametrize("face_closure", [True, False])
def test_a_contact_remade_under_load_starts_with_its_faces_closure(empty_scene, face_closure):
    # A joint contact that ends and forms again (as pairs turn over under a sliding block) between
    # discs whose faces the load presses together: with the faces' closure it takes up its share
    # of the load at once, as a plane face would; stress-free, it carries nothing until the block
    # has sunk onto it.
    block_on_slab(friction_deg=20, face_closure=face_closure)
    system = joints.rock_functor().joints
    i, j = system.pairId1[3], system.pairId2[3]
    O.step()
    before = O.interactions[i, j].phys.jointNormalForce
    O.interactions.erase(i, j)
    utils.createInteraction(i, j)
    O.step()
    after = O.interactions[i, j].phys.jointNormalForce
    assert before > 0
    assert after == (pytest.approx(before, rel=0.02) if face_closure else pytest.approx(0, abs=0.02 * before))


def test_a_closure_beyond_the_limit_starts_at_the_limit(empty_scene):
    # The limit keeps a contact made across interpenetrated (or mismatched) faces from starting
    # with a closure whose stored energy would throw its discs apart.
    block_on_slab(friction_deg=20, face_closure=True)
    system = joints.rock_functor().joints
    system.faceClosureLimit = 1e-7  # × R: a twentieth of the closure the block's weight makes
    i, j = system.pairId1[3], system.pairId2[3]
    O.interactions.erase(i, j)
    utils.createInteraction(i, j)
    phys = O.interactions[i, j].phys
    assert phys.overlap == pytest.approx(1e-7 * R, rel=1e-9)


def test_a_negative_closure_limit_is_rejected():
    with pytest.raises(ValueError, match=r"JointSystem.faceClosureLimit = -0.1 is invalid: it must be >= 0"):
        JointSystem(faceClosureLimit=-0.1)


def test_bad_turn_interval_is_rejected():
    law = Law2_ScGeom_SmoothJointPhys_SmoothJoint()
    with pytest.raises(ValueError, match=r"Law2_ScGeom_SmoothJointPhys_SmoothJoint.turnInterval = 0 .*>= 1"):
        law.turnInterval = 0
