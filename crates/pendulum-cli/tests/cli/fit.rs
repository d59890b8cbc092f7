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
            "viscous+coulomb+quadratic"
        ]
    );
    let best = &models[3];
    for key in ["zeta", "friction_angle_rad", "amplitude0_rad"] {
        assert!(best["parameters"][key].is_number(), "{key}");
        assert!(best["standard_errors"][key].is_number(), "{key}");
    }
    assert!(models[2]["parameters"]["quadratic_drag_per_rad"].is_number());
    for m in models {
        for key in ["residual_rms", "aic", "bic"] {
            assert!(m[key].is_number(), "{key}");
        }
    }
    assert!(best["q_factor"].is_number() && best["q_viscous"].is_number());
    // Dry friction alone has a Q over the record, and no viscous part.
    assert!(models[1]["q_factor"].is_number());
    assert!(
        models[1]["q_viscous"].is_null(),
        "no viscous part in dry friction"
    );
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

/// The example files give what the book says they hold (tour.md).
#[test]
fn the_example_files_fit_as_documented() {
    let examples = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    let file = |name: &str| examples.join(name).to_str().unwrap().to_string();
    let decay = json(&["fit", "decay", &file("rundown.csv"), "--length", "0.99362m"]);
    assert_eq!(decay["preferred"], "viscous+coulomb");
    let best = &decay["models"][3]["parameters"];
    assert!((f(best, "friction_angle_rad") / 1e-6 - 1.0).abs() < 0.05);
    assert!((decay["models"][3]["q_viscous"].as_f64().unwrap() / 10_000.0 - 1.0).abs() < 0.02);
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

/// Issue 44, item 3: one Q. `fit trajectory` and `fit decay` on the same
/// record give the same `q_factor` (Q over the record, from the energy
/// lost per cycle), each within three standard errors of the truth SciPy
/// computes from the generating motion (`tools/reference/record_q.py`,
/// `tests/data/record_q/truth.json`), and within their combined standard
/// error of each other; the viscous part alone is `q_viscous` (909 in
/// truth for the Tracker example, where the trajectory fit once printed it
/// as Q beside the decay fit's 206).
#[test]
fn trajectory_and_decay_give_one_q() {
    let data = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/record_q");
    let truth: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(data.join("truth.json")).unwrap()).unwrap();
    let example = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/tracker.txt");
    for (file, name, length) in [
        (example, "tracker.txt", "1.2m"),
        (data.join("drag.csv"), "drag.csv", "0.8m"),
    ] {
        let path = file.to_str().unwrap();
        let q = f(&truth[name], "q_factor");
        let t = json(&["fit", "trajectory", path, "--length", length]);
        let (qt, st) = (f(&t, "q_factor"), f(&t, "q_factor_standard_error"));
        let d = json(&["fit", "decay", path, "--length", length]);
        let best = d["models"]
            .as_array()
            .unwrap()
            .iter()
            .find(|m| m["model"] == d["preferred"])
            .unwrap();
        let (qd, sd) = (f(best, "q_factor"), f(best, "q_factor_standard_error"));
        assert!(
            (qt - q).abs() < 3.0 * st,
            "{name}: trajectory {qt} ± {st}, truth {q}"
        );
        assert!(
            (qd - q).abs() < 3.0 * sd,
            "{name}: decay {qd} ± {sd}, truth {q}"
        );
        assert!(
            (qt - qd).abs() < st.hypot(sd),
            "{name}: trajectory {qt} ± {st}, decay {qd} ± {sd}"
        );
        // The viscous part is apart, and is not the pendulum's Q.
        let (qv, sv) = (f(&t, "q_viscous"), f(&t, "q_viscous_standard_error"));
        let truth_viscous = f(&truth[name], "q_viscous");
        assert!((qv - truth_viscous).abs() < 3.0 * sv, "{name}: {qv} ± {sv}");
        assert!(qv > 4.0 * qt, "{name}: {qv} against {qt}");
        // The two commands name the law alike.
        let laws: Vec<&str> = d["models"]
            .as_array()
            .unwrap()
            .iter()
            .map(|m| m["model"].as_str().unwrap())
            .collect();
        assert!(
            laws.contains(&t["damping_law"].as_str().unwrap()),
            "{laws:?}"
        );
        assert!(laws.contains(&"viscous+coulomb+quadratic"), "{laws:?}");
    }
    // `full` is still taken as the law of all three rates.
    let path = data.join("drag.csv");
    let v = json(&[
        "fit",
        "decay",
        path.to_str().unwrap(),
        "--model",
        "full",
        "--length",
        "0.8m",
    ]);
    assert_eq!(v["models"][0]["model"], "viscous+coulomb+quadratic");
}

/// Issue 44, item 2: g's standard error takes the length's uncertainty,
/// and lists its parts: a 0.8 m pendulum measured to 2 mm has g known to
/// no better than 9.81 × 2/800 = 0.0245 m/s², whatever the fit, in `fit
/// trajectory`, `fit decay` (g from the turning points) and `fit period`.
/// Without the uncertainty the text says what the ± leaves out.
#[test]
fn the_length_uncertainty_is_in_g() {
    let data = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/record_q");
    let drag = data.join("drag.csv");
    let path = drag.to_str().unwrap();
    let with = ["--length", "0.8m", "--length-uncertainty", "2mm"];
    let parts = |v: &serde_json::Value| (f(v, "fit"), f(v, "length"));
    let mut args = vec!["fit", "trajectory", path];
    args.extend(with);
    let t = json(&args);
    let se = f(&t["standard_errors"], "g_m_s2");
    let (fit, length) = parts(&t["standard_error_parts"]["g_m_s2"]);
    assert!(se >= 0.024, "trajectory: {se}");
    assert!((se - fit.hypot(length)).abs() < 1e-12 * se, "{t}");
    assert!((length / (f(&t["parameters"], "g_m_s2") * 0.002 / 0.8) - 1.0).abs() < 1e-9);
    assert_eq!(f(&t, "length_standard_error_m"), 0.002);
    let mut args = vec!["fit", "decay", path];
    args.extend(with);
    let d = json(&args);
    let g = &d["gravity"];
    assert!(f(g, "standard_error_m_s2") >= 0.024, "decay: {g}");
    assert!((f(g, "g_m_s2") - 9.80665).abs() < 3.0 * f(&g["standard_error_parts"], "fit"));
    // A period table of the same pendulum, its periods exact.
    let dir = tempfile::tempdir().unwrap();
    let mut table = String::from("amplitude_deg,period_s\n");
    for a in [5.0_f64, 10.0, 15.0, 20.0, 25.0] {
        let (mut x, mut y) = (1.0_f64, (a.to_radians() / 2.0).cos());
        for _ in 0..40 {
            (x, y) = ((x + y) / 2.0, (x * y).sqrt());
        }
        let t = std::f64::consts::TAU * (0.8_f64 / 9.80665).sqrt() / x;
        table.push_str(&format!("{a},{}\n", t * (1.0 + 1e-5 * (a - 15.0) / 10.0)));
    }
    let p = write(dir.path(), "periods.csv", &table);
    let mut args = vec!["fit", "period", p.to_str().unwrap()];
    args.extend(with);
    let v = json(&args);
    assert!(f(&v["standard_errors"], "g_m_s2") >= 0.024, "period: {v}");
    assert!(f(&v["standard_error_parts"]["g_m_s2"], "length") > 0.024);
    // Without it: the fit's part alone, said.
    let out = crate::util::pendulum()
        .args(["fit", "trajectory", path, "--length", "0.8m"])
        .assert()
        .success()
        .get_output()
        .stdout
        .clone();
    let text = String::from_utf8(out).unwrap();
    assert!(
        text.contains("the length's uncertainty is not in it"),
        "{text}"
    );
    let v = json(&["fit", "trajectory", path, "--length", "0.8m"]);
    assert!(
        v["standard_error_parts"]["g_m_s2"]["length"].is_null(),
        "{v}"
    );
    // A table of amplitudes gives no g for it to go in: refused, not
    // ignored.
    let rundown = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/rundown.csv");
    let e = refuses(
        &[
            "fit",
            "decay",
            rundown.to_str().unwrap(),
            "--length",
            "0.99362m",
            "--length-uncertainty",
            "1mm",
        ],
        "--length-uncertainty",
    );
    assert!(e.contains("does not give"), "{e}");
    // The uncertainty without a length is refused by its flag.
    refuses(
        &["fit", "trajectory", path, "--length-uncertainty", "2mm"],
        "--length-uncertainty",
    );
    refuses(
        &[
            "fit",
            "decay",
            path,
            "--length",
            "0.8m",
            "--length-uncertainty",
            "-2mm",
        ],
        "--length-uncertainty",
    );
}

/// The warning codes of a fit's JSON (a trajectory's `warning_codes`, a
/// run-down's or a table's `warnings[].code`).
fn codes(v: &serde_json::Value) -> Vec<String> {
    if let Some(c) = v["warning_codes"].as_array() {
        return c.iter().map(|c| c.as_str().unwrap().to_string()).collect();
    }
    v["warnings"]
        .as_array()
        .map(|w| {
            w.iter()
                .map(|w| w["code"].as_str().unwrap().to_string())
                .collect()
        })
        .unwrap_or_default()
}

/// Issue 44: `fit beats` read a Tracker project (or export) without a
/// word, taking its video frames for beats. It is refused, naming the fit
/// that reads it.
#[test]
fn fit_beats_refuses_a_track() {
    let example = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/tracker.txt");
    let e = refuses(
        &["fit", "beats", example.to_str().unwrap()],
        "fit trajectory",
    );
    assert!(e.contains("video's frames"), "{e}");
    let dir = tempfile::tempdir().unwrap();
    let trk = write(dir.path(), "swing.trk", &tracker_project(&[(0..60, 0.0)]));
    refuses(&["fit", "beats", trk.to_str().unwrap()], "fit trajectory");
}

/// A Tracker project (`.trk`) as Tracker 5 writes it: a clip of 30 frames
/// a second, axes at (400, 50) px with 500 px a metre, and a point mass on
/// the frames of each range, the bob of a 0.8 m pendulum swinging 12° with
/// ζ = 0.002, displaced sideways by `shift` m on that range (a stray mark
/// elsewhere in the picture).
fn tracker_project(ranges: &[(std::ops::Range<u32>, f64)]) -> String {
    let (w, zeta, a0) = ((9.80665f64 / 0.8).sqrt(), 0.002, 12f64.to_radians());
    let mut frames = String::new();
    for (range, shift) in ranges {
        for k in range.clone() {
            let t = f64::from(k) / 30.0;
            let th = a0 * (-zeta * w * t).exp() * (w * t).cos();
            let (x, y) = (0.8 * th.sin() + shift, -0.8 * th.cos());
            // Image pixels, y down, about the axes' origin.
            let (px, py) = (400.0 + 500.0 * x, 50.0 - 500.0 * y);
            frames.push_str(&format!(
                "<property name=\"[{k}]\" type=\"object\">\n<object class=\"org.opensourcephysics.cabrillo.tracker.PointMass$FrameData\">\n<property name=\"x\" type=\"double\">{px}</property>\n<property name=\"y\" type=\"double\">{py}</property>\n</object>\n</property>\n"
            ));
        }
    }
    format!(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<object class=\"org.opensourcephysics.cabrillo.tracker.TrackerPanel\">\n<property name=\"videoclip\" type=\"object\">\n<object class=\"org.opensourcephysics.media.core.VideoClip\">\n<property name=\"startframe\" type=\"int\">0</property>\n<property name=\"stepsize\" type=\"int\">1</property>\n<property name=\"starttime\" type=\"double\">0.0</property>\n</object>\n</property>\n<property name=\"clipcontrol\" type=\"object\">\n<object class=\"org.opensourcephysics.media.core.StepperClipControl\">\n<property name=\"delta_t\" type=\"double\">33.333333333333336</property>\n</object>\n</property>\n<property name=\"coords\" type=\"object\">\n<object class=\"org.opensourcephysics.media.core.ImageCoordSystem\">\n<property name=\"framedata\" type=\"array\">\n<property name=\"[0]\" type=\"object\">\n<object class=\"org.opensourcephysics.media.core.ImageCoordSystem$FrameData\">\n<property name=\"xorigin\" type=\"double\">400.0</property>\n<property name=\"yorigin\" type=\"double\">50.0</property>\n<property name=\"angle\" type=\"double\">0.0</property>\n<property name=\"xscale\" type=\"double\">500.0</property>\n<property name=\"yscale\" type=\"double\">500.0</property>\n</object>\n</property>\n</property>\n</object>\n</property>\n<property name=\"tracks\" type=\"collection\">\n<property name=\"item\" type=\"object\">\n<object class=\"org.opensourcephysics.cabrillo.tracker.PointMass\">\n<property name=\"name\" type=\"string\">mass A</property>\n<property name=\"framedata\" type=\"array\">\n{frames}</property>\n</object>\n</property>\n</property>\n</object>\n"
    )
}

/// Issue 44: points after a tracking gap in a `.trk` entered the
/// trajectory fit, and the decay fit refused "amplitude 475°". The record
/// is split at its gaps and its longest run fitted, the rest left out and
/// said; g from the run is within three standard errors of the truth.
#[test]
fn a_tracking_gap_leaves_out_what_follows_it() {
    let dir = tempfile::tempdir().unwrap();
    // 40 s of the swing, then a gap of 5 s, then 2 s of marks 0.3 m off.
    let trk = write(
        dir.path(),
        "gap.trk",
        &tracker_project(&[(0..1200, 0.0), (1350..1410, 0.3)]),
    );
    let p = trk.to_str().unwrap();
    let t = json(&["fit", "trajectory", p, "--length", "0.8m"]);
    assert!(codes(&t).contains(&"samples_left_out".to_string()), "{t}");
    assert_eq!(t["points"], 1200);
    assert!(
        t["warnings"].to_string().contains("60 samples"),
        "{}",
        t["warnings"]
    );
    // The figures are the run's alone: those of the project without the
    // marks after the gap.
    let alone = write(dir.path(), "alone.trk", &tracker_project(&[(0..1200, 0.0)]));
    let a = json(&[
        "fit",
        "trajectory",
        alone.to_str().unwrap(),
        "--length",
        "0.8m",
    ]);
    assert_eq!(t["parameters"], a["parameters"]);
    assert!(codes(&a).is_empty(), "{a}");
    let d = json(&["fit", "decay", p, "--length", "0.8m"]);
    assert!(codes(&d).contains(&"samples_left_out".to_string()), "{d}");
    // The pivot fitted to the run's arc alone: the marks after the gap
    // are no part of it (they made a 6.6 m radius, g 80.6 m/s² and a
    // warning of pixels).
    let c = json(&["fit", "trajectory", p, "--pivot", "fit"]);
    let r = f(&c, "length_m");
    assert!((r - 0.8).abs() < 1e-9, "{c}");
    assert_eq!(codes(&c), ["samples_left_out"], "{c}");
    // One lost frame is no gap: nothing is left out.
    let trk = write(
        dir.path(),
        "lost.trk",
        &tracker_project(&[(0..600, 0.0), (601..1200, 0.0)]),
    );
    let t = json(&[
        "fit",
        "trajectory",
        trk.to_str().unwrap(),
        "--length",
        "0.8m",
    ]);
    assert!(!codes(&t).contains(&"samples_left_out".to_string()), "{t}");
}

/// Issue 44: a table of radians declared degrees (a 0.53° swing) got no
/// hint. Angles or amplitudes declared in degrees that never reach a
/// degree are said to look like radians, naming the figures they change;
/// a fair swing in degrees says nothing of the kind.
#[test]
fn radians_declared_degrees_are_named() {
    let dir = tempfile::tempdir().unwrap();
    let w = (9.80665f64 / 0.6).sqrt();
    let swing = |amplitude: f64| {
        let mut text = String::from("time_s,angle_deg\n");
        for i in 0..900 {
            let t = f64::from(i) / 30.0;
            let wobble = 2e-3 * amplitude * (f64::from(i) * 1.7).sin();
            let a = amplitude * (-0.01 * t).exp() * (w * t).cos() + wobble;
            text.push_str(&format!("{t},{a}\n"));
        }
        text
    };
    // 0.53 rad written under a degree's name.
    let wrong = write(dir.path(), "wrong.csv", &swing(0.53));
    let v = json(&[
        "fit",
        "trajectory",
        wrong.to_str().unwrap(),
        "--length",
        "0.6m",
    ]);
    assert!(
        codes(&v).contains(&"angles_look_like_radians".to_string()),
        "{v}"
    );
    let text = v["warnings"].to_string();
    assert!(
        text.contains("amplitude_rad") && text.contains("57.3 times"),
        "{text}"
    );
    // 8° in degrees: nothing.
    let fair = write(dir.path(), "fair.csv", &swing(8.0));
    let v = json(&[
        "fit",
        "trajectory",
        fair.to_str().unwrap(),
        "--length",
        "0.6m",
    ]);
    assert!(
        !codes(&v).contains(&"angles_look_like_radians".to_string()),
        "{v}"
    );
    // A run-down's amplitudes the same.
    let mut table = String::from("time_s,amplitude_deg\n");
    for i in 0..60 {
        let t = 10.0 * f64::from(i);
        table.push_str(&format!("{t},{}\n", 0.53 * (-1e-3 * t).exp()));
    }
    let rundown = write(dir.path(), "rundown.csv", &table);
    let v = json(&[
        "fit",
        "decay",
        rundown.to_str().unwrap(),
        "--model",
        "viscous",
    ]);
    assert!(
        codes(&v).contains(&"angles_look_like_radians".to_string()),
        "{v}"
    );
}

/// Issue 44: ω_n on Tracker times rounded to three digits came out
/// 0.36% and 0.54% low, the file read without a word. Times rounded to
/// three significant figures (a 2-minute export at 29.97 frames a
/// second, several frames to a stamp past 10 s) are rebuilt on their
/// frame grid and said; ω_n is the closed form's within three standard
/// errors.
#[test]
fn times_rounded_to_three_figures_are_rebuilt() {
    let dir = tempfile::tempdir().unwrap();
    let (length, zeta, a0): (f64, f64, f64) = (0.9, 0.003, 0.05);
    let wn = (9.80665 / length).sqrt();
    let wd = wn * (1.0 - zeta * zeta).sqrt();
    let figures = |t: f64| {
        if t == 0.0 {
            return "0".to_string();
        }
        let digits = (2 - t.log10().floor() as i32).max(0) as usize;
        format!("{t:.digits$}")
    };
    let mut text = String::from("mass_A\nt\tx\ty\n");
    for k in 0..3600 {
        let t = f64::from(k) / 29.97;
        // The closed form of section 1-4, released from rest.
        let env = a0 * (-zeta * wn * t).exp();
        let th = env * ((wd * t).cos() + zeta * wn / wd * (wd * t).sin());
        let wobble = 1e-4 * (f64::from(k) * 2.3).sin();
        text.push_str(&format!(
            "{}\t{}\t{}\n",
            figures(t),
            length * th.sin() + wobble,
            -length * th.cos()
        ));
    }
    let path = write(dir.path(), "rounded.txt", &text);
    let v = json(&[
        "fit",
        "trajectory",
        path.to_str().unwrap(),
        "--model",
        "linear",
    ]);
    let rebuilt = &v["time_rebuilt"];
    assert!(
        (f(rebuilt, "frame_interval_s") * 29.97 - 1.0).abs() < 1e-6,
        "{rebuilt}"
    );
    assert!(
        rebuilt["repeated_times"].as_u64().unwrap() > 2000,
        "{rebuilt}"
    );
    // The linear model's ω_0 carries the finite-amplitude correction at
    // 0.05 rad (1.6e-4): compare ω_d / √(1 − ζ²) before it.
    let (w, se) = (
        f(&v["parameters"], "omega_d_rad_s"),
        f(&v["standard_errors"], "omega_d_rad_s"),
    );
    assert!((w - wd).abs() < 3.0 * se, "ω_d {w} ± {se} vs {wd}");
}

/// Issue 44: `fit decay --period` counted a swing as half a period
/// without a word in `--help`. The help says so, and with `--period` a
/// swing column takes half of it each (no length needed).
#[test]
fn a_swing_is_half_a_period() {
    let help = crate::util::pendulum()
        .args(["fit", "decay", "--help"])
        .assert()
        .success()
        .get_output()
        .stdout
        .clone();
    let help = String::from_utf8(help).unwrap();
    assert!(help.contains("a swing is a half"), "{help}");
    let dir = tempfile::tempdir().unwrap();
    let mut text = String::from("swing,amplitude_rad\n");
    // λ = 1e-3 /s, a 2 s period: a swing is 1 s.
    for i in 0..80 {
        let s = 5 * i;
        text.push_str(&format!("{s},{}\n", 0.05 * (-1e-3 * f64::from(s)).exp()));
    }
    let path = write(dir.path(), "swings.csv", &text);
    let v = json(&[
        "fit",
        "decay",
        path.to_str().unwrap(),
        "--period",
        "2s",
        "--model",
        "viscous",
    ]);
    // Q = ω/(2λ) = π/(2e-3).
    let q = f(&v["models"][0], "q_factor");
    assert!(
        (q / (std::f64::consts::PI / 2e-3) - 1.0).abs() < 1e-3,
        "{q}"
    );
}

/// Issue 44: a period-versus-length table with χ² 13.5 on 4 degrees of
/// freedom (probability 0.009) got no warning. A χ² less likely than 1%
/// is warned, naming the figures whose standard errors it widens; one as
/// likely as not says nothing.
#[test]
fn a_table_whose_scatter_exceeds_its_uncertainties_is_warned() {
    let dir = tempfile::tempdir().unwrap();
    let table = |scale: f64| {
        let mut text = String::from("length_m,period_s,period_err_s\n");
        for (i, l) in [0.3, 0.5, 0.7, 0.9, 1.1, 1.3].iter().enumerate() {
            let k = [1.0, -1.6, 0.4, 1.5, -1.9, 0.6][i];
            let t = std::f64::consts::TAU * (l / 9.81_f64).sqrt() + scale * 2e-3 * k;
            text.push_str(&format!("{l},{t},0.002\n"));
        }
        write(dir.path(), &format!("t{scale}.csv"), &text)
    };
    let loud = json(&["fit", "period", table(2.0).to_str().unwrap()]);
    let p = f(&loud, "chi_square_probability");
    assert!(p < 0.01, "{loud}");
    let w = loud["warnings"].to_string();
    assert!(
        codes(&loud).contains(&"residuals_exceed_uncertainties".to_string())
            && w.contains("g_m_s2")
            && w.contains("length_offset_m"),
        "{w}"
    );
    let quiet = json(&["fit", "period", table(0.8).to_str().unwrap()]);
    assert!(f(&quiet, "chi_square_probability") > 0.01, "{quiet}");
    assert!(codes(&quiet).is_empty(), "{quiet}");
}

/// What the reader left out is said on standard error by the fits that
/// read their file in `pendulum-data` (a blank cell's row), and options
/// for positions given for a file of angles are said not to have been
/// used: nothing taken, or left, without a word.
#[test]
fn the_fits_say_what_the_reader_left_out() {
    let dir = tempfile::tempdir().unwrap();
    let mut text = String::from("time_s,angle_deg\n");
    for i in 0..400 {
        let t = 0.05 * f64::from(i);
        if i == 50 {
            text.push_str(&format!("{t},\n"));
        } else {
            let a = 10.0 * (-0.002 * t).exp() * (3.13 * t).cos();
            text.push_str(&format!("{t},{a}\n"));
        }
    }
    let path = write(dir.path(), "blank.csv", &text);
    for command in ["trajectory", "decay"] {
        let out = crate::util::pendulum()
            .args(["fit", command])
            .arg(&path)
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(out.status.success(), "{command}: {err}");
        assert!(
            err.contains("1 row with a blank cell in a column used skipped (line 52)"),
            "{command}: {err}"
        );
    }
    let out = crate::util::pendulum()
        .args(["fit", "trajectory"])
        .arg(&path)
        .args(["--pivot", "fit", "--y-down"])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains(
            "--pivot, --y-down are for x and y positions, and the file holds angles: not used"
        ),
        "{err}"
    );
    let amplitudes = concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/rundown.csv");
    let out = crate::util::pendulum()
        .args(["fit", "decay", amplitudes, "--scale", "2m"])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("--scale is for x and y positions, and the file holds amplitudes: not used"),
        "{err}"
    );
}
