//! The measurement files people have (issue 10), through the real binary:
//! Tracker exports, spreadsheets with semicolons and decimal commas,
//! space-aligned tables, headers with units, headerless files, rounded and
//! absolute times.

use super::util::{f, json, refuses};
use std::path::{Path, PathBuf};

fn examples() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples")
}

fn write(dir: &Path, name: &str, text: &str) -> String {
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path.to_str().unwrap().to_string()
}

/// A 1 m pendulum, 4° from rest, ζ = 0.003, at 30 frames a second for
/// `seconds`: the linear motion, in degrees (no noise: formats only; below
/// 5°, so `--model auto` fits the linear law).
fn swing(seconds: usize) -> Vec<(f64, f64)> {
    let w = (9.80665f64).sqrt();
    (0..seconds * 30)
        .map(|i| {
            let t = i as f64 / 30.0;
            (t, 4.0 * (-0.003 * w * t).exp() * (w * t).cos())
        })
        .collect()
}

#[test]
fn a_tracker_export_is_read_as_it_is() {
    // examples/tracker.txt: title line, tab-separated t x y, CRLF, blank cells.
    let file = examples().join("tracker.txt");
    let file = file.to_str().unwrap();
    let t = json(&["fit", "trajectory", file, "--model", "nonlinear"]);
    assert_eq!(t["format"]["separator"], "tab");
    assert_eq!(t["format"]["skipped_rows"], 4);
    assert_eq!(
        t["format"]["columns_used"],
        serde_json::json!(["t", "x", "y"])
    );
    assert_eq!(t["pivot"]["source"], "default");
    // The generator's truth: 15.5° release, ζ = 5.5e-4 plus drag; ω_n = sqrt(g/1.2).
    let wn = (9.80665f64 / 1.2).sqrt();
    assert!((f(&t["parameters"], "omega_n_rad_s") / wn - 1.0).abs() < 1e-3);
    let phase = f(&t["parameters"], "phase_rad");
    let pi = std::f64::consts::PI;
    assert!((-0.5 * pi..2.0 * pi).contains(&phase), "{phase}");
    // fit decay on the same file: the turning points, a physical law
    // preferred (air drag, no negative coefficient), Q as the trajectory's.
    let d = json(&["fit", "decay", file]);
    assert_eq!(d["omega_source"], "turning_points");
    // A law with drag; the record (20 s of a 15.5° swing) hardly tells
    // viscous damping from dry friction beside the drag, and says so: the
    // generator's law is the preferred one or its runner-up within ΔBIC 2.
    let preferred = d["preferred"].as_str().unwrap();
    assert!(preferred.ends_with("+quadratic"), "{preferred}");
    if preferred != "viscous+quadratic" {
        assert_eq!(d["runner_up"]["model"], "viscous+quadratic");
        assert!(f(&d["runner_up"], "delta_bic") < 2.0, "{}", d["runner_up"]);
    }
    let models = d["models"].as_array().unwrap();
    for m in models {
        for (name, value) in m["parameters"].as_object().unwrap() {
            assert!(value.as_f64().unwrap() >= 0.0, "{}: {name}", m["model"]);
        }
    }
    let best = models
        .iter()
        .find(|m| m["model"] == "viscous+quadratic")
        .unwrap();
    assert!(best["at_bound"].as_array().unwrap().is_empty());
    let weights: f64 = models.iter().map(|m| f(m, "akaike_weight")).sum();
    assert!((weights - 1.0).abs() < 1e-9);
    // The trajectory fit finds the same law, and the generator's viscous
    // rate and drag within 3σ, as the decay fit does.
    assert_eq!(t["damping_law"], "viscous+quadratic");
    for (key, decay_key, truth) in [
        ("zeta", "zeta", 5.5e-4),
        ("quadratic_drag_per_rad", "quadratic_drag_per_rad", 0.025),
    ] {
        let (v, se) = (f(&t["parameters"], key), f(&t["standard_errors"], key));
        assert!((v - truth).abs() < 3.0 * se, "{key}: {v} ± {se}");
        let (w, sw) = (
            f(&best["parameters"], decay_key),
            f(&best["standard_errors"], decay_key),
        );
        assert!(
            (v - w).abs() < 3.0 * se.hypot(sw),
            "{key}: {v} vs decay {w}"
        );
    }
    // The drag the generator put in (b = 0.025 per radian), within 3σ.
    let b = f(&best["parameters"], "quadratic_drag_per_rad");
    let se = f(&best["standard_errors"], "quadratic_drag_per_rad");
    assert!((b - 0.025).abs() < 3.0 * se, "{b} ± {se}");
    // --pivot fit: the circle's radius is the length.
    let c = json(&["fit", "trajectory", file, "--pivot", "fit"]);
    assert!((f(&c, "track_radius") - 1.2).abs() < 0.01);
    assert_eq!(c["length_source"], "track_radius");
    assert!(c["parameters"]["g_m_s2"].is_number());
}

#[test]
fn turning_points_are_written_when_asked() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("turns.csv");
    let file = examples().join("tracker.txt");
    json(&[
        "fit",
        "decay",
        file.to_str().unwrap(),
        "--turning-points",
        out.to_str().unwrap(),
    ]);
    let text = std::fs::read_to_string(&out).unwrap();
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("time_s,amplitude_rad,side"));
    assert!(lines.count() > 100);
}

#[test]
fn semicolons_and_decimal_commas() {
    let file = examples().join("rundown-semicolon.csv");
    let v = json(&[
        "fit",
        "decay",
        file.to_str().unwrap(),
        "--length",
        "0.99362m",
        "--model",
        "viscous",
    ]);
    assert_eq!(v["format"]["separator"], "semicolon");
    assert_eq!(v["format"]["decimal"], "comma");
    assert_eq!(v["points"], 121);
    let q = f(&v["models"][0], "q_factor");
    assert!((q / 10_000.0 - 1.0).abs() < 0.05, "{q}");
    // A bad cell: file, line, column and the separator detected.
    let dir = tempfile::tempdir().unwrap();
    let bad = write(
        dir.path(),
        "bad.csv",
        "Zeit (s);Amplitude (°)\n0;3,0\n60;2,9x\n120;2,8\n",
    );
    let e = refuses(&["fit", "decay", &bad], "line 3");
    for word in ["Amplitude (°)", "2,9x", "semicolon", "bad.csv"] {
        assert!(e.contains(word), "{e} should name {word}");
    }
}

#[test]
fn spaces_units_in_parentheses_and_no_header() {
    let dir = tempfile::tempdir().unwrap();
    let rows = swing(20);
    let spaces: String = rows
        .iter()
        .map(|(t, a)| format!("  {t:>10.5}   {a:>12.6}\n"))
        .collect();
    let aligned = write(
        dir.path(),
        "aligned.txt",
        &format!("     t        angle_deg\n{spaces}"),
    );
    let v = json(&["fit", "trajectory", &aligned]);
    assert_eq!(v["format"]["separator"], "spaces");
    assert_eq!(v["model"], "linear");
    let w = (9.80665f64).sqrt();
    assert!((f(&v["parameters"], "omega_d_rad_s") / w - 1.0).abs() < 1e-4);
    let parens: String = rows
        .iter()
        .map(|(t, a)| format!("{t},{}\n", a.to_radians()))
        .collect();
    let lab = write(
        dir.path(),
        "lab.csv",
        &format!("Time (s),Angle (rad)\n{parens}"),
    );
    assert_eq!(
        json(&["fit", "trajectory", &lab])["format"]["columns_used"],
        serde_json::json!(["Time (s)", "Angle (rad)"])
    );
    let bare: String = rows.iter().map(|(t, a)| format!("{t},{a}\n")).collect();
    let headerless = write(dir.path(), "bare.csv", &bare);
    refuses(&["fit", "trajectory", &headerless], "--columns");
    let v = json(&[
        "fit",
        "trajectory",
        &headerless,
        "--columns",
        "time_s,angle_deg",
    ]);
    assert_eq!(v["points"], 600);
    // An angle column with no unit needs --angle-unit.
    let unitless = write(dir.path(), "theta.csv", &format!("t,theta\n{bare}"));
    refuses(&["fit", "trajectory", &unitless], "--angle-unit");
    let v = json(&["fit", "trajectory", &unitless, "--angle-unit", "deg"]);
    assert!((f(&v["parameters"], "amplitude_rad") - 4f64.to_radians()).abs() < 1e-3);
}

#[test]
fn rounded_times_are_named_and_rebuilt_from_the_frame_rate() {
    let dir = tempfile::tempdir().unwrap();
    // Times at 30 frames/s exported to 4 significant figures: 100.0, 100.0, 100.1...
    let rows = swing(120);
    let text: String = rows
        .iter()
        .map(|(t, a)| format!("{},{a}\n", format_4(*t)))
        .collect();
    let file = write(
        dir.path(),
        "rounded.csv",
        &format!("time_s,angle_deg\n{text}"),
    );
    // Rebuilt on their frame grid (issue 44; they were refused, naming
    // --frame-rate), and said.
    let w = (9.80665f64).sqrt();
    let v = json(&["fit", "trajectory", &file]);
    let rebuilt = &v["time_rebuilt"];
    assert!(
        (f(rebuilt, "frame_interval_s") * 30.0 - 1.0).abs() < 1e-7,
        "{v}"
    );
    assert!((f(&v["parameters"], "omega_d_rad_s") / w - 1.0).abs() < 1e-4);
    // --frame-rate makes them from the rows, as before.
    let v = json(&["fit", "trajectory", &file, "--frame-rate", "30"]);
    assert_eq!(v["format"]["frame_rate"], 30.0);
    assert!(v["time_rebuilt"].is_null());
    assert!((f(&v["parameters"], "omega_d_rad_s") / w - 1.0).abs() < 1e-4);
}

/// `x` to 4 significant figures, as a spreadsheet exports it.
fn format_4(x: f64) -> String {
    if x == 0.0 {
        return "0".into();
    }
    let digits = 3 - x.abs().log10().floor() as i32;
    let scale = 10f64.powi(digits);
    format!("{}", (x * scale).round() / scale)
}

#[test]
fn absolute_times_are_measured_from_the_first_row() {
    // A data logger's Unix times: both viscous laws are fitted, none dropped.
    let dir = tempfile::tempdir().unwrap();
    let mut text = String::from("time_s,amplitude_deg\n");
    for i in 0..100 {
        let t = 1.7e9 + 20.0 * f64::from(i);
        let a = 3.0 * (-3e-4 * 20.0 * f64::from(i)).exp();
        text.push_str(&format!("{t},{a}\n"));
    }
    let file = write(dir.path(), "logger.csv", &text);
    let v = json(&["fit", "decay", &file, "--length", "0.99362m"]);
    assert_eq!(f(&v["format"], "time_origin_s"), 1.7e9);
    let models = v["models"].as_array().unwrap();
    assert_eq!(models.len(), 7);
    let viscous = &models[0];
    assert!(viscous["failed"].is_null(), "{viscous}");
    assert!((f(&viscous["parameters"], "decay_rate_per_s") / 3e-4 - 1.0).abs() < 1e-6);
    assert!((f(&viscous["parameters"], "amplitude0_rad") - 3f64.to_radians()).abs() < 1e-9);
}

/// A logger that samples at a fixed rate writes no time column: refused
/// with the flag that reads it, then read with `--sample-rate` (issue 23).
#[test]
fn a_fixed_rate_logger_without_times_is_read_with_its_rate() {
    let dir = tempfile::tempdir().unwrap();
    let w = (9.80665f64 / 0.6).sqrt();
    let mut text = String::from("angle_deg\n");
    for i in 0..600 {
        let t = f64::from(i) / 50.0;
        text.push_str(&format!("{}\n", 3.0 * (-0.02 * t).exp() * (w * t).cos()));
    }
    let file = write(dir.path(), "logger.csv", &text);
    let message = refuses(&["fit", "trajectory", &file], "--sample-rate");
    assert!(message.contains("no time column"), "{message}");
    let v = json(&[
        "fit",
        "trajectory",
        &file,
        "--sample-rate",
        "50",
        "--length",
        "0.6m",
    ]);
    assert_eq!(v["points"], 600);
    let g = f(&v["parameters"], "g_m_s2");
    assert!((g / 9.80665 - 1.0).abs() < 1e-3, "{g}");
    // The same rate under the video name.
    let v = json(&["fit", "trajectory", &file, "--frame-rate", "50"]);
    assert!(
        (f(&v["parameters"], "omega_d_rad_s") / w - 1.0).abs() < 2e-3,
        "{v}"
    );
    // fit decay reads the same file with the same flag (it refused it).
    let d = json(&["fit", "decay", &file, "--sample-rate", "50"]);
    let viscous = &d["models"][0];
    let rate = f(&viscous["parameters"], "decay_rate_per_s");
    assert!((rate / 0.02 - 1.0).abs() < 0.02, "{rate}");
}

/// Times out of order are quoted as the file writes them, not less the
/// first time (a real extrema list, maxima then minima, read as it is).
#[test]
fn times_out_of_order_are_quoted_as_written() {
    let dir = tempfile::tempdir().unwrap();
    let text = "time_s,amplitude_rad\n1.5,0.30\n3.5,0.28\n5.5,0.26\n0.25,0.29\n2.25,0.27\n";
    let file = write(dir.path(), "extrema.csv", text);
    let message = refuses(&["fit", "decay", &file], "line 5");
    assert!(
        message.contains("0.25 is not after the previous 5.5"),
        "{message}"
    );
}

/// Nothing the reader leaves out goes unsaid: rows skipped for a blank
/// cell are a warning naming how many and where (the fit commands also
/// count them in their summary), and a second column of a kind, not read,
/// is named; both survive --quiet. A file without them warns of nothing.
#[test]
fn what_the_reader_leaves_out_is_a_warning() {
    let dir = tempfile::tempdir().unwrap();
    let mut text = String::from("time_s,frequency,frequency\n");
    for i in 0..64 {
        if i == 5 {
            text.push_str("5,\n");
        } else {
            text.push_str(&format!("{i},{},{}\n", 1e-9 * ((i * 7) % 5) as f64, i));
        }
    }
    let path = write(dir.path(), "gappy.csv", &text);
    let out = assert_cmd::Command::cargo_bin("pendulum")
        .unwrap()
        .args(["--quiet", "stability", &path])
        .assert()
        .success()
        .get_output()
        .clone();
    let stderr = String::from_utf8(out.stderr).unwrap();
    assert!(
        stderr.contains("1 row with a blank cell in a column used skipped (line 7)"),
        "{stderr}"
    );
    assert!(
        stderr.contains("column 2 ('frequency') is read as the rate; column 3 ('frequency')"),
        "{stderr}"
    );
    let mut plain = String::from("time_s,frequency\n");
    for i in 0..64 {
        plain.push_str(&format!("{i},{}\n", 1e-9 * ((i * 7) % 5) as f64));
    }
    let clean = write(dir.path(), "clean.csv", &plain);
    let out = assert_cmd::Command::cargo_bin("pendulum")
        .unwrap()
        .args(["stability", &clean])
        .assert()
        .success()
        .get_output()
        .clone();
    assert!(!String::from_utf8(out.stderr).unwrap().contains("warning"));
}

/// Real Tracker projects (tests/data/real, MIT, from a university lab):
/// the swing of a 39-inch string with its pivot fitted gives g near
/// Toronto's (9.805 m/s², within two standard errors), the arc's radius
/// near the string's length plus the bob's (0.99 m to about 1.02 m); the
/// 80° run-down's Q is a free pendulum's in air (a few hundred), by a
/// law that depends on the amplitude.
#[test]
fn real_tracker_projects_give_g_and_q() {
    let real = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/real");
    let swing = real.join("pendulum_length2.trk");
    let t = json(&[
        "fit",
        "trajectory",
        swing.to_str().unwrap(),
        "--pivot",
        "fit",
    ]);
    let g = f(&t["parameters"], "g_m_s2");
    let se = f(&t["standard_errors"], "g_m_s2");
    assert!((g - 9.805).abs() < 2.0 * se, "g {g} ± {se}");
    let radius = f(&t, "track_radius");
    assert!((0.99..1.03).contains(&radius), "{radius}");
    assert_eq!(t["format"]["rows"], 152);
    let run_down = real.join("pendulum_fullPeriod.trk");
    let d = json(&["fit", "decay", run_down.to_str().unwrap()]);
    assert_eq!(d["format"]["rows"], 4502);
    let preferred = d["models"]
        .as_array()
        .unwrap()
        .iter()
        .find(|m| m["model"] == d["preferred"])
        .unwrap();
    let q = f(preferred, "q_factor");
    assert!((200.0..600.0).contains(&q), "{q}");
    // An 80° start: the amplitude-dependent laws, not viscous alone.
    assert_ne!(d["preferred"], "viscous");
}

/// A TAPR TICC counter's log, as a serial terminal captures it (its
/// banner, then a timestamp and a channel a line): `fit beats` reads the
/// first channel logged, a seconds pendulum made to gain 2.0 s/day with
/// 1.5 ms of beat error (tools/examples), and `--gate chB` the GPS
/// receiver's pulse per second beside it, which keeps time. A log of
/// time intervals (`TI(A->B)`) is phase for `stability`: an offset of
/// ±1 ns alternating has ADEV and TOTDEV 2√2 ns/τ₀ and MTIE 2 ns at τ₀.
#[test]
fn a_ticc_log_is_read_by_its_lines() {
    let ticc = examples().join("ticc.txt");
    let ticc = ticc.to_str().unwrap();
    let pendulum = json(&["fit", "beats", ticc]);
    assert_eq!(pendulum["format"]["reader"], "TICC log");
    assert_eq!(pendulum["format"]["gate_labels"][0], "chA");
    let rate = f(&pendulum, "rate_s_per_day");
    assert!(
        (rate - 2.0).abs() < 3.0 * f(&pendulum, "rate_se_s_per_day"),
        "{rate}"
    );
    assert!((f(&pendulum, "beat_error_ms") - 1.5).abs() < 0.01);
    let pps = json(&["fit", "beats", ticc, "--gate", "chB"]);
    assert!(f(&pps, "rate_s_per_day").abs() < 1e-4, "{pps}");

    let dir = tempfile::tempdir().unwrap();
    let mut log = String::from("# TAPR TICC Timestamping Counter\n");
    for k in 0..64 {
        let x = if k % 2 == 0 { 1e-9 } else { -1e-9 };
        log.push_str(&format!("{x:.12} TI(A->B)\n"));
    }
    let path = write(dir.path(), "ti.log", &log);
    let s = json(&["stability", &path, "--tau0", "1s"]);
    assert_eq!(s["format"]["reader"], "TICC log");
    let first = &s["stability"][0];
    assert!(
        (f(first, "adev") - 8f64.sqrt() * 1e-9).abs() < 1e-21,
        "{first}"
    );
    assert!(
        (f(first, "totdev") - 8f64.sqrt() * 1e-9).abs() < 1e-21,
        "{first}"
    );
    assert!((f(first, "mtie_s") - 2e-9).abs() < 1e-21, "{first}");
}
