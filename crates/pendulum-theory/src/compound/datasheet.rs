//! A design's datasheet as one analysis: its parts, mass, inertia,
//! equivalent length and period, its temperature and barometric
//! coefficients, the gas's effect (buoyancy, carried gas, damping and so
//! Q) and the rating nut's, in a gas (air, nitrogen or helium, 1 Pa to 1.2
//! bar) at a temperature; with a semi-arc, the arc a drive keeps as the
//! pressure changes and so the circular error's share of the barometric
//! error, and the semi-arc at which the two cancel (Airy's and Baily's
//! compensation by the arc). The command line's `design` and Python's
//! `design` are this call.
//!
//! The arc against pressure: a drive that gives the same energy each
//! swing keeps the arc at which the losses per cycle equal it: Stokes's
//! damping and the pivot's (`π ω A² c`, the pivot's `c = I ω / Q_pivot`
//! taken as independent of the gas) and the form drag's `(8/3) ω² A³ D`
//! ([`super::gas`]). The circular error is the exact one,
//! [`crate::period::circular_error`], or on a suspension spring
//! [`crate::suspension::period_ratio`]'s. The barometric coefficient with the
//! arc's change
//! is a central difference of ±1% of the pressure of the two together,
//! and the cancelling semi-arc the root of it, found by a scan and
//! bisection.

use super::description::Design;
use super::gas::InGas;
use super::{rate_of_length_ratio, CompoundPendulum};
use crate::analysis::Refusal;
use crate::error::format_significant;
use crate::gas::{Gas, GasState};
use crate::pendulum::{Pendulum, STANDARD_GRAVITY};
use crate::warning::Warning;
use serde::Serialize;

/// The air a datasheet is for when none is given: standard pressure, Pa.
pub const DEFAULT_PRESSURE_PA: f64 = 101_325.0;
/// The temperature when none is given, °C (also where it was regulated).
pub const DEFAULT_TEMPERATURE_C: f64 = 20.0;
/// Relative humidity when none is given (0 to 1), at the standard
/// pressure and above; below, this times the pressure over the standard.
pub const DEFAULT_HUMIDITY: f64 = 0.5;
/// Temperatures a clock may have been regulated at, °C.
pub const REGULATED_AT_RANGE_C: (f64, f64) = (-50.0, 100.0);

/// The air and temperature a datasheet is for; every `None` the default.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Air {
    /// Pressure, Pa.
    pub pressure_pa: Option<f64>,
    /// Temperature, °C.
    pub temperature_c: Option<f64>,
    /// Relative humidity, 0 to 1.
    pub humidity: Option<f64>,
    /// The temperature the clock was regulated at, °C (default the
    /// temperature's default).
    pub regulated_at_c: Option<f64>,
    /// The gas (default air).
    pub gas: Option<Gas>,
    /// The Q the pendulum would have in a vacuum: its pivot's or
    /// suspension's and the escapement's losses (default: none, so the gas
    /// alone damps it).
    pub pivot_q: Option<f64>,
    /// The semi-arc it swings at this pressure, rad (default: none, so
    /// the arc's share of the barometric error is not given).
    pub amplitude_rad: Option<f64>,
}

/// The largest semi-arc a row of the pressure table may reach, rad (60°):
/// beyond, the drive that keeps the given arc would swing it further than
/// any clock's escapement allows.
pub const MAX_SEMI_ARC_RAD: f64 = std::f64::consts::PI / 3.0;

/// The pressures of the datasheet's table, Pa: a pumped tank to 1.2 bar,
/// with a Shortt clock's tank (27 hPa) and the standard atmosphere; the
/// sheet's own pressure is added in its place. A pressure at which the gas
/// would float the pendulum (a bob no denser than the gas) is left out.
pub const TABLE_PRESSURES_PA: [f64; 11] = [
    1.0, 10.0, 100.0, 1000.0, 2700.0, 10_000.0, 30_000.0, 60_000.0, 80_000.0, 101_325.0, 110_000.0,
];

/// One row of the pressure table.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PressureRow {
    /// Pressure, Pa.
    pub pressure_pa: f64,
    /// The gas's density, kg/m³.
    pub density_kg_m3: f64,
    /// The Q the gas alone gives (none when nothing in the design meets
    /// the gas: point masses on idealised rods).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub q_gas: Option<f64>,
    /// With the pivot's losses (`q_gas` when none are given; at the row's
    /// arc with the form drag when a semi-arc is given).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub q: Option<f64>,
    /// Rate against a vacuum from buoyancy and the carried gas, s/day.
    pub gas_rate_s_per_day: f64,
    /// The semi-arc the drive keeps, degrees (with a semi-arc given; none
    /// where it would pass 60°).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub semi_arc_deg: Option<f64>,
    /// The circular error at that arc against a vanishing arc, s/day.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub circular_rate_s_per_day: Option<f64>,
    /// The two together, against the rate at the datasheet's pressure,
    /// s/day.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rate_change_s_per_day: Option<f64>,
}

/// One part's share of the gas's effect.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PartGas {
    /// Its name.
    pub name: String,
    /// Its added-mass coefficient (gas carried over gas displaced).
    pub added_mass_coefficient: f64,
    /// Its share of the gas's damping, 0 to 1.
    pub damping_share: f64,
}

/// One part's row.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PartRow {
    /// Its name.
    pub name: String,
    /// Its material.
    pub material: String,
    /// Its mass, kg.
    pub mass_kg: f64,
    /// Its centre below the pivot, m.
    pub centre_m: f64,
}

/// A design's datasheet.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Datasheet {
    /// The parts.
    pub parts: Vec<PartRow>,
    /// Mass, kg.
    pub mass_kg: f64,
    /// Centre of mass below the pivot, m.
    pub centre_of_mass_m: f64,
    /// Inertia about the pivot, kg m².
    pub inertia_kg_m2: f64,
    /// Equivalent simple length `I / m d`, m.
    pub equivalent_length_m: f64,
    /// Small swings, in a vacuum, s.
    pub period_s: f64,
    /// Gravity, m/s².
    pub g_m_s2: f64,
    /// Rate change per °C, s/day.
    pub temperature_coefficient_s_per_day_per_c: f64,
    /// At `temperature_c` against `regulated_at_c`, s/day.
    pub temperature_rate_s_per_day: f64,
    /// The rate change per K/m of vertical temperature gradient (warmer
    /// upwards) at a constant temperature half-way down the pendulum,
    /// s/day.
    pub gradient_coefficient_s_per_day_per_k_per_m: f64,
    /// The rate change per percentage point of relative humidity once the
    /// parts that take up water (wood) have settled, s/day (none when no
    /// part takes up water, or in a gas other than air, which is dry).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub humidity_coefficient_s_per_day_per_percent: Option<f64>,
    /// The moisture content wood settles at in the air as given, % (none
    /// when no part takes up water).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub wood_moisture_percent: Option<f64>,
    /// The temperature, °C.
    pub temperature_c: f64,
    /// Where it was regulated, °C.
    pub regulated_at_c: f64,
    /// The air's density, kg/m³.
    pub air_density_kg_m3: f64,
    /// In that air against a vacuum (buoyancy and entrained air), s/day.
    pub air_rate_s_per_day: f64,
    /// Of which buoyancy, s/day.
    pub air_buoyancy_rate_s_per_day: f64,
    /// The change per hPa of pressure at that temperature and humidity
    /// (buoyancy and carried gas, at a constant arc).
    pub pressure_coefficient_s_per_day_per_hpa: f64,
    /// The gas.
    pub gas: Gas,
    /// Its viscosity, Pa s.
    pub gas_viscosity_pa_s: f64,
    /// Its mean free path, m.
    pub mean_free_path_m: f64,
    /// The damping torque per unit angular velocity, N m s.
    pub gas_damping_n_m_s: f64,
    /// The Q the gas's viscous damping alone gives (none when nothing in
    /// the design meets the gas: point masses on idealised rods).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub q_gas: Option<f64>,
    /// The Q of the pivot's losses, as given.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub q_pivot: Option<f64>,
    /// Both together, and at the semi-arc given with the form drag (none
    /// when nothing damps it).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub q: Option<f64>,
    /// Each part's share of the gas's effect.
    pub gas_parts: Vec<PartGas>,
    /// The semi-arc as given, degrees.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub semi_arc_deg: Option<f64>,
    /// The circular error's change per hPa at that semi-arc, as the gas's
    /// damping changes the arc, s/day.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub circular_pressure_coefficient_s_per_day_per_hpa: Option<f64>,
    /// Both changes together, s/day per hPa.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub net_pressure_coefficient_s_per_day_per_hpa: Option<f64>,
    /// The semi-arc at which the circular error's change cancels the
    /// buoyancy's, degrees (none when the gas's damping does not change
    /// with pressure, or the arc would pass 60°).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cancelling_semi_arc_deg: Option<f64>,
    /// The pressure table.
    pub against_pressure: Vec<PressureRow>,
    /// The rating nut: the part with a thread, or the part named `nut`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub nut: Option<String>,
    /// The rate change as the nut (and the bob on it) moves 1 mm down,
    /// s/day (negative: slower).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub nut_rate_s_per_day_per_mm: Option<f64>,
    /// The nut's pitch, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub nut_pitch_m: Option<f64>,
    /// Per turn of the nut lowering the bob, s/day.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub nut_rate_s_per_day_per_turn: Option<f64>,
    /// Per division of the nut, s/day.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub nut_rate_s_per_day_per_division: Option<f64>,
    /// The suspension spring's effect, when the design hangs from one.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub spring: Option<SpringSheet>,
    /// What to check before trusting the sheet.
    pub warnings: Vec<Warning>,
    /// The gas as taken: pressure, Pa.
    pub pressure_pa: f64,
    /// Relative humidity, 0 to 1 (in the JSON `humidity_percent`, %; 0 in
    /// a gas other than air).
    #[serde(rename = "humidity_percent", serialize_with = "as_percent")]
    pub humidity: f64,
}

/// A spring that gives more than this share of the restoring torque is
/// warned of (a regulator's gives about a thousandth).
pub const STIFF_SPRING_SHARE: f64 = 0.05;

/// What a suspension spring does ([`crate::suspension`]).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SpringSheet {
    /// Its bending length `sqrt(EI/T)`, m.
    pub bending_length_m: f64,
    /// The point the pendulum turns about, below the chops, m.
    pub effective_pivot_m: f64,
    /// Its rate against the design rigid about the chops, s/day
    /// (positive: gaining; in the equivalent length and period).
    pub rate_s_per_day: f64,
    /// The elastic share of the restoring stiffness.
    pub elastic_share: f64,
    /// The part of the design's temperature coefficient that its modulus's
    /// change with temperature makes, s/day per °C.
    pub modulus_temperature_coefficient_s_per_day_per_c: f64,
    /// The pendulum rocking on the spring, Hz (none for a point mass).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub second_mode_hz: Option<f64>,
}

/// Checks `value` within `range` (in the unit shown, `scale` times the
/// value's).
fn within(
    field: &'static str,
    value: f64,
    range: (f64, f64),
    scale: f64,
    unit: &str,
) -> Result<f64, Refusal> {
    if (range.0..=range.1).contains(&value) {
        return Ok(value);
    }
    let got = if value.is_finite() {
        format!(", got {}", format_significant(value * scale, 6))
    } else {
        String::new()
    };
    Err(Refusal::field(
        field,
        format!(
            "must lie between {} and {} {unit}{got}",
            range.0 * scale,
            range.1 * scale
        ),
    ))
}

/// `, got V unit` for a finite value, else nothing.
fn shown_got(v: f64, unit: &str) -> String {
    if v.is_finite() {
        format!(", got {}{unit}", format_significant(v, 6))
    } else if v.is_nan() {
        ", got a value that is not a number".to_string()
    } else {
        ", got an infinite value".to_string()
    }
}

/// Seconds in a day.
const DAY: f64 = 86_400.0;

/// A fraction serialised as per cent.
fn as_percent<S: serde::Serializer>(fraction: &f64, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_f64(100.0 * fraction)
}

/// The semi-arc, rad, at which `net(a)` (the barometric coefficient with
/// the arc's change) is zero: scanned from 0.01° to 60° in steps of 5%,
/// then bisected to 1e-9 rad. None without a change of sign.
fn cancelling_arc(net: &dyn Fn(f64) -> f64) -> Option<f64> {
    let mut a = 0.01_f64.to_radians();
    let mut before = net(a);
    while a < MAX_SEMI_ARC_RAD {
        let next = (a * 1.05).min(MAX_SEMI_ARC_RAD);
        let now = net(next);
        if before.is_finite() && now.is_finite() && before.signum() != now.signum() {
            let (mut lo, mut hi) = (a, next);
            for _ in 0..60 {
                let mid = 0.5 * (lo + hi);
                if net(mid).signum() == before.signum() {
                    lo = mid;
                } else {
                    hi = mid;
                }
                if hi - lo < 1e-9 {
                    break;
                }
            }
            return Some(0.5 * (lo + hi));
        }
        before = now;
        a = next;
    }
    None
}

/// The lengthening of the period by the damping, `1/(8Q²)` of a day, s,
/// beyond which a datasheet warns that its rates leave it out (Q below
/// 330).
pub const LOW_Q_SHIFT_S_PER_DAY: f64 = 0.1;

/// The datasheet of `design` under `g` (default standard gravity) in
/// `air`.
pub fn datasheet(design: &Design, g: Option<f64>, air: &Air) -> Result<Datasheet, Refusal> {
    let kind = air.gas.unwrap_or(Gas::Air);
    let (gas, regulated_at) = checked_air(air)?;
    let (p, t, h) = (gas.pressure_pa, gas.temperature_c, gas.humidity);
    let g = crate::analysis::require_finite("g", g.unwrap_or(STANDARD_GRAVITY))?;
    let pendulum = &design.pendulum.in_gravity(g);
    let props = pendulum.properties();
    let period = small_swing_period(props.equivalent_length, g)?;
    let warmer = pendulum
        .at_temperature(t - regulated_at)
        .map_err(|e| Refusal::data(e.to_string()))?
        .properties()
        .equivalent_length;
    let (in_gas, coefficient) = swinging_in(pendulum, &gas, g)?;
    let rates = in_gas.rates;
    let rho = gas.density();
    let drive = KeptArc {
        pendulum,
        gas: &gas,
        g,
        here: &in_gas,
        // The pivot's losses as a damping torque, the same at every pressure.
        pivot: air
            .pivot_q
            .map_or(0.0, |qp| in_gas.inertia * in_gas.omega / qp),
        share: pendulum.spring_effect().map_or(0.0, |e| e.elastic_share),
    };
    let cancelling = cancelling_arc(&|a| drive.net_per_hpa(a)).map(f64::to_degrees);
    let q = crate::analysis::finite(drive.q(&in_gas, air.amplitude_rad));
    let here = air
        .amplitude_rad
        .map(|a| (a, rates.total + drive.circular(a)));
    let against_pressure = drive.pressure_table(here);
    let damping_total = in_gas.damping;
    let nut = nut_rates(design, pendulum);
    Ok(Datasheet {
        parts: part_rows(pendulum),
        mass_kg: props.mass,
        centre_of_mass_m: props.centre_of_mass,
        inertia_kg_m2: props.inertia,
        equivalent_length_m: props.equivalent_length,
        period_s: period,
        g_m_s2: g,
        temperature_coefficient_s_per_day_per_c: pendulum.temperature_coefficient(),
        temperature_rate_s_per_day: rate_of_length_ratio(warmer / props.equivalent_length),
        gradient_coefficient_s_per_day_per_k_per_m: pendulum.gradient_coefficient(),
        // Only air carries a humidity: a dry tank's gas has none to vary.
        humidity_coefficient_s_per_day_per_percent: (kind == Gas::Air)
            .then(|| pendulum.humidity_coefficient(h, t))
            .flatten(),
        wood_moisture_percent: takes_water(pendulum)
            .then(|| crate::moisture::equilibrium_moisture_content(h, t)),
        temperature_c: t,
        regulated_at_c: regulated_at,
        air_density_kg_m3: rho,
        air_rate_s_per_day: rates.total,
        air_buoyancy_rate_s_per_day: rates.buoyancy,
        pressure_coefficient_s_per_day_per_hpa: coefficient,
        gas: kind,
        gas_viscosity_pa_s: gas.viscosity(),
        mean_free_path_m: gas.mean_free_path(),
        gas_damping_n_m_s: damping_total,
        q_gas: crate::analysis::finite(in_gas.q),
        q_pivot: air.pivot_q,
        q,
        gas_parts: gas_parts(pendulum, &in_gas),
        semi_arc_deg: air.amplitude_rad.map(f64::to_degrees),
        circular_pressure_coefficient_s_per_day_per_hpa: air
            .amplitude_rad
            .and_then(|a| crate::analysis::finite(drive.net_per_hpa(a) - coefficient)),
        net_pressure_coefficient_s_per_day_per_hpa: air
            .amplitude_rad
            .and_then(|a| crate::analysis::finite(drive.net_per_hpa(a))),
        cancelling_semi_arc_deg: cancelling,
        against_pressure,
        nut: nut.name,
        nut_rate_s_per_day_per_mm: nut.per_mm,
        nut_pitch_m: nut.pitch,
        nut_rate_s_per_day_per_turn: nut.per_turn,
        nut_rate_s_per_day_per_division: nut.per_division,
        spring: spring_sheet(pendulum),
        warnings: warnings(pendulum, props.equivalent_length, q, air.humidity),
        pressure_pa: p,
        humidity: h,
    })
}

/// The gas `air` describes, its defaults filled in, and the temperature
/// the clock was regulated at, °C; refused when a value is out of its
/// range (the pivot's Q below 1, a semi-arc past 60°).
fn checked_air(air: &Air) -> Result<(GasState, f64), Refusal> {
    let kind = air.gas.unwrap_or(Gas::Air);
    let pressure = air.pressure_pa.unwrap_or(DEFAULT_PRESSURE_PA);
    // Room air pumped down keeps its composition: below the standard
    // pressure the default humidity falls with it.
    let humidity_default = if kind == Gas::Air {
        DEFAULT_HUMIDITY * (pressure / DEFAULT_PRESSURE_PA).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let gas = GasState::new(
        kind,
        pressure,
        air.temperature_c.unwrap_or(DEFAULT_TEMPERATURE_C),
        air.humidity.unwrap_or(humidity_default),
    )?;
    let regulated_at = within(
        "regulated_at",
        air.regulated_at_c.unwrap_or(DEFAULT_TEMPERATURE_C),
        REGULATED_AT_RANGE_C,
        1.0,
        "°C",
    )?;
    if let Some(q) = air.pivot_q {
        if !(q.is_finite() && q >= 1.0) {
            return Err(Refusal::field(
                "pivot_q",
                format!("must be a number of 1 or more{}", shown_got(q, "")),
            ));
        }
    }
    if let Some(a) = air.amplitude_rad {
        if !(a > 0.0 && a <= MAX_SEMI_ARC_RAD) {
            return Err(Refusal::field(
                "amplitude",
                format!(
                    "must be more than 0 and at most 60 degrees (a semi-arc){}",
                    shown_got(a.to_degrees(), "°")
                ),
            ));
        }
    }
    Ok((gas, regulated_at))
}

/// The period of small swings in a vacuum, s, of the simple pendulum of
/// the equivalent length `length`, m, under `g`, m/s²; the refusal names
/// `g` when gravity is at fault, else the design.
fn small_swing_period(length: f64, g: f64) -> Result<f64, Refusal> {
    Ok(Pendulum::new(length, g)
        .map_err(|e| match e.quantity {
            crate::error::Quantity::Gravity => Refusal::input("g", &e),
            _ => Refusal::input("design", &e),
        })?
        .small_angle_period())
}

/// `pendulum` in `gas` under `g`, m/s², and its barometric coefficient,
/// s/day per hPa; refused when the gas floats it (a part no denser than
/// the gas) or damps it below Q 1/2.
fn swinging_in(
    pendulum: &CompoundPendulum,
    gas: &GasState,
    g: f64,
) -> Result<(InGas, f64), Refusal> {
    let in_gas = pendulum.in_gas(gas, g);
    let coefficient = pendulum.pressure_coefficient(gas, g);
    if !(in_gas.rates.total.is_finite() && coefficient.is_finite()) {
        return Err(Refusal::data(format!(
            "in {} at {} hPa the pendulum floats: the gas it displaces weighs as much as it \
             does (a part no denser than the gas)",
            gas.gas.name(),
            format_significant(gas.pressure_pa / 100.0, 6)
        )));
    }
    if in_gas.q < 0.5 {
        return Err(Refusal::data(format!(
            "in this gas the pendulum does not swing: the gas alone damps it to Q {} (below \
             1/2, overdamped){}",
            format_significant(in_gas.q, 3),
            if g < 1e-3 { "; check g" } else { "" }
        )));
    }
    Ok((in_gas, coefficient))
}

/// A clock whose drive keeps a semi-arc at the sheet's pressure: what the
/// arc, the circular error and the rate at another pressure follow from.
struct KeptArc<'a> {
    /// The design, in the sheet's gravity.
    pendulum: &'a CompoundPendulum,
    /// The gas at the sheet's pressure.
    gas: &'a GasState,
    /// Gravity, m/s².
    g: f64,
    /// The design in that gas.
    here: &'a InGas,
    /// The pivot's losses as a damping torque, N m s (0 when none given).
    pivot: f64,
    /// A suspension spring's elastic share of the restoring torque (0
    /// without one).
    share: f64,
}

impl KeptArc<'_> {
    /// The rate of the circular error at semi-arc `a`, rad, s/day (losing:
    /// negative). On a suspension spring the circular error shrinks by its
    /// elastic share ([`crate::suspension::period_ratio`]).
    fn circular(&self, a: f64) -> f64 {
        if self.share > 0.0 {
            return DAY * (1.0 / crate::suspension::period_ratio(a, self.share) - 1.0);
        }
        crate::Amplitude::from_radians(a)
            .map_or(f64::NAN, |a| 0.0 - DAY * crate::period::circular_error(a))
    }

    /// The design in the gas at pressure `pp`, Pa, and the semi-arc, rad,
    /// its drive keeps there when it keeps `a` at the sheet's pressure;
    /// `None` past 60°.
    fn at(&self, pp: f64, a: f64) -> (InGas, Option<f64>) {
        if pp == self.gas.pressure_pa {
            // Here the arc is the one given (not a root found again).
            return (self.here.clone(), Some(a));
        }
        let there = self.pendulum.in_gas(&self.gas.at_pressure(pp), self.g);
        let loss = self.here.loss_over_arc_squared(a, self.pivot);
        if loss.is_nan() || loss <= 0.0 {
            // Nothing damps it: nothing changes its arc.
            return (there, Some(a));
        }
        let arc = there.arc_for_loss_of(self.here, a, self.pivot);
        (there, (arc <= MAX_SEMI_ARC_RAD).then_some(arc))
    }

    /// The barometric coefficient, s/day per hPa, of the gas and the
    /// circular error together as the arc kept at `a`, rad, changes with
    /// the pressure: a central difference of ±1% of the pressure.
    fn net_per_hpa(&self, a: f64) -> f64 {
        let p = self.gas.pressure_pa;
        let rate = |f: f64| match self.at(p * f, a) {
            (there, Some(arc)) => there.rates.total + self.circular(arc),
            (_, None) => f64::NAN,
        };
        (rate(1.01) - rate(0.99)) / (0.02 * p) * 100.0
    }

    /// The Q of the design in the gas `there` with the pivot's losses: at
    /// a vanishing arc, or at the semi-arc `arc`, rad, with the form drag.
    fn q(&self, there: &InGas, arc: Option<f64>) -> f64 {
        arc.map_or(
            there.inertia * there.omega / (there.damping + self.pivot),
            |a| there.q_at(a, self.pivot),
        )
    }

    /// The row of the pressure table at `pp`, Pa: with the arc the drive
    /// keeps there when `here` (the semi-arc given, rad, and the rate at
    /// it, s/day) is, and the rate's change against `here`'s.
    fn pressure_row(&self, pp: f64, here: Option<(f64, f64)>) -> PressureRow {
        let (there, arc) = match here {
            Some((a, _)) => self.at(pp, a),
            None => (
                self.pendulum.in_gas(&self.gas.at_pressure(pp), self.g),
                None,
            ),
        };
        PressureRow {
            pressure_pa: pp,
            density_kg_m3: self.gas.at_pressure(pp).density(),
            q_gas: crate::analysis::finite(there.q),
            q: crate::analysis::finite(self.q(&there, arc)),
            gas_rate_s_per_day: there.rates.total,
            semi_arc_deg: arc.map(f64::to_degrees),
            circular_rate_s_per_day: arc.map(|a| self.circular(a)),
            rate_change_s_per_day: arc
                .zip(here)
                .map(|(a, (_, r0))| there.rates.total + self.circular(a) - r0),
        }
    }

    /// The pressure table: a row at each of [`TABLE_PRESSURES_PA`] and at
    /// the sheet's own pressure, in order, leaving out the pressures at
    /// which the gas floats the pendulum; `here` as for
    /// [`KeptArc::pressure_row`].
    fn pressure_table(&self, here: Option<(f64, f64)>) -> Vec<PressureRow> {
        let p = self.gas.pressure_pa;
        let mut pressures: Vec<f64> = TABLE_PRESSURES_PA.to_vec();
        if !pressures.contains(&p) {
            pressures.push(p);
            pressures.sort_by(f64::total_cmp);
        }
        pressures
            .iter()
            .map(|&pp| self.pressure_row(pp, here))
            .filter(|r| r.gas_rate_s_per_day.is_finite() && r.q_gas.is_none_or(f64::is_finite))
            .collect()
    }
}

/// The rating nut's lines of the datasheet, each `None` unless the nut
/// moves the rate.
struct NutRates {
    /// The nut's name.
    name: Option<String>,
    /// The rate change as it moves 1 mm down, s/day.
    per_mm: Option<f64>,
    /// Its thread's pitch, m.
    pitch: Option<f64>,
    /// The rate change per turn, s/day.
    per_turn: Option<f64>,
    /// The rate change per division, s/day.
    per_division: Option<f64>,
}

/// The rating nut of `design` (the part with a thread, or the part named
/// `nut`) and the rate change, s/day, per mm, per turn and per division
/// as it moves `pendulum`'s bob down.
fn nut_rates(design: &Design, pendulum: &CompoundPendulum) -> NutRates {
    let nut = design
        .thread
        .map(|th| th.part)
        .or_else(|| pendulum.parts().iter().position(|q| q.name == "nut"));
    let per_metre = nut.and_then(|i| pendulum.rate_per_metre(i));
    let pitch = design.thread.map(|th| th.pitch);
    let per_turn = per_metre.zip(pitch).map(|(r, p)| r * p);
    let per_division = per_turn.zip(design.thread.and_then(|th| th.divisions));
    NutRates {
        name: per_metre.and(nut).map(|i| pendulum.parts()[i].name.clone()),
        per_mm: per_metre.map(|r| r * 1e-3),
        pitch: per_metre.and(pitch),
        per_turn,
        per_division: per_division.map(|(r, d)| r / f64::from(d)),
    }
}

/// Whether any part of `pendulum` takes up water (wood).
fn takes_water(pendulum: &CompoundPendulum) -> bool {
    pendulum
        .parts()
        .iter()
        .any(|q| q.material.moisture_expansion.is_some())
}

/// Each part's row: its name, material, mass, kg, and centre below the
/// pivot, m.
fn part_rows(pendulum: &CompoundPendulum) -> Vec<PartRow> {
    pendulum
        .parts()
        .iter()
        .zip(pendulum.centres())
        .map(|(q, &c)| PartRow {
            name: q.name.clone(),
            material: q.material.name.clone(),
            mass_kg: q.mass(),
            centre_m: c,
        })
        .collect()
}

/// Each part's share of the gas's effect `in_gas`: its added-mass
/// coefficient and its share of the damping (0 when nothing damps).
fn gas_parts(pendulum: &CompoundPendulum, in_gas: &InGas) -> Vec<PartGas> {
    let damping_total = in_gas.damping;
    pendulum
        .parts()
        .iter()
        .zip(&in_gas.parts)
        .map(|(part, f)| PartGas {
            name: part.name.clone(),
            added_mass_coefficient: f.added_mass_coefficient,
            damping_share: if damping_total > 0.0 {
                f.damping / damping_total
            } else {
                0.0
            },
        })
        .collect()
}

/// What `pendulum`'s suspension spring does, when it hangs from one: its
/// bending length, pivot and rate, and the temperature coefficient its
/// modulus makes, s/day per °C.
fn spring_sheet(pendulum: &CompoundPendulum) -> Option<SpringSheet> {
    pendulum.spring_effect().map(|e| SpringSheet {
        bending_length_m: e.bending_length,
        effective_pivot_m: e.effective_pivot,
        rate_s_per_day: e.rate,
        elastic_share: e.elastic_share,
        modulus_temperature_coefficient_s_per_day_per_c: pendulum.temperature_coefficient()
            - pendulum
                .without_spring_thermoelasticity()
                .temperature_coefficient(),
        second_mode_hz: e.second_mode_hz,
    })
}

/// The sheet's warnings, in order: an `equivalent_length`, m, longer
/// than any clock's, a stiff suspension spring, a Q `q` so low that the
/// damping moves the period, a `humidity` of 1% or less (a fraction of 1
/// given for a percentage?), and each part that takes up water but is no
/// rod.
fn warnings(
    pendulum: &CompoundPendulum,
    equivalent_length: f64,
    q: Option<f64>,
    humidity: Option<f64>,
) -> Vec<Warning> {
    let length = crate::pendulum::length_warning(equivalent_length)
        .map(|w| Warning::new("length_implausible", w, Some("equivalent_length_m")));
    let spring =
        stiff_spring_warning(pendulum).map(|w| Warning::new("stiff_spring", w, Some("spring")));
    length
        .into_iter()
        .chain(spring)
        .chain(
            q.map(|q| (q, DAY / (8.0 * q * q)))
                .filter(|&(_, shift)| shift >= LOW_Q_SHIFT_S_PER_DAY)
                .map(|(q, shift)| {
                    Warning::new(
                        "low_q",
                        format!(
                            "Q {} is far below a clock pendulum's: the damping itself \
                             lengthens the period by 1/(8Q²), {} s/day, which the rates \
                             here leave out",
                            crate::error::format_significant(q, 3),
                            crate::error::format_significant(shift, 3)
                        ),
                        Some("q"),
                    )
                }),
        )
        .chain(humidity.filter(|&h| h > 0.0 && h <= 0.01).map(|h| {
            let said = crate::gas::per_cent_warning(&format!(
                "the humidity is {} %",
                crate::error::format_significant(100.0 * h, 3)
            ));
            Warning::new("per_cent_as_fraction", said, Some("humidity"))
        }))
        .chain(across_grain(pendulum).map(|name| {
            let said = format!(
                "'{name}' takes up water but is not a rod (a cylinder five times as long \
                 as it is wide): only its growth along its \
                 length (wood's along the grain) is modelled, not the 20 to 40 times larger \
                 swelling across the grain"
            );
            Warning::new(
                "swelling_across_grain",
                said,
                Some("humidity_coefficient_s_per_day_per_percent"),
            )
        }))
        .collect()
}

/// The warning of a suspension spring that gives more than
/// [`STIFF_SPRING_SHARE`] of the restoring torque, if `pendulum` hangs
/// from one.
fn stiff_spring_warning(pendulum: &CompoundPendulum) -> Option<String> {
    pendulum.spring_effect().and_then(|e| {
        (e.elastic_share > STIFF_SPRING_SHARE).then(|| {
            format!(
                "the suspension spring is stiff: it gives {}% of the restoring torque \
                 (its bending length {} mm); the pendulum bends it rather than turning \
                 about it, and its temperature and its fatigue dominate the rate",
                crate::error::format_significant(100.0 * e.elastic_share, 3),
                crate::error::format_significant(1e3 * e.bending_length, 3)
            )
        })
    })
}

/// The names of `pendulum`'s parts with mass that take up water but are
/// no rod, so swell across their grain.
fn across_grain(pendulum: &CompoundPendulum) -> impl Iterator<Item = String> + '_ {
    pendulum
        .parts()
        .iter()
        .filter(|q| {
            // A rod is a cylinder at least five times as long as it is
            // wide, its grain along it.
            q.material.moisture_expansion.is_some()
                && !q.massless
                && !matches!(q.shape, super::Shape::Cylinder { length, diameter, .. }
                    if length >= 5.0 * diameter)
        })
        .map(|q| q.name.clone())
}
