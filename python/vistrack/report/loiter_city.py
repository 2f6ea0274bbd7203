"""The output of ``vistrack loiter`` for a scenario with a ``city`` block (beyond every anchor):
metrics.json, one figure per method of the loiter circles in their visibility polygons, report.md."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from .._core import Environment
from ..io import write_json
from ..loiter import METHOD_NAMES, Scenario
from ..loiter.city import CityLoiter, CityRun, plan_city
from ..loiter.planning import Plan
from ..plotting.loiter_city import city_loiter_figure
from .document import Document, Picture, Table


def city_lines(scenario: Scenario, result: CityLoiter) -> list[str]:
    """What the command prints: each AOI that has no flyable circle, then each method's numbers."""
    lines = [f"{scenario.name} {room.reason}" for room in result.rooms if not room.flyable]
    lines += [f"{scenario.name} aoi {room.index}: no flyable circle about it; loiters on one {room.shift:.0f} m off it "
              "inside its visibility polygon (off_centre)" for room in result.rooms if room.flyable and room.shift > 0]
    lines += [f"{scenario.name} {method}: skipped, cannot fly this layout: {reason}"
              for method, reason in result.refused.items()]
    for run in result.runs:
        seen = min(run.centre_line_of_sight) if run.centre_line_of_sight else 0.0
        lines.append(f"{scenario.name} {run.method} (city, R {result.radius:.0f} m, {len(result.flyable)} of "
                     f"{len(result.rooms)} AOIs): {run.plan.flight_time / 60:.2f} min, covered "
                     f"{run.coverage.time:.0f} s with line of sight ({run.coverage.open_time:.0f} s ignoring "
                     f"buildings); centres seen >= {100 * seen:.1f} % of loiter time")
    return lines


def write_city(out: Path, scenario: Scenario, env: Environment, result: CityLoiter) -> list[Path]:
    """metrics.json (every AOI's MaxRadius and flyability, every method's city scores), city_<method>.png
    (or city.png when no method could fly) and report.md."""
    out.mkdir(parents=True, exist_ok=True)
    written = [write_json({"scenario": scenario.name, "aois": scenario.aois.tolist(),
                           "turn_radius": scenario.turn_radius, "aoi_radius_wanted": scenario.aoi_radius,
                           "city": result.record()}, out / "metrics.json")]
    pictures = []
    runs: list[CityRun | None] = list(result.runs) or [None]
    for run in runs:
        name = "city.png" if run is None else f"city_{run.method}.png"
        title = f"{scenario.name}: loiter circles in their visibility polygons at {result.altitude:.0f} m"
        if run is not None:
            title += f" ({METHOD_NAMES.get(run.method, run.method)})"
        written.append(city_loiter_figure(env, result, out / name, None if run is None else run.plan, title))
        pictures.append(Picture(name, title, "Filled: each AOI's visibility polygon at the flight altitude "
                                             "(red: no flyable circle); dashed: MaxRadius; solid: the loiter circle."))
    aoi_rows = [[str(r.index), f"{r.max_radius:.1f}", "yes" if r.flyable else "no", r.reason or ""]
                for r in result.rooms]
    run_rows = [[METHOD_NAMES.get(run.method, run.method), f"{run.plan.flight_time / 60:.2f}",
                 f"{run.coverage.time:.0f}", f"{run.coverage.open_time:.0f}",
                 " ".join(f"{100 * s:.1f}" for s in run.centre_line_of_sight)] for run in result.runs]
    document = Document(
        f"Loiter over a city: {scenario.name}",
        [f"flight altitude {result.altitude:.0f} m (world z); loiter radius {result.radius or 0:.1f} m "
         f"(wanted {scenario.aoi_radius:g} m, turn radius {scenario.turn_radius:g} m)",
         f"{len(result.flyable)} of {len(result.rooms)} AOIs have a flyable circle in their visibility polygon",
         "beyond every anchor: the paper flies over open ground"],
        [Table(["AOI", "MaxRadius (m)", "flyable", "reason"], aoi_rows),
         Table(["method", "flight (min)", "covered s (line of sight)", "covered s (ignoring buildings)",
                "centre seen in loiter (%) per flyable AOI"], run_rows),
         *pictures])
    path = out / "report.md"
    path.write_text(document.markdown(), encoding="utf-8")
    written.append(path)
    return written


def run_city(out: Path, scenario: Scenario, methods: Sequence[str], order: str = "given"
             ) -> tuple[list[Path], list[str], dict[str, Plan]]:
    """Plan the scenario over its city (loiter.city.plan_city), write its folder: the files written,
    the lines to print and the plans flown (method -> plan; empty when none could fly)."""
    assert scenario.city is not None
    env = scenario.city.load(scenario.origin)
    result = plan_city(scenario, methods, env, order)
    return write_city(out, scenario, env, result), city_lines(scenario, result), {r.method: r.plan for r in result.runs}
