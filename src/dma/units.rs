//! Units of the quantities a DMA export holds, parsed from the text written in the file (or given on
//! the command line) and converted once to SI: moduli → Pa, frequency → Hz, temperature → °C (the
//! interface unit of `Measurement`), phase angle → rad. A unit that is not in these tables is an
//! error, never a guess.

use std::f64::consts::PI;

/// Unit of a modulus column.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ModulusUnit {
    /// Pascal (also N/m²).
    Pa,
    /// Kilopascal.
    KPa,
    /// Megapascal (also N/mm²).
    MPa,
    /// Gigapascal.
    GPa,
    /// Pound-force per square inch.
    Psi,
    /// Dyne per square centimetre (CGS, older rheometer software and RepTate files): 0.1 Pa.
    DynPerCm2,
}

/// Unit of a frequency column.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FreqUnit {
    /// Hertz (cycles per second).
    Hz,
    /// Kilohertz.
    KHz,
    /// Angular frequency ω in rad/s: f = ω / 2π.
    RadPerS,
}

/// Unit of a temperature column.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TempUnit {
    /// Degree Celsius.
    Celsius,
    /// Kelvin: T(°C) = T(K) − 273.15.
    Kelvin,
}

/// Unit of a phase-angle column.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum AngleUnit {
    /// Degree.
    Degree,
    /// Radian.
    Radian,
}

/// Accepted spellings, for messages.
pub const MODULUS_UNITS: &str = "Pa, kPa, MPa, GPa, N/m², N/mm², psi, dyn/cm²";
/// Accepted spellings, for messages.
pub const FREQ_UNITS: &str = "Hz, kHz, rad/s";
/// Accepted spellings, for messages.
pub const TEMP_UNITS: &str = "°C, C, degC, K";
/// Accepted spellings, for messages.
pub(crate) const ANGLE_UNITS: &str = "°, deg, rad";

/// Strip brackets, spaces and the usual look-alikes of the degree sign; keeps case (mPa ≠ MPa).
pub(crate) fn clean_unit(s: &str) -> String {
    let mut t = s.trim();
    loop {
        let b = t.as_bytes();
        if b.len() >= 2
            && ((b[0] == b'[' && b[b.len() - 1] == b']')
                || (b[0] == b'(' && b[b.len() - 1] == b')'))
        {
            t = t[1..t.len() - 1].trim();
        } else {
            break;
        }
    }
    t.chars()
        .filter(|c| !c.is_whitespace())
        .map(|c| match c {
            'º' | '˚' | '�' => '°',
            '℃' => 'C',
            '²' => '2',
            '·' | '*' => '.',
            _ => c,
        })
        .collect::<String>()
        .replace("°C", "C")
        .replace("℃", "C")
}

impl ModulusUnit {
    /// Parse a unit as written in a file or on the command line.
    pub fn parse(s: &str) -> Option<Self> {
        Some(match clean_unit(s).as_str() {
            "Pa" | "N/m2" | "N/m^2" => ModulusUnit::Pa,
            "kPa" | "KPa" => ModulusUnit::KPa,
            "MPa" | "N/mm2" | "N/mm^2" => ModulusUnit::MPa,
            "GPa" => ModulusUnit::GPa,
            "psi" => ModulusUnit::Psi,
            "dyn/cm2" | "dyn/cm^2" | "dyne/cm2" => ModulusUnit::DynPerCm2,
            _ => return None,
        })
    }
    /// Factor to Pa.
    pub(crate) fn to_pa(self) -> f64 {
        match self {
            ModulusUnit::Pa => 1.0,
            ModulusUnit::KPa => 1e3,
            ModulusUnit::MPa => 1e6,
            ModulusUnit::GPa => 1e9,
            // 1 lbf/in² = 4.4482216152605 N / (0.0254 m)² (exact by definition of lb and in).
            ModulusUnit::Psi => 4.448_221_615_260_5 / (0.0254 * 0.0254),
            // 1 dyn = 1e-5 N, 1 cm² = 1e-4 m².
            ModulusUnit::DynPerCm2 => 0.1,
        }
    }
}

impl FreqUnit {
    /// Parse a unit as written. `1/s` is refused: it may mean Hz or rad/s.
    pub fn parse(s: &str) -> Option<Self> {
        Some(match clean_unit(s).as_str() {
            "Hz" | "hz" | "HZ" | "cps" => FreqUnit::Hz,
            "kHz" => FreqUnit::KHz,
            "rad/s" | "rad/sec" | "rads-1" | "rad.s-1" | "rad/S" => FreqUnit::RadPerS,
            _ => return None,
        })
    }
    /// Convert a value in this unit to Hz.
    pub(crate) fn to_hz(self, v: f64) -> f64 {
        match self {
            FreqUnit::Hz => v,
            FreqUnit::KHz => v * 1e3,
            // f = ω / 2π
            FreqUnit::RadPerS => v / (2.0 * PI),
        }
    }
}

impl TempUnit {
    /// Parse a unit as written (`C` alone is read as °C in a temperature column).
    pub fn parse(s: &str) -> Option<Self> {
        Some(match clean_unit(s).as_str() {
            "C" | "degC" | "deg.C" | "Cel" | "celsius" | "Celsius" => TempUnit::Celsius,
            "K" | "kelvin" | "Kelvin" => TempUnit::Kelvin,
            _ => return None,
        })
    }
    /// Convert a value in this unit to °C.
    pub(crate) fn to_celsius(self, v: f64) -> f64 {
        match self {
            TempUnit::Celsius => v,
            TempUnit::Kelvin => v - crate::material::ZERO_CELSIUS_K,
        }
    }
}

impl AngleUnit {
    /// Parse a unit as written.
    pub fn parse(s: &str) -> Option<Self> {
        Some(match clean_unit(s).as_str() {
            "°" | "deg" | "degree" | "degrees" | "Grad" => AngleUnit::Degree,
            "rad" => AngleUnit::Radian,
            _ => return None,
        })
    }
    /// Convert to rad.
    pub(crate) fn to_rad(self, v: f64) -> f64 {
        match self {
            AngleUnit::Degree => v.to_radians(),
            AngleUnit::Radian => v,
        }
    }
}

/// An empty or dimensionless unit (tan δ).
pub(crate) fn is_dimensionless(s: &str) -> bool {
    matches!(clean_unit(s).as_str(), "" | "-" | "1" | "#")
}

/// Whether `s` reads as a unit of any quantity a DMA export holds (used only to tell a unit row from a
/// name row, and a unit inside a column name from other bracketed text).
pub(crate) fn looks_like_unit(s: &str) -> bool {
    let c = clean_unit(s);
    if ModulusUnit::parse(&c).is_some()
        || FreqUnit::parse(&c).is_some()
        || TempUnit::parse(&c).is_some()
        || AngleUnit::parse(&c).is_some()
    {
        return true;
    }
    const OTHER: &[&str] = &[
        "s", "min", "h", "ms", "N", "mN", "kN", "mm", "m", "µm", "μm", "um", "%", "1/s", "1/Pa",
        "1/kPa", "1/MPa", "1/GPa", "Pa.s", "Pas", "MPas", "MPa.s", "kPas", "mPas", "mPa.s", "N.m",
        "µN.m", "mN.m", "N/m", "g", "mg", "J", "W", "1/K", "1/rad", "N.m/rad", "-",
    ];
    OTHER.contains(&c.as_str())
}

/// Split a column name that carries its unit (`E' (MPa)`, `Storage modulus / MPa`, `E'[MPa]`,
/// `Temp./°C`) into name and unit. Bracketed text that is not a unit (`Oscillation strain (cmd)`,
/// `tan(delta)`) stays part of the name.
pub(crate) fn split_name_unit(name: &str) -> (String, Option<String>) {
    let n = name.trim();
    if let Some(stripped) = n.strip_suffix(']') {
        if let Some(i) = stripped.rfind('[') {
            let unit = &stripped[i + 1..];
            return (
                stripped[..i].trim().to_string(),
                Some(unit.trim().to_string()),
            );
        }
    }
    if let Some(stripped) = n.strip_suffix(')') {
        if let Some(i) = stripped.rfind('(') {
            let unit = &stripped[i + 1..];
            if i > 0 && (looks_like_unit(unit) || is_dimensionless(unit) && unit.trim() == "-") {
                return (
                    stripped[..i].trim().to_string(),
                    Some(unit.trim().to_string()),
                );
            }
        }
    }
    // `name / unit` or `name/unit`: the first slash whose right side is a unit.
    for (i, _) in n.match_indices('/') {
        let (lhs, rhs) = (&n[..i], &n[i + 1..]);
        if !lhs.trim().is_empty() && (looks_like_unit(rhs) && !lhs.trim().ends_with('1')) {
            return (lhs.trim().to_string(), Some(rhs.trim().to_string()));
        }
    }
    if let Some(i) = n.rfind(" in ") {
        let rhs = &n[i + 4..];
        if looks_like_unit(rhs) {
            return (n[..i].trim().to_string(), Some(rhs.trim().to_string()));
        }
    }
    if let Some((stem, unit)) = snake_unit_suffix(n) {
        return (stem.to_string(), Some(unit.to_string()));
    }
    (n.to_string(), None)
}

/// A unit written as the last `_`-separated part of a one-word name, as scripts write them
/// (`freq_hz`, `omega_rad_s`, `temperature_C`, `T_K`, `G_storage_pa`, `E_loss_MPa`): (stem, unit as
/// it reads in a unit row). Lower-case spellings are accepted only where they are unambiguous:
/// `mpa` (mPa or MPa?) and `ms` stay part of the name, so that such a column has no unit and asks
/// for one.
fn snake_unit_suffix(name: &str) -> Option<(&str, &'static str)> {
    if name.contains(char::is_whitespace) || !name.contains('_') {
        return None;
    }
    const SUFFIXES: &[(&str, &str)] = &[
        ("_rad_s", "rad/s"),
        ("_rad_per_s", "rad/s"),
        ("_Hz", "Hz"),
        ("_hz", "Hz"),
        ("_kHz", "kHz"),
        ("_khz", "kHz"),
        ("_Pa", "Pa"),
        ("_pa", "Pa"),
        ("_kPa", "kPa"),
        ("_kpa", "kPa"),
        ("_MPa", "MPa"),
        ("_GPa", "GPa"),
        ("_gpa", "GPa"),
        ("_psi", "psi"),
        ("_C", "°C"),
        ("_c", "°C"),
        ("_degC", "°C"),
        ("_degc", "°C"),
        ("_K", "K"),
        ("_k", "K"),
        ("_deg", "°"),
        ("_rad", "rad"),
    ];
    for (suffix, unit) in SUFFIXES {
        if let Some(stem) = name.strip_suffix(suffix) {
            if !stem.is_empty() && !stem.ends_with('_') {
                return Some((stem, unit));
            }
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_units_and_refuses_unknown() {
        assert_eq!(ModulusUnit::parse("[MPa]"), Some(ModulusUnit::MPa));
        assert_eq!(ModulusUnit::parse("N/mm²"), Some(ModulusUnit::MPa));
        assert_eq!(ModulusUnit::parse("mPa"), None); // milli, not mega: never guessed
        assert_eq!(FreqUnit::parse("rad/s"), Some(FreqUnit::RadPerS));
        assert_eq!(FreqUnit::parse("1/s"), None);
        assert_eq!(TempUnit::parse("[\u{b0}C]"), Some(TempUnit::Celsius));
        assert_eq!(TempUnit::parse(" C"), Some(TempUnit::Celsius));
        assert_eq!(TempUnit::parse("K"), Some(TempUnit::Kelvin));
        // 2π rad/s is exactly 1 Hz up to one rounding.
        assert!((FreqUnit::RadPerS.to_hz(2.0 * PI) - 1.0).abs() < 1e-15);
        assert_eq!(TempUnit::Kelvin.to_celsius(273.15), 0.0);
    }

    #[test]
    fn splits_units_from_names() {
        assert_eq!(
            split_name_unit("E' (MPa)"),
            ("E'".into(), Some("MPa".into()))
        );
        assert_eq!(
            split_name_unit("Storage modulus / MPa"),
            ("Storage modulus".into(), Some("MPa".into()))
        );
        assert_eq!(
            split_name_unit("E''[GPa]"),
            ("E''".into(), Some("GPa".into()))
        );
        assert_eq!(
            split_name_unit("Temp./°C"),
            ("Temp.".into(), Some("°C".into()))
        );
        assert_eq!(split_name_unit("tan(delta)"), ("tan(delta)".into(), None));
        // Units as the last part of a snake_case name.
        let s = |n: &str| split_name_unit(n);
        assert_eq!(s("freq_hz"), ("freq".into(), Some("Hz".into())));
        assert_eq!(s("omega_rad_s"), ("omega".into(), Some("rad/s".into())));
        assert_eq!(
            s("temperature_C"),
            ("temperature".into(), Some("°C".into()))
        );
        assert_eq!(s("T_K"), ("T".into(), Some("K".into())));
        assert_eq!(s("G_storage_pa"), ("G_storage".into(), Some("Pa".into())));
        assert_eq!(s("E_loss_MPa"), ("E_loss".into(), Some("MPa".into())));
        assert_eq!(s("tan_delta"), ("tan_delta".into(), None));
        // mPa or MPa? Not decided here: no unit, so the reader asks for one.
        assert_eq!(s("E_loss_mpa"), ("E_loss_mpa".into(), None));
        assert_eq!(
            split_name_unit("Oscillation strain (cmd)"),
            ("Oscillation strain (cmd)".into(), None)
        );
        assert_eq!(
            split_name_unit("1/temperature"),
            ("1/temperature".into(), None)
        );
    }
}
