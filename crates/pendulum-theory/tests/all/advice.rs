//! The clock doctor's advice against hand calculations: the nut's turns
//! from the period's law (`T ∝ √l`, so a clock gaining `r` s/day wants
//! its length times `(1 + r/86400)²`), and the crutch from a swing
//! stepped through in time (no inverse formula), on 20 clocks each.

use pendulum_theory::advice::{advise, Advice, BobMove, Clockwork, Known, NutTurn};
use pendulum_theory::compound::regulate::{Nut, Regulated};
use pendulum_theory::listening::analysis::Oscillator;
use std::f64::consts::PI;

/// Twenty clocks: length (m), rate (s/day), thread (tpi or pitch in mm).
fn clocks() -> Vec<(f64, f64, Nut)> {
    let lengths = [0.2483, 0.9936, 1.4, 0.25, 0.75, 2.0, 0.5, 1.0, 0.3, 1.2];
    let rates = [12.0, -30.0, 0.7, -0.4, 95.0, -150.0, 3.3, -7.1, 44.0, -1.9];
    (0..20)
        .map(|i| {
            let nut = if i % 2 == 0 {
                Nut {
                    tpi: Some([20.0, 32.0, 40.0][i % 3]),
                    ..Nut::default()
                }
            } else {
                Nut {
                    pitch: Some([0.5e-3, 0.7e-3, 1.0e-3][i % 3]),
                    ..Nut::default()
                }
            };
            (
                lengths[i % 10],
                rates[(i * 3) % 10] * (1.0 + 0.1 * i as f64),
                nut,
            )
        })
        .collect()
}

#[test]
fn the_nut_turns_as_the_period_law_says_and_the_right_way() {
    for (length, rate, nut) in clocks() {
        let advice = advise(&Clockwork {
            rate_s_per_day: Some(rate),
            beat_s: 1.0,
            known: Known {
                pendulum: Some(Regulated::Length(length)),
                nut,
                ..Known::default()
            },
            ..Clockwork::default()
        })
        .unwrap();
        let Some(Advice::Regulate {
            bob,
            bob_shift_m,
            nut_turns,
            nut_turn,
            ..
        }) = advice.first().cloned()
        else {
            panic!("no regulation for {length} m at {rate} s/day: {advice:?}");
        };
        // By hand: the new length over the old is (1 + r/86400)².
        let change = length * ((1.0 + rate / 86_400.0).powi(2) - 1.0);
        let pitch = nut.pitch.unwrap_or_else(|| 0.0254 / nut.tpi.unwrap());
        assert!(
            (bob_shift_m - change.abs()).abs() < 1e-9 * length,
            "{bob_shift_m} against {change}"
        );
        let turns = nut_turns.unwrap();
        assert!((turns - change.abs() / pitch).abs() < 1e-6 * turns);
        // A gaining clock's pendulum is too short: the bob goes down, the
        // nut anticlockwise seen from below (a right-hand thread).
        if rate > 0.0 {
            assert_eq!((bob, nut_turn), (BobMove::Lower, NutTurn::Anticlockwise));
        } else {
            assert_eq!((bob, nut_turn), (BobMove::Raise, NutTurn::Clockwise));
        }
    }
}

/// A harmonic swing `θ = A sin ωt` whose escapement sits `offset` rad off
/// rest, stepped through in time: a beat as the pendulum passes
/// `offset + h` going one way and `offset - h` coming back. Returns the
/// two intervals: the one holding the swing to the + side, then the one
/// holding the swing to the − side.
fn stepped(a: f64, omega: f64, offset: f64, h: f64) -> (f64, f64) {
    let period = 2.0 * PI / omega;
    let n = 2_000_000;
    let dt = 2.0 * period / n as f64;
    let theta = |t: f64| a * (omega * t).sin();
    let speed = |t: f64| a * omega * (omega * t).cos();
    let mut beats: Vec<(f64, bool)> = Vec::new();
    for i in 0..n {
        let (t0, t1) = (i as f64 * dt, (i + 1) as f64 * dt);
        let going = speed(t0) > 0.0;
        let edge = if going { offset + h } else { offset - h };
        let (f0, f1) = (theta(t0) - edge, theta(t1) - edge);
        if f0 * f1 < 0.0 && (speed(t1) > 0.0) == going {
            // Linear interpolation within the step (the step is 1e-6 of
            // a period).
            beats.push((t0 + dt * f0 / (f0 - f1), going));
        }
    }
    // From a beat going + to the next (coming back): the swing to +.
    let i = beats.iter().position(|b| b.1).unwrap();
    (beats[i + 1].0 - beats[i].0, beats[i + 2].0 - beats[i + 1].0)
}

#[test]
fn the_crutch_goes_towards_the_longer_gaps_side_by_the_offset() {
    for k in 0..20 {
        let a = (1.5 + 0.3 * k as f64).to_radians();
        let h = [0.0_f64, 0.5, 1.0, 0.8][k % 4].to_radians().min(0.5 * a);
        let beat = [1.0, 0.5, 0.75, 0.3][k % 4];
        let omega = PI / beat;
        // The escapement off to the + side by 2-20% of the swing.
        let offset = a * (0.02 + 0.009 * k as f64);
        let (plus, minus) = stepped(a, omega, offset, h);
        let be = 0.5 * (minus - plus).abs();
        // The swing away from the offset takes the longer gap.
        assert!(minus > plus, "clock {k}: {minus} against {plus}");
        let advice = advise(&Clockwork {
            rate_s_per_day: None,
            beat_s: beat,
            beat_error_s: Some(be),
            oscillator: Some(Oscillator::Pendulum),
            lift_rad: Some(2.0 * h),
            known: Known {
                pendulum: Some(Regulated::Length(0.9936)),
                amplitude_rad: Some(a),
                crutch_m: Some(0.2),
                ..Known::default()
            },
            ..Clockwork::default()
        })
        .unwrap();
        let Some(Advice::SetInBeat {
            crutch_deg,
            bob_m,
            crutch_pin_m,
            split_percent,
            ..
        }) = advice.last().cloned()
        else {
            panic!("clock {k}: no beat setting in {advice:?}");
        };
        // The move is the offset (towards −, the side of the longer gap,
        // as the sentence says), within the stepping's error.
        assert!(
            (crutch_deg.to_radians() - offset).abs() < 1e-4 * offset,
            "clock {k}: {crutch_deg}° against {}°",
            offset.to_degrees()
        );
        assert!((bob_m - 0.9936 * offset).abs() < 1e-4 * bob_m);
        assert!((crutch_pin_m.unwrap() - 0.2 * offset).abs() < 1e-4 * bob_m);
        let long = 100.0 * minus / (plus + minus);
        assert!((split_percent[0] - long).abs() < 1e-3, "{split_percent:?}");
        let sentence = advice.last().unwrap().sentence();
        assert!(sentence.contains("towards the side the pendulum swings to in the longer gap"));
    }
}

/// A rate within its error of zero is left alone; a watch is regulated by
/// its index; a beat error under the limit brings no advice.
#[test]
fn what_is_not_advised() {
    let on_time = advise(&Clockwork {
        rate_s_per_day: Some(0.05),
        rate_standard_error_s_per_day: Some(0.04),
        beat_s: 1.0,
        beat_error_s: Some(0.004),
        ..Clockwork::default()
    })
    .unwrap();
    assert_eq!(on_time.len(), 1, "{on_time:?}");
    assert_eq!(on_time[0].code(), "on_time");
    let watch = advise(&Clockwork {
        rate_s_per_day: Some(-12.0),
        beat_s: 0.125,
        beat_error_s: Some(0.3e-3),
        ..Clockwork::default()
    })
    .unwrap();
    assert_eq!(watch.len(), 1, "{watch:?}");
    assert!(watch[0].sentence().contains("towards F"), "{watch:?}");
}
