"""Command-line arguments: the shared argument types, and usage errors of every command (exit status
2, one line naming the option and the value)."""

from __future__ import annotations

import argparse

import pytest

from support.cli import one_line_error
from vistrack.commands import positive_numbers


def test_positive_numbers() -> None:
    parse = positive_numbers("--spacings", "50,25")
    assert parse("50, 25,1.5") == [50.0, 25.0, 1.5]
    for bad in ("", "a,b", "10,-1", "0", "nan"):
        with pytest.raises(argparse.ArgumentTypeError, match=r"--spacings = .*need positive numbers like 50,25"):
            parse(bad)


@pytest.mark.sanitize
def test_cli_usage_errors_exit_2(capsys: pytest.CaptureFixture[str]) -> None:
    """Usage errors are exit status 2, one line, naming the option and the value."""
    one_line_error(["run"], capsys, 2, "scenario file is required")
    one_line_error(["run", "x.yaml", "--max-volumes", "-3"], capsys, 2, "--max-volumes")
    one_line_error(["intercept", "--rho", "nan"], capsys, 2, "--rho")
    # Ranges the library would refuse only after the inputs were read are the parser's too.
    one_line_error(["orbits", "--rate-margin", "1"], capsys, 2, "--rate-margin = 1.0", "[0, 1)")
    one_line_error(["simulate", "--plan", "p.json", "--fixed-step", "1e-10"], capsys, 2, "--fixed-step = 1e-10")
    one_line_error(["simulate", "--plan", "p.json", "--atol", "1e7"], capsys, 2, "--atol")
    one_line_error(["simulate", "--plan", "p.json", "--k-psi", "0"], capsys, 2, "--k-psi")
    one_line_error(["tune", "--beta", "1e4"], capsys, 2, "--beta")
    one_line_error(["tune", "--sweep", "0.01,5000"], capsys, 2, "--sweep = '5000'")
