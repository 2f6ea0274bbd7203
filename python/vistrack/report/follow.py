"""The output folder of ``vistrack follow``: figures, trajectory CSVs and metrics.json."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from ..follow_scenario import FollowStudy
from ..io import write_follow_trajectory, write_json
from ..plotting.follow import figure_compare, figure_paths, figure_scores


def write_follow(study: FollowStudy, out: Path, title: str = "") -> dict[str, Any]:
    """follow_paths.png (the paper's view), follow_scores.png (sigma, mode, errors, camera over
    time), follow_compare.png (planner beside the baseline), follow_city.png (both on the city road
    with line of sight, when run), trajectory.csv (the planner's run), baseline_trajectory.csv,
    city_trajectory.csv, city_baseline_trajectory.csv, and metrics.json (with the figures' and
    files' names). Returns the metrics record."""
    out.mkdir(parents=True, exist_ok=True)
    p = study.parameters
    label = "with wind compensation" if p.wind_compensation else "without wind compensation"
    title = f"{title} ({label})" if title else label
    files = [figure_paths(study.follow, out / "follow_paths.png", title),
             figure_scores(study.follow, p.threshold, p.hysteresis, out / "follow_scores.png", title),
             write_follow_trajectory(study.follow, out / "trajectory.csv")]
    if study.baseline is not None:
        files.append(figure_compare([("sinusoid planner (the paper)", study.follow),
                                     ("vector field (74), constant radius", study.baseline)],
                                    out / "follow_compare.png", title))
        files.append(write_follow_trajectory(study.baseline, out / "baseline_trajectory.csv"))
    if study.city_follow is not None:
        runs = [("sinusoid planner (the paper)", study.city_follow)]
        if study.city_baseline is not None:
            runs.append(("vector field (74), constant radius", study.city_baseline))
        files.append(figure_compare(runs, out / "follow_city.png", f"{title}, on a city road", study.environment))
        files.append(write_follow_trajectory(study.city_follow, out / "city_trajectory.csv"))
        if study.city_baseline is not None:
            files.append(write_follow_trajectory(study.city_baseline, out / "city_baseline_trajectory.csv"))
    record = study.metrics()
    record["files"] = [f.name for f in files]
    write_json(record, out / "metrics.json")
    return record
