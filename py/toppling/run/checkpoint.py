"""Checkpoints that resume a run."""
from __future__ import annotations

import json
import os
from typing import Any, Sequence

from yade import O


class Checkpoint:
    """``<folder>/checkpoint.yade.bz2``: the scene (by ``O.save``) with the driver's own state
    (where in its loop it was) inside it, in ``O.tags``, so that the two can never come from two
    different moments; ``checkpoint.json`` is a copy of the state to read without loading the scene."""

    TAG = "toppling.checkpoint"

    def __init__(self, folder: str):
        self.scene_path = os.path.join(folder, "checkpoint.yade.bz2")
        self.state_path = os.path.join(folder, "checkpoint.json")

    def exists(self) -> bool:
        return os.path.exists(self.scene_path)

    def save(self, state: dict[str, Any]) -> None:
        # Written aside and moved into place in one rename: a run killed while saving (a long run
        # is stopped at any moment) leaves the previous checkpoint whole; aside under the process'
        # own name, as runs sharing a settled scene may save the same one at once.
        os.makedirs(os.path.dirname(self.scene_path), exist_ok=True)
        text = json.dumps(state)
        O.tags[self.TAG] = text
        scene_tmp = self.scene_path.replace("checkpoint.", f"checkpoint.saving-{os.getpid()}.")
        O.save(scene_tmp)
        os.replace(scene_tmp, self.scene_path)
        state_tmp = f"{self.state_path}.{os.getpid()}.tmp"
        with open(state_tmp, "w") as f:
            f.write(text)
        os.replace(state_tmp, self.state_path)

    @staticmethod
    def align() -> None:
        """Pass the scene through its own serialization, as a save and a load would. YADE keeps
        state that a save drops (the collider's sorted bounds and its potential interactions,
        the time stepper's first-run flag), and a resumed run rebuilds it at another moment
        than the run that never stopped: the two then part in the last bits and, a chaotic
        system, in their breaks. A run that aligns wherever it may save resumes bit for bit."""
        O.saveTmp(Checkpoint.TAG)
        O.loadTmp(Checkpoint.TAG)

    def saved_inputs(self) -> dict[str, Any]:
        """The parameters of the checkpointed run, from the copy (or, without it, the scene)."""
        if os.path.exists(self.state_path):
            with open(self.state_path) as f:
                return json.load(f).get("inputs", {})
        return self.load().get("inputs", {})

    def continues(self, inputs: dict[str, Any], resume: int, free: Sequence[str] = ()) -> bool:
        """Whether a run with parameters ``inputs`` continues this checkpoint rather than starting
        afresh: ``resume`` = 1 yes, 0 no, -1 if there is one, so that running the same command
        again continues a stopped run. With -1 the checkpoint's ``"inputs"`` must be the same
        (apart from the ``free`` ones, which may change between a run and its continuation):
        a run with other parameters stops rather than overwrite another run's results."""
        if resume not in (-1, 0, 1):
            raise ValueError(f"resume = {resume} is invalid: it must be -1 (continue a run with the same "
                             "parameters), 0 (start afresh) or 1 (continue the checkpoint)")
        if resume != -1:
            return bool(resume)
        if not self.exists():
            return False
        saved = self.saved_inputs()

        def fixed(d: dict[str, Any]) -> dict[str, Any]:
            return {k: v for k, v in json.loads(json.dumps(d)).items() if k not in free}  # as stored

        then, now = fixed(saved), fixed(inputs)
        differ = sorted(k for k in then.keys() | now.keys() if then.get(k) != now.get(k))
        if differ:
            changes = ", ".join(f"{k} {then.get(k)!r} there, {now.get(k)!r} here" for k in differ)
            raise ValueError(f"{os.path.dirname(self.state_path)} holds the checkpoint of a run with other "
                             f"parameters ({changes}): resume=0 starts afresh and discards it, resume=1 "
                             "continues it with these parameters, or choose another out folder")
        return True

    def load(self) -> dict[str, Any]:
        if not self.exists():
            raise FileNotFoundError(f"no checkpoint in {os.path.dirname(self.scene_path)}: run without resume first")
        try:
            O.load(self.scene_path)
        except RuntimeError as e:  # YADE's own words ("unregistered class") name no file and no way on
            raise ValueError(f"{self.scene_path} cannot be loaded ({e}): it was saved by another build of YADE or "
                             "toppling; resume=0 starts afresh and discards it") from None
        if self.TAG not in O.tags.keys():
            raise ValueError(f"{self.scene_path} holds a scene without a run's state (saved by O.save, or by an "
                             "older toppling): it cannot be resumed; resume=0 starts afresh and discards it")
        return json.loads(O.tags[self.TAG])
