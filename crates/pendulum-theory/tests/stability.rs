//! The stability statistics against the published test of W. J. Riley:
//! the NBS14 10-point data set (phase and frequency) and its deviations at
//! τ = 1 and 2, as tabulated in NIST Special Publication 1065, *Handbook
//! of Frequency Stability Analysis* (2008), section 12.4 ("Validation"),
//! and in Riley, "The Calculation of Time Domain Frequency Stability"
//! (wriley.com/paper1ht.htm). Each value must agree to the table's printed
//! digits (half a unit of its last digit), from phase data and from the
//! frequency data alike.

use pendulum_theory::stability::{adev, hdev, mdev, oadev, ohdev, phase_from_frequency, tdev};

/// The NBS14 phase data (τ₀ = 1).
const PHASE: [f64; 10] = [
    0.00000, 103.11111, 123.22222, 157.33333, 166.44444, 48.55555, -96.33333, -2.22222, 111.88889,
    0.00000,
];

/// The same set as frequency data.
const FREQUENCY: [f64; 9] = [
    892.0, 809.0, 823.0, 798.0, 671.0, 644.0, 883.0, 903.0, 677.0,
];

type Statistic = fn(&[f64], f64, usize) -> Option<f64>;

/// (name, statistic, printed values at τ = 1 and 2).
const TABLE: [(&str, Statistic, [&str; 2]); 6] = [
    ("ADEV", adev, ["91.22945", "115.8082"]),
    ("OADEV", oadev, ["91.22945", "85.95287"]),
    ("MDEV", mdev, ["91.22945", "74.78849"]),
    ("TDEV", tdev, ["52.67135", "86.35831"]),
    // The table prints HDEV(1) as 70.80608 and OHDEV(1) as 70.80607; at
    // τ = τ₀ the two are one formula (every point is used either way), so
    // one of the printed values is rounded the other way: 70.806071 here,
    // and HDEV(1) = OHDEV(1) exactly (checked below).
    ("HDEV", hdev, ["70.80607", "116.7980"]),
    ("OHDEV", ohdev, ["70.80607", "85.61487"]),
];

/// Half a unit of the last printed digit of `printed`.
fn half_unit(printed: &str) -> f64 {
    let decimals = printed.split_once('.').map_or(0, |(_, d)| d.len());
    0.5 * 10f64.powi(-(decimals as i32))
}

#[test]
fn the_nbs14_table_to_its_printed_digits() {
    let from_frequency = phase_from_frequency(&FREQUENCY, 1.0);
    for (name, statistic, printed) in TABLE {
        for (m, text) in [1_usize, 2].into_iter().zip(printed) {
            let truth: f64 = text.parse().unwrap();
            for (data, x) in [("phase", &PHASE[..]), ("frequency", &from_frequency[..])] {
                let got = statistic(x, 1.0, m).unwrap_or(f64::NAN);
                assert!(
                    (got - truth).abs() <= half_unit(text),
                    "{name} at τ = {m} from {data}: {got}, table {text}"
                );
            }
        }
    }
}

/// At `τ = τ₀` the non-overlapping and overlapping estimators are one
/// formula.
#[test]
fn at_tau0_the_overlapping_estimators_are_the_plain_ones() {
    assert_eq!(hdev(&PHASE, 1.0, 1), ohdev(&PHASE, 1.0, 1));
    assert_eq!(adev(&PHASE, 1.0, 1), oadev(&PHASE, 1.0, 1));
    let (a, m) = (adev(&PHASE, 1.0, 1).unwrap(), mdev(&PHASE, 1.0, 1).unwrap());
    assert!((a / m - 1.0).abs() < 1e-14, "{a} {m}");
}

/// Too short a series has no statistic, and a bad τ₀ none either.
#[test]
fn too_few_points_give_none() {
    assert!(oadev(&PHASE[..4], 1.0, 2).is_none());
    assert!(ohdev(&PHASE[..6], 1.0, 2).is_none());
    assert!(mdev(&PHASE[..5], 1.0, 2).is_none());
    assert!(adev(&PHASE, 0.0, 1).is_none());
    assert!(adev(&PHASE, 1.0, 0).is_none());
    assert!(hdev(&PHASE[..3], 1.0, 1).is_none());
}

/// The statistics scale as they must: phase in other units scales them
/// alike, τ₀ scales σ_y as 1/τ₀ and leaves the time deviation alone, and
/// a frequency offset (a line in the phase) leaves every one unchanged.
#[test]
fn scalings_and_a_frequency_offset() {
    let scaled: Vec<f64> = PHASE.iter().map(|x| 1e-9 * x).collect();
    let drifted: Vec<f64> = PHASE
        .iter()
        .enumerate()
        .map(|(i, x)| x + 3.7 * i as f64)
        .collect();
    for (name, statistic, _) in TABLE {
        let base = statistic(&PHASE, 1.0, 1).unwrap();
        let small = statistic(&scaled, 1.0, 1).unwrap();
        assert!((small / base - 1e-9).abs() < 1e-20, "{name}");
        let slow = statistic(&PHASE, 10.0, 1).unwrap();
        let expected = if name == "TDEV" { base } else { base / 10.0 };
        assert!((slow / expected - 1.0).abs() < 1e-12, "{name}");
        let with_offset = statistic(&drifted, 1.0, 1).unwrap();
        assert!((with_offset / base - 1.0).abs() < 1e-12, "{name}");
    }
}

/// Seeded white phase, white frequency, flicker frequency and random-walk
/// frequency series (1,000 points each), and every statistic at octave
/// averaging factors as allantools 2024.06 computes it
/// (`tools/reference/stability.py`): equal to 1e-10 relative.
#[test]
fn four_noise_types_as_allantools_computes_them() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/stability");
    let mut checked = 0;
    for noise in ["white_pm", "white_fm", "flicker_fm", "random_walk_fm"] {
        let x: Vec<f64> = std::fs::read_to_string(dir.join(format!("{noise}.csv")))
            .unwrap()
            .lines()
            .skip(1)
            .map(|l| l.parse().unwrap())
            .collect();
        let devs = std::fs::read_to_string(dir.join(format!("{noise}_devs.csv"))).unwrap();
        for line in devs.lines().skip(1) {
            let cells: Vec<&str> = line.split(',').collect();
            let (name, m, truth): (&str, usize, f64) = (
                cells[0],
                cells[1].parse().unwrap(),
                cells[2].parse().unwrap(),
            );
            let statistic: Statistic = match name {
                "adev" => adev,
                "oadev" => oadev,
                "mdev" => mdev,
                "tdev" => tdev,
                "hdev" => hdev,
                "ohdev" => ohdev,
                other => panic!("unknown statistic {other}"),
            };
            let got = statistic(&x, 1.0, m).unwrap_or(f64::NAN);
            assert!(
                (got / truth - 1.0).abs() < 1e-10,
                "{noise} {name} m = {m}: {got}, allantools {truth}"
            );
            checked += 1;
        }
    }
    assert!(checked >= 4 * 6 * 7, "only {checked} values checked");
}
