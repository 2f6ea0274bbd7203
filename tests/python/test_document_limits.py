"""Issue 29: every JSON and YAML file goes through one bounded reader (depth, values with YAML aliases
expanded, size), and messages quote a bounded preview of a value. Before: a GeoJSON height nested
100,000 deep crashed the interpreter (SIGSEGV) in the message quoting it, and a YAML alias bomb in
any key of a scenario, loiter, follow, sweep or intercept file exhausted memory in ``schema.fail``'s
``repr``."""

from __future__ import annotations

from pathlib import Path
from typing import Any, Callable

import pytest

import vistrack as vt
from support.cli import one_line_error
from support.geojson import square_collection
from support.refusal import refuses

pytestmark = pytest.mark.sanitize


def nested(depth: int) -> str:
    return "[" * depth + "]" * depth


def alias_bomb(key: str = "bomb", levels: int = 9) -> str:
    """A "billion laughs": 9 levels of 9 aliases each expand to 9^9 = 387 million strings."""
    lines = [f"{key}:", '  - &l0 ["lol", "lol", "lol", "lol", "lol", "lol", "lol", "lol", "lol"]']
    for level in range(1, levels):
        lines.append(f"  - &l{level} [" + ", ".join([f"*l{level - 1}"] * 9) + "]")
    return "\n".join(lines) + "\n"


def test_a_geojson_value_nested_100000_deep_is_refused_while_parsed(tmp_path: Path,
                                                                    capsys: pytest.CaptureFixture[str]) -> None:
    """The 200 KB map of the issue: SIGSEGV through from_geojson and ``vistrack volumes --map``."""
    deep = tmp_path / "deep.geojson"
    deep.write_text(square_collection(nested(100_000)))
    refuses(lambda: vt.Environment.from_geojson(str(deep)), "deep.geojson", "nested deeper than 100 levels")
    path = tmp_path / "path.csv"
    path.write_text("0,0\n10,0\n")
    one_line_error(["volumes", "--map", str(deep), "--path", str(path), "--out", str(tmp_path / "out")], capsys, 1,
                   "deep.geojson", "nested deeper than 100 levels")
    # Within the limit the value is parsed, then refused as a height, quoted in 40 characters.
    deep.write_text(square_collection(nested(96)))
    message = refuses(lambda: vt.Environment.from_geojson(str(deep)), "properties.height = [[[[", "expected a number")
    assert len(message) < 200


@pytest.mark.parametrize("kind", ["scenario", "loiter", "follow", "sweep", "intercept"])
def test_alias_bombs_are_refused_while_read(kind: str, tmp_path: Path) -> None:
    """An unknown key holding 9^9 aliased strings: its repr exhausted memory (44 s to 3 GB)."""
    from vistrack.follow_scenario import FollowScenario
    from vistrack.intercept import InterceptProblem
    from vistrack.io import read_loiter_scenario
    from vistrack.scenario import Scenario
    from vistrack.sweep.spec import SweepSpec

    loaders: dict[str, Callable[[Path], Any]] = {
        "scenario": Scenario.load, "loiter": read_loiter_scenario, "follow": FollowScenario.load,
        "sweep": SweepSpec.load, "intercept": lambda path: InterceptProblem.load(path, {}),
    }
    bomb = tmp_path / "bomb.yaml"
    bomb.write_text(alias_bomb())
    refuses(lambda: loaders[kind](bomb), "bomb.yaml", "more than 1000000 values", "alias", "line 8")


def test_yaml_limits_count_what_aliases_expand_to(tmp_path: Path) -> None:
    from vistrack.io import parse_yaml

    # 6 levels expand to 672,603 values: read (as shared lists); 7 levels to 6 million: refused.
    assert parse_yaml(alias_bomb(levels=6), "k", "f")["bomb"][5][0][0][0][0][0][0] == "lol"
    refuses(lambda: parse_yaml(alias_bomb(levels=7), "k", "f"), "k = f: more than 1000000 values")
    # Nesting through aliases: each anchor nests the one before 30 levels deeper.
    chain = ["a: &a0 " + nested(30)]
    chain += [f"a{k}: &a{k} " + "[" * 30 + f"*a{k - 1}" + "]" * 30 for k in range(1, 4)]
    refuses(lambda: parse_yaml("\n".join(chain), "k", "f"), "k = f: nested deeper than 100 levels, aliases expanded",
            "line 4")
    assert parse_yaml("\n".join(chain[:3]), "k", "f")["a2"][0][0][0]
    refuses(lambda: parse_yaml("x: " + nested(101), "k", "f"), "k = f: nested deeper than 100 levels")
    refuses(lambda: parse_yaml("x: &r [1, *r]\n", "k", "f"), "the alias *r is inside its own anchor")
    # A merge key is an alias too.
    merges = ["l0: &l0 {a: 1, b: 2, c: 3, d: 4, e: 5, f: 6, g: 7, h: 8, i: 9}"]
    merges += [f"l{k}: &l{k} {{<<: [" + ", ".join([f"*l{k - 1}"] * 9) + "]}" for k in range(1, 9)]
    refuses(lambda: parse_yaml("\n".join(merges), "k", "f"), "more than 1000000 values")
    refuses(lambda: parse_yaml("a: 1\na: 2\n", "k", "f"), "found the key 'a' twice")


def test_json_readers_are_bounded_in_depth(tmp_path: Path) -> None:
    """Roads, orbit plans and missions read JSON in Python through the same reader."""
    from vistrack.io import read_plan, read_roads

    deep, plan = tmp_path / "deep.json", tmp_path / "deep.plan"
    for depth in (101, 100_000):
        deep.write_text('{"features": ' + nested(depth) + "}")
        plan.write_text(deep.read_text())
        refuses(lambda: read_roads(deep), "routes.roads = ", "nested deeper than 100 levels")
        refuses(lambda: read_plan(deep), "plan = ", "nested deeper than 100 levels")
        refuses(lambda: vt.mission.load(plan), "deep.plan", "nested deeper than 100 levels")


def test_messages_quote_a_bounded_preview() -> None:
    """schema.fail once built repr() of the whole value, then cut it to 80 characters."""
    from vistrack import schema
    from vistrack.preview import preview

    tree: list[Any] = ["lol"]
    for _ in range(40):  # 2^40 leaves through shared references: repr would never finish
        tree = [tree, tree]
    message = refuses(lambda: schema.number("poi.speed", tree), "poi.speed = [[[[[[[[[[[[", "must be a number")
    assert len(message) < 120
    assert preview("x" * 10**7) == "'" + "x" * 76 + "..."
    assert preview(list(range(10**6))).endswith("...") and len(preview(list(range(10**6)))) == 80
    assert preview(10**5000) == "<an integer of about 5001 digits>"
    for small in (1.5, "a", [1, "a"], (1,), {"k": [None, True]}, set(), frozenset({2})):
        assert preview(small) == repr(small)
