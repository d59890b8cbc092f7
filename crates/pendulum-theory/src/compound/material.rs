//! Materials: density and linear thermal expansion.
//!
//! Values at room temperature (about 20 °C). Sources: densities and
//! expansion coefficients of metals from the CRC Handbook of Chemistry and
//! Physics (97th ed., 2016, "Thermal expansion of metals and alloys" and
//! "Density of ... elements"); Invar 36 from the NIST Cryogenic Materials
//! Properties tables and Carpenter Technology's Invar 36 datasheet
//! (1.2-1.6e-6/K at 20-100 °C annealed; 1.3e-6 taken for "invar
//! annealed", and [`AGED_INVAR_EXPANSION`] for "invar", the aged rod a
//! pendulum has); type 304 stainless steel 8000 kg/m³ and 17.3e-6/K (AK
//! Steel's 304/304L datasheet, 0-100 °C); mercury's *volume*
//! expansion 1.82e-4/K (CRC), which is what a mercury jar uses; fused
//! silica from Heraeus's datasheet (0.55e-6/K); soda-lime glass (a mercury
//! jar) 2500 kg/m³ and 9.0e-6/K (Schott's and Corning's soda-lime data,
//! 8.5-9.5e-6/K); wood along the grain from
//! the USDA Wood Handbook (FPL-GTR-190, 2010, ch. 4: 3.1e-6 to 4.5e-6/K for
//! dry wood parallel to the grain; 3.5e-6 taken, density 600 kg/m³ as for
//! dry oak or hard maple; its growth with the water it takes up is
//! [`crate::moisture`]'s); carbon-fibre epoxy (unidirectional, along the
//! fibres) from typical manufacturers' data (-0.5e-6 to 0.5e-6/K; 0.0
//! taken, density 1600 kg/m³). Clock steel (a plain carbon steel rod):
//! 11.5e-6/K, the figure the horological literature uses (Rawlings, "The
//! Science of Clocks and Watches", 3rd ed., 1993).

/// Invar's expansion as a pendulum's rod shows it after years, 1/K: 0.65e-6.
/// From E. T. Hall's Littlemore clock ("The Littlemore Clock",
/// Horological Science Newsletter, June 1996): its rod and bob of Invar
/// then 15 years old were compensated, "found by experiment to give a
/// minimum temperature coefficient", by a slug of 45.5 mm of Invar and
/// 38.5 mm of type 304 stainless steel (17.3e-6/K) under the bob's support
/// point 84 mm up inside it; the rod's 1.04 m of fall that the slug's rise
/// must cancel, `α (1090 - 45.5 - 6) mm = 38.5 mm × 17.3e-6`, gives 0.64e-6,
/// and the whole design in this crate's model is compensated to 0.0024
/// s/day per °C at 0.65e-6 (`tests/all/materials.rs`; the sizes Hall did not
/// give make it uncertain by about 0.1e-6). Annealed Invar as supplied is 1.2e-6 to 1.6e-6
/// (Carpenter's Invar 36 datasheet; NIST's cryogenic tables): "invar
/// annealed", 1.3e-6. Invar's expansion falls as it ages after annealing
/// (Matthys, Accurate Clock Pendulums, 2004, ch. 22 and 23).
pub const AGED_INVAR_EXPANSION: f64 = 0.65e-6;

/// A material of a pendulum part.
#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    /// Its name.
    pub name: String,
    /// Density, kg/m³.
    pub density: f64,
    /// Linear thermal expansion coefficient, 1/K; for a liquid, the volume
    /// coefficient.
    pub expansion: f64,
    /// A liquid (mercury): it takes the width of its jar (the part it
    /// rests on, whose expansion sets that width) and rises as its volume
    /// grows.
    pub liquid: bool,
    /// Young's modulus, Pa, where known (a suspension spring needs it).
    pub modulus: Option<f64>,
    /// The modulus's temperature coefficient `(1/E) dE/dT`, 1/K, where
    /// known (a suspension spring's own temperature effect).
    pub modulus_coefficient: Option<f64>,
    /// Its growth along its length per percentage point of moisture
    /// content it takes up, 1/% (wood along the grain,
    /// [`crate::moisture::WOOD_MOISTURE_EXPANSION`]); `None` for what takes
    /// up no water.
    pub moisture_expansion: Option<f64>,
}

/// The elastic constants of the table's materials that springs are made
/// of: (name, Young's modulus Pa, its temperature coefficient 1/K where
/// known). Moduli of spring materials from PTC's spring-design table
/// ("Modulus of elasticity values for non-compression springs": music
/// wire 29.0e6 psi, stainless 302/304/316 28.0e6, spring brass 15.0e6);
/// Invar 36 145 GPa (its makers' datasheets; NIST's cryogenic fit gives
/// 152 GPa at 293 K); fused silica 72 GPa. Temperature coefficients: a
/// spring steel (C70 wire) -2.5e-4/K and fused silica +1.52e-4/K, as the
/// Advanced LIGO suspension parameters give them (pygwinc,
/// `ifo/aLIGO/ifo.yaml`, `dlnEdT`); the others are not in the table: give
/// them as a material's `modulus_coefficient`.
pub const ELASTIC: [(&str, f64, Option<f64>); 5] = [
    ("steel", 200e9, Some(-2.5e-4)),
    ("stainless steel", 193e9, None),
    ("brass", 103e9, None),
    ("invar", 145e9, None),
    ("fused silica", 72e9, Some(1.52e-4)),
];

/// The built-in table: (name, density kg/m³, expansion 1/K).
pub const TABLE: [(&str, f64, f64); 15] = [
    ("steel", 7850.0, 11.5e-6),
    ("invar", 8050.0, AGED_INVAR_EXPANSION),
    ("invar annealed", 8050.0, 1.3e-6),
    ("stainless steel", 8000.0, 17.3e-6),
    ("brass", 8500.0, 19.0e-6),
    ("aluminium", 2700.0, 23.1e-6),
    ("zinc", 7140.0, 30.2e-6),
    ("lead", 11_340.0, 28.9e-6),
    ("mercury", 13_534.0, 182.0e-6),
    ("cast iron", 7200.0, 10.5e-6),
    ("fused silica", 2200.0, 0.55e-6),
    ("wood", 600.0, 3.5e-6),
    ("carbon fibre", 1600.0, 0.0),
    ("copper", 8960.0, 16.5e-6),
    ("glass", 2500.0, 9.0e-6),
];

/// The liquids of the table.
const LIQUIDS: [&str; 1] = ["mercury"];

impl Material {
    /// A material from the built-in table, by name (case and spaces or
    /// hyphens ignored; "aluminum" and "carbon fiber" accepted).
    pub fn named(name: &str) -> Option<Self> {
        let key: String = name
            .to_ascii_lowercase()
            .chars()
            .filter(|c| c.is_ascii_alphanumeric())
            .collect();
        let key = match key.as_str() {
            "aluminum" => "aluminium".to_string(),
            "carbonfiber" => "carbonfibre".to_string(),
            _ => key,
        };
        TABLE
            .iter()
            .find(|(n, _, _)| n.replace(' ', "") == key)
            .map(|&(n, density, expansion)| {
                let elastic = ELASTIC.iter().find(|e| e.0 == n);
                Self {
                    name: n.to_string(),
                    density,
                    expansion,
                    liquid: LIQUIDS.contains(&n),
                    modulus: elastic.map(|e| e.1),
                    modulus_coefficient: elastic.and_then(|e| e.2),
                    moisture_expansion: (n == "wood")
                        .then_some(crate::moisture::WOOD_MOISTURE_EXPANSION),
                }
            })
    }

    /// The names in the table, for messages.
    pub fn names() -> Vec<&'static str> {
        TABLE.iter().map(|t| t.0).collect()
    }
}
