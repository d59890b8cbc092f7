//! The suspension spring against the closed forms of its limits, and the
//! statements of the literature it reproduces.

use pendulum_theory::suspension::{effect, Body, Strip};

const G: f64 = 9.80665;

/// A regulator's spring: steel, 15 mm long, 12 mm wide, 0.1 mm thick.
fn spring(length: f64, thickness: f64) -> Strip {
    Strip {
        length,
        width: 0.012,
        thickness,
        modulus: 2.0e11,
    }
}

fn close(a: f64, b: f64, tol: f64) {
    assert!(
        (a / b - 1.0).abs() <= tol,
        "{a} against {b} (tolerance {tol})"
    );
}

/// Without tension the strip is a cantilever: its end stiffnesses are
/// `12EI/L³`, `-6EI/L²`, `4EI/L` (any strength-of-materials text, e.g.
/// Timoshenko & Gere §1.11 with the axial force zero); the tension's first
/// correction is the geometric stiffness `T/(30L) [36, -3L, 4L²]`
/// (Przemieniecki, *Theory of Matrix Structural Analysis*, 1968, §15.2),
/// which this checks at a tension where the next term is 1e-7 of it.
#[test]
fn a_strip_without_tension_is_a_cantilever() {
    let s = spring(0.015, 1e-4);
    let (l, ei): (f64, f64) = (s.length, s.bending_stiffness());
    let t = 1e-6 * ei / (l * l);
    let k = s.stiffness(t);
    let cantilever = [12.0 * ei / l.powi(3), -6.0 * ei / (l * l), 4.0 * ei / l];
    let geometric = [36.0 * t / (30.0 * l), -3.0 * t / 30.0, 4.0 * l * t / 30.0];
    for i in 0..3 {
        close(k[i], cantilever[i] + geometric[i], 1e-9);
    }
}

/// A point mass at the end of a strip clamped at the top: the strip
/// bends within `λ` of the clamp and hangs straight below, so the mass
/// swings on `L - λ tanh(L/λ)` (the lateral stiffness of a tensioned
/// strip with a free end, solved in closed form; Saulson 1990 gives its
/// long-strip form `L - λ`), and the elastic share `∂ ln ω²/∂ ln EI` is
/// `½ λ (tanh a - a sech² a) / (L - λ tanh a)`, `a = L/λ`.
#[test]
fn a_point_mass_hangs_from_a_point_lambda_below_the_clamp() {
    for (length, thickness) in [(0.015, 1e-4), (0.3, 5e-5), (0.01, 4e-4), (0.002, 3e-4)] {
        let s = spring(length, thickness);
        let body = Body {
            mass: 8.0,
            centre: 0.0,
            inertia: 0.0,
        };
        let e = effect(&s, &body, G).unwrap();
        let lambda = (s.bending_stiffness() / (8.0 * G)).sqrt();
        let a = length / lambda;
        let l_eff = length - lambda * a.tanh();
        close(e.omega, (G / l_eff).sqrt(), 1e-12);
        close(e.bending_length, lambda, 1e-15);
        let share = 0.5 * lambda * (a.tanh() - a / a.cosh().powi(2)) / l_eff;
        close(e.elastic_share, share, 1e-7);
        assert!(e.second_mode_hz.is_none());
    }
}

/// A strip of no stiffness is a string: the rigid pendulum below it is a
/// double pendulum whose upper link has no mass, `det([[T/L, 0], [0, M g
/// d]] - ω² [[M, M d], [M d, M d² + I_c]]) = 0` in the string's bottom
/// displacement and the body's angle. (A strip of great stiffness is not
/// a rigid pivot but a cantilever the pendulum must bend: clamped in the
/// chops, it swings only as far as it flexes.)
#[test]
fn a_strip_of_no_stiffness_is_a_string() {
    let body = Body {
        mass: 8.0,
        centre: 0.9,
        inertia: 8.0 * 0.05 * 0.05 / 2.0,
    };
    let length: f64 = 0.015;
    let (m, d, ic) = (body.mass, body.centre, body.inertia);
    // A modulus that makes λ = 1e-9 L.
    let t = m * G;
    let floppy = Strip {
        modulus: (1e-9 * length).powi(2) * t * 12.0 / (0.012 * 1e-12),
        ..spring(length, 1e-4)
    };
    let e = effect(&floppy, &body, G).unwrap();
    let (k11, k22) = (t / length, m * G * d);
    let (a, b, c) = (m * ic, m * k22 + (m * d * d + ic) * k11, k11 * k22);
    let string = (b - (b * b - 4.0 * a * c).sqrt()) / (2.0 * a);
    close(e.omega, string.sqrt(), 1e-6);
}

/// A seconds pendulum of 8 kg on a regulator's spring: it turns about a
/// point close to `λ` below the chops (to the order of `λ/l`), the spring
/// gains by about `λ/l` of a day (86,400 λ/(2 l) s/day from the shorter
/// pendulum plus as much from the bending), and its elastic share is
/// about `λ/(2l)`.
#[test]
fn a_regulators_spring() {
    let s = spring(0.015, 1e-4);
    let body = Body {
        mass: 8.0,
        centre: 0.98,
        inertia: 8.0 * 0.06 * 0.06 / 4.0,
    };
    let e = effect(&s, &body, G).unwrap();
    let lambda = e.bending_length;
    assert!((1e-3..2e-3).contains(&lambda), "{lambda}");
    let l = s.length + body.centre;
    assert!((e.effective_pivot / lambda - 1.0).abs() < 0.05, "{e:?}");
    assert!(
        (e.elastic_share / (lambda / (2.0 * l)) - 1.0).abs() < 0.05,
        "{e:?}"
    );
    let expected = 86_400.0 * 0.5 * e.elastic_share * 2.0;
    assert!(
        e.rate > 0.0 && (e.rate / expected - 1.0).abs() < 0.1,
        "{e:?}"
    );
    assert!(e.second_mode_hz.unwrap() > 10.0, "{e:?}");
}

/// Bad strips are refused by field, never a non-finite number.
#[test]
fn bad_strips_are_refused() {
    let body = Body {
        mass: 8.0,
        centre: 0.98,
        inertia: 0.01,
    };
    for (strip, field) in [
        (spring(0.0, 1e-4), "length"),
        (spring(0.015, -1e-4), "thickness"),
        (spring(f64::NAN, 1e-4), "length"),
        (
            Strip {
                modulus: 0.0,
                ..spring(0.015, 1e-4)
            },
            "modulus",
        ),
    ] {
        let e = effect(&strip, &body, G).unwrap_err();
        assert_eq!(e.field_name(), Some(field), "{e}");
    }
    let e = effect(
        &spring(0.015, 1e-4),
        &Body {
            centre: -1.0,
            ..body
        },
        G,
    )
    .unwrap_err();
    assert_eq!(e.field_name(), Some("centre"), "{e}");
}

/// A strip clamped at both ends, its bottom moved sideways without
/// turning: González's stiffness of a suspension wire clamped at both
/// ends (Class. Quantum Grav. 17, 4409, 2000, eq. 9, as pygwinc's
/// `suspQuad` uses it) tends at low frequency to `T / (L - 2λ)`, the
/// strip shortened by a bending length at each end; exactly it is `T / (L
/// - 2λ tanh(L/2λ))`, which differs by `e^{-L/λ}`.
#[test]
fn a_strip_clamped_at_both_ends_is_two_bending_lengths_shorter() {
    for (length, thickness, tension) in [(0.015, 1e-4, 80.0), (0.6, 4e-4, 200.0), (0.3, 1e-4, 20.0)]
    {
        let s = spring(length, thickness);
        let lambda = (s.bending_stiffness() / tension).sqrt();
        let k = s.stiffness(tension)[0];
        close(
            k,
            tension / (length - 2.0 * lambda),
            2.0 * (-length / lambda).exp() + 1e-14,
        );
        // González's formula itself at a frequency far below the wire's
        // own (k L = 1e-5): a steel strip's density, 7850 kg/m³.
        let wave = 1e-5 / length;
        let kd = wave * lambda;
        let gonzalez =
            tension * wave * (1.0 + kd * kd) * ((wave * length).cos() + kd * (wave * length).sin())
                / ((1.0 - kd * kd) * (wave * length).sin() - 2.0 * kd * (wave * length).cos());
        close(k, gonzalez, 2.0 * (-length / lambda).exp() + 1e-9);
    }
}

use crate::common;
use common::parts::{cylinder, part};
use pendulum_theory::compound::{CompoundPendulum, Placement, Shape};

/// A design hanging from a spring: the spring `thickness` thick, an
/// Invar rod clamped below it and a brass bob held at its centre on the
/// rod (no compensation: the rod's expansion alone, 0.65e-6/K).
fn regulator(thickness: f64, massless_spring: bool) -> CompoundPendulum {
    let spring = pendulum_theory::compound::Part {
        massless: massless_spring,
        ..spring_part(thickness, "steel", 0.0075)
    };
    CompoundPendulum::new(vec![
        spring,
        part(
            "rod",
            cylinder(1.0, 0.008, 0.0),
            "invar",
            Placement::Centre(0.515),
        ),
        part(
            "bob",
            cylinder(0.1, 0.1, 0.0),
            "brass",
            Placement::Centre(0.965),
        ),
    ])
    .unwrap()
}

/// A spring 15 mm long, 12 mm wide and `thickness` thick, of `material`,
/// its centre `centre` below the pivot.
fn spring_part(thickness: f64, material: &str, centre: f64) -> pendulum_theory::compound::Part {
    part(
        "spring",
        Shape::Spring {
            length: 0.015,
            width: 0.012,
            thickness,
        },
        material,
        Placement::Centre(centre),
    )
}

/// Through the design: a point mass at the bottom of a massless spring
/// has the equivalent length `L - λ tanh(L/λ)` of the closed form above,
/// `λ = sqrt(EI / M g)` in the gravity it hangs in.
/// A spring not hanging from the pivot, or of a material without its
/// modulus's temperature coefficient, is refused by field.
#[test]
fn a_design_hanging_from_a_spring() {
    let spring = pendulum_theory::compound::Part {
        massless: true,
        ..spring_part(1e-4, "steel", 0.0075)
    };
    let bob = pendulum_theory::compound::Part {
        point_mass: 8.0,
        ..part("bob", Shape::Point, "steel", Placement::Centre(0.015))
    };
    let design = CompoundPendulum::new(vec![spring, bob]).unwrap();
    let lambda = (2e11 * 0.012 * 1e-12 / 12.0 / (8.0 * G)).sqrt();
    close(
        design.properties().equivalent_length,
        0.015 - lambda * (0.015 / lambda).tanh(),
        1e-12,
    );
    // In the Moon's gravity the tension is a sixth: the bending length
    // grows by sqrt(6) and the spring's share with it (a new user's find:
    // the design's spring was always taken in standard gravity).
    let moon: f64 = 1.62;
    let lambda = (2e11 * 0.012 * 1e-12 / 12.0 / (8.0 * moon)).sqrt();
    let there = design.in_gravity(moon);
    close(
        there.properties().equivalent_length,
        0.015 - lambda * (0.015 / lambda).tanh(),
        1e-12,
    );
    assert!(
        there.spring_effect().unwrap().elastic_share
            > 2.0 * design.spring_effect().unwrap().elastic_share
    );
    // Derived designs keep it.
    assert_eq!(there.at_temperature(1.0).unwrap().gravity(), moon);
    let bob = || {
        part(
            "bob",
            cylinder(0.1, 0.1, 0.0),
            "brass",
            Placement::Centre(0.5),
        )
    };
    let clamped = || {
        part(
            "rod",
            cylinder(0.5, 0.008, 0.0),
            "steel",
            Placement::Centre(0.265),
        )
    };
    for (spring, field) in [
        (spring_part(1e-4, "steel", 0.01), "centre"),
        (spring_part(1e-4, "brass", 0.0075), "modulus_coefficient"),
        (spring_part(1e-4, "lead", 0.0075), "material"),
    ] {
        let e = CompoundPendulum::new(vec![spring, clamped()]).unwrap_err();
        assert_eq!((e.part.as_str(), e.field), ("spring", field), "{e}");
    }
    // Geometry: the rod clamped at the spring's bottom, nothing reaching
    // into it, nothing resting on it, one spring, and something below it.
    let steel = || spring_part(1e-4, "steel", 0.0075);
    let cases: Vec<(Vec<pendulum_theory::compound::Part>, &str, &str)> = vec![
        (vec![steel(), bob()], "spring", "length"),
        (
            vec![
                steel(),
                part(
                    "rod",
                    cylinder(0.5, 0.008, 0.0),
                    "steel",
                    Placement::Centre(0.26),
                ),
            ],
            "spring",
            "length",
        ),
        (
            vec![
                steel(),
                clamped(),
                part(
                    "nut",
                    cylinder(0.01, 0.02, 0.0),
                    "steel",
                    Placement::RestsOn(0),
                ),
            ],
            "nut",
            "rests_on",
        ),
        (
            vec![steel(), clamped(), spring_part(1e-4, "steel", 0.0075)],
            "spring",
            "shape",
        ),
        (vec![steel()], "spring", "shape"),
    ];
    for (parts, name, field) in cases {
        let e = CompoundPendulum::new(parts).unwrap_err();
        assert_eq!((e.part.as_str(), e.field), (name, field), "{e}");
    }
    assert!(CompoundPendulum::new(vec![steel(), clamped(), bob()]).is_ok());
}

/// "Anywhere from 16% to 84% of a pendulum's total temperature
/// sensitivity is due to the suspension spring, with the actual amount
/// depending on the spring's dimensions, modulus of elasticity, and
/// suspended weight" (Matthys, Accurate Clock Pendulums, 2004, ch. 16,
/// from James's equations): an uncompensated Invar seconds pendulum of 6
/// kg on steel springs 0.1 to 0.3 mm thick (a regulator's) falls in that
/// range, the thicker spring the larger share; a spring as thin as 0.03
/// mm would fall below it.
#[test]
fn the_springs_share_of_the_temperature_coefficient() {
    let share = |thickness: f64| {
        let d = regulator(thickness, false);
        let total = d.temperature_coefficient();
        let spring = total
            - d.without_spring_thermoelasticity()
                .temperature_coefficient();
        assert!(total < 0.0 && spring < 0.0, "{total} {spring}");
        spring / total
    };
    let shares: Vec<f64> = [1e-4, 2e-4, 3e-4].iter().map(|&t| share(t)).collect();
    assert!(
        shares.iter().all(|s| (0.16..=0.84).contains(s)),
        "{shares:?}"
    );
    assert!(shares.windows(2).all(|w| w[1] > w[0]), "{shares:?}");
    assert!(share(3e-5) < 0.16);
}

/// The spring's own expansion moves what hangs below it: a design on a
/// steel spring warmed by 10 °C is the rigid design whose parts below the
/// spring were lowered by the spring's growth (its length times steel's
/// 11.5e-6/K) and grew with the rod, its modulus 0.25% lower.
#[test]
fn what_hangs_from_the_spring_moves_with_it() {
    let cold = regulator(1e-4, true);
    let warm = cold.at_temperature(10.0).unwrap();
    let grown = 0.015 * 11.5e-6 * 10.0;
    // The rod's centre: the spring's new bottom, then half the warmed rod.
    let rod_half = 0.5 * 1.0 * (1.0 + 0.65e-6 * 10.0);
    close(warm.centres()[1], 0.015 + grown + rod_half, 1e-12);
    assert!((warm.centres()[0] - 0.5 * (0.015 + grown)).abs() < 1e-15);
}

/// The quarter period, in scaled time, of `θ'' = -[(1 - ε) sin θ + ε θ]`
/// from rest at `a`: classical fourth-order Runge-Kutta with steps of 1e-4
/// (its error, of order h⁴, below 1e-14 here), the crossing of zero found
/// by the secant method on a last partial step.
fn quarter_period_integrated(a: f64, e: f64) -> f64 {
    let f = |y: [f64; 2]| [y[1], -((1.0 - e) * y[0].sin() + e * y[0])];
    let step = |y: [f64; 2], h: f64| {
        let k1 = f(y);
        let k2 = f([y[0] + 0.5 * h * k1[0], y[1] + 0.5 * h * k1[1]]);
        let k3 = f([y[0] + 0.5 * h * k2[0], y[1] + 0.5 * h * k2[1]]);
        let k4 = f([y[0] + h * k3[0], y[1] + h * k3[1]]);
        [
            y[0] + h / 6.0 * (k1[0] + 2.0 * k2[0] + 2.0 * k3[0] + k4[0]),
            y[1] + h / 6.0 * (k1[1] + 2.0 * k2[1] + 2.0 * k3[1] + k4[1]),
        ]
    };
    let h = 1e-4;
    let (mut t, mut y) = (0.0, [a, 0.0]);
    loop {
        let next = step(y, h);
        if next[0] <= 0.0 {
            let (mut lo, mut hi) = (0.0, h);
            let (mut flo, mut fhi) = (y[0], next[0]);
            for _ in 0..60 {
                let mid = hi - fhi * (hi - lo) / (fhi - flo);
                let fm = step(y, mid)[0];
                if fm.abs() < 1e-17 || (hi - lo) < 1e-16 {
                    return t + mid;
                }
                (lo, flo, hi, fhi) = (hi, fhi, mid, fm);
            }
            return t + hi;
        }
        (t, y) = (t + h, next);
    }
}

/// The period of a pendulum on a spring at a finite swing
/// ([`pendulum_theory::suspension::period_ratio`]): with no elastic share
/// it is the crate's AGM (the exact period of a rigid pendulum) within
/// 4e-16 up to 150°; all elastic it is 1 (a linear oscillator); its
/// growth at small swings is `(1 - ε) A²/16`; and at 10° and 60° for
/// shares 0.01, 0.3 and 0.9 it is the integrated equation of motion's
/// within 1e-11.
#[test]
fn a_spring_shrinks_the_circular_error() {
    use pendulum_theory::suspension::period_ratio;
    use pendulum_theory::Amplitude;
    for deg in [0.5, 3.0, 10.0, 45.0, 90.0, 150.0] {
        let a = f64::to_radians(deg);
        let agm = pendulum_theory::period::period_ratio(Amplitude::from_radians(a).unwrap());
        let ours = period_ratio(a, 0.0);
        assert!((ours / agm - 1.0).abs() < 4e-16, "{deg}: {ours} {agm}");
        assert_eq!(period_ratio(a, 1.0), 1.0);
    }
    let a = 1e-3;
    for e in [0.0, 0.2, 0.7] {
        let slope = (period_ratio(a, e) - 1.0) / (a * a / 16.0);
        assert!((slope - (1.0 - e)).abs() < 1e-6, "{e}: {slope}");
    }
    for deg in [10.0, 60.0] {
        for e in [0.01, 0.3, 0.9] {
            let a = f64::to_radians(deg);
            let integrated = quarter_period_integrated(a, e) / std::f64::consts::FRAC_PI_2;
            let ours = period_ratio(a, e);
            eprintln!("{deg}°, share {e}: {ours:.15} against {integrated:.15}");
            assert!((ours / integrated - 1.0).abs() < 1e-11, "{deg} {e}");
        }
    }
}

/// A clock on a stiff spring (0.6 mm: an elastic share of a few per cent)
/// driven by Airy's impulse at the bottom of the swing, which leaves the
/// period alone: its free period at the steady arc is the integrated
/// equation of motion's with the spring's linear torque
/// (`quarter_period_integrated`, within 1e-11), smaller than a rigid
/// pendulum's by the elastic share of the circular error; the clock's own
/// period is that lengthened by the damping's `1/(8Q²)` within 1e-11; and a
/// day's long run a row an hour, regulated to the steady period, ends
/// within 1e-6 s/day of it (the long run's half swings carry the spring's
/// factor too: without it they would lose the share of the circular
/// error, 0.9 s/day).
#[test]
fn a_clock_on_a_spring_keeps_the_smaller_circular_error() {
    use pendulum_theory::clock::analysis::{analyse, ClockInput, ClockPendulum, NoRows, RunInput};
    use pendulum_theory::clock::escapement::spec::{Drive, Kind};
    let design = regulator(6e-4, false);
    let share = design.spring_effect().unwrap().elastic_share;
    assert!((0.01..0.2).contains(&share), "{share}");
    let result = analyse(
        &ClockInput {
            escapement: Some(Kind::from_name("impulse").unwrap()),
            impulse_angle: Some(0.0),
            q: Some(1e4),
            drive: Some(Drive::Energy(40e-6)),
            run: Some(RunInput {
                duration: 86_400.0,
                every: Some(3600.0),
                ..RunInput::default()
            }),
            ..ClockInput::new(ClockPendulum::Design(design))
        },
        &mut NoRows,
    )
    .unwrap();
    let s = &result.steady;
    let a = s.amplitude_rad;
    let integrated = quarter_period_integrated(a, share) / std::f64::consts::FRAC_PI_2;
    let rigid = quarter_period_integrated(a, 0.0) / std::f64::consts::FRAC_PI_2;
    let ratio = s.free_period_s / s.small_angle_period_s;
    eprintln!(
        "share {share:.4} at {:.3}°: {ratio:.14} against {integrated:.14} (rigid {rigid:.14})",
        s.amplitude_deg
    );
    assert!((ratio / integrated - 1.0).abs() < 1e-11);
    assert!(((ratio - 1.0) / (rigid - 1.0) - (1.0 - share)).abs() < 1e-3);
    assert!(
        (s.period_s / s.free_period_s - 1.0 - 1.0 / (8.0 * 1e8)).abs() < 1e-11,
        "{} {} {}",
        s.period_s,
        s.free_period_s,
        s.escapement_rate_s_per_day
    );
    let run = result.long_run.unwrap();
    assert!(
        run.final_rate_s_per_day.abs() < 1e-6,
        "{}",
        run.final_rate_s_per_day
    );
}

/// The period table of a pendulum on a spring (`period --design` of a
/// design hanging from one): each row's period ratio is the integrated
/// equation of motion's `θ'' = -ω²[(1 - ε) sin θ + ε θ]`
/// (`quarter_period_integrated`, within 1e-11), its circular error `1 -
/// T0/T` from it, the slope per degree the derivative of that (a central
/// difference of the integrated periods at ±0.01°, within 1e-5: the
/// difference's own truncation); the rows have no power series (the
/// seed's is a rigid pendulum's) and say their share. A share of 1 or
/// more, or not a number, is refused by name; none is the rigid table.
#[test]
fn the_period_table_on_a_spring() {
    use pendulum_theory::period::table::{table, Amplitudes, PeriodInput};
    let input = |deg: f64, share: Option<f64>| PeriodInput {
        length: 0.994,
        g: Some(9.81),
        amplitudes: Amplitudes::One(deg.to_radians()),
        series_terms: None,
        elastic_share: share,
    };
    let integrated = |deg: f64, e: f64| {
        quarter_period_integrated(deg.to_radians(), e) / std::f64::consts::FRAC_PI_2
    };
    for (deg, e) in [(3.0, 0.3), (20.0, 0.05), (45.0, 0.8)] {
        let row = table(&input(deg, Some(e))).unwrap().remove(0);
        let ratio = integrated(deg, e);
        close(row.period_ratio, ratio, 1e-11);
        close(row.period_s, row.small_angle_period_s * ratio, 1e-11);
        // The integration's 1e-11 of the period, relative to the error.
        close(
            row.circular_error,
            1.0 - 1.0 / ratio,
            1e-11 / row.circular_error,
        );
        let h = 0.01;
        let slope = ((1.0 - 1.0 / integrated(deg + h, e)) - (1.0 - 1.0 / integrated(deg - h, e)))
            / (2.0 * h)
            * 86_400.0;
        close(row.circular_error_s_per_day_per_deg, slope, 1e-5);
        assert!(row.series.is_none());
        assert_eq!(row.elastic_share, Some(e));
    }
    let rigid = table(&input(10.0, None)).unwrap().remove(0);
    let zero = table(&input(10.0, Some(0.0))).unwrap().remove(0);
    assert_eq!(rigid, zero);
    assert!(rigid.series.is_some());
    for bad in [1.0, 1.5, -0.1, f64::NAN] {
        let refusal = table(&input(10.0, Some(bad))).unwrap_err();
        assert!(refusal.to_string().contains("elastic_share"), "{refusal}");
    }
}

/// What swings a design on a spring as a rigid pendulum warns with both
/// circular errors once they differ by a thousandth of a second a day,
/// and not for a rigid pivot or a swing too small to matter.
#[test]
fn a_rigid_swing_of_a_spring_design_is_warned() {
    use pendulum_theory::suspension::rigid_swing_warning;
    let w = rigid_swing_warning(0.863, 10f64.to_radians()).unwrap();
    assert!(w.contains("0.863") && w.contains("10°"), "{w}");
    assert!(rigid_swing_warning(0.0, 0.5).is_none());
    // A regulator's spring (share 8.8e-4) at 0.5°: 0.41 s/day of circular
    // error, 3.6e-4 s/day of it the spring's: no warning; at 3°: 0.013.
    assert!(rigid_swing_warning(8.8e-4, 0.5f64.to_radians()).is_none());
    assert!(rigid_swing_warning(8.8e-4, 3f64.to_radians()).is_some());
}

/// The amplitude a period implies on a spring (`amplitude --design`):
/// [`pendulum_theory::period::inverse::amplitude_on_spring`] gives back the
/// amplitude whose period [`pendulum_theory::suspension::period_ratio`]
/// gives, within 1e-9 (its conditioning at 0.5° is 1/(2 × the circular
/// error's part of the period), 8,000 for share 0.3: the bisection's 1e-15
/// of the amplitude, and 1e-16 of the period times that); its conditioning
/// is `d ln A / d ln T` of the same function (a difference of ±1e-5 of the
/// amplitude, within 1e-3); a period below T0 or beyond the spring's at
/// 180° is refused by name, and T0 itself is a vanishing swing.
#[test]
fn the_amplitude_a_period_implies_on_a_spring() {
    use pendulum_theory::period::inverse::amplitude_on_spring;
    use pendulum_theory::suspension::period_ratio;
    let t0 = 2.0;
    for e in [0.001, 0.3, 0.9] {
        for deg in [0.5, 5.0, 45.0, 120.0, 170.0] {
            let a = f64::to_radians(deg);
            let period = t0 * period_ratio(a, e);
            let (got, kappa) = amplitude_on_spring(t0, period, e).unwrap();
            let tol = 1e-9f64.max(2e-16 * kappa);
            assert!((got / a - 1.0).abs() < tol, "{e} {deg}: {got} against {a}");
            let h = 1e-5 * a;
            let slope = (period_ratio(a + h, e).ln() - period_ratio(a - h, e).ln())
                / ((a + h).ln() - (a - h).ln());
            assert!(
                (kappa * slope - 1.0).abs() < 1e-3,
                "{e} {deg}: {kappa} {slope}"
            );
        }
        let most = t0 * period_ratio(std::f64::consts::PI.next_down(), e);
        let refused = amplitude_on_spring(t0, 1.001 * most, e).unwrap_err();
        assert!(refused.to_string().contains("180°"), "{refused}");
        let refused = amplitude_on_spring(t0, 0.999 * t0, e).unwrap_err();
        assert!(refused.to_string().contains("small-angle"), "{refused}");
        assert_eq!(amplitude_on_spring(t0, t0, e).unwrap().0, 0.0);
    }
}
