//! `pendulum synth ticks` and `pendulum listen` through the binary: a
//! recording with known truth is heard back.

use super::util::{f, json, pendulum, refuses};

fn read_times(path: &std::path::Path) -> Vec<f64> {
    let mut reader = csv::Reader::from_path(path).unwrap();
    reader
        .records()
        .map(|r| r.unwrap()[0].parse::<f64>().unwrap())
        .collect()
}

#[test]
fn ten_minutes_at_3600_bph_are_heard_back() {
    let dir = tempfile::tempdir().unwrap();
    let wav = dir.path().join("clock.wav");
    let truth = dir.path().join("truth.csv");
    let ticks = dir.path().join("ticks.csv");
    pendulum()
        .args([
            "synth",
            "ticks",
            wav.to_str().unwrap(),
            "--bph",
            "3600",
            "--rate",
            "12",
        ])
        .args([
            "--beat-error",
            "1.5",
            "--duration",
            "10min",
            "--snr-db",
            "20",
        ])
        .args([
            "--reverb",
            "0.3s",
            "--seed",
            "7",
            "--truth",
            truth.to_str().unwrap(),
        ])
        .assert()
        .success();
    let v = json(&[
        "listen",
        wav.to_str().unwrap(),
        "--ticks",
        ticks.to_str().unwrap(),
    ]);
    assert_eq!(v["sample_rate_hz"], 44_100);
    assert!((f(&v, "rate_s_per_day") - 12.0).abs() < 0.05, "{v}");
    assert!((f(&v, "beat_error_ms") - 1.5).abs() < 0.1, "{v}");
    assert_eq!(v["missed"], 0);
    assert_eq!(v["extra"], 0);
    let found = read_times(&ticks);
    let truth = read_times(&truth);
    assert_eq!(found.len(), truth.len());
    let rms = (found
        .iter()
        .zip(&truth)
        .map(|(a, b)| (a - b).powi(2))
        .sum::<f64>()
        / truth.len() as f64)
        .sqrt();
    assert!(rms < 1e-4, "rms {rms} s");
    // The ticks file is a beat log `fit beats` reads.
    let b = json(&["fit", "beats", ticks.to_str().unwrap(), "--bph", "3600"]);
    assert!((f(&b, "rate_s_per_day") - 12.0).abs() < 0.05);
}

#[test]
fn what_is_not_a_clock_recording_is_refused_in_one_line() {
    let dir = tempfile::tempdir().unwrap();
    let text = dir.path().join("notes.wav");
    std::fs::write(&text, "not audio at all").unwrap();
    refuses(&["listen", text.to_str().unwrap()], "notes.wav");
    let short = dir.path().join("short.wav");
    pendulum()
        .args([
            "synth",
            "ticks",
            short.to_str().unwrap(),
            "--duration",
            "3s",
        ])
        .assert()
        .success();
    refuses(&["listen", short.to_str().unwrap()], "short.wav");
    let noise = dir.path().join("noise.wav");
    // Ticks 40 dB under the noise: nothing regular to hear.
    pendulum()
        .args([
            "synth",
            "ticks",
            noise.to_str().unwrap(),
            "--duration",
            "30s",
        ])
        .args(["--snr-db", "-40"])
        .assert()
        .success();
    refuses(&["listen", noise.to_str().unwrap()], "noise.wav");
    let missing = dir.path().join("nowhere.wav");
    refuses(&["listen", missing.to_str().unwrap()], "nowhere.wav");
    refuses(
        &["synth", "ticks", short.to_str().unwrap(), "--bph", "100"],
        "--bph",
    );
}

#[test]
fn stereo_takes_the_louder_channel_unless_told() {
    let dir = tempfile::tempdir().unwrap();
    let mono = dir.path().join("mono.wav");
    pendulum()
        .args([
            "synth",
            "ticks",
            mono.to_str().unwrap(),
            "--bph",
            "5400",
            "--rate",
            "-8",
        ])
        .args(["--duration", "2min", "--seed", "9"])
        .assert()
        .success();
    // Left: the clock 26 dB down; right: the clock.
    let mut reader = hound::WavReader::open(&mono).unwrap();
    let spec = reader.spec();
    let samples: Vec<i16> = reader.samples::<i16>().map(|s| s.unwrap()).collect();
    let stereo = dir.path().join("stereo.wav");
    let mut writer = hound::WavWriter::create(
        &stereo,
        hound::WavSpec {
            channels: 2,
            ..spec
        },
    )
    .unwrap();
    for &s in &samples {
        writer.write_sample(s / 20).unwrap();
        writer.write_sample(s).unwrap();
    }
    writer.finalize().unwrap();
    let v = json(&["listen", stereo.to_str().unwrap()]);
    assert_eq!(v["channel"], 2);
    assert!((f(&v, "rate_s_per_day") + 8.0).abs() < 0.05, "{v}");
    let left = json(&["listen", stereo.to_str().unwrap(), "--channel", "1"]);
    assert_eq!(left["channel"], 1);
    refuses(
        &["listen", stereo.to_str().unwrap(), "--channel", "3"],
        "--channel",
    );
}
