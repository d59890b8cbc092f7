//! The clock: escapements, steady states and long runs, against closed
//! forms, an independent integrator, and the statements of the
//! horological literature (each test names its source).

use pendulum_theory::clock::direct::half_swing;
use pendulum_theory::clock::escapement::{Deadbeat, Escapement, Impulse, Recoil};
use pendulum_theory::clock::long_run::{run, LongRun};
use pendulum_theory::clock::{Clock, ClockError, HalfSwingMethod};
use pendulum_theory::damping::Damping;
use pendulum_theory::simulation::{
    simulate, Action, Method, Model, Observer, Options, TurningPoint,
};
use pendulum_theory::{Amplitude, Pendulum};

const MASS_KG: f64 = 5.0;

fn seconds_pendulum() -> Pendulum {
    Pendulum::new(0.99362, 9.80665).unwrap()
}

fn clock(q: f64, escapement: Box<dyn Escapement>) -> Clock {
    let p = seconds_pendulum();
    Clock {
        pendulum: p,
        q,
        escapement,
        torque_scale: MASS_KG * p.g_m_s2() * p.length_m(),
    }
}

/// The energy per beat (over m g l) that a viscous pendulum needs to
/// swing at `a` rad: the loss per period `π A²/Q` (small swings), halved.
fn energy_for(a: f64, q: f64) -> f64 {
    0.5 * std::f64::consts::PI * a * a / q
}

/// Airy (1830): an impulse at the bottom of the swing leaves the period
/// alone; one before the bottom gains, one after loses, by the amount his
/// first-order integral gives. Here at 3°, Q = 10,000, the impulse 1°
/// before and after the bottom: the integrated steady state against the
/// first-order integral (the library's nonlinear form, and Airy's
/// small-angle one computed here in closed form: an impulse Δv at θ_i
/// before the bottom shortens each half swing, π long in scaled time, by
/// Δv θ_i / A²).
#[test]
fn airy_impulse_before_at_and_after_the_bottom() {
    let q = 1e4;
    let a = 3f64.to_radians();
    let e = energy_for(a, q);
    let at_bottom = clock(
        q,
        Box::new(Impulse {
            angle: 0.0,
            energy: e,
        }),
    );
    let s = at_bottom.steady(HalfSwingMethod::Direct, 1.0).unwrap();
    assert!(s.escapement_rate.abs() < 1e-3, "{s:?}");
    for (deg, sign) in [(1.0, 1.0), (-1.0, -1.0)] {
        let c = clock(
            q,
            Box::new(Impulse {
                angle: f64::to_radians(deg),
                energy: e,
            }),
        );
        let s = c.steady(HalfSwingMethod::Direct, 1.0).unwrap();
        assert_eq!(s.escapement_rate.signum(), sign, "{s:?}");
        let first_order = s.escapement_rate_first_order;
        assert!(
            (s.escapement_rate / first_order - 1.0).abs() < 0.02,
            "{} against {first_order}",
            s.escapement_rate
        );
        // Airy's small-angle closed form, independently: the impulse
        // Δv = e / v at θ_i (v = sqrt(A² - θ_i²), scaled) advances the
        // half swing of length π by Δv θ_i / A²; rate = 86400 · that / π.
        let amp = s.amplitude;
        let theta = f64::to_radians(deg);
        let dv = e / (amp * amp - theta * theta).sqrt();
        let airy = 86_400.0 * dv * theta / (amp * amp) / std::f64::consts::PI;
        assert!(
            (s.escapement_rate / airy - 1.0).abs() < 0.02,
            "{} against Airy's {airy}",
            s.escapement_rate
        );
    }
}

/// The energy balance `A² = Q ΔE / (π m g l)` (ΔE the energy given per
/// period) for an impulse at the bottom, Q from 1,000 to 10⁶: within 1%.
#[test]
fn the_energy_balance_sets_the_amplitude() {
    for q in [1e3, 1e4, 1e5, 1e6] {
        let e = energy_for(3f64.to_radians(), q);
        let c = clock(
            q,
            Box::new(Impulse {
                angle: 0.0,
                energy: e,
            }),
        );
        let s = c.steady(HalfSwingMethod::Direct, 1.0).unwrap();
        let per_period = 2.0 * s.energy_per_beat;
        let mgl = c.torque_scale;
        let expected = (q * per_period / (std::f64::consts::PI * mgl)).sqrt();
        assert!(
            (s.amplitude / expected - 1.0).abs() < 0.01,
            "Q {q}: {} against {expected}",
            s.amplitude
        );
    }
}

struct Turns(Vec<(f64, f64)>);
impl Observer for Turns {
    fn turning_point(&mut self, p: &TurningPoint) -> Action {
        self.0.push((p.time, p.angle.abs()));
        Action::Continue
    }
}

/// The long-run method against direct simulation over 1,000 periods at
/// 3°, Q = 10⁶: the free pendulum against the symplectic method at
/// tolerance 1e-12, and a driven deadbeat clock against its half swings
/// integrated by DOP853 at 3e-14 (the symplectic driver has no
/// escapement; DOP853 at 1e-13 and 3e-14 differ by 5e-9 of the
/// amplitude, so the tighter one is the reference): amplitude within
/// 1e-9 relative, accumulated time within 1e-6 s.
#[test]
fn the_long_run_method_against_direct_simulation() {
    let p = seconds_pendulum();
    let (a0, q) = (3f64.to_radians(), 1e6);
    let t0 = p.small_angle_period();
    let model = Model::new(p, Damping::from_q(q).unwrap(), 0.0, 0.0).unwrap();
    let mut turns = Turns(Vec::new());
    simulate(
        &model,
        Amplitude::from_radians(a0).unwrap(),
        &Options {
            duration: 1001.0 * t0,
            tolerance: 1e-12,
            method: Method::Symplectic,
            sample_interval: None,
        },
        &mut turns,
    )
    .unwrap();
    let free = clock(
        q,
        Box::new(Impulse {
            angle: 0.0,
            energy: 0.0,
        }),
    );
    let mut rows = Vec::new();
    run(
        &free,
        &|_| 1.0,
        &|_| 1.0,
        &LongRun {
            duration: 1000.0 * t0,
            amplitude: a0,
            nominal_period: t0,
            every: None,
        },
        &mut |r| {
            rows.push((r.time, r.amplitude));
            true
        },
    );
    let ((ts, as_), (tm, am)) = (turns.0[2000], rows[2000]);
    assert!((am / as_ - 1.0).abs() < 1e-9, "{am} against {as_}");
    assert!((tm - ts).abs() < 1e-6, "{tm} against {ts}");

    let deadbeat = Deadbeat {
        lift: 2f64.to_radians(),
        torque: 2e-7,
        friction: 0.15,
        offset: 0.0,
    };
    let omega = p.natural_angular_frequency();
    let (mut a, mut time) = (a0, 0.0);
    for beat in 0..2000 {
        let h = half_swing(&deadbeat, q, 1.0, beat, a, 3e-14).unwrap();
        a = h.amplitude;
        time += h.time / omega;
    }
    let driven = clock(q, Box::new(deadbeat));
    let mut last = None;
    run(
        &driven,
        &|_| 1.0,
        &|_| 1.0,
        &LongRun {
            duration: 1001.0 * t0,
            amplitude: a0,
            nominal_period: t0,
            every: None,
        },
        &mut |r| {
            if r.beats == 2000 {
                last = Some((r.time, r.amplitude));
            }
            true
        },
    );
    let (tm, am) = last.unwrap();
    assert!(a > a0 * 1.0002, "the drive grows the swing: {a}");
    assert!((am / a - 1.0).abs() < 1e-9, "{am} against {a}");
    assert!((tm - time).abs() < 1e-6, "{tm} against {time}");
}

/// Many beats per step (a row an hour) against one step per beat, over a
/// day of a deadbeat clock whose drive falls by 30% over eight days:
/// amplitude within 1e-6, time error within 1e-4 s.
#[test]
fn many_beats_per_step_against_one() {
    let c = clock(
        1e4,
        Box::new(Deadbeat {
            lift: 2f64.to_radians(),
            torque: 2e-5,
            friction: 0.15,
            offset: 0.0,
        }),
    );
    let s = c.steady(HalfSwingMethod::Averaged, 1.0).unwrap();
    let drive = |t: f64| 1.0 - 0.3 * t / (8.0 * 86_400.0);
    let last = |every: Option<f64>| {
        let mut last = None;
        let f = run(
            &c,
            &drive,
            &|_| 1.0,
            &LongRun {
                duration: 86_400.0,
                amplitude: s.amplitude,
                nominal_period: s.period,
                every,
            },
            &mut |r| {
                last = Some(*r);
                true
            },
        );
        (last.unwrap(), f.multi_steps)
    };
    let ((one, single), (many, multi)) = (last(None), last(Some(3600.0)));
    assert_eq!(single, 0);
    assert!(multi > 100, "{multi}");
    assert_eq!(one.beats, many.beats);
    assert!(
        (many.amplitude / one.amplitude - 1.0).abs() < 1e-6,
        "{many:?} {one:?}"
    );
    assert!(
        (many.time_error - one.time_error).abs() < 1e-4,
        "{many:?} {one:?}"
    );
    // The drive falling, the swing shrinks and the clock gains (a smaller
    // circular error).
    assert!(one.amplitude < s.amplitude && one.time_error > 0.0);
}

/// Isochronism as the horological texts describe it (Rawlings, The
/// Science of Clocks and Watches, 3rd ed., ch. 5; Woodward, My Own Right
/// Time, ch. 5): a deadbeat escapement adds almost no error of its own,
/// so more drive means a larger arc and a losing clock (the circular
/// error); a recoil escapement gains as the drive increases, which offsets
/// much of the circular error; a constant-force escapement keeps the arc
/// whatever the drive. Drive from 0.5x to 2x, Q = 10,000, lift 2°.
#[test]
fn isochronism_of_deadbeat_recoil_and_constant_force() {
    use pendulum_theory::clock::escapement::ConstantForce;
    let lift = 2f64.to_radians();
    let torque = 2e-5;
    let deadbeat = clock(
        1e4,
        Box::new(Deadbeat {
            lift,
            torque,
            friction: 0.15,
            offset: 0.0,
        }),
    );
    let recoil = clock(
        1e4,
        Box::new(Recoil {
            lift,
            torque,
            recoil: 1.0,
        }),
    );
    let constant = clock(
        1e4,
        Box::new(ConstantForce {
            lift,
            impulse: torque,
            torque,
            friction: 0.15,
        }),
    );
    let at = |c: &Clock, f: f64| c.steady(HalfSwingMethod::Direct, f).unwrap();
    let (d1, d2) = (at(&deadbeat, 0.5), at(&deadbeat, 2.0));
    let (r1, r2) = (at(&recoil, 0.5), at(&recoil, 2.0));
    let (c1, c2) = (at(&constant, 0.5), at(&constant, 2.0));
    assert!(d2.amplitude > d1.amplitude && d2.rate < d1.rate);
    assert!(d1.escapement_rate.abs() < 0.01 && d2.escapement_rate.abs() < 0.01);
    assert!(r2.escapement_rate > r1.escapement_rate && r1.escapement_rate > 0.0);
    assert!((r2.rate - r1.rate).abs() < 0.5 * (d2.rate - d1.rate).abs());
    // Constant force: the arc moves only by the locking friction's share.
    assert!((c2.amplitude / c1.amplitude - 1.0).abs() < 0.5 * (d2.amplitude / d1.amplitude - 1.0));
}

/// A drive too weak to carry the swing through the lift: the pendulum
/// stops, and the error says how much drive it would need; that much (and
/// a little more) keeps it going.
#[test]
fn a_weak_drive_stops_the_pendulum() {
    let c = clock(
        1e4,
        Box::new(Deadbeat {
            lift: 4f64.to_radians(),
            torque: 1e-7,
            friction: 0.15,
            offset: 0.0,
        }),
    );
    let Err(ClockError::Stops { minimum_factor, .. }) = c.steady(HalfSwingMethod::Direct, 1.0)
    else {
        panic!("it should stop");
    };
    assert!(minimum_factor > 1.0);
    let s = c
        .steady(HalfSwingMethod::Direct, minimum_factor * 1.01)
        .unwrap();
    assert!(s.amplitude > 2f64.to_radians());
}

/// A schedule: linear between its points, held beyond them, 1 when empty;
/// and the period factor of a rate (a clock gaining 86.4 s/day runs its
/// half swings 1/1.001 as long).
#[test]
fn schedules_and_period_factors() {
    use pendulum_theory::clock::long_run::{period_factor, piecewise_linear};
    let (t, v) = ([0.0, 10.0, 20.0], [1.0, 0.5, 0.8]);
    assert_eq!(piecewise_linear(&t, &v, -5.0), 1.0);
    assert_eq!(piecewise_linear(&t, &v, 5.0), 0.75);
    assert_eq!(piecewise_linear(&t, &v, 10.0), 0.5);
    assert!((piecewise_linear(&t, &v, 15.0) - 0.65).abs() < 1e-15);
    assert_eq!(piecewise_linear(&t, &v, 25.0), 0.8);
    assert_eq!(piecewise_linear(&[], &[], 3.0), 1.0);
    assert_eq!(period_factor(86.4), 1.0 / 1.001);
}
