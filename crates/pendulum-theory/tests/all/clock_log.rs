//! The clock-log analysis against synthetic logs of known truth
//! (`common/logs.rs`: an independent generator that varies what real logs
//! vary) and the cases issue 44 found wrong.
//!
//! The grid: 200 seeded logs, each drawn at random from what clocks and
//! their keepers give: a drift of 0 or ±0.01 s/day a day, a room whose
//! temperature swings 0.5 to 3 °C a day and wanders with the weather, a
//! clock that follows it 0 to 12 hours late (a quarter of them at once),
//! a barometric error or none, the body tide or none, white frequency
//! noise 0.01 to 0.2 s/day (over an hour), a random walk of the rate of 0
//! to 0.2 s/day a day, 7 to 365 days, a reading every 3 s to every day
//! (readings by hand a little early or late). The rate and each injected
//! coefficient must lie within 3 of their standard errors of the truth in
//! at least 95% of the logs, the temperature lag's 95% range must hold
//! the truth in at least 90%, and a log is refused only when it holds
//! too few readings for a mean rate.

use crate::common;

use common::logs::{generate, Log, LogSpec, BFO, EPOCH};
use common::records::Rng;
use pendulum_theory::clock_log::{analyse, LogColumn, LogInput, LogKind, LogResult, LogWarning};

/// The log `spec` makes, as the analysis takes it.
fn input(log: &Log, spec: &LogSpec) -> LogInput {
    let mut columns = vec![LogColumn::new("temperature", log.temperature_c.clone())];
    if spec.pressure_coefficient.is_some() {
        columns.push(LogColumn::new(
            "pressure",
            log.pressure_hpa.iter().map(|p| p * 100.0).collect(),
        ));
    }
    LogInput {
        time_s: log.time_s.clone(),
        kind: Some(if spec.rates {
            LogKind::Rate
        } else {
            LogKind::Offset
        }),
        values: log.values.clone(),
        columns,
        epoch_unix_s: spec.tide.then_some(EPOCH),
        station: spec.tide.then_some(BFO),
        tides: spec.tide,
        skip_stability: true,
        ..LogInput::default()
    }
}

/// A term's figure and its standard error, kept or left out (a term
/// left out gives what the model with it put back allows).
fn term(r: &LogResult, name: &str) -> Option<(f64, f64)> {
    let t = r.terms.iter().find(|t| t.name == name)?;
    Some((t.estimate?, t.standard_error?))
}

/// The grid's log number `seed`.
fn grid_spec(seed: u64) -> LogSpec {
    let mut rng = Rng(seed * 7919 + 13);
    let drift = [0.0, 0.01, -0.01][(rng.uniform() * 3.0) as usize % 3];
    let lag_s = if rng.uniform() < 0.25 {
        0.0
    } else {
        rng.uniform() * 12.0 * 3600.0
    };
    let step_s = rng.log_uniform(3.0, 86_400.0);
    let days = rng.log_uniform(7.0, 365.0);
    let random_walk = if rng.uniform() < 0.3 {
        0.0
    } else {
        rng.uniform() * 0.2
    };
    LogSpec {
        days,
        step_s,
        jitter: if step_s > 3000.0 { 0.1 } else { 0.0 },
        rate: rng.uniform() - 0.5,
        drift,
        temperature_coefficient: rng.uniform() - 0.5,
        swing_c: 0.5 + 2.5 * rng.uniform(),
        weather_c: 0.3 + rng.uniform(),
        lag_s,
        pressure_coefficient: (rng.uniform() < 0.5).then_some(-0.01),
        white_fm: rng.log_uniform(0.01, 0.2),
        random_walk,
        reading_noise_s: 0.0,
        thermometer_noise_c: 0.0,
        rates: false,
        tide: rng.uniform() < 0.3,
    }
}

/// What one log of the grid gave: per quantity, covered or not (`None`:
/// not in the check), and what was missed.
struct Outcome {
    seed: u64,
    covered: Vec<(&'static str, bool)>,
    lag_covered: Option<bool>,
    refused: bool,
    /// Warnings a right answer should not carry.
    false_alarms: Vec<String>,
    notes: Vec<String>,
}

fn judge(seed: u64) -> Outcome {
    let spec = grid_spec(seed);
    let log = generate(&spec, seed);
    let mut out = Outcome {
        seed,
        covered: Vec::new(),
        lag_covered: None,
        refused: false,
        false_alarms: Vec::new(),
        notes: Vec::new(),
    };
    let r = match analyse(&input(&log, &spec)) {
        Ok(r) => r,
        Err(e) => {
            out.refused = true;
            // Refused only when a mean rate needs more readings.
            let readings = log.time_s.len();
            out.covered.push(("refusal", readings < 5));
            out.notes
                .push(format!("refused with {readings} readings: {e}"));
            return out;
        }
    };
    let mut check = |name: &'static str, got: Option<(f64, f64)>, truth: f64| {
        let ok = got.is_some_and(|(v, se)| (v - truth).abs() <= 3.0 * se);
        if !ok {
            out.notes.push(format!("{name}: {got:?} against {truth}"));
        }
        out.covered.push((name, ok));
    };
    check(
        "rate",
        Some((r.rate_s_per_day, r.rate_standard_error_s_per_day)),
        log.mean_rate,
    );
    // A log too short for terms gives its mean rate alone, and says so.
    if r.bins >= 10 {
        check("drift", term(&r, "drift"), spec.drift);
        check(
            "temperature",
            term(&r, "temperature"),
            spec.temperature_coefficient,
        );
        if let Some(c) = spec.pressure_coefficient {
            check("pressure", term(&r, "pressure"), c);
        }
        if spec.tide && spec.days >= 3.0 {
            check("tide", term(&r, "tide"), 1.0);
        }
        if let Some([lo, hi]) = r.temperature_lag_range_s {
            let covered = lo <= spec.lag_s * (1.0 + 1e-9) && spec.lag_s <= hi * (1.0 + 1e-9) + 1.0;
            if !covered {
                out.notes.push(format!(
                    "lag {} h outside [{}, {}]",
                    spec.lag_s / 3600.0,
                    lo / 3600.0,
                    hi / 3600.0
                ));
            }
            out.lag_covered = Some(covered);
        }
    } else {
        assert!(
            r.warnings
                .iter()
                .any(|w| matches!(w, LogWarning::Short { .. })),
            "seed {seed}: {} bins and no word of it",
            r.bins
        );
    }
    // The generator makes no jumps or glitches: none may be reported.
    for w in &r.warnings {
        if matches!(
            w,
            LogWarning::JumpsUndone { .. }
                | LogWarning::GlitchesLeftOut { .. }
                | LogWarning::WrapsUndone { .. }
                | LogWarning::Implausible { .. }
        ) {
            out.false_alarms.push(format!("{w:?}"));
        }
    }
    out
}

/// The 200 logs, run before a release (several CPU-minutes); CI runs
/// the first 60 of them to the same thresholds.
#[test]
#[ignore = "the 200 logs (about 2 CPU-minutes): cargo test --release -p pendulum-theory --test all clock_log:: -- --ignored"]
fn two_hundred_logs_of_every_kind() {
    grid(1..=200, true);
}

/// The first 60 of the 200 logs. A few dozen cannot hold a flat 95%
/// (one miss in 29 pressure logs is 3.4%): each count must instead be
/// what a 95% (the lag's range: 90%) coverage gives, a one-sided exact
/// binomial test at 1%.
#[test]
fn sixty_logs_of_every_kind() {
    grid(1..=60, false);
}

/// Every figure within 3 standard errors in 95% of the logs given, the
/// lag's range holding the truth in 90%, no accident warned on any: as
/// counts of the 200 (`flat`), or as counts a binomial draw at those
/// rates gives.
fn grid(seeds: std::ops::RangeInclusive<u64>, flat: bool) {
    let holds = |k: usize, n: usize, p: f64| {
        if flat {
            k as f64 >= p * n as f64
        } else {
            binomial_at_most(k, n, p) >= 0.01
        }
    };
    let seeds: Vec<u64> = seeds.collect();
    let half = seeds.len().div_ceil(2);
    let outcomes: Vec<Outcome> = std::thread::scope(|scope| {
        let handles: Vec<_> = seeds
            .chunks(half)
            .map(|chunk| scope.spawn(move || chunk.iter().map(|&s| judge(s)).collect::<Vec<_>>()))
            .collect();
        handles
            .into_iter()
            .flat_map(|h| h.join().unwrap())
            .collect()
    });
    let misses: Vec<String> = outcomes
        .iter()
        .filter(|o| !o.notes.is_empty())
        .map(|o| format!("seed {}: {}", o.seed, o.notes.join("; ")))
        .collect();
    for name in [
        "rate",
        "drift",
        "temperature",
        "pressure",
        "tide",
        "refusal",
    ] {
        let rows: Vec<bool> = outcomes
            .iter()
            .flat_map(|o| o.covered.iter())
            .filter(|c| c.0 == name)
            .map(|c| c.1)
            .collect();
        let covered = rows.iter().filter(|&&c| c).count();
        println!(
            "{name}: {covered} of {} within 3 standard errors",
            rows.len()
        );
        assert!(
            holds(covered, rows.len(), 0.95),
            "{name}: {covered} of {}; misses: {misses:#?}",
            rows.len()
        );
    }
    let lags: Vec<bool> = outcomes.iter().filter_map(|o| o.lag_covered).collect();
    let held = lags.iter().filter(|&&c| c).count();
    println!("lag: {held} of {} ranges hold the truth", lags.len());
    assert!(
        holds(held, lags.len(), 0.9),
        "lag: {held} of {}",
        lags.len()
    );
    let alarms: Vec<String> = outcomes
        .iter()
        .flat_map(|o| {
            o.false_alarms
                .iter()
                .map(move |a| format!("seed {}: {a}", o.seed))
        })
        .collect();
    assert!(alarms.is_empty(), "warnings on clean logs: {alarms:#?}");
}

/// P(X ≤ k) for X binomial with `n` trials of chance `p`, by summing the
/// terms (each from the last by the ratio of successive terms).
fn binomial_at_most(k: usize, n: usize, p: f64) -> f64 {
    let mut term = (1.0 - p).powi(n as i32);
    let mut sum = term;
    for i in 0..k.min(n) {
        term *= (n - i) as f64 / (i + 1) as f64 * p / (1.0 - p);
        sum += term;
    }
    sum
}

#[test]
fn the_binomial_tail_is_the_textbook_one() {
    // P(X ≤ 2) of 10 fair coins: 56/1024; all of them: 1.
    assert!((binomial_at_most(2, 10, 0.5) - 56.0 / 1024.0).abs() < 1e-15);
    assert!((binomial_at_most(10, 10, 0.5) - 1.0).abs() < 1e-12);
}

/// Issue 44's plain 20-day log: a drift of 0.01 s/day a day, the room
/// swinging ±1.5 °C and the clock following at once, white frequency
/// noise 0.05 s/day, a rate of 0.50: wrong in 9 of 12 seeds before (the
/// lag at its bound, a walk invented, the drift dropped, the rate 0.39 ±
/// 0.007). Every seed's rate and coefficients within 3 standard errors,
/// read every 10 minutes and every hour. (Read every minute, seed 7's
/// drift is 3.15 standard errors off: over 100 seeds there the drift's
/// errors have an RMS of 1.07 standard errors, a chance of 1 in 600.)
#[test]
fn the_plain_twenty_day_log_of_twelve_seeds() {
    for step_s in [600.0, 3600.0] {
        let spec = LogSpec {
            days: 20.0,
            step_s,
            drift: 0.01,
            temperature_coefficient: -0.2,
            swing_c: 1.5,
            lag_s: 0.0,
            white_fm: 0.05,
            rate: 0.5,
            ..LogSpec::default()
        };
        for seed in 1..=12 {
            let log = generate(&spec, seed);
            let r = analyse(&input(&log, &spec)).unwrap();
            let z = |got: Option<(f64, f64)>, truth: f64| {
                let (v, se) = got.unwrap();
                (v - truth) / se
            };
            let checks = [
                (
                    "rate",
                    z(
                        Some((r.rate_s_per_day, r.rate_standard_error_s_per_day)),
                        log.mean_rate,
                    ),
                ),
                ("drift", z(term(&r, "drift"), 0.01)),
                ("temperature", z(term(&r, "temperature"), -0.2)),
            ];
            for (name, z) in checks {
                assert!(
                    z.abs() <= 3.0,
                    "every {step_s} s, seed {seed}: {name} {z} standard errors off"
                );
            }
            let [lo, _] = r.temperature_lag_range_s.unwrap();
            assert_eq!(lo, 0.0, "seed {seed}: a lag of 0 lies in the range");
        }
    }
}

/// A chronometer's daily offsets over 341 days whose rate wanders (a
/// random walk): the rate is the log's own mean rate (its ends' offsets
/// over its span) less the weather, not the first weeks' rate the
/// walk's start gave before; its standard error holds the truth.
#[test]
fn a_daily_log_whose_rate_wanders_gives_its_mean_rate() {
    for seed in 1..=6 {
        let spec = LogSpec {
            days: 341.0,
            step_s: 86_400.0,
            jitter: 0.05,
            rate: -0.6,
            temperature_coefficient: 0.0,
            white_fm: 0.2,
            random_walk: 0.1,
            reading_noise_s: 0.05,
            ..LogSpec::default()
        };
        let log = generate(&spec, seed);
        let mut given = input(&log, &spec);
        given.columns.clear();
        let r = analyse(&given).unwrap();
        let n = log.time_s.len();
        let own =
            (log.values[n - 1] - log.values[0]) / (log.time_s[n - 1] - log.time_s[0]) * 86_400.0;
        assert!(
            (r.rate_s_per_day - own).abs() < 0.05 * r.rate_standard_error_s_per_day,
            "seed {seed}: {} ± {} against the log's own {own}",
            r.rate_s_per_day,
            r.rate_standard_error_s_per_day
        );
        assert!(
            (r.rate_s_per_day - log.mean_rate).abs() <= 3.0 * r.rate_standard_error_s_per_day,
            "seed {seed}: {} ± {} against {}",
            r.rate_s_per_day,
            r.rate_standard_error_s_per_day,
            log.mean_rate
        );
    }
}

/// A master clock's 25 hourly offsets against NTP (refused at every bin
/// before): its mean rate with its standard error, and a word that the
/// log is too short for the drift.
#[test]
fn twenty_five_hourly_offsets_give_a_rate() {
    let spec = LogSpec {
        days: 1.0,
        step_s: 3600.0,
        rate: 1.3,
        temperature_coefficient: 0.0,
        white_fm: 0.1,
        reading_noise_s: 2e-3,
        ..LogSpec::default()
    };
    let log = generate(&spec, 4);
    assert_eq!(log.time_s.len(), 25);
    let mut given = input(&log, &spec);
    given.columns.clear();
    let r = analyse(&given).unwrap();
    assert!((r.rate_s_per_day - log.mean_rate).abs() <= 3.0 * r.rate_standard_error_s_per_day);
    assert!(r.rate_standard_error_s_per_day < 0.2);
    assert!(r
        .warnings
        .iter()
        .any(|w| matches!(w, LogWarning::Short { what: "drift" })));
    // Fewer readings than a mean rate needs are refused by name.
    given.time_s.truncate(4);
    given.values.truncate(4);
    let e = analyse(&given).unwrap_err();
    assert!(e.to_string().contains("at least 5 samples"), "{e}");
}

/// One missed pulse (an offset read a second late once) in a month of
/// offsets: left out with a warning that names its time; the rate is the
/// clean log's.
#[test]
fn a_glitch_is_left_out_and_named() {
    let spec = LogSpec {
        days: 30.0,
        step_s: 10.0,
        ..LogSpec::default()
    };
    let log = generate(&spec, 9);
    let clean = analyse(&input(&log, &spec)).unwrap();
    let mut glitched = input(&log, &spec);
    let at = glitched.time_s.len() / 3;
    glitched.values[at] += 1.0;
    let r = analyse(&glitched).unwrap();
    let named = r.warnings.iter().find_map(|w| match w {
        LogWarning::GlitchesLeftOut {
            count,
            first_time_s,
            largest_s,
            ..
        } => Some((*count, *first_time_s, *largest_s)),
        _ => None,
    });
    let (count, time, size) = named.expect("the glitch is named");
    assert_eq!(count, 1);
    assert_eq!(time, glitched.time_s[at]);
    assert!((size - 1.0).abs() < 1e-3);
    assert!(
        (r.rate_s_per_day - clean.rate_s_per_day).abs() < 0.1 * clean.rate_standard_error_s_per_day
    );
}

/// A room that swings 3 °C a day and no tide: the spectrum is of what
/// the weather leaves, so the day's swing is not read as K1 (it was
/// "K1 seen, 0.57 s/day", a hundred times the body tide).
#[test]
fn a_daily_swing_is_not_a_tide() {
    let spec = LogSpec {
        days: 60.0,
        step_s: 300.0,
        swing_c: 3.0,
        temperature_coefficient: -0.2,
        white_fm: 0.02,
        ..LogSpec::default()
    };
    let log = generate(&spec, 2);
    let r = analyse(&input(&log, &spec)).unwrap();
    let s = r.spectrum.as_ref().unwrap();
    for name in ["K1", "S1", "O1"] {
        if let Some(l) = s.lines.iter().find(|l| l.name == name) {
            assert!(
                l.amplitude_s_per_day < 0.02,
                "{name}: {} s/day",
                l.amplitude_s_per_day
            );
        }
    }
}

/// With a wandering rate the figures draw the model with the wander it
/// estimated: the bins lie on both sides of the rate's model in every
/// three weeks (the line ran above nearly all of them for weeks), and
/// the partial residuals scatter about their line.
#[test]
fn the_figures_draw_the_wander() {
    let spec = LogSpec {
        days: 120.0,
        step_s: 600.0,
        random_walk: 0.15,
        white_fm: 0.05,
        ..LogSpec::default()
    };
    let log = generate(&spec, 3);
    let r = analyse(&input(&log, &spec)).unwrap();
    let three_weeks = (21.0 * 86_400.0 / r.bin_s) as usize;
    for window in r.per_bin.chunks(three_weeks) {
        let above = window.iter().filter(|b| b[1] > b[2]).count() as f64 / window.len() as f64;
        assert!(
            (0.3..=0.7).contains(&above),
            "{above} of the bins above the model"
        );
    }
    let p = r
        .partials
        .iter()
        .find(|p| p.term.name == "temperature")
        .unwrap();
    let above =
        p.x.iter()
            .zip(&p.y)
            .filter(|(x, y)| **y > p.at_mean + p.slope * (**x - p.mean))
            .count() as f64
            / p.x.len() as f64;
    assert!(
        (0.4..=0.6).contains(&above),
        "{above} of the partials above their line"
    );
}

/// The pulse a flag makes, by direct quadrature of the exact motion:
/// `Δt = ∫_{−α}^{α} dθ / (ω_n sqrt(2 (cos θ − cos A)))`, composite
/// five-point Gauss–Legendre over 4,000 panels; independent of the
/// elliptic-function route the library takes.
fn pulse_by_quadrature(amplitude: f64, flag: f64, radius: f64, length: f64, g: f64) -> f64 {
    let alpha = 2.0 * (flag / (4.0 * radius)).asin();
    let omega = (g / length).sqrt();
    let nodes = [
        (0.0, 128.0 / 225.0),
        (-0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
        (0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
        (-0.906_179_845_938_664, 0.236_926_885_056_189_1),
        (0.906_179_845_938_664, 0.236_926_885_056_189_1),
    ];
    let panels = 4000;
    let h = 2.0 * alpha / panels as f64;
    let mut sum = 0.0;
    for p in 0..panels {
        let centre = -alpha + (p as f64 + 0.5) * h;
        for (x, w) in nodes {
            let theta = centre + 0.5 * h * x;
            sum += 0.5 * h * w / (omega * (2.0 * (theta.cos() - amplitude.cos())).sqrt());
        }
    }
    sum
}

/// The amplitude from a pulse's width, against the exact motion
/// integrated independently: 1e-9 relative from 1° to 60°, for a
/// seconds pendulum's bob flag and a gate near the pivot.
#[test]
fn pulse_width_gives_the_amplitude_of_the_exact_motion() {
    use pendulum_theory::clock_log::amplitude_from_pulse;
    let g = 9.81;
    for (flag, radius, length) in [
        (0.01_f64, 1.0_f64, 0.994),
        (0.005, 0.3, 0.994),
        (0.02, 0.25, 0.2485),
    ] {
        for degrees in [1.0_f64, 2.0, 3.0, 5.0, 10.0, 30.0, 60.0] {
            let a = degrees.to_radians();
            let alpha = 2.0 * (flag / (4.0 * radius)).asin();
            if alpha > 0.8 * a {
                continue;
            }
            let pulse = pulse_by_quadrature(a, flag, radius, length, g);
            let got = amplitude_from_pulse(pulse, flag, radius, length, g).unwrap();
            assert!(
                (got / a - 1.0).abs() < 1e-9,
                "{degrees}° (flag {flag} m at {radius} m): got {}°",
                got.to_degrees()
            );
        }
    }
    // To first order the speed at the bottom: w/Δt = 2 ω r sin(A/2).
    let (flag, radius, length) = (0.001, 1.0, 1.0);
    let a = 3f64.to_radians();
    let v = 2.0 * (g / length).sqrt() * radius * (a / 2.0).sin();
    let got = amplitude_from_pulse(flag / v, flag, radius, length, g).unwrap();
    assert!((got / a - 1.0).abs() < 1e-3);
    // A pulse no swing that clears the flag makes is refused.
    assert!(amplitude_from_pulse(10.0, 0.01, 1.0, 1.0, g).is_err());
    assert!(amplitude_from_pulse(-1.0, 0.01, 1.0, 1.0, g).is_err());
}

/// A photogate's flag width or gate radius without its pulse widths was
/// ignored (a new user's find): refused by name.
#[test]
fn a_photogates_sizes_without_its_pulses_are_refused() {
    let time: Vec<f64> = (0..200).map(|i| i as f64 * 3600.0).collect();
    let values: Vec<f64> = time.iter().map(|t| 1e-6 * t).collect();
    for (flag, radius, field) in [
        (Some(0.01), None, "flag_width"),
        (None, Some(1.0), "gate_radius"),
    ] {
        let e = analyse(&LogInput {
            time_s: time.clone(),
            kind: Some(LogKind::Offset),
            values: values.clone(),
            flag_width_m: flag,
            gate_radius_m: radius,
            ..LogInput::default()
        })
        .unwrap_err();
        assert_eq!(e.field_name(), Some(field), "{e}");
        assert!(e.to_string().contains("pulse_width"), "{e}");
    }
}
