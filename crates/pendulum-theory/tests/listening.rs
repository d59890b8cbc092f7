//! Ticks found in synthetic recordings (the library's own generator, seeds
//! fixed, tick shapes drawn per seed) against the true tick times.

use pendulum_theory::fitting::beats::analyse_beats;
use pendulum_theory::listening::detect::{
    beat_period, coarse_onsets, drop_outliers, envelope_rate, Envelope, Refiner, Tick,
};
use pendulum_theory::listening::synth::{synthesize, TickRecording};

/// Runs the detector over `samples` in blocks of 4096, as a decoder feeds it.
fn detect(samples: &[f32], rate: f64, beat: Option<f64>) -> (Vec<Tick>, usize) {
    let mut envelope = Envelope::new(rate);
    for block in samples.chunks(4096) {
        envelope.push(block);
    }
    let env_rate = envelope_rate(&envelope, rate);
    let beat = beat
        .or_else(|| beat_period(&envelope.values, env_rate, 0.05, 2.0))
        .expect("a beat");
    let coarse = coarse_onsets(&envelope.values, env_rate, beat);
    let mut refiner = Refiner::new(rate, &coarse);
    for block in samples.chunks(4096) {
        refiner.push(block);
    }
    let (ticks, rejected) = refiner.finish();
    let (ticks, dropped) = drop_outliers(ticks);
    (ticks, coarse.missed + rejected + dropped)
}

struct Score {
    rms_ms: f64,
    mean_ms: f64,
    matched: usize,
    invented: usize,
    missed: usize,
}

fn score(ticks: &[Tick], truth: &[f64]) -> Score {
    let mut errors = Vec::new();
    let mut invented = 0;
    for t in ticks {
        match truth
            .iter()
            .map(|&x| t.time - x)
            .min_by(|a, b| a.abs().total_cmp(&b.abs()))
        {
            Some(e) if e.abs() < 5e-3 => errors.push(e),
            _ => invented += 1,
        }
    }
    let n = errors.len() as f64;
    let mean = errors.iter().sum::<f64>() / n;
    let rms = (errors.iter().map(|e| e * e).sum::<f64>() / n).sqrt();
    Score {
        rms_ms: rms * 1e3,
        mean_ms: mean * 1e3,
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
        beat_error_ms: 1.5,
        snr_db,
        reverb_s: 0.3,
        hum_db: -30.0,
        missing: 0.0,
        seed,
    }
}

#[test]
fn ten_minutes_at_3600_bph() {
    let s = spec(3600.0, 44_100, 20.0, 11);
    let rec = synthesize(&s);
    let (ticks, missed) = detect(&rec.samples, 44_100.0, None);
    let sc = score(&ticks, &rec.ticks);
    eprintln!(
        "3600 bph: rms {:.4} ms (mean {:.4}), matched {}, invented {}, missed {} (reported {missed})",
        sc.rms_ms, sc.mean_ms, sc.matched, sc.invented, sc.missed
    );
    let times: Vec<f64> = ticks.iter().map(|t| t.time).collect();
    let a = analyse_beats(&times, Some(1.0)).unwrap();
    eprintln!("rate {:?} beat error {}", a.rate_s_per_day, a.beat_error_ms);
    assert!(sc.rms_ms < 0.1);
    assert_eq!(sc.invented, 0);
    assert_eq!(sc.missed, 0);
    assert!((a.rate_s_per_day.unwrap() - 12.0).abs() < 0.05);
    assert!((a.beat_error_ms - 1.5).abs() < 0.1);
}

/// Every rate of the issue at 44.1 kHz, each with its own tick shape
/// (seed): tick times within 0.1 ms RMS, rate within 0.05
/// s/day, beat error within 0.1 ms, no invented or missed beats.
#[test]
fn other_rates_and_phone_sampling() {
    for (bph, sample_rate, seed) in [
        (1800.0, 44_100, 21),
        (2880.0, 44_100, 22),
        (5400.0, 44_100, 23),
        (18_000.0, 44_100, 24),
        (28_800.0, 44_100, 25),
    ] {
        let mut s = spec(bph, sample_rate, 20.0, seed);
        s.duration = 300.0;
        let rec = synthesize(&s);
        let (ticks, _) = detect(&rec.samples, f64::from(sample_rate), None);
        let sc = score(&ticks, &rec.ticks);
        let times: Vec<f64> = ticks.iter().map(|t| t.time).collect();
        let nominal = 3600.0 / bph;
        let a = analyse_beats(&times, Some(nominal)).unwrap();
        eprintln!(
            "{bph} bph at {sample_rate} Hz: rms {:.4} ms (mean {:.4}), invented {}, missed {}, rate {:.4}, beat error {:.4}",
            sc.rms_ms, sc.mean_ms, sc.invented, sc.missed, a.rate_s_per_day.unwrap(), a.beat_error_ms
        );
        assert!(sc.rms_ms < 0.1, "{bph} at {sample_rate}");
        assert_eq!((sc.invented, sc.missed), (0, 0), "{bph} at {sample_rate}");
        assert!((a.rate_s_per_day.unwrap() - 12.0).abs() < 0.05, "{bph}");
        assert!((a.beat_error_ms - 1.5).abs() < 0.1, "{bph}");
    }
}

/// Phone sampling (8 kHz): no tick time is wrong; a tick whose first sound
/// is lost under the noise is reported missed, never timed on its drop.
#[test]
fn phone_sampling_times_no_tick_wrongly() {
    for (bph, seed) in [(3600.0, 26), (18_000.0, 27)] {
        let mut s = spec(bph, 8000, 20.0, seed);
        s.duration = 300.0;
        let rec = synthesize(&s);
        let (ticks, reported) = detect(&rec.samples, 8000.0, None);
        let sc = score(&ticks, &rec.ticks);
        let times: Vec<f64> = ticks.iter().map(|t| t.time).collect();
        let a = analyse_beats(&times, Some(3600.0 / bph)).unwrap();
        eprintln!(
            "{bph} bph at 8 kHz: rms {:.4} ms, invented {}, missed {} (reported {reported}) of {}, rate {:.4}, beat error {:.4}",
            sc.rms_ms, sc.invented, sc.missed, rec.ticks.len(), a.rate_s_per_day.unwrap(), a.beat_error_ms
        );
        assert!(sc.rms_ms < 0.1);
        assert_eq!(sc.invented, 0, "{bph}");
        assert!(reported >= sc.missed, "{bph}");
        assert!((a.rate_s_per_day.unwrap() - 12.0).abs() < 0.05, "{bph}");
        assert!((a.beat_error_ms - 1.5).abs() < 0.1, "{bph}");
    }
}
