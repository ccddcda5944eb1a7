"""Tilting by rotating gravity (thesis Fig 5-7), in stages run to equilibrium or failure."""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable, Optional, Sequence

import numpy as np
from yade import O

from toppling import scene

G = 9.81


def set_tilt(alpha_deg: float) -> None:
    """Tilt the table by ``alpha_deg`` towards +x (the toe side): gravity (g sin a, -g cos a)."""
    a = math.radians(alpha_deg)
    O.engines[-1].gravity = (G * math.sin(a), -G * math.cos(a), 0)


def positions(ids: Sequence[int]) -> np.ndarray:
    return np.array([tuple(O.bodies[i].state.pos)[:2] for i in ids])


@dataclass
class StageCriteria:
    chunk: float = 0.02  # simulated seconds between checks
    rest_speed: float = 1e-3  # [m/s] fastest watched disc slower than this: equilibrium
    fail_displacement: float = 5e-3  # [m] a watched disc moved more since the last equilibrium: failed
    max_stage_time: float = 0.4  # [s] still moving faster than rest_speed after this: failed (creep)

    def __post_init__(self):
        for name in ("chunk", "rest_speed", "fail_displacement", "max_stage_time"):
            if getattr(self, name) <= 0:
                raise ValueError(f"{name} = {getattr(self, name)} is invalid: it must be > 0")


def run_stage(alpha_deg: float, watched: Sequence[int], reference: np.ndarray, criteria: StageCriteria,
              on_chunk: Optional[Callable[[], None]] = None, settling: bool = False) -> str:
    """Tilt to ``alpha_deg`` and run until ``'equilibrium'`` or ``'failed'`` (see
    StageCriteria), judged on the ``watched`` discs against their ``reference`` positions.
    ``settling``: the first stage, a large tilt from rest whose elastic response may exceed
    ``fail_displacement``; only the time limit can fail it."""
    set_tilt(alpha_deg)
    start, before = O.time, positions(watched)
    while True:
        O.run(max(1, int(criteria.chunk / O.dt)), True)
        scene.check_stable(f"the stage at {alpha_deg} deg")
        now = positions(watched)
        speed = np.linalg.norm(now - before, axis=1).max() / criteria.chunk
        moved = np.linalg.norm(now - reference, axis=1).max()
        before = now
        if on_chunk:
            on_chunk()
        if moved > criteria.fail_displacement and not settling:
            return "failed"
        if speed < criteria.rest_speed:
            return "equilibrium"
        if O.time - start > criteria.max_stage_time:
            return "failed"
