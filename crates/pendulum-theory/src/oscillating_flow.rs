//! The force of a gas on a body oscillating in it: the air a pendulum
//! drags along (added mass) and the air that damps it, for a sphere, a
//! long cylinder moving across its axis and a plate moving in its own
//! plane, from the continuum (Stokes) to the free-molecular limit.
//!
//! A body displacing gas of mass `M'` and moving at `u = U e^{iωt}` feels
//! `F = -M' (k du/dt + k' ω u)`: `k` is the added-mass coefficient (the air
//! carried along, over the displaced air), `k'` the damping coefficient.
//!
//! Methods (continuum, incompressible, small amplitude against the size):
//! - Sphere of radius `a` (Stokes 1851, "On the effect of the internal
//!   friction of fluids on the motion of pendulums", Trans. Camb. Phil.
//!   Soc. 9, §II; in modern form Landau and Lifshitz, Fluid Mechanics,
//!   2nd ed., §24 problem 5): with the boundary layer's thickness `δ =
//!   sqrt(2ν/ω)`, `k = 1/2 + 9δ/4a`, `k' = (9δ/4a)(1 + δ/a)`. Exact for
//!   the linearised Navier-Stokes equations.
//! - Cylinder of radius `a`, per unit length (Stokes 1851, §III; the
//!   closed form with modified Bessel functions as in J. E. Sader, J.
//!   Appl. Phys. 84 (1998) 64, eq. 21): `k - i k' = 1 + 4 K₁(z) / (z
//!   K₀(z))` with `z = a sqrt(iω/ν)`. Exact for an infinite cylinder; a
//!   rod's ends and a short cylinder's are left out (Stokes: the error is
//!   of order the diameter over the length).
//! - Plate of thickness `t` moving in its own plane, both faces (Stokes's
//!   oscillating plane, 1851 §I; Landau and Lifshitz §24): each face
//!   carries `ρ δ/2` per unit area and is damped by `ρ ω δ/2`, so `k = k'
//!   = δ/t` over the plate's displaced air; to which the edge's potential
//!   flow adds `t/D` to `k` (Lamb §114). The rim's own drag is left out:
//!   an error of order `t/D`.
//!
//! The Bessel functions of the complex argument (|arg z| = π/4) are
//! computed from `K_ν(z) = ∫₀^∞ exp(-z cosh s) cosh(νs) ds` (DLMF
//! 10.32.9) by the trapezoidal rule with step 1/16: the integrand is
//! analytic in the strip |Im s| < π/4, so the rule's error is below
//! `exp(-2π (π/4)/h) ≈ 1e-34` relative (Trefethen and Weideman, SIAM
//! Review 56 (2014) 385), and the sum is cut where `Re(z) (cosh s - 1) > 50`.
//! Measured against mpmath's `besselk` at 60 points from |z| = 1e-3 to
//! 100: the ratio `K₁/K₀` agrees to 3e-15 relative
//! (`tests/data/oscillating_flow/`).
//!
//! Rarefied gas: when the mean free path `λ` is not small against the body,
//! the continuum overstates the drag, which in the free-molecular limit is
//! proportional to the density: for a sphere Epstein's `F = (4π/3)(1 +
//! π/8) ρ c̄ a² u` (diffuse reflection; P. S. Epstein, Phys. Rev. 23 (1924)
//! 710), for a plate `ρ c̄ u / 4` per unit area of each face (full
//! accommodation; G. A. Bird, Molecular Gas Dynamics, 1994, §7.2), for a
//! cylinder the sphere's drag per unit of projected area (an approximation
//! of this crate, within the factor 1.3 by which the exact crossflow
//! results for diffuse cylinders and spheres differ). The two are joined
//! harmonically, `1/k' = 1/k'_continuum + 1/k'_molecular`; for a sphere
//! in steady flow this is `1 + 1.616 λ/a` against Stokes's drag, within
//! 12% of Millikan's measured slip correction (Allen and Raabe, J.
//! Aerosol Sci. 13 (1982) 537) at every Knudsen number (measured in
//! `tests/all/oscillating_flow.rs`; worst near λ = a), and the boundary
//! layer's added mass is scaled by the same factor.

use realfft::num_complex::Complex;
use std::f64::consts::PI;

/// The coefficients of the force of the gas on a body (see the module
/// notes).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Flow {
    /// Added-mass coefficient `k`: the air carried along over the air
    /// displaced.
    pub added_mass: f64,
    /// Damping coefficient `k'`.
    pub damping: f64,
}

/// The gas around the body: what the flow depends on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Medium {
    /// Angular frequency of the swing, rad/s.
    pub omega: f64,
    /// Kinematic viscosity, m²/s.
    pub nu: f64,
    /// Mean free path, m.
    pub mean_free_path: f64,
    /// Mean molecular speed, m/s.
    pub mean_speed: f64,
}

impl Medium {
    /// The boundary layer's thickness `sqrt(2ν/ω)`, m.
    pub fn delta(&self) -> f64 {
        (2.0 * self.nu / self.omega).sqrt()
    }

    /// Scales a continuum flow for rarefaction, given the free-molecular
    /// damping coefficient `molecular` (see the module notes); `potential`
    /// is the part of `k` that is ideal flow.
    fn rarefied(&self, continuum: Flow, molecular: f64, potential: f64) -> Flow {
        if molecular.is_infinite() {
            return continuum;
        }
        let damping = continuum.damping * molecular / (continuum.damping + molecular);
        let factor = damping / continuum.damping;
        Flow {
            added_mass: potential + (continuum.added_mass - potential) * factor,
            damping,
        }
    }
}

/// The Euler-Mascheroni constant.
const EULER_GAMMA: f64 = 0.577_215_664_901_532_9;

/// Epstein's factor for diffuse reflection, `1 + π/8`.
const EPSTEIN: f64 = 1.0 + PI / 8.0;

/// A sphere of radius `a`, m (see the module notes).
pub fn sphere(a: f64, m: &Medium) -> Flow {
    let r = m.delta() / a;
    let continuum = Flow {
        added_mass: 0.5 + 2.25 * r,
        damping: 2.25 * r * (1.0 + r),
    };
    // Epstein's drag over M' ω, with M' = (4π/3) a³ ρ.
    let molecular = EPSTEIN * m.mean_speed / (a * m.omega);
    m.rarefied(continuum, molecular, 0.5)
}

/// A long cylinder of radius `a`, m, moving across its axis, per unit
/// length (see the module notes).
pub fn cylinder(a: f64, m: &Medium) -> Flow {
    let z = Complex::new(0.0, m.omega / m.nu).sqrt() * a;
    let (k0, k1) = bessel_k01_scaled(z);
    let g = Complex::new(1.0, 0.0) + k1 * 4.0 / (z * k0);
    let continuum = Flow {
        added_mass: g.re,
        damping: -g.im,
    };
    // The sphere's free-molecular drag per projected area, (4/3) ε ρ c̄
    // (2a) per length, over M' ω = π a² ρ ω.
    let molecular = 8.0 * EPSTEIN * m.mean_speed / (3.0 * PI * a * m.omega);
    m.rarefied(continuum, molecular, 1.0)
}

/// A plate of thickness `t` and diameter `d`, m, moving in its own plane
/// (see the module notes).
pub fn plate(t: f64, d: f64, m: &Medium) -> Flow {
    let r = m.delta() / t;
    let edge = t / d;
    let continuum = Flow {
        added_mass: edge + r,
        damping: r,
    };
    // ρ c̄ /4 per area and face: 2 × c̄/4 over (t ω).
    let molecular = m.mean_speed / (2.0 * t * m.omega);
    m.rarefied(continuum, molecular, edge)
}

/// `e^z K₀(z)` and `e^z K₁(z)` for `Re z > 0` (see the module notes; the
/// factor `e^z` keeps large arguments from underflowing).
pub fn bessel_k01_scaled(z: Complex<f64>) -> (Complex<f64>, Complex<f64>) {
    if z.norm() < 1e-6 {
        // The leading terms of the series (DLMF 10.31.2 and 10.31.1):
        // K₀ = -ln(z/2) - γ, K₁ = 1/z + (z/2)(ln(z/2) + γ - 1/2), each to
        // O(z² ln z), below 1e-11 relative here.
        let log = (z * 0.5).ln() + EULER_GAMMA;
        let k0 = -log;
        let k1 = z.inv() + z * 0.5 * (log - 0.5);
        return (k0 * z.exp(), k1 * z.exp());
    }
    let h = 1.0 / 16.0;
    let (mut k0, mut k1) = (Complex::new(0.0, 0.0), Complex::new(0.0, 0.0));
    let mut i = 0;
    loop {
        let s = i as f64 * h;
        let c = s.cosh();
        if z.re * (c - 1.0) > 50.0 || i > 100_000 {
            break;
        }
        let e = (-z * (c - 1.0)).exp();
        let w = if i == 0 { 0.5 * h } else { h };
        k0 += e * w;
        k1 += e * (w * c);
        i += 1;
    }
    (k0, k1)
}
