"""Loiter studies: every method on a scenario (plans, coverage, the best visiting order, flights in
wind), seeded random scenarios at scale, and their summaries. Output folders: vistrack.report.loiter."""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable, Iterator, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .._core import VistrackError
from .._core import limits as _limits
from ..fdm.aircraft import aircraft
from .fdm import fdm_score
from .flying import fly_and_score
from .planning import METHOD_NAMES, METHODS, Coverage, Plan, metrics
from .scenario import Scenario, random_aois

# The AOI area the paper's Table 1 counts per covered second (m^2): its TLPP and LDLPP coverages are
# whole multiples of it (873,713 = 131 x 6,669.56; pi x 46.076^2, close to but not the AOI's
# pi x 46^2 = 6,647.6), so coverage / this is the paper's covered time in seconds.
PAPER_AREA_PER_SECOND = 873713.0 / 131.0

__all__ = [
    "MAX_STEPS",
    "PAPER_AREA_PER_SECOND",
    "MethodRun",
    "check_steps",
    "evaluate",
    "paper_numbers",
    "random_scenarios",
    "random_study",
    "summary",
    "wind_directions",
    "wind_summary",
]


def paper_numbers(scenario: Scenario, method: str) -> dict[str, Any]:
    """The paper's Table 1 numbers for a method, as the scenario file gives them (None where it does
    not), with the coverage also in covered seconds."""
    paper = scenario.paper.get(method, {})
    area = paper.get("coverage_m2")
    return {"paper_flight_time_min": paper.get("flight_time_min"), "paper_coverage_m2": area,
            "paper_covered_time_s": None if area is None else area / PAPER_AREA_PER_SECOND}


@dataclass
class MethodRun:
    """One method on one scenario: the plan, its coverage, and with ``order="best"`` the same for
    the best visiting order."""

    method: str
    plan: Plan
    coverage: Coverage
    best_plan: Plan | None = None
    best_coverage: Coverage | None = None
    wind: list[dict[str, Any]] = field(default_factory=list)
    wind_paths: list[tuple[str, np.ndarray]] = field(default_factory=list)

    def record(self, scenario: Scenario) -> dict[str, Any]:
        row: dict[str, Any] = {"scenario": scenario.name, "aois": len(scenario.aois)}
        row.update(metrics(self.plan, self.coverage, scenario.dt, scenario.threshold))
        if self.method in scenario.paper:
            row.update(paper_numbers(scenario, self.method))
        if self.best_plan is not None and self.best_coverage is not None:
            row["best_order"] = list(self.best_plan.order)
            row["best_flight_time_s"] = self.best_plan.flight_time
            row["best_transit_time_s"] = self.best_plan.transit_time
            row["best_coverage_time_s"] = self.best_coverage.time
            row["time_saved_s"] = self.plan.flight_time - self.best_plan.flight_time
        if self.wind:
            row["wind"] = self.wind
        return row


# A study scores each plan and writes it (path CSV, animation, report.html) at every step of dt:
# about 100 bytes and 30 microseconds per step and method. 5e5 steps is 5.8 days of flight at dt
# 1 s (the paper's plans fly minutes; turns: 1000 over 5 AOIs, 2 x 10^5 steps).
MAX_STEPS = 500_000


def check_steps(scenario: Scenario, plan: Plan, methods: int = 1) -> None:
    """VistrackError naming ``dt`` (and what makes the plan long) when scoring and writing ``plan``
    every dt would take more than MAX_STEPS steps, or when the coverage matrices of ``methods``
    such plans and the copy the report makes of one (steps x AOIs x 8 bytes each) would exceed
    ``limits.MAX_WORK_BYTES``; checked before any of that work."""
    steps = math.floor(plan.flight_time / scenario.dt) + 1
    held = float(steps) * len(scenario.aois) * 8.0 * (methods + 1)  # the report copies one (cov.fraction)
    if held > _limits.MAX_WORK_BYTES:
        fits = math.ceil(scenario.dt * held / _limits.MAX_WORK_BYTES)
        raise VistrackError(
            f"dt = {scenario.dt:g}: {methods + 1} coverage matrices (one per method, one copy) of about "
            f"{steps:.4g} steps x {len(scenario.aois)} AOIs (8 bytes per step and AOI, kept for the report) "
            f"would hold about {held / 1e9:.4g} GB, above the {_limits.MAX_WORK_BYTES / 1e9:.4g} GB one planned "
            f"piece of work may take (MAX_WORK_BYTES): raise dt ({fits} s fits), score fewer AOIs or fewer methods "
            "(--method)")
    if steps <= MAX_STEPS:
        return
    aois = np.asarray(scenario.aois, dtype=float)
    far = int(np.argmax(np.hypot(aois[:, 0] - scenario.start[0], aois[:, 1] - scenario.start[1])))
    distance = float(np.hypot(*(aois[far] - np.asarray(scenario.start))))
    raise VistrackError(
        f"dt = {scenario.dt:g}: the {plan.method} plan flies {plan.flight_time:.4g} s, {steps:.4g} steps of dt to "
        f"score and write (about {steps * 100 / 1e6:.4g} MB of path CSV), above the {MAX_STEPS:.0e} a loiter "
        f"study takes per plan: raise dt to {math.ceil(plan.flight_time / (MAX_STEPS - 1)):g} s or more, or "
        f"shorten the plan (turns = {scenario.turns}; the farthest AOI, aois[{far}], lies {distance:.4g} m from "
        "the start)")


def evaluate(scenario: Scenario, methods: Sequence[str] = METHODS, order: str = "given",
             winds: Sequence[tuple[float, float]] = (), refused: dict[str, str] | None = None) -> list[MethodRun]:
    """Plan and score each method; ``order="best"`` adds the best visiting order; ``winds`` flies
    each plan in those constant (east, north) winds and scores the flown paths. With ``refused``,
    a method that cannot fly the layout is skipped and its reason stored there by method (LDLPP
    needs room for its turns); without, its VistrackError is raised."""
    if scenario.aircraft is not None and winds:  # refused before any plan when the aircraft cannot fly it
        aircraft(scenario.aircraft).check_plan(scenario.speed, scenario.turn_radius)
    runs = []
    for method in methods:
        try:
            plan = scenario.plan(method)
        except VistrackError as error:
            if refused is None:
                raise
            refused[method] = str(error)
            continue
        check_steps(scenario, plan, len(methods) * (2 if order == "best" else 1))
        run = MethodRun(method, plan, scenario.coverage(plan))
        if order == "best":
            run.best_plan = scenario.plan(method, "best")
            run.best_coverage = scenario.coverage(run.best_plan)
        for wind in winds:
            record = fly_and_score(scenario, plan, wind, planned=run.coverage)
            if scenario.aircraft is not None:  # the same flight on the 6-DOF aircraft, beside it
                record["fdm"] = fdm_score(scenario, plan, wind, run.coverage, scenario.aircraft)
            run.wind_paths.append((f"wind ({wind[0]:g}, {wind[1]:g}) m/s", np.asarray(record.pop("_trajectory"))))
            run.wind.append(record)
        runs.append(run)
    return runs


def wind_directions(speeds: Sequence[float], count: int = 8) -> list[tuple[float, float]]:
    """Winds of each speed from ``count`` directions evenly around the compass (east first), rounded
    to 1e-9 m/s (no 6e-16 where a component is zero)."""
    def clean(value: float) -> float:
        return round(value, 9) + 0.0

    return [(clean(speed * math.cos(2 * math.pi * k / count)), clean(speed * math.sin(2 * math.pi * k / count)))
            for speed in speeds for k in range(count)]


def wind_summary(rows: Sequence[dict[str, Any]]) -> list[dict[str, Any]]:
    """Per method and wind speed, over scenarios and directions: the share of the loiter time with
    the AOI covered (flown; the plan's), the flight time and the covered time against the plan."""
    out = []
    methods = [m for m in METHOD_NAMES if any(r["method"] == m for r in rows)]
    for method in methods:
        flights = [w for r in rows if r["method"] == method for w in r.get("wind", [])]
        for speed in sorted({round(math.hypot(*w["wind"]), 6) for w in flights}):
            mine = [w for w in flights if abs(math.hypot(*w["wind"]) - speed) < 1e-6]

            def stats(values: list[float]) -> list[float]:
                return [float(np.min(values)), float(np.median(values)), float(np.max(values))]

            out.append({
                "method": method, "wind_speed": speed, "flights": len(mine),
                "finished": sum(bool(w["finished"]) for w in mine),
                "loiter_covered": stats([w["loiter_covered_fraction"] for w in mine]),
                "planned_loiter_covered": stats([w["planned_loiter_covered_fraction"] for w in mine]),
                "flight_time_ratio": stats([w["flight_time_s"] / w["planned_flight_time_s"] for w in mine]),
                "coverage_time_ratio": stats([w["coverage_time_s"] / w["planned_coverage_time_s"] for w in mine]),
                "max_cross_track_m": stats([w["max_cross_track_m"] for w in mine]),
            })
    return out


def random_scenarios(count: int, seed: int, aoi_counts: Iterable[int] = range(4, 10)) -> Iterator[Scenario]:
    """The seeded random scenarios of :func:`random_study` (and ``vistrack loiter --random N --seed
    S``), in order: scenario k has ``aoi_counts[k % len]`` AOIs, all drawn from one generator."""
    sizes = list(aoi_counts)
    rng = np.random.default_rng(seed)
    for k in range(count):
        yield Scenario(aois=random_aois(sizes[k % len(sizes)], rng), name=f"random-{seed}-{k}")


def random_study(count: int, seed: int, methods: Sequence[str] = METHODS, order: str = "given",
                 aoi_counts: Iterable[int] = range(4, 10),
                 progress: Callable[[int, int], None] | None = None) -> list[dict[str, Any]]:
    """``count`` seeded random scenarios (section 4.1's area and vehicle; sizes cycling through
    ``aoi_counts``), every method on each: one record per (scenario, method)."""
    records: list[dict[str, Any]] = []
    for k, scenario in enumerate(random_scenarios(count, seed, aoi_counts)):
        for run in evaluate(scenario, methods, order):
            row = run.record(scenario)
            row["index"] = k
            records.append(row)
        if progress is not None:
            progress(k + 1, count)
    return records


def summary(records: Sequence[dict[str, Any]]) -> list[dict[str, Any]]:
    """Per method: quartiles of flight, transit and covered time, how often it is the fastest, has
    the shortest transit, covers most; the best order's median saving when present."""
    methods = [m for m in METHOD_NAMES if any(r["method"] == m for r in records)]
    by_index: dict[int, dict[str, dict[str, Any]]] = {}
    for r in records:
        by_index.setdefault(int(r["index"]), {})[r["method"]] = r
    out = []
    for method in methods:
        mine = [r for r in records if r["method"] == method]

        def quartiles(key: str, mine: list[dict[str, Any]] = mine) -> list[float]:
            return [float(q) for q in np.percentile([float(r[key]) for r in mine], [25, 50, 75])]

        def share(key: str, best: Callable[[Iterable[float]], float], method: str = method) -> float:
            wins = [group[method][key] == best(g[key] for g in group.values()) for group in by_index.values()]
            return float(np.mean(wins))

        row = {"method": method, "scenarios": len(mine),
               "flight_time_s": quartiles("flight_time_s"), "transit_time_s": quartiles("transit_time_s"),
               "coverage_time_s": quartiles("coverage_time_s"),
               "coverage_per_aoi_s": [float(q) for q in np.percentile(
                   [float(r["coverage_time_s"]) / int(r["aois"]) for r in mine], [25, 50, 75])],
               "fastest": share("flight_time_s", min), "shortest_transit": share("transit_time_s", min),
               "most_coverage": share("coverage_time_s", max)}
        if all("time_saved_s" in r for r in mine):
            row["time_saved_s"] = quartiles("time_saved_s")
            row["time_saved_fraction"] = [float(q) for q in np.percentile(
                [float(r["time_saved_s"]) / float(r["flight_time_s"]) for r in mine], [25, 50, 75])]
        out.append(row)
    return out
