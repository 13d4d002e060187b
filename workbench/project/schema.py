"""`python -m workbench.project.schema`: write the published JSON Schema of the project file."""

from __future__ import annotations

import json
from pathlib import Path

from workbench.project.io import atomic_write_text, json_schema

TARGET = Path(__file__).resolve().parents[2] / "schema" / "project.schema.json"

if __name__ == "__main__":
    atomic_write_text(TARGET, json.dumps(json_schema(), indent=2) + "\n")
    print(f"wrote {TARGET}")
