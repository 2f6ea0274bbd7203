"""Where the repository's files are, for the tests and the scripts that reuse them."""

from __future__ import annotations

from pathlib import Path

REPO = Path(__file__).resolve().parents[3]
EXAMPLES = REPO / "examples"
DEMO_SCENARIO = REPO / "python" / "vistrack" / "scenarios" / "demo.yaml"
