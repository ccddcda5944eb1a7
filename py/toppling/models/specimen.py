"""Platen compression of a rectangular bonded specimen (numerical UCS test, thesis §4.3, §5.2.3).

The discs within Rmax of the top and bottom edges are the platens and move towards each
other; axial stress = platen force / (width t), axial strain = platen closure / height,
lateral strain from the mean x of the discs within Rmax of the two sides.
"""
from __future__ import annotations

from dataclasses import dataclass, field

from yade import O

from toppling.build import bonding, boundary, engines, geometry, packing
from toppling.build.discs import add_discs
from toppling.run.steps import check_stable, run_steps


@dataclass
class Specimen:
    ids: list[int]
    top: list[int]
    bottom: list[int]
    left: list[int]
    right: list[int]
    width: float
    height: float
    thickness: float
    bonds: int


@dataclass
class Curve:
    axial_strain: list[float] = field(default_factory=lambda: [0.0])
    axial_stress: list[float] = field(default_factory=lambda: [0.0])  # compression positive [Pa]
    lateral_strain: list[float] = field(default_factory=lambda: [0.0])  # extension positive

    @property
    def peak(self) -> float:
        return max(self.axial_stress)

    @property
    def strain_at_peak(self) -> float:
        return self.axial_strain[self.axial_stress.index(self.peak)]


def build_specimen(width: float, height: float, rmin: float, rmax: float, porosity: float, material,
                   relax_steps: int, bond_gap: float, seed: int = 1) -> Specimen:
    """Pack, relax (free, damped: the packing's overlaps would break weak bonds) and bond a
    width x height specimen; ``bond_gap`` in units of rmin."""
    region = geometry.region([(0, 0), (width, 0), (width, height), (0, height)])
    discs = packing.pack_polygon(region, rmin, rmax, porosity, seed=seed).discs
    ids = add_discs(discs, material)
    O.engines = engines.engines(gravity=(0, 0, 0), local_damping=0.9)
    run_steps(relax_steps)
    bonds = bonding.bond_within_gap(bond_gap * rmin)

    def edge(a, b):
        return boundary.near([(a, b)], rmax, ids)
    return Specimen(ids, edge((0, height), (width, height)), edge((0, 0), (width, 0)),
                    edge((0, 0), (0, height)), edge((width, 0), (width, height)),
                    width, height, material.thickness, bonds)


def _mean_x(ids: list[int]) -> float:
    return sum(O.bodies[i].state.pos[0] for i in ids) / len(ids)


def compress(spec: Specimen, velocity: float, local_damping: float = 0.0, post_peak_drop: float = 0.5,
             max_strain: float = 0.05, steps_per_sample: int = 100) -> Curve:
    """Drive the platens at ``velocity`` each until the stress has fallen below
    ``post_peak_drop`` x peak after the peak, or the strain reaches ``max_strain``."""
    if velocity <= 0:
        raise ValueError(f"velocity = {velocity} is invalid: it must be > 0 m/s")
    engines.set_local_damping(local_damping)
    boundary.move(spec.top, (0, -velocity))
    boundary.move(spec.bottom, (0, velocity))
    curve, t0 = Curve(), O.time
    width0 = _mean_x(spec.right) - _mean_x(spec.left)
    while True:
        run_steps(steps_per_sample)
        check_stable("the compression test")
        force = sum(O.forces.f(i)[1] for i in spec.top) - sum(O.forces.f(i)[1] for i in spec.bottom)
        curve.axial_strain.append(2 * velocity * (O.time - t0) / spec.height)
        curve.axial_stress.append(0.5 * force / (spec.width * spec.thickness))  # the specimen pushes out
        curve.lateral_strain.append((_mean_x(spec.right) - _mean_x(spec.left)) / width0 - 1)
        past_peak = curve.axial_strain[-1] > 1.1 * curve.strain_at_peak
        if (past_peak and curve.axial_stress[-1] < post_peak_drop * curve.peak) or curve.axial_strain[-1] > max_strain:
            return curve


def elastic_constants(curve: Curve, lo: float = 0.1, hi: float = 0.5) -> tuple[float, float]:
    """Young's modulus and Poisson's ratio, secant between lo x peak and hi x peak on the
    rising branch (plane stress 2D values, as PFC2D reports them)."""
    first = [next(k for k, s in enumerate(curve.axial_stress) if s >= f * curve.peak) for f in (lo, hi)]
    d_axial = curve.axial_strain[first[1]] - curve.axial_strain[first[0]]
    young = (curve.axial_stress[first[1]] - curve.axial_stress[first[0]]) / d_axial
    poisson = (curve.lateral_strain[first[1]] - curve.lateral_strain[first[0]]) / d_axial
    return young, poisson
