"""Shared command-line argument types."""

from __future__ import annotations

import argparse

import pytest

from vistrack.commands import positive_numbers


def test_positive_numbers() -> None:
    parse = positive_numbers("--spacings", "50,25")
    assert parse("50, 25,1.5") == [50.0, 25.0, 1.5]
    for bad in ("", "a,b", "10,-1", "0", "nan"):
        with pytest.raises(argparse.ArgumentTypeError, match=r"--spacings = .*need positive numbers like 50,25"):
            parse(bad)
