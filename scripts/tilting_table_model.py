"""The tilting-table example's definitions (materials, tables, build()) without running it,
for scripts that measure something on its model (benchmark, column bending)."""
import os
import tempfile

EXAMPLE = os.path.join(os.environ["TOPPLING_REPO"], "examples", "tilting_table.py")  # set by the ./yade launcher
MARKER = "# ---- build or resume ----"  # the example's definitions end here, its run starts


def definitions(**params) -> dict:
    """The example's namespace (its source up to MARKER) for the table parameters ``params``
    (values as in a yade-batch table line, e.g. rmin=0.002, arrangement="'ideal'")."""
    source = open(EXAMPLE).read()
    if MARKER not in source:
        raise RuntimeError(f"{EXAMPLE} has no line {MARKER!r}: update scripts/tilting_table_model.py")
    params.setdefault("out", f"'{tempfile.gettempdir()}/tilting_table_model'")
    with tempfile.NamedTemporaryFile("w", suffix=".table", delete=False) as f:
        f.write(" ".join(params) + "\n" + " ".join(str(v) for v in params.values()) + "\n")
    os.environ["YADE_BATCH"] = f"{f.name}:2"
    namespace = {"__name__": "tilting_table"}
    try:
        exec(compile(source.split(MARKER)[0], EXAMPLE, "exec"), namespace)
    finally:
        os.unlink(f.name)
    return namespace
