//! Criterion benchmarks of the simulation: 100 periods of a seconds
//! pendulum at 3° with Q = 10^6, every turning point located, with each
//! method at the tolerances users pick. `bench/compare_scipy.sh` compares
//! 1000-period runs with SciPy and Boost.Odeint.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use pendulum_theory::damping::Damping;
use pendulum_theory::simulation::{simulate, Method, Model, Options, Silent};
use pendulum_theory::{Amplitude, Pendulum};

fn simulation(c: &mut Criterion) {
    let pendulum = Pendulum::with_standard_gravity(0.99362).unwrap();
    let model = Model::new(pendulum, Damping::from_q(1e6).unwrap(), 0.0, 0.0).unwrap();
    let amplitude = Amplitude::from_degrees(3.0).unwrap();
    let duration = 100.0 * pendulum.period(amplitude);
    let mut group = c.benchmark_group("simulate 100 periods");
    for (method, tolerance) in [
        (Method::Dop853, 1e-10),
        (Method::Dop853, 1e-12),
        (Method::Symplectic, 1e-8),
        (Method::Symplectic, 1e-10),
    ] {
        let options = Options {
            duration,
            tolerance,
            method,
            sample_interval: None,
        };
        group.bench_function(format!("{} tol {tolerance:e}", method.name()), |b| {
            b.iter(|| simulate(&model, black_box(amplitude), &options, &mut Silent).unwrap())
        });
    }
    group.finish();
}

criterion_group!(benches, simulation);
criterion_main!(benches);
