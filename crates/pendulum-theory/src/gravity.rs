//! Local gravity: the WGS 84 normal gravity on the ellipsoid, with the
//! free-air correction for height.
//!
//! Somigliana's closed formula (NIMA TR8350.2, 3rd ed., eq. 4-1):
//! `γ(φ) = γ_e (1 + k sin²φ) / sqrt(1 - e² sin²φ)`, with the WGS 84 constants
//! below, and the free-air gradient −3.086e-6 m/s² per metre of height
//! (the usual linear term of TR8350.2 eq. 4-3). It omits local anomalies,
//! which reach a few 1e-4 m/s² (a few tens of ppm in a clock's rate); a
//! careful clockmaker measures g, or computes it back from a pendulum.

use crate::error::{require_finite, InputError, Problem, Quantity};

/// Normal gravity at the equator, m/s² (WGS 84).
pub const EQUATORIAL_GRAVITY: f64 = 9.780_325_335_9;
/// Somigliana's constant `k = (b γ_p - a γ_e) / (a γ_e)` (WGS 84).
pub const SOMIGLIANA_K: f64 = 0.001_931_852_652_41;
/// First eccentricity squared of the WGS 84 ellipsoid.
pub const ECCENTRICITY_SQUARED: f64 = 0.006_694_379_990_13;
/// Free-air gradient, m/s² per metre (negative: gravity falls with height).
pub const FREE_AIR_GRADIENT: f64 = -3.086e-6;

/// The lowest height the free-air formula is used at, m: the deepest ocean
/// floor (Challenger Deep, about −11 km). Below it one is inside the
/// Earth, where gravity falls with depth instead of rising.
pub const MIN_HEIGHT_M: f64 = -11_000.0;
/// The highest, m: the Kármán line. The linear free-air term errs by
/// `3h/R` of itself (5% at 100 km).
pub const MAX_HEIGHT_M: f64 = 100_000.0;

/// WGS 84 normal gravity at geodetic latitude `latitude_deg` (degrees,
/// −90..=90) and `height_m` metres above the ellipsoid, m/s²; heights from
/// [`MIN_HEIGHT_M`] to [`MAX_HEIGHT_M`].
///
/// 9.7803253359 at the equator, 9.8321849379 at the poles, 9.806199 at 45°.
/// The formula is evaluated in double precision with no cancellation, so
/// the result carries 2 ulp of rounding; the model itself is good to about
/// 1e-4 m/s² (anomalies), which is what a user should quote.
///
/// # Examples
///
/// ```
/// use pendulum_theory::gravity::normal_gravity;
///
/// // WGS 84's normal gravity at the equator (γ_e) and at the poles (γ_p).
/// assert!((normal_gravity(0.0, 0.0)? - 9.780_325_335_9).abs() < 1e-12);
/// assert!((normal_gravity(90.0, 0.0)? - 9.832_184_937_9).abs() < 1e-10);
/// // 1000 m up, the free-air gradient takes 3.086 mm/s² off.
/// let drop = normal_gravity(45.0, 0.0)? - normal_gravity(45.0, 1000.0)?;
/// assert!((drop - 3.086e-3).abs() < 1e-12);
/// # Ok::<(), pendulum_theory::InputError>(())
/// ```
pub fn normal_gravity(latitude_deg: f64, height_m: f64) -> Result<f64, InputError> {
    let lat = require_finite(Quantity::Latitude, latitude_deg)?;
    if !(-90.0..=90.0).contains(&lat) {
        return Err(InputError::new(
            Quantity::Latitude,
            lat,
            Problem::LatitudeOutOfRange,
        ));
    }
    let h = require_finite(Quantity::Height, height_m)?;
    if h < MIN_HEIGHT_M {
        return Err(InputError::new(
            Quantity::Height,
            h,
            Problem::BelowMinimum {
                minimum: MIN_HEIGHT_M,
            },
        ));
    }
    if h > MAX_HEIGHT_M {
        return Err(InputError::new(
            Quantity::Height,
            h,
            Problem::AboveMaximum {
                maximum: MAX_HEIGHT_M,
            },
        ));
    }
    let s2 = lat.to_radians().sin().powi(2);
    let surface =
        EQUATORIAL_GRAVITY * (1.0 + SOMIGLIANA_K * s2) / (1.0 - ECCENTRICITY_SQUARED * s2).sqrt();
    Ok(surface + FREE_AIR_GRADIENT * h)
}

/// How far `g` (m/s²) lies from standard gravity, in parts per million:
/// `10⁶ (g / g_n - 1)`, `g_n` = [`crate::STANDARD_GRAVITY`] (exact by
/// definition, CGPM 1901).
pub fn deviation_from_standard_ppm(g: f64) -> f64 {
    (g / crate::pendulum::STANDARD_GRAVITY - 1.0) * 1e6
}

/// The height when a latitude is given without one, m: the ellipsoid.
pub const DEFAULT_HEIGHT_M: f64 = 0.0;

/// The value of g an analysis uses, and where it came from.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct Resolved {
    /// m/s².
    pub g_m_s2: f64,
    /// `"standard"` (none given: [`crate::STANDARD_GRAVITY`]), `"given"`,
    /// or `"wgs84"` (normal gravity at a latitude and height).
    pub g_source: &'static str,
}

/// g given (`g`, m/s²), or the normal gravity at `latitude` (degrees) and
/// `height` (m, default 0), or standard gravity when neither is given;
/// each checked, refusals naming `g`, `latitude` or `height`.
pub fn resolve(
    g: Option<f64>,
    latitude: Option<f64>,
    height: Option<f64>,
) -> Result<Resolved, crate::analysis::Refusal> {
    use crate::analysis::Refusal;
    match (g, latitude) {
        (Some(_), Some(_)) => Err(Refusal::field("g", "give g or a latitude, not both")),
        (Some(g), None) => {
            // The pendulum's check of g, so the sentence is every other's.
            crate::Pendulum::new(1.0, g).map_err(|e| Refusal::input("g", &e))?;
            Ok(Resolved {
                g_m_s2: g,
                g_source: "given",
            })
        }
        (None, Some(lat)) => normal_gravity(lat, height.unwrap_or(DEFAULT_HEIGHT_M))
            .map(|g| Resolved {
                g_m_s2: g,
                g_source: "wgs84",
            })
            .map_err(|e| match e.quantity {
                Quantity::Height => Refusal::input("height", &e),
                _ => Refusal::input("latitude", &e),
            }),
        (None, None) if height.is_some() => Err(Refusal::field("height", "needs a latitude")),
        (None, None) => Ok(Resolved {
            g_m_s2: crate::STANDARD_GRAVITY,
            g_source: "standard",
        }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn equator_and_poles() {
        assert_eq!(normal_gravity(0.0, 0.0).unwrap(), EQUATORIAL_GRAVITY);
        let pole = normal_gravity(90.0, 0.0).unwrap();
        // TR8350.2 table 3.4: γ_p = 9.8321849379 m/s².
        assert!((pole - 9.832_184_937_9).abs() < 1e-9);
        assert_eq!(pole, normal_gravity(-90.0, 0.0).unwrap());
    }

    #[test]
    fn free_air() {
        let g0 = normal_gravity(45.0, 0.0).unwrap();
        let g1 = normal_gravity(45.0, 1000.0).unwrap();
        assert!((g0 - g1 - 3.086e-3).abs() < 1e-12);
    }

    #[test]
    fn refuses_bad_latitude() {
        assert!(normal_gravity(90.5, 0.0).is_err());
        assert!(normal_gravity(f64::NAN, 0.0).is_err());
        assert!(normal_gravity(10.0, f64::INFINITY).is_err());
    }

    #[test]
    fn refuses_heights_inside_the_earth_or_in_space() {
        // 1e7 m below sea level is inside the Earth (issue 9).
        let deep = normal_gravity(45.0, -1e7).unwrap_err();
        assert!(matches!(deep.problem, Problem::BelowMinimum { .. }));
        assert!(normal_gravity(45.0, 1e6).is_err());
        assert!(normal_gravity(45.0, -10_994.0).is_ok()); // Challenger Deep
        assert!(normal_gravity(45.0, 8_849.0).is_ok()); // Everest
    }
}
