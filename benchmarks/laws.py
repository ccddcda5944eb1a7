"""Benchmark: our parallel-bond law on the disc path and on YADE's generic loop, against YADE's
JCFpm and Cundall-Strack, on one packing.

Builds one bonded 2D packing (triangular lattice of ~20 000 discs with radii jittered by
up to 10 %, bottom row fixed, gravity) and times, in the same YADE process and on the same
discs, the step with each: µs per step and ns per interaction-step. Run it through the
launcher; it re-runs itself with 1 and 2 threads, prints a Markdown table and, last, one JSON
line {"fast_1": ns, "fast_2": ns, "generic_1": ns, ...} (ns per interaction-step). Before it, the
second core's other use: two one-thread runs of the disc path side by side, their steps per second
summed, against one run on two threads:

    ./yade -x -n benchmarks/laws.py                 # all thread counts
    ./yade -x -n -j2 benchmarks/laws.py worker      # one thread count, JSON on stdout
    BENCH_LAWS=fast ./yade -x -n -j1 benchmarks/laws.py worker   # one law
"""
import json
import math
import os
import random
import subprocess
import sys
import time

N_SIDE = int(os.environ.get("BENCH_SIDE", "141"))  # 141 x 141 = 19 881 discs
STEPS = int(os.environ.get("BENCH_STEPS", "200"))
REPEATS = 3
R = 1e-3


def lattice(seed=1):
    rng = random.Random(seed)
    for j in range(N_SIDE):
        for i in range(N_SIDE):
            yield (2 * R * i + (R if j % 2 else 0), math.sqrt(3) * R * j, R * rng.uniform(0.9, 1.0) + 1e-9 * R, j == 0)


LAWS = tuple(os.environ.get("BENCH_LAWS", "fast generic JCFpm CundallStrack").split())  # fast, generic: the parallel-bond law on each path


def build(law_name):
    from yade import O, utils
    from yade import wrapper as w
    from toppling.build import bonding, discs

    O.reset()
    if law_name in ("fast", "generic"):
        mat = w.ParallelBondMat(young=1e9, density=2700, bondYoung=1e9, frictionAngle=0.5)
        ip2, law2 = w.Ip2_ParallelBondMat_ParallelBondMat_ParallelBondPhys(), w.Law2_ScGeom_ParallelBondPhys_ParallelBond()
    elif law_name == "JCFpm":
        mat = w.JCFpmMat(young=1e9, density=2700, frictionAngle=0.5, tensileStrength=1e7, cohesion=1e7)
        ip2, law2 = w.Ip2_JCFpmMat_JCFpmMat_JCFpmPhys(cohesiveTresholdIteration=1), w.Law2_ScGeom_JCFpmPhys_JointedCohesiveFrictionalPM()
    else:
        mat = w.FrictMat(young=1e9, density=2700, frictionAngle=0.5)
        ip2, law2 = w.Ip2_FrictMat_FrictMat_FrictPhys(), w.Law2_ScGeom_FrictPhys_CundallStrack()
    O.materials.append(mat)
    for x, y, r, fixed in lattice():
        # Cundall-Strack has no bonds: enlarge its discs slightly so that every neighbour pair touches.
        b = utils.sphere((x, y, 0), 1.0005 * R if law_name == "CundallStrack" else r, material=mat, fixed=fixed)
        discs.set_disc_mass(b, 1.0)
        if not fixed:
            b.state.blockedDOFs = discs.PLANE_DOFS
        O.bodies.append(b)
    factor = 1.2 if law_name == "JCFpm" else 1.0  # JCFpm bonds what it detects at step 0
    bo1, ig2 = w.Bo1_Sphere_Aabb(aabbEnlargeFactor=factor), w.Ig2_Sphere_Sphere_ScGeom(interactionDetectionFactor=factor)
    # Each law runs at its own stable time step (GlobalStiffnessTimeStepper), as a user would.
    fast = law_name == "fast"
    loop, newton = (w.DiscInteractionLoop, w.DiscNewtonIntegrator) if fast else (w.InteractionLoop, w.NewtonIntegrator)
    O.engines = [w.ForceResetter(), w.InsertionSortCollider([bo1]), loop([ig2], [ip2], [law2]),
                 w.GlobalStiffnessTimeStepper(timestepSafetyCoefficient=0.5, timeStepUpdateInterval=100),
                 newton(gravity=(0, -9.81, 0), damping=0.1)]
    if law_name in ("fast", "generic"):
        bonding.bond_within_gap(gap=0.25 * R)
    O.run(1, True)
    bo1.aabbEnlargeFactor = ig2.interactionDetectionFactor = 1.0


def measure(law_name):
    from yade import O
    from toppling.run.steps import run_steps
    build(law_name)
    run_steps(50)  # warm-up
    seconds = math.inf
    for _ in range(REPEATS):  # best of several: the machine's other load only slows runs down
        start, first = time.perf_counter(), O.iter
        run_steps(STEPS)  # as the library runs a scene (the disc path keeps its bonds in an array)
        if O.iter != first + STEPS:
            raise RuntimeError(f"{law_name}: the run stopped early (unstable?) at iteration {O.iter}")
        seconds = min(seconds, (time.perf_counter() - start) / STEPS)
    interactions = sum(1 for i in O.interactions if i.isReal)
    return {"law": law_name, "discs": len(O.bodies), "interactions": interactions, "dt": O.dt,
            "us_per_step": seconds * 1e6, "ns_per_interaction_step": seconds * 1e9 / interactions}


def worker():
    from yade import O
    threads = O.numThreads if hasattr(O, "numThreads") else int(os.environ.get("OMP_NUM_THREADS", "1"))
    rows = [dict(measure(name), threads=threads) for name in LAWS]
    print("BENCHMARK-JSON " + json.dumps(rows))


def run_workers(threads: int, copies: int = 1, laws: str = " ".join(LAWS)) -> list:
    """The rows of ``copies`` worker processes of ``threads`` threads each, run side by side."""
    repo = os.environ["TOPPLING_REPO"]  # set by the ./yade launcher
    command = [os.path.join(repo, "yade"), "-x", "-n", "-j", str(threads), os.path.join(repo, "benchmarks", "laws.py"), "worker"]
    procs = [subprocess.Popen(command, stdout=subprocess.PIPE, text=True, env=dict(os.environ, BENCH_LAWS=laws))
             for _ in range(copies)]
    rows = []
    for proc in procs:
        out, _ = proc.communicate()
        if proc.returncode:
            raise RuntimeError(f"{' '.join(command)} failed ({proc.returncode})")
        line = next(l for l in out.splitlines() if l.startswith("BENCHMARK-JSON "))
        rows.append([dict(r, threads=threads) for r in json.loads(line[len("BENCHMARK-JSON "):])])
    return rows


def main():
    rows = run_workers(1)[0] + run_workers(2)[0]
    side_by_side = [r[0] for r in run_workers(1, copies=2, laws="fast")]
    out = os.path.join(os.environ["TOPPLING_REPO"], "results", "benchmark_laws")
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "summary.json"), "w") as f:
        json.dump(rows + side_by_side, f, indent=2)
    print("| law | threads | discs | interactions | µs/step | ns/interaction-step | vs JCFpm |")
    print("|---|---|---|---|---|---|---|")
    for r in rows:
        jcfpm = next(x for x in rows if x["law"] == "JCFpm" and x["threads"] == r["threads"])
        print(f"| {r['law']} | {r['threads']} | {r['discs']} | {r['interactions']} | {r['us_per_step']:.0f} | "
              f"{r['ns_per_interaction_step']:.0f} | {r['ns_per_interaction_step'] / jcfpm['ns_per_interaction_step']:.2f} |")
    two_threads = next(r for r in rows if r["law"] == "fast" and r["threads"] == 2)
    each = [1e6 / r["us_per_step"] for r in side_by_side]
    print(f"disc path, the second core: one run on 2 threads {1e6 / two_threads['us_per_step']:.0f} steps/s; two 1-thread "
          f"runs side by side {sum(each):.0f} steps/s summed ({' + '.join(f'{x:.0f}' for x in each)})")
    print(json.dumps({f"{r['law'].lower()}_{r['threads']}": round(r["ns_per_interaction_step"], 1) for r in rows
                      if r["law"] != "CundallStrack"}))


if __name__ == "__main__":
    worker() if sys.argv[-1] == "worker" else main()
