//! The clock doctor's advice through the real binary: `listen`, `fit
//! beats`, `regulate --bph` and `clock` end in what to do, its amounts
//! checked by hand (the length's law `l (1 + r/86400)²`, the crutch's
//! offset `ω b A / 2` to first order) and its directions as a clockmaker
//! reads them.

use crate::util::{docs_files, f, json, pendulum, refuses, text};
use std::f64::consts::PI;

fn synth(dir: &std::path::Path, args: &[&str]) -> String {
    let path = dir.join("clock.wav");
    let path = path.to_str().unwrap().to_string();
    pendulum()
        .args(["synth", "ticks", &path])
        .args(args)
        .assert()
        .success();
    path
}

/// A seconds clock gaining 12 s/day and 15 ms out of beat, with its
/// length, nut, swing and crutch given.
#[test]
fn a_recording_is_advised_as_by_hand() {
    let dir = tempfile::tempdir().unwrap();
    let wav = synth(
        dir.path(),
        &[
            "--bph",
            "3600",
            "--rate",
            "12",
            "--beat-error",
            "15",
            "--duration",
            "60",
        ],
    );
    let v = json(&[
        "listen",
        &wav,
        "--length",
        "0.994m",
        "--nut-tpi",
        "32",
        "--amplitude",
        "3deg",
        "--crutch",
        "180mm",
    ]);
    let rate = f(&v, "rate_s_per_day");
    let advice = v["advice"].as_array().unwrap();
    let regulate = &advice[0];
    assert_eq!(regulate["code"], "regulate");
    assert_eq!(regulate["bob"], "lower");
    assert_eq!(regulate["nut_turn"], "anticlockwise");
    let shift = 0.994 * ((1.0 + rate / 86_400.0).powi(2) - 1.0);
    assert!(
        (f(regulate, "bob_shift_m") - shift).abs() < 1e-9,
        "{regulate}"
    );
    let turns = shift / (0.0254 / 32.0);
    assert!(
        (f(regulate, "nut_turns") - turns).abs() < 1e-6,
        "{regulate}"
    );

    let beat = &advice[1];
    assert_eq!(beat["code"], "set_in_beat");
    let be = 1e-3 * f(&v, "beat_error_ms");
    let omega = PI / f(&v, "mean_beat_s");
    let offset = omega * be * 3f64.to_radians() / 2.0;
    let crutch = f(beat, "crutch_deg").to_radians();
    assert!(
        (crutch / offset - 1.0).abs() < 2e-3,
        "{crutch} against {offset}"
    );
    assert!((f(beat, "bob_m") - 0.994 * crutch).abs() < 1e-9);
    assert!((f(beat, "crutch_pin_m") - 0.18 * crutch).abs() < 1e-9);
    assert_eq!(beat["amplitude_assumed"], false);

    // The text ends with the same, in words.
    let text = text(&["listen", &wav, "--nut-pitch", "0.7mm"]);
    let tail: Vec<&str> = text.lines().rev().take(3).collect();
    assert_eq!(tail[2], "What to do:", "{text}");
    assert!(tail[1].contains("lower the bob"), "{text}");
    assert!(tail[1].contains("anticlockwise seen from below"), "{text}");
    assert!(tail[1].contains("simple pendulum of this beat"), "{text}");
    assert!(tail[0].contains("towards the side the pendulum swings to in the longer gap"));
    assert!(tail[0].contains("assumed"), "{text}");
}

/// A timer's beat log: the same advice from `fit beats`, and a clock on
/// time within its error is told to leave the nut.
#[test]
fn a_beat_log_is_advised_too() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("beats.csv");
    // A seconds clock losing 30 s/day, its tocks 12 ms late: the
    // intervals 1.012 and 0.988 s, a beat error of 12 ms.
    let beat = 1.0 / (1.0 - 30.0 / 86_400.0);
    let mut text = String::from("time_s\n");
    for i in 0..600 {
        let t = i as f64 * beat + if i % 2 == 0 { 0.0 } else { 0.012 };
        text.push_str(&format!("{t:.6}\n"));
    }
    std::fs::write(&path, text).unwrap();
    let v = json(&[
        "fit",
        "beats",
        path.to_str().unwrap(),
        "--bph",
        "3600",
        "--nut-pitch",
        "1mm",
    ]);
    let a = &v["advice"];
    assert_eq!(a[0]["code"], "regulate", "{a}");
    assert_eq!(a[0]["bob"], "raise");
    assert_eq!(a[0]["nut_turn"], "clockwise");
    assert_eq!(a[0]["length_from_beat"], true);
    let rate = f(&v, "rate_s_per_day");
    let length = 9.80665 * (f(&v, "mean_beat_s") / PI).powi(2);
    let shift = length * (1.0 - (1.0 + rate / 86_400.0).powi(2));
    assert!((f(&a[0], "bob_shift_m") - shift).abs() < 1e-9, "{a}");
    assert!((f(&a[0], "nut_turns") - shift / 1e-3).abs() < 1e-6, "{a}");
    assert_eq!(a[1]["code"], "set_in_beat");
    assert!((f(&a[1], "beat_error_ms") - 12.0).abs() < 1e-3, "{a}");
}

/// `regulate --bph 3600` is the seconds pendulum, 9.80665/π² m long.
#[test]
fn regulate_takes_the_beat() {
    let by_beat = json(&["regulate", "--bph", "3600", "--rate", "-30"]);
    let length = 9.80665 / (PI * PI);
    let by_length = json(&[
        "regulate",
        "--length",
        &format!("{length}m"),
        "--rate",
        "-30",
    ]);
    assert!((f(&by_beat, "shift_m") - f(&by_length, "shift_m")).abs() < 1e-12);
    assert!(f(&by_beat, "shift_m") < 0.0);
    refuses(&["regulate", "--bph", "20000", "--rate", "3"], "--bph");
    refuses(&["regulate", "--bph", "100", "--rate", "3"], "--bph");
}

/// The simulated clock's own offset comes back from its beat error: the
/// advice inverts the harmonic model, the clock integrates its
/// escapement.
#[test]
fn a_simulated_clock_gets_its_offset_back() {
    for offset in [0.05, 0.1, 0.3] {
        let v = json(&[
            "clock",
            "--length",
            "0.994m",
            "--drive",
            "20uJ",
            "--beat-error",
            &format!("{offset}deg"),
        ]);
        let a = &v["advice"][0];
        assert_eq!(a["code"], "set_in_beat", "{v}");
        assert!(
            (f(a, "crutch_deg") / offset - 1.0).abs() < 1e-3,
            "{offset}: {a}"
        );
        let warned = v["warnings"].to_string();
        assert!(
            warned.contains("towards the side the pendulum swings to"),
            "{warned}"
        );
    }
}

/// What the user says of the clock is checked before the recording is
/// read: a refusal names the flag.
#[test]
fn advice_flags_are_refused_by_name() {
    let dir = tempfile::tempdir().unwrap();
    let wav = synth(dir.path(), &["--duration", "20"]);
    refuses(&["listen", &wav, "--nut-tpi", "0"], "--nut-tpi");
    refuses(&["listen", &wav, "--crutch", "-1mm"], "--crutch");
    refuses(&["listen", &wav, "--amplitude", "200deg"], "--amplitude");
    refuses(&["listen", &wav, "--length", "-1m"], "--length");
    // A crutch longer than the pendulum: metres typed for millimetres.
    refuses(
        &["listen", &wav, "--length", "1m", "--crutch", "180"],
        "--crutch",
    );
}

/// The documentation's listening examples: the lines they show (the
/// warnings, findings and advice that end the text) are what the binary
/// prints for the recording the same page says, just before, how to make.
#[test]
fn the_documentation_shows_what_the_binary_says() {
    let docs = docs_files();
    for tag in ["<!-- advice-example:", "<!-- doctor-example:"] {
        let (page, page_text) = docs
            .iter()
            .find(|(_, text)| text.contains(tag))
            .unwrap_or_else(|| panic!("no page of the documentation holds {tag}"));
        let start = page_text.find(tag).expect("the marker");
        let block = &page_text[start..];
        let block = &block[block.find("```text\n").unwrap() + 8..];
        let block = &block[..block.find("```").unwrap()];
        // After the command and the "…" that stands for the figures.
        let shown: Vec<&str> = block.lines().skip_while(|l| *l != "…").skip(1).collect();
        assert!(shown.len() >= 3, "{page}: {tag} {block}");
        let make = page_text[..start]
            .rfind("`pendulum synth ticks clock.wav")
            .map(|i| &page_text[i + 1..])
            .and_then(|s| s.find('`').map(|j| &s[..j]))
            .unwrap_or_else(|| panic!("{page}: no synth ticks command before {tag}"));
        let dir = tempfile::tempdir().unwrap();
        let mut args: Vec<&str> = make.split_whitespace().skip(1).collect();
        let wav = dir.path().join("clock.wav");
        let wav = wav.to_str().unwrap();
        args[2] = wav;
        pendulum().args(&args).assert().success();
        let marker = &page_text[start + tag.len()..];
        let marker = &marker[..marker.find("-->").unwrap()];
        let listen: Vec<&str> = marker
            .split_whitespace()
            .map(|a| if a == "clock.wav" { wav } else { a })
            .collect();
        let text = text(&listen);
        let printed: Vec<&str> = text.lines().skip_while(|l| *l != shown[0]).collect();
        assert_eq!(printed, shown, "{page}: {tag}");
    }
}
