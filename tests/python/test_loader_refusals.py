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
    refuses(lambda: read_plan(plan), "not valid JSON", "too long")
    mission = tmp_path / "long.plan"
    mission.write_text(f'{{"fileType": {digits}}}')
    refuses(lambda: vt.mission.load(mission), "too long")
    refuses(lambda: schema.number("poi.speed", 10**400), "poi.speed = 'an integer of 401 digits'", "finite")


def test_symlink_loops_in_a_scenario_name_the_key(tmp_path: Path) -> None:
    """Issue 29: a symlink loop as any path inside a scenario was ``RuntimeError: Symlink loop``
    (from Path.resolve); now the one resolver names the key."""
    from vistrack.scenario import Scenario

    loop = tmp_path / "loop.csv"
    loop.symlink_to(loop)
    scenario = tmp_path / "loop.yaml"
    scenario.write_text("city: {mesh: loop.csv}\n")
    refuses(lambda: Scenario.load(scenario), "city.mesh", "symlink loop")
    scenario.write_text("poi: {path: loop.csv}\n")
    refuses(lambda: Scenario.load(scenario), "poi.path", "symlink loop")
    refuses(lambda: Scenario.load(loop), "scenario", "symlink loop")


def test_a_tilde_naming_no_home_directory_names_the_key(tmp_path: Path) -> None:
    """Found by CI's fuzzer: ``~name/...`` for a user this machine does not have was Path.expanduser's
    ``RuntimeError: Could not determine home directory``; now the one resolver names the key."""
    from vistrack.scenario import Scenario

    scenario = tmp_path / "tilde.yaml"
    scenario.write_text('city: {mesh: "~no_such_user_vistrack/city.obj"}\n')
    refuses(lambda: Scenario.load(scenario), "city.mesh", "no home directory")


def test_waypoints_of_two_lengths_name_the_point(tmp_path: Path) -> None:
    """Found by the fuzzer (seed 3): poi.waypoints mixing [x, y] and [x, y, z] loaded, then numpy's
    ValueError (an inhomogeneous array) escaped where the path was built; now the loader names it."""
    from vistrack.scenario import Scenario

    scenario = tmp_path / "mixed.yaml"
    scenario.write_text("poi: {waypoints: [[-290, -210], [-100, -210, 50]]}\n")
    refuses(lambda: Scenario.load(scenario), "poi.waypoints[1]", "must have 2 coordinates, as poi.waypoints[0]")
    scenario.write_text("poi: {waypoints: [[-290, -210, 0], [-100, -210, 50], [0, 0]]}\n")
    refuses(lambda: Scenario.load(scenario), "poi.waypoints[2]", "must have 3 coordinates")


def test_numeric_tables_refuse_values_that_are_not_finite(tmp_path: Path) -> None:
    """Found by the fuzzer (seed 8): a vehicle track's "1E5160" read as inf (and "nan" as NaN) and
    came back from the reader; every numeric table now names the line."""
    from vistrack.follow.files import read_road_path, read_vehicle_track

    track = tmp_path / "track.csv"
    for bad in ("1E5160", "nan", "-inf"):
        track.write_text(f"t,x,y\n0,0,0\n10,{bad},5\n")
        refuses(lambda: read_vehicle_track(track), "vehicle.track", "line 3", "not a finite number", bad)
        refuses(lambda: read_road_path(track), "road", "line 3")
    track.write_text("t,x,y\n0,0,0\n10,100,5\n")
    times, positions = read_vehicle_track(track)
    assert times.tolist() == [0.0, 10.0] and positions.tolist() == [[0.0, 0.0], [100.0, 5.0]]


def test_a_plan_whose_firmware_type_is_not_a_number_names_the_key(tmp_path: Path) -> None:
    """Found by the fuzzer (seed 9): a .plan with a list as mission.firmwareType was a TypeError
    (unhashable type) where the firmware was looked up."""
    plan = tmp_path / "bad.plan"
    for code in ("[3]", "true", "\"3\""):
        plan.write_text('{"fileType": "Plan", "version": 1, "mission": {"version": 2, "firmwareType": '
                        + code + ', "items": []}}')
        refuses(lambda: vt.mission.load(plan), "mission.firmwareType", "must be 3 (ArduPilot) or 12 (PX4)")


def test_input_files_must_be_regular_files(tmp_path: Path) -> None:
    """Issue 29: a FIFO blocked every reader forever and /dev/zero was read until memory ran out;
    every reader now refuses what is not a regular file before opening it, and files above
    MAX_INPUT_BYTES (1 GiB) unread."""
    import os

    from vistrack.io import read_route
    from vistrack.io.text import MAX_INPUT_BYTES, read_text

    assert MAX_INPUT_BYTES == vt._core.limits.MAX_INPUT_BYTES == 2**30
    fifo = tmp_path / "route.fifo"
    os.mkfifo(fifo)
    refuses(lambda: read_route(fifo, "route"), "route = ", "route.fifo", "a FIFO")
    refuses(lambda: vt.PoiPath.from_csv(str(fifo), 1.0), "path", "not a regular")
    refuses(lambda: read_route("/dev/zero", "route"), "/dev/zero", "a character device")
    refuses(lambda: vt.Environment.from_mesh("/dev/zero"), "/dev/zero", "not a regular")
    refuses(lambda: read_text(tmp_path, "scenario"), "is a folder")
    big = tmp_path / "big.csv"
    with big.open("wb") as stream:  # sparse: no disk used
        stream.truncate(MAX_INPUT_BYTES + 1)
    refuses(lambda: read_route(big, "route"), "big.csv", "above the limit")
    refuses(lambda: vt.PoiPath.from_csv(str(big), 1.0), "big.csv", "above the limit")


@pytest.mark.parametrize("special", ["fifo", "/dev/zero", "loop"])
def test_waypoints_refuses_special_route_files_promptly(special: str, tmp_path: Path,
                                                        capsys: pytest.CaptureFixture[str]) -> None:
    """Issue 29: ``vistrack waypoints FIFO`` hung and ``vistrack waypoints /dev/zero`` read until
    memory ran out; both, and a symlink loop, are now a one-line error with exit status 1."""
    import os
    import signal

    from support.cli import one_line_error

    route = tmp_path / "route.csv"
    if special == "fifo":
        os.mkfifo(route)
    elif special == "loop":
        route.symlink_to(route)
    else:
        route = Path(special)

    def hung(signum: int, frame: object) -> None:
        raise TimeoutError("vistrack waypoints blocked on the route file")

    previous = signal.signal(signal.SIGALRM, hung)
    signal.alarm(20)
    try:
        one_line_error(["waypoints", str(route), "--out", str(tmp_path / "out")], capsys, 1, "ROUTE = ", str(route))
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, previous)
