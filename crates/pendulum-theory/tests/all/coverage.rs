//! Issue 23's acceptance for the trajectory fit: over seeded records made
//! by a generator that varies what real records vary
//! (`common/records.rs`), every fit either reports g, Q and the first
//! crest's amplitude with 1σ intervals that cover the truth 55-80% of the
//! time, or refuses or warns; and never a figure more than 5 standard
//! errors from the truth without a warning. CI runs a fixed subset of
//! 20 short records; `cargo test --release -p pendulum-theory --test all coverage:: -- --ignored`
//! runs the 200.

use crate::common;

use common::records::{record, Record};
use pendulum_theory::analysis::Refusal;
use pendulum_theory::fitting::tracked::{analyse, LengthSource, Track, TrackInput};

/// How one record's fit went (the fields only Debug reads are shown in
/// the log).
#[derive(Debug)]
enum Outcome {
    Refused(#[allow(dead_code)] String),
    Warned(#[allow(dead_code)] Vec<&'static str>),
    /// The law fitted and the standardised errors `(estimate - truth) / σ`
    /// by name.
    Reported(#[allow(dead_code)] &'static str, Vec<(&'static str, f64)>),
}

/// The library's analysis of a record, with its length given.
fn fit(rec: &Record) -> Result<Track, Refusal> {
    analyse(&TrackInput {
        time: &rec.time,
        angle: &rec.angle,
        model: None,
        drag_law: None,
        length: Some((rec.truth.length_m, LengthSource::Given)),
        length_standard_error: None,
        force: true,
        angle_from_positions: false,
        declared_degrees: false,
        angular_velocity: &[],
    })
}

fn judge(rec: &Record) -> Outcome {
    let t = &rec.truth;
    let r = match fit(rec) {
        Ok(r) => r,
        Err(e) => return Outcome::Refused(e.to_string()),
    };
    // A Q the data cannot measure is said (zeta_undetermined); the other
    // figures still stand.
    let blocking: Vec<&'static str> = r
        .warning_codes
        .iter()
        .copied()
        .filter(|c| *c != "zeta_undetermined")
        .collect();
    if !blocking.is_empty() {
        return Outcome::Warned(blocking);
    }
    let z = |name: &str, truth: f64| {
        let (v, se) = (r.parameters.get(name)?, r.standard_errors.get(name)?);
        Some((v - truth) / se)
    };
    let mut out = Vec::new();
    if let Some(x) = z("g_m_s2", t.g) {
        out.push(("g", x));
    }
    if let Some(x) = z("first_crest_amplitude_rad", t.first_crest_rad) {
        out.push(("first_crest", x));
    }
    if t.viscous_only() && !r.warning_codes.contains(&"zeta_undetermined") {
        if let Some(x) = z("zeta", 0.5 / t.q) {
            out.push(("q", x));
        }
    }
    Outcome::Reported(r.damping_law, out)
}

/// What a record varies, in a line.
fn describe(rec: &Record) -> String {
    let t = &rec.truth;
    format!(
        "{:.0}° Q {:.0} friction {:.1e} drag {:.1e} {:.0} fps {} samples noise {:.2}° held {}",
        t.release_rad.to_degrees(),
        t.q,
        t.friction_rad,
        t.quadratic,
        t.frame_rate,
        rec.time.len(),
        t.noise_rad.to_degrees(),
        t.held_frames
    )
}

struct Tally {
    within: std::collections::BTreeMap<&'static str, (usize, usize)>,
    far: Vec<String>,
    refused: usize,
    warned: usize,
}

fn run(seeds: impl Iterator<Item = u64>, small: bool) -> Tally {
    let mut tally = Tally {
        within: Default::default(),
        far: Vec::new(),
        refused: 0,
        warned: 0,
    };
    // The records are judged on every core, each printed as it finishes
    // (the 200 take most of an hour of CPU), then tallied in seed order.
    let seeds: Vec<u64> = seeds.collect();
    let next = std::sync::atomic::AtomicUsize::new(0);
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let mut done: Vec<(u64, String, Outcome)> = std::thread::scope(|s| {
        let workers: Vec<_> = (0..threads)
            .map(|_| {
                s.spawn(|| {
                    let mut mine = Vec::new();
                    loop {
                        let i = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                        let Some(&seed) = seeds.get(i) else { break };
                        let rec = record(seed, small);
                        let clock = std::time::Instant::now();
                        let outcome = judge(&rec);
                        let took = clock.elapsed().as_secs_f64();
                        let line =
                            format!("seed {seed} ({took:.1} s): {}: {outcome:?}", describe(&rec));
                        eprintln!("{line}");
                        mine.push((seed, line, outcome));
                    }
                    mine
                })
            })
            .collect();
        workers
            .into_iter()
            .flat_map(|w| w.join().expect("a coverage worker panicked"))
            .collect()
    });
    done.sort_by_key(|d| d.0);
    for (_, line, outcome) in done {
        match &outcome {
            Outcome::Refused(_) => tally.refused += 1,
            Outcome::Warned(_) => tally.warned += 1,
            Outcome::Reported(_, z) => {
                for (name, x) in z {
                    let e = tally.within.entry(name).or_default();
                    e.1 += 1;
                    if x.abs() <= 1.0 {
                        e.0 += 1;
                    }
                    if x.abs() > 5.0 || !x.is_finite() {
                        tally.far.push(format!("{name} {x:.1}σ: {line}"));
                    }
                }
            }
        }
    }
    tally
}

fn check(tally: &Tally, band: bool) {
    eprintln!(
        "refused {}, warned {}; 1σ coverage: {:?}",
        tally.refused, tally.warned, tally.within
    );
    assert!(
        tally.far.is_empty(),
        "beyond 5σ without a warning:\n{}",
        tally.far.join("\n")
    );
    for (name, (inside, all)) in &tally.within {
        let (k, n) = (*inside as f64, *all as f64);
        if band {
            // The 200: the band.
            assert!(
                (0.55..=0.8).contains(&(k / n)),
                "{name}: {inside} of {all} within 1σ"
            );
        } else {
            // A subset of a few dozen cannot hold a band 25 points wide:
            // its count must be what a 68.3% coverage gives (two-sided
            // binomial at 1%, normal approximation with continuity).
            let p = 0.6827;
            let z = ((k - n * p).abs() - 0.5) / (n * p * (1.0 - p)).sqrt();
            assert!(
                z < 2.576,
                "{name}: {inside} of {all} within 1σ (z = {z:.2})"
            );
        }
    }
}

/// CI's sample: 20 short records (some 45 CPU-seconds; the 200 are run
/// before a release, `coverage_200` below, about an hour of CPU).
#[test]
fn coverage_ci_subset() {
    check(&run(0..20, true), false);
}

/// Records of the 200 whose damping law was once chosen wrong, beyond 5σ
/// without a warning: 1007 (51°, Q 1325 with dry friction: drag fitted in
/// place of the viscous part, the first crest 6.8σ off) and 1008 (13°,
/// Q 322 with friction: the fit of both laws did not settle, friction was
/// missed, g -7.7σ and the first crest +31σ); and 1106, which a first
/// mend of 1008 broke. Each is now reported, every figure within 5σ.
#[test]
fn records_whose_damping_law_was_missed() {
    let tally = run([1007, 1008, 1106].into_iter(), false);
    assert_eq!((tally.refused, tally.warned), (0, 0));
    assert!(tally.far.is_empty(), "{:#?}", tally.far);
}

#[test]
#[ignore = "the 200 records of issue 23 (several minutes): cargo test --release -p pendulum-theory --test all coverage:: -- --ignored"]
fn coverage_200() {
    check(&run(1000..1200, false), true);
}

/// The records named in `COVERAGE_SEEDS` (comma-separated; of the 200
/// unless `COVERAGE_SMALL` is set), judged and printed: for looking into
/// one record.
#[test]
#[ignore = "looks into the seeds in COVERAGE_SEEDS"]
fn coverage_seeds() {
    let seeds: Vec<u64> = std::env::var("COVERAGE_SEEDS")
        .unwrap_or_default()
        .split(',')
        .filter_map(|s| s.trim().parse().ok())
        .collect();
    let small = std::env::var("COVERAGE_SMALL").is_ok();
    for &seed in &seeds {
        let rec = record(seed, small);
        let t = &rec.truth;
        eprintln!("seed {seed}: {}", describe(&rec));
        // COVERAGE_DUMP=DIR writes the record as DIR/seed-N.csv, to run
        // through the binary.
        if let Ok(dir) = std::env::var("COVERAGE_DUMP") {
            let mut text = String::from("time_s,angle_rad\n");
            for (t, a) in rec.time.iter().zip(&rec.angle) {
                text.push_str(&format!("{t},{a}\n"));
            }
            std::fs::write(format!("{dir}/seed-{seed}.csv"), text).unwrap();
        }
        if std::env::var("COVERAGE_DESCRIBE").is_ok() {
            continue;
        }
        if let Ok(r) = fit(&rec) {
            let first: Vec<String> = rec
                .angle
                .iter()
                .take(6)
                .map(|a| format!("{a:.4}"))
                .collect();
            eprintln!(
                "seed {seed}: truth crest {:.5} release {:.5}; fit {:?} ± {:?}; held {}; first angles {first:?}; dt {:.4}",
                t.first_crest_rad,
                t.release_rad,
                r.parameters,
                r.standard_errors,
                r.held_samples,
                rec.time[1] - rec.time[0]
            );
        }
    }
    if std::env::var("COVERAGE_DESCRIBE").is_ok() {
        return;
    }
    let tally = run(seeds.into_iter(), small);
    eprintln!("beyond 5σ: {:#?}", tally.far);
}
