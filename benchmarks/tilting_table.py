"""Benchmark: what a tilting-table run costs at a given packing.

Builds the tilting-table model (toppling.models.tilting_table, the calibrated ideal case's
parameters of examples/params.py) at the radii given, lets gravity load the joints (the time step
sees them once they carry force), then times the step: best of BENCH_REPEATS (3). Prints a row:
discs, interactions, dt, steps per second and simulated seconds per wall hour, which with the
2-3 s a run simulates says how long a packing takes; and what a checkpoint's alignment costs.

With ``z_order`` ``both`` it builds the scene twice in the same process, discs in the packer's
order (``z_order`` 0) and in Z-order (1), times them in turn (0, 1, 0, 1: the machine's load
drifts alike over both), and prints the speed-up of Z-order over the packer's order. With
``path`` ``both`` it times one scene, saved after the warm-up, on YADE's generic interaction
loop and on the disc path in turn (generic, fast, generic, fast), in CPU time, and prints the
speed-up of the disc path.

    ./yade -x -n -j1 benchmarks/tilting_table.py [rmin rmax [arrangement [joint_stiffness_scale [z_order [path]]]]]
"""
import os
import statistics
import sys
import time
from types import SimpleNamespace

from yade import O

from examples import params
from toppling.build import engines
from toppling.models import tilting_table
from toppling.run.checkpoint import Checkpoint
from toppling.run.steps import run_steps

WARM_UP, STEPS, REPEATS = 2000, 2000, int(os.environ.get("BENCH_REPEATS", "3"))


def build(rmin: float, rmax: float, arrangement: str, joint_stiffness_scale: float, z_order: int) -> None:
    """The model's scene, without running it."""
    O.reset()
    case = SimpleNamespace(**{**params.TILTING_TABLE_IDEAL, "arrangement": arrangement, "rmin": rmin, "rmax": rmax,
                              "joint_stiffness_scale": joint_stiffness_scale, "z_order": z_order})
    tilting_table.from_params(case, params).build()


def time_steps() -> dict:
    run_steps(WARM_UP)
    rates = []
    for _ in range(REPEATS):
        start = time.time()
        run_steps(STEPS)  # as the library runs a scene
        rates.append(STEPS / (time.time() - start))
    rate = max(rates)  # the least disturbed by the rest of the machine
    return dict(discs=sum(1 for b in O.bodies if b is not None), interactions=len(O.interactions), dt=O.dt,
                rate=rate, per_hour=rate * O.dt * 3600)


def compare_paths(pairs: int = 6) -> None:
    """Time the built scene on the generic loop and on the disc path in turn, ``pairs`` times,
    from one saved state."""
    run_steps(WARM_UP)
    O.saveTmp("benchmark")
    rates = {False: [], True: []}
    for fast in (False, True) * pairs:
        O.loadTmp("benchmark")
        engines.set_fast(fast)
        run_steps(200)  # the collider and the time stepper rebuilt after the load
        start = time.process_time()  # of this thread's steps (O.run's waiting thread would count too)
        run_steps(STEPS)
        rates[fast].append(STEPS / (time.process_time() - start))
        print(f"| {'fast' if fast else 'generic'} | {len(O.bodies)} | {len(O.interactions)} | {O.dt:.2e} | "
              f"{rates[fast][-1]:.0f} | {rates[fast][-1] * O.dt * 3600:.2f} |", flush=True)
    ratios = [fast / generic for fast, generic in zip(rates[True], rates[False])]
    print(f"disc path over the generic loop, in steps per CPU second: x{statistics.median(ratios):.2f} (median of "
          f"{pairs} pairs; " + ", ".join(f"x{r:.2f}" for r in ratios) + ")")


def alignment_cost(rate: float) -> str:
    """What Checkpoint.align (exact_resume) costs here: its own time, and the step after it
    (a scene YADE loaded is laid out otherwise in memory), against ``rate`` steps/s before."""
    start = time.perf_counter()
    Checkpoint.align()
    seconds = time.perf_counter() - start
    run_steps(200)
    start = time.perf_counter()
    run_steps(STEPS)
    after = STEPS / (time.perf_counter() - start)
    return (f"alignment (Checkpoint.align): {seconds:.3f} s; then {after:.0f} steps/s against {rate:.0f} before "
            f"(x{after / rate:.2f})")


def row(r: dict, label: str = "") -> str:
    return f"| {label}{r['discs']} | {r['interactions']} | {r['dt']:.2e} | {r['rate']:.0f} | {r['per_hour']:.2f} |"


def main() -> None:
    args = sys.argv[1:]
    rmin, rmax = (float(args[0]), float(args[1])) if len(args) >= 2 else (2e-3, 8e-3)
    arrangement = args[2] if len(args) >= 3 else "ideal"
    scale = float(args[3]) if len(args) >= 4 else 1.0
    order = args[4] if len(args) >= 5 else "1"
    path = args[5] if len(args) >= 6 else "fast"
    if order not in ("0", "1", "both"):
        raise SystemExit(f"z_order = {order} is invalid: it must be 0, 1 or both")
    if path not in ("fast", "generic", "both") or (path == "both" and order == "both"):
        raise SystemExit(f"path = {path} is invalid: it must be fast, generic or both (both with one z_order)")
    print(f"tilting table, {arrangement}, R {1e3 * rmin:g}-{1e3 * rmax:g} mm, joint stiffness x {scale:g}, "
          f"{O.numThreads} thread(s)")
    if path == "both":
        print("| path | discs | interactions | dt (s) | steps per CPU s | simulated s per CPU hour |")
        print("|---|---|---|---|---|---|")
        build(rmin, rmax, arrangement, scale, int(order))
        compare_paths()
        return
    orders = [0, 1, 0, 1] if order == "both" else [int(order)]
    print(f"| {'z_order: ' if order == 'both' else ''}discs | interactions | dt (s) | steps/s | simulated s per wall hour |")
    print("|---|---|---|---|---|")
    rates = {0: [], 1: []}
    for z in orders:
        build(rmin, rmax, arrangement, scale, z)
        engines.set_fast(path == "fast")
        r = time_steps()
        rates[z].append(r["rate"])
        print(row(r, f"{z}: " if order == "both" else ""), flush=True)
        print(alignment_cost(r["rate"]), flush=True)
    if order == "both":
        print(f"Z-order over the packer's order: x{max(rates[1]) / max(rates[0]):.2f} in steps/s "
              f"(best of each; pairs x{rates[1][0] / rates[0][0]:.2f}, x{rates[1][1] / rates[0][1]:.2f})")


main()
