//! What listening must not say without a word (issue 45): an amplitude
//! no running clock has, windows that a periodic error biases alike; and
//! what it must hear through: strikes, chimes and handling.

use pendulum_theory::fitting::beat_log::{BeatWarning, Nominal};
use pendulum_theory::listening::analysis::{listen_to_samples, ListenInput};
use pendulum_theory::listening::synth::{synthesize, synthesize_with, Interference, TickRecording};

/// The book's seconds clock with `--lift-angle 2` (book/src/listening.md
/// and guides/clockmaker.md): the generator puts the drop 16 ms after the
/// unlocking, as in a watch, where a seconds clock's comes some 0.2 s
/// later, so the amplitude came out 38.7°, unwarned. A pendulum clock
/// swings 15° at most: not given, warned with the figure.
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

/// One clock with sounds that are not ticks laid over it: heard with and
/// without its beat rate given, its rate within 0.5 s/day and beat error
/// within 0.3 ms of the truth, every tick outside the loud spans (and half
/// a second around them) found, the spans cut reported over the loud ones
/// and no clock said lost; the same clock alone has nothing cut or lost.
fn heard_through(label: &str, spec: &TickRecording, what: &[Interference], level_db: f64) {
    let rec = synthesize_with(spec, what, level_db);
    assert!(!rec.loud.is_empty(), "{label}: nothing loud");
    let truth_beat = 3600.0 / spec.beats_per_hour / (1.0 + spec.rate_s_per_day / 86_400.0);
    for nominal in [None, Some(Nominal::BeatsPerHour(spec.beats_per_hour))] {
        let label = format!("{label}, nominal {nominal:?}");
        let input = ListenInput {
            nominal,
            ..ListenInput::default()
        };
        let heard = listen_to_samples(&rec.samples, f64::from(spec.sample_rate), &input)
            .unwrap_or_else(|e| panic!("{label}: refused: {e}"));
        let b = &heard.beats;
        let rate = b.rate_s_per_day.expect("a rate");
        eprintln!(
            "{label}: rate {rate:.3}, beat error {:.3} ms, missed {}, loud {:?}, warnings {:?}",
            b.beat_error_ms,
            heard.missed,
            rec.loud,
            b.warnings.iter().map(|w| w.to_string()).collect::<Vec<_>>()
        );
        assert!(
            (rate - spec.rate_s_per_day).abs() < 0.5,
            "{label}: rate {rate}"
        );
        assert!(
            (b.beat_error_ms - spec.beat_error_ms.abs()).abs() < 0.3,
            "{label}: beat error {}",
            b.beat_error_ms
        );
        assert!((b.mean_beat_s / truth_beat - 1.0).abs() < 1e-3, "{label}");
        let outside = |t: f64| rec.loud.iter().all(|&(a, z)| t < a - 0.5 || t > z + 0.5);
        let wanted: Vec<f64> = rec.ticks.iter().copied().filter(|&t| outside(t)).collect();
        let found = wanted
            .iter()
            .filter(|&&t| heard.ticks.iter().any(|h| (h.time - t).abs() < 5e-4))
            .count();
        assert!(
            found as f64 >= 0.99 * wanted.len() as f64,
            "{label}: {found} of the {} ticks outside the loud spans found",
            wanted.len()
        );
        let cut = b.warnings.iter().find_map(|w| match w {
            BeatWarning::SoundsCut { spans, .. } => Some(spans.clone()),
            _ => None,
        });
        let cut = cut.unwrap_or_else(|| panic!("{label}: no span cut reported"));
        // The same spans as data, with the beats in them.
        let as_data: Vec<(f64, f64)> = heard.cut_s.iter().map(|s| (s[0], s[1])).collect();
        assert_eq!(as_data, cut, "{label}");
        assert!(heard.cut_beats > 0, "{label}");
        for &(a, z) in &rec.loud {
            // Each loud span's start is inside a span cut (its tail may
            // fall under the ticks before it ends).
            assert!(
                cut.iter().any(|&(c, d)| c <= a + 0.5 && d >= a + 0.5),
                "{label}: loud {a}-{z} not cut ({cut:?})"
            );
        }
        assert!(
            !b.warning_codes.contains(&"clock_lost"),
            "{label}: {:?}",
            b.warnings
        );
    }
    // The clock alone: nothing cut, nothing lost, no word of either.
    let clean = synthesize(spec);
    let heard = listen_to_samples(
        &clean.samples,
        f64::from(spec.sample_rate),
        &ListenInput::default(),
    )
    .unwrap_or_else(|e| panic!("{label} alone: refused: {e}"));
    assert!(
        heard.cut_s.is_empty() && heard.lost_s.is_empty(),
        "{label} alone"
    );
    assert_eq!(heard.cut_beats, 0, "{label} alone");
    let codes = &heard.beats.warning_codes;
    assert!(
        !codes.contains(&"sounds_cut") && !codes.contains(&"clock_lost"),
        "{label} alone: {codes:?}"
    );
}

/// A clock that stops part-way (its ticks gone at 200 s of 300, the room's
/// noise going on) is warned with the time, not left in silence: the
/// figures are the first 200 s's.
#[test]
fn a_clock_that_stops_is_warned_with_the_time() {
    let spec = TickRecording {
        duration: 300.0,
        rate_s_per_day: 12.0,
        beat_error_ms: 1.5,
        snr_db: 90.0,
        seed: 11,
        ..TickRecording::DEFAULT
    };
    let mut rec = synthesize(&spec);
    let rate = f64::from(spec.sample_rate);
    let stop = (200.0 * rate) as usize;
    // The room's noise, 24 dB under a tick's peak (half of full scale), by
    // a seeded xorshift and Box-Muller.
    let mut state = 0x2545_F491_4F6C_DD1D_u64;
    let mut uniform = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        ((state >> 11) as f64 + 0.5) / (1u64 << 53) as f64
    };
    let sigma = 0.5 * 10f64.powf(-24.0 / 20.0);
    for (i, x) in rec.samples.iter_mut().enumerate() {
        let clock = if i < stop { f64::from(*x) } else { 0.0 };
        let noise = (-2.0 * uniform().ln()).sqrt() * (std::f64::consts::TAU * uniform()).cos();
        *x = (clock + sigma * noise) as f32;
    }
    let heard = listen_to_samples(&rec.samples, rate, &ListenInput::default()).unwrap();
    let b = &heard.beats;
    let rate_found = b.rate_s_per_day.unwrap();
    assert!((rate_found - 12.0).abs() < 0.5, "{rate_found}");
    assert_eq!(heard.lost_s.len(), 1, "{:?}", heard.lost_s);
    let [from, to] = heard.lost_s[0];
    assert!(
        (from - 200.0).abs() < 2.0 && (to - 300.0).abs() < 1.0,
        "{from} {to}"
    );
    let said: Vec<String> = b.warnings.iter().map(|w| w.to_string()).collect();
    assert!(
        b.warning_codes.contains(&"clock_lost") && said.iter().any(|w| w.contains("-300 s")),
        "{said:?}"
    );
    assert!(!b.warning_codes.contains(&"sounds_cut"), "{said:?}");
}

/// Issue 45: a long-case clock striking six in the middle and at the end;
/// a bracket clock's chime and strike. Whole recordings were refused, or
/// the clock lost after the strike with no word. A strike in the first
/// seconds and the recorder handled for its first 10 s (the tracker
/// learnt the ticks' level from the first beats, which were the strike's
/// or the cut's).
#[test]
fn strikes_and_chimes_are_cut_and_the_clock_followed() {
    let long_case = TickRecording {
        duration: 300.0,
        rate_s_per_day: 12.0,
        beat_error_ms: 1.5,
        snr_db: 24.0,
        seed: 7,
        ..TickRecording::DEFAULT
    };
    let bracket = TickRecording {
        beats_per_hour: 7200.0,
        duration: 180.0,
        rate_s_per_day: -20.0,
        beat_error_ms: -0.8,
        seed: 8,
        ..long_case
    };
    let strike = |at_s| [Interference::Strike { at_s, blows: 6 }];
    std::thread::scope(|scope| {
        scope.spawn(|| {
            heard_through("six at 240 s", &long_case, &strike(240.0), 18.0);
            heard_through("six at 120 s", &long_case, &strike(120.0), 18.0);
            heard_through("six at 2 s", &long_case, &strike(2.0), 18.0);
        });
        scope.spawn(|| {
            let chime = [
                Interference::Chime {
                    at_s: 60.0,
                    notes: 16,
                },
                Interference::Strike {
                    at_s: 74.0,
                    blows: 8,
                },
            ];
            heard_through("chime and eight", &bracket, &chime, 20.0);
            let handled = [Interference::Handling {
                at_s: 0.0,
                for_s: 10.0,
            }];
            heard_through("handled 0-10 s", &long_case, &handled, 10.0);
            heard_through("bracket handled 0-10 s", &bracket, &handled, 10.0);
        });
    });
}

/// The findings of `spec` heard with its beat rate given (and the lift's
/// 1.5° when the drop is a clock's), with `change` applied to the samples.
fn findings_of(
    spec: &TickRecording,
    change: impl Fn(&mut Vec<f32>),
) -> Vec<pendulum_theory::findings::Finding> {
    let mut rec = synthesize(spec);
    change(&mut rec.samples);
    let heard = listen_to_samples(
        &rec.samples,
        f64::from(spec.sample_rate),
        &ListenInput {
            nominal: Some(Nominal::BeatsPerHour(spec.beats_per_hour)),
            lift_angle: spec.drop_ms.map(|_| 1.5f64.to_radians()),
            ..ListenInput::default()
        },
    )
    .unwrap_or_else(|e| panic!("{spec:?}: refused: {e}"));
    heard.findings
}

/// Issue 45, item 3: a seconds clock whose escape wheel turns once a
/// minute with a ±1 ms error: found at its period and named; a bracket
/// clock's 30 s error found at its period, not named (its train is not
/// known); the amplitude within 8% (it was 11-22% short: the clean-up
/// predicted each tick from neighbours up to twenty beats away, which
/// fall short of the bend's top, and "corrected" ticks by a ringing
/// period towards the straight line).
#[test]
fn a_wheel_s_periodic_error_is_named_by_its_period() {
    use pendulum_theory::findings::Finding;
    let cases = [(3600.0, 60.0, Some(30)), (7200.0, 30.0, None)];
    for (bph, period, teeth) in cases {
        let spec = TickRecording {
            beats_per_hour: bph,
            duration: 300.0,
            rate_s_per_day: 15.0,
            snr_db: 24.0,
            periodic_error_ms: 1.0,
            periodic_error_period_s: period,
            seed: 3,
            ..TickRecording::DEFAULT
        };
        let found = findings_of(&spec, |_| ());
        let wheel = found.iter().find_map(|f| match *f {
            Finding::PeriodicError {
                period_s,
                amplitude_ms,
                escape_teeth,
                ..
            } => Some((period_s, amplitude_ms, escape_teeth)),
            _ => None,
        });
        let (p, a, t) = wheel.unwrap_or_else(|| panic!("{bph}: none in {found:?}"));
        assert!((p / period - 1.0).abs() < 0.02, "{bph}: period {p}");
        assert!((a - 1.0).abs() < 0.08, "{bph}: amplitude {a}");
        assert_eq!(t, teeth, "{bph}");
        // The same clock without the error: no such finding.
        let clean = findings_of(
            &TickRecording {
                periodic_error_ms: 0.0,
                ..spec
            },
            |_| (),
        );
        assert!(clean.is_empty(), "{bph}: {clean:?}");
    }
}

/// Issue 45, item 3: a seconds clock whose swing falls 20% an hour (its
/// drop coming later after each unlocking): found, with the fall over
/// the recording (−3.3% in 10 min) and when it would stop (the swing
/// 2.5° falling to the lift's half, 0.75°, 0.7/0.2 h from the start:
/// 3.33 h after the end).
#[test]
fn a_falling_arc_is_found_with_when_the_clock_stops() {
    use pendulum_theory::findings::Finding;
    use pendulum_theory::listening::synth::typical_drop_ms;
    let spec = TickRecording {
        duration: 600.0,
        drop_ms: Some(typical_drop_ms(1.0)),
        arc_change_percent_per_hour: -20.0,
        seed: 4,
        ..TickRecording::DEFAULT
    };
    let found = findings_of(&spec, |_| ());
    let fall = found.iter().find_map(|f| match *f {
        Finding::ArcFalls {
            change_percent,
            stops_in_h,
            ..
        } => Some((change_percent, stops_in_h)),
        _ => None,
    });
    let (change, stops) = fall.unwrap_or_else(|| panic!("none in {found:?}"));
    let truth = -20.0 * 598.0 / 3600.0;
    assert!((change - truth).abs() < 0.5, "{change} against {truth}");
    assert!((stops / 3.33 - 1.0).abs() < 0.1, "{stops}");
}

/// Hum, clipping and noise are found where they are, each alone; and no
/// finding at all on clean recordings of clocks in good order (a finding
/// that fires on them teaches users to skip the list): pendulum clocks
/// with a clock's drop and watches, a little rate, beat error under what
/// is worth setting, 24 to 35 dB.
#[test]
fn findings_come_where_their_cause_is_and_nowhere_else() {
    use pendulum_theory::findings::Finding;
    let clean = [
        (3600.0, 24.0, 0.5, 1),
        (3600.0, 35.0, -3.0, 2),
        (5400.0, 28.0, 0.6, 3),
        (7200.0, 30.0, -0.4, 4),
        (18_000.0, 30.0, 0.1, 5),
        (21_600.0, 26.0, -0.2, 6),
        (28_800.0, 32.0, 0.3, 7),
    ];
    std::thread::scope(|scope| {
        for (bph, snr, be, seed) in clean {
            scope.spawn(move || {
                let beat = 3600.0 / bph;
                let spec = TickRecording {
                    beats_per_hour: bph,
                    duration: 120.0,
                    rate_s_per_day: 4.0 - seed as f64,
                    beat_error_ms: be,
                    snr_db: snr,
                    drop_ms: (bph < 10_000.0)
                        .then(|| pendulum_theory::listening::synth::typical_drop_ms(beat)),
                    seed,
                    ..TickRecording::DEFAULT
                };
                let found = findings_of(&spec, |_| ());
                assert!(found.is_empty(), "{bph} bph seed {seed}: {found:?}");
            });
        }
    });
    let spec = TickRecording {
        duration: 60.0,
        seed: 9,
        ..TickRecording::DEFAULT
    };
    let codes =
        |found: Vec<Finding>| -> Vec<&'static str> { found.iter().map(Finding::code).collect() };
    let hum = findings_of(
        &TickRecording {
            hum_db: -6.0,
            ..spec
        },
        |_| (),
    );
    assert_eq!(codes(hum), ["hum"]);
    // Played four times too loud: the ticks' peaks cut at full scale.
    let clipped = findings_of(&spec, |s| {
        s.iter_mut().for_each(|x| *x = (4.0 * *x).clamp(-1.0, 1.0))
    });
    assert_eq!(codes(clipped), ["clipped"]);
    let noisy = findings_of(
        &TickRecording {
            snr_db: 9.0,
            ..spec
        },
        |_| (),
    );
    assert_eq!(codes(noisy), ["noisy"]);
}

/// A long-case clock in a quieter room (30 dB) striking six at 240 s. The
/// bell's beating partials, heard for 20 s after the last blow, had set
/// the beat search on 0.094 s (the whole recording refused); with the
/// beat given, the tracker lost 16 of the 279 ticks in the tail (its floor
/// was the room's before the strike, under the tail: a run over it held
/// several beats). The beat search cuts the tails too, and the tracker
/// learns its floor afresh after each cut.
#[test]
fn ticks_in_a_bell_s_tail_are_followed() {
    let quiet = TickRecording {
        duration: 300.0,
        rate_s_per_day: 12.0,
        beat_error_ms: 1.5,
        snr_db: 30.0,
        seed: 4,
        ..TickRecording::DEFAULT
    };
    let strike = [Interference::Strike {
        at_s: 240.0,
        blows: 6,
    }];
    heard_through("six at 240 s, 30 dB", &quiet, &strike, 18.0);
}

/// A tock a third of the tick (−10 dB) or less is read at its beat, or
/// refused with the reason, never at half the beat (a 21,600 watch was
/// read at 10,801 bph with a beat error of 0.01 ms): watches and clocks
/// with tocks 10-14 dB under their ticks, in no room and in a 0.3 s one.
/// The level alone cannot tell a weak tock from a room's echo (the clean
/// watch of `a_watch_through_phone_codecs_is_heard` has echoes at 0.12-0.21
/// of the ticks' rise between them); that the tock stands alone near the
/// middle can (`listening::analysis::HALF_BEAT_WEAK_RISE`).
#[test]
fn a_weak_tock_never_halves_the_beat() {
    let cases = [
        (21_600.0, -10.0, 30.0, 0.0, 21),
        (28_800.0, -10.0, 26.0, 0.3, 22),
        (18_000.0, -12.0, 30.0, 0.3, 23),
        (3600.0, -10.0, 26.0, 0.0, 24),
        (7200.0, -14.0, 30.0, 0.3, 25),
        (28_800.0, -14.0, 50.0, 0.3, 26),
    ];
    std::thread::scope(|scope| {
        for (bph, tock_db, snr_db, reverb_s, seed) in cases {
            scope.spawn(move || {
                let spec = TickRecording {
                    beats_per_hour: bph,
                    duration: if bph > 10_000.0 { 30.0 } else { 120.0 },
                    rate_s_per_day: 6.0,
                    beat_error_ms: 0.4,
                    snr_db,
                    tock_db,
                    reverb_s,
                    seed,
                    ..TickRecording::DEFAULT
                };
                let rec = synthesize(&spec);
                let heard = listen_to_samples(&rec.samples, 44_100.0, &ListenInput::default());
                match heard {
                    Ok(h) => {
                        let read = h.beats.beats_per_hour;
                        assert!(
                            (read / bph - 1.0).abs() < 1e-3,
                            "{bph} bph, tock {tock_db} dB: read at {read}"
                        );
                        assert!(
                            (h.beats.beat_error_ms - 0.4).abs() < 0.1,
                            "{bph}: beat error {}",
                            h.beats.beat_error_ms
                        );
                    }
                    Err(e) => {
                        let said = e.to_string();
                        assert!(
                            said.contains("tock"),
                            "{bph}: refused without the reason: {said}"
                        );
                    }
                }
            });
        }
    });
}
