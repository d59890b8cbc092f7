//! `pendulum fit decay|trajectory|beats`.

use crate::util::{f, json, refuses};
use pendulum_theory::fitting::decay::DecayModel;
use std::path::{Path, PathBuf};

fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

/// A run-down made by the library's own combined law, noiseless but for a
/// deterministic ±1e-4 rad wobble, with a comment and an empty line.
fn decay_file(dir: &Path) -> PathBuf {
    let law = DecayModel::ViscousCoulomb;
    let mut text = String::from("# a seconds pendulum running down\ntime_s,amplitude_deg\n");
    for i in 0..100 {
        let t = 20.0 * f64::from(i);
        let wobble = 1e-4 * (f64::from(i) * 2.3).sin();
        let a = law.amplitude(t, &[0.05, 3e-4, 8e-6]) + wobble;
        text.push_str(&format!("{t},{}\n", a.to_degrees()));
        if i == 40 {
            text.push('\n');
        }
    }
    write(dir, "decay.csv", &text)
}

#[test]
fn decay_prefers_the_generating_model_and_reports_physics() {
    let dir = tempfile::tempdir().unwrap();
    let path = decay_file(dir.path());
    let v = json(&[
        "fit",
        "decay",
        path.to_str().unwrap(),
        "--length",
        "0.99362m",
        "--mass",
        "5kg",
    ]);
    assert_eq!(v["points"], 100);
    assert_eq!(v["preferred"], "viscous+coulomb");
    let models = v["models"].as_array().unwrap();
    assert_eq!(models.len(), DecayModel::ALL.len());
    let names: Vec<&str> = models
        .iter()
        .map(|m| m["model"].as_str().unwrap())
        .collect();
    assert_eq!(
        names,
        [
            "viscous",
            "coulomb",
            "quadratic",
            "viscous+coulomb",
            "viscous+quadratic",
            "coulomb+quadratic",
            "full"
        ]
    );
    let best = &models[3];
    for key in ["zeta", "friction_angle_rad", "amplitude0_rad"] {
        assert!(best["parameters"][key].is_number(), "{key}");
        assert!(best["standard_errors"][key].is_number(), "{key}");
    }
    assert!(models[2]["parameters"]["quadratic_drag"].is_number());
    for m in models {
        for key in ["residual_rms", "aic", "bic"] {
            assert!(m[key].is_number(), "{key}");
        }
    }
    assert!(best["q_factor"].is_number());
    assert!(models[1]["q_factor"].is_null(), "no Q for dry friction");
    assert!(best["energy_loss_per_period_j"].is_number() && best["power_w"].is_number());
    // λ = 3e-4 /s on ω = 2π/T: ζ = λ/ω.
    let zeta = f(&best["parameters"], "zeta");
    assert!((zeta / (3e-4 / 3.1413) - 1.0).abs() < 0.02, "{zeta}");
}

#[test]
fn decay_by_swing_count_needs_the_length() {
    let dir = tempfile::tempdir().unwrap();
    let mut text = String::from("swing,amplitude_rad\n");
    for i in 0..50 {
        text.push_str(&format!(
            "{},{}\n",
            10 * i,
            0.05 * (-0.002 * f64::from(10 * i)).exp()
        ));
    }
    let path = write(dir.path(), "swings.csv", &text);
    let p = path.to_str().unwrap();
    refuses(&["fit", "decay", p], "--length");
    let v = json(&[
        "fit", "decay", p, "--length", "0.99362", "--model", "viscous",
    ]);
    assert_eq!(v["models"].as_array().unwrap().len(), 1);
    // 0.002 per half swing of about a second: λ ≈ 0.002 /s.
    let lambda = f(&v["models"][0]["parameters"], "decay_rate_per_s");
    assert!((lambda / 0.002 - 1.0).abs() < 0.01, "{lambda}");
}

#[test]
fn trajectory_gives_g() {
    let dir = tempfile::tempdir().unwrap();
    let pendulum = pendulum_theory::Pendulum::with_standard_gravity(0.5).unwrap();
    let damped = pendulum_theory::damped::DampedPendulum::new(
        pendulum,
        pendulum_theory::damping::Damping::from_zeta(0.005).unwrap(),
    );
    let mut text = String::from("time_s,angle_deg\n");
    for i in 0..800 {
        let t = 0.01 * f64::from(i);
        let wobble = 1e-3 * (f64::from(i) * 1.7).sin();
        let theta = damped.state_at(0.02, 0.0, t).angle + 0.01 + wobble;
        text.push_str(&format!("{t},{}\n", theta.to_degrees()));
    }
    let path = write(dir.path(), "video.csv", &text);
    let residuals = dir.path().join("res.csv");
    let v = json(&[
        "fit",
        "trajectory",
        path.to_str().unwrap(),
        "--length",
        "0.5m",
        "--residuals",
        residuals.to_str().unwrap(),
    ]);
    let p = &v["parameters"];
    for key in [
        "amplitude_rad",
        "zeta",
        "offset_rad",
        "g_m_s2",
        "omega_d_rad_s",
        "phase_rad",
    ] {
        assert!(
            p[key].is_number() && v["standard_errors"][key].is_number(),
            "{key}"
        );
    }
    // A 0.02 rad swing: the amplitude correction is 2.5e-5, far below the noise.
    let g = f(p, "g_m_s2");
    assert!((g / 9.80665 - 1.0).abs() < 1e-3, "{g}");
    assert!((f(p, "offset_rad") - 0.01).abs() < 1e-3);
    assert_eq!(
        std::fs::read_to_string(&residuals).unwrap().lines().count(),
        801
    );
}

#[test]
fn beats_like_a_timegrapher() {
    let dir = tempfile::tempdir().unwrap();
    let mut text = String::from("time_s\n");
    let beat = 0.2 / (1.0 + 8.0 / 86_400.0); // 18,000 beats/hour, 8 s/day fast
    for i in 0..3000 {
        if i == 500 {
            continue; // a missed beat
        }
        let tock = if i % 2 == 1 { 0.0004 } else { 0.0 };
        text.push_str(&format!("{}\n", f64::from(i) * beat + tock));
    }
    let path = write(dir.path(), "beats.csv", &text);
    let v = json(&["fit", "beats", path.to_str().unwrap()]);
    for key in [
        "mean_beat_s",
        "beats_per_hour",
        "rate_s_per_day",
        "beat_error_ms",
        "jitter_ms",
    ] {
        assert!(v[key].is_number(), "{key}");
    }
    assert_eq!(v["beats"], 3000);
    assert_eq!(v["repaired"]["missed"], 1);
    assert!((f(&v, "rate_s_per_day") - 8.0).abs() < 0.01, "{v}");
    // Tocks 0.4 ms late: intervals of beat ± 0.4 ms, half their difference 0.4 ms.
    assert!((f(&v, "beat_error_ms") - 0.4).abs() < 0.01);
    assert!(v["allan_deviation"].as_array().unwrap().len() >= 5);
    let with_bph = json(&["fit", "beats", path.to_str().unwrap(), "--bph", "18000"]);
    assert_eq!(with_bph["rate_s_per_day"], v["rate_s_per_day"]);
}

#[test]
fn beats_of_a_gate_off_centre() {
    // Issue 23: a photogate off the bob's centre, passes alternating
    // 0.70/0.48 s and drifting to 0.97/0.20 s as the swing decays (a
    // 1.18 s period). Every pass is kept, the rate is the period's, and
    // the drift is reported.
    let dir = tempfile::tempdir().unwrap();
    let period: f64 = 1.18;
    let omega = std::f64::consts::TAU / period;
    let gate = 0.2;
    let (a0, a1) = (gate / (0.24 * omega).cos(), gate / (0.10 * omega).cos());
    let crests = 300;
    let mut text = String::from("time_s\n");
    for k in 1..=crests {
        let crest = f64::from(k) * period;
        let a = a0 * (a1 / a0).powf(f64::from(k) / f64::from(crests));
        let half = (gate / a).acos() / omega;
        text.push_str(&format!("{}\n{}\n", crest - half, crest + half));
    }
    let path = write(dir.path(), "gate.csv", &text);
    let v = json(&["fit", "beats", path.to_str().unwrap(), "--period", "1.18s"]);
    assert_eq!(v["beats"], 600, "{v}");
    assert_eq!(v["repaired"]["missed"], 0, "{v}");
    assert_eq!(v["repaired"]["doubled"], 0, "{v}");
    assert!(f(&v, "rate_s_per_day").abs() < 0.5, "{v}");
    assert!((f(&v, "beat_error_start_ms") - 110.0).abs() < 10.0, "{v}");
    assert!(f(&v, "beat_error_end_ms") > 350.0, "{v}");
    // (The drift also scatters each side's intervals: the rate and the
    // beat error are said to be uncertain too.)
    let codes = v["warning_codes"].as_array().unwrap();
    assert!(codes.iter().any(|c| c == "sides_drift"), "{v}");
    // A steady clock says nothing of the kind.
    let steady: String = std::iter::once("time_s\n".to_string())
        .chain(
            (0..2000).map(|i| format!("{}\n", f64::from(i) + if i % 2 == 1 { 0.003 } else { 0.0 })),
        )
        .collect();
    let path = write(dir.path(), "steady.csv", &steady);
    let v = json(&["fit", "beats", path.to_str().unwrap()]);
    assert_eq!(v["warning_codes"].as_array().unwrap().len(), 0, "{v}");
    assert!((f(&v, "beat_error_end_ms") - 3.0).abs() < 1e-6, "{v}");
}

#[test]
fn bad_files_name_the_file_the_line_and_the_column() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let bad = |name: &str, text: &str, what: &[&str]| {
        let path = write(d, name, text);
        let m = refuses(&["fit", "decay", path.to_str().unwrap()], name);
        for w in what {
            assert!(m.contains(w), "{m} should mention {w}");
        }
    };
    bad(
        "missing.csv",
        "time_s,foo\n0,1\n1,0.9\n2,0.8\n",
        &["no amplitude column", "time_s, foo", "comma-separated"],
    );
    // An amplitude column without a unit needs --angle-unit.
    bad(
        "unitless.csv",
        "time_s,amp\n0,1\n1,0.9\n2,0.8\n",
        &["amp", "--angle-unit"],
    );
    bad(
        "text.csv",
        "time_s,amplitude_deg\n0,3\n1,abc\n2,2.8\n",
        &["line 3", "amplitude_deg", "abc"],
    );
    bad(
        "unsorted.csv",
        "time_s,amplitude_deg\n0,3\n2,2.9\n1,2.8\n3,2.7\n",
        &["line 4", "time_s", "sort"],
    );
    bad(
        "few.csv",
        "time_s,amplitude_deg\n0,3\n1,2.9\n",
        &["2 points"],
    );
    bad(
        "negative.csv",
        "time_s,amplitude_deg\n0,3\n1,-2.9\n2,2.8\n3,2.7\n",
        &["line 3", "amplitude_deg", "positive"],
    );
    // A short row is a row with blank cells: skipped and counted.
    let ragged = write(
        d,
        "ragged.csv",
        "time_s,amplitude_deg\n0,3\n1\n2,2.8\n3,2.7\n4,2.6\n",
    );
    let v = json(&[
        "fit",
        "decay",
        ragged.to_str().unwrap(),
        "--model",
        "viscous",
    ]);
    assert_eq!(v["format"]["skipped_rows"], 1);
    assert_eq!(v["points"], 4);
    let missing = d.join("nowhere.csv");
    refuses(&["fit", "decay", missing.to_str().unwrap()], "nowhere.csv");
    let beats = write(d, "beats.csv", "time_s\n0\n1\n");
    refuses(&["fit", "beats", beats.to_str().unwrap()], "beats.csv");
    let video = write(d, "video.csv", "time_s,angle_deg\n0,1\n0.01,x\n");
    refuses(&["fit", "trajectory", video.to_str().unwrap()], "line 3");
}

/// The README's example files give what the README says they hold.
#[test]
fn the_example_files_fit_as_documented() {
    let examples = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    let file = |name: &str| examples.join(name).to_str().unwrap().to_string();
    let decay = json(&["fit", "decay", &file("rundown.csv"), "--length", "0.99362m"]);
    assert_eq!(decay["preferred"], "viscous+coulomb");
    let best = &decay["models"][3]["parameters"];
    assert!((f(best, "friction_angle_rad") / 1e-6 - 1.0).abs() < 0.05);
    assert!((decay["models"][3]["q_factor"].as_f64().unwrap() / 10_000.0 - 1.0).abs() < 0.02);
    let video = json(&[
        "fit",
        "trajectory",
        &file("video.csv"),
        "--length",
        "0.5m",
        "--model",
        "nonlinear",
    ]);
    assert!((f(&video["parameters"], "g_m_s2") / 9.80665 - 1.0).abs() < 3e-4);
    let beats = json(&["fit", "beats", &file("beats.csv"), "--bph", "3600"]);
    assert!((f(&beats, "rate_s_per_day") - 4.0).abs() < 0.05);
    assert_eq!(beats["repaired"]["missed"], 2);
}

/// A real record that no free decay from one release describes (a light
/// pendulum stopped by friction within a second, read by an encoder in 2°
/// steps; tests/data/encoder-stops.csv names its source): the nonlinear
/// fit, seeded by rewinding the heavily damped swing to a release near
/// the top, runs off (release amplitude at the top, not determined) and
/// fits worse than the linear one, so the linear fit is reported, and
/// says so. Its damping matches the peaks' logarithmic
/// decrement (the first three crests, 46°, 20°, 2° less the quantisation,
/// give ζ ≈ 0.13-0.17).
#[test]
fn a_record_the_nonlinear_fit_cannot_follow_falls_back_to_the_linear_one() {
    let file = format!(
        "{}/tests/data/encoder-stops.csv",
        env!("CARGO_MANIFEST_DIR")
    );
    let v = json(&["fit", "trajectory", &file, "--columns", "time_s,angle_deg"]);
    assert_eq!(v["model"], "linear", "{v}");
    assert_eq!(v["model_requested"], "auto");
    let warnings = v["warnings"].to_string();
    // (It runs off, or does not converge at all from the linear start.)
    assert!(
        warnings.contains("the linear fit is reported")
            && (warnings.contains("worse than the linear one")
                || warnings.contains("did not converge")),
        "{warnings}"
    );
    // ln(46/20) / 2π gives ζ ≈ 0.13 for the first swing.
    let zeta = f(&v["parameters"], "zeta");
    assert!((0.12..0.2).contains(&zeta), "{zeta}");
    assert!(f(&v, "residual_rms_rad").to_degrees() < 2.5);
}

/// Issue 23, wrong answers 3 and 4: `--pivot fit` on a short noisy arc
/// gave g with a standard error that left out the radius's (13.52 ±
/// 0.0014 where the bob hung 0.338 m below the pivot); on pixels it gave g
/// in thousands with no word. Now the radius's error is carried into g's,
/// and g far from any pendulum's is warned, naming pixels.
#[test]
fn a_fitted_pivot_carries_its_radius_error_and_knows_pixels() {
    let dir = tempfile::tempdir().unwrap();
    // 0.338 m, 4° swing, 10 s at 30 frames a second, positions with 2 mm
    // of deterministic scatter (a short arc: the radius is poorly fixed).
    let arc = |scale: f64| {
        let w = (9.80665f64 / 0.338).sqrt();
        let mut text = String::from("t,x,y\n");
        for i in 0..300 {
            let t = f64::from(i) / 30.0;
            let th = 4f64.to_radians() * (-0.02 * t).exp() * (w * t).cos();
            let (dx, dy) = (
                0.002 * (f64::from(i) * 1.7).sin(),
                0.002 * (f64::from(i) * 2.9).cos(),
            );
            let (x, y) = (0.338 * th.sin() + dx, -0.338 * th.cos() + dy);
            text.push_str(&format!("{t},{},{}\n", x * scale, y * scale));
        }
        text
    };
    let metres = write(dir.path(), "arc.csv", &arc(1.0));
    let v = json(&[
        "fit",
        "trajectory",
        metres.to_str().unwrap(),
        "--pivot",
        "fit",
    ]);
    let (r, sr) = (f(&v, "track_radius"), f(&v, "track_radius_standard_error"));
    let (g, sg) = (
        f(&v["parameters"], "g_m_s2"),
        f(&v["standard_errors"], "g_m_s2"),
    );
    assert!(sg >= 0.99 * g * sr / r, "g {g} ± {sg}, radius {r} ± {sr}");
    assert!((g - 9.80665).abs() <= 3.0 * sg, "g {g} ± {sg}");
    // The same track in pixels, 500 to the metre.
    let pixels = write(dir.path(), "pixels.csv", &arc(500.0));
    let v = json(&[
        "fit",
        "trajectory",
        pixels.to_str().unwrap(),
        "--pivot",
        "fit",
    ]);
    let codes = v["warning_codes"].as_array().unwrap();
    assert!(
        codes.iter().any(|c| c == "gravity_implausible"),
        "{codes:?}"
    );
    assert!(
        v["warnings"].to_string().contains("pixels"),
        "{}",
        v["warnings"]
    );
}
