//! `pendulum log` and `pendulum stability` on the records issue 44 found
//! answered wrong: each is now answered, refused with its reason or
//! warned with the figure it concerns, through the real binary.

use crate::util::{f, json, pendulum, refuses};

/// A file of the project's examples, by its path from the repository.
fn example(name: &str) -> String {
    format!("{}/../../examples/{name}", env!("CARGO_MANIFEST_DIR"))
}

fn write(dir: &std::path::Path, name: &str, text: &str) -> String {
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path.to_str().unwrap().to_string()
}

/// A small generator of standard normal deviates (xorshift and
/// Box–Muller), so the files do not depend on a crate's stream.
struct Normal(u64);

impl Normal {
    fn uniform(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        ((self.0 >> 11) as f64 + 0.5) / (1u64 << 53) as f64
    }
    fn next(&mut self) -> f64 {
        let (a, b) = (self.uniform(), self.uniform());
        (-2.0 * a.ln()).sqrt() * (std::f64::consts::TAU * b).cos()
    }
}

/// `--start` on a log whose times are already dates moved them decades
/// on (to 2076) and fitted the tides for those dates: refused, naming
/// the flag and the log's first date.
#[test]
fn start_on_a_dated_log_is_refused() {
    let e = refuses(
        &["log", &example("clock-log.csv"), "--start", "2026-01-01"],
        "--start",
    );
    assert!(e.contains("already dates"), "{e}");
    assert!(e.contains("2026-01-01T00:00:00Z"), "{e}");
}

/// A video's frame times (a Tracker export) were taken as a clock's half
/// periods without a word: refused, pointing to the fits.
#[test]
fn video_frame_times_are_not_half_periods() {
    let e = refuses(&["log", &example("tracker.txt")], "video's frames");
    assert!(e.contains("fit trajectory"), "{e}");
}

/// A master clock's 25 hourly offsets against NTP were refused at every
/// `--bin`: now the mean rate is given, and it agrees with the offsets'
/// own least-squares slope within its standard error.
#[test]
fn twenty_five_hourly_offsets_give_a_rate() {
    let dir = tempfile::tempdir().unwrap();
    let mut noise = Normal(0x5eed_0025);
    let mut text = String::from("time_s,offset_s\n");
    let (mut ts, mut xs) = (Vec::new(), Vec::new());
    for i in 0..25 {
        let t = 3600.0 * i as f64;
        // 0.8 s/day fast, white phase noise of 5 ms (NTP's).
        let x = 0.8 * t / 86_400.0 + 0.005 * noise.next();
        text.push_str(&format!("{t},{x:.6}\n"));
        ts.push(t);
        xs.push(x);
    }
    let path = write(dir.path(), "hourly.csv", &text);
    let v = json(&["log", &path]);
    let rate = f(&v, "rate_s_per_day");
    let se = f(&v, "rate_standard_error_s_per_day");
    let n = ts.len() as f64;
    let (mt, mx) = (ts.iter().sum::<f64>() / n, xs.iter().sum::<f64>() / n);
    let slope = ts
        .iter()
        .zip(&xs)
        .map(|(t, x)| (t - mt) * (x - mx))
        .sum::<f64>()
        / ts.iter().map(|t| (t - mt).powi(2)).sum::<f64>();
    let slope = slope * 86_400.0;
    assert!(se > 0.0 && se < 0.1, "{se}");
    assert!(
        (rate - slope).abs() < 3.0 * se,
        "rate {rate} ± {se} against the slope {slope}"
    );
    assert!((rate - 0.8).abs() < 3.0 * se, "rate {rate} ± {se}");
}

/// One missed pulse (a 1 s step) in 30 days of offsets every 10 min: the
/// warning names ADEV at the shortest τ and the jump's time; `--outliers
/// remove` takes it out and says so, and the deviations come back to
/// those of the series without it.
#[test]
fn a_missed_pulse_is_named_and_can_be_removed() {
    let dir = tempfile::tempdir().unwrap();
    let mut noise = Normal(0x0dd_5eed);
    let (mut clean, mut stepped) = (
        String::from("time_s,offset_s\n"),
        String::from("time_s,offset_s\n"),
    );
    let mut x = 0.0;
    for i in 0..30 * 144 {
        x += 6e-4 * noise.next();
        let t = 600 * i;
        clean.push_str(&format!("{t},{x:.9}\n"));
        let step = if i >= 2000 { 1.0 } else { 0.0 };
        stepped.push_str(&format!("{t},{:.9}\n", x + step));
    }
    let clean = write(dir.path(), "clean.csv", &clean);
    let stepped = write(dir.path(), "stepped.csv", &stepped);

    let out = pendulum()
        .args(["stability", &stepped])
        .assert()
        .success()
        .get_output()
        .clone();
    let text = String::from_utf8(out.stdout).unwrap();
    let warning = text
        .lines()
        .find(|l| l.starts_with("warning: ADEV"))
        .unwrap_or_else(|| panic!("no warning naming ADEV:\n{text}"));
    assert!(warning.contains("1 jump"), "{warning}");
    assert!(warning.contains("1200000 s from the start"), "{warning}");
    assert!(warning.contains("--outliers remove"), "{warning}");

    let reference = json(&["stability", &clean]);
    assert!(
        reference["warnings"].as_array().unwrap().is_empty(),
        "a clean series is warned: {}",
        reference["warnings"]
    );
    let removed = json(&["stability", &stepped, "--outliers", "remove"]);
    let w = &removed["warnings"][0];
    assert_eq!(w["code"], "accidents");
    assert_eq!(w["figure"], "adev");
    assert!(w["message"].as_str().unwrap().contains("taken out"), "{w}");
    assert_eq!(w["removed"], true);
    assert!(f(w, "adev_factor") > 10.0, "{w}");
    let rows = |v: &serde_json::Value| -> Vec<f64> {
        v["stability"]
            .as_array()
            .unwrap()
            .iter()
            .take(6)
            .map(|r| f(r, "adev"))
            .collect()
    };
    for (a, b) in rows(&removed).iter().zip(rows(&reference)) {
        assert!((a / b - 1.0).abs() < 0.01, "{a} against {b}");
    }
}

/// A real chronometer's daily time errors (Arnold No. 36 at Greenwich,
/// 1779-80, 341 days): its rate "at the mean time" was -1.81 ± 0.39
/// s/day, the first weeks' rate, where the log's own ends give -0.61:
/// now the rate is the mean over the log, within its standard error of
/// the ends' (first to last reading over the span, an independent
/// figure), with a standard error that holds the rate's wander.
#[test]
fn a_real_chronometer_gives_its_mean_rate() {
    let path = format!(
        "{}/tests/data/logs/arnold36.csv",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(&path).unwrap();
    let rows: Vec<(f64, f64)> = text
        .lines()
        .skip(1)
        .map(|l| {
            let (t, x) = l.split_once(',').unwrap();
            (t.parse().unwrap(), x.parse().unwrap())
        })
        .collect();
    let (first, last) = (rows[0], rows[rows.len() - 1]);
    let ends = (last.1 - first.1) / (last.0 - first.0) * 86_400.0;
    let v = json(&["log", &path]);
    let rate = f(&v, "rate_s_per_day");
    let se = f(&v, "rate_standard_error_s_per_day");
    assert!((rate - ends).abs() < se, "{rate} ± {se} against {ends}");
    // The rate wandered by some 2 s/day over the year: a standard error
    // of white noise alone (0.7 s/day a day over 340 days: 0.002) would
    // be far too small.
    assert!(se > 0.02 && se < 0.2, "{se}");
}

/// A daily cycle in 30 days of offsets: the rows it rules carry no
/// interval, and the text says why once for the run of them, not once a
/// row; the figure draws ADEV's interval as a bar on its point, not as
/// two more lines in the legend.
#[test]
fn a_daily_cycle_is_said_once_and_intervals_are_bars() {
    let dir = tempfile::tempdir().unwrap();
    let mut noise = Normal(0x05ee_dda7);
    let mut text = String::from("time_s,offset_s\n");
    let mut x = 0.0;
    for i in 0..30 * 144 {
        let t = 600.0 * i as f64;
        // 0.5 s/day of daily swing in the rate, white FM of 0.02 s/day.
        let rate = 0.5 * (std::f64::consts::TAU * t / 86_400.0).sin() + 0.02 * noise.next();
        x += rate * 600.0 / 86_400.0;
        text.push_str(&format!("{t},{x:.9}\n"));
    }
    let path = write(dir.path(), "daily.csv", &text);
    let plot = dir.path().join("daily.svg");
    let out = pendulum()
        .args(["stability", &path, "--plot", plot.to_str().unwrap()])
        .assert()
        .success()
        .get_output()
        .clone();
    let text = String::from_utf8(out.stdout).unwrap();
    let reasons: Vec<&str> = text
        .lines()
        .filter(|l| l.starts_with("No interval at"))
        .collect();
    assert_eq!(reasons.len(), 1, "{text}");
    assert_eq!(reasons[0].matches("periodic signal").count(), 1, "{text}");
    assert!(reasons[0].contains(" to "), "{text}");
    let svg = std::fs::read_to_string(&plot).unwrap();
    assert!(svg.contains("68% interval as a bar"), "legend");
    assert!(!svg.contains("interval, low"), "legend");
}

/// `log` ends in advice (issue 45, item 2): the rate at the log's end as
/// the move of the bob and the nut's turns, checked by hand: a simple
/// pendulum of length L gaining r s/day beats `1 + r/86,400` times too
/// often and T ∝ √L, so `ΔL = L ((1 + r/86,400)² − 1)` (about
/// `2 L r / 86,400`), the nut's turns that over its pitch; the direction from the sign (a gaining clock's bob goes down,
/// the nut anticlockwise seen from below). With no length the log's own
/// beat gives the simple pendulum `g (b/π)²`, said; with neither, no
/// advice and the text says what to give.
#[test]
fn a_log_ends_in_the_move_of_the_bob() {
    let dir = tempfile::tempdir().unwrap();
    let mut noise = Normal(0x5eed_0045);
    for (rate, length, pitch_mm) in [(-8.0, 1.2, 1.0), (5.0, 0.994, 0.5), (-0.9, 0.25, 0.7)] {
        // Thirty days of hourly rates, white noise of 0.3 s/day.
        let mut text = String::from("time_s,rate_s_per_day\n");
        for i in 0..720 {
            let r: f64 = rate + 0.3 * noise.next();
            text.push_str(&format!("{},{r:.4}\n", 3600 * i));
        }
        let path = write(dir.path(), "rates.csv", &text);
        let (l, p) = (format!("{length}m"), format!("{pitch_mm}mm"));
        let v = json(&["log", &path, "--length", &l, "--nut-pitch", &p]);
        let a = &v;
        let end = a["rate_at_end_s_per_day"].as_f64().unwrap();
        assert!((end - rate).abs() < 0.5, "{end} against {rate}");
        let advice = &a["advice"][0];
        assert_eq!(advice["code"], "regulate", "{advice}");
        let shift = (length * ((1.0 + end / 86_400.0).powi(2) - 1.0)).abs();
        let got = advice["bob_shift_m"].as_f64().unwrap();
        assert!((got / shift - 1.0).abs() < 1e-9, "{got} against {shift}");
        let turns = advice["nut_turns"].as_f64().unwrap();
        assert!((turns / (shift / (pitch_mm * 1e-3)) - 1.0).abs() < 1e-9);
        let (bob, nut) = if end > 0.0 {
            ("lower", "anticlockwise")
        } else {
            ("raise", "clockwise")
        };
        assert_eq!(advice["bob"], bob, "{advice}");
        assert_eq!(advice["nut_turn"], nut, "{advice}");
        assert_eq!(advice["length_from_beat"], false);
        // No length and no beat: no advice, and the text says so.
        let v = json(&["log", &path]);
        assert_eq!(v["advice"], serde_json::json!([]), "{v}");
        let said = crate::util::text(&["log", &path]);
        assert!(said.contains("give --length or --design"), "{said}");
    }
    // Half periods: the log's own beat, 1.0 s less a gain of 3 s/day.
    let mut text = String::from("time_s,half_period_s\n");
    let beat = 1.0 / (1.0 + 3.0 / 86_400.0);
    let mut t = 0.0;
    for _ in 0..20_000 {
        let b = beat + 2e-5 * noise.next();
        t += b;
        text.push_str(&format!("{t:.7},{b:.8}\n"));
    }
    let path = write(dir.path(), "halves.csv", &text);
    let v = json(&["log", &path, "--bph", "3600"]);
    let a = &v;
    let advice = &a["advice"][0];
    assert_eq!(advice["code"], "regulate", "{advice}");
    assert_eq!(advice["bob"], "lower");
    assert_eq!(advice["length_from_beat"], true);
    let b = a["beat_s"].as_f64().unwrap();
    let simple = 9.80665 * (b / std::f64::consts::PI).powi(2);
    assert!((advice["length_m"].as_f64().unwrap() / simple - 1.0).abs() < 1e-9);
    let end = a["rate_at_end_s_per_day"].as_f64().unwrap();
    assert!((end - 3.0).abs() < 0.3, "{end}");
}

/// A daily log read to the millisecond (eight readings of a clock gaining
/// 0.5 s/day, the last digit wandering by ±2 ms): most day-to-day steps
/// are equal, so the median of their deviations is nothing, and every
/// other step stood "infinitely" out: two of them were undone as whole
/// beats the reference slipped, the scatter went with them, and the rate
/// came out 0.502 ± 8e-17 s/day. The scale now falls back to the standard
/// deviation where the median's is below the readings' rounding: no jump,
/// and an error bar the size of the scatter (a least-squares line through
/// the readings: ± about 0.0005 s/day).
#[test]
fn a_daily_log_read_to_the_millisecond_keeps_its_scatter() {
    let dir = tempfile::tempdir().unwrap();
    let mut text = String::from("time_s,offset_s\n");
    for d in 0..8 {
        let wobble = 0.002 * ((d * 7) % 3) as f64 - 0.002;
        text.push_str(&format!("{},{:.4}\n", d * 86_400, 0.5 * d as f64 + wobble));
    }
    let path = write(dir.path(), "daily.csv", &text);
    let v = json(&["log", &path]);
    assert_eq!(v["wraps"], serde_json::json!([]), "{v}");
    let (rate, se) = (
        f(&v, "rate_s_per_day"),
        f(&v, "rate_standard_error_s_per_day"),
    );
    assert!(se > 1e-4 && se < 0.01, "{rate} ± {se}");
    assert!((rate - 0.5).abs() < 3.0 * se, "{rate} ± {se}");
}
