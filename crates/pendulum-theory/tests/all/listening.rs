//! Ticks found in synthetic recordings against the true tick times: the
//! library's generator (seeds fixed, tick shapes drawn per seed), and a
//! second generator written here (noise-burst ticks, a drop louder than
//! the tick) so that the detector is not tuned to one shape.

use pendulum_theory::fitting::beat_log::Nominal;
use pendulum_theory::fitting::beats::analyse_beats;
use pendulum_theory::listening::analysis::{listen, ListenFailure, ListenInput, SliceSource};
use pendulum_theory::listening::detect::Tick;
use pendulum_theory::listening::synth::{synthesize, Synthesized, TickRecording};

/// What the detector found.
struct Found {
    ticks: Vec<Tick>,
    /// Onset to drop, s, per side.
    drops: [Option<f64>; 2],
    /// Beats reported missed (no tick found, or one dropped as noise).
    reported: usize,
}

/// Runs the detector `pendulum listen` and Python's `listen` run (the one
/// library call), over the samples in blocks of 4096 (as a decoder feeds
/// them). `None` when no beat is found; no ticks when fewer than four
/// stand out of the noise (the call refuses the recording).
fn detect(samples: &[f32], rate: f64, nominal_beat: Option<f64>) -> Option<Found> {
    let mut source = SliceSource {
        samples,
        rate: rate as u32,
    };
    let input = ListenInput {
        nominal: nominal_beat.map(|b| Nominal::Period(2.0 * b)),
        ..ListenInput::default()
    };
    match listen(&mut source, &input) {
        Ok(r) => Some(Found {
            ticks: r.ticks,
            drops: r.drop_ms.map(|d| d.map(|d| d * 1e-3)),
            reported: r.missed,
        }),
        // Refused for the noise, or for ticks on one side only (the tocks
        // too weak to time: issue 24's refusal): nothing found, nothing
        // invented.
        Err(ListenFailure::Refused(r))
            if r.reason.contains("stand out of the noise")
                || r.reason.contains("only every other beat") =>
        {
            Some(Found {
                ticks: Vec::new(),
                drops: [None, None],
                reported: 0,
            })
        }
        Err(ListenFailure::Refused(r)) => {
            eprintln!("refused: {r}");
            None
        }
        Err(ListenFailure::Source(never)) => match never {},
    }
}

struct Score {
    rms_ms: f64,
    matched: usize,
    /// Ticks more than 5 ms from every true tick.
    invented: usize,
    /// True ticks with no tick found within 0.5 ms.
    missed: usize,
}

fn score(ticks: &[Tick], truth: &[f64]) -> Score {
    let mut errors = Vec::new();
    let mut invented = 0;
    for t in ticks {
        let e = truth
            .iter()
            .map(|&x| t.time - x)
            .min_by(|a, b| a.abs().total_cmp(&b.abs()))
            .unwrap_or(f64::INFINITY);
        if e.abs() < 0.5e-3 {
            errors.push(e);
        } else if e.abs() > 5e-3 {
            invented += 1;
        }
    }
    let n = errors.len().max(1) as f64;
    let rms = (errors.iter().map(|e| e * e).sum::<f64>() / n).sqrt();
    Score {
        rms_ms: rms * 1e3,
        matched: errors.len(),
        invented,
        missed: truth.len() - errors.len(),
    }
}

fn spec(bph: f64, sample_rate: u32, snr_db: f64, seed: u64) -> TickRecording {
    TickRecording {
        sample_rate,
        duration: 600.0,
        beats_per_hour: bph,
        rate_s_per_day: 12.0,
        rate_change_s_per_day_per_hour: 0.0,
        beat_error_ms: 1.5,
        snr_db,
        reverb_s: 0.3,
        hum_db: -30.0,
        missing: 0.0,
        seed,
        ..TickRecording::DEFAULT
    }
}

/// The acceptance bounds: tick times within 0.1 ms RMS, no tick invented
/// or missed, rate within 0.05 s/day, beat error within 0.1 ms.
fn check_exact(label: &str, found: &Found, rec: &Synthesized, nominal_beat: f64, rate: f64) {
    let truth = &rec.ticks;
    let sc = score(&found.ticks, truth);
    let times: Vec<f64> = found.ticks.iter().map(|t| t.time).collect();
    let a = analyse_beats(&times, Some(nominal_beat)).unwrap();
    let drops = found.drops.map(|d| d.map(|d| d * 1e3));
    eprintln!(
        "{label}: drop {drops:.2?} ms (truth {:.2})",
        rec.drop_delay * 1e3
    );
    for d in drops {
        let d = d.unwrap_or_else(|| panic!("{label}: no drop found"));
        // Within 0.7 ms: a room echo of the tick arriving just before the
        // drop moves its onset (18,000 bph, seed 24: 0.66 ms early).
        assert!(
            (d - rec.drop_delay * 1e3).abs() < 0.7,
            "{label}: drop {d} ms"
        );
    }
    eprintln!(
        "{label}: rms {:.4} ms, matched {} of {}, invented {}, missed {} (reported {}), rate {:.4}, beat error {:.4}",
        sc.rms_ms,
        sc.matched,
        truth.len(),
        sc.invented,
        sc.missed,
        found.reported,
        a.rate_s_per_day.unwrap(),
        a.beat_error_ms
    );
    assert!(sc.rms_ms < 0.1, "{label}");
    assert_eq!((sc.invented, sc.missed), (0, 0), "{label}");
    assert!((a.rate_s_per_day.unwrap() - rate).abs() < 0.05, "{label}");
    assert!((a.beat_error_ms - 1.5).abs() < 0.1, "{label}");
}

#[test]
fn ten_minutes_at_3600_bph() {
    let rec = synthesize(&spec(3600.0, 44_100, 20.0, 11));
    let found = detect(&rec.samples, 44_100.0, None).expect("a beat");
    check_exact("3600 bph", &found, &rec, 1.0, 12.0);
}

/// Every rate of the issue, at 44.1 kHz and at a phone's 8 kHz, each with
/// its own tick shape (seed).
#[test]
fn every_rate_at_44_and_8_khz() {
    for (bph, seed) in [
        (1800.0, 21),
        (2880.0, 22),
        (5400.0, 23),
        (18_000.0, 24),
        (28_800.0, 25),
    ] {
        for sample_rate in [44_100, 8000] {
            let mut s = spec(bph, sample_rate, 20.0, seed);
            s.duration = 300.0;
            let rec = synthesize(&s);
            let found = detect(&rec.samples, f64::from(sample_rate), None).expect("a beat");
            let label = format!("{bph} bph at {sample_rate} Hz");
            check_exact(&label, &found, &rec, 3600.0 / bph, 12.0);
        }
    }
    let mut s = spec(3600.0, 8000, 20.0, 26);
    s.duration = 300.0;
    let rec = synthesize(&s);
    let found = detect(&rec.samples, 8000.0, None).expect("a beat");
    check_exact("3600 bph at 8000 Hz", &found, &rec, 1.0, 12.0);
}

/// In strong noise the ticks that do not stand out are reported missed,
/// and nothing is taken for a tick: at 6 dB (a tick's peak twice the
/// noise's RMS) and 8 dB, with and without the nominal rate given.
#[test]
fn strong_noise_reports_missed_beats_and_invents_none() {
    // The four records are independent: each on its own thread.
    std::thread::scope(|scope| {
        for (snr, bph, seed) in [
            (6.0, 3600.0, 31),
            (6.0, 18_000.0, 32),
            (8.0, 3600.0, 33),
            (8.0, 28_800.0, 34),
        ] {
            scope.spawn(move || strong_noise_case(snr, bph, seed));
        }
    });
}

/// One record of [`strong_noise_reports_missed_beats_and_invents_none`].
fn strong_noise_case(snr: f64, bph: f64, seed: u64) {
    {
        let rec = synthesize(&spec(bph, 44_100, snr, seed));
        for nominal in [None, Some(3600.0 / bph)] {
            let label = format!("{snr} dB, {bph} bph, nominal {nominal:?}");
            let Some(found) = detect(&rec.samples, 44_100.0, nominal) else {
                eprintln!("{label}: no beat found");
                assert!(nominal.is_none(), "{label}");
                continue;
            };
            let sc = score(&found.ticks, &rec.ticks);
            eprintln!(
                "{label}: matched {} of {}, invented {}, missed {} (reported {})",
                sc.matched,
                rec.ticks.len(),
                sc.invented,
                sc.missed,
                found.reported
            );
            assert_eq!(sc.invented, 0, "{label}");
            // Every beat of the record between the first tick kept and the
            // last is accounted for: found, or reported missed (none is
            // counted before the first or after the last, issue 24).
            let (Some(first), Some(last)) = (found.ticks.first(), found.ticks.last()) else {
                continue;
            };
            let half = 1800.0 / bph;
            let inside = rec
                .ticks
                .iter()
                .filter(|&&t| t > first.time - half && t < last.time + half)
                .count();
            assert!(
                found.ticks.len() + found.reported + 2 >= inside,
                "{label}: {} found, {} reported, {inside} inside",
                found.ticks.len(),
                found.reported
            );
            // Nor many more: the tracker's count across long runs of
            // misses may slip a beat in a few hundred (4 in 1,705 at 6 dB).
            assert!(
                found.ticks.len() + found.reported <= inside + 2 + inside / 100,
                "{label}: {} found, {} reported, {inside} inside",
                found.ticks.len(),
                found.reported
            );
        }
    }
}

/// A clock in strong noise is heard at its own beat or refused, never at
/// half its beat (every other tick taken for the beat, the tocks between
/// them too faint to stand on their own): at 6 dB, 3,600 beats an hour,
/// seed 7 of the twelve `synth ticks` seeds (three heard, the rest refused)
/// was read at 1,800 with a beat error of 0.001 ms and advice for a 4 m
/// pendulum; the three are checked.
#[test]
fn strong_noise_never_halves_the_beat() {
    std::thread::scope(|scope| {
        for seeds in [[7].as_slice(), &[10, 11]] {
            scope.spawn(move || {
                for &seed in seeds {
                    let mut s = spec(3600.0, 44_100, 6.0, seed);
                    s.duration = 300.0;
                    let rec = synthesize(&s);
                    let mut source = SliceSource {
                        samples: &rec.samples,
                        rate: 44_100,
                    };
                    if let Ok(r) = listen(&mut source, &ListenInput::default()) {
                        let bph = r.beats.beats_per_hour;
                        eprintln!("seed {seed}: {bph} beats an hour");
                        assert!((bph / 3600.0 - 1.0).abs() < 0.01, "seed {seed}: {bph}");
                    }
                }
            });
        }
    });
}

/// Ticks left out (a knock covered them, or the clock hesitated) are
/// reported missed, never filled in.
#[test]
fn missing_ticks_are_reported() {
    let mut s = spec(5400.0, 44_100, 20.0, 41);
    s.duration = 300.0;
    s.missing = 0.03;
    let rec = synthesize(&s);
    let found = detect(&rec.samples, 44_100.0, None).expect("a beat");
    let sc = score(&found.ticks, &rec.ticks);
    eprintln!(
        "3% left out: matched {} of {}, {} left out, invented {}, reported {}",
        sc.matched,
        rec.ticks.len(),
        rec.missing.len(),
        sc.invented,
        found.reported
    );
    assert!(rec.missing.len() > 5);
    assert_eq!((sc.invented, sc.missed), (0, 0));
    assert_eq!(found.reported, rec.missing.len());
}

/// A second generator, independent of the library's: each sound a burst
/// of band-limited noise (not resonances), the drop 1.6 times louder than
/// the unlocking and 12 ms after it (as in a watch or a small escapement),
/// or at 0.7 of it and 180 ms after (a seconds pendulum crossing a small
/// lift), a slow fade of the level (the phone moved), no room. The first
/// sound is the tick.
#[test]
fn another_generator_with_a_louder_drop() {
    for (drop_delay, drop_gain) in [(0.012, 1.6), (0.180, 0.7)] {
        second_generator(drop_delay, drop_gain);
    }
}

fn second_generator(drop_delay: f64, drop_gain: f64) {
    let rate: f64 = 22_050.0;
    let beat = 3600.0 / 4320.0 / (1.0 - 30.0 / 86_400.0); // 4320 bph losing 30 s/day
    let duration = 240.0;
    let n = (duration * rate) as usize;
    let mut state = 0x2545_F491_4F6C_DD1D_u64;
    let mut noise = move || {
        // xorshift64*, uniform in [-1, 1).
        state ^= state >> 12;
        state ^= state << 25;
        state ^= state >> 27;
        (state.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    };
    let burst: Vec<f64> = {
        // Noise through a two-pole resonator at 2.7 kHz, decaying in 0.8 ms.
        let (f, r) = (2700.0 / rate, (-1.0 / (0.8e-3 * rate)).exp());
        let (a1, a2) = (2.0 * r * (std::f64::consts::TAU * f).cos(), -r * r);
        let (mut y1, mut y2) = (0.0, 0.0);
        let raw: Vec<f64> = (0..(0.01 * rate) as usize)
            .map(|i| {
                let x = if i < 12 { noise() } else { 0.0 };
                let y = x + a1 * y1 + a2 * y2;
                y2 = y1;
                y1 = y;
                y
            })
            .collect();
        let peak = raw.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        raw.iter().map(|v| v / peak).collect()
    };
    let mut samples = vec![0.0_f64; n];
    let mut truth = Vec::new();
    let mut t: f64 = 0.3;
    let mut k = 0;
    while t + 0.05 < duration {
        let shift = if k % 2 == 1 { 2.0e-3 } else { 0.0 };
        let onset = t + shift;
        truth.push(onset);
        let level = 0.3 * (1.0 - 0.5 * onset / duration);
        for (gain, at) in [(level, onset), (drop_gain * level, onset + drop_delay)] {
            let first = (at * rate).ceil() as usize;
            // Linear interpolation of the burst at the exact onset.
            let frac = first as f64 - at * rate;
            for (j, s) in samples
                .iter_mut()
                .skip(first)
                .take(burst.len() - 1)
                .enumerate()
            {
                let v = burst[j] * (1.0 - frac) + burst[j + 1] * frac;
                *s += gain * v;
            }
        }
        t += beat;
        k += 1;
    }
    let samples: Vec<f32> = samples
        .iter()
        .map(|&v| (v + 0.01 * noise()) as f32)
        .collect();
    let found = detect(&samples, rate, None).expect("a beat");
    let sc = score(&found.ticks, &truth);
    let times: Vec<f64> = found.ticks.iter().map(|t| t.time).collect();
    let a = analyse_beats(&times, Some(3600.0 / 4320.0)).unwrap();
    eprintln!(
        "second generator, drop {drop_delay} s: found {:?} s, rms {:.4} ms, matched {} of {}, invented {}, rate {:.3}, beat error {:.3}",
        found.drops,
        sc.rms_ms,
        sc.matched,
        truth.len(),
        sc.invented,
        a.rate_s_per_day.unwrap(),
        a.beat_error_ms
    );
    assert_eq!((sc.invented, sc.missed), (0, 0));
    assert!(sc.rms_ms < 0.1);
    assert!((a.rate_s_per_day.unwrap() + 30.0).abs() < 0.05);
    assert!((a.beat_error_ms - 2.0).abs() < 0.1);
    for d in found.drops {
        let d = d.expect("a drop");
        assert!(
            (d - drop_delay).abs() < 0.7e-3,
            "drop {d} s against {drop_delay} s"
        );
    }
}

/// The median sounds shown (`MedianSound::shown`) run from before the
/// unlocking to 5 ms past the drop the analysis reports, so a picture of
/// them shows both sounds of a beat; the sounds matched (`samples`) stop
/// before the drop, as the timing needs, and are the shown ones' start.
#[test]
fn the_median_sounds_shown_cover_the_drop() {
    let rec = synthesize(&TickRecording {
        duration: 240.0,
        ..spec(3600.0, 44_100, 25.0, 5)
    });
    let mut source = SliceSource {
        samples: &rec.samples,
        rate: 44_100,
    };
    let r = listen(&mut source, &ListenInput::default()).expect("heard");
    let sounds = r.sounds.expect("median sounds");
    for (side, sound) in sounds.iter().enumerate() {
        let drop = r.drop_ms[side].expect("a drop") * 1e-3;
        let after_onset = (sound.shown.len() as f64 - sound.onset) / 44_100.0;
        assert!(
            after_onset >= drop + 4e-3,
            "side {side}: {after_onset} s shown, drop {drop} s"
        );
        let matched = (sound.samples.len() as f64 - sound.onset) / 44_100.0;
        assert!(matched < drop, "side {side}: matched to {matched} s");
        // The same median from the same start: the sound matched is the
        // shown one's beginning.
        assert_eq!(&sound.shown[..sound.samples.len()], &sound.samples[..]);
    }
}
