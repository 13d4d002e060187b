"""The seed 000 part's spec (projects/parts/seed_part.json) in SI, shared by the part and press tests."""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path

from workbench.project import PartSpec

SEED = Path(__file__).resolve().parents[1] / "projects" / "parts" / "seed_part.json"


def seed_spec() -> dict:
    """The seed part converted from mm/deg (file) to SI (model), as the service does it."""
    return dataclasses.asdict(PartSpec.model_validate(json.loads(SEED.read_text())).to_si())
