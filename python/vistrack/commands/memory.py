"""What lowers the work of each command, for the one message a real memory exhaustion gets (the
estimates before the work name the knob themselves; this is what is left when a platform's memory
runs out anyway)."""

from __future__ import annotations

_TRACKING = "a larger planning.spacing or min_spacing, a coarser planning.resolution_deg, a shorter path"

KNOBS = {
    "demo": _TRACKING,
    "run": _TRACKING,
    "volumes": "a larger --spacing, fewer --points, a coarser --resolution",
    "orbits": _TRACKING,
    "simulate": "a shorter --plan or a smaller --map",
    "tune": "fewer --sweep values",
    "intercept": "a coarser --tolerance",
    "waypoints": "a larger --dt, a shorter route or fewer --monte-carlo runs",
    "loiter": "a larger dt, fewer AOIs, fewer --method or --random scenarios",
    "follow": "a larger flight.dt or a shorter vehicle track",
    "sweep": "fewer cases or --workers, or a lighter base case",
    "city": "a smaller OpenStreetMap extract",
}


def out_of_memory(command: str) -> str:
    """The message of a real memory exhaustion in ``command``, naming that command's knobs."""
    knobs = KNOBS.get(command)
    return "out of memory" + (f" (lower the work: {knobs})" if knobs else "")
