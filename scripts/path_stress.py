"""Whether the loading path (a ramp to the start tilt, or stages from below it) changes the
stresses a packing's bonds carry at the later stages: two runs of one packing compared at the
last stage both ended with (almost) no bond broken.

    source scripts/env.sh; /usr/bin/python3 scripts/path_stress.py <run A> <run B> [<run A> <run B> ...]

Per pair prints that stage's tilt, the largest bond tensile stress sigma_max [kPa] of each run
(A first) and their difference B - A, how much the largest stress rose per degree into that
stage (mean of both runs), and both failure tilts. Then the mean difference over the pairs with
its standard error, and that over the mean rise: how many degrees the path moves the tilt at
which the first bond reaches the strength. The stages are read from the runs' ParaView series
(scripts/first_crack.py, up to the first stage with more than FEW_BROKEN broken bonds).
"""
import os
import statistics
import sys
from typing import Optional, Sequence

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bond_stress_history import run_record  # noqa: E402
from first_crack import elastic_peaks  # noqa: E402


def rise(curve: dict[float, float], tilt: float) -> Optional[float]:
    """How much ``curve`` (tilt: largest stress) rose per degree from the stage before ``tilt``
    to it; None at its first stage."""
    before = [t for t in curve if t < tilt]
    return (curve[tilt] - curve[max(before)]) / (tilt - max(before)) if before else None


def compare(peaks_a: Sequence[tuple], peaks_b: Sequence[tuple]) -> Optional[tuple[float, float, float, Optional[float]]]:
    """(tilt, largest stress of A, of B, mean rise per degree into it) at the last stage both
    runs' ``elastic_peaks`` hold; None if they share none."""
    a, b = ({t: stresses[0] for t, stresses, *_ in peaks} for peaks in (peaks_a, peaks_b))
    common = set(a) & set(b)
    if not common:
        return None
    tilt = max(common)
    rises = [r for r in (rise(a, tilt), rise(b, tilt)) if r is not None]
    return tilt, a[tilt], b[tilt], statistics.mean(rises) if rises else None


def main(folders: Sequence[str]) -> None:
    print("| run A | run B | tilt (°) | σ A (kPa) | σ B (kPa) | B − A (kPa) | rise (kPa/°) | failure A / B (°) |")
    print("|---|---|---|---|---|---|---|---|")
    differences, rises = [], []
    for run_a, run_b in zip(folders[::2], folders[1::2]):
        compared = compare(elastic_peaks(run_a), elastic_peaks(run_b))
        failures = " / ".join(f"{run_record(f).get('failure_tilt_deg')}" for f in (run_a, run_b))
        names = " | ".join(os.path.basename(f.rstrip("/")) for f in (run_a, run_b))
        if compared is None:
            print(f"| {names} | - | - | - | - | - | {failures} |")
            continue
        tilt, sigma_a, sigma_b, up = compared
        differences.append((sigma_b - sigma_a) / 1e3)
        rises += [up / 1e3] if up is not None and up > 0 else []
        print(f"| {names} | {tilt:g} | {sigma_a / 1e3:.1f} | {sigma_b / 1e3:.1f} | {differences[-1]:+.1f} | "
              f"{'-' if up is None else f'{up / 1e3:.1f}'} | {failures} |")
    if len(differences) > 1:
        mean, error = statistics.mean(differences), statistics.stdev(differences) / len(differences) ** 0.5
        print(f"\nB − A over {len(differences)} pairs: {mean:+.2f} ± {error:.2f} kPa (mean ± standard error)", end="")
        if rises:
            up = statistics.mean(rises)
            print(f"; over the mean rise {up:.2f} kPa/°: {mean / up:+.2f} ± {error / up:.2f}°", end="")
        print()


if __name__ == "__main__":
    if len(sys.argv) < 3 or len(sys.argv) % 2 == 0:
        sys.exit(__doc__)
    main(sys.argv[1:])
