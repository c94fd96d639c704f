//! The master-curve and Prony options a user can set, one set of names for every way in: the flags
//! of `viscoroll master`, `fit` and `run`, and the keys of a compound in `compounds.toml`
//! (`--criterion slope-weighted` ↔ `criterion = "slope-weighted"`, `--fit-range -30:60` ↔
//! `fit_range = "-30:60"`, `--max-terms 18` ↔ `max_terms = 18`, `--loss-weight 0.12` ↔
//! `loss_weight = 0.12`).
//!
//! Input: the option values as given (text, parsed and checked here, the message naming the
//! option); output: a [`FitTuning`] that lays the given options over [`FitOptions`]. Options not
//! given keep the defaults of the command (e.g. `fit` and `run` use the table of the shifts as the
//! shift law, `master` the better of WLF and Arrhenius).

use super::fit_compound::FitOptions;
use crate::tts::{LawChoice, ShiftCriterion, ShiftSource, TemperatureBasis, VerticalShift};
use crate::ShiftLaw;
use std::path::Path;

/// The options given, each `None` (or false) when not given.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct FitTuning {
    /// `shift`: automatic shifting or a given law.
    pub shift: Option<ShiftSource>,
    /// `vertical`: the vertical shift.
    pub vertical: Option<VerticalShift>,
    /// `criterion`: what the automatic shifting compares.
    pub criterion: Option<ShiftCriterion>,
    /// `law`: the master curve's shift law.
    pub law: Option<LawChoice>,
    /// `fit_range`: WLF and Arrhenius fitted over these temperatures only, °C.
    pub fit_range_c: Option<(f64, f64)>,
    /// `nominal`: shift with the nominal (set) temperatures.
    pub nominal: bool,
    /// `max_terms`: at most this many relaxation terms.
    pub max_terms: Option<usize>,
    /// `target_rms`: the fewest terms that reach these RMS log10 errors of E′ and E″.
    pub target_rms: Option<[f64; 2]>,
    /// `reduce`: reduce the dense fit to the fewest terms no less accurate.
    pub reduce: bool,
    /// `loss_weight`: weight of the E″ residuals against the E′ residuals in the Prony fit
    /// (crate::prony::PronySettings::loss_weight; docs/MATH.md §5.2).
    pub loss_weight: Option<f64>,
}

impl FitTuning {
    /// Lay the given options over `o` (options not given leave `o` as it is).
    pub fn apply(&self, o: &mut FitOptions) {
        if let Some(s) = &self.shift {
            o.master.shift = s.clone();
        }
        if let Some(v) = self.vertical {
            o.master.vertical = v;
        }
        if let Some(c) = self.criterion {
            o.master.criterion = c;
        }
        if let Some(l) = self.law {
            o.master.law = l;
        }
        if let Some(r) = self.fit_range_c {
            o.master.law_fit_range_c = Some(r);
        }
        if self.nominal {
            o.master.temperature = TemperatureBasis::Nominal;
        }
        if let Some(n) = self.max_terms {
            o.prony.max_terms = Some(n);
        }
        if let Some(t) = self.target_rms {
            o.prony.target_rms_log10 = Some(t);
        }
        if let Some(w) = self.loss_weight {
            o.prony.loss_weight = w;
        }
        o.prony.reduce_terms |=
            self.reduce || self.max_terms.is_some() || self.target_rms.is_some();
    }

    /// Set the option `key` from its text, as `compounds.toml` and the command line write it
    /// (`shift`, `vertical`, `criterion`, `law`, `fit_range`, `target_rms`; a `shift` file is
    /// found from `base`, a WLF or Arrhenius law is at `tref`); the error names the key.
    pub fn set_text(
        &mut self,
        key: &str,
        text: &str,
        tref: Option<f64>,
        base: &Path,
    ) -> Result<(), String> {
        let named = |e: String| format!("{key}: {e}");
        match key {
            "shift" => self.shift = Some(parse_shift(text, tref, base).map_err(named)?),
            "vertical" => self.vertical = Some(parse_vertical(text).map_err(named)?),
            "criterion" => self.criterion = Some(parse_criterion(text).map_err(named)?),
            "law" => self.law = Some(parse_law(text).map_err(named)?),
            "fit_range" => self.fit_range_c = Some(parse_fit_range(text).map_err(named)?),
            "target_rms" => self.target_rms = Some(parse_target_rms(text).map_err(named)?),
            _ => return Err(format!("{key}: not an option given as text")),
        }
        Ok(())
    }
}

/// `vertical`: `fitted`, `temperature` or `none`.
pub fn parse_vertical(s: &str) -> Result<VerticalShift, String> {
    match s.trim().to_ascii_lowercase().as_str() {
        "fitted" => Ok(VerticalShift::Fitted),
        "temperature" => Ok(VerticalShift::Temperature),
        "none" => Ok(VerticalShift::None),
        _ => Err(format!(
            "vertical `{s}`: expected fitted, temperature or none"
        )),
    }
}

/// `criterion`: `slope-weighted`, `storage`, `joint` or `tan-delta` (as `master --criterion`).
pub fn parse_criterion(s: &str) -> Result<ShiftCriterion, String> {
    match s.trim().to_ascii_lowercase().replace('_', "-").as_str() {
        "slope-weighted" => Ok(ShiftCriterion::SlopeWeighted),
        "storage" => Ok(ShiftCriterion::Storage),
        "joint" => Ok(ShiftCriterion::Joint),
        "tan-delta" => Ok(ShiftCriterion::TanDelta),
        _ => Err(format!(
            "criterion `{s}`: expected slope-weighted, storage, joint or tan-delta"
        )),
    }
}

/// `law`: `auto`, `wlf`, `arrhenius` or `table`.
pub fn parse_law(s: &str) -> Result<LawChoice, String> {
    match s.trim().to_ascii_lowercase().as_str() {
        "auto" => Ok(LawChoice::Auto),
        "wlf" => Ok(LawChoice::Wlf),
        "arrhenius" => Ok(LawChoice::Arrhenius),
        "table" => Ok(LawChoice::Table),
        _ => Err(format!("law `{s}`: expected auto, wlf, arrhenius or table")),
    }
}

/// `fit_range`: `TMIN:TMAX` in °C, finite, TMIN < TMAX.
pub fn parse_fit_range(r: &str) -> Result<(f64, f64), String> {
    let (a, b) = r
        .split_once(':')
        .ok_or_else(|| format!("fit-range: expected TMIN:TMAX in °C, got {r:?}"))?;
    let parse = |v: &str| {
        v.trim()
            .parse::<f64>()
            .ok()
            .filter(|x| x.is_finite())
            .ok_or_else(|| format!("fit-range: {v:?} is not a temperature in °C"))
    };
    let (lo, hi) = (parse(a)?, parse(b)?);
    if lo >= hi {
        return Err(format!("fit-range {r}: TMIN must lie below TMAX"));
    }
    Ok((lo, hi))
}

/// `target_rms`: `E1` for both moduli or `E1,E2`, finite and > 0.
pub fn parse_target_rms(s: &str) -> Result<[f64; 2], String> {
    let v: Vec<f64> = s
        .split(',')
        .map(|t| t.trim().parse::<f64>())
        .collect::<Result<_, _>>()
        .map_err(|_| format!("target-rms {s}: expected E1 or E1,E2 (RMS log10 errors)"))?;
    let t = match v.as_slice() {
        [a] => [*a, *a],
        [a, b] => [*a, *b],
        _ => return Err(format!("target-rms {s}: expected one or two numbers")),
    };
    if t.iter().any(|x| !(x.is_finite() && *x > 0.0)) {
        return Err(format!("target-rms {s}: the errors must be finite and > 0"));
    }
    Ok(t)
}

/// `loss_weight`: the weight of E″ against E′ in the Prony fit, finite and > 0 (1 = both alike, the
/// default; below 1 favours E′).
pub(crate) fn check_loss_weight(w: f64) -> Result<f64, String> {
    if w.is_finite() && w > 0.0 {
        Ok(w)
    } else {
        Err(format!(
            "loss-weight {w}: expected a finite weight > 0 (1: E′ and E″ alike; below 1 favours E′)"
        ))
    }
}

fn parse_number(s: &str, what: &str) -> Result<f64, String> {
    s.trim()
        .parse::<f64>()
        .ok()
        .filter(|v| v.is_finite())
        .ok_or_else(|| format!("shift: {what} = {s:?} is not a finite number"))
}

/// `shift`: `auto`, `wlf:C1,C2` (C2 in K, at `tref`), `arrhenius:EA` (J/mol, at `tref`), or a file
/// (relative paths from `base`): a JSON shift law, or a table with a name row (`T_C,log10_aT`, or
/// `T,log_aT` over a unit row `C,-`), referred to its row with log10 aT = 0, else to `tref`.
pub fn parse_shift(spec: &str, tref: Option<f64>, base: &Path) -> Result<ShiftSource, String> {
    if spec == "auto" {
        return Ok(ShiftSource::Auto);
    }
    let need_tref = |form: &str| {
        tref.ok_or_else(|| {
            format!("shift {form} needs a reference temperature (tref, the temperature its constants refer to)")
        })
    };
    let checked = |law: ShiftLaw, what: String| {
        law.validate()
            .map(|_| ShiftSource::Given { law: law.clone() })
            .map_err(|e| format!("{what}: {e}"))
    };
    if let Some(rest) = spec.strip_prefix("wlf:") {
        let parts: Vec<&str> = rest.split(',').collect();
        if parts.len() != 2 {
            return Err(format!("shift wlf:C1,C2 expects two numbers, got {rest:?}"));
        }
        let (c1, c2_k) = (parse_number(parts[0], "C1")?, parse_number(parts[1], "C2")?);
        let t_ref_c = need_tref("wlf:C1,C2")?;
        return checked(
            ShiftLaw::Wlf { t_ref_c, c1, c2_k },
            format!("shift wlf:C1,C2 needs C1 > 0 and C2 > 0 K, got C1 = {c1}, C2 = {c2_k}"),
        );
    }
    if let Some(rest) = spec.strip_prefix("arrhenius:") {
        let ea = parse_number(rest, "EA")?;
        let t_ref_c = need_tref("arrhenius:EA")?;
        return checked(
            ShiftLaw::Arrhenius {
                t_ref_c,
                activation_energy_j_per_mol: ea,
            },
            format!("shift arrhenius:EA needs EA > 0 J/mol, got {ea}"),
        );
    }
    let path = base.join(spec);
    if !path.is_file() {
        return Err(format!(
            "shift {spec:?}: expected auto, wlf:C1,C2, arrhenius:EA or an existing file"
        ));
    }
    let text = crate::fsutil::read_regular_to_string(&path, crate::limits::INPUT_BYTES_MAX)
        .map_err(|e| format!("cannot read shift file {}: {e}", path.display()))?;
    if text.trim_start().starts_with('{') {
        let law = serde_json::from_str::<ShiftLaw>(&text)
            .map_err(|e| format!("{} is not a shift-law JSON: {e}", path.display()))?;
        checked(law, format!("shift law {}", path.display()))
    } else {
        crate::dma::shiftfactors::shift_table_from_bytes(
            &path.display().to_string(),
            text.as_bytes(),
            tref,
        )
        .map(|law| ShiftSource::Given { law })
        .map_err(|e| e.to_string())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn given_options_lay_over_the_defaults_and_others_stay() {
        let mut o = FitOptions::default();
        let before = o.clone();
        FitTuning::default().apply(&mut o);
        assert_eq!(o, before);
        let t = FitTuning {
            criterion: Some(parse_criterion("storage").unwrap()),
            vertical: Some(parse_vertical("fitted").unwrap()),
            law: Some(parse_law("wlf").unwrap()),
            fit_range_c: Some(parse_fit_range("-30:60").unwrap()),
            nominal: true,
            max_terms: Some(18),
            loss_weight: Some(check_loss_weight(0.12).unwrap()),
            ..FitTuning::default()
        };
        t.apply(&mut o);
        assert_eq!(o.master.criterion, ShiftCriterion::Storage);
        assert_eq!(o.master.vertical, VerticalShift::Fitted);
        assert_eq!(o.master.law, LawChoice::Wlf);
        assert_eq!(o.master.law_fit_range_c, Some((-30.0, 60.0)));
        assert_eq!(o.master.temperature, TemperatureBasis::Nominal);
        assert_eq!(o.prony.max_terms, Some(18));
        assert_eq!(o.prony.loss_weight, 0.12);
        assert!(o.prony.reduce_terms);
        // Untouched: the point-temperature correction of the main job.
        assert_eq!(
            o.master.correct_point_temperatures,
            before.master.correct_point_temperatures
        );
    }

    #[test]
    fn bad_values_name_their_option() {
        for (e, key) in [
            (parse_criterion("e-prime").unwrap_err(), "criterion"),
            (parse_vertical("up").unwrap_err(), "vertical"),
            (parse_law("vft").unwrap_err(), "law"),
            (parse_fit_range("60:-30").unwrap_err(), "fit-range"),
            (parse_fit_range("x:3").unwrap_err(), "fit-range"),
            (parse_target_rms("0,1").unwrap_err(), "target-rms"),
            (check_loss_weight(0.0).unwrap_err(), "loss-weight"),
            (check_loss_weight(f64::NAN).unwrap_err(), "loss-weight"),
            (
                parse_shift("wlf:1,2", None, Path::new(".")).unwrap_err(),
                "shift",
            ),
            (
                parse_shift("nope.csv", Some(20.0), Path::new(".")).unwrap_err(),
                "shift",
            ),
        ] {
            assert!(e.contains(key), "{e}");
        }
        assert_eq!(
            parse_shift("wlf:8.86,101.6", Some(20.0), Path::new(".")).unwrap(),
            ShiftSource::Given {
                law: ShiftLaw::Wlf {
                    t_ref_c: 20.0,
                    c1: 8.86,
                    c2_k: 101.6
                }
            }
        );
    }
}
