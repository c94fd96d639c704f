//! The one printer of `viscoroll roll`'s answer, half-space ([`super::roll`]) or cover
//! ([`super::roll_cover`]): the JSON object on stdout or the text on stderr, then the warnings.
//!
//! It takes the SI solution, the temperature shift (fit files only), the warnings and what each
//! caller adds (JSON fields, text lines), and prints the shared fields once.

use super::roll_args::Args;
use crate::contact::scene::RollSolution;

/// The temperature a fit's spectrum was moved to.
pub(super) struct Shift {
    /// °C.
    pub temp_c: f64,
    /// log10 a_T used.
    pub log10_a_t: f64,
    /// Outside the measured temperatures.
    pub extrapolated: bool,
}

/// One answer of `roll`, ready to print.
pub(super) struct Answer<'a> {
    /// The command line.
    pub args: &'a Args,
    /// The SI solution.
    pub sol: &'a RollSolution,
    /// The temperature (fit files).
    pub shift: Option<Shift>,
    /// Number of creep terms of the spectrum solved.
    pub terms: usize,
    /// Every warning for the user (temperature first, then solver and body).
    pub warnings: &'a [String],
    /// Fields the caller adds to the JSON object.
    pub json_extra: serde_json::Map<String, serde_json::Value>,
    /// Appended to the text's first line (e.g. ", cover 5 mm").
    pub header_suffix: String,
    /// Text lines right after the first line.
    pub lines_after_header: Vec<String>,
    /// Text lines after the SI figures.
    pub lines_after: Vec<String>,
}

impl Answer<'_> {
    /// Print the answer (JSON on stdout with `--json`, text on stderr otherwise), then every warning
    /// on stderr.
    pub fn print(&self) {
        if self.args.json {
            outln!("{}", super::output::versioned(self.json()));
        } else {
            self.text();
        }
        for w in self.warnings {
            errln!("warning: {w}");
        }
    }

    /// The JSON object: the shared fields (module doc of [`super::roll`]) plus the caller's.
    fn json(&self) -> serde_json::Value {
        let (args, sol) = (self.args, self.sol);
        let d = &sol.dimensionless;
        let shift = self.shift.as_ref();
        let mut obj = serde_json::json!({
            "friction": sol.friction,
            "contact_length_mm": sol.contact_length_m * 1e3,
            "offset_mm": sol.offset_m * 1e3,
            "resistance_n_per_m": sol.resistance_n_per_m,
            "max_pressure_mpa": sol.max_pressure_pa * 1e-6,
            "x_mm": sol.x_m.iter().map(|x| x * 1e3).collect::<Vec<_>>(),
            "pressure_mpa": sol.pressure_pa.iter().map(|p| p * 1e-6).collect::<Vec<_>>(),
            "radius_mm": args.radius_mm,
            "load_n_per_m": args.load_n_per_m,
            "speed_m_s": args.speed_m_s,
            "poisson": sol.problem.poisson,
            "lambda": d.lambda,
            "beta": d.beta,
            "load": d.load,
            "friction_rho": d.friction_rho,
            "rho": sol.problem.rho,
            "time_scale_s": sol.problem.time_scale_s,
            "creep": sol.problem.terms,
            "scheme": d.scheme,
            "n": d.n,
            "iterations": d.iterations,
            "temp_c": shift.map(|a| a.temp_c),
            "log10_a_t": shift.map(|a| a.log10_a_t),
            "extrapolated": shift.map(|a| a.extrapolated),
            "warnings": self.warnings,
        });
        if let Some(map) = obj.as_object_mut() {
            for (k, v) in &self.json_extra {
                map.insert(k.clone(), v.clone());
            }
        }
        obj
    }

    /// The human-readable answer on stderr.
    fn text(&self) {
        let (args, sol) = (self.args, self.sol);
        if let Some(a) = &self.shift {
            errln!(
                "at {} °C: log10 a_T = {:.4}{}",
                a.temp_c,
                a.log10_a_t,
                if a.extrapolated {
                    " (extrapolated)"
                } else {
                    ""
                }
            );
        }
        errln!(
            "roll R = {} mm, N = {} N/m, V = {} m/s on {} ({} terms, nu = {}){}",
            args.radius_mm,
            args.load_n_per_m,
            args.speed_m_s,
            args.spectrum.display(),
            self.terms,
            sol.problem.poisson,
            self.header_suffix
        );
        for l in &self.lines_after_header {
            errln!("{l}");
        }
        errln!("friction F/N        = {:.6e}", sol.friction);
        errln!("resistance          = {:.6e} N/m", sol.resistance_n_per_m);
        errln!("contact length      = {:.6} mm", sol.contact_length_m * 1e3);
        errln!(
            "offset (centre ahead of lowest point) = {:.6} mm",
            sol.offset_m * 1e3
        );
        errln!(
            "max pressure        = {:.6} MPa",
            sol.max_pressure_pa * 1e-6
        );
        for l in &self.lines_after {
            errln!("{l}");
        }
    }
}
