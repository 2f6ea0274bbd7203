"""Where the repository's files are, for the tests and the scripts that reuse them."""

from __future__ import annotations

import os
from pathlib import Path

REPO = Path(__file__).resolve().parents[3]
EXAMPLES = REPO / "examples"
DEMO_SCENARIO = REPO / "python" / "vistrack" / "scenarios" / "demo.yaml"
# The real data (Charlotte, the campus): ../shared/data beside the repository unless VISTRACK_DATA names it.
SHARED_DATA = Path(os.environ.get("VISTRACK_DATA", REPO.parent / "shared" / "data"))
