"""Long loiter plans (issue 29): ``turns: 1000`` (the documented maximum) completes, its drawing
costs the picture (one turn of each loiter, bounded arrows), not the flight; an AOI 1e7 m away is
refused before the work with a one-line error naming dt."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import vistrack as vt
from support.cli import one_line_error
from support.paths import EXAMPLES
from vistrack.loiter.study import MAX_STEPS
from vistrack.plotting import loiter as figures

pytestmark = pytest.mark.sanitize

AOIS = [(300.0, 200.0), (600.0, 500.0)]


def test_a_thousand_turns_draw_as_one() -> None:
    once = vt.loiter.plan(AOIS, "tlpp", turns=1)
    thousand = vt.loiter.plan(AOIS, "tlpp", turns=1000)
    assert thousand.flight_time > 100 * once.flight_time
    # The outline of a loiter of 1000 turns is the outline of one (the rest retraces it).
    assert len(figures.plan_outline(thousand)) == len(figures.plan_outline(once))
    assert len(figures.plan_outline(thousand)) <= figures.MAX_ARC_POINTS * len(thousand.segments)
    arrows = figures._arrows(thousand.segments)
    assert 0 < len(arrows) <= figures.MAX_ARROWS_PER_SEGMENT * len(thousand.segments)


def test_turns_1000_completes(tmp_path: Path) -> None:
    # The 5-AOI example at turns: 1000 ran past 3 minutes (one matplotlib arrow per 150 m flown, a
    # segment list rebuilt per sample in the CSV and the role counts); it now takes seconds. The
    # generous timeout only catches a relapse into that cost.
    scenario = tmp_path / "turns.yaml"
    scenario.write_text((EXAMPLES / "loiter_5aoi.yaml").read_text().replace("turns: 1\n", "turns: 1000\n"))
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(Path(vt.__file__).parents[1]), *sys.path])}
    code = ("import sys; sys.path.insert(0, %r); from support.build_tree import use_build_tree; use_build_tree(); "
            "from vistrack.cli import main; sys.exit(main(sys.argv[1:]))" % str(Path(__file__).parent))
    done = subprocess.run([sys.executable, "-c", code, "loiter", str(scenario), "--out", str(tmp_path / "out"),
                           "--no-animation", "--no-html"], capture_output=True, text=True, timeout=120, env=env)
    assert done.returncode == 0, done.stderr
    rows = (tmp_path / "out" / "path_ldlpp.csv").read_text().count("\n") - 1
    plan = vt.loiter.load_scenario(scenario).plan("ldlpp")
    assert rows == int(np.floor(plan.flight_time)) + 1 and rows < MAX_STEPS


def test_an_aoi_1e7_m_away_is_refused_naming_dt(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    scenario = tmp_path / "far.yaml"
    scenario.write_text((EXAMPLES / "loiter_5aoi.yaml").read_text().replace("[541.8, 249.6]", "[1.0e7, 249.6]"))
    err = one_line_error(["loiter", str(scenario), "--out", str(tmp_path / "out")], capsys, 1,
                         "dt = 1:", "steps of dt", "raise dt to 4 s", "aois[4]")
    assert "out of memory" not in err
