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
    }
}

fn synthetic(model: DecayModel, seed: u64) -> (Vec<f64>, Vec<f64>) {
    let mut noise = Noise(seed);
    let p = truth(model);
    let t: Vec<f64> = (0..100).map(|i| f64::from(i) * 20.0).collect();
    let a = t.iter().map(|&x| model.amplitude(x, &p) + SIGMA * noise.gaussian()).collect();
    (t, a)
}

#[test]
fn each_fit_recovers_its_parameters_within_three_sigma() {
    for model in DecayModel::ALL {
        let (t, a) = synthetic(model, 1);
        let fit = fit_decay(model, &t, &a, Some(std::f64::consts::PI)).unwrap();
        for (j, want) in truth(model).iter().enumerate() {
            let (got, se) = (fit.fit.parameters[j], fit.fit.standard_errors[j]);
            assert!((got - want).abs() <= 3.0 * se, "{} p{j}: {got} ± {se} vs {want}", model.name());
        }
        // The residuals are the noise.
        assert!((fit.fit.residual_rms / SIGMA - 1.0).abs() < 0.25, "{}", fit.fit.residual_rms);
    }
}

#[test]
fn one_sigma_coverage_over_100_seeds() {
    for model in DecayModel::ALL {
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

#[test]
fn model_selection_picks_the_generating_model() {
    for model in [DecayModel::Viscous, DecayModel::Coulomb, DecayModel::ViscousCoulomb] {
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
        assert!(right >= 18, "{}: chosen in only {right} of 20", model.name());
    }
}

#[test]
fn beats_with_jitter_recover_rate_and_beat_error() {
    let mut noise = Noise(7);
    let beat = 1.0 / (1.0 + 5.0 / 86_400.0); // 5 s/day fast
    let mut t = vec![0.0];
    for i in 1..20_000 {
        let tick = if i % 2 == 1 { 0.0015 } else { -0.0015 };
        t.push(i as f64 * beat + tick / 2.0 * if i % 2 == 1 { 1.0 } else { 0.0 } + 2e-4 * noise.gaussian());
    }
    let a = analyse_beats(&t, None).unwrap();
    assert_eq!(a.nominal_beat, Some(1.0));
    assert!((a.rate_s_per_day.unwrap() - 5.0).abs() < 0.05, "{:?}", a.rate_s_per_day);
    assert!((a.beat_error_ms - 0.75).abs() < 0.05, "{}", a.beat_error_ms);
    assert!((a.jitter_ms / (2e-4 * 2f64.sqrt() * 1e3) - 1.0).abs() < 0.1, "{}", a.jitter_ms);
}
