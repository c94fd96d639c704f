//! The master-curve and Prony flags shared by `viscoroll master`, `fit` and `run` (one definition, so
//! they carry the same names everywhere, and the same as the keys of `compounds.toml`); parsed and
//! checked by crate::pipeline::tuning into a [`FitTuning`].

use crate::pipeline::tuning::{self, FitTuning};
use crate::tts::{LawChoice, ShiftCriterion, VerticalShift};
use std::path::Path;

/// The master-curve (time–temperature superposition) flags.
#[derive(Debug, Clone, Default, clap::Args)]
pub struct TtsArgs {
    /// Horizontal shifts: `auto`, `wlf:C1,C2` (C2 in K, at --tref), `arrhenius:EA` (J/mol, at
    /// --tref), or a file: a JSON shift law, or a table with a name row (`T_C,log10_aT`, or `T,log_aT`
    /// over a unit row `C,-`; comma, semicolon, tab or white space), referred to the row with
    /// log10 aT = 0, else to --tref [default: auto].
    #[arg(long)]
    pub shift: Option<String>,
    /// Vertical shift b_T: `fitted` (from the residual offset; horizontal then from tan δ) or
    /// `temperature` (T/T_ref) [default when given without a value: fitted; off when absent].
    #[arg(long, value_enum, num_args = 0..=1, default_missing_value = "fitted")]
    pub vertical: Option<VerticalArg>,
    /// What the automatic shifting compares [default: slope-weighted].
    #[arg(long, value_enum)]
    pub criterion: Option<CriterionArg>,
    /// Law used as the master curve's shift law [default: `master` auto, `fit` and `run` table].
    #[arg(long, value_enum)]
    pub law: Option<LawArg>,
    /// Fit WLF and Arrhenius only to isotherms in this range of temperatures, `TMIN:TMAX` in °C
    /// (e.g. above T_g) [default: all].
    #[arg(long, allow_hyphen_values = true)]
    pub fit_range: Option<String>,
    /// Use the nominal (set) temperatures instead of the mean measured ones.
    #[arg(long)]
    pub nominal: bool,
}

/// The Prony flags.
#[derive(Debug, Clone, Default, clap::Args)]
pub struct PronyArgs {
    /// Keep at most N relaxation terms (E∞ not counted): the fit chooses their positions and
    /// non-negative weights (e.g. 18 for an LS-DYNA card). Default: no cap.
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u64).range(1..))]
    pub max_terms: Option<u64>,
    /// Target RMS log10 error of E′ and E″ ("0.02" for both, "0.012,0.10" for each): the fewest
    /// terms that reach it. Default: the errors of the dense grid fit (fewer terms, no less accurate).
    #[arg(long, value_name = "E1[,E2]")]
    pub target_rms: Option<String>,
    /// Reduce the dense grid fit to the fewest terms at free positions that are no less accurate
    /// against the data (implied by --max-terms and --target-rms; default: the dense grid fit).
    #[arg(long)]
    pub reduce: bool,
    /// Weight of the E″ residuals against the E′ residuals in the Prony fit (default 1: both alike;
    /// below 1 favours E′, e.g. 0.12 with --max-terms 26 beats pyvisco on both E′ and E″ on its
    /// EMS-CA master curve; see the user guide's trade table).
    #[arg(long, value_name = "W")]
    pub loss_weight: Option<f64>,
}

/// `--vertical` values.
#[derive(Debug, Clone, Copy, clap::ValueEnum)]
pub enum VerticalArg {
    /// From the residual offset of log E′.
    Fitted,
    /// T/T_ref (kelvin).
    Temperature,
    /// None.
    None,
}

/// `--criterion` values.
#[derive(Debug, Clone, Copy, clap::ValueEnum)]
pub enum CriterionArg {
    /// log E′ and log E″, each weighted per isotherm by its local slope against its scatter (E″
    /// carries the shift where E′ is flat); the default.
    SlopeWeighted,
    /// log E′ only.
    Storage,
    /// log E′ and log E″ jointly (each weighted by its own scatter).
    Joint,
    /// log tan δ.
    TanDelta,
}

/// `--law` values.
#[derive(Debug, Clone, Copy, clap::ValueEnum)]
pub enum LawArg {
    /// The better of WLF and Arrhenius by RMS.
    Auto,
    /// WLF.
    Wlf,
    /// Arrhenius.
    Arrhenius,
    /// The table of measured shifts.
    Table,
}

impl TtsArgs {
    /// The options given, checked; `tref` is the temperature a `wlf:`/`arrhenius:` shift refers to;
    /// with `prony`, the Prony flags too.
    pub fn tuning(
        &self,
        tref: Option<f64>,
        prony: Option<&PronyArgs>,
    ) -> anyhow::Result<FitTuning> {
        let err = |e: String| anyhow::anyhow!("--{e}");
        let mut t = FitTuning {
            shift: self
                .shift
                .as_deref()
                .map(|s| tuning::parse_shift(s, tref, Path::new("")))
                .transpose()
                .map_err(err)?,
            vertical: self.vertical.map(|v| match v {
                VerticalArg::Fitted => VerticalShift::Fitted,
                VerticalArg::Temperature => VerticalShift::Temperature,
                VerticalArg::None => VerticalShift::None,
            }),
            criterion: self.criterion.map(|c| match c {
                CriterionArg::SlopeWeighted => ShiftCriterion::SlopeWeighted,
                CriterionArg::Storage => ShiftCriterion::Storage,
                CriterionArg::Joint => ShiftCriterion::Joint,
                CriterionArg::TanDelta => ShiftCriterion::TanDelta,
            }),
            law: self.law.map(|l| match l {
                LawArg::Auto => LawChoice::Auto,
                LawArg::Wlf => LawChoice::Wlf,
                LawArg::Arrhenius => LawChoice::Arrhenius,
                LawArg::Table => LawChoice::Table,
            }),
            fit_range_c: self
                .fit_range
                .as_deref()
                .map(tuning::parse_fit_range)
                .transpose()
                .map_err(err)?,
            nominal: self.nominal,
            ..FitTuning::default()
        };
        if let Some(p) = prony {
            t.max_terms = p.max_terms.map(|n| n as usize);
            t.target_rms = p
                .target_rms
                .as_deref()
                .map(tuning::parse_target_rms)
                .transpose()
                .map_err(err)?;
            t.reduce = p.reduce;
            t.loss_weight = p
                .loss_weight
                .map(tuning::check_loss_weight)
                .transpose()
                .map_err(err)?;
        }
        Ok(t)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::ValueEnum;

    #[test]
    fn flag_values_are_the_compounds_toml_values() {
        // Each `--criterion`/`--law`/`--vertical` value, as clap spells it, parses in compounds.toml
        // to the same setting.
        for c in CriterionArg::value_variants() {
            let name = c.to_possible_value().unwrap().get_name().to_string();
            let from_toml = tuning::parse_criterion(&name).unwrap();
            let from_flag = TtsArgs {
                criterion: Some(*c),
                ..TtsArgs::default()
            }
            .tuning(None, None)
            .unwrap()
            .criterion;
            assert_eq!(Some(from_toml), from_flag, "{name}");
        }
        for l in LawArg::value_variants() {
            let name = l.to_possible_value().unwrap().get_name().to_string();
            let from_flag = TtsArgs {
                law: Some(*l),
                ..TtsArgs::default()
            }
            .tuning(None, None)
            .unwrap()
            .law;
            assert_eq!(Some(tuning::parse_law(&name).unwrap()), from_flag, "{name}");
        }
        for v in VerticalArg::value_variants() {
            let name = v.to_possible_value().unwrap().get_name().to_string();
            let from_flag = TtsArgs {
                vertical: Some(*v),
                ..TtsArgs::default()
            }
            .tuning(None, None)
            .unwrap()
            .vertical;
            assert_eq!(
                Some(tuning::parse_vertical(&name).unwrap()),
                from_flag,
                "{name}"
            );
        }
    }
}
