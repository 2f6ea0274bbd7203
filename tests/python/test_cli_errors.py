"""Bad invocations of every command, as one table: binary, overflowing or misplaced inputs and
out-of-range options end in one stderr line naming the option (or the file), with exit status 2
(usage) or 1 (failure), never a traceback."""

from __future__ import annotations

from pathlib import Path

import pytest

from support.cli import cli, one_line_error
from support.geojson import square_collection

pytestmark = pytest.mark.sanitize


@pytest.mark.parametrize("args, option", [
    (["orbits", "--from-plan", "{bin}"], "--from-plan"),
    (["simulate", "--plan", "{bin}"], "--plan"),
    (["intercept", "--config", "{bin}"], "--config"),
    (["volumes", "--map", "{city}", "--path", "{bin}"], "binary.dat:2"),
    (["volumes", "--map", "{huge}", "--path", "{csv}"], "huge.geojson"),
])
def test_cli_binary_and_overflowing_inputs_are_one_line(args: list[str], option: str, tmp_path: Path,
                                                        capsys: pytest.CaptureFixture[str]) -> None:
    """orbits --from-plan, simulate --plan, intercept --config and volumes --path with binary files,
    and volumes --map with the 1e999 GeoJSON, printed tracebacks: now one line naming the option
    (or, for a bad value inside a file, the file)."""
    binary = tmp_path / "binary.dat"
    binary.write_bytes(bytes(range(256)) * 64)
    huge = tmp_path / "huge.geojson"
    huge.write_text(square_collection("1e999"))
    city = tmp_path / "city.geojson"
    city.write_text(square_collection("10"))
    csv = tmp_path / "path.csv"
    csv.write_text("0,0\n10,0\n")
    argv = [a.format(bin=binary, huge=huge, csv=csv, city=city) for a in args]
    argv += ["--out", str(tmp_path / "out")] if args[0] not in ("intercept",) else []
    code, err = cli(argv, capsys)
    assert code in (1, 2), (code, err)
    assert err.count("\n") == 1 and "Traceback" not in err, err
    assert option in err, err


@pytest.mark.parametrize("args, status, fragment", [
    (["waypoints", "{route}", "--monte-carlo", "1000000000"], 2, "--monte-carlo = 1000000000"),
    (["waypoints", "{route}", "--turn-radius", "1e300"], 2, "--turn-radius = 1e+300"),
    (["waypoints", "{route}", "--out", "{file}"], 1, "--out"),
    (["loiter", "--random", "100000000", "--out", "{out}"], 2, "--random = 100000000"),
    (["loiter", "--random", "1", "--wind", "nan,0", "--out", "{out}"], 2, "--wind"),
    (["loiter", "--random", "1", "--out", "{file}"], 1, "is a file, not a folder"),
    (["follow", "{binary}"], 1, "not UTF-8"),
    (["sweep", "{binary}"], 1, "not UTF-8"),
])
def test_new_commands_bad_invocations_are_one_line(args: list[str], status: int, fragment: str, tmp_path: Path,
                                                   capsys: pytest.CaptureFixture[str]) -> None:
    """A monte-carlo count of 10^9 hung; --out on a file failed after the work (a Python errno line)."""
    route = tmp_path / "route.csv"
    route.write_text("x,y\n0,0\n200,0\n200,200\n")
    file = tmp_path / "afile"
    file.write_text("keep\n")
    binary = tmp_path / "binary.yaml"
    binary.write_bytes(b"garbage\x00\xff\n")
    argv = [a.format(route=route, file=file, out=tmp_path / "out", binary=binary) for a in args]
    one_line_error(argv, capsys, status, fragment)
    assert file.read_text() == "keep\n"


@pytest.mark.parametrize("name", ["../../x", "/tmp/x", "a/b", ".."])
def test_loiter_scenario_names_stay_inside_out(name: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """Issue 29: a loiter scenario's ``name: ../../x`` wrote its report outside --out (two scenarios
    write to --out/<name>); names are now checked as the tracking and sweep names are."""
    work = tmp_path / "a" / "b"
    work.mkdir(parents=True)
    bad, good = work / "bad.yaml", work / "good.yaml"
    bad.write_text(f"name: {name!r}\naois: [[300, 300]]\n")
    good.write_text("aois: [[300, 300]]\n")
    before = sorted(tmp_path.rglob("*"))
    one_line_error(["loiter", str(good), str(bad), "--out", str(work / "out")], capsys, 1, "name = ")
    assert sorted(p for p in tmp_path.rglob("*") if "out" not in p.parts) == before


def test_sweep_tls_scheduler_is_one_line(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """Issue 29: ``--scheduler tls://...`` printed ``TypeError: TLS expects a ssl_context``."""
    sweep = tmp_path / "sweep.yaml"
    sweep.write_text("kind: loiter\nbase: {aois: [[300, 300]]}\nparameters: {method: [tlpp, ldlpp]}\n")
    one_line_error(["sweep", str(sweep), "--out", str(tmp_path / "out"), "--quiet", "--scheduler",
                    "tls://127.0.0.1:1"], capsys, 1, "scheduler = tls://127.0.0.1:1", "cannot connect")


def test_tune_refuses_before_its_progress_bar(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """Issue 29: ``vistrack tune`` drew its progress bar, then printed the one-line error. A bar is
    now drawn at the work's first report (vistrack.progress.Progress), after the input is checked."""
    err = one_line_error(["tune", "--speed", "5", "--poi-speed", "5", "--out", str(tmp_path / "out")], capsys, 1,
                         "radius_rate = 1.3", "Lemma 5")
    assert "beta sweep" not in err and "\r" not in err, repr(err)
    from vistrack.progress import Progress

    with Progress("nothing reported"):
        pass
    assert capsys.readouterr().err == ""
    with Progress("reported", unit="step") as bar:
        bar(1, 2)
    assert "reported" in capsys.readouterr().err
