"""Work estimated in bytes before it starts (issue 29): a finer VV grid, a batch of VVs, a loiter
coverage matrix, a sweep's cases and its routes are refused (or built lazily) before memory runs
out, with messages naming the knob of the command at hand; "out of memory" names each command's
own knobs."""

from __future__ import annotations

import itertools
import json
import tracemalloc
from pathlib import Path

import numpy as np
import pytest

import vistrack as vt
from support.cli import one_line_error
from support.refusal import refuses
from vistrack.cli import COMMANDS
from vistrack.commands.memory import KNOBS, out_of_memory
from vistrack.sweep import SweepSpec
from vistrack.sweep.spec import _pair

pytestmark = pytest.mark.sanitize

LIMIT = vt._core.limits.MAX_WORK_BYTES
PATH = vt.PoiPath(np.array([[0.0, 0.0], [1000.0, 0.0]]), 5.0)


def test_a_finer_vv_grid_is_refused_by_its_bytes() -> None:
    # resolution_deg 0.1 passed the count check (51 VVs) and then ran out: 474.3 MB each.
    work = vt.check_work(PATH, vt.Planning())
    assert work.initial_volumes == 51 and work.initial_bytes < LIMIT
    refuses(lambda: vt.check_work(PATH, vt.Planning(resolution_deg=0.1)), "planning.resolution_deg = 0.1",
            "51 VVs", "474.3 MB each", "24.19 GB", "a coarser resolution_deg")
    far = vt.PoiPath(np.array([[0.0, 0.0], [9e6, 0.0]]), 5.0)
    refuses(lambda: vt.check_work(far, vt.Planning(max_volumes=10**9)), "planning.spacing = 20",
            "a larger planning.spacing")


def test_a_batch_of_vvs_is_refused_by_its_bytes() -> None:
    scene = vt.VisibilityScene(vt.Environment.demo())
    pois = np.tile([[0.0, -300.0, 1.0]], (100_000, 1))
    refuses(lambda: vt.visibility_volumes(scene, pois, 400.0), "pois = 100000 points", "543.5 GB",
            "batches of 367 fit")


def test_a_dense_coverage_matrix_is_refused_naming_dt() -> None:
    # 10,000 AOIs (the documented maximum) over 40,000 steps: a 3.2 GB matrix.
    side = np.arange(100) * 200.0
    aois = np.array([(x, y) for x in side for y in side])
    poses = np.column_stack([np.linspace(0.0, 1e4, 40_000), np.zeros(40_000), np.zeros(40_000)])
    refuses(lambda: vt.loiter.coverage(poses, aois, turn_rates=np.zeros(40_000)), "dt = 1:", "40000 steps x 10000 AOIs",
            "3.201 GB", "raise dt (2 s fits)")


def test_loiter_study_of_2000_aois_names_dt(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    grid = [[300.0 + 200.0 * (i % 45), 300.0 + 200.0 * (i // 45)] for i in range(2000)]
    scenario = tmp_path / "grid.yaml"
    scenario.write_text(json.dumps({"name": "grid", "aois": grid}))
    err = one_line_error(["loiter", str(scenario), "--out", str(tmp_path / "out")], capsys, 1,
                         "dt = 1:", "6 coverage matrices", "2000 AOIs", "GB", "s fits")  # 5 methods + a copy
    assert "out of memory" not in err and "planning.spacing" not in err


def test_out_of_memory_names_each_commands_knobs() -> None:
    assert set(KNOBS) == set(COMMANDS)
    for command in ("loiter", "follow", "sweep", "intercept", "waypoints"):
        assert "planning.spacing" not in out_of_memory(command)
    assert "dt" in out_of_memory("loiter") and "planning.spacing" in out_of_memory("run")


def test_a_million_cases_are_built_one_at_a_time() -> None:
    spec = SweepSpec.from_dict({"kind": "loiter", "base": {"aois": [[300, 300], [600, 500]]},
                                "parameters": {"dt": {"start": 1, "stop": 1_000_000, "step": 1}}})
    tracemalloc.start()
    cases = spec.cases()
    last = cases[len(cases) - 1]
    _, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    assert len(cases) == 1_000_000 and last.parameters == {"dt": 1_000_000} and last.data["dt"] == 1_000_000
    assert peak < 10e6  # a deep copy of the base per case held 10^6 copies
    first = next(iter(cases))
    assert first == cases[0] and first.data is not cases[0].data  # each case its own copy


def test_grid_and_zip_cases_in_index_order() -> None:
    spec = SweepSpec.from_dict({"kind": "loiter", "base": {"aois": [[300, 300], [600, 500]]},
                                "parameters": {"dt": [1, 2, 3], "threshold": [0.5, 0.75]}})
    expected = list(itertools.product([1, 2, 3], [0.5, 0.75]))
    cases = spec.cases()
    assert [(c.parameters["dt"], c.parameters["threshold"]) for c in cases] == expected
    assert [(cases[i].parameters["dt"], cases[i].parameters["threshold"]) for i in range(6)] == expected
    assert [c.index for c in cases[1:4]] == [1, 2, 3]


def _grid_roads(tmp_path: Path, side: int) -> Path:
    def street(a: list[float], b: list[float]) -> dict[str, object]:
        return {"type": "Feature", "geometry": {"type": "LineString", "coordinates": [a, b]}}

    features = []
    for i in range(side * side):
        x, y = 100.0 * (i % side), 100.0 * (i // side)
        if i % side < side - 1:
            features.append(street([x, y], [x + 100, y]))
        if i // side < side - 1:
            features.append(street([x, y], [x, y + 100]))
    path = tmp_path / "roads.geojson"
    path.write_text(json.dumps({"type": "FeatureCollection", "features": features}))
    return path


def test_all_routes_of_2500_nodes_are_counted_before_any_is_computed(tmp_path: Path) -> None:
    roads = _grid_roads(tmp_path, 50)
    base = {"city": {"demo": True}, "poi": {"route": [[-290, -210], [95, -210]]}}
    refuses(lambda: SweepSpec.from_dict({"base": base, "routes": {"roads": str(roads), "nodes": "all"}}),
            "routes.nodes = 'all'", "3123750 routes", "more than 1000000", "routes.sample")
    sampled = SweepSpec.from_dict({"base": base, "routes": {"roads": str(roads), "nodes": "all", "sample": 4},
                                   "parameters": {"uav.altitude": [150.0, 200.0]}})
    assert sampled.case_count == 8 and len(sampled.routes) == 4


@pytest.mark.parametrize("ordered", [False, True])
def test_route_pairs_by_index_match_itertools(ordered: bool) -> None:
    nodes = [7, 3, 11, 5, 2]
    listed = list(itertools.permutations(nodes, 2) if ordered else itertools.combinations(nodes, 2))
    assert [_pair(nodes, i, ordered) for i in range(len(listed))] == listed
