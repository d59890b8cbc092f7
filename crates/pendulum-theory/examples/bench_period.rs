//! Prints nanoseconds per evaluation of the period and of `ellipk`, for
//! `bench/compare_scipy.sh`, which runs SciPy on the same inputs.
//!
//! Usage: `bench_period N REPEATS` (defaults 1000000 and 20). Inputs: N
//! amplitudes evenly spaced over 1..15 degrees, then over 1..179 degrees;
//! the figure is the best of REPEATS passes over the whole array. As with
//! NumPy's vectorised loop, only the pass's result is hidden from the
//! optimiser (`black_box` on the sum), not each element.

use pendulum_theory::elliptic::ellipk;
use pendulum_theory::{Amplitude, Pendulum};
use std::hint::black_box;
use std::time::Instant;

fn best_ns_per_item(n: usize, repeats: usize, mut pass: impl FnMut() -> f64) -> f64 {
    let mut best = f64::INFINITY;
    for _ in 0..repeats {
        let start = Instant::now();
        black_box(pass());
        best = best.min(start.elapsed().as_secs_f64());
    }
    best * 1e9 / n as f64
}

fn main() {
    let mut args = std::env::args().skip(1);
    let n: usize = args
        .next()
        .and_then(|a| a.parse().ok())
        .unwrap_or(1_000_000);
    let repeats: usize = args.next().and_then(|a| a.parse().ok()).unwrap_or(20);
    let pendulum = Pendulum::with_standard_gravity(0.99362).expect("valid pendulum");
    for (from, to) in [(1.0, 15.0), (1.0, 179.0)] {
        let amps: Vec<Amplitude> = (0..n)
            .map(|i| {
                let d = from + (to - from) * i as f64 / (n - 1) as f64;
                Amplitude::from_degrees(d).expect("valid amplitude")
            })
            .collect();
        let params: Vec<f64> = amps.iter().map(|a| a.modulus().m()).collect();
        let period = best_ns_per_item(n, repeats, || {
            amps.iter().map(|&a| pendulum.period(a)).sum()
        });
        let k = best_ns_per_item(n, repeats, || params.iter().map(|&m| ellipk(m)).sum());
        println!("{from}..{to} deg  pendulum period(A0): {period:.2} ns  ellipk(m): {k:.2} ns");
    }
}
