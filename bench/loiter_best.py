"""Issue 33's numbers, beyond the paper: the loiter directions chosen (ldlpp_best: each AOI the
shorter way; tlpp_best: both first directions) against the printed planners on seeded random
layouts (section 4.1's area and vehicle, 3-8 AOIs; none tuned on), with the given and with the best
visiting order; then the time `best` takes on the 9-AOI example with order optimisation, beside
the printed methods' (median of 5 runs). Prints markdown.

    VISTRACK_BUILD_DIR=build/dev python3 bench/loiter_best.py [--layouts 200] [--seed 1000]
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[1]
if os.environ.get("VISTRACK_BUILD_DIR"):
    sys.path.insert(0, str(REPO / "tests" / "python"))
    import conftest  # noqa: F401  (imports vistrack from python/ with the build tree's _core)

from vistrack import loiter


def layout_table(count: int, seed: int) -> None:
    print("| order | layouts | ldlpp_best saves (median / mean / max) | ldlpp_best slower than LDLPP | "
          "tlpp_best saves (median / mean) | printed TLPP rule picks the longer | TLPP shorter than LDLPP / "
          "than ldlpp_best | best saves on the fastest printed (median) |")
    print("|---|---|---|---|---|---|---|---|")
    for order in ("given", "best"):
        ldlpp, tlpp, slower, rule, tl, tlb, best = [], [], 0, 0, 0, 0, []
        for k in range(count):
            scenario = loiter.random_scenario(3 + k % 6, seed + k)
            p = {m: scenario.plan(m, order) for m in loiter.ALL_METHODS}
            ldlpp.append(1 - p["ldlpp_best"].length / p["ldlpp"].length)
            tlpp.append(1 - p["tlpp_best"].length / p["tlpp"].length)
            slower += p["ldlpp_best"].length > p["ldlpp"].length * (1 + 1e-12)
            rule += p["tlpp_best"].length < p["tlpp"].length * (1 - 1e-12)
            tl += p["tlpp"].length < p["ldlpp"].length
            tlb += p["tlpp"].length < p["ldlpp_best"].length
            printed = min(p[m].length for m in loiter.METHODS)
            best.append(1 - scenario.plan("best", order).length / printed)
        pct = 100.0 / count
        print(f"| {order} | {count} | {100 * np.median(ldlpp):.2f} / {100 * np.mean(ldlpp):.2f} / "
              f"{100 * np.max(ldlpp):.2f} % | {slower} | {100 * np.median(tlpp):.2f} / {100 * np.mean(tlpp):.2f} % | "
              f"{rule * pct:.1f} % | {tl * pct:.1f} % / {tlb * pct:.1f} % | {100 * np.median(best):.2f} % |")


def timing_table() -> None:
    scenario = loiter.load_scenario(REPO / "examples" / "loiter_9aoi.yaml")
    print("| 9 AOIs, order best | planning time (ms, median of 5) | flight time (min) | method |")
    print("|---|---|---|---|")
    total = 0.0
    for method in (*loiter.ALL_METHODS, "best"):
        times = []
        for _ in range(5):
            start = time.perf_counter()
            plan = scenario.plan(method, "best")
            times.append(time.perf_counter() - start)
        median = float(np.median(times))
        if method in loiter.METHODS:
            total += median
        print(f"| {method} | {1e3 * median:.1f} | {plan.flight_time / 60:.2f} | {plan.method} |")
    print(f"\nbest / the three printed methods' planning time together: x{1e3 * median / (1e3 * total):.2f}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--layouts", type=int, default=200)
    parser.add_argument("--seed", type=int, default=1000)
    args = parser.parse_args()
    layout_table(args.layouts, args.seed)
    print()
    timing_table()


if __name__ == "__main__":
    main()
