//! The gas a pendulum swings in: air, nitrogen or helium, from a near
//! vacuum (1 Pa) to 1.2 bar: its density, viscosity, mean free path and
//! molecular speed.
//!
//! Methods and sources:
//! - Density of air: the CIPM-2007 equation (see [`crate::air`]), used
//!   down to 1 Pa: its compressibility terms are a virial expansion in the
//!   pressure and vanish as it falls, leaving the ideal gas, which air is
//!   there (the second virial term of air is -2e-4 per bar at 20 °C, so
//!   the error below 600 hPa is under 2e-5 of the density plus CIPM's own
//!   22 ppm).
//! - Nitrogen and helium: the gas law with the second virial coefficient
//!   at 20 °C, `ρ = p M / (R T (1 + B p / R T))`: nitrogen `B = -4.5`
//!   cm³/mol, helium `B = +11.8` cm³/mol (Dymond and Smith, The Virial
//!   Coefficients of Pure Gases and Mixtures, 1980; both change by less
//!   than 3 cm³/mol over -20 to 60 °C, an error under 1.5e-4 of the
//!   density at 1.2 bar). Molar masses 28.0134 and 4.002602 g/mol.
//! - Viscosity: Sutherland's law `μ = μ0 (T/T0)^1.5 (T0 + S)/(T + S)`
//!   with T0 = 273.15 K, for air μ0 = 17.16 µPa s, S = 110.4 K, for
//!   nitrogen μ0 = 16.63 µPa s, S = 107 K (F. M. White, Viscous Fluid
//!   Flow, 3rd ed., 2006, table 1-2: within 2% from 170 to 1,900 K);
//!   helium, which Sutherland's law fits poorly, by the power law `μ =
//!   18.7 µPa s (T/T0)^0.66`, which passes through the tabulated 18.7 and
//!   19.6 µPa s at 0 and 20 °C (NIST Chemistry WebBook, thermophysical
//!   properties of fluids) and stays within 1% over -20 to 60 °C. The
//!   viscosity of a dilute gas does not depend on its pressure (Maxwell);
//!   the water in moist air changes it by under 1% and is left out.
//! - Mean free path: the hard-sphere relation to the viscosity, `λ = (μ /
//!   p) sqrt(π R T / 2M)` (Chapman and Cowling; 65 nm for air at 20 °C
//!   and 1 atm, the figure the aerosol literature uses, e.g. Hinds,
//!   Aerosol Technology, 2nd ed., 1999, §2.3: 66 nm).
//! - Mean molecular speed `c̄ = sqrt(8 R T / π M)` (kinetic theory).

use crate::air::{cipm_density, dry_air_molar_mass, vapour_fraction, TEMPERATURE_RANGE_C};
use crate::analysis::Refusal;
use crate::error::format_significant;

/// The warning for a humidity that looks like a fraction of 1 given for a
/// percentage: `what` ("the humidity is 0.6 %") and the likely fix.
pub fn per_cent_warning(what: &str) -> String {
    format!(
        "{what}: it is read in per cent (air that dry is rare indoors); if it is a fraction \
         of 1, multiply it by 100"
    )
}

/// The molar gas constant, J/(mol K) (CODATA 2018, exact).
const R: f64 = 8.314_462_618;

/// The pressures a gas may have, Pa: 1 Pa (a pumped tank) to 1.2 bar.
pub const PRESSURE_RANGE_PA: (f64, f64) = (1.0, 120_000.0);

/// A gas.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Gas {
    /// Moist air (CIPM-2007).
    Air,
    /// Dry nitrogen, as in a Shortt clock's tank.
    Nitrogen,
    /// Helium.
    Helium,
}

impl Gas {
    /// Every gas, for messages.
    pub const ALL: [Gas; 3] = [Gas::Air, Gas::Nitrogen, Gas::Helium];

    /// Its name.
    pub fn name(self) -> &'static str {
        match self {
            Gas::Air => "air",
            Gas::Nitrogen => "nitrogen",
            Gas::Helium => "helium",
        }
    }

    /// A gas by name (case ignored; `n2`, `he` accepted).
    pub fn named(name: &str) -> Option<Gas> {
        match name.trim().to_ascii_lowercase().as_str() {
            "air" => Some(Gas::Air),
            "nitrogen" | "n2" => Some(Gas::Nitrogen),
            "helium" | "he" => Some(Gas::Helium),
            _ => None,
        }
    }

    /// A gas by name, or the refusal (field `gas`) listing the names.
    pub fn parse(name: &str) -> Result<Gas, Refusal> {
        Gas::named(name).ok_or_else(|| {
            let names: Vec<&str> = Gas::ALL.iter().map(|g| g.name()).collect();
            Refusal::field(
                "gas",
                format!("unknown gas '{name}' (known: {})", names.join(", ")),
            )
        })
    }

    /// Molar mass, kg/mol (air: dry, 400 µmol/mol CO₂).
    fn molar_mass(self) -> f64 {
        match self {
            Gas::Air => dry_air_molar_mass(0.0004),
            Gas::Nitrogen => 28.0134e-3,
            Gas::Helium => 4.002_602e-3,
        }
    }
}

/// A gas at a pressure, temperature and (for air) humidity, checked.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GasState {
    /// Which gas.
    pub gas: Gas,
    /// Pressure, Pa.
    pub pressure_pa: f64,
    /// Temperature, °C.
    pub temperature_c: f64,
    /// Relative humidity, 0 to 1 (air only; 0 for the others).
    pub humidity: f64,
}

impl GasState {
    /// The gas `gas` at `pressure_pa`, `temperature_c` and relative
    /// humidity `humidity`, refused (naming the field) outside 1 Pa to 1.2
    /// bar, -20 to 60 °C, a humidity outside 0 to 1, a humidity given for
    /// a gas other than air, or more water vapour than the pressure holds.
    pub fn new(
        gas: Gas,
        pressure_pa: f64,
        temperature_c: f64,
        humidity: f64,
    ) -> Result<Self, Refusal> {
        let (p0, p1) = PRESSURE_RANGE_PA;
        if !(p0..=p1).contains(&pressure_pa) {
            return Err(Refusal::field(
                "pressure",
                format!(
                    "must lie between {} Pa and {} hPa{}",
                    p0,
                    p1 / 100.0,
                    got(pressure_pa / 100.0, "hPa")
                ),
            ));
        }
        let (t0, t1) = TEMPERATURE_RANGE_C;
        if !(t0..=t1).contains(&temperature_c) {
            return Err(Refusal::field(
                "temperature",
                format!(
                    "must lie between {t0} and {t1} °C{}",
                    got(temperature_c, "°C")
                ),
            ));
        }
        if !(0.0..=1.0).contains(&humidity) {
            return Err(Refusal::field(
                "humidity",
                format!("must lie between 0 and 100 %{}", got(humidity * 100.0, "%")),
            ));
        }
        if gas != Gas::Air && humidity > 0.0 {
            return Err(Refusal::field(
                "humidity",
                format!("is for air; {} is taken dry", gas.name()),
            ));
        }
        if gas == Gas::Air && vapour_fraction(pressure_pa, temperature_c, humidity) >= 0.5 {
            return Err(Refusal::field(
                "humidity",
                format!(
                    "{} % at {} °C is more water vapour than {} hPa of air can be \
                     (half of it or more): give a lower humidity",
                    format_significant(humidity * 100.0, 3),
                    format_significant(temperature_c, 4),
                    format_significant(pressure_pa / 100.0, 4)
                ),
            ));
        }
        Ok(Self {
            gas,
            pressure_pa,
            temperature_c,
            humidity,
        })
    }

    /// The same gas at pressure `p` Pa, its composition kept (a case
    /// pumped down or pressurised: the relative humidity scales with the
    /// pressure). Unchecked: for pressures within the range.
    pub fn at_pressure(&self, p: f64) -> Self {
        Self {
            pressure_pa: p,
            humidity: (self.humidity * p / self.pressure_pa).min(1.0),
            ..*self
        }
    }

    fn kelvin(&self) -> f64 {
        self.temperature_c + 273.15
    }

    /// Density, kg/m³ (see the module notes).
    pub fn density(&self) -> f64 {
        let (p, tk) = (self.pressure_pa, self.kelvin());
        let b = match self.gas {
            Gas::Air => return cipm_density(p, self.temperature_c, self.humidity),
            Gas::Nitrogen => -4.5e-6,
            Gas::Helium => 11.8e-6,
        };
        let ideal = R * tk / p;
        self.gas.molar_mass() / (ideal + b)
    }

    /// Dynamic viscosity, Pa s (see the module notes).
    pub fn viscosity(&self) -> f64 {
        let tk = self.kelvin();
        let t0 = 273.15;
        let sutherland = |mu0: f64, s: f64| mu0 * (tk / t0).powf(1.5) * (t0 + s) / (tk + s);
        match self.gas {
            Gas::Air => sutherland(17.16e-6, 110.4),
            Gas::Nitrogen => sutherland(16.63e-6, 107.0),
            Gas::Helium => 18.7e-6 * (tk / t0).powf(0.66),
        }
    }

    /// Kinematic viscosity `μ/ρ`, m²/s.
    pub fn kinematic_viscosity(&self) -> f64 {
        self.viscosity() / self.density()
    }

    /// Mean free path, m (see the module notes).
    pub fn mean_free_path(&self) -> f64 {
        let m = self.gas.molar_mass();
        self.viscosity() / self.pressure_pa
            * (std::f64::consts::PI * R * self.kelvin() / (2.0 * m)).sqrt()
    }

    /// Mean molecular speed, m/s.
    pub fn mean_speed(&self) -> f64 {
        (8.0 * R * self.kelvin() / (std::f64::consts::PI * self.gas.molar_mass())).sqrt()
    }
}

fn got(v: f64, unit: &str) -> String {
    if v.is_finite() {
        format!(", got {} {unit}", format_significant(v, 6))
    } else {
        String::new()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Against independent figures: air's viscosity at 20 °C, 18.2 µPa s
    /// (NIST WebBook, Lemmon and Jacobsen 2004: 18.21); nitrogen 17.6
    /// (17.58); helium 19.6 (19.61); the mean free path of air at 20 °C
    /// and 1 atm, 66 nm (Hinds §2.3); the ideal-gas densities at 1 atm,
    /// 20 °C (p M / R T); and the low-pressure limit of air, where CIPM's
    /// formula must become the ideal gas.
    #[test]
    fn against_published_properties() {
        let at = |g, p| GasState::new(g, p, 20.0, 0.0).unwrap();
        for (g, mu) in [
            (Gas::Air, 18.21e-6),
            (Gas::Nitrogen, 17.58e-6),
            (Gas::Helium, 19.61e-6),
        ] {
            let v = at(g, 101_325.0).viscosity();
            assert!((v / mu - 1.0).abs() < 0.01, "{g:?}: {v}");
        }
        let lambda = at(Gas::Air, 101_325.0).mean_free_path();
        assert!((lambda / 66e-9 - 1.0).abs() < 0.03, "{lambda}");
        for (g, m) in [(Gas::Nitrogen, 28.0134e-3), (Gas::Helium, 4.0026e-3)] {
            let ideal = 101_325.0 * m / (8.314_462 * 293.15);
            let rho = at(g, 101_325.0).density();
            assert!((rho / ideal - 1.0).abs() < 5e-4, "{g:?}: {rho}");
        }
        let low = at(Gas::Air, 2700.0).density();
        let ideal = 2700.0 * 28.965e-3 / (8.314_462 * 293.15);
        assert!((low / ideal - 1.0).abs() < 1e-4, "{low} {ideal}");
    }

    #[test]
    fn refusals_name_the_field() {
        let f = |g, p, t, h| {
            GasState::new(g, p, t, h)
                .unwrap_err()
                .field_name()
                .unwrap_or("-")
        };
        assert_eq!(f(Gas::Air, 0.5, 20.0, 0.5), "pressure");
        assert_eq!(f(Gas::Air, 2e5, 20.0, 0.5), "pressure");
        assert_eq!(f(Gas::Air, f64::NAN, 20.0, 0.5), "pressure");
        assert_eq!(f(Gas::Air, 1e5, 90.0, 0.5), "temperature");
        assert_eq!(f(Gas::Helium, 1e5, 20.0, 0.5), "humidity");
        // 100% at 60 °C is 200 hPa of water: not in 300 hPa of air.
        assert_eq!(f(Gas::Air, 30_000.0, 60.0, 1.0), "humidity");
    }
}
