"""Replays every fuzz target's seeds and stored findings (tests/fuzz/regressions/<target>/) through
the same check the fuzzer applies: a finite result or a VistrackError, nothing else. A finding of
scripts/fuzz.sh becomes a regression test by copying its input into that folder."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "fuzz"))
import seeds
import targets

pytestmark = pytest.mark.sanitize  # the input-facing surface (scripts/sanitize.sh)


@pytest.mark.parametrize("name", sorted(targets.TARGETS))
def test_seeds_and_findings_pass_the_fuzz_check(name: str) -> None:
    target = targets.TARGETS[name]
    inputs = seeds.seed_inputs(name)
    assert inputs, f"no seed for {name}"
    for data in inputs:
        targets.check(target, data)


def test_stored_regressions_belong_to_a_target() -> None:
    stored = {folder.name for folder in seeds.REGRESSIONS.iterdir() if folder.is_dir()}
    assert stored <= set(targets.TARGETS), stored - set(targets.TARGETS)


def test_the_check_fails_on_nan_and_on_other_exceptions() -> None:
    """The oracle itself can fail: a NaN anywhere in a result, or an exception that is not a VistrackError."""
    with pytest.raises(targets.Finding):
        targets.require_finite({"a": [1.0, float("nan")]})

    def raises_key_error(data: bytes) -> None:
        raise KeyError("x")

    with pytest.raises(KeyError):
        targets.check(targets.Target("bad", raises_key_error, 16), b"")
