"""Sweeps (vistrack.sweep, vistrack sweep): sweep files, road routes, the results table, and runs
on a LocalCluster and on a real `dask scheduler` with two `dask worker` processes that equal
running every case alone."""

from __future__ import annotations

import json
import math
import os
import socket
import subprocess
import sys
from pathlib import Path
from typing import Any

import numpy as np
import pytest
import yaml

import vistrack as vt
from support.build_tree import dask_preload_arguments
from support.paths import REPO, SHARED_DATA
from support.sweeps import assert_same_sweep, renamed_note, without_run_columns
from vistrack.cli import main
from vistrack.io import read_results_table, read_roads, read_route, write_results_table
from vistrack.sweep import SERIAL, SweepSpec
from vistrack.sweep.kinds import flatten

# A cheap tracking case on the demo city (about 1.5 s): a 385 m straight street, 2-degree VVs.
CHEAP_BASE: dict[str, Any] = {
    "name": "cheap",
    "city": {"demo": True},
    "poi": {"route": [[-290, -210], [95, -210]], "speed": 5.0},
    "uav": {"speed": 20.0, "min_turn_radius": 15.0, "altitude": 200.0},
    "sensor": {"d_max": 300.0},
    "planning": {"spacing": 20.0, "cutoff": 5.0e6, "resolution_deg": 2.0},
    "baselines": [60.0],
}
FOUR_CASES = {"name": "four", "base": CHEAP_BASE,
              "parameters": {"uav.altitude": [180.0, 220.0], "control.beta": [0.02, 0.03]}}


def alone(case: vt.sweep.Case) -> dict[str, Any]:
    """The row of one case run by itself: a fresh environment and planner, the pipeline's defaults
    (Figure 4's metric runs included), nothing shared with any other case."""
    result = vt.run(vt.Scenario.from_dict(case.data, base=case.folder))  # a fresh planner, Figure 4 runs too
    metrics = flatten({k: v for k, v in result.metrics.items() if k not in ("scenario", "timings_s")})
    del metrics["plan.volumes_computed"]
    return {"case": case.index, **case.parameters, **metrics}


# --- sweep files ------------------------------------------------------------------------------------


def test_values_ranges_and_draws() -> None:
    spec = SweepSpec.from_dict({"base": CHEAP_BASE, "seed": 7, "parameters": {
        "uav.altitude": {"start": 150, "stop": 250, "step": 50},
        "control.beta": {"start": 0.1, "stop": 0.3, "step": 0.1},  # 0.3 / 0.1 rounds below 3
        "sensor.d_max": {"start": 200.0, "stop": 300.0, "num": 3},
        "control.k_psi": {"random": "uniform", "low": 10.0, "high": 30.0, "count": 4},
        "uav.min_turn_radius": {"random": "integers", "low": 10, "high": 12, "count": 5},
        "control.direction": {"random": "choice", "values": ["ccw", "cw"], "count": 3},
    }})
    p = spec.parameters
    assert p["uav.altitude"] == [150, 200, 250] and all(isinstance(v, int) for v in p["uav.altitude"])
    assert p["control.beta"] == pytest.approx([0.1, 0.2, 0.3]) and len(p["control.beta"]) == 3
    assert p["sensor.d_max"] == [200.0, 250.0, 300.0]
    assert all(10.0 <= v <= 30.0 for v in p["control.k_psi"]) and len(set(p["control.k_psi"])) == 4
    assert set(p["uav.min_turn_radius"]) <= {10, 11, 12}
    assert set(p["control.direction"]) <= {"ccw", "cw"}
    assert spec.case_count == 3 * 3 * 3 * 4 * 5 * 3
    # Seeded: the same file gives the same draws; another seed gives others; a draw does not
    # depend on the parameters declared after it.
    again = SweepSpec.from_dict({"base": CHEAP_BASE, "seed": 7, "parameters": {
        "uav.altitude": [1], "control.beta": [1], "sensor.d_max": [1],
        "control.k_psi": {"random": "uniform", "low": 10.0, "high": 30.0, "count": 4}}})
    assert again.parameters["control.k_psi"] == p["control.k_psi"]
    other = SweepSpec.from_dict({"base": CHEAP_BASE, "seed": 8, "parameters": {
        "uav.altitude": [1], "control.beta": [1], "sensor.d_max": [1],
        "control.k_psi": {"random": "uniform", "low": 10.0, "high": 30.0, "count": 4}}})
    assert other.parameters["control.k_psi"] != p["control.k_psi"]


def test_grid_and_zip_cases() -> None:
    grid = SweepSpec.from_dict({"base": CHEAP_BASE, "seed": 3, "parameters": {
        "uav.altitude": [180, 220], "control.direction": ["ccw", "cw"], "baselines": [[], [40.0, 80.0]]}})
    cases = grid.cases()
    assert [c.index for c in cases] == list(range(8))
    assert [c.parameters["uav.altitude"] for c in cases] == [180] * 4 + [220] * 4  # last varies fastest
    assert [c.parameters["control.direction"] for c in cases[:4]] == ["ccw", "ccw", "cw", "cw"]
    assert cases[5].data["uav"]["altitude"] == 220 and cases[5].data["baselines"] == [40.0, 80.0]
    assert cases[5].data["control"]["direction"] == "ccw" and grid.base["uav"]["altitude"] == 200.0
    assert len({c.seed for c in cases}) == 8 and cases[5].seed == grid.cases()[5].seed
    zipped = SweepSpec.from_dict({"base": CHEAP_BASE, "combine": "zip", "parameters": {
        "uav.altitude": [180, 200, 220], "sensor.d_max": [250, 300, 350]}})
    assert [(c.data["uav"]["altitude"], c.data["sensor"]["d_max"]) for c in zipped.cases()] == [
        (180, 250), (200, 300), (220, 350)]
    # A source key replaces the section's other source (the base reads its map from "demo").
    mesh = SweepSpec.from_dict({"base": CHEAP_BASE, "parameters": {"city.mesh": ["a.obj"]}}, "/tmp")
    assert mesh.cases()[0].data["city"] == {"mesh": "a.obj"}


@pytest.mark.parametrize(("data", "message"), [
    ({"parameters": {"uav.altitude": [1]}}, "base = None: required"),
    ({"base": CHEAP_BASE, "kind": "juggling", "parameters": {"uav.altitude": [1]}}, "kind = 'juggling'"),
    ({"base": CHEAP_BASE, "parameters": {"uav.altitud": [1]}}, "did you mean uav.altitude"),
    ({"base": CHEAP_BASE, "parameters": {"uav.altitude": 200}}, "parameters.uav.altitude = 200"),
    ({"base": CHEAP_BASE, "parameters": {"uav.altitude": []}}, "at least one value"),
    ({"base": CHEAP_BASE, "parameters": {"uav.altitude": {"start": 1, "stop": 0, "step": 1}}},
     "parameters.uav.altitude.stop = 0"),
    ({"base": CHEAP_BASE, "parameters": {"uav.altitude": {"start": 1, "stop": 2, "step": 0}}},
     "parameters.uav.altitude.step = 0"),
    ({"base": CHEAP_BASE, "parameters": {"control.beta": {"random": "cauchy", "count": 2}}},
     "parameters.control.beta.random = 'cauchy'"),
    ({"base": CHEAP_BASE, "parameters": {"control.beta": {"random": {"count": 4}, "count": 2}}},
     "parameters.control.beta.random = {'count': 4}: must be one of"),
    ({"base": CHEAP_BASE, "parameters": {"control.beta": {"random": "uniform", "low": 1, "count": 2}}},
     "random: uniform takes exactly count, high, low, random"),
    ({"base": CHEAP_BASE, "combine": "zip", "parameters": {"uav.altitude": [1, 2], "control.beta": [1]}},
     "needs as many values"),
    ({"base": CHEAP_BASE, "combine": "outer", "parameters": {"uav.altitude": [1]}}, "combine = 'outer'"),
    ({"base": CHEAP_BASE}, "at least one parameter"),
    ({"base": CHEAP_BASE, "parameters": {"uav.altitude": [1]}, "metrics": ["plan.radius"]},
     "metrics = 'plan.radius': no such metric"),
    ({"base": CHEAP_BASE, "parameters": {"uav.altitude": [1]}, "colour": "red"}, "colour = 'red': unknown key"),
    ({"base": {**CHEAP_BASE, "uav": {"speed": -1}}, "parameters": {"uav.altitude": [1]}}, "base: uav.speed = -1"),
    ({"base": CHEAP_BASE, "routes": {"nodes": [0, 999]}}, "routes.nodes[1] = 999"),
    ({"base": CHEAP_BASE, "routes": {"nodes": [3, 3]}}, "at least two different nodes"),
    ({"base": CHEAP_BASE, "routes": {"nodes": [0, 1], "points": [[0, 0]]}}, "give one of nodes"),
])
def test_bad_sweep_files_name_the_key(data: dict[str, Any], message: str) -> None:
    with pytest.raises(vt.VistrackError) as error:
        SweepSpec.from_dict(data)
    assert message in str(error.value)


def test_examples_are_valid_sweep_files() -> None:
    examples = sorted((REPO / "examples").glob("sweep_*.yaml"))
    assert (REPO / "examples" / "sweep_small.yaml") in examples
    for path in examples:
        if "charlotte" in path.name and not SHARED_DATA.is_dir():
            continue
        spec = SweepSpec.load(path)
        assert spec.case_count >= 1 and spec.name == yaml.safe_load(path.read_text()).get("name", path.stem)


# --- road routes --------------------------------------------------------------------------------------


def check_route_follows_roads(roads: vt.RoadNetwork, points: list[list[float]], a: int, b: int) -> None:
    nodes = [roads.nearest_node(np.array(p)) for p in points]
    assert nodes[0] == a and nodes[-1] == b
    edges = {tuple(sorted(e)) for e in np.asarray(roads.edges).tolist()}
    assert all(tuple(sorted(pair)) in edges for pair in zip(nodes, nodes[1:]))
    assert np.allclose(np.asarray(roads.nodes)[nodes], points)


def test_routes_between_chosen_nodes_of_the_demo_streets() -> None:
    roads = vt.Environment.demo().roads
    spec = SweepSpec.from_dict({"base": CHEAP_BASE, "routes": {"nodes": [0, 8, 80]},
                                "parameters": {"uav.altitude": [180, 220]}})
    assert list(spec.parameters) == ["route", "uav.altitude"]
    assert spec.parameters["route"] == ["0-8", "0-80", "8-80"] and spec.case_count == 6
    for label, route in spec.routes.items():
        a, b = map(int, label.split("-"))
        check_route_follows_roads(roads, route.points, a, b)
        # The shortest route: no road path between the two nodes is shorter (Dijkstra oracle below).
        length = np.sum(np.hypot(*np.diff(np.asarray(route.points), axis=0).T))
        assert length == pytest.approx(dijkstra(roads, a, b))
    case = spec.cases()[3]  # route 0-80, altitude 220
    assert case.data["poi"]["waypoints"] == spec.routes["0-80"].points and "route" not in case.data["poi"]
    ordered = SweepSpec.from_dict({"base": CHEAP_BASE, "routes": {"nodes": [0, 8, 80], "ordered": True}})
    assert ordered.case_count == 6 and "80-0" in ordered.routes
    near = SweepSpec.from_dict({"base": CHEAP_BASE, "routes": {"points": [[-290, -210], [95, -210]]}})
    (label,) = near.routes
    a, b = map(int, label.split("-"))
    assert a == roads.nearest_node(np.array([-290.0, -210.0])) and b == roads.nearest_node(np.array([95.0, -210.0]))
    sample = {"base": CHEAP_BASE, "routes": {"nodes": "all", "sample": 5}, "seed": 4}
    assert SweepSpec.from_dict(sample).parameters == SweepSpec.from_dict(sample).parameters
    assert SweepSpec.from_dict(sample).case_count == 5


def dijkstra(roads: vt.RoadNetwork, a: int, b: int) -> float:
    import heapq

    xy = np.asarray(roads.nodes)
    neighbours: dict[int, list[int]] = {}
    for u, v in np.asarray(roads.edges).tolist():
        neighbours.setdefault(u, []).append(v)
        neighbours.setdefault(v, []).append(u)
    best = {a: 0.0}
    queue = [(0.0, a)]
    while queue:
        d, u = heapq.heappop(queue)
        if u == b:
            return d
        if d > best[u]:
            continue
        for v in neighbours.get(u, []):
            nd = d + float(np.hypot(*(xy[u] - xy[v])))
            if nd < best.get(v, math.inf):
                best[v] = nd
                heapq.heappush(queue, (nd, v))
    return math.inf


def test_road_file(tmp_path: Path) -> None:
    lines = {"type": "FeatureCollection", "features": [
        {"type": "Feature", "properties": {}, "geometry": {"type": "LineString",
                                                           "coordinates": [[0, 0], [100, 0], [200, 0]]}},
        # meets the first street at (100, 0) within 0.3 m: one junction node
        {"type": "Feature", "properties": {}, "geometry": {"type": "MultiLineString",
                                                           "coordinates": [[[100.3, 0], [100, 100]],
                                                                           [[100, 100], [0, 100]]]}},
    ]}
    path = tmp_path / "roads.geojson"
    path.write_text(json.dumps(lines))
    roads = read_roads(path)
    assert np.asarray(roads.nodes).tolist() == [[0, 0], [100, 0], [200, 0], [100, 100], [0, 100]]
    assert sorted(map(tuple, np.asarray(roads.edges).tolist())) == [(0, 1), (1, 2), (1, 3), (3, 4)]
    assert roads.shortest_route(0, 4) == [0, 1, 3, 4]
    spec = SweepSpec.from_dict({"base": CHEAP_BASE, "routes": {"roads": "roads.geojson", "nodes": [2, 4]}}, tmp_path)
    assert spec.routes["2-4"].points == [[200, 0], [100, 0], [100, 100], [0, 100]]
    bad = tmp_path / "bad.geojson"
    bad.write_text(json.dumps({"type": "FeatureCollection", "features": [
        {"type": "Feature", "geometry": {"type": "Point", "coordinates": [0, 0]}}]}))
    with pytest.raises(vt.VistrackError, match=r"routes.roads = .*bad.geojson: features\[0\] is 'Point'"):
        read_roads(bad)
    with pytest.raises(vt.VistrackError, match=r"routes.roads = .*missing.geojson"):
        SweepSpec.from_dict({"base": CHEAP_BASE, "routes": {"roads": "missing.geojson", "nodes": [0, 1]}}, tmp_path)
    # A disconnected network: the pair without a route is named.
    apart = tmp_path / "apart.geojson"
    apart.write_text(json.dumps({"type": "FeatureCollection", "features": [
        {"type": "Feature", "geometry": {"type": "LineString", "coordinates": [[0, 0], [1, 0]]}},
        {"type": "Feature", "geometry": {"type": "LineString", "coordinates": [[5, 5], [6, 5]]}}]}))
    with pytest.raises(vt.VistrackError, match="no road route from node 0 to node 2"):
        SweepSpec.from_dict({"base": CHEAP_BASE, "routes": {"roads": str(apart), "nodes": [0, 2]}})


# --- the results table ----------------------------------------------------------------------------------


def test_results_table_round_trips(tmp_path: Path) -> None:
    rows = [
        {"case": 0, "a": 0.1 + 0.2, "b": True, "c": "x", "d": [1, 2], "e": 3, "f": None},
        {"case": 1, "a": 1, "b": None, "c": None, "d": {"k": 1}, "e": 4, "f": None},
    ]
    columns = ["case", "a", "b", "c", "d", "e", "f"]
    write_results_table(rows, columns, tmp_path, metadata={"name": "t"})
    back = read_results_table(tmp_path / "results.parquet")
    assert back[0] == {"case": 0, "a": 0.1 + 0.2, "b": True, "c": "x", "d": "[1, 2]", "e": 3, "f": None}
    assert back[1] == {"case": 1, "a": 1.0, "b": None, "c": None, "d": '{"k": 1}', "e": 4, "f": None}
    import pyarrow.parquet as pq

    table = pq.read_table(tmp_path / "results.parquet")
    assert [str(t) for t in table.schema.types] == ["int64", "double", "bool", "string", "string", "int64", "string"]
    assert json.loads(table.schema.metadata[b"vistrack.sweep"]) == {"name": "t"}
    import csv

    with (tmp_path / "results.csv").open() as stream:
        written = list(csv.DictReader(stream))
    assert float(written[0]["a"]) == 0.1 + 0.2  # every digit
    assert written[1]["b"] == "" and written[0]["d"] == "[1, 2]"


# --- running -----------------------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def local_cluster_sweep(tmp_path_factory: pytest.TempPathFactory) -> vt.sweep.SweepResult:
    """The four-case sweep on a LocalCluster of two worker processes."""
    out = tmp_path_factory.mktemp("local")
    return vt.sweep.run(SweepSpec.from_dict(FOUR_CASES), scheduler=None, n_workers=2, out=out)


def test_local_cluster_equals_each_case_run_alone(local_cluster_sweep: vt.sweep.SweepResult) -> None:
    result = local_cluster_sweep
    cases = result.spec.cases()
    assert [row["case"] for row in result.rows] == [0, 1, 2, 3]
    assert all(row["run_status"] == "ok" for row in result.rows), result.failed
    assert without_run_columns(result.rows) == [alone(case) for case in cases]  # exactly, every metric
    # The cases differ (the parameters matter), and they ran on both workers.
    # (Not the visibility: the smooth locus keeps the POI in view in all four.)
    assert len({row["simulation.radial_error_after_max_abs_m"] for row in result.rows}) > 1
    assert len({row["run_worker"] for row in result.rows}) == 2
    # Files: the table read back equals the rows; one figure per varied parameter.
    names = {p.name for p in result.files}
    assert {"results.csv", "results.parquet", "sweep.json", "rows.jsonl", "uav.altitude.png",
            "control.beta.png"} <= names
    assert read_results_table(result.out / "results.parquet") == result.rows
    summary = json.loads((result.out / "sweep.json").read_text())
    assert summary["cases"] == 4 and summary["failed"] == 0
    assert len((result.out / "rows.jsonl").read_text().splitlines()) == 4


def test_environment_and_planner_built_once_per_worker(local_cluster_sweep: vt.sweep.SweepResult) -> None:
    workers = local_cluster_sweep.workers
    assert len(workers) == 2
    assert sum(w["cases_run"] for w in workers.values()) == 4
    for address, counts in workers.items():
        ran = sum(row["run_worker"] == address for row in local_cluster_sweep.rows)
        assert counts["cases_run"] == ran
        assert counts["environments_built"] == (1 if ran else 0), counts
        assert counts["planners_built"] == (1 if ran else 0), counts
    # The second case on a worker took its VVs from the worker's planner: the two altitudes share
    # the POI path, so a worker's later cases computed none.
    for address in workers:
        mine = [row for row in local_cluster_sweep.rows if row["run_worker"] == address]
        assert mine[0]["run_volumes_computed"] > 0
        assert all(row["run_volumes_computed"] == 0 for row in mine[1:])


def free_port() -> int:
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


@pytest.mark.cluster
def test_real_scheduler_and_two_workers_equal_the_local_cluster(
        local_cluster_sweep: vt.sweep.SweepResult, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    port = free_port()
    address = f"tcp://127.0.0.1:{port}"
    dask = [sys.executable, "-m", "dask"]
    logs = [(tmp_path / f"{name}.log").open("w") for name in ("scheduler", "worker-a", "worker-b")]
    processes = [subprocess.Popen(
        [*dask, "scheduler", "--host", "127.0.0.1", "--port", str(port), "--no-dashboard", *dask_preload_arguments()],
        stdout=logs[0], stderr=subprocess.STDOUT, env=os.environ)]
    try:
        for log in logs[1:]:
            processes.append(subprocess.Popen(
                [*dask, "worker", address, "--host", "127.0.0.1", "--nthreads", "1", "--nworkers", "1",
                 "--no-dashboard", "--name", Path(log.name).stem, *dask_preload_arguments()],
                stdout=log, stderr=subprocess.STDOUT, env=os.environ))
        from distributed import Client

        with Client(address, timeout="60s") as client:
            client.wait_for_workers(2, timeout=120)
        sweep_file = tmp_path / "four.yaml"
        sweep_file.write_text(yaml.safe_dump(FOUR_CASES, sort_keys=False))
        out = tmp_path / "out"
        assert main(["sweep", str(sweep_file), "--out", str(out), "--scheduler", address, "--quiet"]) == 0
    finally:
        for process in reversed(processes):
            process.terminate()
        for process in processes:
            try:
                process.wait(timeout=20)
            except subprocess.TimeoutExpired:
                process.kill()
        for log in logs:
            log.close()
    printed = capsys.readouterr().out
    assert "4 cases in" in printed and address in printed
    rows = read_results_table(out / "results.parquet")
    assert [row["run_error"] for row in rows] == [None] * 4
    assert without_run_columns(rows) == without_run_columns(local_cluster_sweep.rows)
    assert all(row["run_worker"].startswith("tcp://127.0.0.1:") for row in rows)
    summary = json.loads((out / "sweep.json").read_text())
    assert summary["scheduler"] == address and len(summary["workers"]) == 2
    assert all(w["environments_built"] <= 1 for w in summary["workers"].values())


def test_a_failing_case_is_one_row(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    sweep = {"name": "one-bad", "base": CHEAP_BASE,
             "parameters": {"sensor.d_max": [300.0, -5.0], "planning.resolution_deg": [3.0]},
             "metrics": ["simulation.visibility_fraction", "plan.*"]}
    path = tmp_path / "bad.yaml"
    path.write_text(yaml.safe_dump(sweep, sort_keys=False))
    assert main(["sweep", str(path), "--out", str(tmp_path / "out"), "--scheduler", SERIAL, "--quiet"]) == 0
    printed = capsys.readouterr().out
    assert "case 1 failed: sensor.d_max = -5:" in printed
    rows = read_results_table(tmp_path / "out" / "results.parquet")
    assert [row["run_status"] for row in rows] == ["ok", "failed"]
    good, bad = rows
    assert bad["sensor.d_max"] == -5.0 and "sensor.d_max = -5:" in bad["run_error"]
    assert bad["simulation.visibility_fraction"] is None and bad["plan.samples"] is None
    assert good["run_error"] is None and 0.0 < good["simulation.visibility_fraction"] <= 1.0
    kept = [c for c in rows[0] if not c.startswith("run_")]
    assert kept[:3] == ["case", "sensor.d_max", "planning.resolution_deg"]
    assert all(c == "simulation.visibility_fraction" or c.startswith("plan.") for c in kept[3:])
    # The failed case is drawn as a cross; the figure is written.
    assert (tmp_path / "out" / "figures" / "sensor.d_max.png").stat().st_size > 10_000


def test_declared_metric_names_match_a_run(local_cluster_sweep: vt.sweep.SweepResult) -> None:
    import fnmatch

    declared = vt.sweep.get_kind("tracking").metric_names
    produced = vt.sweep.metric_columns(local_cluster_sweep)
    assert all(any(fnmatch.fnmatchcase(m, d) for d in declared) for m in produced), produced
    assert all(any(fnmatch.fnmatchcase(m, d) for m in produced) for d in declared), declared


def test_route_sweep_equals_each_route_alone(tmp_path: Path) -> None:
    """Routes sharing streets: their VVs fall on the same road points up to rounding, and a VV a
    rounding error away must not leak from one case into another (one planner per path)."""
    base = {**CHEAP_BASE, "planning": {**CHEAP_BASE["planning"], "resolution_deg": 3.0}, "baselines": []}
    spec = SweepSpec.from_dict({"name": "routes", "base": base, "routes": {"nodes": [12, 54, 65]}})
    result = vt.sweep.run(spec, SERIAL, out=tmp_path, figures=False)
    assert result.column("route") == ["12-54", "12-65", "54-65"]
    assert without_run_columns(result.rows) == [alone(case) for case in spec.cases()]
    for row in result.rows:
        points = np.asarray(spec.routes[row["route"]].points)
        assert row["poi.length_m"] == pytest.approx(np.sum(np.hypot(*np.diff(points, axis=0).T)))
    assert result.workers["serial"]["environments_built"] <= 1
    assert result.workers["serial"]["planners_built"] == 3


# --- the waypoints kind (vt.waypoint_nav) ---------------------------------------------------------------


def test_waypoint_sweep_equals_fly(tmp_path: Path) -> None:
    route_file = REPO / "examples" / "waypoints_paper.csv"
    spec = SweepSpec.from_dict({"name": "wp", "kind": "waypoints",
                                "base": {"units": "paper", "route": str(route_file),
                                         "wind": {"east": 0.0, "north": 0.08}},
                                "parameters": {"method": ["dwn", "wn"], "uav.min_turn_radius": [0.7, -1.0]}})
    result = vt.sweep.run(spec, SERIAL, out=tmp_path, figures=False)
    assert [row["run_status"] for row in result.rows] == ["ok", "failed", "ok", "failed"]
    assert "uav.min_turn_radius = -1: must be" in result.rows[1]["run_error"]
    route = read_route(route_file)
    for row in (result.rows[0], result.rows[2]):
        flight = vt.waypoint_nav.fly(route, method=row["method"], wind=vt.flight.Wind(east=0.0, north=0.08))
        expected = {k: v for k, v in flight.metrics().items() if not isinstance(v, list)}
        assert {k: row[k] for k in expected} == expected
        assert row["route_length"] == pytest.approx(np.sum(np.hypot(*np.diff(route, axis=0).T)))
        assert row["path_ratio"] == pytest.approx(flight.path_length / row["route_length"])
    assert result.rows[0]["label"] == "DWN" and result.rows[2]["label"] == "WN R_WP=1R"


def test_waypoint_sweep_pairs_methods_on_seeded_random_routes(tmp_path: Path) -> None:
    spec = SweepSpec.from_dict({"kind": "waypoints", "seed": 5,
                                "base": {"units": "paper", "random_route": {"count": 4, "legs": [4, 8]},
                                         "wind": {"east": 0.1 * math.cos(math.radians(30.0)),
                                                  "north": 0.1 * math.sin(math.radians(30.0)), "gusts": {"seed": 11}}},
                                "parameters": {"random_route.seed": [1, 2], "method": ["dwn", "wn"]}})
    rows = vt.sweep.run(spec, SERIAL, out=tmp_path, figures=False).rows
    assert all(row["run_status"] == "ok" for row in rows), [row["run_error"] for row in rows]
    # The same route (and gusts) for both methods of a seed, another route for another seed.
    assert rows[0]["route_length"] == rows[1]["route_length"] != rows[2]["route_length"] == rows[3]["route_length"]
    route = vt.waypoint_nav.random_route(np.random.default_rng(2), 4, 0.7, (4.0, 8.0))
    wind = vt.flight.Wind(east=0.1 * math.cos(math.radians(30.0)), north=0.1 * math.sin(math.radians(30.0)),
                          gusts=vt.waypoint_nav.paper_gusts(11))
    assert rows[3]["max_miss_over_R"] == vt.waypoint_nav.fly(route, method="wn", wind=wind).metrics()["max_miss_over_R"]
    # Without a route seed, every case draws its own route from its own seed: reproducibly.
    own = SweepSpec.from_dict({"kind": "waypoints", "seed": 5, "base": {"units": "paper", "random_route": {"count": 4}},
                               "parameters": {"method": ["dwn", "wn"]}})
    first = vt.sweep.run_cases(own.cases(), SERIAL)
    assert first[0]["route_length"] != first[1]["route_length"]
    assert without_run_columns(first) == without_run_columns(vt.sweep.run_cases(own.cases(), SERIAL))


def test_waypoint_gusts_take_the_paper_model_and_the_case_seed() -> None:
    """A gusts block given in part: the paper's gust model for the rest, the case's seed without one."""
    route = [[0.0, 0.0], [5.0, 0.0], [5.0, 5.0]]
    spec = SweepSpec.from_dict({"kind": "waypoints", "base": {"units": "paper", "waypoints": route},
                                "parameters": {"wind.gusts": [{}, {"seed": 3, "intensity": 0.01}]}})
    cases = spec.cases()
    rows = vt.sweep.run_cases(cases, SERIAL)
    paper = vt.waypoint_nav.paper_gusts(cases[0].seed)
    mine = vt.flight.Gusts(seed=3, intensity=0.01, length_scale=paper.length_scale)
    for row, gusts in zip(rows, (paper, mine)):
        expected = vt.waypoint_nav.fly(route, wind=vt.flight.Wind(gusts=gusts)).metrics()
        assert (row["max_miss_over_R"], row["duration"]) == (expected["max_miss_over_R"], expected["duration"])
    assert rows[0]["duration"] != rows[1]["duration"]


POLAR_NOTE = renamed_note("wind.speed, wind.direction_deg", "wind.east, wind.north")
OLD_WAYPOINT_NOTES = {renamed_note("turn_radius", "uav.min_turn_radius"), renamed_note("speed", "uav.speed"),
                      POLAR_NOTE, renamed_note("wind.gusts: SEED", "wind.gusts: {seed: SEED}"),
                      renamed_note("wind.gusts: true", "wind.gusts: {}")}


def test_old_waypoint_sweep_spellings(capsys: pytest.CaptureFixture[str]) -> None:
    """Before the one schema: the vehicle at the top level, the wind by speed and direction, gusts as
    true or a seed. They still load, one line on stdout each, into the cases the new spelling gives."""
    route = str(REPO / "examples" / "waypoints_paper.csv")
    old = {"kind": "waypoints", "seed": 3,
           "base": {"units": "paper", "route": route, "turn_radius": 0.6, "speed": 0.9,
                    "wind": {"speed": 0.05, "direction_deg": 0.0, "gusts": 7}},
           "parameters": {"turn_radius": [0.6, 0.65], "wind": [{"speed": 0.0, "gusts": False},
                                                               {"speed": 0.05, "direction_deg": 180.0, "gusts": True}],
                          "wind.gusts": [7, True]}}
    spec = SweepSpec.from_dict(old)
    assert set(capsys.readouterr().out.splitlines()) == OLD_WAYPOINT_NOTES
    west = {"east": 0.05 * math.cos(math.pi), "north": 0.05 * math.sin(math.pi)}
    new = {"kind": "waypoints", "seed": 3,
           "base": {"units": "paper", "route": route, "uav": {"min_turn_radius": 0.6, "speed": 0.9},
                    "wind": {"east": 0.05, "north": 0.0, "gusts": {"seed": 7}}},
           "parameters": {"uav.min_turn_radius": [0.6, 0.65],
                          "wind": [{"east": 0.0, "north": 0.0, "gusts": False}, {**west, "gusts": {}}],
                          "wind.gusts": [{"seed": 7}, {}]}}
    again = SweepSpec.from_dict(new)
    assert capsys.readouterr().out == ""
    assert_same_sweep(spec, again)
    # The old polar keys varied one at a time: the case's wind becomes components when it runs.
    polar = SweepSpec.from_dict({"kind": "waypoints", "base": {"units": "paper", "route": route},
                                 "parameters": {"wind.speed": [0.05], "wind.direction_deg": [180.0]}})
    assert capsys.readouterr().out.splitlines() == [POLAR_NOTE] * 2
    case = polar.cases()[0]
    flown = vt.sweep.run_cases([case], SERIAL)[0]
    wind = vt.flight.Wind(**west)
    expected = vt.waypoint_nav.fly(read_route(Path(route)), wind=wind).metrics()
    assert flown["max_miss_over_R"] == expected["max_miss_over_R"] and flown["duration"] == expected["duration"]
    with pytest.raises(vt.VistrackError, match=r"parameters\.uav\.speed = .*given twice"):
        SweepSpec.from_dict({"kind": "waypoints", "base": {"units": "paper", "route": route},
                             "parameters": {"speed": [0.8], "uav.speed": [0.9]}})


@pytest.mark.parametrize(("base", "message"), [
    ({"waypoints": [[0, 0], [1, 0]], "route": "x.csv"}, "give exactly one of route"),
    ({"waypoints": [[0, 0], [1, 0]], "colour": 1}, "colour = 1: unknown key"),
    ({"waypoints": [[0, 0], [1, 0]], "method": "fast"}, "method = 'fast'"),
    ({"waypoints": [[0, 0], [1, 0]], "wind": {"gale": 3}}, "wind.gale = 3: unknown key"),
    ({"waypoints": [[0, 0], [1, 0]], "uav": {"speed": 0}}, "uav.speed = 0: must be"),
    ({"waypoints": [[0, 0], [1, 0]], "wind": {"gusts": {"seed": -1}}}, "wind.gusts.seed = -1"),
    ({"waypoints": [[0, 0], [1, 0]], "wind": {"speed": 1, "east": 1}}, "not both"),
    ({"route": "missing.csv"}, "route = "),
])
def test_bad_waypoint_bases_name_the_key(base: dict[str, Any], message: str) -> None:
    with pytest.raises(vt.VistrackError) as error:
        SweepSpec.from_dict({"kind": "waypoints", "base": base, "parameters": {"uav.speed": [0.8]}})
    assert message in str(error.value)


def test_a_registered_kind_runs_through_the_sweep(tmp_path: Path) -> None:
    """What another planner does to join: register a kind; its numpy metrics become plain values."""
    from vistrack.sweep import CaseKind, CaseOutput, register_kind
    from vistrack.sweep.kinds import KINDS, dotted_keys

    def run(data: dict[str, Any], context: vt.sweep.CaseContext) -> CaseOutput:
        if data["x"] < 0:
            raise ValueError(f"x = {data['x']}: must be >= 0")
        draw = np.random.default_rng(context.seed).uniform()
        return CaseOutput({"square": np.float64(data["x"]) ** 2, "even": np.bool_(data["x"] % 2 == 0),
                           "draw": draw}, {"note": np.int64(3)})

    register_kind(CaseKind(name="toy", description="x squared", load_base=lambda value, folder: dict(value),
                           keys=dotted_keys, run=run, metric_names=("square", "even", "draw"),
                           figure_metrics=("square",)))
    try:
        spec = SweepSpec.from_dict({"kind": "toy", "base": {"x": 0}, "parameters": {"x": [2, -1, 3]}, "seed": 9})
        result = vt.sweep.run(spec, SERIAL, out=tmp_path)
    finally:
        del KINDS["toy"]
    rows = read_results_table(tmp_path / "results.parquet")
    assert [(r["x"], r["square"], r["even"], r["run_status"]) for r in rows] == [
        (2, 4.0, True, "ok"), (-1, None, None, "failed"), (3, 9.0, False, "ok")]
    assert rows[1]["run_error"].startswith("ValueError: x = -1: must be >= 0")
    assert rows[0]["run_note"] == 3 and type(result.rows[0]["square"]) is float
    assert rows[2]["draw"] == np.random.default_rng(spec.cases()[2].seed).uniform()
    assert (tmp_path / "figures" / "x.png").is_file()


@pytest.mark.sanitize
def test_non_finite_metrics_are_empty_with_a_note(tmp_path: Path) -> None:
    """Issue 29: a NaN or infinite metric went into results.csv as nan/inf and into sweep.json and
    rows.jsonl as bare NaN/Infinity (not JSON); now the cell is empty and run_not_finite says why."""
    from vistrack.sweep import CaseKind, CaseOutput, register_kind
    from vistrack.sweep.kinds import KINDS, dotted_keys

    def run(data: dict[str, Any], context: vt.sweep.CaseContext) -> CaseOutput:
        bad = {0: 2.0, 1: float("nan"), 2: math.inf}[data["x"]]
        return CaseOutput({"value": np.float64(bad) if data["x"] else 1.0, "pair": [1.0, bad]}, {"score": bad})

    register_kind(CaseKind(name="nan_toy", description="NaN", load_base=lambda value, folder: dict(value),
                           keys=dotted_keys, run=run, metric_names=("value", "pair"), figure_metrics=("value",)))
    try:
        spec = SweepSpec.from_dict({"kind": "nan_toy", "base": {"x": 0}, "parameters": {"x": [0, 1, 2]}})
        vt.sweep.run(spec, SERIAL, out=tmp_path)
    finally:
        del KINDS["nan_toy"]

    def strict(text: str) -> Any:
        return json.loads(text, parse_constant=lambda name: pytest.fail(f"{name} in a results file"))

    lines = (tmp_path / "rows.jsonl").read_text().splitlines()
    rows = sorted((strict(line) for line in lines), key=lambda r: r["case"])
    strict((tmp_path / "sweep.json").read_text())
    assert [r["value"] for r in rows] == [1.0, None, None]
    assert rows[1]["pair"] == [1.0, None] and rows[1]["run_score"] is None
    assert rows[1]["run_not_finite"] == "NaN or infinity, written empty: value, pair, run_score"
    assert "run_not_finite" not in rows[0]
    import csv

    with (tmp_path / "results.csv").open(newline="") as stream:
        cells = [cell.lower() for line in csv.reader(stream) for cell in line]
    assert not {"nan", "inf", "-inf", "infinity"} & set(cells)
    assert not any("nan" in c or "inf" in c for c in cells if c.startswith("["))
    table = read_results_table(tmp_path / "results.parquet")
    assert [r["value"] for r in table] == [1.0, None, None]
    assert all(r["run_status"] == "ok" for r in table)
