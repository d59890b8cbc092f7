//! `pendulum clock` through the binary.

use super::util::{f, files_in, json, pendulum, refuses};

/// The steady state of a deadbeat seconds clock: the circular error is the
/// exact period's at the steady amplitude (`period` computes it on its
/// own), the escapement's part is nearly nil, the energy balance holds
/// (energy per beat × 2 = the viscous loss per period π m g l A²/Q), and
/// the parts add up to the rate.
#[test]
fn a_deadbeat_clock() {
    let v = json(&[
        "clock",
        "--length",
        "0.99362m",
        "--q",
        "10000",
        "--escapement",
        "deadbeat",
        "--lift-angle",
        "2",
        "--drive",
        "20uJ",
    ]);
    let s = &v["steady"];
    let a = f(s, "amplitude_rad");
    assert!((2.0f64.to_radians()..5f64.to_radians()).contains(&a), "{v}");
    let p = json(&[
        "period",
        "--length",
        "0.99362m",
        "--amplitude",
        &format!("{}rad", a),
    ]);
    let circular = f(&p, "circular_error_s_per_day");
    assert!(
        (f(s, "circular_error_s_per_day") / circular - 1.0).abs() < 1e-9,
        "{p}"
    );
    assert!(f(s, "escapement_rate_s_per_day").abs() < 1e-3);
    let sum = f(s, "circular_rate_s_per_day") + f(s, "escapement_rate_s_per_day");
    assert!((f(s, "rate_s_per_day") - sum).abs() < 1e-6);
    let loss = std::f64::consts::PI * 5.0 * 9.80665 * 0.99362 * a * a / 1e4;
    assert!(
        (2.0 * f(s, "energy_per_beat_j") / loss - 1.0).abs() < 0.01,
        "{v}"
    );
}

/// The isochronism table and plot (deadbeat: the rate falls as the drive
/// rises), a long run with a mainspring's drive falling over eight days
/// and rewound, written as CSV with one row an hour.
#[test]
fn isochronism_and_a_long_run() {
    let dir = tempfile::tempdir().unwrap();
    let plot = dir.path().join("iso.svg");
    let v = json(&[
        "clock",
        "--length",
        "0.99362m",
        "--drive",
        "20uJ",
        "--drive-range",
        "0.5x..2x",
        "--steps",
        "4",
        "--plot",
        plot.to_str().unwrap(),
    ]);
    let rows = v["isochronism"].as_array().unwrap();
    assert_eq!(rows.len(), 4);
    let rates: Vec<f64> = rows.iter().map(|r| f(r, "rate_s_per_day")).collect();
    assert!(rates.windows(2).all(|w| w[1] < w[0]), "{rates:?}");
    let svg = std::fs::read_to_string(&plot).unwrap();
    assert!(svg.contains("drive factor") && svg.contains("amplitude (°)"));

    let spring = dir.path().join("spring.csv");
    std::fs::write(
        &spring,
        "time_s,drive_factor\n0,1\n691200,0.7\n691201,1\n1382400,0.7\n",
    )
    .unwrap();
    let out = dir.path().join("run.csv");
    let v = json(&[
        "clock",
        "--length",
        "0.99362m",
        "--drive",
        "20uJ",
        "--duration",
        "16days",
        "--every",
        "1h",
        "--drive-file",
        spring.to_str().unwrap(),
        "--swings",
        out.to_str().unwrap(),
    ]);
    let run = &v["long_run"];
    assert!(!run["stopped"].as_bool().unwrap());
    let text = std::fs::read_to_string(&out).unwrap();
    let mut lines = text.lines();
    assert_eq!(
        lines.next().unwrap(),
        "time_s,beats,amplitude_rad,rate_s_per_day,time_error_s,drive_factor"
    );
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 16 * 24 + 1);
    // The drive weakens: the arc shrinks over the first eight days, and
    // is back after the rewinding.
    let at = |day: f64| rows.iter().find(|r| r[0] >= day * 86_400.0 - 1.0).unwrap();
    assert!(at(7.9)[2] < at(0.0)[2] * 0.95);
    assert!(at(9.0)[2] > at(7.9)[2]);
    assert!((at(7.9)[5] - (1.0 - 0.3 * 7.9 / 8.0)).abs() < 1e-3);
}

/// Bad input: one line naming the flag, exit 2, nothing left behind.
#[test]
fn bad_clocks_are_refused() {
    let base = ["clock", "--length", "1m"];
    let with = |extra: &[&str]| {
        let mut v: Vec<String> = base.iter().map(|s| s.to_string()).collect();
        v.extend(extra.iter().map(|s| s.to_string()));
        v
    };
    for (extra, flag, words) in [
        (
            vec!["--drive", "1uJ"],
            "--drive",
            "the pendulum stops: drive below",
        ),
        (
            vec!["--drive", "20uJ", "--lift-angle", "400"],
            "--lift-angle",
            "170°",
        ),
        (vec!["--drive", "-20uJ"], "--drive", "positive"),
        (vec!["--drive", "20 kg"], "--drive", "neither a torque"),
        (vec!["--drive", "20uJ", "--q", "-5"], "--q", "exceed"),
        (
            vec!["--drive", "2e-4Nm", "--escapement", "impulse"],
            "--drive",
            "energy per beat",
        ),
        (
            vec!["--drive", "20uJ", "--friction", "-1"],
            "--friction",
            "negative",
        ),
        (
            vec!["--drive", "20uJ", "--drive-range", "2x..1x"],
            "--drive-range",
            "smaller",
        ),
        (vec!["--drive", "20J"], "--drive", "give less drive"),
        (
            vec![
                "--drive",
                "20uJ",
                "--escapement",
                "recoil",
                "--friction",
                "1",
            ],
            "--friction",
            "below 1",
        ),
        (
            vec![
                "--drive",
                "20uJ",
                "--escapement",
                "recoil",
                "--friction",
                "0.99999",
            ],
            "--escapement",
            "no drive keeps this escapement going",
        ),
        (
            vec!["--drive", "20uJ", "--beat-error", "5"],
            "--beat-error",
            "give a unit",
        ),
        (
            vec!["--drive", "20uJ", "--beat-error", "5 kg"],
            "--beat-error",
            "neither a beat error",
        ),
        (
            vec!["--drive", "20uJ", "--beat-error", "1.2s"],
            "--beat-error",
            "less than the beat",
        ),
        (
            vec!["--drive", "20uJ", "--beat-error", "3deg"],
            "--beat-error",
            "in beat it would go",
        ),
        (
            vec!["--drive", "20uJ", "--beat-error", "nan ms"],
            "--beat-error",
            "finite",
        ),
    ] {
        let args = with(&extra);
        let refs: Vec<&str> = args.iter().map(String::as_str).collect();
        let e = refuses(&refs, flag);
        assert!(e.contains(words), "{e}");
    }
    let dir = tempfile::tempdir().unwrap();
    let bad = dir.path().join("bad.csv");
    std::fs::write(&bad, "time_s,drive_factor\n0,1\n10,x\n").unwrap();
    let out = dir.path().join("out.csv");
    let e = refuses(
        &[
            "clock",
            "--length",
            "1m",
            "--drive",
            "20uJ",
            "--duration",
            "1day",
            "--drive-file",
            bad.to_str().unwrap(),
            "--swings",
            out.to_str().unwrap(),
        ],
        "--drive-file",
    );
    assert!(e.contains("line 3"), "{e}");
    assert_eq!(files_in(dir.path()).len(), 1, "only bad.csv is left");
    pendulum()
        .args([
            "clock",
            "--length",
            "1m",
            "--drive",
            "20uJ",
            "--duration",
            "1h",
        ])
        .assert()
        .success();
}

/// The time error after a three-day run of `design` at 20 µJ a beat with
/// the drive file `text` (written to `path`), a row an hour.
fn three_days(design: &str, path: &std::path::Path, text: &str) -> f64 {
    std::fs::write(path, text).unwrap();
    let v = json(&[
        "clock",
        "--design",
        design,
        "--drive",
        "20uJ",
        "--duration",
        "3days",
        "--every",
        "1h",
        "--drive-file",
        path.to_str().unwrap(),
    ]);
    f(&v["long_run"], "time_error_s")
}

/// A long run of a design through a warm spell: 10 °C warmer from the
/// first day on moves the rate by ten times the design's temperature
/// coefficient (`design` gives it on its own) and by the thinner air's
/// effect (the pressure held), so after three days the
/// clock is 2 × that many seconds off the same run at constant
/// temperature (within 1%). Without a design the temperature column is
/// refused.
#[test]
fn a_warm_spell() {
    let design = format!(
        "{}/../../examples/seconds-steel-brass.toml",
        env!("CARGO_MANIFEST_DIR")
    );
    let coefficient = f(
        &json(&["design", &design]),
        "temperature_coefficient_s_per_day_per_c",
    );
    // The room's air at constant pressure thins as it warms: the design's
    // air effect at 30 °C less at 20 °C.
    let air = |t: &str| {
        f(
            &json(&["design", &design, "--temperature", t]),
            "air_rate_s_per_day",
        )
    };
    let thinner = air("30") - air("20");
    let dir = tempfile::tempdir().unwrap();
    let error_after = |text: &str| three_days(&design, &dir.path().join("weather.csv"), text);
    let steady = error_after("time_s,temperature_c\n0,20\n");
    let warm = error_after("time_s,temperature_c\n0,20\n86400,20\n86401,30\n");
    let expected = 2.0 * (10.0 * coefficient + thinner);
    assert!(
        ((warm - steady) / expected - 1.0).abs() < 0.01,
        "{} against {expected}",
        warm - steady
    );
    let path = dir.path().join("weather.csv");
    let e = refuses(
        &[
            "clock",
            "--length",
            "1m",
            "--drive",
            "20uJ",
            "--duration",
            "1day",
            "--drive-file",
            path.to_str().unwrap(),
        ],
        "--drive-file",
    );
    assert!(e.contains("need a design"), "{e}");
}

/// The long-case clock's wooden rod through a damp spell: 2 points more
/// humidity from the first day on move the rate by twice the datasheet's
/// humidity coefficient (the wood settled at once) and by the damper air's
/// own effect (`design --humidity`), so after three days the clock is 2 ×
/// that many seconds off the dry run (within 2%: Simpson's isotherm curves
/// over the 2 points). A gradient of 1 K/m from the first day on moves it
/// by the datasheet's gradient coefficient (within 1%), and a gradient
/// column in K/cm is read as such.
#[test]
fn a_damp_spell_and_a_gradient_through_the_binary() {
    let design = format!(
        "{}/../../examples/longcase-wood.toml",
        env!("CARGO_MANIFEST_DIR")
    );
    let sheet = json(&["design", &design]);
    let humidity = f(&sheet, "humidity_coefficient_s_per_day_per_percent");
    let gradient = f(&sheet, "gradient_coefficient_s_per_day_per_k_per_m");
    let air = |h: &str| {
        f(
            &json(&["design", &design, "--humidity", h]),
            "air_rate_s_per_day",
        )
    };
    let damper = air("52") - air("50");
    let dir = tempfile::tempdir().unwrap();
    let error_after = |text: &str| three_days(&design, &dir.path().join("weather.csv"), text);
    let dry = error_after("time_s,humidity_percent\n0,50\n");
    let damp = error_after("time_s,humidity_percent\n0,50\n86400,50\n86401,52\n");
    let expected = 2.0 * (2.0 * humidity + damper);
    assert!(
        ((damp - dry) / expected - 1.0).abs() < 0.02,
        "{} against {expected}",
        damp - dry
    );
    // Humidities that never pass 1 are likely fractions: said so.
    let path = dir.path().join("fractions.csv");
    std::fs::write(&path, "time_s,humidity_percent\n0,0.5\n86400,0.6\n").unwrap();
    let v = json(&[
        "clock",
        "--design",
        &design,
        "--drive",
        "20uJ",
        "--duration",
        "2days",
        "--every",
        "1h",
        "--drive-file",
        path.to_str().unwrap(),
    ]);
    assert!(
        v["long_run"]["warnings"]
            .to_string()
            .contains("multiply it by 100"),
        "{}",
        v["long_run"]
    );
    // A drive file without a header is told to name its columns there
    // (clock has no --columns).
    std::fs::write(&path, "0,20\n86400,21\n").unwrap();
    let e = refuses(
        &[
            "clock",
            "--design",
            &design,
            "--drive",
            "20uJ",
            "--duration",
            "1day",
            "--drive-file",
            path.to_str().unwrap(),
        ],
        "--drive-file",
    );
    assert!(
        e.contains("in a first line") && !e.contains("--columns"),
        "{e}"
    );
    let steep = error_after("time_s,gradient (K/cm)\n0,0\n86400,0\n86401,0.01\n");
    assert!(
        ((steep - dry) / (2.0 * gradient) - 1.0).abs() < 0.01,
        "{} against {}",
        steep - dry,
        2.0 * gradient
    );
}

/// `simulate --method averaged`: the same turning points as the
/// symplectic method at tolerance 1e-12 over 200 periods at Q = 10,000
/// (amplitude within 1e-9, time within 1e-6 s); drag and dry friction are
/// refused naming --method.
#[test]
fn simulate_by_the_averaged_method() {
    let dir = tempfile::tempdir().unwrap();
    let last = |method: &[&str]| {
        let path = dir.path().join("swings.csv");
        let mut args = vec![
            "simulate",
            "--length",
            "0.99362m",
            "--amplitude",
            "3",
            "--q",
            "10000",
            "--duration",
            "400s",
            "--swings",
            path.to_str().unwrap(),
        ];
        args.extend_from_slice(method);
        json(&args);
        let text = std::fs::read_to_string(&path).unwrap();
        let row: Vec<f64> = text
            .lines()
            .last()
            .unwrap()
            .split(',')
            .map(|x| x.parse().unwrap())
            .collect();
        row
    };
    let a = last(&["--method", "averaged"]);
    let s = last(&["--method", "symplectic", "--tolerance", "1e-12"]);
    assert_eq!(a[0], s[0]);
    assert!((a[1] - s[1]).abs() < 1e-6, "{a:?} {s:?}");
    assert!((a[2] / s[2] - 1.0).abs() < 1e-9, "{a:?} {s:?}");
    refuses(
        &[
            "simulate",
            "--length",
            "1m",
            "--amplitude",
            "3",
            "--quadratic-drag",
            "0.1",
            "--duration",
            "10s",
            "--method",
            "averaged",
        ],
        "--method",
    );
}

/// The drive file is read by the shared measurement reader: a spreadsheet
/// of much of Europe (semicolons, decimal commas, hours, German names)
/// gives the run the plain CSV gives; pressures in inHg the run in hPa
/// gives; times are the run's own (a file that starts on day 1 holds its
/// first row until then); temperatures in K and °F are converted; a unit of
/// the wrong kind, a blank cell or a row too wide is refused naming it.
#[test]
fn drive_files_as_people_write_them() {
    let design = format!(
        "{}/../../examples/seconds-steel-brass.toml",
        env!("CARGO_MANIFEST_DIR")
    );
    let dir = tempfile::tempdir().unwrap();
    let run = |name: &str, text: &str| three_days(&design, &dir.path().join(name), text);
    let plain = run(
        "plain.csv",
        "time_s,temperature_c,drive_factor\n0,20,1\n86400,20,1\n172800,26,0.8\n",
    );
    let european = run(
        "europe.csv",
        "Zeit (h);Temperatur (°C);Antrieb\n0;20,0;1\n24;20,0;1\n48;26,0;0,8\n",
    );
    assert!(
        (plain - european).abs() <= 1e-9 * plain.abs().max(1e-3),
        "{plain} against {european}"
    );
    // 29.92 inHg = 1013.21 hPa, then 28.5 inHg = 965.12 hPa.
    let hpa = run(
        "hpa.csv",
        "time_s,pressure_hpa\n0,1013.2087\n86400,965.1209\n",
    );
    let inhg = run("inhg.csv", "time_s,pressure (inHg)\n0,29.92\n86400,28.5\n");
    assert!(
        (hpa - inhg).abs() < 1e-3 * hpa.abs(),
        "{hpa} against {inhg}"
    );
    // A schedule that starts on day 1 holds its first row before it: the
    // same as one that states day 0.
    let late = run("late.csv", "time_s,temperature_c\n86400,25\n");
    let early = run("early.csv", "time_s,temperature_c\n0,25\n86400,25\n");
    assert_eq!(late, early);
    // Kelvin and Fahrenheit are temperatures too: 25 °C is 298.15 K and
    // 77 °F (the same run to rounding).
    let kelvin = run("kelvin.csv", "time_s,temperature (K)\n86400,298.15\n");
    let fahrenheit = run("fahrenheit.csv", "time_s,temperature (°F)\n86400,77\n");
    for other in [kelvin, fahrenheit] {
        assert!(
            (other - early).abs() <= 1e-9 * early.abs().max(1e-3),
            "{other} {early}"
        );
    }
    let bad = dir.path().join("wrong-unit.csv");
    std::fs::write(&bad, "time_s,temperature (hPa)\n0,68\n").unwrap();
    let args = [
        "clock",
        "--design",
        &design,
        "--drive",
        "20uJ",
        "--duration",
        "1day",
        "--drive-file",
    ];
    let e = refuses(
        &[&args[..], &[bad.to_str().unwrap()]].concat(),
        "--drive-file",
    );
    assert!(e.contains("'hpa' is not a unit of temperature"), "{e}");
    // A blank cell in a schedule is refused by its line and column (its
    // row was skipped without a word, taking its other settings with it).
    let blank = dir.path().join("blank.csv");
    std::fs::write(
        &blank,
        "time_s,humidity_percent,temperature_c\n0,50,20\n86400,60,\n",
    )
    .unwrap();
    let e = refuses(
        &[&args[..], &[blank.to_str().unwrap()]].concat(),
        "--drive-file",
    );
    assert!(e.contains("line 3, column temperature_c: empty"), "{e}");
    // A row with more cells than the rest is refused by its line (a short
    // file's odd row was taken for the data and the rows above for
    // settings).
    let wide = dir.path().join("wide.csv");
    std::fs::write(&wide, "time_s,humidity_percent\n0,50\n86400,60,7\n").unwrap();
    let e = refuses(
        &[&args[..], &[wide.to_str().unwrap()]].concat(),
        "--drive-file",
    );
    assert!(
        e.contains("line 3 holds 3 cells where the rows before it hold 2"),
        "{e}"
    );
}

/// A Shortt-like tank whose nitrogen leaks from 27 to 60 hPa: the gas damps
/// more, so an impulse clock (the same energy every impulse, so its arc
/// squared goes as Q for a linearly damped swing) settles at
/// sqrt(Q₆₀/Q₂₇) of its arc, with Q at each pressure the given Q at 27 hPa
/// (of which `design` says the gas takes `q_gas`) and the gas's share
/// there changed to the design's `q_gas` at 60 hPa; within 0.5% (the
/// circular error's and the impulse's small departures from that law).
#[test]
fn a_tank_that_leaks_damps_the_arc() {
    let design = format!(
        "{}/../../examples/seconds-steel-brass.toml",
        env!("CARGO_MANIFEST_DIR")
    );
    let q_gas = |p: &str| {
        f(
            &json(&["design", &design, "--gas", "nitrogen", "--pressure", p]),
            "q_gas",
        )
    };
    let (q27, q60) = (q_gas("27"), q_gas("60"));
    let given = 20_000.0;
    let pivot = 1.0 / (1.0 / given - 1.0 / q27);
    let later = 1.0 / (1.0 / pivot + 1.0 / q60);
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("tank.csv");
    std::fs::write(&path, "time_s,pressure_hpa\n0,27\n86400,27\n86401,60\n").unwrap();
    let v = json(&[
        "clock",
        "--design",
        &design,
        "--escapement",
        "impulse",
        "--drive",
        "5uJ",
        "--q",
        "20000",
        "--duration",
        "4days",
        "--every",
        "1h",
        "--drive-file",
        path.to_str().unwrap(),
        "--gas",
        "nitrogen",
    ]);
    let start = f(&v["steady"], "amplitude_rad");
    let end = f(&v["long_run"], "final_amplitude_rad");
    let expected = (later / given).sqrt();
    assert!(
        ((end / start) / expected - 1.0).abs() < 0.005,
        "arc ratio {} against {expected}",
        end / start
    );
}

/// Out of beat, through the binary: a beat error given in milliseconds is
/// found to a microsecond and its offset reported; the same offset given
/// as an angle gives the same beat error back; the JSON carries both and
/// the warning, and an isochronism curve reports the beat error at every
/// drive (the offset held, the beat error falling as the arc grows, as
/// `2δ / (ω sqrt(A² - h²))` says).
#[test]
fn a_clock_out_of_beat() {
    let base = ["clock", "--length", "0.99362m", "--drive", "20uJ"];
    let run = |extra: &[&str]| {
        let mut v: Vec<&str> = base.to_vec();
        v.extend(extra);
        json(&v)
    };
    let by_time = run(&["--beat-error", "20ms"]);
    let b = f(&by_time["steady"], "beat_error_ms");
    assert!((b - 20.0).abs() < 1e-3, "{by_time}");
    let delta = f(&by_time, "out_of_beat_deg");
    assert!(delta > 0.0 && delta < 0.2, "{by_time}");
    assert_eq!(by_time["warnings"][0]["code"], "out_of_beat", "{by_time}");
    assert_eq!(by_time["warnings"][0]["figure"], "out_of_beat_deg");
    assert!(by_time["warnings"][0]["message"]
        .as_str()
        .unwrap()
        .contains("out of beat"));
    assert!(f(&by_time, "out_of_beat_rate_s_per_day").abs() < 1e-3);
    let by_angle = run(&[
        "--beat-error",
        &format!("{delta}deg"),
        "--drive-range",
        "1x..4x",
        "--steps",
        "3",
    ]);
    assert!(
        (f(&by_angle["steady"], "beat_error_ms") - b).abs() < 1e-3,
        "{by_angle}"
    );
    let points = by_angle["isochronism"].as_array().unwrap();
    let errors: Vec<f64> = points.iter().map(|p| f(p, "beat_error_ms")).collect();
    assert!(errors.windows(2).all(|w| w[1] < w[0]), "{errors:?}");
    let in_beat = run(&[]);
    assert_eq!(f(&in_beat["steady"], "beat_error_ms"), 0.0);
    assert!(in_beat.get("warnings").is_none() && in_beat["out_of_beat_rate_s_per_day"].is_null());
}
