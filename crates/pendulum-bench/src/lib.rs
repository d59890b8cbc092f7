//! The criterion benchmarks of `pendulum-theory` live in this crate's
//! `benches/` (`cargo bench -p pendulum-bench`): apart from the library,
//! so that `cargo test` never compiles criterion.
