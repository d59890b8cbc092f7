//! Listening live against listening to the same recording as a file: the
//! same ticks, the same totals, the same windows, whatever the blocks the
//! samples come in.

use pendulum_theory::fitting::beat_log::Nominal;
use pendulum_theory::listening::analysis::{listen_to_samples, ListenInput, Listening};
use pendulum_theory::listening::live::{LiveListener, LEARN_S};
use pendulum_theory::listening::synth::{synthesize, TickRecording};
use pendulum_theory::listening::windows::Window;

/// The samples pushed in blocks of `sizes` in turn; the windows printed
/// while it went, and the end.
fn live(
    samples: &[f32],
    rate: u32,
    input: &ListenInput,
    sizes: &[usize],
) -> (Vec<Window>, Listening) {
    let mut listener = LiveListener::new(rate, input).expect("input");
    let mut windows = Vec::new();
    let mut at = 0;
    for size in sizes.iter().cycle() {
        if at >= samples.len() {
            break;
        }
        let end = (at + size).min(samples.len());
        windows.extend(listener.push(&samples[at..end]).expect("push"));
        at = end;
    }
    (windows, listener.finish().expect("finish"))
}

fn recording(bph: f64, sample_rate: u32, beat_error_ms: f64, rate_change: f64) -> TickRecording {
    TickRecording {
        sample_rate,
        duration: 900.0,
        beats_per_hour: bph,
        rate_s_per_day: -7.0,
        rate_change_s_per_day_per_hour: rate_change,
        beat_error_ms,
        snr_db: 25.0,
        reverb_s: 0.3,
        hum_db: -30.0,
        missing: 0.05,
        seed: 11,
        ..TickRecording::DEFAULT
    }
}

/// The totals of `a` and `b` agree: the same ticks kept (to a few), the
/// rate within a tenth of its standard error, the beat error within a
/// tenth of its.
fn same(label: &str, file: &Listening, live: &Listening) {
    let (a, b) = (&file.beats, &live.beats);
    let ticks = file.ticks.len() as i64 - live.ticks.len() as i64;
    assert!(
        ticks.abs() <= 2,
        "{label}: {} ticks from the file, {} live",
        file.ticks.len(),
        live.ticks.len()
    );
    let (ra, rb) = (a.rate_s_per_day.unwrap(), b.rate_s_per_day.unwrap());
    let rate_se = a.rate_se_s_per_day.unwrap();
    let be_se = a.beat_error_se_ms.unwrap().max(1e-3);
    assert!(
        (ra - rb).abs() <= 0.1 * rate_se,
        "{label}: rate {ra} from the file, {rb} live (se {})",
        rate_se
    );
    assert!(
        (a.beat_error_ms - b.beat_error_ms).abs() <= 0.1 * be_se,
        "{label}: beat error {} from the file, {} live",
        a.beat_error_ms,
        b.beat_error_ms
    );
    assert_eq!(file.timed_on, live.timed_on, "{label}");
    assert_eq!(file.duration_s, live.duration_s, "{label}");
}

#[test]
fn live_gives_the_files_totals_and_windows() {
    for (bph, sr, be, change) in [
        (3600.0, 8000, 1.5, 0.0),
        (18_000.0, 8000, 1.5, 0.0),
        (5400.0, 8000, 0.5, 20.0),
    ] {
        let spec = recording(bph, sr, be, change);
        let rec = synthesize(&spec);
        let input = ListenInput {
            nominal: Some(Nominal::BeatsPerHour(bph)),
            every: Some(60.0),
            ..ListenInput::default()
        };
        let file = listen_to_samples(&rec.samples, f64::from(sr), &input).expect("file");
        for sizes in [&[4096][..], &[1, 333, 8000, 17][..]] {
            let label = format!("{bph} bph at {sr} Hz, blocks {sizes:?}");
            let (printed, end) = live(&rec.samples, sr, &input, sizes);
            same(&label, &file, &end);
            // The windows printed as they completed (all but the last
            // minute or two, which the end gives) are the end's.
            assert!(
                printed.len() + 3 >= end.windows.len() && printed.len() <= end.windows.len(),
                "{label}: {} printed of {}",
                printed.len(),
                end.windows.len()
            );
            for (p, w) in printed.iter().zip(&end.windows) {
                let r = |x: &Window| x.rate_s_per_day.unwrap();
                assert!(
                    (r(p) - r(w)).abs() <= 1e-9,
                    "{label}: window {} printed {p:?}, at the end {w:?}",
                    p.start_s
                );
            }
        }
        eprintln!("{bph}: file {:?} live ok", file.beats.rate_s_per_day);
    }
}

/// A recording shorter than what is learnt is the file's.
#[test]
fn a_short_recording_is_the_files() {
    let spec = TickRecording {
        duration: 0.5 * LEARN_S,
        ..recording(3600.0, 8000, 1.0, 0.0)
    };
    let rec = synthesize(&spec);
    let input = ListenInput::default();
    let file = listen_to_samples(&rec.samples, 8000.0, &input).expect("file");
    let (_, end) = live(&rec.samples, 8000, &input, &[1000]);
    assert_eq!(file, end);
}

/// Live, the first reading comes within seconds and each window within a
/// few seconds of its end, counted in the sound pushed (the time the
/// listener waits for, whatever the machine's speed; `bench/live.py`
/// measures the same at the sound card's pace): a provisional reading
/// after 8 s of a watch and by 32 s of a seconds clock (issue 45: at the
/// first window's end, 5 min in); each window ending after the first
/// [`LEARN_S`] and the first 128 ticks of each side by 5 s after its end
/// (it was 85 beats after: 74-86 s for a seconds clock, 10.6 s for a
/// watch; those ending sooner come when both are there).
#[test]
fn readings_come_within_seconds() {
    // (bph, window, first reading by, windows ending after this on time,
    // the recording: the refiner's median tick and tock are made once 128
    // ticks of each side are heard, 4 min 16 s of a seconds clock.)
    for (bph, every, first_by, settled, duration) in [
        (28_800.0, 10.0, 10.0, LEARN_S, 60.0),
        (3600.0, 60.0, 40.0, 300.0, 480.0),
        (7200.0, 30.0, 40.0, 150.0, 270.0),
    ] {
        let spec = TickRecording {
            duration,
            beats_per_hour: bph,
            rate_s_per_day: 5.0,
            beat_error_ms: 0.6,
            seed: 45,
            ..TickRecording::DEFAULT
        };
        let rec = synthesize(&spec);
        let rate = f64::from(spec.sample_rate);
        let input = ListenInput {
            every: Some(every),
            ..ListenInput::default()
        };
        let mut listener = LiveListener::new(spec.sample_rate, &input).expect("input");
        let block = (0.1 * rate) as usize;
        let (mut first, mut late) = (None, Vec::new());
        for (i, chunk) in rec.samples.chunks(block).enumerate() {
            let heard = ((i * block + chunk.len()) as f64) / rate;
            for w in listener.push(chunk).expect("push") {
                late.push((w.end_s, heard - w.end_s));
            }
            if let Some(p) = listener.take_provisional() {
                assert!(first.is_none(), "{bph}: a second provisional reading");
                assert!(
                    (p.beats_per_hour / bph - 1.0).abs() < 1e-3,
                    "{bph}: provisional {p:?}"
                );
                let r = p.rate_s_per_day.expect("a rate");
                let se = p.rate_se_s_per_day.expect("its error");
                assert!((r - 5.0).abs() < 4.0 * se + 0.5, "{bph}: provisional {p:?}");
                first = Some(heard);
            }
        }
        let first = first.expect("a provisional reading");
        assert!(first <= first_by, "{bph}: first reading after {first} s");
        let whole = (spec.duration / every).floor() as usize;
        assert!(late.len() + 1 >= whole, "{bph}: {late:?}");
        assert!(
            late.iter().any(|(end, _)| *end >= settled),
            "{bph}: {late:?}"
        );
        for (end, after) in late.iter().filter(|(end, _)| *end >= settled) {
            assert!(
                *after <= 5.0,
                "{bph}: window ending at {end} s printed {after} s after"
            );
        }
        eprintln!("{bph}: first after {first} s; windows after {late:?}");
    }
}
