//! What listening must not say without a word (issue 45): an amplitude
//! no running clock has, and windows that a periodic error biases alike.

use pendulum_theory::fitting::beat_log::Nominal;
use pendulum_theory::listening::analysis::{listen_to_samples, ListenInput};
use pendulum_theory::listening::synth::{synthesize, TickRecording};

/// The README's seconds clock with `--lift-angle 2`: the generator puts
/// the drop 16 ms after the unlocking, as in a watch, where a seconds
/// clock's comes some 0.2 s later, so the amplitude came out 38.7°,
/// unwarned. A pendulum clock swings 15° at most: not given, warned with
/// the figure.
#[test]
fn an_amplitude_no_pendulum_clock_has_is_not_given() {
    let rec = synthesize(&TickRecording {
        duration: 60.0,
        ..TickRecording::DEFAULT
    });
    let heard = listen_to_samples(
        &rec.samples,
        44_100.0,
        &ListenInput {
            lift_angle: Some(2f64.to_radians()),
            ..ListenInput::default()
        },
    )
    .unwrap();
    assert_eq!(heard.amplitude_deg, Some(None), "{:?}", heard.amplitude_deg);
    let codes = &heard.beats.warning_codes;
    assert!(codes.contains(&"amplitude_impossible"), "{codes:?}");
    let said = heard
        .beats
        .warnings
        .iter()
        .map(|w| w.to_string())
        .collect::<Vec<_>>();
    assert!(said.iter().any(|w| w.contains("38.")), "{said:?}");
    // A watch's 52° lift on a balance's 16 ms drop at 28,800 bph: a swing
    // a balance has, given and not warned.
    let watch = synthesize(&TickRecording {
        duration: 30.0,
        beats_per_hour: 28_800.0,
        ..TickRecording::DEFAULT
    });
    let heard = listen_to_samples(
        &watch.samples,
        44_100.0,
        &ListenInput {
            lift_angle: Some(52f64.to_radians()),
            ..ListenInput::default()
        },
    )
    .unwrap();
    let a = heard.amplitude_deg.flatten().expect("an amplitude");
    assert!(a > 100.0 && a < 330.0, "{a}");
    assert!(!heard.beats.warning_codes.contains(&"amplitude_impossible"));
}

/// A seconds clock whose escape wheel turns once a minute with a ±1 ms
/// periodic error, read in windows of a minute: every window's slope is
/// biased alike (the least-squares slope of one whole sine period is not
/// zero), so the windows' mean stood nine standard errors from the whole
/// recording's rate without a word. Warned; windows of 45 s, which the
/// error does not repeat in, are not.
#[test]
fn windows_a_wheel_biases_alike_are_warned() {
    let rec = synthesize(&TickRecording {
        duration: 600.0,
        rate_s_per_day: 15.0,
        ..TickRecording::DEFAULT
    });
    // The time warp t → t + 1 ms sin(2πt/60 s), by linear interpolation of
    // the samples (a tick's shape barely changes: the warp's slope is
    // 1e-4).
    let rate = 44_100.0;
    let n = rec.samples.len();
    let warped: Vec<f32> = (0..n)
        .map(|i| {
            let t = i as f64 / rate;
            let source = (t - 1e-3 * (std::f64::consts::TAU * t / 60.0).sin()) * rate;
            let (k, frac) = (source.floor(), source - source.floor());
            let k = k.max(0.0) as usize;
            if k + 1 >= n {
                return 0.0;
            }
            ((1.0 - frac) * f64::from(rec.samples[k]) + frac * f64::from(rec.samples[k + 1])) as f32
        })
        .collect();
    let heard = |every: f64| {
        listen_to_samples(
            &warped,
            rate,
            &ListenInput {
                nominal: Some(Nominal::BeatsPerHour(3600.0)),
                every: Some(every),
                ..ListenInput::default()
            },
        )
        .unwrap()
    };
    let minute = heard(60.0);
    let totals = minute.window_totals.unwrap();
    eprintln!(
        "windows {:?} ± {:?}, whole {:?} ± {:?}",
        totals.rate_mean_s_per_day,
        totals.rate_mean_se_s_per_day,
        minute.beats.rate_s_per_day,
        minute.beats.rate_se_s_per_day
    );
    assert!(
        minute.beats.warning_codes.contains(&"windows_biased"),
        "{:?}",
        minute.beats.warning_codes
    );
    let other = heard(45.0);
    assert!(
        !other.beats.warning_codes.contains(&"windows_biased"),
        "{:?}",
        other.beats.warning_codes
    );
}
