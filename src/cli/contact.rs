//! `viscoroll contact`: the dimensionless problem of the thesis (ch. 3–4) for a creep function
//! γ(ζ) = Σ fᵢe^(−bᵢζ) given as `f:b` pairs, at given contact length λ or load N′.
//!
//! `--json` prints one object: `lambda`, `beta`, `beta_over_lambda`, `load` (N′), `friction_rho` (ρ·F/N),
//! `friction` (F/N, only with `--rho`), `n`, `scheme`, `iterations`, `xi`, `pressure`, `creep` (the terms).
//!
//! With `--cover H′` (the dimensionless cover thickness h′ = h/(VT), issue 14) the problem is solved on
//! a rubber cover bonded to a rigid carcass, with `--model auto|half-space|layer|winkler` (default
//! `auto`) and `--poisson` (default ½): the dimensionless equivalent of `roll --cover-mm`. The JSON then
//! adds the fields `roll --cover-mm` prints: `model`, `model_reason`, `model_error_estimate`, `cover`
//! (h′), `cover_over_contact` (h′/λ), `poisson`, `error_estimate`, `tol`, `min_pressure_ratio`,
//! `min_gap_ratio`, `warnings`.

use crate::contact::cover::{push_length_warning, solve_cover, solve_cover_at_lambda};
use crate::contact::{self, AutoSettings, Body, ContactSettings, CreepTerm, Scheme};
use anyhow::{bail, Context};

/// Arguments of `viscoroll contact`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// Creep terms f:b[,f:b…] of γ(ζ) = Σ f·e^(−bζ) (f ≥ 0, b > 0; `0:1` is the elastic half-space).
    #[arg(long, value_name = "f:b[,f:b...]", allow_hyphen_values = true)]
    pub creep: String,
    /// Contact length λ (in units of V·T).
    #[arg(long, allow_negative_numbers = true)]
    pub lambda: Option<f64>,
    /// Load N′ = 2∫Q′dξ (eq. 3.24); λ is then found by the bracketed load loop.
    #[arg(long, allow_negative_numbers = true)]
    pub load: Option<f64>,
    /// Number of intervals on the contact.
    #[arg(long, default_value_t = 40)]
    pub n: usize,
    /// Discretisation: `thesis` (piecewise-linear collocation, `--n` intervals), `exact` (one creep
    /// term only; the pressure is then sampled at n + 1 points) or `auto` (error-controlled
    /// Chebyshev–exponential scheme, `--tol`).
    #[arg(long, default_value_t = Scheme::Thesis)]
    pub scheme: Scheme,
    /// Relative tolerance on ρF/N and λ for `--scheme auto` (1e-12 … 0.1).
    #[arg(long, default_value_t = 1e-6)]
    pub tol: f64,
    /// Dimensionless roll radius ρ = R/(VT); with it, the friction coefficient F/N is reported.
    #[arg(long, allow_negative_numbers = true)]
    pub rho: Option<f64>,
    /// Cover thickness h′ = h/(VT) (dimensionless): solve on a rubber cover bonded to a rigid carcass.
    #[arg(long, allow_negative_numbers = true)]
    pub cover: Option<f64>,
    /// Body with a cover: auto (default: the cheapest within --tol of the layer), half-space, layer,
    /// winkler (uniaxial columns, the conveyor design tools' model).
    #[arg(long)]
    pub model: Option<String>,
    /// Poisson's ratio of the cover, 0 ≤ ν ≤ 0.5 (used with --cover).
    #[arg(long, default_value_t = 0.5, allow_negative_numbers = true)]
    pub poisson: f64,
    /// Print one JSON object on stdout.
    #[arg(long)]
    pub json: bool,
}

/// Parse `f:b[,f:b…]` into creep terms (f ≥ 0, b > 0, finite).
pub fn parse_creep(text: &str) -> anyhow::Result<Vec<CreepTerm>> {
    let mut terms = Vec::new();
    for (i, item) in text.split(',').enumerate() {
        let item = item.trim();
        let (f, b) = item
            .split_once(':')
            .with_context(|| format!("--creep term {} `{item}` is not of the form f:b", i + 1))?;
        let f: f64 = f.trim().parse().with_context(|| {
            format!("--creep term {} `{item}`: f = `{f}` is not a number", i + 1)
        })?;
        let b: f64 = b.trim().parse().with_context(|| {
            format!("--creep term {} `{item}`: b = `{b}` is not a number", i + 1)
        })?;
        if !(f.is_finite() && f >= 0.0) {
            bail!(
                "--creep term {} `{item}`: f must be finite and >= 0, got {f}",
                i + 1
            );
        }
        if !(b.is_finite() && b > 0.0) {
            bail!(
                "--creep term {} `{item}`: b must be finite and > 0, got {b}",
                i + 1
            );
        }
        terms.push(CreepTerm { f, b });
    }
    Ok(terms)
}

/// Run `viscoroll contact`.
pub fn run(args: Args) -> anyhow::Result<()> {
    let terms = parse_creep(&args.creep)?;
    if let Some(rho) = args.rho {
        if !(rho.is_finite() && rho > 0.0) {
            bail!("--rho must be finite and > 0, got {rho}");
        }
    }
    let settings = ContactSettings {
        scheme: args.scheme,
        n: args.n,
        auto: AutoSettings {
            tol: args.tol,
            ..AutoSettings::default()
        },
        ..ContactSettings::default()
    };
    if args.cover.is_some() || args.model.is_some() {
        return run_cover(&args, &terms, &settings);
    }
    if args.scheme == Scheme::Auto {
        return run_auto(&args, &terms, &settings);
    }
    let sol = match (args.lambda, args.load) {
        (Some(lambda), None) => {
            if !(lambda.is_finite() && lambda > 0.0) {
                bail!("--lambda must be finite and > 0, got {lambda}");
            }
            contact::solve_at_lambda(&terms, lambda, &settings)?
        }
        (None, Some(load)) => {
            if !(load.is_finite() && load > 0.0) {
                bail!("--load must be finite and > 0, got {load}");
            }
            contact::solve_at_load(&terms, load, &settings)?
        }
        (Some(_), Some(_)) => bail!("give only one of --lambda and --load, not both"),
        (None, None) => bail!("give one of --lambda L (contact length) or --load N' (load)"),
    };
    let friction = args.rho.map(|rho| sol.friction_rho / rho);
    if args.json {
        let mut obj = solution_json(&sol, &terms);
        if let Some(e) = sol.error_estimate {
            obj["error_estimate"] = serde_json::json!(e);
        }
        print_json(obj, args.rho, friction);
    } else {
        errln!(
            "scheme {}  n = {}  load iterations = {}",
            sol.scheme,
            sol.n,
            sol.iterations
        );
        errln!("creep terms (f, b): {}", args.creep);
        errln!("lambda           = {:.9}", sol.lambda);
        errln!("beta             = {:.9}", sol.beta);
        errln!("beta/lambda      = {:.9}", sol.beta / sol.lambda);
        errln!("load N'          = {:.9}", sol.load);
        errln!("rho*F/N          = {:.9}", sol.friction_rho);
        if let Some(fr) = friction {
            errln!("F/N              = {fr:.9e}");
        }
        if terms == [CreepTerm { f: 10.0, b: 1.0 }] && args.lambda == Some(1.0) {
            errln!(
                "thesis Table 1 (n = 40): beta/lambda = 0.1959, rho*F/N = 0.43093; \
                 Goodier & Loutzenheiser: 0.1952, 0.4308"
            );
        }
        errln!("{:>14} {:>14}", "xi", "Q'");
        for (x, q) in sol.xi.iter().zip(&sol.pressure) {
            errln!("{x:>14.6e} {q:>14.6e}");
        }
    }
    Ok(())
}

/// `--scheme auto`: the error-controlled solver; JSON adds `error_estimate`, `modes_used`,
/// `modes_total`, `modes_lumped`, `modes_dropped`, `min_pressure_ratio`, `tol`, `warnings`.
fn run_auto(args: &Args, terms: &[CreepTerm], settings: &ContactSettings) -> anyhow::Result<()> {
    let sol = match (args.lambda, args.load) {
        (Some(lambda), None) => contact::solve_at_lambda(terms, lambda, settings)?,
        (None, Some(load)) => contact::solve_at_load(terms, load, settings)?,
        _ => bail!("give exactly one of --lambda and --load"),
    };
    let d = &sol;
    let Some(diag) = d.diagnostics.as_ref() else {
        bail!("the auto scheme returned no diagnostics");
    };
    let friction = args.rho.map(|rho| d.friction_rho / rho);
    if args.json {
        let mut obj = serde_json::to_value(&sol)?;
        obj["creep"] = serde_json::json!(terms);
        obj["beta_over_lambda"] = serde_json::json!(d.beta / d.lambda);
        print_json(obj, args.rho, friction);
    } else {
        errln!(
            "scheme auto  tol = {:e}  modes used {}/{} (lumped {}, dropped {})  load solves = {}",
            args.tol,
            diag.modes_used,
            diag.modes_total,
            diag.modes_lumped,
            diag.modes_dropped,
            d.iterations
        );
        errln!("lambda           = {:.12}", d.lambda);
        errln!("beta             = {:.12}", d.beta);
        errln!("beta/lambda      = {:.12}", d.beta / d.lambda);
        errln!("load N'          = {:.12}", d.load);
        errln!("rho*F/N          = {:.12}", d.friction_rho);
        if let Some(fr) = friction {
            errln!("F/N              = {fr:.12e}");
        }
        errln!(
            "error estimate   = {:.3e}",
            d.error_estimate.unwrap_or(f64::NAN)
        );
        errln!("min Q'/max Q'    = {:.3e}", diag.min_pressure_ratio);
        for w in &d.warnings {
            errln!("warning: {w}");
        }
    }
    Ok(())
}

/// `--cover H′`: the body chosen (or asked for) on the cover, at given load (error-controlled, `--tol`)
/// or at given λ (the layer by the collocation with `--n` intervals, its estimate from n/2; the
/// half-space by `--scheme`; `auto` takes the criterion at the given λ).
fn run_cover(args: &Args, terms: &[CreepTerm], settings: &ContactSettings) -> anyhow::Result<()> {
    let name = args.model.as_deref().unwrap_or("auto");
    // the body asked for on a cover of h′ (its lengths in units of V·T)
    let body_on = |h: f64| Body::choice(name, Some(h)).ok().flatten();
    if body_on(1.0).is_none() {
        bail!("--model `{name}` is not known (auto, half-space, layer, winkler)");
    }
    let Some(h) = args.cover else {
        bail!("--model {name} needs --cover H' (the cover thickness h/(VT))");
    };
    if !(h.is_finite() && h > 0.0) {
        bail!("--cover must be finite and > 0, got {h}");
    }
    let nu = args.poisson;
    if !(nu.is_finite() && (0.0..=0.5).contains(&nu)) {
        bail!("--poisson must be in [0, 0.5], got {nu}");
    }
    if !(args.tol.is_finite() && (1e-12..=0.1).contains(&args.tol)) {
        bail!("--tol must be in [1e-12, 0.1], got {}", args.tol);
    }
    let body = body_on(h).context("--model with --cover")?;
    let c = match (args.lambda, args.load) {
        (None, Some(load)) => {
            if !(load.is_finite() && load > 0.0) {
                bail!("--load must be finite and > 0, got {load}");
            }
            solve_cover(terms, load, nu, &body, args.tol)?
        }
        (Some(lambda), None) => {
            if !(lambda.is_finite() && lambda > 0.0) {
                bail!("--lambda must be finite and > 0, got {lambda}");
            }
            solve_cover_at_lambda(terms, lambda, nu, &body, settings)?
        }
        (Some(_), Some(_)) => bail!("give only one of --lambda and --load, not both"),
        (None, None) => bail!("give one of --lambda L (contact length) or --load N' (load)"),
    };
    let a = &c.answer;
    let d = &a.solution;
    let mut warnings = a.warnings.clone();
    let friction = args.rho.map(|rho| d.friction_rho / rho);
    if let Some(rho) = args.rho {
        // the validity checks of `roll --cover-mm`, in units of V·T
        let depth = d.beta.max(d.lambda - d.beta).powi(2) / (2.0 * rho);
        if depth > 0.3 * h {
            warnings.push(format!(
                "indentation ≈ {depth:.3e} V·T is {:.0} % of the cover (> 30 %): small-strain layer theory loses validity",
                100.0 * depth / h
            ));
        }
        push_length_warning(&mut warnings, d.lambda, rho);
    }
    if args.json {
        let mut obj = solution_json(d, terms);
        let cover = serde_json::json!({
            "cover": h,
            "cover_over_contact": h / d.lambda,
            "poisson": nu,
            "model": c.model.name(),
            "model_reason": c.reason,
            "model_error_estimate": c.model_error_estimate,
            "error_estimate": a.error_estimate,
            "tol": args.tol,
            "min_pressure_ratio": a.min_pressure_ratio,
            "min_gap_ratio": a.min_gap_ratio,
            "warnings": warnings,
        });
        if let (Some(o), serde_json::Value::Object(extra)) = (obj.as_object_mut(), cover) {
            o.extend(extra);
        }
        print_json(obj, args.rho, friction);
    } else {
        errln!(
            "cover h' = {h}  nu = {nu}  creep terms (f, b): {}",
            args.creep
        );
        errln!("body             = {} ({})", c.model.name(), c.reason);
        errln!("lambda           = {:.9}", d.lambda);
        errln!("beta             = {:.9}", d.beta);
        errln!("load N'          = {:.9}", d.load);
        errln!("rho*F/N          = {:.9}", d.friction_rho);
        if let Some(fr) = friction {
            errln!("F/N              = {fr:.9e}");
        }
        errln!(
            "error estimate   = {:.3e}{}",
            a.error_estimate,
            c.model_error_estimate
                .map(|e| format!(", model error estimate (vs the layer) {e:.2e}"))
                .unwrap_or_default()
        );
        for w in &warnings {
            errln!("warning: {w}");
        }
    }
    Ok(())
}

/// The fields every `contact --json` answer carries: scheme, creep terms, λ, β, β/λ, N′, ρF/N, n,
/// solves, and the pressure Q′(ξ).
fn solution_json(d: &contact::DimensionlessSolution, terms: &[CreepTerm]) -> serde_json::Value {
    serde_json::json!({
        "scheme": d.scheme,
        "creep": terms,
        "lambda": d.lambda,
        "beta": d.beta,
        "beta_over_lambda": d.beta / d.lambda,
        "load": d.load,
        "friction_rho": d.friction_rho,
        "n": d.n,
        "iterations": d.iterations,
        "xi": d.xi,
        "pressure": d.pressure,
    })
}

/// Print the one JSON object, with `rho` and `friction` = (ρF/N)/ρ when `--rho` was given.
fn print_json(mut obj: serde_json::Value, rho: Option<f64>, friction: Option<f64>) {
    if let (Some(rho), Some(fr)) = (rho, friction) {
        obj["rho"] = serde_json::json!(rho);
        obj["friction"] = serde_json::json!(fr);
    }
    outln!("{}", super::output::versioned(obj));
}
