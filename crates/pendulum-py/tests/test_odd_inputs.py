"""Odd inputs through every analysis of the Python module: NaN, infinities,
zeros, negatives, 1e±300, counts past 2**63. Each call answers with finite
numbers only or raises ValueError naming its keyword; nothing panics,
overflows into OverflowError or hangs."""

import math
import random

import pytest

import pendulum_theory as pt

ODD = [0.0, -0.0, -1.0, 1e-300, 1e300, float("nan"), float("inf"), -float("inf"), 1.0, 0.5,
       3.14159, 1e-9, 1e9, 2.0, 86400.0, -86400.0, 7.0]

def pick():
    return random.choice(ODD)

def finite(x, path=""):
    """Asserts every number in `x` is finite."""
    if isinstance(x, float):
        assert math.isfinite(x), path
    elif isinstance(x, dict):
        for k, v in x.items():
            finite(v, path + "." + k)
    elif isinstance(x, (list, tuple)):
        for i, v in enumerate(x):
            finite(v, f"{path}[{i}]")

ROD = {"name": "rod", "shape": "rod", "material": "steel", "length": 1.0, "diameter": 0.008, "centre": 0.5}
BOB = {"name": "bob", "shape": "cylinder", "material": "brass", "length": 0.1, "diameter": 0.1, "centre": 0.95}

calls = {
    "period_table": lambda: pt.period_table(pick(), pick(), g=pick(), series_terms=random.choice([None, 0, 1, 5, -3])),
    "period_range": lambda: pt.period_table(pick(), amplitude_range=(pick(), pick()), steps=random.choice([None, 2, 3, -1])),
    "length": lambda: pt.length(pick(), amplitude=pick(), g=pick()),
    "length_bph": lambda: pt.length(bph=pick(), g=pick()),
    "amplitude": lambda: pt.amplitude(pick(), pick(), period_uncertainty=pick(), g=pick()),
    "damped": lambda: pt.damped(pick(), pick(), q=pick(), friction_angle=random.choice([None, pick()]), mass=random.choice([None, pick()]), extrema=random.choice([None, 0, 3, -5])),
    "damped_c": lambda: pt.damped(1.0, 0.1, damping_coefficient=pick(), mass=pick()),
    "train": lambda: pt.train([random.choice([0, 8, 64, 10**6]) for _ in range(3)], [random.choice([0, 8, 10**6]) for _ in range(2)], arbor_turns_per_hour=pick(), g=pick()),
    "train_for": lambda: pt.train_for(pick(), escape_teeth=random.choice([None, 0, 30, 10**9]), tolerance=pick()),
    "design": lambda: pt.design([{**ROD, "length": pick()}, {**BOB, "diameter": pick(), "centre": pick()}], temperature=pick(), pressure_hpa=pick(), humidity=pick(), g=pick()),
    "regulate": lambda: pt.regulate(pick(), length=pick(), nut_pitch=random.choice([None, pick()]), nut_tpi=random.choice([None, pick()])),
    "regulate_design": lambda: pt.regulate(pick(), parts=[ROD, BOB], part="bob", tray=random.choice([None, pick()])),
    "compensate": lambda: pt.compensate([ROD, BOB], random.choice(["zinc", "gridiron", "mercury", "collar", "x"]), jar_diameter=random.choice([None, pick()]), tube_bore=random.choice([None, pick()])),
    "clock": lambda: pt.clock(pick(), drive_energy=pick(), q=pick(), lift_angle=random.choice([None, pick()]), mass=random.choice([None, pick()])),
    "clock_iso": lambda: pt.clock(0.99362, drive_energy=2e-5, drive_range=(pick(), pick()), steps=random.choice([None, 2, 3])),
    "clock_run": lambda: pt.clock_run(0.99362, pick(), every=random.choice([None, pick()]), drive_energy=2e-5),
    "simulate_drag": lambda: pt.simulate(0.99362, 0.1, 10.0, drag={"three_halves_drag": pick()}, method=random.choice(["dop853", "symplectic"])),
    "listen": lambda: pt.listen([random.uniform(-1, 1) for _ in range(2000)], pick()),
}

HUGE = 10**30


@pytest.mark.parametrize("name", sorted(calls))
def test_odd_inputs(name):
    random.seed(sum(map(ord, name)))
    for _ in range(25):
        try:
            r = calls[name]()
        except ValueError as e:
            assert str(e), name
            continue
        finite(r[0] if isinstance(r, tuple) else r, name)


@pytest.mark.parametrize("call", [
    lambda: pt.train([HUGE, 8], [8]),
    lambda: pt.train([-64, 8], [8]),
    lambda: pt.regulate(12, length=1, nut_pitch=7e-4, nut_divisions=-3),
    lambda: pt.period_table(1, 0.1, series_terms=HUGE),
    lambda: pt.period_table(1, amplitude_range=(0.1, 0.2), steps=-HUGE),
    lambda: pt.damped(1, 0.1, q=100, extrema=HUGE),
    lambda: pt.clock(1, drive_energy=2e-5, every_beats=HUGE, escapement="free"),
    lambda: pt.clock(1, drive_energy=2e-5, steps=-1, drive_range=(0.5, 2)),
])
def test_counts_out_of_range_are_value_errors(call):
    with pytest.raises(ValueError):
        call()


@pytest.mark.parametrize("call, keyword", [
    (lambda: pt.clock(1.0, drive_energy=2e-5, beat_error=True), "beat_error"),
    (lambda: pt.clock_run(1.0, 86400.0, drive_energy=2e-5, q=False), "q"),
    (lambda: pt.period(True, 0.1), "length"),
    (lambda: pt.design([ROD, BOB], humidity=True), "humidity"),
    (lambda: pt.clock_run(1.0, 86400.0, drive_energy=2e-5,
                          drive_schedule=([0.0, 3600.0], [1.0, True])), "drive_schedule"),
    (lambda: pt.train([True, 60, 30], [8, 8]), "wheels"),
    (lambda: pt.exact_angle([0.0, True], 1.0, 0.1), "t"),
    (lambda: pt.period(__import__("numpy").array([True, False]), 0.1), "length"),
])
def test_true_and_false_are_not_numbers(call, keyword):
    """Python takes True for 1: ``beat_error=True`` was a beat error of a
    second. Every function refuses a boolean where it takes a number."""
    with pytest.raises(ValueError, match=f"^{keyword}: must be a number"):
        call()
    assert pt.stability([0.0, 1.0, 2.0, 4.0] * 8, 1.0, force=True) is not None


@pytest.mark.parametrize("bad", [float("nan"), float("inf"), -float("inf")])
def test_a_non_finite_size_in_a_design_names_its_field(bad):
    """NaN in a design's dict gave the JSON reader's "expected value at line
    1 column 74"; it is refused as the command line refuses ``nan`` in a
    design file: by the part and the field."""
    with pytest.raises(ValueError, match="^part 'rod': length: must be a finite number"):
        pt.design([dict(ROD, length=bad), BOB])
