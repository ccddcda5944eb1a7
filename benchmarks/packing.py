"""Benchmark: fill a square with ~20 000 discs (R 1-2.5 mm) and report time and quality.

    ./yade -x -n benchmarks/packing.py          # porosity 0.18
    BENCH_POROSITY=0.16 ./yade -x -n benchmarks/packing.py
"""
import json
import math
import os

from toppling.build import geometry, packing

POROSITY = float(os.environ.get("BENCH_POROSITY", "0.18"))
RMIN, RMAX, N = 1e-3, 2.5e-3, 20000
mean_r2 = (RMAX**3 - RMIN**3) / (3 * (RMAX - RMIN))
side = math.sqrt(N * math.pi * mean_r2 / (1 - POROSITY))
square = geometry.region([(0, 0), (side, 0), (side, side), (0, side)])
result = packing.pack_polygon(square, RMIN, RMAX, POROSITY, seed=1)
centres_inside = all(square.containsMany([(x, y) for x, y, _ in result.discs], 0.0))
summary = {"discs": len(result.discs), "target_porosity": POROSITY, "porosity": result.porosity,
           "mean_overlap_over_rmin": result.mean_overlap / RMIN, "seconds": result.seconds, "steps": result.steps,
           "all_centres_inside": centres_inside}
os.makedirs("results/benchmark_packing", exist_ok=True)
with open("results/benchmark_packing/summary.json", "w") as f:
    json.dump(summary, f, indent=2)
print("PACKING " + json.dumps(summary))
