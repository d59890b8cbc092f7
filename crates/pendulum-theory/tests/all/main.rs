//! The library's integration tests, one binary: each module an area
//! (its own doc says what it checks), `common` what they share. One
//! binary links once and runs every module's tests on the same threads,
//! so a long test of one area overlaps the others' (CI's wall time).
//! A single area: `cargo test --release -p pendulum-theory --test all
//! coverage::`.

mod advice;
mod clock;
mod clock_log;
mod common;
mod compound;
mod coverage;
mod damped_properties;
mod damped_reference;
mod doctor;
mod fitting;
mod gas_effects;
mod identities;
mod listening;
mod live;
mod materials;
mod module_graph;
mod oscillating_flow;
mod periodic;
mod reference;
mod simulation;
mod stability;
mod suspension;
mod tide;
