"""--export and --origin on `vistrack orbits` and `vistrack run`: the files pymavlink and
QGroundControl's format expect, GeoJSON in WGS84, and one-line errors."""

from __future__ import annotations

import json

import numpy as np
import pytest

import vistrack as vt
from support.paths import DEMO_SCENARIO, REPO
from vistrack.cli import main
from vistrack.mission import Command, Georeference

CHARLOTTE = Georeference(35.2249, -80.8403)


def test_orbits_export_plan_waypoints_geojson(charlotte, tmp_path, capsys) -> None:
    mavwp = pytest.importorskip("pymavlink.mavwp")
    files = [tmp_path / "route.plan", tmp_path / "route.waypoints", tmp_path / "route.geojson"]
    args = ["orbits", "--map", str(charlotte / "buildings.geojson"),
            "--path", str(charlotte / "paths" / "paper_slow.csv"),
            "--out", str(tmp_path / "out"), "--quiet", "--origin", "35.2249,-80.8403", "--direction", "cw"]
    for file in files:
        args += ["--export", str(file)]
    assert main(args) == 0
    printed = capsys.readouterr().out
    assert "timed loiters" in printed and "companion computer" in printed
    plan = vt.OrbitPlan.from_json((tmp_path / "out" / "plan.json").read_text())
    loader = mavwp.MAVWPLoader()
    count = loader.load(str(files[1]))
    mission = vt.mission.load(files[0])
    assert count == len(mission) + 1
    loiters = [loader.wp(i) for i in range(count) if loader.wp(i).command == Command.NAV_LOITER_TIME]
    assert len(loiters) >= len(plan.times) - 2 and all(w.param3 > 0 for w in loiters)  # clockwise
    assert all(w.z == 300.0 for w in loiters)  # the UAV's default altitude, relative to home
    assert sum(w.param1 for w in loiters) == pytest.approx(plan.times[-1], abs=0.5)
    # The first loiter circles the POI near the path's start (paper_slow starts at (-150, -45)).
    east, north = CHARLOTTE.to_local(loiters[0].x, loiters[0].y)
    assert np.hypot(east + 150.0, north + 45.0) < 30.0
    data = json.loads(files[2].read_text())
    assert data["origin"] == [35.2249, -80.8403, 0.0]
    kinds = {f["properties"]["kind"] for f in data["features"]}
    assert kinds == {"poi_path", "orbit_center", "home", "route"}
    path = next(f for f in data["features"] if f["properties"]["kind"] == "poi_path")["geometry"]["coordinates"]
    np.testing.assert_allclose(CHARLOTTE.to_local(path[0][1], path[0][0]), (-150.0, -45.0), atol=1e-6)


def test_run_export_with_the_scenario_origin(tmp_path, capsys) -> None:
    scenario = tmp_path / "demo.yaml"
    text = (DEMO_SCENARIO).read_text()
    scenario.write_text("origin: [35.2249, -80.8403, 230]\n" + text)
    out = tmp_path / "report"
    assert main(["run", str(scenario), "--out", str(out), "--quiet", "--export", str(tmp_path / "r.txt"),
                 "--export", str(tmp_path / "r.geojson")]) == 0
    metrics = json.loads((out / "metrics.json").read_text())
    assert metrics["origin"] == [35.2249, -80.8403, 230.0]
    mission = vt.mission.load(tmp_path / "r.txt")
    assert mission.home == (35.2249, -80.8403, 230.0) and mission.cruise_speed == 20.0  # the demo UAV
    data = json.loads((tmp_path / "r.geojson").read_text())
    trajectory = next(f for f in data["features"] if f["properties"]["kind"] == "trajectory")
    assert trajectory["properties"]["visibility_fraction"] == metrics["simulation"]["visibility_fraction"]
    assert len(trajectory["geometry"]["coordinates"]) > 100


def test_export_errors_are_one_line(tmp_path, capsys) -> None:
    args = ["run", str(DEMO_SCENARIO), "--out", str(tmp_path / "o"),
            "--quiet", "--export", str(tmp_path / "r.plan")]
    assert main(args) == 2
    assert "--export = " in capsys.readouterr().err and not (tmp_path / "r.plan").exists()
    assert main([*args[:-1], str(tmp_path / "r.kml"), "--origin", "35,-80"]) == 2
    assert "--export = " in capsys.readouterr().err
    assert main(["run", "x.yaml", "--origin", "95,0"]) == 2  # argparse's usage error
    assert "--origin[0] = 95.0: must be in [-90, 90] degrees" in capsys.readouterr().err


def test_lonlat_map_example(charlotte, tmp_path, capsys) -> None:
    import runpy

    runpy.run_path(str(REPO / "examples" / "lonlat_map.py"))["main"](tmp_path)
    printed = capsys.readouterr().out
    assert "167 buildings" in printed and "origin = (35.22" in printed
    assert vt.mission.load(tmp_path / "route.waypoints").items == vt.mission.load(tmp_path / "route.plan").items


def test_export_mission_helper_for_planners(tmp_path, capsys) -> None:
    """What `vistrack loiter|waypoints|follow --export` call: a to_mission built with --origin."""
    from vistrack.commands import export_mission
    from vistrack.mission import MissionBuilder

    def build(ref: Georeference) -> vt.mission.Mission:
        return MissionBuilder(ref, 60.0, speed=12.0).waypoints([[0, 0], [100, 50]]).return_to_launch().build()

    export_mission([str(tmp_path / "r.plan"), str(tmp_path / "r.waypoints")], build, CHARLOTTE)
    assert capsys.readouterr().out.count("4 mission items") == 2
    assert vt.mission.load(tmp_path / "r.plan").items == vt.mission.load(tmp_path / "r.waypoints").items
    export_mission([], build, None)  # nothing asked, nothing needed
    with pytest.raises(vt.VistrackError, match=r"--export = .*needs a georeference"):
        export_mission([str(tmp_path / "x.plan")], build, None)
