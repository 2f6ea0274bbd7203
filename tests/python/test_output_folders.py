"""Issue 29: the output folder of every command. A second run into a busy --out folder is refused
with one line naming the folder (three concurrent ``vistrack waypoints`` runs with different winds
all exited 0 and left a folder mixing their results); an --out that is a file is one line naming
--out before the work (``vistrack sweep --out FILE`` reported ``[Errno 17] File exists``)."""

from __future__ import annotations

import fcntl
import os
import subprocess
import sys
from pathlib import Path

import pytest

from support.cli import NO_MEDIA, cli, one_line_error
from support.geojson import square_collection
from support.paths import REPO

pytestmark = pytest.mark.sanitize


def route(tmp_path: Path) -> Path:
    file = tmp_path / "route.csv"
    file.write_text("x,y\n0,0\n200,0\n200,200\n")
    return file


def sweep_file(tmp_path: Path) -> Path:
    file = tmp_path / "sweep.yaml"
    file.write_text("kind: loiter\nbase: {aois: [[300, 300]]}\nparameters: {method: [tlpp, ldlpp]}\n")
    return file


def test_a_busy_output_folder_is_refused(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    busy = tmp_path / "busy"
    busy.mkdir()
    (busy / "metrics.json").write_text("{}\n")
    descriptor = os.open(busy, os.O_RDONLY | os.O_DIRECTORY)
    try:
        fcntl.flock(descriptor, fcntl.LOCK_EX | fcntl.LOCK_NB)  # another run holds it
        one_line_error(["waypoints", str(route(tmp_path)), "--out", str(busy), *NO_MEDIA], capsys, 1,
                       f"--out = {busy}: the folder is in use by another vistrack run")
        one_line_error(["sweep", str(sweep_file(tmp_path)), "--out", str(busy), "--scheduler", "serial", "--quiet"],
                       capsys, 1, f"--out = {busy}: the folder is in use")
        assert [p.name for p in busy.iterdir()] == ["metrics.json"]  # untouched
    finally:
        os.close(descriptor)
    # Free again: the run writes, leaves no lock file and releases the folder when it ends.
    code, err = cli(["waypoints", str(route(tmp_path)), "--out", str(busy), *NO_MEDIA], capsys)
    assert code == 0, err
    names = sorted(p.name for p in busy.iterdir())
    assert "trajectory_dwn.csv" in names and not [n for n in names if "lock" in n], names
    descriptor = os.open(busy, os.O_RDONLY | os.O_DIRECTORY)
    try:
        fcntl.flock(descriptor, fcntl.LOCK_EX | fcntl.LOCK_NB)  # would raise if the run still held it
    finally:
        os.close(descriptor)


def test_a_second_process_is_refused_while_a_run_writes(tmp_path: Path) -> None:
    """A real second ``vistrack`` process against a folder locked by a running command."""
    out = tmp_path / "out"
    holder = subprocess.Popen(  # a command that locks its --out and then waits (a long run)
        [sys.executable, "-c", (
            "import sys; sys.path.insert(0, sys.argv[1]); from support.build_tree import use_build_tree; "
            "use_build_tree(); from vistrack.commands.output import output_folder; "
            "from vistrack.commands.output_lock import output_locks\n"
            "with output_locks():\n output_folder(sys.argv[2]); print('locked', flush=True); sys.stdin.read()"),
         str(REPO / "tests" / "python"), str(out)], stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)
    try:
        assert holder.stdout is not None and holder.stdout.readline() == "locked\n"
        second = subprocess.run(
            [sys.executable, "-c", (
                "import sys; sys.path.insert(0, sys.argv[1]); from support.build_tree import use_build_tree; "
                "use_build_tree(); from vistrack.cli import main; sys.exit(main(sys.argv[2:]))"),
             str(REPO / "tests" / "python"), "waypoints", str(route(tmp_path)), "--out", str(out), *NO_MEDIA],
            capture_output=True, text=True, timeout=120)
    finally:
        holder.communicate("")
    assert second.returncode == 1, second.stderr
    assert second.stderr.count("\n") == 1 and "the folder is in use by another vistrack run" in second.stderr
    assert holder.returncode == 0
    assert not out.exists()  # the holder created it, wrote nothing and removed it; the second run left it


@pytest.mark.parametrize("command", [
    ["waypoints", "{route}"], ["sweep", "{sweep}", "--scheduler", "serial", "--quiet"],
    ["follow", "{follow}", "--no-city"], ["loiter", "--random", "1"], ["demo"], ["intercept"], ["tune"],
    ["volumes", "--map", "{city}", "--path", "{path}"], ["orbits", "--map", "{city}", "--path", "{path}"],
    ["simulate", "--plan", "{path}"],
])
def test_out_that_is_a_file_names_the_option(command: list[str], tmp_path: Path,
                                             capsys: pytest.CaptureFixture[str]) -> None:
    """Every command writing a folder checks --out through one helper (commands.output.output_folder)."""
    file = tmp_path / "afile"
    file.write_text("keep\n")
    city = tmp_path / "city.geojson"
    city.write_text(square_collection("10"))
    path = tmp_path / "path.csv"
    path.write_text("0,0\n10,0\n")
    follow = REPO / "examples" / "follow_stop.yaml"
    argv = [a.format(route=route(tmp_path), sweep=sweep_file(tmp_path), follow=follow, city=city, path=path)
            for a in command]
    one_line_error([*argv, "--out", str(file)], capsys, 1, f"--out = {file}: is a file, not a folder")
    assert file.read_text() == "keep\n"


def test_a_failed_run_leaves_no_folder(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "new" / "deep"
    one_line_error(["waypoints", str(tmp_path / "missing.csv"), "--out", str(out)], capsys, 1, "missing.csv")
    assert not (tmp_path / "new").exists()


def test_sweep_run_into_a_file_names_out(tmp_path: Path) -> None:
    """The library's sweep.run once raised FileExistsError ([Errno 17]) for an out that is a file."""
    from support.refusal import refuses
    from vistrack.sweep import run

    file = tmp_path / "afile"
    file.write_text("keep\n")
    refuses(lambda: run(sweep_file(tmp_path), "serial", out=file), f"out = {file}: is a file, not a folder")
