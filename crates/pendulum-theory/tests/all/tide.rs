//! The body tide against ETERNA's PREDICT (Wenzel 1996), run through
//! PyGTide 0.9.7 with the KSM03 catalogue and the Wahr–Dehant–Zschau
//! gravimetric factors, no ocean loading (`tools/reference/tides.py`):
//! hourly over January 2026 at the Black Forest Observatory and at
//! Sutherland, the RMS difference below 3 nm/s² (0.3 µGal).

use pendulum_theory::tide::{gravity_change, rate_s_per_day, Station};

/// (Unix time, ETERNA's gravity in nm/s², positive when g increases).
fn reference(name: &str) -> (Station, Vec<f64>, Vec<f64>) {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/tides")
        .join(name);
    let text = std::fs::read_to_string(path).unwrap();
    let station_line = text.lines().next().unwrap();
    let words: Vec<&str> = station_line
        .split("station ")
        .nth(1)
        .unwrap()
        .split_whitespace()
        .collect();
    let station = Station {
        latitude_deg: words[0].parse().unwrap(),
        longitude_deg: words[1].parse().unwrap(),
        height_m: words[2].parse().unwrap(),
    };
    let (mut times, mut values) = (Vec::new(), Vec::new());
    for line in text.lines().skip(2) {
        let (time, value) = line.split_once(',').unwrap();
        // 2026-01-DDTHH:00:00Z, January 2026 and 2026-02-01.
        let day: f64 = time[8..10].parse().unwrap();
        let hour: f64 = time[11..13].parse().unwrap();
        let month_start = if &time[5..7] == "02" { 31.0 } else { 0.0 };
        let jan1_2026 = 1_767_225_600.0;
        times.push(jan1_2026 + (month_start + day - 1.0) * 86_400.0 + hour * 3600.0);
        values.push(value.parse::<f64>().unwrap());
    }
    (station, times, values)
}

#[test]
fn a_month_hourly_at_two_stations_within_3_nm_s2_of_eterna() {
    for name in ["bfo.csv", "sutherland.csv"] {
        let (station, times, eterna) = reference(name);
        assert_eq!(times.len(), 745, "{name}");
        let ours = gravity_change(station, &times).unwrap();
        let diff: Vec<f64> = ours.iter().zip(&eterna).map(|(o, e)| o * 1e9 - e).collect();
        let rms = (diff.iter().map(|d| d * d).sum::<f64>() / diff.len() as f64).sqrt();
        let max = diff.iter().fold(0.0f64, |m, d| m.max(d.abs()));
        let range = eterna.iter().fold(f64::MIN, |m, v| m.max(*v))
            - eterna.iter().fold(f64::MAX, |m, v| m.min(*v));
        println!("{name}: RMS {rms:.3} nm/s², max {max:.3}, range {range:.1}");
        assert!(
            rms < 3.0,
            "{name}: RMS {rms} nm/s² against ETERNA (max {max})"
        );
    }
}

/// The pendulum's rate is Δg/2g of a day: ±1000 nm/s² is ±4.4 ms/day.
#[test]
fn the_rate_is_half_the_fractional_change_of_g() {
    let r = rate_s_per_day(1e-6, 9.81);
    assert!((r - 1e-6 / 9.81 / 2.0 * 86_400.0).abs() < 1e-18);
}

/// Times far apart need the ephemeris about each, not every knot between
/// them (two times 200 years apart made 584,000 knots, 79 s): a time's
/// tide with a companion two centuries off is its tide alone, to the
/// rounding of its place on the knots' grid.
#[test]
fn times_centuries_apart_are_each_their_own_tide() {
    let station = Station {
        latitude_deg: 48.33,
        longitude_deg: 8.33,
        height_m: 589.0,
    };
    let t = 1_767_225_600.0 + 12_345.6;
    let alone = gravity_change(station, &[t]).unwrap()[0];
    for far in [-2_208_988_800.0, 4_102_444_800.0] {
        let both = gravity_change(station, &[far, t]).unwrap();
        assert!(
            (both[1] - alone).abs() < 1e-18,
            "{} against {alone}",
            both[1]
        );
        assert!(both[0].is_finite() && both[0].abs() < 3e-6);
    }
}

/// The work of a tide's times is judged before any is computed: ten
/// million need forcing (they ran 50 s unasked), as do a few hundred a
/// month apart over decades (each month's K1 means are 183 days of both
/// bodies); a table every hour for a month does not.
#[test]
fn the_work_of_many_times_or_many_months_needs_forcing() {
    use pendulum_theory::tide::{at, series, work_seconds};
    let station = Station {
        latitude_deg: 48.33,
        longitude_deg: 8.33,
        height_m: 0.0,
    };
    let start = 1_767_225_600.0;
    let many: Vec<f64> = (0..10_000_000).map(|k| start + f64::from(k)).collect();
    let refused = at(station, &many, false).unwrap_err().to_string();
    assert!(
        refused.starts_with("time: 10000000 times over 116 days: about "),
        "{refused}"
    );
    assert!(refused.contains("force it"), "{refused}");
    let decades = series(station, -2e9, 4e9, 40.0 * 86_400.0, false).unwrap_err();
    let decades = decades.to_string();
    assert!(
        decades.starts_with("every: 1737 times over 69440 days"),
        "{decades}"
    );
    assert!(decades.contains("force it"), "{decades}");
    assert!(work_seconds(745.0, 31.0 * 86_400.0) < 1.0);
    assert_eq!(
        series(station, start, start + 31.0 * 86_400.0, 3600.0, false)
            .unwrap()
            .len(),
        745
    );
    let too_many = series(station, start, start + 86_400.0 * 365.0, 1.0, true).unwrap_err();
    assert!(
        too_many
            .to_string()
            .contains("more than the 10000000 a table may have"),
        "{too_many}"
    );
}
