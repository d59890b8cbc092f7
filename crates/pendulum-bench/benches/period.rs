//! Criterion benchmarks of the period evaluation, over the amplitudes a
//! clockmaker uses (1..15 degrees) and over the whole range (1..179 degrees).
//! `bench/compare_scipy.sh` prints the same figures beside SciPy's.

use criterion::{black_box, criterion_group, criterion_main, Criterion, Throughput};
use pendulum_theory::elliptic::ellipk;
use pendulum_theory::period::circular_error;
use pendulum_theory::{Amplitude, Pendulum};

const N: usize = 4096;

fn amplitudes(from_deg: f64, to_deg: f64) -> Vec<Amplitude> {
    (0..N)
        .map(|i| {
            let d = from_deg + (to_deg - from_deg) * i as f64 / (N - 1) as f64;
            Amplitude::from_degrees(d).unwrap()
        })
        .collect()
}

fn period(c: &mut Criterion) {
    let pendulum = Pendulum::with_standard_gravity(0.99362).unwrap();
    for (name, from, to) in [("1..15deg", 1.0, 15.0), ("1..179deg", 1.0, 179.0)] {
        let amps = amplitudes(from, to);
        let params: Vec<f64> = amps.iter().map(|a| a.modulus().m()).collect();
        let mut group = c.benchmark_group(format!("period {name}"));
        group.throughput(Throughput::Elements(N as u64));
        group.bench_function("Pendulum::period", |b| {
            b.iter(|| amps.iter().map(|&a| pendulum.period(a)).sum::<f64>())
        });
        group.bench_function("ellipk(m)", |b| {
            b.iter(|| black_box(&params).iter().map(|&m| ellipk(m)).sum::<f64>())
        });
        group.bench_function("circular_error", |b| {
            b.iter(|| amps.iter().map(|&a| circular_error(a)).sum::<f64>())
        });
        group.finish();
    }
}

criterion_group!(benches, period);
criterion_main!(benches);
