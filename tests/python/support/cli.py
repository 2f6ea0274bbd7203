"""Running ``vistrack`` in this process and checking that an error is one line on stderr."""

from __future__ import annotations

import pytest

from vistrack.cli import main as cli_main


def cli(args: list[str], capsys: pytest.CaptureFixture[str]) -> tuple[int, str]:
    """Exit status and stderr of ``vistrack ARGS`` (in this process)."""
    status = cli_main(args)
    err = capsys.readouterr().err
    return status, err


def one_line_error(args: list[str], capsys: pytest.CaptureFixture[str], status: int, *fragments: str) -> str:
    """``vistrack ARGS`` exits with ``status`` and one stderr line, no traceback, holding every fragment."""
    code, err = cli(args, capsys)
    assert code == status, (code, err)
    assert err.count("\n") == 1 and "Traceback" not in err, err
    assert err.startswith("vistrack ") and ": error: " in err, err
    for fragment in fragments:
        assert fragment in err, f"{fragment!r} not in {err!r}"
    return err


NO_MEDIA = ["--no-animation", "--no-html"]  # the report media are tested in test_planner_reports.py
