"""vistrack.dubins: hand vectors, batch vs scalar, circle path, intercept against brute force."""

from __future__ import annotations

import math
import subprocess
import sys
import threading
from pathlib import Path

import numpy as np
import pytest

import vistrack as vt
from support.build_tree import standalone_executable
from support.refusal import refuses
from support.threads import ticks_during
from vistrack import VistrackError, dubins

pytestmark = pytest.mark.sanitize  # the input-facing surface (scripts/sanitize.sh)


def test_both_import_styles() -> None:
    assert vt.dubins.shortest_path is dubins.shortest_path
    assert dubins.WORDS == ("LSL", "LSR", "RSL", "RSR", "RLR", "LRL")


def test_hand_vectors() -> None:
    # Straight ahead 10 m: LSL (0, 10, 0).
    p = dubins.shortest_path((0, 0, 0), (10, 0, 0), 1.0)
    assert p.word == "LSL" and p.segment_types == ("L", "S", "L")
    assert p.length == pytest.approx(10.0, abs=1e-14)
    # Quarter turn left on the start's left circle (centre (0, 1)): one arc of pi/2.
    q = dubins.shortest_path((0, 0, 0), (1, 1, math.pi / 2), 1.0)
    assert q.length == pytest.approx(math.pi / 2, abs=1e-12)
    # LRL built by hand in dubins_test.cpp: (pi/6, 4 pi/3, pi/6), length 5 pi/3.
    r = dubins.shortest_path((0, 0, 0), (0, 2 - 2 * math.sqrt(3), math.pi), 1.0)
    assert r.word == "LRL"
    assert r.segment_lengths == pytest.approx((math.pi / 6, 4 * math.pi / 3, math.pi / 6), abs=1e-12)
    # Scaling rho scales the arc lengths.
    s = dubins.shortest_path((0, 0, 0), (0, 2 * (2 - 2 * math.sqrt(3)), math.pi), 2.0)
    assert s.length == pytest.approx(10 * math.pi / 3, abs=1e-12)


def test_sampling_and_at() -> None:
    p = dubins.shortest_path((1, 2, 0.3), (-4, 5, 2.0), 1.5)
    rows = p.sample(0.1)
    assert rows.shape[1] == 3
    assert tuple(rows[-1]) == (-4.0, 5.0, 2.0)
    assert tuple(rows[0]) == (1.0, 2.0, 0.3)
    steps = np.hypot(np.diff(rows[:, 0]), np.diff(rows[:, 1]))
    assert steps.max() <= 0.1 + 1e-12
    assert p.at(p.length) == (-4.0, 5.0, 2.0)
    mid = p.sample_at([0.0, p.length / 2, p.length])
    assert mid.shape == (3, 3)
    assert tuple(mid[1]) == pytest.approx(p.at(p.length / 2))
    # A zero-length path samples to the goal alone.
    assert dubins.shortest_path((1, 1, 0), (1, 1, 2 * math.pi), 1.0).sample(0.1).tolist() == [[1.0, 1.0, 2 * math.pi]]
    # Re-planning from the middle gives the remaining length.
    rest = dubins.shortest_path(tuple(mid[1]), (-4, 5, 2.0), 1.5)
    assert rest.length == pytest.approx(p.length / 2, abs=1e-9)


def test_every_word_and_word_lengths() -> None:
    lengths = dubins.word_lengths((0, 0, 0), (3, 1, 1.0), 1.0)
    assert set(lengths) == set(dubins.WORDS)
    best = dubins.shortest_path((0, 0, 0), (3, 1, 1.0), 1.0)
    assert min(lengths.values()) == pytest.approx(best.length, abs=1e-12)
    for word, length in lengths.items():
        if math.isfinite(length):
            assert dubins.path((0, 0, 0), (3, 1, 1.0), 1.0, word).length == pytest.approx(length, abs=1e-12)


def test_batch_matches_scalar() -> None:
    rng = np.random.default_rng(5)
    n = 3000
    q0 = np.column_stack([rng.uniform(-10, 10, (n, 2)), rng.uniform(-np.pi, np.pi, n)])
    q1 = np.column_stack([rng.uniform(-10, 10, (n, 2)), rng.uniform(-np.pi, np.pi, n)])
    lengths, words = dubins.shortest_lengths(q0, q1, 2.0)
    assert lengths.shape == (n,) and words.dtype == np.uint8
    for i in range(0, n, 7):
        p = dubins.shortest_path(q0[i], q1[i], 2.0)
        assert lengths[i] == pytest.approx(p.length, rel=1e-12, abs=1e-12)
        assert dubins.WORDS[words[i]] == p.word
        assert dubins.shortest_length(q0[i], q1[i], 2.0) == lengths[i]
    # Fortran-ordered and float32 inputs are converted.
    l2, _ = dubins.shortest_lengths(np.asfortranarray(q0), q1.astype(np.float32).astype(np.float64), 2.0)
    assert np.allclose(l2, lengths)
    # One thread gives the same numbers as all cores.
    l1, w1 = dubins.shortest_lengths(q0, q1, 2.0, threads=1)
    assert np.array_equal(l1, lengths) and np.array_equal(w1, words)


def test_batch_runs_concurrently_with_the_gil_released() -> None:
    rng = np.random.default_rng(1)
    q0 = rng.uniform(-5, 5, (200000, 3))
    q1 = rng.uniform(-5, 5, (200000, 3))
    expected, _ = dubins.shortest_lengths(q0, q1, 1.0)
    results: list[np.ndarray] = []
    threads = [threading.Thread(target=lambda: results.append(dubins.shortest_lengths(q0, q1, 1.0)[0]))
               for _ in range(3)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert len(results) == 3 and all(np.array_equal(r, expected) for r in results)
    # Another Python thread runs while a long batch is computed: the GIL is released.
    big0 = np.tile(q0, (10, 1))
    big1 = np.tile(q1, (10, 1))
    ticks, seconds = ticks_during(lambda: dubins.shortest_lengths(big0, big1, 1.0, threads=1))
    assert seconds > 0.02 and ticks >= 3, (ticks, seconds)


@pytest.mark.parametrize(
    ("call", "field"),
    [
        (lambda: dubins.shortest_path((0, 0, 0), (1, 1, 0), 0.0), "rho"),
        (lambda: dubins.shortest_path((0, 0, 0), (1, 1, 0), -2.0), "rho = -2"),
        (lambda: dubins.shortest_path((0, float("nan"), 0), (1, 1, 0), 1.0), "q0.y"),
        (lambda: dubins.shortest_length((0, 0, 0), (1, 1, float("inf")), 1.0), "q1.psi"),
        (lambda: dubins.shortest_length((0, 0, 0), (1, 1, 0), 0.0), "rho"),
        (lambda: dubins.shortest_lengths(np.zeros((3, 3)), np.zeros((3, 3)), 1.0, threads=-1), "threads"),
        (lambda: dubins.path((0, 0, 0), (1, 1, 0), 1.0, "LLL"), "word"),
        (lambda: dubins.path((0, 0, 0), (100, 0, 0), 1.0, "RLR"), "word"),
        (lambda: dubins.shortest_lengths(np.zeros((3, 2)), np.zeros((3, 3)), 1.0), "q0s"),
        (lambda: dubins.shortest_lengths(np.zeros((3, 3)), np.zeros((4, 3)), 1.0), "q1s.shape[0]"),
        (lambda: dubins.shortest_lengths(np.zeros((3, 3)), np.array([[0, 0, 0], [1, np.inf, 0], [0, 0, 0]]), 1.0),
         "q1s[1].y"),
        (lambda: dubins.path_to_circle((0, 0, 0), 1.0, (5, 5), 1.0, 0.0, "up"), "direction"),
        (lambda: dubins.path_to_circle((0, 0, 0), 1.0, (5, 5), -1.0, 0.0, "cw"), "radius = -1"),
        (lambda: dubins.intercept_circle((0, 0, 0), 1.0, 0.0, (5, 5), 1.0, 0.0, 1.0), "pursuer_speed"),
        (lambda: dubins.intercept_circle((0, 0, 0), 1.0, 1.0, (5, 5), 1.0, 0.0, float("nan")), "target_speed"),
        (lambda: dubins.shortest_path((0, 0, 0), (3, 0, 0), 1.0).at(5.0), "s = 5"),
    ],
)
def test_bad_input_names_the_field(call, field: str) -> None:
    with pytest.raises(VistrackError, match=field.replace("[", r"\[").replace("]", r"\]").replace(".", r"\.")):
        call()


# ---- path to a circle ------------------------------------------------------------------------

CENTER = (12.0, -7.0)
RADIUS = 3.0
START = (0.5, 1.0, 0.7)


@pytest.mark.parametrize("direction", ["cw", "ccw"])
def test_path_to_circle_arrives_tangent(direction: str) -> None:
    for angle in np.linspace(-4, 4, 17):
        p = dubins.path_to_circle(START, 1.0, CENTER, RADIUS, angle, direction)
        x, y, psi = p.goal
        assert (x, y) == pytest.approx((CENTER[0] + RADIUS * math.cos(angle), CENTER[1] + RADIUS * math.sin(angle)))
        tangent = angle - math.pi / 2 if direction == "cw" else angle + math.pi / 2
        assert math.remainder(psi - tangent, 2 * math.pi) == pytest.approx(0.0, abs=1e-12)
        # The end of the integrated path is the goal (sampled just before the exact last row).
        before = p.sample_at([p.length * (1 - 1e-12)])[0]
        assert math.hypot(before[0] - x, before[1] - y) < 1e-9


def test_length_to_circle_is_continuous_and_periodic_under_four_rho() -> None:
    assert dubins.four_rho_condition(START[:2], 1.0, CENTER, RADIUS)
    angles = np.linspace(0.0, 2 * np.pi, 20001)
    for direction in ("cw", "ccw"):
        d = dubins.length_to_circle(START, 1.0, CENTER, RADIUS, angles, direction)
        csc = dubins.length_to_circle(START, 1.0, CENTER, RADIUS, angles, direction, csc_only=True)
        # Under the 4 rho condition the shortest word is CSC (paper, Section II).
        assert np.allclose(d, csc, rtol=0, atol=1e-12)
        # Continuity (Theorem 1): neighbouring samples h = 3.1e-4 rad apart differ by at most
        # (r + 2 rho + |p - C|) h, far below a 2 pi rho jump.
        h = angles[1] - angles[0]
        bound = (RADIUS + 2.0 + math.hypot(CENTER[0] - START[0], CENTER[1] - START[1])) * h
        assert np.abs(np.diff(d)).max() <= bound
        # Period exactly 2 pi.
        shifted = dubins.length_to_circle(START, 1.0, CENTER, RADIUS, angles + 2 * np.pi * 3, direction)
        assert np.allclose(shifted, d, atol=1e-9)


def test_csc_branches_are_discontinuous_but_their_minimum_is_not() -> None:
    # Lemma 1/2: single words jump by 2 pi rho where an arc disappears; the minimum does not.
    angles = np.linspace(0.0, 2 * np.pi, 4001)
    lsl = np.array([dubins.word_lengths(START, dubins.path_to_circle(START, 1.0, CENTER, RADIUS, a).goal, 1.0)["LSL"]
                    for a in angles])
    assert np.abs(np.diff(lsl)).max() > 5.0  # a ~2 pi jump somewhere on the circle


# ---- intercept -------------------------------------------------------------------------------


def brute_force_intercept(pursuer, rho, vp, center, radius, alpha0, vt_, direction, dt=2e-4, t_max=200.0):
    """First time T on a grid with D(alpha(T)) <= v_p T (the pursuer can be there in time)."""
    sign = -1.0 if direction == "cw" else 1.0
    times = np.arange(0.0, t_max, dt)
    angles = alpha0 + sign * vt_ * times / radius
    d = dubins.length_to_circle(pursuer, rho, center, radius, angles, direction)
    ok = np.nonzero(d <= vp * times)[0]
    assert ok.size, "no interception within t_max"
    return times[ok[0]]


@pytest.mark.parametrize(
    "case",
    [
        {"pursuer": (0, 0, 0), "rho": 1.0, "vp": 1.0, "center": (-4, 3), "radius": 1.0, "alpha0": math.pi, "vt": 1.2,
         "direction": "cw"},
        {"pursuer": (0, 0, 0), "rho": 1.0, "vp": 1.0, "center": (-4, 3), "radius": 1.0, "alpha0": math.pi, "vt": 1.2,
         "direction": "ccw"},
        {"pursuer": (2, -1, 2.0), "rho": 0.5, "vp": 2.0, "center": (10, 4), "radius": 3.0, "alpha0": 0.3, "vt": 1.0,
         "direction": "cw"},
        {"pursuer": (2, -1, -1.0), "rho": 0.8, "vp": 1.0, "center": (-6, 8), "radius": 2.0, "alpha0": -2.0, "vt": 3.0,
         "direction": "ccw"},
        {"pursuer": (0, 0, 0), "rho": 1.0, "vp": 1.0, "center": (1.5, 0.5), "radius": 2.0, "alpha0": 1.0, "vt": 0.7,
         "direction": "cw"},
    ],
)
def test_intercept_against_brute_force(case: dict) -> None:
    r = dubins.intercept_circle(case["pursuer"], case["rho"], case["vp"], case["center"], case["radius"],
                                case["alpha0"], case["vt"], case["direction"])
    t_brute = brute_force_intercept(case["pursuer"], case["rho"], case["vp"], case["center"], case["radius"],
                                    case["alpha0"], case["vt"], case["direction"])
    assert r.time == pytest.approx(t_brute, abs=2e-4 + 1e-9)
    # Equal travel times, and the target really is at the path's goal at that time.
    assert r.path.length / case["vp"] == pytest.approx(r.time, abs=1e-9)
    sign = -1.0 if case["direction"] == "cw" else 1.0
    a = case["alpha0"] + sign * case["vt"] * r.time / case["radius"]
    gx, gy, _ = r.path.goal
    assert (gx, gy) == pytest.approx((case["center"][0] + case["radius"] * math.cos(a),
                                      case["center"][1] + case["radius"] * math.sin(a)), abs=1e-9)
    assert r.period == pytest.approx(2 * math.pi)
    near = math.hypot(case["pursuer"][0] - case["center"][0], case["pursuer"][1] - case["center"][1])
    assert r.four_rho_condition == (abs(near - case["radius"]) > 4 * case["rho"])


# ---- standalone executable -------------------------------------------------------------------


def test_vistrack_dubins_csv(tmp_path) -> None:
    import subprocess

    exe = standalone_executable("vistrack_dubins")
    if exe is None:
        pytest.skip("vistrack_dubins not built (set VISTRACK_BUILD_DIR or install the package)")
    rng = np.random.default_rng(8)
    q0 = rng.uniform(-20, 20, (500, 3))
    q1 = rng.uniform(-20, 20, (500, 3))
    source = tmp_path / "pairs.csv"
    lines = ["x0,y0,psi0,x1,y1,psi1"] + [",".join(repr(float(v)) for v in (*a, *b)) for a, b in zip(q0, q1)]
    source.write_text("\n".join(lines) + "\n")
    out = tmp_path / "out.csv"
    done = subprocess.run([exe, "--rho", "2.5", "--segments", "-o", str(out), str(source)], capture_output=True,
                          text=True)
    assert done.returncode == 0, done.stderr
    rows = out.read_text().splitlines()
    assert rows[0] == "length,word,seg1,seg2,seg3" and len(rows) == 501
    lengths, words = dubins.shortest_lengths(q0, q1, 2.5)
    for i, row in enumerate(rows[1:]):
        length, word, *segments = row.split(",")
        assert float(length) == pytest.approx(lengths[i], rel=1e-15, abs=1e-15)
        assert word == dubins.WORDS[words[i]]
        assert sum(map(float, segments)) == pytest.approx(float(length), rel=1e-12)
    # Bad input: a clear message naming the line and column, exit code 2, input untouched.
    bad = tmp_path / "bad.csv"
    bad.write_text("0,0,0,1,1,0\n0,0,nan,1,1,0\n")
    done = subprocess.run([exe, "--rho", "1", str(bad)], capture_output=True, text=True)
    assert done.returncode == 2 and "bad.csv:2 psi0" in done.stderr
    assert bad.read_text() == "0,0,0,1,1,0\n0,0,nan,1,1,0\n"
    done = subprocess.run([exe, "--rho", "-1", str(source)], capture_output=True, text=True)
    assert done.returncode == 2 and "--rho = -1" in done.stderr


def test_huge_thread_counts_are_refused_not_a_segfault() -> None:
    """shortest_lengths(..., threads=100000) killed the interpreter with SIGSEGV."""
    q0, q1 = np.zeros((4, 3)), np.ones((4, 3))
    for threads in (100000, 2**31 - 1, -1):
        refuses(lambda t=threads: vt.dubins.shortest_lengths(q0, q1, 2.0, threads=t), f"threads = {threads}")
    lengths, _ = vt.dubins.shortest_lengths(q0, q1, 2.0, threads=1024)
    assert np.all(np.isfinite(lengths))


def test_huge_thread_count_in_a_fresh_interpreter() -> None:
    """The same call in its own process: it exits normally (a SIGSEGV would be returncode -11)."""
    code = ("import numpy as np, vistrack as vt\n"
            "try:\n vt.dubins.shortest_lengths(np.zeros((4,3)), np.ones((4,3)), 2.0, threads=100000)\n"
            "except vt.VistrackError as e:\n print(e)\n")
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    preload = "import sys; sys.path.insert(0, %r); import support.build_tree\n" % str(Path(__file__).resolve().parent)
    done = subprocess.run([sys.executable, "-c", preload + code], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert "threads = 100000" in done.stdout


@pytest.mark.parametrize("rho", [5e-324, 1e-300, 1e308, math.inf, math.nan, 0.0, -1.0])
def test_dubins_turn_radius_out_of_range(rho: float) -> None:
    """shortest_path((0,0,0),(10,5,1.0),5e-324).length was NaN; 1e-300 or 1e308 gave inf."""
    refuses(lambda: vt.dubins.shortest_path((0, 0, 0), (10, 5, 1.0), rho), "rho = ", "[1e-06, 1e+07] m")


def test_dubins_far_coordinates_and_huge_circles() -> None:
    """Coordinates 1e300 and path_to_circle(..., radius=1e300) gave inf."""
    refuses(lambda: vt.dubins.shortest_path((0, 0, 0), (1e300, 5, 1.0), 1.0), "q1.x = 1e+300")
    refuses(lambda: vt.dubins.path_to_circle((0, 0, 0), 1.0, (10, 0), 1e300, 0.5, "cw"), "radius = 1e+300")
    # Far from the origin on the scale of rho: refused naming rho and how far it may be.
    refuses(lambda: vt.dubins.shortest_path((2.6e6, 0, 0), (2.6e6 + 1, 0, 1.0), 1e-5), "rho = 1e-05",
            "translate the problem nearer the origin")
