"""Results as JSON text."""
from __future__ import annotations

import json
import math
from typing import Any


def json_text(result: Any) -> str:
    """``result`` as indented JSON; JSON has no infinity, so a force no support can give (inf) is null."""
    return json.dumps(_finite(result), indent=1)


def _finite(value: Any) -> Any:
    if isinstance(value, float) and not math.isfinite(value):
        return None
    if isinstance(value, dict):
        return {k: _finite(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_finite(v) for v in value]
    return value
