"""How many of the tilting-table layout's cuts its cross-joint rules keep, column by column:
``./yade -x -n scripts/cross_joint_count.py [arrangement] [layout_seed ...]`` (random, 1 2 3 by
default). The example prints the same total when it builds; this needs no packing."""
import os
import sys

sys.path.insert(0, os.path.join(os.environ["TOPPLING_REPO"], "scripts"))  # set by the ./yade launcher
from tilting_table_model import definitions  # noqa: E402

from toppling import analysis  # noqa: E402


def count(arrangement: str, layout_seed: int) -> None:
    model = definitions(arrangement=f"'{arrangement}'", layout_seed=layout_seed)
    layout = model["column_layout"]()
    cuts = model["cross_joint_heights"](layout)
    kept = layout.cross_joints(cuts, model["BLOCK_LENGTH"])
    kept_in = [layout.column_of(0.5 * (a[0] + b[0])) for a, b in zip(kept.segmentStarts, kept.segmentEnds)]
    columns = ", ".join(f"{analysis.column_label(k)} {kept_in.count(k)}/{len(heights)}"
                        for k, heights in cuts.items() if heights)
    print(f"{arrangement}, layout seed {layout_seed}: {len(kept_in)} of {sum(map(len, cuts.values()))} cuts kept "
          f"({columns})")


args = sys.argv[1:]
arrangement = args[0] if args else "random"
for seed in [int(a) for a in args[1:]] or [1, 2, 3]:
    count(arrangement, seed)
