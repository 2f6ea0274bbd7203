"""The tracking report's locus line from metrics.json: a smooth locus with no smooth reference (an
infeasible plan: max_abs_acceleration_mps2 is None) is reported, not a formatting error."""

from __future__ import annotations

from vistrack.report.run import locus_line

PLAN = {"locus": "smooth", "check_points": 181, "check_volumes_computed": 0, "check_rounds": 0,
        "paper_violations": 0, "paper_max_violation_m": 0.0, "tracking_margin_m": 1.0, "min_clearance_m": 5.27,
        "max_abs_acceleration_mps2": 0.125, "mean_lowering_m": 59.66, "max_lowering_m": 217.39,
        "max_lowering_at_s": 189.1, "max_lowering_at_m": 945.0}


def test_locus_line_with_and_without_a_smooth_reference() -> None:
    assert "C1 with |d2R/dt2| <= 0.12 m/s²" in locus_line(PLAN)
    line = locus_line({**PLAN, "max_abs_acceleration_mps2": None})
    assert "not C1 (no smooth reference: the plan is infeasible)" in line and "None" not in line
    assert locus_line({"locus": "paper"}).startswith("the paper's")
