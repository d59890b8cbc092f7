//! The real pendulum against closed forms computed here and published
//! figures (each test names its source).

use crate::common;

use common::parts::part;
use pendulum_theory::compound::{CompoundPendulum, Material, Part, Placement, Shape};
use pendulum_theory::gas::{Gas, GasState};
use pendulum_theory::train::beats_per_hour;

fn rod(length: f64, diameter: f64, material: &str) -> Part {
    part(
        "rod",
        Shape::Cylinder {
            length,
            diameter,
            bore: 0.0,
        },
        material,
        Placement::Centre(0.5 * length),
    )
}

#[test]
fn a_uniform_rod_alone() {
    // I = m (L²/3 + D²/16) about its end, d = L/2: l = 2L/3 + D²/(8L).
    let (l, d) = (1.2, 0.006);
    let p = CompoundPendulum::new(vec![rod(l, d, "steel")])
        .unwrap()
        .properties();
    let expected = 2.0 * l / 3.0 + d * d / (8.0 * l);
    assert!((p.equivalent_length - expected).abs() < 4.0 * f64::EPSILON * expected);
    let mass = 7850.0 * std::f64::consts::PI / 4.0 * d * d * l;
    assert!((p.mass - mass).abs() < 4.0 * f64::EPSILON * mass);
}

#[test]
fn rod_and_disc_by_the_parallel_axis_theorem() {
    let (l, d) = (1.0, 0.008);
    let (dd, t, c) = (0.2, 0.01, 0.95);
    let p = CompoundPendulum::new(vec![
        rod(l, d, "steel"),
        part(
            "bob",
            Shape::Disc {
                diameter: dd,
                thickness: t,
            },
            "brass",
            Placement::Centre(c),
        ),
    ])
    .unwrap()
    .properties();
    let pi = std::f64::consts::PI;
    let m_rod = 7850.0 * pi * d * d / 4.0 * l;
    let m_disc = 8500.0 * pi * dd * dd / 4.0 * t;
    let i = m_rod * (l * l / 3.0 + d * d / 16.0) + m_disc * (dd * dd / 8.0 + c * c);
    let moment = m_rod * l / 2.0 + m_disc * c;
    let expected = i / moment;
    assert!((p.equivalent_length - expected).abs() < 8.0 * f64::EPSILON * expected);
}

#[test]
fn a_point_bob_on_a_massless_rod_is_the_simple_pendulum() {
    let mut r = rod(1.0, 0.005, "steel");
    r.massless = true;
    let bob = Part {
        name: "bob".into(),
        shape: Shape::Point,
        material: Material::named("brass").unwrap(),
        point_mass: 1.0,
        placement: Placement::Centre(0.99362),
        massless: false,
        time_constant: 0.0,
        moisture_time_constant: 0.0,
    };
    let p = CompoundPendulum::new(vec![r, bob]).unwrap();
    let props = p.properties();
    assert!((props.equivalent_length - 0.99362).abs() <= f64::EPSILON * 0.99362);
    // The figure horological texts quote (e.g. Rawlings, The Science of
    // Clocks and Watches): a steel rod (α = 11.5e-6/°C) loses about half a second a day per °C,
    // 86400 α / 2 = 0.497 s/day.
    let c = p.temperature_coefficient();
    assert!((c + 0.497).abs() < 0.001, "{c}");
}

#[test]
fn the_seconds_train() {
    // The long-case going train (as in Rawlings, The Science of Clocks and
    // Watches): centre wheel 64 into an
    // 8-leaf pinion, third wheel 60 into 8, a 30-tooth escape wheel, the
    // centre arbor turning once an hour: 3,600 beats an hour, a 2 s
    // period, a seconds pendulum 0.99362 m long at standard gravity.
    let bph = beats_per_hour(&[64, 60, 30], &[8, 8], 1.0).unwrap();
    assert_eq!(bph, 3600.0);
    let period = 2.0 * 3600.0 / bph;
    let g = 9.80665;
    let length = g * period * period / (4.0 * std::f64::consts::PI * std::f64::consts::PI);
    assert!((length - 0.99362).abs() < 5e-6, "{length}");
}

/// A seconds pendulum: steel rod, brass cylinder bob on a steel nut.
fn regulator() -> CompoundPendulum {
    CompoundPendulum::new(vec![
        rod(1.0, 0.008, "steel"),
        part(
            "nut",
            Shape::Cylinder {
                length: 0.01,
                diameter: 0.015,
                bore: 0.0,
            },
            "steel",
            Placement::Centre(0.995),
        ),
        part(
            "bob",
            Shape::Cylinder {
                length: 0.15,
                diameter: 0.08,
                bore: 0.008,
            },
            "brass",
            Placement::RestsOn(1),
        ),
    ])
    .unwrap()
}

#[test]
fn buoyancy_and_the_barometer() {
    // Buoyancy of a brass bob (8,500 kg/m³) in air of 1.2 kg/m³: the
    // restoring weight falls by 1.2/8500, the clock slows by
    // 86400 × 1.2/8500 / 2 = 6.1 s/day (the figure quoted with Matthys,
    // Accurate Clock Pendulums, 2004).
    let bob = CompoundPendulum::new(vec![part(
        "bob",
        Shape::Sphere { diameter: 0.1 },
        "brass",
        Placement::Centre(0.99),
    )])
    .unwrap();
    let air = |p: f64| GasState::new(Gas::Air, p, 20.0, 0.5).unwrap();
    let g = 9.80665;
    // 1.2 kg/m³ is air at 1,014 hPa, 20 °C and 50%.
    assert!((air(101_420.0).density() - 1.2).abs() < 1e-3);
    let b = bob.in_gas(&air(101_420.0), g).rates.buoyancy;
    assert!((b + 6.1).abs() < 0.05, "{b}");
    // The barometric coefficient of a brass-bob seconds pendulum, per inch
    // of mercury (3386.39 Pa) at 20 °C and 50%: Matthys measured 0.2 to
    // 0.4 s/day per inHg on real regulators; buoyancy alone is 0.20.
    let clock = regulator();
    let inhg = 3386.39;
    let (low, high) = (101_325.0 - inhg / 2.0, 101_325.0 + inhg / 2.0);
    let rates = |p: f64| clock.in_gas(&air(p), g).rates;
    let total = rates(high).total - rates(low).total;
    let buoyancy = rates(high).buoyancy - rates(low).buoyancy;
    eprintln!("per inHg: total {total:.3}, buoyancy {buoyancy:.3} s/day");
    assert!((-0.5..=-0.2).contains(&total), "{total}");
    assert!((buoyancy + 0.20).abs() < 0.02, "{buoyancy}");
}

#[test]
fn regulation_by_the_nut() {
    let clock = regulator();
    let l = clock.properties().equivalent_length;
    // Gaining 12 s/day: lengthen by l ((1 + 12/86400)² - 1) ≈ 0.276 mm
    // for a simple pendulum; the bob moves by about that.
    let shift = clock.regulation(1, 12.0).unwrap();
    let simple = l * ((1.0 + 12.0 / 86_400.0_f64).powi(2) - 1.0);
    assert!(
        shift > 0.0 && (shift / simple - 1.0).abs() < 0.1,
        "{shift} {simple}"
    );
}

#[test]
fn bad_designs_are_refused_naming_the_part_and_field() {
    let e = CompoundPendulum::new(vec![rod(-1.0, 0.01, "steel")]).unwrap_err();
    assert_eq!((e.part.as_str(), e.field), ("rod", "length"));
    let e = CompoundPendulum::new(vec![part(
        "bob",
        Shape::Sphere { diameter: 0.1 },
        "brass",
        Placement::Centre(0.02),
    )])
    .unwrap_err();
    assert_eq!((e.part.as_str(), e.field), ("bob", "centre"));
    assert!(Material::named("unobtainium").is_none());
}

/// Warming changes sizes, never mass; a bob resting on a nut that does not
/// move rises as it grows, so the clock gains (a positive coefficient).
#[test]
fn warming_keeps_the_mass_and_a_rising_bob_gains() {
    let zero = Material {
        name: "zero".into(),
        density: 7850.0,
        expansion: 0.0,
        liquid: false,
        modulus: None,
        modulus_coefficient: None,
        moisture_expansion: None,
    };
    let mut r = rod(1.1, 0.008, "steel");
    r.material = zero.clone();
    let mut nut = part(
        "nut",
        Shape::Cylinder {
            length: 0.012,
            diameter: 0.016,
            bore: 0.0,
        },
        "steel",
        Placement::Centre(1.077),
    );
    nut.material = zero;
    let bob = part(
        "bob",
        Shape::Cylinder {
            length: 0.14,
            diameter: 0.08,
            bore: 0.0085,
        },
        "brass",
        Placement::RestsOn(1),
    );
    let p = CompoundPendulum::new(vec![r, nut, bob]).unwrap();
    let (m0, m1) = (
        p.properties().mass,
        p.at_temperature(10.0).unwrap().properties().mass,
    );
    assert!((m1 / m0 - 1.0).abs() < 1e-14, "{m0} {m1}");
    assert!(p.temperature_coefficient() > 0.0);
}

/// Graham's mercury jar against the first-order condition derived here
/// by hand. Everything but the mercury is massless (the jar of a density
/// 1e-9 kg/m³); the rod of steel (α_s) carries the stirrup down, the jar's
/// bottom (thickness w, α_j) and the mercury's height H = h (1 + βΔ) /
/// (1 + α_j Δ)² (β its volume expansion, the width following the jar) and
/// diameter d = (D - 2w)(1 + α_j Δ) rise from it. With the mercury's
/// centre c and k² = H²/12 + d²/16, l = c + k²/c, and dl/dΔ = dc (1 -
/// k²/c²) + dk²/c with dc = (R - s) α_s - w α_j - h (β - 2α_j)/2 and dk² =
/// h² (β - 2α_j)/6 + (D - 2w)² α_j/8; its zero in h is found here by
/// bisection and must match the library's height.
#[test]
fn the_mercury_jar_against_the_first_order_condition() {
    let (r, s_len, big_d, w) = (1.0, 0.01, 0.06, 0.003);
    let steel = Material::named("steel").unwrap();
    let beta = Material::named("mercury").unwrap().expansion;
    let jar = Material {
        name: "light glass".into(),
        density: 1e-9,
        expansion: 9e-6,
        liquid: false,
        modulus: None,
        modulus_coefficient: None,
        moisture_expansion: None,
    };
    let mut rod_part = rod(r, 0.008, "steel");
    rod_part.massless = true;
    let mut stirrup = part(
        "stirrup",
        Shape::Cylinder {
            length: s_len,
            diameter: 0.02,
            bore: 0.0,
        },
        "steel",
        Placement::Centre(r - 0.5 * s_len),
    );
    stirrup.massless = true;
    let bob = part(
        "bob",
        Shape::Cylinder {
            length: 0.1,
            diameter: big_d,
            bore: 0.0,
        },
        "brass",
        Placement::RestsOn(1),
    );
    let design = CompoundPendulum::new(vec![rod_part, stirrup, bob]).unwrap();
    let (compensated, h) = design.with_mercury_jar(2, &jar, big_d, w).unwrap();

    let (a_s, a_j) = (steel.expansion, jar.expansion);
    let slope = |h: f64| {
        let top = (r - s_len) - w;
        let c = top - 0.5 * h;
        let inner = big_d - 2.0 * w;
        let k2 = h * h / 12.0 + inner * inner / 16.0;
        let dc = (r - s_len) * a_s - w * a_j - 0.5 * h * (beta - 2.0 * a_j);
        let dk2 = h * h * (beta - 2.0 * a_j) / 6.0 + inner * inner * a_j / 8.0;
        dc * (1.0 - k2 / (c * c)) + dk2 / c
    };
    let (mut lo, mut hi) = (1e-3, 0.5);
    assert!(slope(lo) > 0.0 && slope(hi) < 0.0);
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if slope(mid) > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let expected = 0.5 * (lo + hi);
    assert!(
        (h / expected - 1.0).abs() < 1e-8,
        "library {h}, by hand {expected}"
    );
    assert!(compensated.temperature_coefficient().abs() < 1e-6);
    // The mercury's mass stays put as it warms; its level rises.
    let warm = compensated.at_temperature(10.0).unwrap();
    let mass = |p: &CompoundPendulum| p.parts()[4].mass();
    assert!((mass(&warm) / mass(&compensated) - 1.0).abs() < 1e-12);
    let Shape::Cylinder { length, .. } = warm.parts()[4].shape else {
        panic!("the mercury is a cylinder");
    };
    let rise = h * ((1.0 + 10.0 * beta) / (1.0 + 10.0 * a_j).powi(2));
    assert!((length / rise - 1.0).abs() < 1e-14);
}

/// A liquid placed by its centre, or as a disc, is refused: it rests on
/// its jar's bottom.
#[test]
fn a_liquid_must_rest_in_its_jar() {
    let mercury = part(
        "mercury",
        Shape::Cylinder {
            length: 0.1,
            diameter: 0.05,
            bore: 0.0,
        },
        "mercury",
        Placement::Centre(0.9),
    );
    let e = CompoundPendulum::new(vec![rod(1.0, 0.008, "steel"), mercury]).unwrap_err();
    assert_eq!((e.part.as_str(), e.field), ("mercury", "rests_on"));
}

/// A point bob of mass m at x on a uniform rod (mass M_r, length L,
/// diameter D): l(x) = (M_r (L²/3 + D²/16) + m x²) / (M_r L/2 + m x), so
/// moving the bob down changes the rate by -43200 l'(x) / l s/day per
/// metre, with l'(x) by the quotient rule; and the effective mass M d / l
/// gives the swing's energy M g d (1 - cos A) as m_eff g l (1 - cos A).
#[test]
fn the_nut_rate_and_the_effective_mass_by_hand() {
    let (big_l, dia, x, m) = (1.1, 0.008, 0.99, 4.0);
    let bob = Part {
        name: "bob".into(),
        shape: Shape::Point,
        material: Material::named("brass").unwrap(),
        point_mass: m,
        placement: Placement::Centre(x),
        massless: false,
        time_constant: 0.0,
        moisture_time_constant: 0.0,
    };
    let p = CompoundPendulum::new(vec![rod(big_l, dia, "steel"), bob]).unwrap();
    let m_r = 7850.0 * std::f64::consts::PI / 4.0 * dia * dia * big_l;
    let num = m_r * (big_l * big_l / 3.0 + dia * dia / 16.0) + m * x * x;
    let den = m_r * big_l / 2.0 + m * x;
    let l = num / den;
    let slope = (2.0 * m * x * den - m * num) / (den * den);
    let expected = -43_200.0 * slope / l;
    let got = p.rate_per_metre(1).unwrap();
    assert!(
        (got / expected - 1.0).abs() < 1e-7,
        "{got} against {expected}"
    );
    let props = p.properties();
    let energy = (m_r + m) * 9.80665 * (den / (m_r + m)) * (1.0 - 0.05_f64.cos());
    let simple = props.effective_mass() * 9.80665 * l * (1.0 - 0.05_f64.cos());
    assert!((simple / energy - 1.0).abs() < 1e-13);
}
