"""Collect the tilting-table summaries into one comparison table (ours vs thesis Table 5-4).

    source scripts/env.sh; /usr/bin/python3 calibration/tilting_table/collect.py [results/tilting_table [pattern ...]]

Prints a Markdown table (pasted into README.md) from every ``<folder>/*/summary.json`` (only the
runs whose name matches one of the shell-style ``pattern``s, when given), then
the particle-size check (issue 4: failure tilt and phi within 2 deg of the coarser packing of
the same model): runs that differ only in rmin/rmax, each compared with the next coarser one of
the same bond gap and with the next coarser one of the same bond density (a gap in proportion to
the mean radius); a run that stood to its last stage counts as failing above it; the spread of
failure tilt (range, mean, standard deviation, seeds within 3 deg of the thesis, and whether
the mean is, by two standard errors) and phi over
packings that differ only in their seed, and over the random arrangement's draws (packing seed and
layout seed) where several layouts were run; and the size check on the means over seeds, decided
only when two standard errors of the difference keep it inside (or outside) the 2 deg; and what
a stronger bond does to the same packings (the shift packing by packing, and the stronger mean
it gives when added to the weaker one's mean over all its seeds).
"""
import math
import statistics
import sys
from typing import NamedTuple, Optional, Sequence

from examples import params
from examples.params import SIZE_TOLERANCE_DEG, TARGET_TOLERANCE_DEG
from toppling.analyse.seeds import failed_seeds, first_stage_failure, fmt, inside_band, mean_against, mean_difference, stats_text, within
from toppling.io.reader import read_summaries


CALIBRATION = ("bond_tensile_strength", "main_joint_friction", "base_joint_friction")  # 0: the thesis' tables
NUMERICS = {"timestep_safety": 0.5, "seed": 1, "joint_stiffness_scale": 1.0}  # defaults (older summaries lack keys)
# inputs newer than some summaries: the value those runs had
ADDED = {"shrink_overlaps": 0, "fail_columns": 1, "bond_gap": 0.0, "damping": 0.7, "settle_damping": 0.7,
         "stage_rate": 0.0, "layout_seed": 1, "sliding_toe": 0, "cut_rules": 1, "toe_column": 1,
         "joint_pieces": 0, "arrest_time": 0.0}
# no part of the model (z_order only numbers the discs)
RUN_ONLY = ("out", "resume", "checkpoint_every", "max_tilt", "post_failure_time", "z_order")
TABLE_BOND_GAP = params.TABLE_5_2_BOND_GAP  # what bond_gap 0 stands for
SEED = ("seed",)  # what draws one packing of a model
DRAW = ("seed", "layout_seed")  # what draws one random arrangement: its packing and its block layout
MEAN_AGAINST_HEADER = (f"mean − thesis ± standard error (°): within {TARGET_TOLERANCE_DEG:g}° by two standard "
                       "errors?")


def model_key(inputs: dict, drawn_by: Sequence[str] = SEED) -> tuple[tuple[str, object], ...]:
    """What defines the model apart from the particle size, the bond gap and the inputs that
    draw one realisation of it (``drawn_by``), as (input, value) pairs: hashable, and
    ``dict(key)`` gives them back by name."""
    left_out = ("bond_gap",) + tuple(drawn_by)
    names = ("arrangement",) + CALIBRATION + tuple(name for name in ADDED if name not in left_out)
    return tuple((name, inputs.get(name, ADDED.get(name))) for name in names)


def bond_gap(inputs: dict) -> float:
    """The bond gap [m] a run used."""
    return inputs.get("bond_gap", ADDED["bond_gap"]) or TABLE_BOND_GAP


def same_bond_density(a: dict, b: dict) -> bool:
    """Bond gaps in proportion to the mean radius, (rmin + rmax) / 2, bond as many neighbours per
    disc whatever the particle size (docs/tilting_table.md, "Bond gap")."""
    relative = [bond_gap(i) / (i["rmin"] + i["rmax"]) for i in (a, b)]
    return abs(relative[0] - relative[1]) <= 0.01 * relative[1]


def numerics(inputs: dict) -> dict:
    return {name: inputs.get(name, default) for name, default in NUMERICS.items()}


def draw(s: dict, drawn_by: Sequence[str]) -> tuple:
    """The values of the inputs ``drawn_by`` that drew run ``s``."""
    inputs = {**ADDED, **NUMERICS, **s["inputs"]}
    return tuple(inputs[name] for name in drawn_by)


def overall_phi(s: dict) -> Optional[float]:
    """phi of the one line through all of run ``s``'s failure points (toppling.analyse.failure's
    overall surface), which compares runs whose points split into different numbers of
    surfaces: the summary's ``phi_overall_deg``; a one-surface run's phi; for a two-surface
    summary older than that key, the same least-squares line through its ``failure_points``."""
    if s.get("phi_overall_deg") is not None:
        return s["phi_overall_deg"]
    if len(s["phi_deg"]) == 1:
        return s["phi_deg"][0]
    points = s.get("failure_points") or []
    if len(points) < 2:
        return None
    fit = statistics.linear_regression([x for x, _ in points], [y for _, y in points])
    return math.degrees(math.atan(-fit.slope))  # the slope frame's phi (toppling.analyse.failure.Plane)


def phi_change(s: dict, ref: dict) -> tuple[Optional[list[float]], str]:
    """phi of run ``s`` minus that of ``ref``, surface by surface (None if they have different
    numbers of surfaces), and its text for a table."""
    if len(s["phi_deg"]) != len(ref["phi_deg"]):
        return None, f"{len(s['phi_deg'])} vs {len(ref['phi_deg'])} surfaces"
    phi = [a - b for a, b in zip(s["phi_deg"], ref["phi_deg"])]
    return phi, fmt(phi)


def tilt_change(s: dict, ref: dict) -> tuple[Optional[bool], str]:
    """Whether run ``s``'s failure tilt is within the tolerance of ``ref``'s (None: the runs do
    not tell), and the text for a table. One of them at least failed; one that stood to its last
    stage would have failed above it."""
    tilts = [run["failure_tilt_deg"] for run in (s, ref)]
    if None not in tilts:
        return abs(tilts[0] - tilts[1]) <= SIZE_TOLERANCE_DEG, f"{tilts[0] - tilts[1]:+.1f}"
    text = " vs ".join(fmt(t) if t is not None else f"stands to {fmt(run.get('stable_up_to_deg'))}"
                       for t, run in zip(tilts, (s, ref)))
    failed, stood = (tilts[1], s) if tilts[0] is None else (tilts[0], ref)
    if (stood.get("stable_up_to_deg") or 0.0) - failed > SIZE_TOLERANCE_DEG:
        return False, text
    return None, text


def same_gap(a: dict, b: dict) -> bool:
    return bond_gap(a) == bond_gap(b)


# the ways a finer packing is compared with a coarser one: the same bond gap (Table 5-2's, as run)
# and the same bonds per disc
BONDINGS = (same_gap, same_bond_density)


def next_coarser(group: list[tuple[str, dict]], s: dict, bonding) -> Optional[tuple[str, dict]]:
    """The run of ``group`` of the same packing seed with the next larger rmax than ``s`` that
    ``bonding(s, run)`` accepts, of the same numerical settings where there is one, and of those
    the least in doubt (``doubt``: a rerun from a lower start_tilt). Another seed's packing is no
    pair: seeds are compared on their means (size_over_seeds)."""
    seed = numerics(s["inputs"])["seed"]
    coarser = [run for run in group if run[1]["inputs"]["rmax"] > s["inputs"]["rmax"]
               and bonding(s["inputs"], run[1]["inputs"]) and numerics(run[1]["inputs"])["seed"] == seed]
    same = [run for run in coarser if numerics(run[1]["inputs"]) == numerics(s["inputs"])]
    return min(same or coarser, key=lambda run: (run[1]["inputs"]["rmax"], doubt(run[1]))) \
        if coarser else None


def size_row(name: str, s: dict, coarse_name: str, coarse: dict) -> Optional[str]:
    """One line of the size check; None if neither run failed (they tell nothing)."""
    failed = [run["failure_tilt_deg"] is not None for run in (s, coarse)]
    if not any(failed):
        return None
    tilt_ok, tilt_text = tilt_change(s, coarse)
    phi, phi_text = phi_change(s, coarse) if all(failed) else (None, "-")
    phi_ok = phi is not None and all(abs(d) <= SIZE_TOLERANCE_DEG for d in phi)
    ok = "-" if tilt_ok is None else "yes" if tilt_ok and phi_ok else "no"
    gaps = f"{1e3 * bond_gap(s['inputs']):g} vs {1e3 * bond_gap(coarse['inputs']):g}"
    return f"| {name} vs {coarse_name} | {gaps} | {tilt_text} | {phi_text} | {ok} |"


def size_check(runs: dict[str, dict]) -> list[str]:
    """Lines comparing each packing of a model with the next coarser one of the same bond gap,
    and with the next coarser one of the same bond density: R 1-2.5 mm with R 1-4 mm, the
    issue's pair, and R 1-4 mm with R 2-8 mm, the coarse runs the calibration used."""
    models: dict[tuple, list[tuple[str, dict]]] = {}
    for name, s in runs.items():
        models.setdefault(model_key(s["inputs"]), []).append((name, s))
    lines = []
    for group in models.values():
        for name, s in group:
            for bonding in BONDINGS:
                partner = next_coarser(group, s, bonding)
                row = size_row(name, s, *partner) if partner else None
                if row:
                    lines.append(row)
    return lines


def entered_cracked(s: dict) -> bool:
    """Whether bonds of the rock broke on the ramp to start_tilt (besides those that freed a
    loose disc: toppling.bonding.rock_breaks): the run warned that its failure tilt may be low
    and that a lower start_tilt judges in stages the tilts the ramp passed."""
    breaks = s.get("breaks_before_stages") or {}
    return breaks.get("ramp", 0) > breaks.get("loose", {}).get("ramp", 0)


def doubt(s: dict) -> tuple[bool, bool, float]:
    """How far a run's failure tilt is in doubt, least first: a first-stage failure is only an
    upper bound, a slope cracked by the ramp may fail low. A rerun of the same packing from a
    lower start_tilt clears both and replaces the run; of runs alike in these, the one whose
    stages began lowest judged the most tilts in stages."""
    return first_stage_failure(s), entered_cracked(s), s["inputs"].get("start_tilt", math.inf)


def one_per_draw(group: list[dict], drawn_by: Sequence[str] = SEED) -> list[dict]:
    """One run per draw (the values of ``drawn_by``): the least in doubt (``doubt``), the first
    listed of those."""
    chosen: dict[tuple, dict] = {}
    for s in group:
        key = draw(s, drawn_by)
        if key not in chosen or doubt(s) < doubt(chosen[key]):
            chosen[key] = s
    return [chosen[key] for key in sorted(chosen)]


class SeedGroup(NamedTuple):
    """What the runs of one seed group share: the model (model_key), packing size, bond gap [m]
    and numerical settings."""
    model: tuple
    rmin: float
    rmax: float
    gap: float
    safety: float
    joints: float  # joint_stiffness_scale

    def without_size(self) -> "SeedGroup":
        """The model this group is a packing of, bonded with any gap."""
        return self._replace(rmin=None, rmax=None, gap=None)

    def bonding(self) -> dict:
        """The same_gap / same_bond_density view of this group's inputs."""
        return {"rmin": self.rmin, "rmax": self.rmax, "bond_gap": self.gap}

    def size_text(self) -> str:
        return f"R {1e3 * self.rmin:g}–{1e3 * self.rmax:g} mm"


def seed_groups(runs: dict[str, dict], drawn_by: Sequence[str] = SEED) -> dict[SeedGroup, list[dict]]:
    """One run per draw (one_per_draw) of each model, packing size, bond gap and numerical
    setting; by default a draw is a packing seed."""
    groups: dict[SeedGroup, list[dict]] = {}
    for s in runs.values():
        inputs = s["inputs"]
        settings = numerics(inputs)
        key = SeedGroup(model_key(inputs, drawn_by), inputs["rmin"], inputs["rmax"], bond_gap(inputs),
                        settings["timestep_safety"], settings["joint_stiffness_scale"])
        groups.setdefault(key, []).append(s)
    return {key: one_per_draw(group, drawn_by) for key, group in groups.items()}


def group_name(key: SeedGroup) -> str:
    joints = f", joint stiffness x {key.joints:g}" if key.joints != 1 else ""
    model = dict(key.model)
    joints += f", local damping {model['damping']:g}" if model["damping"] != ADDED["damping"] else ""
    joints += f", steps at {model['stage_rate']:g} deg/s" if model["stage_rate"] else ""
    layout = model.get("layout_seed", ADDED["layout_seed"])  # absent where the layout is drawn
    joints += f", layout seed {layout:g}" if layout != ADDED["layout_seed"] else ""
    joints += ", sliding toe" if model["sliding_toe"] else ""
    joints += ", every block boundary a joint" if not model["cut_rules"] else ""
    joints += ", no toe column" if not model["toe_column"] else ""
    joints += ", joints between pieces of rock" if model["joint_pieces"] else ""
    frictions = ("main_joint_friction", "base_joint_friction")  # 0: Table 5-3's
    joints += "".join(f", {name.replace('_', ' ')} {model[name]:g}" for name in frictions if model.get(name))
    strength = model["bond_tensile_strength"]  # 0: Table 5-2's
    strength = f" {strength / 1e3:g} kPa" if strength else ""
    gap = f", bond gap {1e3 * key.gap:g} mm" if key.gap != TABLE_BOND_GAP else ""
    return f"{model['arrangement']}{strength} {key.size_text()}{gap}, safety {key.safety:g}{joints}"


def seed_spread(runs: dict[str, dict], drawn_by: Sequence[str] = SEED) -> list[str]:
    """Lines giving, for each model, packing size and time step run with several draws (packing
    seeds; with DRAW, packing and layout seeds where several layouts were run), the range, mean
    and standard deviation of the failure tilt, how many draws failed within the issue's
    tolerance of the thesis' tilt, whether their mean is (``mean_against``), and the mean,
    standard deviation and range of the overall phi (``overall_phi``). A draw that stood to its
    last stage, or failed in its first (an upper bound), counts as one outside the tolerance and
    in none of the figures."""
    lines = []
    for key, group in seed_groups(runs, drawn_by).items():
        failed = failed_seeds(group)
        if len(failed) < 2 or len({draw(s, drawn_by)[-1] for s in group}) < 2:
            continue  # the last input drawn does not vary: one run, or another table's group
        tilts = [s["failure_tilt_deg"] for s in failed]
        phis = [phi for phi in map(overall_phi, failed) if phi is not None]
        seeds = ", ".join("/".join(f"{v:g}" for v in draw(s, drawn_by)) for s in group)
        target = group[0]["thesis"]["failure_tilt_deg"]
        inside = inside_band(tilts, target, TARGET_TOLERANCE_DEG)
        phi_range = f"{stats_text(phis)} ({min(phis):.1f}–{max(phis):.1f})" if phis else "-"
        stood = sum(s["failure_tilt_deg"] is None for s in group)
        bounded = [f"{s['failure_tilt_deg']:g}" for s in group if first_stage_failure(s)]
        others = ([f"{stood} stood"] if stood else []) + ([f"at most {', '.join(bounded)}"] if bounded else [])
        others = f" ({'; '.join(others)})" if others else ""
        lines.append(f"| {group_name(key)} | {seeds} | {min(tilts):.1f}–{max(tilts):.1f} | {stats_text(tilts)} | "
                     f"{inside} of {len(group)}{others} | {mean_against(tilts, target, TARGET_TOLERANCE_DEG)} | {phi_range} |")
    return lines


def size_over_seeds(runs: dict[str, dict]) -> list[str]:
    """The size check on seed means: each packing run with several seeds, or against one that
    was, compared with the next coarser packing of the same model, bond gap and numerical
    settings: mean failure tilt and overall phi (``overall_phi``) of the seeds that failed, the
    difference of the means with its standard error, and the verdict of mean_difference; beside
    it the difference of the first surface's phi, which a toe segment along the table pulls
    down in the runs whose points split."""
    groups = seed_groups(runs)
    lines = []
    for key, group in groups.items():
        for coarse_key in coarser_partners(groups, key):
            lines += size_over_seeds_row(key, group, coarse_key, groups[coarse_key])
    return lines


def coarser_partners(groups: dict[SeedGroup, list[dict]], key: SeedGroup) -> list[SeedGroup]:
    """The next coarser packing of ``key``'s model and numerical settings of the same bond gap,
    and that of the same bond density where it is another group."""
    coarser = [k for k in groups if k.without_size() == key.without_size() and k.rmax > key.rmax]
    partners = []
    for bonding in BONDINGS:
        matching = [k for k in coarser if bonding(key.bonding(), k.bonding())]
        if matching:
            partners.append(min(matching, key=lambda k: k.rmax))
    return list(dict.fromkeys(partners))


def size_over_seeds_row(key: SeedGroup, group: list[dict], coarse_key: SeedGroup, partner: list[dict]) -> list[str]:
    """The row of size_over_seeds for one pair of seed groups; none with one seed on each side."""
    if max(len(group), len(partner)) < 2:
        return []  # one seed each: size_check's pair
    sides = [failed_seeds(g) for g in (group, partner)]
    tilts = [[s["failure_tilt_deg"] for s in side] for side in sides]
    phis = [[phi for phi in map(overall_phi, side) if phi is not None] for side in sides]
    firsts = [[s["phi_deg"][0] for s in side if s["phi_deg"]] for side in sides]
    cells = []
    for g, side, t, p in zip((group, partner), sides, tilts, phis):
        stood = len(g) - len(side)
        extra = f", {stood} stood or bounded" if stood else ""
        cells.append(f"{len(side)} of {len(g)}{extra}: {stats_text(t)}, φ {stats_text(p)}")
    tilt_text, tilt_ok = mean_difference(*tilts, SIZE_TOLERANCE_DEG)
    phi_text, phi_ok = mean_difference(*phis, SIZE_TOLERANCE_DEG)
    verdict = ("yes" if tilt_ok == phi_ok == "yes" else "no" if "no" in (tilt_ok, phi_ok)
               else phi_ok if tilt_ok == "yes" else tilt_ok)  # an undecided phi leaves it undecided
    coarse = coarse_key.size_text()
    coarse += f", bond gap {1e3 * coarse_key.gap:g} mm" if coarse_key.gap != key.gap else ""
    first_text = mean_difference(*firsts, SIZE_TOLERANCE_DEG)[0]
    return [f"| {group_name(key)} vs {coarse} | {cells[0]} | {cells[1]} | {tilt_text} | {phi_text} | {first_text} | "
            f"{verdict} |"]


def without_strength(key: SeedGroup) -> SeedGroup:
    """``key`` with its bond tensile strength left out: the groups that differ only in it."""
    return key._replace(model=tuple((name, None if name == "bond_tensile_strength" else value)
                                    for name, value in key.model))


def strength_pairs(runs: dict[str, dict]) -> list[str]:
    """Lines pairing each seed group with a stronger one of the same model, packing size and
    numerics: the failure tilt's shift over the packings run at both strengths (each pair shares
    its packing, so the packings' scatter drops out), and the stronger strength's mean estimated
    as the weaker one's mean over all its seeds plus that shift, against the thesis
    (``within``). A packing pairs only where it failed above its first stage at both strengths."""
    groups = seed_groups(runs)
    lines = []
    for weak_key, weak in groups.items():
        for strong_key, strong in groups.items():
            strengths = [dict(k.model)["bond_tensile_strength"] for k in (weak_key, strong_key)]
            if without_strength(weak_key) != without_strength(strong_key) or not 0 < strengths[0] < strengths[1]:
                continue
            lines += strength_pair_row(weak_key, failed_seeds(weak), strengths[1], failed_seeds(strong))
    return lines


def strength_pair_row(weak_key: SeedGroup, weak: list[dict], strength: float, strong: list[dict]) -> list[str]:
    """The row of strength_pairs for one weaker and one stronger group; none under two pairs."""
    stronger = {draw(s, SEED): s["failure_tilt_deg"] for s in strong}
    pairs = {draw(s, SEED): s["failure_tilt_deg"] for s in weak if draw(s, SEED) in stronger}
    if len(pairs) < 2 or len(weak) < 2:
        return []
    shifts = [stronger[seed] - tilt for seed, tilt in pairs.items()]
    tilts = [s["failure_tilt_deg"] for s in weak]
    shift, shift_se = statistics.mean(shifts), statistics.stdev(shifts) / len(shifts) ** 0.5
    estimate = statistics.mean(tilts) + shift
    se = (statistics.variance(tilts) / len(tilts) + shift_se ** 2) ** 0.5
    target = weak[0]["thesis"]["failure_tilt_deg"]
    seeds = ", ".join(f"{seed:g}" for (seed,) in sorted(pairs))
    return [f"| {group_name(weak_key)} | {strength / 1e3:g} kPa | {seeds} | {shift:+.1f} ± {shift_se:.1f} | "
            f"{len(tilts)}: {stats_text(tilts)} | {estimate:.1f} ± {se:.1f} | "
            f"{estimate - target:+.1f} ± {se:.1f}: {within(estimate - target, se, TARGET_TOLERANCE_DEG)} |"]


def joint_stiffness_check(runs: dict[str, dict]) -> list[str]:
    """Lines comparing each run with softened joints (joint_stiffness_scale < 1) with the run
    that differs from it only in that, at Table 5-3's stiffness: the failure tilt and phi it
    changes, and the time step and wall time it gains (wall times compare on one machine)."""
    def rest(inputs: dict) -> dict:
        full = {**ADDED, **NUMERICS, **inputs}
        return {k: v for k, v in full.items() if k not in RUN_ONLY + ("joint_stiffness_scale",)}

    lines = []
    for name, s in runs.items():
        scale = numerics(s["inputs"])["joint_stiffness_scale"]
        stiff = [(n, r) for n, r in runs.items() if numerics(r["inputs"])["joint_stiffness_scale"] == 1
                 and rest(r["inputs"]) == rest(s["inputs"])]
        if scale == 1 or not stiff or s["failure_tilt_deg"] is None or stiff[0][1]["failure_tilt_deg"] is None:
            continue
        ref_name, ref = stiff[0]
        _, phi = phi_change(s, ref)
        dt_gain = (s["simulated_time"] / s["steps"]) / (ref["simulated_time"] / ref["steps"])
        lines.append(f"| {name} vs {ref_name} | {scale:g} | {s['failure_tilt_deg'] - ref['failure_tilt_deg']:+.1f} | "
                     f"{phi} | {dt_gain:.1f} | {ref['wall_time'] / s['wall_time']:.1f} |")
    return lines


def main(folder: str, patterns: Sequence[str] = ("*",)) -> None:
    runs = read_summaries(folder, patterns)
    rows = []
    for name, s in runs.items():
        inputs = s["inputs"]
        tilt = fmt(s["failure_tilt_deg"]) if s["failure_tilt_deg"] is not None else \
            f"none up to {fmt(s.get('stable_up_to_deg'))}"
        if s["stages"][-1].get("failed_by") == "max_stage_time":  # a creep rather than a collapse
            tilt += " (time limit)"
        arrested = s.get("arrested_failures", [])
        if arrested:  # failures that came to rest before the slope's (arrest_time > 0)
            tilt += f" (came to rest at {fmt([failure['tilt'] for failure in arrested])})"
        stable = [stage["tilt"] for stage in s["stages"] if stage["outcome"] == "equilibrium"]
        changed = [f"{knob} {inputs[knob]:g}" for knob in CALIBRATION if inputs.get(knob)] or ["Tables 5-2/5-3"]
        changed += [f"{knob} {value:g}" for knob, value in numerics(inputs).items() if value != NUMERICS[knob]]
        changed += [f"{knob} {inputs[knob]:g}" for knob in ADDED if inputs.get(knob, ADDED[knob]) != ADDED[knob]]
        changed = ", ".join(changed)
        rows.append(f"| {name} | {inputs['arrangement']} | {changed} | "
                    f"{1e3 * inputs['rmin']:g}–{1e3 * inputs['rmax']:g} | {s['discs']} | "
                    f"{fmt(max(stable)) if stable else '-'} | {tilt} | {fmt(s['thesis']['failure_tilt_deg'])} | {fmt(s['phi_deg'])} | "
                    f"{fmt(s['thesis']['phi_deg'])} | {fmt(s['s_over_h'], 2)} | {fmt(s['t_over_h'], 2)} | "
                    f"{s['tensile_breaks']} / {s['shear_breaks']} | {s['wall_time']:.0f} |")
    if not rows:
        sys.exit(f"no {folder}/*/summary.json matching {' '.join(patterns)}: run the tilting_table batch first "
                 "(see README)")
    print("| run | arrangement | parameters | R (mm) | discs | last equilibrium (°) | failure tilt (°) | thesis (°) | φ (°) | thesis φ (°) | S/H | T/H "
          "| tensile / shear breaks | wall time (s) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    print("\n".join(rows))
    section(f"Particle size (finer minus next coarser packing of the same model, of the same bond gap or the same "
            f"bond density; within {SIZE_TOLERANCE_DEG:g} deg?)",
            ["runs", "bond gap (mm)", "failure tilt (°)", "φ (°)", "within tolerance"], size_check(runs))
    section("Packing seed (range over the seeds of the same model, packing size and time step)",
            ["model", "seeds", "failure tilt (°)", "mean ± sd (°)", f"within {TARGET_TOLERANCE_DEG:g}° of the thesis",
             MEAN_AGAINST_HEADER, "overall φ (°)"], seed_spread(runs))
    section("Packing and layout (range over the random arrangement's draws, packing seed / layout seed, of the same "
            "model, packing size and time step)",
            ["model", "packing / layout seeds", "failure tilt (°)", "mean ± sd (°)",
             f"within {TARGET_TOLERANCE_DEG:g}° of the thesis", MEAN_AGAINST_HEADER, "overall φ (°)"],
            seed_spread(runs, DRAW))
    section(f"Particle size over seeds (finer minus next coarser, means of the seeds that failed ± the standard "
            f"error; within {SIZE_TOLERANCE_DEG:g} deg by two standard errors?)",
            ["model vs coarser", "finer: seeds failed, failure tilt (°), overall φ (°)", "coarser: the same",
             "failure tilt (°)", "overall φ (°)", "first surface's φ (°)", "within tolerance"], size_over_seeds(runs))
    section("Bond strength on the same packings (a stronger group minus the weaker, packing by packing; the "
            "stronger's mean estimated as the weaker's mean over all its seeds plus that shift ± the standard error)",
            ["weaker model", "stronger", "paired seeds", "shift (°)", "weaker: seeds failed, failure tilt (°)",
             "estimated mean (°)", MEAN_AGAINST_HEADER], strength_pairs(runs))
    section("Joint stiffness (softened minus Table 5-3's; time step and wall time: how many times larger / smaller)",
            ["runs", "joint stiffness x", "failure tilt (°)", "φ (°)", "mean time step", "wall time"],
            joint_stiffness_check(runs))


def section(title: str, header: list[str], rows: list[str]) -> None:
    """A titled markdown table after the main one; nothing when it has no rows."""
    if rows:
        print(f"\n{title}:\n")
        print(f"| {' | '.join(header)} |")
        print("|" + "---|" * len(header))
        print("\n".join(rows))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "results/tilting_table", sys.argv[2:] or ("*",))
