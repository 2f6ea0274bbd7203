"""What every file loader refuses alike: keys that are numbers, and numbers too long for Python,
each named in a VistrackError rather than a TypeError, ValueError or OverflowError."""

from __future__ import annotations

from pathlib import Path

import pytest

import vistrack as vt
from support.refusal import refuses

pytestmark = pytest.mark.sanitize


def test_yaml_keys_that_are_numbers_name_the_key(tmp_path: Path) -> None:
    """Found by the fuzzer (tests/fuzz/regressions/intercept/fuzz-integer-key.yaml): a YAML key
    such as ``0:`` raised TypeError while sorting the unknown keys."""
    from vistrack.follow_scenario import FollowScenario
    from vistrack.intercept import InterceptProblem

    path = tmp_path / "keys.yaml"
    path.write_text("0: w\nradius: 1.0\n")
    refuses(lambda: InterceptProblem.load(path, {}), "config.0")
    refuses(lambda: FollowScenario.load(path), "0 = 'w'", "unknown key")
    # The same in every loader that lists unknown keys (tests/fuzz/regressions/loiter/number-key.yaml).
    from vistrack.io import read_loiter_scenario
    from vistrack.scenario import Scenario
    from vistrack.sweep.spec import SweepSpec

    refuses(lambda: read_loiter_scenario(path), "0 = 'w'", "unknown key")
    refuses(lambda: Scenario.load(path), "0 = 'w'", "unknown section")
    refuses(lambda: SweepSpec.load(path), "0 = 'w'", "unknown key")
    loiter_sweep = tmp_path / "sweep.yaml"
    loiter_sweep.write_text("kind: loiter\nbase: {aois: [[300, 300]], 1: 2}\nparameters: {speed: [10, 12]}\n")
    refuses(lambda: SweepSpec.load(loiter_sweep), "1 = 2", "unknown key")


def test_numbers_too_long_for_python_are_refused(tmp_path: Path) -> None:
    """Found in review: Python reads at most 4300-digit integers and float() overflows past 1e308;
    both escaped as ValueError/OverflowError from the YAML and JSON loaders."""
    from vistrack import schema
    from vistrack.io import read_plan
    from vistrack.scenario import Scenario

    digits = "1" * 5000
    scenario = tmp_path / "long.yaml"
    scenario.write_text(f"poi: {{speed: {digits}}}\n")
    refuses(lambda: Scenario.load(scenario), "not valid YAML", "too long")
    plan = tmp_path / "long.json"
    plan.write_text(f'{{"format": {digits}}}')
    refuses(lambda: read_plan(plan), "not JSON", "too long")
    mission = tmp_path / "long.plan"
    mission.write_text(f'{{"fileType": {digits}}}')
    refuses(lambda: vt.mission.load(mission), "too long")
    refuses(lambda: schema.number("poi.speed", 10**400), "poi.speed = 'an integer of 401 digits'", "finite")
