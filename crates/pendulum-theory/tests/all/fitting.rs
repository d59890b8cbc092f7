//! Fits recover known parameters from synthetic data made by the library's
//! own models with seeded Gaussian noise: within 3 standard errors, with a
//! 1-sigma coverage near 68% over 100 seeds, and the right model chosen.

use pendulum_theory::fitting::beats::analyse_beats;
use pendulum_theory::fitting::decay::{fit_decay, preferred, DecayModel};

/// splitmix64 and Box-Muller: a small, seeded Gaussian source.
struct Noise(u64);

impl Noise {
    fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    fn uniform(&mut self) -> f64 {
        ((self.next_u64() >> 11) as f64 + 0.5) / (1u64 << 53) as f64
    }
    fn gaussian(&mut self) -> f64 {
        let (u, v) = (self.uniform(), self.uniform());
        (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos()
    }
}

const SIGMA: f64 = 1e-4; // rad, about 0.006°: a good optical amplitude reader

fn truth(model: DecayModel) -> Vec<f64> {
    match model {
        DecayModel::Viscous => vec![0.05, 5e-4],
        DecayModel::Coulomb => vec![0.05, 1.5e-5],
        DecayModel::Quadratic => vec![0.05, 0.02],
        DecayModel::ViscousCoulomb => vec![0.05, 3e-4, 8e-6],
        // A pendulum in air: drag about as strong as the viscous part at A0.
        DecayModel::ViscousQuadratic => vec![0.05, 3e-4, 0.01],
        // Dry friction and drag, no viscous part: the air pendulums of
        // issue 23 whose full fit put the viscous rate at 0.
        DecayModel::CoulombQuadratic => vec![0.05, 8e-6, 0.02],
        DecayModel::Full => vec![0.05, 3e-4, 5e-6, 0.01],
        // Another drag law of the list: its rate κ (in its own unit) makes
        // about the decay the quadratic one's does at A0.
        DecayModel::Drag {
            viscous, coulomb, ..
        } => {
            let mut p = vec![0.05];
            p.extend(viscous.then_some(3e-4));
            p.extend(coulomb.then_some(5e-6));
            p.push(0.01 * 0.05f64.powf(2.0 - model.power()));
            p
        }
    }
}

fn synthetic(model: DecayModel, seed: u64) -> (Vec<f64>, Vec<f64>) {
    let mut noise = Noise(seed);
    let p = truth(model);
    let t: Vec<f64> = (0..100).map(|i| f64::from(i) * 20.0).collect();
    let a = t
        .iter()
        .map(|&x| model.amplitude(x, &p) + SIGMA * noise.gaussian())
        .collect();
    (t, a)
}

#[test]
fn each_fit_recovers_its_parameters_within_three_sigma() {
    for model in DecayModel::every() {
        let (t, a) = synthetic(model, 1);
        let fit = fit_decay(model, &t, &a, Some(std::f64::consts::PI)).unwrap();
        for (j, want) in truth(model).iter().enumerate() {
            let (got, se) = (fit.fit.parameters[j], fit.fit.standard_errors[j]);
            assert!(
                (got - want).abs() <= 3.0 * se,
                "{} p{j}: {got} ± {se} vs {want}",
                model.name()
            );
        }
        // The residuals are the noise.
        assert!(
            (fit.fit.residual_rms / SIGMA - 1.0).abs() < 0.25,
            "{}",
            fit.fit.residual_rms
        );
    }
}

#[test]
fn one_sigma_coverage_over_100_seeds() {
    for model in DecayModel::every() {
        let p = truth(model);
        let mut covered = vec![0; p.len()];
        for seed in 0..100 {
            let (t, a) = synthetic(model, 1000 + seed);
            let fit = fit_decay(model, &t, &a, None).unwrap();
            for (j, want) in p.iter().enumerate() {
                if (fit.fit.parameters[j] - want).abs() <= fit.fit.standard_errors[j] {
                    covered[j] += 1;
                }
            }
        }
        eprintln!("{}: 1-sigma coverage {covered:?} of 100", model.name());
        for c in covered {
            assert!((55..=80).contains(&c), "{}: coverage {c}", model.name());
        }
    }
}

/// Data from a law without some damping: the laws that have it put it at
/// its bound 0 or within two standard errors of 0, never negative, and a
/// fit with a rate at its bound is never preferred.
#[test]
fn absent_damping_is_never_negative_nor_preferred_at_its_bound() {
    for generator in [
        DecayModel::Viscous,
        DecayModel::Quadratic,
        DecayModel::ViscousQuadratic,
    ] {
        let (mut at_bound, mut checked, mut beyond) = (0, 0, 0);
        for seed in 0..20 {
            let (t, a) = synthetic(generator, 7000 + seed);
            let fits: Vec<_> = DecayModel::ALL
                .iter()
                .filter_map(|&m| fit_decay(m, &t, &a, Some(3.0)).ok())
                .collect();
            for f in &fits {
                for e in &f.parameters {
                    assert!(
                        e.value >= 0.0 || e.name == "amplitude0_rad",
                        "{} from {}: {} = {}",
                        f.model.name(),
                        generator.name(),
                        e.name,
                        e.value
                    );
                }
                at_bound += usize::from(!f.at_bound.is_empty());
                // Only a law that nests the generator's can say a rate is absent.
                let nests = generator
                    .rate_names()
                    .iter()
                    .all(|r| f.model.rate_names().contains(r));
                if !nests {
                    continue;
                }
                // A rate the generator lacks: at 0, or within 2σ of it.
                for (rate, present) in [
                    (
                        "decay_rate_per_s",
                        generator.rate_names().contains(&"decay_rate_per_s"),
                    ),
                    (
                        "amplitude_fall_rad_per_s",
                        generator.rate_names().contains(&"amplitude_fall_rad_per_s"),
                    ),
                    (
                        "quadratic_decay_per_rad_s",
                        generator
                            .rate_names()
                            .contains(&"quadratic_decay_per_rad_s"),
                    ),
                ] {
                    if present {
                        continue;
                    }
                    if let Some(e) = f.parameters.iter().find(|e| e.name == rate) {
                        checked += 1;
                        if !(e.value == 0.0 || e.value <= 2.0 * e.standard_error) {
                            beyond += 1;
                            eprintln!(
                                "{} from {}: {rate} = {} ± {}",
                                f.model.name(),
                                generator.name(),
                                e.value,
                                e.standard_error
                            );
                        }
                    }
                }
            }
            let best = preferred(&fits).unwrap();
            let chosen = fits.iter().find(|f| f.model == best).unwrap();
            assert!(chosen.at_bound.is_empty());
        }
        eprintln!(
            "{}: {at_bound} fits with a rate at its bound; absent rates beyond 2σ: {beyond} of {checked}",
            generator.name()
        );
        // A true zero is beyond 2σ in about 2.3% of fits (a one-sided
        // Gaussian tail; the bound takes the other half): allow up to 10%.
        assert!(beyond * 10 <= checked, "{beyond} of {checked} beyond 2σ");
    }
}

/// A wide swing in air with no viscous part (as in a student's 83° video
/// record: 19 turning points, pure drag): every law fits, none fails; the
/// combined laws put the absent rates at their bound.
#[test]
fn pure_drag_at_large_amplitude_fits_every_law() {
    let mut noise = Noise(83);
    let t: Vec<f64> = (0..19).map(|i| f64::from(i) * 0.889).collect();
    let a: Vec<f64> = t
        .iter()
        .map(|&x| DecayModel::Quadratic.amplitude(x, &[1.44, 0.0267]) + 0.005 * noise.gaussian())
        .collect();
    for model in DecayModel::ALL {
        let fit = fit_decay(model, &t, &a, Some(3.5));
        assert!(fit.is_ok(), "{}: {:?}", model.name(), fit.err());
    }
    let vq = fit_decay(DecayModel::ViscousQuadratic, &t, &a, Some(3.5)).unwrap();
    let kappa = vq.fit.parameters[2];
    assert!(
        (kappa - 0.0267).abs() < 3.0 * vq.fit.standard_errors[2].max(1e-4),
        "{kappa}"
    );
}

#[test]
fn model_selection_picks_the_generating_model() {
    for model in [
        DecayModel::Viscous,
        DecayModel::Coulomb,
        DecayModel::ViscousCoulomb,
        DecayModel::ViscousQuadratic,
    ] {
        let mut right = 0;
        for seed in 0..20 {
            let (t, a) = synthetic(model, 5000 + seed);
            let fits: Vec<_> = DecayModel::ALL
                .iter()
                .filter_map(|&m| fit_decay(m, &t, &a, None).ok())
                .collect();
            if preferred(&fits) == Some(model) {
                right += 1;
            }
        }
        eprintln!("{}: chosen in {right} of 20", model.name());
        assert!(
            right >= 18,
            "{}: chosen in only {right} of 20",
            model.name()
        );
    }
}

/// The 3/2-power drag law, fitted: a 2° run-down of a 0.994 m pendulum
/// simulated by DOP853 with the law's own force (`k = 3e-4 rad^-1/2
/// s^-1/2`) and a little viscous damping (ζ = 2e-5), its turning points
/// read with 1e-5 rad of noise: `viscous+three_halves` gives back `k` and
/// ζ within three standard errors, and the information criterion prefers
/// it to every law the fit tries unnamed (the quadratic ones among them).
#[test]
fn the_three_halves_law_is_fitted_from_a_simulated_run_down() {
    use pendulum_theory::fitting::decay::effective_angular_frequency;
    use pendulum_theory::simulation::forces::drag_law;
    use pendulum_theory::simulation::TurningPoint;
    use pendulum_theory::simulation::{simulate, Action, Method, Model, Observer, Options};
    use pendulum_theory::{damping::Damping, Amplitude, Pendulum};
    struct Turns(Vec<(f64, f64)>);
    impl Observer for Turns {
        fn turning_point(&mut self, p: &TurningPoint) -> Action {
            self.0.push((p.time, p.angle.abs()));
            Action::Continue
        }
    }
    let (k, zeta) = (3e-4, 2e-5);
    let pendulum = Pendulum::with_standard_gravity(0.99362).unwrap();
    let law = drag_law("three_halves_drag").unwrap();
    let model = Model::new(pendulum, Damping::from_zeta(zeta).unwrap(), 0.0, 0.0)
        .unwrap()
        .with_drag(law, k)
        .unwrap();
    let options = Options {
        duration: 3000.0,
        tolerance: 1e-11,
        method: Method::Dop853,
        sample_interval: None,
    };
    let mut turns = Turns(Vec::new());
    simulate(
        &model,
        Amplitude::from_degrees(2.0).unwrap(),
        &options,
        &mut turns,
    )
    .unwrap();
    let mut noise = Noise(32);
    let (t, a): (Vec<f64>, Vec<f64>) = turns
        .0
        .iter()
        .map(|&(t, a)| (t, a + 1e-5 * noise.gaussian()))
        .unzip();
    let omega = effective_angular_frequency(&pendulum, &a);
    let named = DecayModel::from_name("viscous+three_halves").unwrap();
    let fit = fit_decay(named, &t, &a, Some(omega)).unwrap();
    let estimate = |name: &str| {
        let e = fit.parameters.iter().find(|e| e.name == name).unwrap();
        (e.value, e.standard_error)
    };
    let (k_fit, k_se) = estimate("three_halves_drag");
    assert!(
        (k_fit - k).abs() <= 3.0 * k_se && k_se < 0.05 * k,
        "k {k_fit} ± {k_se}"
    );
    let (z_fit, z_se) = estimate("zeta");
    assert!((z_fit - zeta).abs() <= 3.0 * z_se, "ζ {z_fit} ± {z_se}");
    let mut fits: Vec<_> = DecayModel::searched()
        .into_iter()
        .filter_map(|m| fit_decay(m, &t, &a, Some(omega)).ok())
        .collect();
    fits.push(fit);
    let best = preferred(&fits).map(DecayModel::name);
    assert_eq!(best, Some("viscous+three_halves"), "{}", {
        let bics: Vec<String> = fits
            .iter()
            .map(|f| format!("{} {:.1}", f.model.name(), f.fit.bic))
            .collect();
        bics.join(", ")
    });
}

#[test]
fn beats_with_jitter_recover_rate_and_beat_error() {
    let mut noise = Noise(7);
    let beat = 1.0 / (1.0 + 5.0 / 86_400.0); // 5 s/day fast
    let mut t = vec![0.0];
    for i in 1..20_000 {
        let tick = if i % 2 == 1 { 0.0015 } else { -0.0015 };
        t.push(
            i as f64 * beat
                + tick / 2.0 * if i % 2 == 1 { 1.0 } else { 0.0 }
                + 2e-4 * noise.gaussian(),
        );
    }
    let a = analyse_beats(&t, None).unwrap();
    assert_eq!(a.nominal_beat, Some(1.0));
    assert!(
        (a.rate_s_per_day.unwrap() - 5.0).abs() < 0.05,
        "{:?}",
        a.rate_s_per_day
    );
    assert!((a.beat_error_ms - 0.75).abs() < 0.05, "{}", a.beat_error_ms);
    assert!(
        (a.jitter_ms / (2e-4 * 2f64.sqrt() * 1e3) - 1.0).abs() < 0.1,
        "{}",
        a.jitter_ms
    );
}

mod trajectory {
    use super::Noise;
    use pendulum_theory::damped::DampedPendulum;
    use pendulum_theory::damping::Damping;
    use pendulum_theory::fitting::trajectory::{fit_trajectory, TrajectoryModel};
    use pendulum_theory::simulation::{simulate, Method, Model, Observer, Options};
    use pendulum_theory::{Amplitude, Pendulum};

    const NOISE: f64 = 2e-3; // rad: a tracked video at a few pixels' precision
    const OFFSET: f64 = 0.01;

    /// 10 s at 100 frames a second of section 1-4's motion, released at
    /// 0.1 rad, offset by 0.01 rad, with noise.
    fn linear_data(seed: u64) -> (Vec<f64>, Vec<f64>, DampedPendulum) {
        let pendulum = Pendulum::with_standard_gravity(0.5).unwrap();
        let p = DampedPendulum::new(pendulum, Damping::from_zeta(0.005).unwrap());
        let mut noise = Noise(seed);
        let t: Vec<f64> = (0..1000).map(|i| f64::from(i) * 0.01).collect();
        let theta = t
            .iter()
            .map(|&x| p.state_at(0.1, 0.0, x).angle + OFFSET + NOISE * noise.gaussian())
            .collect();
        (t, theta, p)
    }

    /// From rest at A0 the seed's form is `A0 e^{-ζωt} cos(ω_d t - φ) / sqrt(1 - ζ²)`:
    /// envelope `A0/sqrt(1 - ζ²)` and phase `-φ` in the fit's parameters.
    fn linear_truth(p: &DampedPendulum) -> [f64; 5] {
        let zeta = p.damping.zeta();
        [
            0.1 / (1.0 - zeta * zeta).sqrt(),
            p.damped_angular_frequency().unwrap(),
            zeta,
            -p.phase().unwrap(),
            OFFSET,
        ]
    }

    #[test]
    fn linear_fit_recovers_the_motion() {
        let (t, theta, p) = linear_data(3);
        let fit = fit_trajectory(TrajectoryModel::Linear, &t, &theta).unwrap();
        let truth = linear_truth(&p);
        for (j, want) in truth.iter().enumerate() {
            let (got, se) = (fit.fit.parameters[j], fit.fit.standard_errors[j]);
            assert!(
                (got - want).abs() <= 3.0 * se,
                "{}: {got} ± {se} vs {want}",
                fit.names()[j]
            );
        }
        // g from the length, corrected for damping and amplitude: within 3σ
        // of the truth up to the linear model's own error (A²/16 = 6e-4).
        let (g, se) = fit.gravity(0.5);
        assert!(
            (g - 9.80665).abs() <= 3.0 * se + 9.80665 * 1e-3,
            "{g} ± {se}"
        );
    }

    #[test]
    fn linear_fit_coverage_over_100_seeds() {
        let (_, _, p) = linear_data(0);
        let truth = linear_truth(&p);
        let mut covered = [0; 5];
        for seed in 0..100 {
            let (t, theta, _) = linear_data(100 + seed);
            let fit = fit_trajectory(TrajectoryModel::Linear, &t, &theta).unwrap();
            for (j, want) in truth.iter().enumerate() {
                if (fit.fit.parameters[j] - want).abs() <= fit.fit.standard_errors[j] {
                    covered[j] += 1;
                }
            }
        }
        eprintln!("trajectory 1-sigma coverage {covered:?} of 100");
        for c in covered {
            assert!((55..=80).contains(&c), "coverage {c}");
        }
    }

    struct Collect(Vec<f64>);
    impl Observer for Collect {
        fn sample(&mut self, _t: f64, s: &pendulum_theory::damped::State) -> bool {
            self.0.push(s.angle);
            true
        }
    }

    /// The 3/2-power drag law in the trajectory fit, from the same list
    /// as the simulation: a 40° swing of a 0.5 m pendulum simulated with
    /// that law's force (k = 0.02 rad^-1/2 s^-1/2) and a little viscous
    /// damping, 40 s at 50 frames a second with 2e-3 rad of noise, fitted
    /// with the law named: the fit keeps it beside the viscous part, `k`
    /// and ζ within three standard errors.
    #[test]
    fn the_three_halves_law_is_fitted_to_a_trajectory() {
        use pendulum_theory::fitting::trajectory::{fit_observed_with, Observed};
        use pendulum_theory::simulation::forces::drag_law;
        let (k, zeta) = (0.02, 2e-4);
        let law = drag_law("three_halves_drag").unwrap();
        let pendulum = Pendulum::with_standard_gravity(0.5).unwrap();
        let model = Model::new(pendulum, Damping::from_zeta(zeta).unwrap(), 0.0, 0.0)
            .unwrap()
            .with_drag(law, k)
            .unwrap();
        let options = Options {
            duration: 40.0,
            tolerance: 1e-12,
            method: Method::Dop853,
            sample_interval: Some(0.02),
        };
        let mut collect = Collect(Vec::new());
        let release = Amplitude::from_degrees(40.0).unwrap();
        simulate(&model, release, &options, &mut collect).unwrap();
        let mut noise = Noise(15);
        let t: Vec<f64> = (0..collect.0.len()).map(|i| i as f64 * 0.02).collect();
        let theta: Vec<f64> = collect
            .0
            .iter()
            .map(|a| a + NOISE * noise.gaussian())
            .collect();
        let named = fit_observed_with(
            TrajectoryModel::Nonlinear,
            &t,
            &theta,
            Observed::Angle,
            &[law],
        )
        .unwrap();
        assert_eq!(named.law.name(), "viscous+three_halves");
        assert_eq!(named.names()[5], "three_halves_drag");
        let (k_fit, k_se) = (named.fit.parameters[5], named.fit.standard_errors[5]);
        assert!(
            (k_fit - k).abs() <= 3.0 * k_se && k_se < 0.2 * k,
            "k {k_fit} ± {k_se}"
        );
        let (z_fit, z_se) = (named.fit.parameters[2], named.fit.standard_errors[2]);
        assert!((z_fit - zeta).abs() <= 3.0 * z_se, "ζ {z_fit} ± {z_se}");
        // (Unnamed, the search's viscous+quadratic fits such a record
        // about as well: BIC within 0.1 of the 3/2 law's on 20 s of it.
        // The look-alike is why the 3/2 law is fitted when named, not
        // searched.)
    }

    #[test]
    fn nonlinear_fit_of_a_wide_swing_finds_g() {
        // 40° swing: the linear model's frequency is off by A²/16 = 3%.
        let pendulum = Pendulum::with_standard_gravity(0.5).unwrap();
        let model = Model::new(pendulum, Damping::from_zeta(0.002).unwrap(), 0.0, 0.0).unwrap();
        let options = Options {
            duration: 8.0,
            tolerance: 1e-12,
            method: Method::Dop853,
            sample_interval: Some(0.01),
        };
        let mut collect = Collect(Vec::new());
        simulate(
            &model,
            Amplitude::from_degrees(40.0).unwrap(),
            &options,
            &mut collect,
        )
        .unwrap();
        let mut noise = Noise(11);
        // The record starts 0.3 s after the release.
        let t: Vec<f64> = (30..collect.0.len()).map(|i| i as f64 * 0.01).collect();
        let theta: Vec<f64> = (30..collect.0.len())
            .map(|i| collect.0[i] + NOISE * noise.gaussian())
            .collect();
        let fit = fit_trajectory(TrajectoryModel::Nonlinear, &t, &theta).unwrap();
        let (g, se) = fit.gravity(0.5);
        assert!((g - 9.80665).abs() <= 3.0 * se, "{g} ± {se}");
        assert!(se < 0.01, "{se}");
        let zeta = fit.fit.parameters[2];
        assert!(
            (zeta - 0.002).abs() <= 3.0 * fit.fit.standard_errors[2],
            "{zeta}"
        );
    }

    /// Issue 10's acceptance: 40° trajectories, 60 s at 60 frames a second,
    /// noise 0.002 rad, ζ = 0.002: g's 1-sigma interval covers the truth in
    /// 55-80% of 100 seeds for every model that reports g there (the
    /// nonlinear one; the CLI does not report the linear model's g above
    /// 5°). The record starts at a random point of the first swing, so the
    /// release phase varies as in real recordings. Each fit takes some 2
    /// CPU-seconds: CI runs the first 15 seeds (`g_coverage_ci_subset`),
    /// the 100 are run before a release with `-- --ignored`.
    #[test]
    #[ignore = "the 100 seeds of issue 10 (about 3 CPU-minutes): cargo test --release -p pendulum-theory --test all fitting:: -- --ignored"]
    fn nonlinear_g_coverage_over_100_seeds() {
        let (covered, phases_in_range) = g_coverage(0..100);
        assert!((55..=80).contains(&covered), "coverage {covered}");
        assert_eq!(phases_in_range, 100);
    }

    /// The first 15 of those seeds: a band 25 points wide is too narrow
    /// for 15, so the count must be what a 68.3% coverage gives (two-sided
    /// binomial at 1%, normal approximation with continuity), and every
    /// phase in its range.
    #[test]
    fn g_coverage_ci_subset() {
        let seeds = 15;
        let (covered, phases_in_range) = g_coverage(0..seeds);
        let (k, n, p) = (covered as f64, seeds as f64, 0.6827);
        let z = ((k - n * p).abs() - 0.5) / (n * p * (1.0 - p)).sqrt();
        assert!(z < 2.576, "coverage {covered} of {seeds} (z = {z:.2})");
        assert_eq!(phases_in_range, seeds as usize);
    }

    /// Of the seeds given: how many g intervals hold the truth, and how
    /// many phases fall in [-π/2, 2π).
    fn g_coverage(seeds: std::ops::Range<u64>) -> (usize, usize) {
        let pendulum = Pendulum::with_standard_gravity(0.5).unwrap();
        let model = Model::new(pendulum, Damping::from_zeta(0.002).unwrap(), 0.0, 0.0).unwrap();
        let options = Options {
            duration: 62.0,
            tolerance: 1e-13,
            method: Method::Dop853,
            sample_interval: Some(1.0 / 600.0),
        };
        let mut collect = Collect(Vec::new());
        simulate(
            &model,
            Amplitude::from_degrees(40.0).unwrap(),
            &options,
            &mut collect,
        )
        .unwrap();
        // The seeds in two halves on two threads (each fit is independent).
        let seeds: Vec<u64> = seeds.collect();
        let half = seeds.len().div_ceil(2).max(1);
        let samples = &collect.0;
        let (covered, phases_in_range) = std::thread::scope(|scope| {
            let halves: Vec<_> = seeds
                .chunks(half)
                .map(|chunk| {
                    scope.spawn(move || {
                        let (mut covered, mut phases_in_range) = (0, 0);
                        for &seed in chunk {
                            let mut noise = Noise(40_000 + seed);
                            // Start 0 to 1.4 s (one period) after the release, on the 600/s grid.
                            let start = (noise.uniform() * 840.0) as usize;
                            let idx: Vec<usize> = (0..3600).map(|k| start + 10 * k).collect();
                            let t: Vec<f64> =
                                idx.iter().map(|&i| (i - start) as f64 / 600.0).collect();
                            let theta: Vec<f64> = idx
                                .iter()
                                .map(|&i| samples[i] + NOISE * noise.gaussian())
                                .collect();
                            let fit =
                                fit_trajectory(TrajectoryModel::Nonlinear, &t, &theta).unwrap();
                            let (g, se) = fit.gravity(0.5);
                            if (g - 9.80665).abs() <= se {
                                covered += 1;
                            }
                            let phase = fit.fit.parameters[3];
                            let pi = std::f64::consts::PI;
                            if (-0.5 * pi..2.0 * pi).contains(&phase) {
                                phases_in_range += 1;
                            }
                        }
                        (covered, phases_in_range)
                    })
                })
                .collect();
            halves
                .into_iter()
                .map(|h| h.join().unwrap())
                .fold((0, 0), |a, b| (a.0 + b.0, a.1 + b.1))
        });
        eprintln!(
            "nonlinear g 1-sigma coverage {covered} of {}; phase in [-π/2, 2π) {phases_in_range}",
            seeds.len()
        );
        (covered, phases_in_range)
    }
}

/// Issue 23, wrong answer 6: air pendulums whose run-down is dry friction
/// and drag preferred `viscous+quadratic` while the `full` law, its
/// viscous rate at the bound 0, fitted far better: the list lacked the law
/// that full became. Now every law with rates at their bound is the law of
/// its free rates, fitted too (and no worse), and such run-downs prefer
/// `coulomb+quadratic`.
#[test]
fn a_law_at_its_bound_is_a_smaller_law_in_the_list() {
    let mut preferred = 0;
    for seed in 0..20 {
        let (t, a) = synthetic(DecayModel::CoulombQuadratic, 9000 + seed);
        let fits: Vec<_> = DecayModel::ALL
            .iter()
            .filter_map(|&m| fit_decay(m, &t, &a, None).ok())
            .collect();
        assert_eq!(fits.len(), DecayModel::ALL.len(), "seed {seed}");
        for f in fits.iter().filter(|f| !f.at_bound.is_empty()) {
            let free: Vec<&str> = f
                .model
                .rate_names()
                .into_iter()
                .filter(|n| !f.at_bound.contains(n))
                .collect();
            let smaller = fits
                .iter()
                .find(|g| g.model.rate_names() == free)
                .unwrap_or_else(|| panic!("{} at {:?}: no such law", f.model.name(), f.at_bound));
            assert!(
                smaller.fit.residual_rms <= f.fit.residual_rms * (1.0 + 1e-6),
                "{} rms {} against {} rms {}",
                smaller.model.name(),
                smaller.fit.residual_rms,
                f.model.name(),
                f.fit.residual_rms
            );
        }
        if pendulum_theory::fitting::decay::preferred(&fits) == Some(DecayModel::CoulombQuadratic) {
            preferred += 1;
        }
    }
    assert!(
        preferred >= 15,
        "coulomb+quadratic preferred {preferred} times of 20"
    );
}

/// Issue 23: a fit checks its own answer. Each wrong answer the issue
/// lists (times in milliseconds, a radius in pixels, a curve that does not
/// follow the record) is rebuilt here and must carry a warning naming the
/// cause; a fair record none.
mod self_checks {
    use super::Noise;
    use pendulum_theory::fitting::tracked::{analyse, crossings, LengthSource, TrackInput};
    use pendulum_theory::fitting::trajectory::TrajectoryModel;

    /// A 0.6 m pendulum swinging 8° at 30 frames a second for 20 s, the
    /// angle with 0.1° of noise; times scaled by `time_scale`.
    fn record(time_scale: f64, seed: u64) -> (Vec<f64>, Vec<f64>) {
        let mut noise = Noise(seed);
        let w = (9.80665_f64 / 0.6).sqrt();
        (0..600)
            .map(|i| {
                let t = f64::from(i) / 30.0;
                let a = 8f64.to_radians() * (-0.01 * t).exp() * (w * t).cos()
                    + 0.1f64.to_radians() * noise.gaussian();
                (t * time_scale, a)
            })
            .unzip()
    }

    fn codes(
        time: &[f64],
        angle: &[f64],
        length: Option<(f64, LengthSource)>,
    ) -> Vec<&'static str> {
        analyse(&TrackInput {
            time,
            angle,
            model: None,
            drag_law: None,
            length,
            length_standard_error: None,
            force: false,
            angle_from_positions: false,
            declared_degrees: false,
            angular_velocity: &[],
        })
        .unwrap()
        .warning_codes
    }

    /// A drag law named chooses the nonlinear model (a 3° record, which
    /// `auto` fits linearly), and is refused beside the linear model,
    /// naming its field.
    #[test]
    fn a_drag_law_named_is_the_nonlinear_model_s() {
        use pendulum_theory::analysis::Place;
        use pendulum_theory::fitting::tracked::parse_drag_law;
        let (t, a) = record(1.0, 1);
        let small: Vec<f64> = a.iter().map(|v| v * 3.0 / 30.0).collect();
        let input = |model| TrackInput {
            time: &t,
            angle: &small,
            model,
            drag_law: parse_drag_law("three_halves_drag").unwrap(),
            length: None,
            length_standard_error: None,
            force: false,
            angle_from_positions: false,
            declared_degrees: false,
            angular_velocity: &[],
        };
        assert_eq!(analyse(&input(None)).unwrap().model, "nonlinear");
        let refused = analyse(&input(Some(TrajectoryModel::Linear))).unwrap_err();
        assert_eq!(refused.place, Place::Field("drag_law"), "{refused:?}");
    }

    #[test]
    fn a_fair_record_raises_no_warning() {
        let (t, a) = record(1.0, 1);
        assert_eq!(
            codes(&t, &a, Some((0.6, LengthSource::Given))),
            Vec::<&str>::new()
        );
    }

    #[test]
    fn times_in_milliseconds_are_named() {
        let (t, a) = record(1000.0, 2);
        let r = analyse(&TrackInput {
            time: &t,
            angle: &a,
            model: None,
            drag_law: None,
            length: Some((0.6, LengthSource::Given)),
            length_standard_error: None,
            force: false,
            angle_from_positions: false,
            declared_degrees: false,
            angular_velocity: &[],
        })
        .unwrap();
        assert_eq!(r.warning_codes, ["gravity_implausible"]);
        assert!(
            r.warnings[0].to_string().contains("milliseconds"),
            "{}",
            r.warnings[0]
        );
    }

    #[test]
    fn a_radius_in_pixels_is_named() {
        // The arc's radius in pixels (300 px for 0.6 m) taken as metres.
        let (t, a) = record(1.0, 3);
        let r = analyse(&TrackInput {
            time: &t,
            angle: &a,
            model: None,
            drag_law: None,
            length: Some((300.0, LengthSource::TrackRadius)),
            length_standard_error: None,
            force: false,
            angle_from_positions: false,
            declared_degrees: false,
            angular_velocity: &[],
        })
        .unwrap();
        assert_eq!(r.warning_codes, ["gravity_implausible"]);
        assert!(
            r.warnings[0].to_string().contains("pixels"),
            "{}",
            r.warnings[0]
        );
        // A length in millimetres typed as metres.
        let c = codes(&t, &a, Some((600.0, LengthSource::Given)));
        assert_eq!(c, ["gravity_implausible"]);
    }

    #[test]
    fn a_curve_that_does_not_follow_the_record_is_named() {
        // Two pendulums of different length in one column (the wrong
        // column, a record that is not one swing): no damped cosine
        // follows it.
        let mut noise = Noise(4);
        let (t, a): (Vec<f64>, Vec<f64>) = (0..900)
            .map(|i| {
                let t = f64::from(i) / 30.0;
                (
                    t,
                    0.1 * (4.0 * t).cos() + 0.1 * (5.3 * t).cos() + 1e-3 * noise.gaussian(),
                )
            })
            .unzip();
        // The nonlinear model refuses it (its parameters undetermined);
        // the linear one fits it, and must say the fit is no good.
        let c = analyse(&TrackInput {
            time: &t,
            angle: &a,
            model: Some(TrajectoryModel::Linear),
            drag_law: None,
            length: None,
            length_standard_error: None,
            force: false,
            angle_from_positions: false,
            declared_degrees: false,
            angular_velocity: &[],
        })
        .unwrap()
        .warning_codes;
        assert!(
            c.contains(&"poor_fit") || c.contains(&"crossings_differ"),
            "{c:?}"
        );
    }

    #[test]
    fn times_in_milliseconds_without_a_length_are_named_by_the_period() {
        let (t, a) = record(1000.0, 5);
        let c = codes(&t, &a, None);
        assert_eq!(c, ["period_implausible"]);
    }

    #[test]
    fn radians_read_as_degrees_are_named() {
        // A 30° swing of a 0.6 m pendulum in radians, read as degrees: the
        // swing looks 57 times smaller and g loses its finite-amplitude
        // correction (3.4% low).
        let mut noise = Noise(6);
        let pendulum = pendulum_theory::Pendulum::with_standard_gravity(0.6).unwrap();
        let amplitude = pendulum_theory::Amplitude::from_degrees(30.0).unwrap();
        let w = std::f64::consts::TAU / pendulum.period(amplitude);
        let (t, a): (Vec<f64>, Vec<f64>) = (0..900)
            .map(|i| {
                let t = f64::from(i) / 30.0;
                // Near enough a 30° swing for the period (the test is of
                // the hint, not of the model).
                let theta = 30f64.to_radians() * (w * t).cos() + 2e-4 * noise.gaussian();
                (t, theta.to_radians())
            })
            .unzip();
        // (Undamped, so zeta is also not determined.)
        let c = codes(&t, &a, Some((0.6, LengthSource::Given)));
        assert!(c.contains(&"angle_unit"), "{c:?}");
        // (A record read right raises none: a_fair_record_raises_no_warning.)
    }

    #[test]
    fn a_length_far_from_the_pendulum_s_is_named() {
        // The 0.6 m pendulum given as 0.5 m: g 17% low, far beyond its
        // error, and no unit explains it.
        let (t, a) = record(1.0, 7);
        let c = codes(&t, &a, Some((0.5, LengthSource::Given)));
        assert_eq!(c, ["gravity_off"]);
        // 2% off (a ruler's error on a short pendulum) is not warned.
        let c = codes(&t, &a, Some((0.588, LengthSource::Given)));
        assert!(c.is_empty(), "{c:?}");
    }

    #[test]
    fn crossings_count_only_through_the_band() {
        // Noise at the centre crosses nothing; a full swing crosses twice
        // a period.
        let wobble = [0.01, -0.01, 0.02, -0.02, 0.0];
        assert_eq!(crossings(wobble.into_iter(), 0.0, 0.05), 0);
        let swing = (0..400).map(|i| (f64::from(i) * 0.05).cos());
        assert_eq!(crossings(swing, 0.0, 0.1), 6);
    }
}

/// Issue 23, wrong answer 2: a record whose first crest comes a little
/// after its first sample. The nonlinear fit releases the pendulum at the
/// crest before the first sample, a whole period earlier, and its
/// amplitude is extrapolated back through that period; the first crest
/// the record shows is reported beside it, and matches the truth.
mod first_crest {
    use super::Noise;
    use pendulum_theory::damping::Damping;
    use pendulum_theory::fitting::trajectory::{fit_trajectory, TrajectoryModel};
    use pendulum_theory::simulation::{
        simulate, Action, Method, Model, Observer, Options, TurningPoint,
    };
    use pendulum_theory::{Amplitude, Pendulum};

    /// Samples and turning points of the true motion.
    struct Truth {
        samples: Vec<(f64, f64)>,
        turns: Vec<(f64, f64)>,
    }

    impl Observer for Truth {
        fn turning_point(&mut self, p: &TurningPoint) -> Action {
            self.turns.push((p.time, p.angle));
            Action::Continue
        }
        fn sample(&mut self, time: f64, state: &pendulum_theory::damped::State) -> bool {
            self.samples.push((time, state.angle));
            true
        }
    }

    #[test]
    fn the_first_crest_in_the_record_is_reported_and_right() {
        // 11° from rest, 0.5 m, ζ = 0.003; 60 frames a second from 98% of
        // a period after the release, 20 s, 0.15° of noise.
        let pendulum = Pendulum::with_standard_gravity(0.5).unwrap();
        let amplitude = Amplitude::from_degrees(11.0).unwrap();
        let model = Model::new(pendulum, Damping::from_zeta(0.003).unwrap(), 0.0, 0.0).unwrap();
        let period = pendulum.period(amplitude);
        let start = 0.98 * period;
        let mut truth = Truth {
            samples: Vec::new(),
            turns: Vec::new(),
        };
        let options = Options {
            duration: start + 20.0,
            tolerance: 1e-12,
            method: Method::Dop853,
            sample_interval: Some(1.0 / 60.0),
        };
        simulate(&model, amplitude, &options, &mut truth).unwrap();
        let mut noise = Noise(11);
        let (t, theta): (Vec<f64>, Vec<f64>) = truth
            .samples
            .iter()
            .filter(|(time, _)| *time >= start)
            .map(|&(time, angle)| (time, angle + 0.15f64.to_radians() * noise.gaussian()))
            .unzip();
        let (crest_time, crest_angle) = truth
            .turns
            .iter()
            .copied()
            .find(|(time, _)| *time >= t[0])
            .unwrap();
        let fit = fit_trajectory(TrajectoryModel::Nonlinear, &t, &theta).unwrap();
        let [time, time_error, a, a_error] = fit.first_crest(t[1] - t[0]).unwrap();
        assert!(
            (a - crest_angle.abs()).abs() <= 3.0 * a_error,
            "first crest {a} ± {a_error} against {}",
            crest_angle.abs()
        );
        assert!(
            (time - (crest_time - t[0])).abs() <= 3.0 * time_error + 1e-6,
            "first crest at {time} ± {time_error} s against {}",
            crest_time - t[0]
        );
        // The release amplitude lies a period before the record, above any
        // crest in it: the reason the first crest is reported.
        assert!(fit.fit.parameters[0] > crest_angle.abs());
    }
}

/// Issue 23, wrong answer 1: long records of large swings (78-94°
/// releases, 136-375 s, Q 200-550) put the nonlinear fit in a false
/// minimum (amplitude 0.3 rad for 1.5, ω_n 3% low, residuals the size of
/// the swing, no warning). The fit over growing windows converges on each.
mod long_large_swings {
    use super::Noise;
    use pendulum_theory::damping::Damping;
    use pendulum_theory::fitting::tracked::{analyse, LengthSource, TrackInput};
    use pendulum_theory::simulation::{simulate, Method, Model, Observer, Options};
    use pendulum_theory::{Amplitude, Pendulum};

    struct Samples(Vec<(f64, f64)>);

    impl Observer for Samples {
        fn sample(&mut self, time: f64, state: &pendulum_theory::damped::State) -> bool {
            self.0.push((time, state.angle));
            true
        }
    }

    /// An undamped swing, the exact motion `θ = 2 asin(k sn(K − ω t | k²))`
    /// (DLMF 22.19.2 with the library's Jacobi functions, which are
    /// checked against mpmath), 10°, 0.5 m, with 1e-4 rad of noise, over
    /// 10 and 20 s at 30 and 60 frames a second, three seeds each: every
    /// record is fitted by the nonlinear model (8 of 18 such records fell
    /// back to the linear fit, "did not converge", when the model held ζ
    /// at 0 below it: its best ζ lies on either side of 0 by the noise),
    /// and g and ζ = 0 are within four standard errors of the truth.
    #[test]
    fn an_undamped_swing_is_fitted_whichever_side_of_zero_its_zeta_falls() {
        use pendulum_theory::elliptic::{ellipk, jacobi};
        use pendulum_theory::fitting::trajectory::{fit_trajectory, TrajectoryModel};
        let (length, amplitude): (f64, f64) = (0.5, 10f64.to_radians());
        let k = (0.5 * amplitude).sin();
        let omega = (9.806_65 / length).sqrt();
        let quarter = ellipk(k * k);
        let mut zetas = Vec::new();
        for (span, rate) in [(10.0, 30.0), (10.0, 60.0), (20.0, 30.0), (20.0, 60.0)] {
            for seed in 1..=3 {
                let mut noise = Noise(seed);
                let n = (span * rate) as usize;
                let t: Vec<f64> = (0..n).map(|i| i as f64 / rate).collect();
                let theta: Vec<f64> = t
                    .iter()
                    .map(|&x| {
                        2.0 * (k * jacobi(quarter - omega * x, k * k).sn).asin()
                            + 1e-4 * noise.gaussian()
                    })
                    .collect();
                let fit = fit_trajectory(TrajectoryModel::Nonlinear, &t, &theta).unwrap();
                let case = format!("{span} s at {rate}/s, seed {seed}");
                assert_eq!(fit.model, TrajectoryModel::Nonlinear, "{case}");
                assert_eq!(fit.nonlinear_rms_rejected, None, "{case}");
                let (g, se) = fit.gravity(length);
                assert!((g - 9.806_65).abs() <= 4.0 * se, "{case}: g {g} ± {se}");
                let (zeta, zeta_se) = (fit.fit.parameters[2], fit.fit.standard_errors[2]);
                assert!(zeta.abs() <= 4.0 * zeta_se, "{case}: ζ {zeta} ± {zeta_se}");
                zetas.push(zeta);
            }
        }
        // The noise puts ζ on both sides of 0.
        assert!(
            zetas.iter().any(|&z| z < 0.0) && zetas.iter().any(|&z| z > 0.0),
            "{zetas:?}"
        );
    }

    #[test]
    fn the_staged_fit_converges_where_the_whole_record_fit_did_not() {
        for (degrees, q, seconds, seed) in [
            (85.0, 300.0, 200.0, 1),
            (78.0, 200.0, 136.0, 2),
            (94.0, 550.0, 375.0, 3),
        ] {
            let pendulum = Pendulum::with_standard_gravity(0.7).unwrap();
            let model = Model::new(pendulum, Damping::from_q(q).unwrap(), 0.0, 0.0).unwrap();
            let options = Options {
                duration: seconds,
                tolerance: 1e-12,
                method: Method::Dop853,
                sample_interval: Some(1.0 / 30.0),
            };
            let mut samples = Samples(Vec::new());
            let release = Amplitude::from_degrees(degrees).unwrap();
            simulate(&model, release, &options, &mut samples).unwrap();
            let mut noise = Noise(seed);
            let (t, a): (Vec<f64>, Vec<f64>) = samples
                .0
                .iter()
                .map(|&(t, a)| (t, a + 0.2f64.to_radians() * noise.gaussian()))
                .unzip();
            let r = analyse(&TrackInput {
                time: &t,
                angle: &a,
                model: Some(pendulum_theory::fitting::trajectory::TrajectoryModel::Nonlinear),
                drag_law: None,
                length: Some((0.7, LengthSource::Given)),
                length_standard_error: None,
                force: true,
                angle_from_positions: false,
                declared_degrees: false,
                angular_velocity: &[],
            })
            .unwrap();
            let (g, se) = (r.parameters["g_m_s2"], r.standard_errors["g_m_s2"]);
            assert!((g - 9.80665).abs() <= 3.0 * se, "{degrees}°: g {g} ± {se}");
            let crest = r.parameters["first_crest_amplitude_rad"];
            assert!(
                (crest - release.radians()).abs() < 0.02,
                "{degrees}°: crest {crest}"
            );
            assert!(
                r.warning_codes.is_empty(),
                "{degrees}°: {:?}",
                r.warning_codes
            );
        }
    }
}
