//! Seeded standard normal deviates for the unit tests: xorshift64
//! (Marsaglia 2003, shifts 13, 7, 17) and the Box–Muller transform, so a
//! test's draw does not depend on another crate's stream.

/// `n` standard normal deviates from `seed` (not zero).
pub(crate) fn normals(n: usize, mut seed: u64) -> Vec<f64> {
    let mut uniform = || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        ((seed >> 11) as f64 + 0.5) / (1u64 << 53) as f64
    };
    (0..n)
        .map(|_| {
            let (a, b) = (uniform(), uniform());
            (-2.0 * a.ln()).sqrt() * (std::f64::consts::TAU * b).cos()
        })
        .collect()
}
