//! The clock: escapements, steady states and long runs, against closed
//! forms, an independent integrator, and the statements of the
//! horological literature (each test names its source).

use pendulum_theory::clock::direct::{half_swing, Losses};
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
        elastic_share: 0.0,
        drag: Vec::new(),
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

/// A drag law of the simulation's list runs in a clock: the 3/2 power
/// beside a Q of 10⁵, taking four times the viscous loss at 3°. The
/// steady amplitude where the impulse's energy per beat meets the losses
/// of a half swing at small swings, `π A²/(2Q) + k π ⟨|sin|^{5/2}⟩ A^{5/2}`
/// (solved here by bisection), within 0.2% (the finite swing's share,
/// about A²/8), by the integrated half swings; the long-run map's
/// (the drag's energy by quadrature) within 1e-5 of theirs; and the
/// clock without the drag swings wider.
#[test]
fn a_drag_law_runs_in_a_clock() {
    use pendulum_theory::simulation::forces::{drag_law, DRAG_LAWS};
    let law = DRAG_LAWS[drag_law("three_halves_drag").unwrap()];
    let (q, k) = (1e5, 1.91e-4);
    let mean = 0.457_655_858_101_087_83;
    let e = 5.0 * energy_for(3f64.to_radians(), q);
    let loss = |a: f64| {
        0.5 * std::f64::consts::PI * a * a / q + k * std::f64::consts::PI * mean * a.powf(2.5)
    };
    let (mut low, mut high) = (0.0, 0.5);
    for _ in 0..100 {
        let mid = 0.5 * (low + high);
        if loss(mid) < e {
            low = mid;
        } else {
            high = mid;
        }
    }
    let expected = 0.5 * (low + high);
    let impulse = || {
        Box::new(Impulse {
            angle: 0.0,
            energy: e,
        })
    };
    let mut c = clock(q, impulse());
    c.drag = vec![(law, k)];
    let direct = c.steady(HalfSwingMethod::Direct, 1.0).unwrap();
    assert!(
        (direct.amplitude / expected - 1.0).abs() < 2e-3,
        "{} against {expected}",
        direct.amplitude
    );
    let averaged = c.steady(HalfSwingMethod::Averaged, 1.0).unwrap();
    assert!(
        (averaged.amplitude / direct.amplitude - 1.0).abs() < 1e-5,
        "{} against {}",
        averaged.amplitude,
        direct.amplitude
    );
    let free = clock(q, impulse())
        .steady(HalfSwingMethod::Direct, 1.0)
        .unwrap();
    assert!(free.amplitude > 1.5 * direct.amplitude, "{free:?}");
    // The drag counts where a clock stops too: a deadbeat clock that
    // runs without it stops with a hundred times the drag (which takes
    // more than the pallets give at their unlocking), and the drive it
    // needs rises with the drag.
    let deadbeat = || {
        Box::new(Deadbeat {
            lift: 2f64.to_radians(),
            torque: 2e-5,
            friction: 0.15,
            offset: 0.0,
        })
    };
    let plain = clock(q, deadbeat());
    assert!(plain.steady(HalfSwingMethod::Direct, 1.0).is_ok());
    let mut heavy = clock(q, deadbeat());
    heavy.drag = vec![(law, 100.0 * k)];
    let stopped = heavy.steady(HalfSwingMethod::Direct, 1.0);
    assert!(
        matches!(stopped, Err(ClockError::Stops { .. })),
        "{stopped:?}"
    );
    assert!(heavy.minimum_drive() > 1.0 && plain.minimum_drive() < 1.0);
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
        let losses = Losses { q, drag: &[] };
        let h = half_swing(&deadbeat, losses, 1.0, beat, a, 3e-14).unwrap();
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

/// Isochronism as the horological texts describe it. A deadbeat adds
/// almost no error of its own, so more drive means a larger arc and a
/// losing clock (the circular error), and a falling drive a gaining one:
/// "the same clock fitted with [a deadbeat] would gradually gain as it
/// ran down" (Hasluck, Cassell's Cyclopaedia of Mechanics, "Clock
/// escapements and motive power"). An anchor (recoil) clock does the
/// opposite: a recoil clock "go[es] gradually slower" as its spring runs
/// down (Hasluck), "the clock loses as the arc of the pendulum falls off,
/// and vice versa" (Encyclopaedia Britannica, 11th ed., 1911, "Clock").
/// A little recoil still loses with the drive, so between it and the
/// full recoil lies one that keeps time whatever the drive ("the
/// escapement must not have much recoil, nor must it be perfectly dead",
/// Hasluck). A constant-force escapement keeps the arc whatever the
/// drive. Drive from 0.5x to 2x, Q = 10,000, lift 2°, friction 0.15.
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
    let anchor = |recoil: f64| {
        clock(
            1e4,
            Box::new(Recoil {
                lift,
                torque,
                recoil,
                friction: 0.15,
            }),
        )
    };
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
    let recoil = anchor(1.0);
    let (r1, r, r2) = (at(&recoil, 0.5), at(&recoil, 1.0), at(&recoil, 2.0));
    let (c1, c2) = (at(&constant, 0.5), at(&constant, 2.0));
    assert!(d2.amplitude > d1.amplitude && d2.rate < d1.rate);
    assert!(d1.escapement_rate.abs() < 0.01 && d2.escapement_rate.abs() < 0.01);
    // The anchor gains with the drive, at every step.
    assert!(r2.rate > r.rate && r.rate > r1.rate, "{r1:?} {r:?} {r2:?}");
    assert!(r2.escapement_rate > r1.escapement_rate && r1.escapement_rate > 0.0);
    // A little recoil loses with the drive as a deadbeat does, so a
    // recoil between it and the full one keeps time whatever the drive.
    let little = anchor(0.1);
    let (l1, l2) = (at(&little, 0.5), at(&little, 2.0));
    assert!(l2.rate < l1.rate, "{l1:?} {l2:?}");
    // Constant force: the arc moves only by the locking friction's share.
    assert!((c2.amplitude / c1.amplitude - 1.0).abs() < 0.5 * (d2.amplitude / d1.amplitude - 1.0));
}

/// The anchor's arc hardly grows with the drive: the recoil faces'
/// friction takes energy in proportion to the drive and to the arc beyond
/// the lift (Britannica 1911, "Clock": the recoil escapement's pallets
/// "absorb" the extra force). Without friction the energy it gives is the
/// impulse's alone and the arc follows the square root of the drive
/// (viscous losses grow as its square): a fourfold drive doubles it. With
/// friction 0.15 the arc grows as less than the drive's fourth root, and
/// its steady value is the small-angle energy balance's, solved here in
/// closed form: the impulse `T·2h` less the friction's loss `r T (F - 1)
/// (A - h)`, `F = ((1 + μ)/(1 - μ))²`, equals the viscous loss `π A² /
/// (2 Q)` (to the small-angle error, `A²/8`, 2e-4). And the recoil's gain
/// is Airy's small-angle integral of a constant torque towards the middle
/// beyond the lift (returning `r T`, recoiling `r T F`): `86400 r T (1 +
/// F) sqrt(A² - h²) / (π A²)` s/day.
#[test]
fn the_anchors_arc_is_held_by_its_recoil_friction() {
    let (lift, torque, q) = (2f64.to_radians(), 2e-5, 1e4);
    let anchor = |friction: f64| {
        clock(
            q,
            Box::new(Recoil {
                lift,
                torque,
                recoil: 1.0,
                friction,
            }),
        )
    };
    let at = |c: &Clock, f: f64| c.steady(HalfSwingMethod::Direct, f).unwrap();
    let frictionless = anchor(0.0);
    let ratio = at(&frictionless, 4.0).amplitude / at(&frictionless, 1.0).amplitude;
    assert!((ratio - 2.0).abs() < 1e-3, "{ratio}");
    let oiled = anchor(0.15);
    let (s1, s4) = (at(&oiled, 1.0), at(&oiled, 4.0));
    let growth = (s4.amplitude / s1.amplitude).ln() / 4f64.ln();
    assert!(growth < 0.25, "the arc grows as the drive to the {growth}");
    let f = (1.15f64 / 0.85).powi(2);
    let h = 0.5 * lift;
    for (s, drive) in [(s1, 1.0), (s4, 4.0)] {
        let t = torque * drive;
        // π A²/(2Q) + t (F - 1) A - t (2h + (F - 1) h) = 0.
        let (qa, qb, qc) = (
            std::f64::consts::PI / (2.0 * q),
            t * (f - 1.0),
            -t * (2.0 * h + (f - 1.0) * h),
        );
        let a = (-qb + (qb * qb - 4.0 * qa * qc).sqrt()) / (2.0 * qa);
        assert!((s.amplitude / a - 1.0).abs() < 1e-3, "{} {a}", s.amplitude);
        let airy =
            86_400.0 * t * (1.0 + f) * (a * a - h * h).sqrt() / (std::f64::consts::PI * a * a);
        assert!(
            (s.escapement_rate / airy - 1.0).abs() < 0.01,
            "{} {airy}",
            s.escapement_rate
        );
    }
}

/// A clock out of beat by `δ`: the ticks (the drop at the lift's far edge)
/// fall at `θ = δ + h` on the swing out and `δ - h` on the swing back, and
/// for the free swing of amplitude `A` the beat error is `|acos((δ -
/// h)/A) + acos((δ + h)/A) - π| / ω` (closed form; the escapement's
/// torques move it by their ratio to gravity's, 1e-3 here). The beat
/// analysis of `fit beats` reads the same beat error from the model's
/// tick times. In beat it is zero; the escapement's pushes on the two
/// beats cancel to first order, so the rate moves by thousandths of a
/// second a day; and the drive must carry the swing `δ` further to unlock.
#[test]
fn a_clock_out_of_beat_ticks_unevenly() {
    use pendulum_theory::clock::direct::half_swing_ticked;
    use pendulum_theory::clock::escapement::OutOfBeat;
    use pendulum_theory::fitting::beats::analyse_beats;
    let lift = 2f64.to_radians();
    let deadbeat = || Deadbeat {
        lift,
        torque: 2e-5,
        friction: 0.15,
        offset: 0.0,
    };
    let delta = 0.2f64.to_radians();
    let in_beat = clock(1e4, Box::new(deadbeat()));
    let out = clock(
        1e4,
        Box::new(OutOfBeat {
            inner: Box::new(deadbeat()),
            offset: delta,
        }),
    );
    let s0 = in_beat.steady(HalfSwingMethod::Direct, 1.0).unwrap();
    let s = out.steady(HalfSwingMethod::Direct, 1.0).unwrap();
    assert_eq!(s0.beat_error, 0.0);
    let (a, h) = (s.amplitude, 0.5 * lift);
    let omega = out.pendulum.natural_angular_frequency();
    let free =
        (((delta - h) / a).acos() + ((delta + h) / a).acos() - std::f64::consts::PI).abs() / omega;
    assert!(
        (s.beat_error / free - 1.0).abs() < 2e-3,
        "{} {free}",
        s.beat_error
    );
    assert!((s.rate - s0.rate).abs() < 1e-3, "{} {}", s.rate, s0.rate);
    assert!(out.minimum_drive() > in_beat.minimum_drive());
    // Its ticks, half swing by half swing, read as a beat log.
    let mut ticks = Vec::new();
    let (mut time, mut amplitude) = (0.0, s.amplitude);
    for beat in 0..400u64 {
        let (swing, tick) = half_swing_ticked(
            out.escapement.as_ref(),
            out.losses(),
            1.0,
            beat % 2,
            amplitude,
            1e-12,
        )
        .unwrap();
        ticks.push((time + tick.unwrap()) / omega);
        time += swing.time;
        amplitude = swing.amplitude;
    }
    let log = analyse_beats(&ticks, Some(0.5 * s.period)).unwrap();
    assert!(
        (log.beat_error_ms / (1e3 * s.beat_error) - 1.0).abs() < 1e-3,
        "{} {}",
        log.beat_error_ms,
        1e3 * s.beat_error
    );
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

/// Near stopping, out of beat by as much as half the lift, the swing
/// barely passes the far edge on one side: the ticks come most unevenly,
/// and the beat error is still the free swing's closed form (within 5%:
/// the escapement's pushes are a larger share of so small a swing), not
/// nothing.
#[test]
fn a_clock_far_out_of_beat_near_stopping() {
    use pendulum_theory::clock::escapement::OutOfBeat;
    let lift = 2f64.to_radians();
    let delta = 1f64.to_radians();
    let out = clock(
        1e4,
        Box::new(OutOfBeat {
            inner: Box::new(Deadbeat {
                lift,
                torque: 2e-5,
                friction: 0.15,
                offset: 0.0,
            }),
            offset: delta,
        }),
    );
    let s = out
        .steady(HalfSwingMethod::Direct, 1.002 * out.minimum_drive())
        .unwrap();
    let (a, h) = (s.amplitude, 0.5 * lift);
    let omega = out.pendulum.natural_angular_frequency();
    let free =
        (((delta - h) / a).acos() + ((delta + h) / a).acos() - std::f64::consts::PI).abs() / omega;
    assert!(
        (s.beat_error / free - 1.0).abs() < 0.05,
        "{} {free}",
        s.beat_error
    );
}

/// Airy's first-order integral is printed beside the integrated
/// escapement error as a check; where the two part (an anchor with
/// friction 0.9 on its faces: 659 against 591 s/day) the analysis says so,
/// and the constant-force escapement, whose impulse no drive sets, has no
/// least drive (it printed "stops below 7.9e-31 × the drive").
#[test]
fn airy_far_off_is_warned_and_a_constant_force_never_starves() {
    use pendulum_theory::clock::analysis::{analyse, ClockInput, ClockPendulum, NoRows};
    use pendulum_theory::clock::escapement::spec::{Drive, Kind};
    let at = |kind: Kind, friction: f64| {
        analyse(
            &ClockInput {
                escapement: Some(kind),
                friction: Some(friction),
                drive: Some(Drive::Energy(20e-6)),
                ..ClockInput::new(ClockPendulum::Length(1.0))
            },
            &mut NoRows,
        )
        .unwrap()
    };
    let far = at(Kind::from_name("recoil").unwrap(), 0.9);
    let (i, a) = (
        far.steady.escapement_rate_s_per_day,
        far.steady.escapement_rate_airy_s_per_day,
    );
    assert!((a - i).abs() > 0.05 * i.abs(), "{i} {a}");
    assert!(
        far.warnings
            .iter()
            .any(|w| w.code == "airy_first_order_off" && w.message.contains("Airy")),
        "{:?}",
        far.warnings
    );
    let near = at(Kind::from_name("recoil").unwrap(), 0.15);
    assert!(
        !near
            .warnings
            .iter()
            .any(|w| w.code == "airy_first_order_off"),
        "{:?}",
        near.warnings
    );
    assert_eq!(
        at(Kind::from_name("constant-force").unwrap(), 0.15).minimum_drive_factor,
        0.0
    );
    assert!(at(Kind::from_name("deadbeat").unwrap(), 0.15).minimum_drive_factor > 0.05);
}
