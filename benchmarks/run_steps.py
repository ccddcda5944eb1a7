"""Wall time per step of toppling.run.steps.run_steps against O.run(n, True), in runs of n steps.

    ./yade -x -n -j1 benchmarks/run_steps.py

A row of 20 discs (cheap steps, so that any cost of driving them shows): O.run(n, True) waits
for YADE's worker thread by polling every 40 ms, run_steps steps in the calling thread.
"""
import time

from yade import O
from yade.wrapper import ParallelBondMat

from toppling.build import engines
from toppling.build.discs import add_discs
from toppling.run.steps import run_steps

TOTAL = 100_000  # steps per measurement

O.reset()
add_discs([(0.01 * i, 0, 0.005) for i in range(20)], ParallelBondMat(young=1e8, density=2600, thickness=0.1))
O.engines = engines.engines(timestepper=False)
O.dt = 1e-6
print("| runner | steps per run | µs per step |\n|---|---|---|")
for name, run in (("O.run(n, True)", lambda n: O.run(n, True)), ("scene.run_steps(n)", run_steps)):
    for n in (50, TOTAL):
        calls = TOTAL // n
        start = time.time()
        for _ in range(calls):
            run(n)
        print(f"| {name} | {n} | {1e6 * (time.time() - start) / (calls * n):.2f} |", flush=True)
