"""Fill a polygon with discs of uniform radii to a target porosity, with low locked-in stress.

Radius expansion (Potyondy & Cundall 2004): discs with the radii that give the target
porosity exactly are placed at random inside the polygon at a fraction of their size, then
grown back in stages in a frictionless, damped, gravity-free YADE scene whose polygon edges
are walls, and relaxed. A porosity below what the radii can jam at shows up as overlaps; the
packer then refuses with the porosity it could reach.
"""
from __future__ import annotations

import hashlib
import json
import math
import os
import random
import time
from collections import defaultdict
from dataclasses import dataclass, field
from typing import Iterator, Sequence

from yade import O, utils
from yade.wrapper import (Bo1_Facet_Aabb, Bo1_Sphere_Aabb, FrictMat, ForceResetter,
                          GlobalStiffnessTimeStepper, Ig2_Facet_Sphere_ScGeom, Ig2_Sphere_Sphere_ScGeom,
                          InsertionSortCollider, InteractionLoop, Ip2_FrictMat_FrictMat_FrictPhys,
                          Law2_ScGeom_FrictPhys_CundallStrack, NewtonIntegrator, PolygonRegion, Sphere)

from toppling.checks import require
from toppling.run.steps import run_steps

START_SIZE = 0.6      # discs are placed at this fraction of their radius
GROWTH_STAGES = 20
STEPS_PER_STAGE = 100
MAX_MEAN_OVERLAP = 0.01  # of Rmin: above it the porosity is not reachable without locked-in stress
RELAX_ROUNDS, RELAX_STEPS = 40, 250
BYTES_PER_DISC = 10e3  # a bonded disc with its interactions, packer included (measured: 8.2 kB at R 1-4 mm)


@dataclass
class Packing:
    """Discs (x, y, r) filling a polygon, and what was achieved."""
    discs: list = field(default_factory=list)
    porosity: float = 0.0
    mean_overlap: float = 0.0   # mean overlap of touching pairs [m]
    seconds: float = 0.0
    steps: int = 0


def _check_inputs(polygon: PolygonRegion, rmin: float, rmax: float, porosity: float) -> None:
    require("rmin", rmin, "(0, inf)")
    require("rmax", rmax, f"[{rmin}, inf)")  # rmin <= rmax
    require("porosity", porosity, "(0, 1)")
    lo, hi = polygon.aabb()
    require("rmax", rmax, f"(0, {min(hi[0] - lo[0], hi[1] - lo[1]) / 4:.6g}]")  # a quarter of the polygon's smaller side
    count = disc_count(polygon.area(), rmin, rmax, porosity)
    if count * BYTES_PER_DISC > available_memory():
        raise ValueError(f"rmin = {rmin}, rmax = {rmax} are invalid for this polygon: they make about {count:.3g} discs, "
                         f"which need about {count * BYTES_PER_DISC / 1e9:.3g} GB, and {available_memory() / 1e9:.3g} GB "
                         "of memory is available; raise rmin and rmax")


def available_memory() -> int:
    """The memory [bytes] the system can give without swapping (MemAvailable)."""
    with open("/proc/meminfo") as f:
        for line in f:
            if line.startswith("MemAvailable:"):
                return int(line.split()[1]) * 1024
    raise OSError("/proc/meminfo has no MemAvailable")


def disc_count(area: float, rmin: float, rmax: float, porosity: float) -> int:
    """How many discs of radii uniform in rmin..rmax fill ``area`` at ``porosity``."""
    mean_r2 = rmin**2 if rmax == rmin else (rmax**3 - rmin**3) / (3 * (rmax - rmin))
    return max(1, round((1 - porosity) * area / (math.pi * mean_r2)))


def _radii(area: float, rmin: float, rmax: float, porosity: float, rng: random.Random) -> list[float]:
    """Uniform radii whose total area is exactly (1 - porosity) * area."""
    n = disc_count(area, rmin, rmax, porosity)
    radii = [rng.uniform(rmin, rmax) for _ in range(n)]
    scale = math.sqrt((1 - porosity) * area / (math.pi * sum(r * r for r in radii)))
    return [r * scale for r in radii]


def _positions(polygon: PolygonRegion, radii: list[float], rng: random.Random) -> list[tuple[float, float]]:
    lo, hi = polygon.aabb()
    points = []
    for r in radii:
        for _ in range(10000):
            p = (rng.uniform(lo[0], hi[0]), rng.uniform(lo[1], hi[1]))
            if polygon.contains(p, START_SIZE * r):
                points.append(p)
                break
        else:
            raise ValueError("could not place discs inside the polygon: is it thinner than a disc?")
    return points


def _walls(polygon: PolygonRegion, material, half_height: float) -> None:
    """Two facets per polygon edge, standing through the disc plane."""
    rings, start = [list(polygon.vertices)], 0
    for n in polygon.holeSizes:
        rings.append(list(polygon.holeVertices)[start:start + n])
        start += n
    for ring in rings:
        for a, b in zip(ring, ring[1:] + ring[:1]):
            corners = [(a[0], a[1], -half_height), (b[0], b[1], -half_height),
                       (b[0], b[1], half_height), (a[0], a[1], half_height)]
            for tri in ((0, 1, 2), (0, 2, 3)):
                O.bodies.append(utils.facet([corners[k] for k in tri], material=material, fixed=True))


def _overlaps() -> list[float]:
    """Overlaps of touching disc pairs in the current scene [m]."""
    return [i.geom.penetrationDepth for i in O.interactions
            if i.isReal and isinstance(O.bodies[i.id1].shape, Sphere) and isinstance(O.bodies[i.id2].shape, Sphere)]


def pairs_within(centres: Sequence[tuple[float, float]], radii: Sequence[float],
                 gap: float) -> Iterator[tuple[int, int, float]]:
    """Index pairs (i, j, distance of centres), i < j, of discs whose surfaces are at most ``gap``
    apart (overlapping pairs too).

    A uniform cell grid of the largest diameter plus the gap keeps it O(N).
    """
    if not radii:
        return
    cell = 2 * max(radii) + gap
    grid = defaultdict(list)
    for i, (x, y) in enumerate(centres):
        grid[(int(x // cell), int(y // cell))].append(i)
    for (cx, cy), members in grid.items():
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for j in grid.get((cx + dx, cy + dy), ()):
                    for i in members:
                        if i < j:
                            distance = math.dist(centres[i], centres[j])
                            if distance <= radii[i] + radii[j] + gap:
                                yield i, j, distance


def shrink_overlaps(discs: Sequence[tuple[float, float, float]]) -> list[tuple[float, float, float]]:
    """The discs (x, y, r), each shrunk by half its largest overlap, so that no two overlap.

    A relaxed packing still holds small overlaps (up to a few % of Rmin where it jams), whose
    contact force a stress-free bond installed over them must take up in tension as soon as the
    run starts: enough to break weak bonds before gravity acts. Shrinking removes that locked-in
    force at a porosity change of the order of the mean overlap over R.
    """
    centres = [(x, y) for x, y, _ in discs]
    radii = [r for _, _, r in discs]
    shrink = [0.0] * len(discs)
    for i, j, distance in pairs_within(centres, radii, 0.0):
        half = 0.5 * (radii[i] + radii[j] - distance)
        shrink[i], shrink[j] = max(shrink[i], half), max(shrink[j], half)
    return [(x, y, r - s) for (x, y, r), s in zip(discs, shrink)]


def z_order(discs: Sequence[tuple[float, float, float]]) -> list[tuple[float, float, float]]:
    """The discs (x, y, r) reordered along a Z-order (Morton) curve over cells of the largest
    diameter, so that discs near in space get near ids.

    The packer places discs at random, so neighbours' ids are far apart and a step's pass over
    the interactions misses the cache on nearly every body it reads (the interaction loop's own
    time, most of it waiting on those loads, was 31 % of a fine tilting-table step under
    ``perf``). Only the order changes: the same discs, in a different summation order.
    """
    if not discs:
        return []
    cell = 2 * max(r for _, _, r in discs)
    x0, y0 = min(x for x, _, _ in discs), min(y for _, y, _ in discs)

    def key(disc: tuple[float, float, float]) -> int:
        ix, iy = int((disc[0] - x0) // cell), int((disc[1] - y0) // cell)
        return sum(((ix >> b) & 1) << (2 * b) | ((iy >> b) & 1) << (2 * b + 1) for b in range(max(ix, iy).bit_length()))

    return sorted(discs, key=key)


def cache_folder() -> str:
    """Where packings are kept (``$TOPPLING_CACHE/packings``, by default ``~/.cache/toppling/packings``)."""
    return os.path.join(os.environ.get("TOPPLING_CACHE", os.path.expanduser("~/.cache/toppling")), "packings")


def _kept_path(polygon: PolygonRegion, rmin: float, rmax: float, porosity: float, seed: int) -> str:
    """The file of a packing: named by its inputs and by this module's source, so that a changed
    packer makes new packings."""
    with open(__file__, "rb") as f:
        packer = hashlib.sha256(f.read()).hexdigest()
    inputs = json.dumps([list(map(list, polygon.vertices)), list(map(list, polygon.holeVertices)),
                         list(polygon.holeSizes), rmin, rmax, porosity, seed, packer])
    return os.path.join(cache_folder(), hashlib.sha256(inputs.encode()).hexdigest()[:32] + ".json")


def pack_polygon(polygon: PolygonRegion, rmin: float, rmax: float, porosity: float = 0.15,
                 seed: int = 1, keep: bool = False) -> Packing:
    """Discs of radii uniform in rmin..rmax (rescaled by a factor ~1 to hit ``porosity``
    exactly) filling ``polygon``; reproducible from ``seed``. Runs in a scene of its own. With
    ``keep``, the packing is kept in ``cache_folder()`` and a later call with the same inputs
    reads it back (the same discs to the last bit) instead of packing again: the cases of a
    study share their packings."""
    _check_inputs(polygon, rmin, rmax, porosity)
    if not keep:
        return _pack(polygon, rmin, rmax, porosity, seed)
    path = _kept_path(polygon, rmin, rmax, porosity, seed)
    if os.path.exists(path):
        with open(path) as f:
            kept = json.load(f)
        return Packing([tuple(d) for d in kept["discs"]], kept["porosity"], kept["mean_overlap"], 0.0, kept["steps"])
    packed = _pack(polygon, rmin, rmax, porosity, seed)
    os.makedirs(cache_folder(), exist_ok=True)
    aside = f"{path}.{os.getpid()}"  # written aside, then renamed: a run killed meanwhile leaves no half file
    with open(aside, "w") as f:
        json.dump({"discs": packed.discs, "porosity": packed.porosity, "mean_overlap": packed.mean_overlap,
                   "steps": packed.steps}, f)
    os.replace(aside, path)
    return packed


def _pack(polygon: PolygonRegion, rmin: float, rmax: float, porosity: float, seed: int) -> Packing:
    started = time.perf_counter()
    rng = random.Random(seed)
    radii = _radii(polygon.area(), rmin, rmax, porosity, rng)
    positions = _positions(polygon, radii, rng)

    caller = O.thisScene
    O.switchToScene(O.addScene())
    try:
        mat = O.materials.append(FrictMat(young=1e8, poisson=0.5, frictionAngle=0.0, density=1000))
        _walls(polygon, mat, 2 * rmax)
        ids = [O.bodies.append(utils.sphere((x, y, 0), START_SIZE * r, material=mat)) for (x, y), r in zip(positions, radii)]
        for i in ids:
            O.bodies[i].state.blockedDOFs = "zXYZ"
        bo1 = Bo1_Sphere_Aabb(aabbEnlargeFactor=1 / START_SIZE)  # bounds already cover the final size
        O.engines = [ForceResetter(), InsertionSortCollider([bo1, Bo1_Facet_Aabb()]),
                     InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom()],
                                     [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()]),
                     GlobalStiffnessTimeStepper(timestepSafetyCoefficient=0.8, timeStepUpdateInterval=50),
                     NewtonIntegrator(damping=0.7, gravity=(0, 0, 0))]
        for stage in range(1, GROWTH_STAGES + 1):
            size = START_SIZE + (1 - START_SIZE) * stage / GROWTH_STAGES
            for i, r in zip(ids, radii):
                O.bodies[i].shape.radius = size * r
            bo1.aabbEnlargeFactor = 1 / size
            run_steps(STEPS_PER_STAGE)
        for _ in range(RELAX_ROUNDS):  # relax until the overlaps are well below the limit
            run_steps(RELAX_STEPS)
            overlaps = _overlaps()
            if sum(overlaps) / max(1, len(overlaps)) < 0.2 * MAX_MEAN_OVERLAP * rmin:
                break
        discs = [(b.state.pos[0], b.state.pos[1], b.shape.radius) for b in O.bodies if isinstance(b.shape, Sphere)]
        steps = O.iter
    finally:
        O.switchToScene(caller)

    inside = polygon.containsMany([(x, y) for x, y, _ in discs], 0.0)
    discs = [d for d, ok in zip(discs, inside) if ok]
    achieved = 1 - sum(math.pi * r * r for _, _, r in discs) / polygon.area()
    mean_overlap = sum(overlaps) / len(overlaps) if overlaps else 0.0
    if mean_overlap > MAX_MEAN_OVERLAP * rmin:
        raise ValueError(f"porosity = {porosity} is unreachable with radii {rmin}..{rmax} without locked-in stress: "
                         f"mean overlap {mean_overlap / rmin:.1%} of Rmin (limit {MAX_MEAN_OVERLAP:.0%}); use a larger porosity")
    return Packing(discs, achieved, mean_overlap, time.perf_counter() - started, steps)


def pack_predicate(predicate, rmin: float, rmax: float, porosity: float = 0.15, seed: int = 1) -> Packing:
    """Discs filling any ``yade.pack`` predicate, combined as YADE's are (``a | b``, ``a & b``,
    ``a - b``; ``toppling.build.geometry.PolygonPredicate`` for a polygon): its bounding box in
    the xy-plane packed as ``pack_polygon`` does, and the discs wholly inside the predicate at
    z = 0 kept. The edges of the shape cut the packing (as ``yade.pack.filterSpherePack``
    does), so the porosity returned is that of the box."""
    lo, hi = predicate.aabb()
    if not all(map(math.isfinite, (lo[0], lo[1], hi[0], hi[1]))):
        raise ValueError(f"predicate = {predicate!r} is invalid: it must be bounded in the xy-plane (intersect it "
                         "with a bounded one: a & b)")
    box = PolygonRegion(vertices=[(lo[0], lo[1]), (hi[0], lo[1]), (hi[0], hi[1]), (lo[0], hi[1])])
    packed = pack_polygon(box, rmin, rmax, porosity, seed)
    packed.discs = [(x, y, r) for x, y, r in packed.discs if predicate((x, y, 0.0), r)]
    return packed
