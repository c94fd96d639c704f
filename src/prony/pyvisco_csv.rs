//! pyvisco's Prony-term CSV, both ways: the table pyvisco writes for its fitted series
//! (`out.to_csv(prony['df_terms'], units, index_label='i')`) read into a [`RelaxationSpectrum`], and
//! a spectrum written in that layout.
//!
//! Layout (two header rows, quantity then unit; one row per term): `i, tau_i, alpha_i, E_0, E_i`
//! over `-, s, -, MPa, MPa` (`G_0`, `G_i` for shear; moduli in Pa, kPa, MPa or GPa). pyvisco's
//! series is E(t) = E₀ (1 − Σᵢ αᵢ (1 − e^(−t/τᵢ))), so Eᵢ = αᵢ E₀ and E∞ = E₀ (1 − Σᵢ αᵢ)
//! (docs/MATH.md §5's form with E₀ = E∞ + Σ Eᵢ). The reader takes Eᵢ from `E_i` when present, else
//! αᵢ E₀, and E∞ from E₀ (1 − Σ αᵢ) when α is present (E₀ − Σ Eᵢ otherwise). pyvisco scales the
//! αᵢ to sum to 1 when its fit gives more, so E∞ = 0 (a fluid: crate::creep converts it with its flow term, §17; `roll` refuses it) is a
//! file it writes; a |E∞| below 1e-12 E₀ is rounding and read as 0, a more negative one refused.
//! Units are read from the file, never guessed; an unparsable cell is an error, never dropped.

use super::{PronyError, RelaxationSpectrum, RelaxationTerm};
use crate::dma::units::ModulusUnit;
use crate::material::ModulusKind;

/// Whether `bytes` look like pyvisco's Prony-term CSV (a first row naming `tau_i`), not JSON.
pub(crate) fn looks_like_pyvisco_terms(bytes: &[u8]) -> bool {
    let text = String::from_utf8_lossy(bytes);
    let first = text.lines().next().unwrap_or("");
    first
        .trim_start_matches('\u{feff}')
        .split(',')
        .any(|c| c.trim() == "tau_i")
}

/// An error in the file, at a line.
fn bad(file: &str, line: usize, message: String) -> PronyError {
    PronyError::TermsFile {
        file: file.to_string(),
        line,
        message,
    }
}

/// The header rows: (names, units, modulus letter).
fn header(file: &str, text: &str) -> Result<(Vec<String>, Vec<String>, ModulusKind), PronyError> {
    let mut lines = text.lines();
    let split = |l: &str| -> Vec<String> {
        l.trim_start_matches('\u{feff}')
            .split(',')
            .map(|s| s.trim().to_string())
            .collect()
    };
    let names = split(lines.next().unwrap_or(""));
    let units = split(
        lines
            .next()
            .ok_or_else(|| bad(file, 2, "no unit row under the name row".into()))?,
    );
    let kind = if names.iter().any(|n| n == "E_0" || n == "E_i") {
        ModulusKind::Tensile
    } else if names.iter().any(|n| n == "G_0" || n == "G_i") {
        ModulusKind::Shear
    } else {
        return Err(bad(
            file,
            1,
            format!(
                "no instantaneous modulus column E_0 or G_0 (columns: {})",
                names.join(", ")
            ),
        ));
    };
    Ok((names, units, kind))
}

/// Pa per unit of column `name`, whose unit row holds `unit` (Pa, kPa, MPa or GPa), or the error.
fn unit_to_pa(file: &str, name: &str, unit: Option<&String>) -> Result<f64, PronyError> {
    let u = unit.map(String::as_str).unwrap_or("");
    ModulusUnit::parse(u)
        .map(ModulusUnit::to_pa)
        .ok_or_else(|| {
            bad(
                file,
                2,
                format!("{name}: unit {u:?} is not Pa, kPa, MPa or GPa"),
            )
        })
}

/// Read pyvisco's Prony-term CSV (see the module docs); `poisson` is stated by the caller (pyvisco
/// does not write it).
pub fn read_pyvisco_terms(
    file: &str,
    bytes: &[u8],
    poisson: f64,
) -> Result<RelaxationSpectrum, PronyError> {
    let text = String::from_utf8_lossy(bytes);
    let (names, units, kind) = header(file, &text)?;
    let m = match kind {
        ModulusKind::Tensile => "E",
        ModulusKind::Shear => "G",
    };
    let find = |n: &str| names.iter().position(|x| x == n);
    let i_tau = find("tau_i").ok_or_else(|| bad(file, 1, "no column tau_i".into()))?;
    let i_e0 = find(&format!("{m}_0"))
        .ok_or_else(|| bad(file, 1, format!("no column {m}_0 (E∞ needs it)")))?;
    let (i_alpha, i_ei) = (find("alpha_i"), find(&format!("{m}_i")));
    if i_alpha.is_none() && i_ei.is_none() {
        return Err(bad(file, 1, format!("neither alpha_i nor {m}_i")));
    }
    let unit = |i: usize| unit_to_pa(file, &names[i], units.get(i));
    if units.get(i_tau).map(String::as_str) != Some("s") {
        return Err(bad(file, 2, "tau_i: unit must be s".into()));
    }
    let e0_scale = unit(i_e0)?;
    let ei_scale = i_ei.map(unit).transpose()?;
    let mut e0: Option<f64> = None;
    let (mut terms, mut alpha_sum) = (Vec::new(), 0.0);
    for (k, l) in text.lines().enumerate().skip(2) {
        if l.trim().is_empty() {
            continue;
        }
        let cells: Vec<&str> = l.split(',').map(str::trim).collect();
        let get = |i: usize| -> Result<f64, PronyError> {
            let c = cells.get(i).copied().unwrap_or("");
            c.parse::<f64>()
                .ok()
                .filter(|v| v.is_finite() && *v >= 0.0)
                .ok_or_else(|| {
                    bad(
                        file,
                        k + 1,
                        format!("{}: {c:?} is not a finite number ≥ 0", names[i]),
                    )
                })
        };
        let row_e0 = get(i_e0)? * e0_scale;
        if e0.is_some_and(|e| (e - row_e0).abs() > 1e-12 * e) {
            return Err(bad(
                file,
                k + 1,
                format!("{m}_0 differs from the rows above"),
            ));
        }
        e0 = Some(row_e0);
        let alpha = i_alpha.map(get).transpose()?;
        alpha_sum += alpha.unwrap_or(0.0);
        let modulus_pa = match (i_ei, ei_scale, alpha) {
            (Some(i), Some(s), _) => get(i)? * s,
            (_, _, Some(a)) => a * row_e0,
            _ => unreachable!("alpha_i or E_i was checked above"),
        };
        let tau_s = get(i_tau)?;
        if tau_s <= 0.0 {
            return Err(bad(file, k + 1, "tau_i must be > 0".into()));
        }
        terms.push(RelaxationTerm { modulus_pa, tau_s });
    }
    let e0 = e0.ok_or_else(|| bad(file, 3, "no term rows under the two header rows".into()))?;
    let mut e_inf = match i_alpha {
        Some(_) => e0 * (1.0 - alpha_sum),
        None => e0 - terms.iter().map(|t| t.modulus_pa).sum::<f64>(),
    };
    if e_inf.abs() <= 1e-12 * e0 {
        e_inf = 0.0;
    }
    if e_inf < 0.0 {
        return Err(bad(
            file,
            3,
            format!("the terms add up to more than {m}_0 ({m}∞ = {e_inf:e} Pa < 0)"),
        ));
    }
    terms.sort_by(|a, b| a.tau_s.total_cmp(&b.tau_s));
    Ok(RelaxationSpectrum {
        kind,
        poisson,
        modulus_inf_pa: e_inf,
        terms,
    })
}

/// A spectrum in pyvisco's Prony-term layout (moduli in MPa; terms from the longest τ down, as
/// pyvisco writes them; numbers in Rust's shortest round-trip form).
pub fn pyvisco_terms_csv(spectrum: &RelaxationSpectrum) -> String {
    let m = match spectrum.kind {
        ModulusKind::Tensile => "E",
        ModulusKind::Shear => "G",
    };
    let e0 = spectrum.instantaneous_modulus();
    let mut terms = spectrum.terms.clone();
    terms.sort_by(|a, b| b.tau_s.total_cmp(&a.tau_s));
    let mut s = format!("i,tau_i,alpha_i,{m}_0,{m}_i\n-,s,-,MPa,MPa\n");
    for (k, t) in terms.iter().enumerate() {
        s.push_str(&format!(
            "{},{:?},{:?},{:?},{:?}\n",
            k + 1,
            t.tau_s,
            t.modulus_pa / e0,
            e0 / 1e6,
            t.modulus_pa / 1e6
        ));
    }
    s
}

impl RelaxationSpectrum {
    /// Read pyvisco's Prony-term CSV (`read_pyvisco_terms`; `poisson` is stated by the caller).
    pub fn from_pyvisco_csv(file: &str, bytes: &[u8], poisson: f64) -> Result<Self, PronyError> {
        read_pyvisco_terms(file, bytes, poisson)
    }

    /// This spectrum in pyvisco's Prony-term layout (`pyvisco_terms_csv`).
    pub fn to_pyvisco_csv(&self) -> String {
        pyvisco_terms_csv(self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Written then read: every term and E∞ back to a few roundings (MPa and α are one division
    /// each, E∞ = E₀(1 − Σα) a sum of N roundings).
    #[test]
    fn write_read_round_trip() {
        let s = RelaxationSpectrum {
            kind: ModulusKind::Shear,
            poisson: 0.5,
            modulus_inf_pa: 1.5e6,
            terms: vec![
                RelaxationTerm {
                    modulus_pa: 2e6,
                    tau_s: 1e-3,
                },
                RelaxationTerm {
                    modulus_pa: 7e5,
                    tau_s: 10.0,
                },
            ],
        };
        let csv = pyvisco_terms_csv(&s);
        assert!(looks_like_pyvisco_terms(csv.as_bytes()));
        let r = read_pyvisco_terms("p.csv", csv.as_bytes(), 0.5).unwrap();
        assert_eq!(r.kind, ModulusKind::Shear);
        assert!((r.modulus_inf_pa / s.modulus_inf_pa - 1.0).abs() < 1e-14);
        for (a, b) in r.terms.iter().zip(&s.terms) {
            assert_eq!(a.tau_s, b.tau_s);
            assert!((a.modulus_pa / b.modulus_pa - 1.0).abs() < 1e-15);
        }
    }

    /// pyvisco's own layout (α summing to 1 after its scaling): a fluid, E∞ = 0; and its errors.
    #[test]
    fn alphas_summing_to_one_are_a_fluid_and_bad_files_are_refused() {
        let csv =
            "i,tau_i,alpha_i,E_0,E_i\n-,s,-,MPa,MPa\n1,10.0,0.25,4.0,1.0\n2,0.1,0.75,4.0,3.0\n";
        let r = read_pyvisco_terms("p.csv", csv.as_bytes(), 0.5).unwrap();
        assert_eq!(r.modulus_inf_pa, 0.0);
        assert_eq!(r.terms[0].tau_s, 0.1);
        assert_eq!(r.terms[0].modulus_pa, 3e6);
        for bad in [
            "i,tau_i,alpha_i,E_0,E_i\n-,s,-,MPa,MPa\n",
            "i,tau_i,alpha_i,E_0,E_i\n-,ms,-,MPa,MPa\n1,1,0.5,4,2\n",
            "i,tau_i,alpha_i,E_0,E_i\n-,s,-,mPa,MPa\n1,1,0.5,4,2\n",
            "i,tau_i,alpha_i,E_0,E_i\n-,s,-,MPa,MPa\n1,1,0.7,4,2.8\n2,2,0.7,4,2.8\n",
            "i,tau_i,alpha_i,E_0,E_i\n-,s,-,MPa,MPa\n1,x,0.5,4,2\n",
            "i,tau_i,alpha_i\n-,s,-\n1,1,0.5\n",
        ] {
            assert!(
                read_pyvisco_terms("p.csv", bad.as_bytes(), 0.5).is_err(),
                "{bad}"
            );
        }
    }
}
