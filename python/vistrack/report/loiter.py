"""The output folder of ``vistrack loiter``: metrics JSON, sampled paths as CSV, the figures, and the
tables beside the paper's (Table 1, Figure 14), of wind and of random scenarios."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import Any

from .. import loiter
from ..io import write_json, write_loiter_samples_csv
from ..loiter import METHOD_NAMES
from ..loiter_study import MethodRun, summary, wind_summary
from ..plotting import loiter as figures


def write_scenario(out: Path, scenario: loiter.Scenario, runs: Sequence[MethodRun]) -> list[Path]:
    """metrics.json, one sampled-path CSV per method, the methods figure (and the wind figure)."""
    out.mkdir(parents=True, exist_ok=True)
    written = [write_json({
        "scenario": scenario.name, "aois": scenario.aois.tolist(), "start": list(scenario.start),
        "end": list(scenario.end), "turn_radius": scenario.turn_radius, "speed": scenario.speed,
        "aoi_radius": scenario.aoi_radius, "turns": scenario.turns, "threshold": scenario.threshold,
        "dt": scenario.dt, "camera": {"fov_deg": scenario.camera.fov_deg,
                                      "max_gimbal_deg": scenario.camera.max_gimbal_deg,
                                      "altitude": scenario.camera.altitude},
        "methods": [run.record(scenario) for run in runs],
        "loiters": {run.method: loiter.loiter_circles(run.plan) for run in runs},
        "segments": {run.method: loiter.segment_records(run.plan) for run in runs},
    }, out / "metrics.json")]
    for run in runs:
        written.append(write_loiter_samples_csv(out / f"path_{run.method}.csv", run.plan, run.coverage,
                                                   scenario.dt, scenario.threshold))
    plans = {run.method: run.plan for run in runs}
    written.append(figures.methods_figure(plans, {run.method: run.coverage for run in runs},
                                          out / "plans.png", scenario.name))
    best = {run.method: run.best_plan for run in runs if run.best_plan is not None}
    if best:
        written.append(figures.methods_figure(best, {run.method: run.best_coverage for run in runs
                                                     if run.best_coverage is not None},
                                              out / "plans_best_order.png", scenario.name + " (best order)"))
    for run in runs:
        if run.wind_paths:
            shown = run.wind_paths[:: max(1, len(run.wind_paths) // 4)][:4]  # at most four flights drawn
            written.append(figures.wind_figure(run.plan, shown, out / f"wind_{run.method}.png",
                                               f"{METHOD_NAMES[run.method]} flown in unknown wind"))
    return written


def table_markdown(rows: Sequence[dict[str, Any]]) -> str:
    """Table 1 beside ours: flight time (min) and AOI coverage (10^3 m^2) per method and size."""
    sizes = sorted({int(r["aois"]) for r in rows})
    lines = ["| method | | " + " | ".join(f"{n} AOIs" for n in sizes) + " |",
             "|---|---|" + "---|" * len(sizes)]
    for method in [m for m in METHOD_NAMES if any(r["method"] == m for r in rows)]:
        by_size = {int(r["aois"]): r for r in rows if r["method"] == method}

        def cells(key: str, scale: float, digits: int, by_size: dict[int, dict[str, Any]] = by_size) -> str:
            return " | ".join(
                "-" if by_size[n].get(key) is None else f"{by_size[n][key] * scale:.{digits}f}" for n in sizes)

        name = METHOD_NAMES[method]
        lines.append(f"| {name} | flight time, paper (min) | {cells('paper_flight_time_min', 1.0, 2)} |")
        lines.append(f"| | flight time, ours (min) | {cells('flight_time_min', 1.0, 2)} |")
        lines.append(f"| | coverage, paper (10^3 m^2) | {cells('paper_coverage_m2', 1e-3, 0)} |")
        lines.append(f"| | coverage, ours (10^3 m^2) | {cells('coverage_area_m2', 1e-3, 0)} |")
        lines.append(f"| | covered time, ours (s) | {cells('coverage_time_s', 1.0, 0)} |")
        lines.append(f"| | transit time, ours (s) | {cells('transit_time_s', 1.0, 0)} |")
        if all("best_flight_time_s" in by_size[n] for n in sizes):
            lines.append(f"| | best order, ours (min) | {cells('best_flight_time_s', 1 / 60.0, 2)} |")
    return "\n".join(lines) + "\n"


def roles_markdown(rows: Sequence[dict[str, Any]]) -> str:
    """Over all rows, per method: the time on each kind of segment and the share of it with some AOI
    covered (where each method gains or loses coverage)."""
    lines = ["| method | " + " | ".join(f"{role}: time (s), covered" for role in ("transit", "entry", "loiter", "exit"))
             + " |", "|---|---|---|---|---|"]
    for method in [m for m in METHOD_NAMES if any(r["method"] == m for r in rows)]:
        cells = []
        for role in ("transit", "entry", "loiter", "exit"):
            steps = sum(r["steps_by_role"][role]["steps"] for r in rows if r["method"] == method)
            covered = sum(r["steps_by_role"][role]["covered_steps"] for r in rows if r["method"] == method)
            cells.append(f"{steps} s, {100 * covered / steps:.0f} %" if steps else "-")
        lines.append(f"| {METHOD_NAMES[method]} | " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n\nTime steps of 1 s summed over the scenarios; covered: some AOI counts as covered.\n"


def wind_markdown(rows: Sequence[dict[str, Any]]) -> str:
    def q(values: Sequence[float], scale: float = 1.0, digits: int = 0) -> str:
        return f"{values[1] * scale:.{digits}f} ({values[0] * scale:.{digits}f}-{values[2] * scale:.{digits}f})"

    head = ("| method | wind (m/s) | flights | loiter time with the AOI covered (plan: 100 %) | flight time / plan | "
            "covered time / plan | largest distance off the plan (m) |")
    lines = [head, "|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {METHOD_NAMES[r['method']]} | {r['wind_speed']:g} | {r['flights']} | "
                     f"{q(r['loiter_covered'], 100.0)} % | {q(r['flight_time_ratio'], 1.0, 2)} | "
                     f"{q(r['coverage_time_ratio'], 1.0, 2)} | {q(r['max_cross_track_m'])} |")
    return ("\n".join(lines) + "\n\nMedian (min-max) over scenarios and wind directions; the guidance does not "
            "know the wind.\n")


def write_table(out: Path, scenarios: Sequence[loiter.Scenario], rows: Sequence[dict[str, Any]]) -> list[Path]:
    """The study over several scenarios: table.json, table.md, Figure 13 and Figure 14."""
    out.mkdir(parents=True, exist_ok=True)
    plans = [s.plan("ldlpp") for s in scenarios]
    text = table_markdown(rows) + "\n" + roles_markdown(rows)
    winds = wind_summary(rows)
    if winds:
        text += "\n" + wind_markdown(winds)
    return [
        write_json({"rows": list(rows), "wind": winds}, out / "table.json"),
        _write_text(out / "table.md", text),
        figures.scenarios_figure(plans, [f"{s.name} (LDLPP)" for s in scenarios], out / "fig13_scenarios.png"),
        figures.comparison_figure(rows, out / "fig14_comparison.png"),
    ]


def _write_text(path: Path, text: str) -> Path:
    path.write_text(text, encoding="utf-8")
    return path


def summary_markdown(rows: Sequence[dict[str, Any]]) -> str:
    def q(values: Sequence[float], scale: float = 1.0, digits: int = 0) -> str:
        return f"{values[1] * scale:.{digits}f} ({values[0] * scale:.{digits}f}-{values[2] * scale:.{digits}f})"

    saved = any("time_saved_s" in r for r in rows)
    head = ("| method | flight time (min) | transit (s) | covered per AOI (s) | fastest | shortest transit | "
            "most coverage |" + (" best order saves |" if saved else ""))
    lines = [head, "|---" * (7 + saved) + "|"]
    for r in rows:
        line = (f"| {METHOD_NAMES[r['method']]} | {q(r['flight_time_s'], 1 / 60.0, 2)} | {q(r['transit_time_s'])} | "
                f"{q(r['coverage_per_aoi_s'], 1.0, 1)} | {100 * r['fastest']:.0f} % | "
                f"{100 * r['shortest_transit']:.0f} % | {100 * r['most_coverage']:.0f} % |")
        if saved:
            line += f" {q(r['time_saved_fraction'], 100.0, 1)} % |"
        lines.append(line)
    return "\n".join(lines) + "\n\nMedians (quartiles in brackets); shares of the scenarios where the method is best.\n"


def write_random(out: Path, records: Sequence[dict[str, Any]]) -> list[Path]:
    out.mkdir(parents=True, exist_ok=True)
    rows = summary(records)
    return [
        write_json({"summary": rows, "records": list(records)}, out / "random.json"),
        _write_text(out / "random.md", summary_markdown(rows)),
        figures.distribution_figure(records, out / "random_distribution.png"),
    ]
