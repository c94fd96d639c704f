//! `viscoroll ingest`: read DMA exports and report what was found; optionally write the
//! `Measurement` JSON (atomically; an existing file only with `--force`).
//!
//! `--json` prints one object on stdout:
//! `{"command":"ingest","kind","poisson","files":[{"path","sha256","format","encoding","metadata",
//! "columns","isotherms","points","temp_range_c","freq_range_hz","issues"}],"summary",
//! "warnings","output"}`; human text goes to stderr.

use crate::dma::{self, Format, IngestOptions, Measurement};
use crate::ModulusKind;
use std::path::PathBuf;

/// Arguments of `viscoroll ingest`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// DMA export files (EPLEXOR .xls/.xlsx, TRIOS LIMS or text, RheoCompass CSV, Proteus ASCII,
    /// RepTate .osc, generic CSV/TSV/text).
    #[arg(required = true)]
    pub files: Vec<PathBuf>,
    /// Write the Measurement JSON here (atomically).
    #[arg(short = 'o', long = "output")]
    pub output: Option<PathBuf>,
    /// Overwrite the output file if it exists.
    #[arg(long)]
    pub force: bool,
    /// Reader to use instead of detecting it: eplexor, trios-lims, trios-text, rheocompass, proteus,
    /// reptate, generic.
    #[arg(long)]
    pub format: Option<String>,
    /// Unit of modulus columns that have none in the file: Pa, kPa, MPa, GPa.
    #[arg(long)]
    pub modulus_unit: Option<String>,
    /// Unit of the frequency column if the file has none: Hz or rad/s.
    #[arg(long)]
    pub freq_unit: Option<String>,
    /// Unit of temperature columns if the file has none: °C (or C) or K.
    #[arg(long)]
    pub temp_unit: Option<String>,
    /// tensile or shear, when the file does not say which moduli it holds.
    #[arg(long)]
    pub mode: Option<String>,
    /// Which column holds which quantity, for names no reader knows: `key=name,…` with keys freq,
    /// temp, set_temp, storage, loss, complex, tan_delta, phase, segment (e.g.
    /// `--columns freq=Frq,storage=Mod1,loss=Mod2`).
    #[arg(long)]
    pub columns: Option<String>,
    /// Poisson's ratio stated for shear ↔ tensile conversion (dimensionless, default 0.5).
    #[arg(long, default_value_t = 0.5)]
    pub poisson: f64,
    /// Print one JSON object on stdout.
    #[arg(long)]
    pub json: bool,
}

fn options(a: &Args) -> anyhow::Result<IngestOptions> {
    let mut o = IngestOptions {
        poisson: a.poisson,
        ..IngestOptions::default()
    };
    if let Some(c) = &a.columns {
        o.columns = dma::ColumnMap::parse(c).map_err(|e| anyhow::anyhow!("--columns: {e}"))?;
    }
    if let Some(f) = &a.format {
        o.format = Some(f.parse::<Format>().map_err(anyhow::Error::msg)?);
    }
    if let Some(u) = &a.modulus_unit {
        o.set_unit("modulus", u)
            .map_err(|e| anyhow::anyhow!("--modulus-unit {e}"))?;
    }
    if let Some(u) = &a.freq_unit {
        o.set_unit("freq", u)
            .map_err(|e| anyhow::anyhow!("--freq-unit {e}"))?;
    }
    if let Some(u) = &a.temp_unit {
        o.set_unit("temp", u)
            .map_err(|e| anyhow::anyhow!("--temp-unit {e}"))?;
    }
    if let Some(m) = &a.mode {
        o.mode = Some(match m.to_ascii_lowercase().as_str() {
            "tensile" | "tension" | "e" => ModulusKind::Tensile,
            "shear" | "g" => ModulusKind::Shear,
            _ => anyhow::bail!("--mode `{m}`: expected tensile or shear"),
        });
    }
    Ok(o)
}

fn range<I: Iterator<Item = f64>>(it: I) -> Option<(f64, f64)> {
    it.filter(|v| v.is_finite()).fold(None, |acc, v| match acc {
        None => Some((v, v)),
        Some((a, b)) => Some((f64::min(a, v), f64::max(b, v))),
    })
}

fn file_report(m: &Measurement, si: usize) -> serde_json::Value {
    let src = &m.sources[si];
    let isos: Vec<&dma::Isotherm> = m.isotherms.iter().filter(|i| i.source == si).collect();
    let points: usize = isos.iter().map(|i| i.points.len()).sum();
    let issues: Vec<&dma::Issue> = m.issues.iter().filter(|i| i.file == src.path).collect();
    serde_json::json!({
        "path": src.path,
        "sha256": src.sha256,
        "format": src.format,
        "encoding": src.encoding,
        "metadata": src.metadata,
        "columns": src.columns,
        "mode": dma::columns::kind_name(m.kind),
        "isotherms": isos.len(),
        "points": points,
        "nominal_temps_c": isos.iter().map(|i| i.temp_nominal_c).collect::<Vec<_>>(),
        "temp_range_c": range(isos.iter().map(|i| i.temp_mean_c)),
        "freq_range_hz": range(isos.iter().flat_map(|i| i.points.iter().map(|p| p.freq_hz))),
        "issues": issues,
    })
}

/// One file's lines on stderr: format, encoding and hash, its identifying metadata, mode and
/// columns, isotherms and ranges (from its report `r`, [`file_report`]).
fn print_file(src: &dma::SourceFile, r: &serde_json::Value) {
    errln!(
        "{}: {} ({}), sha256 {}",
        src.path,
        src.format,
        src.encoding,
        &src.sha256[..16]
    );
    let keys = [
        "Instrument type",
        "Instrument name",
        "Trios version",
        "Measurement type",
        "Material",
        "Material / Remark",
        "INSTRUMENT",
        "SAMPLE",
        "Date / Time",
        "Run date",
        "Project",
        "Test",
        "trailing text",
    ];
    for k in keys {
        if let Some(v) = src.metadata.get(k) {
            errln!("  {k}: {v}");
        }
    }
    let cols: Vec<String> = src
        .columns
        .iter()
        .map(|c| format!("{} = `{}` [{}]", c.quantity, c.name, c.unit))
        .collect();
    errln!(
        "  mode: {} (evidence: {}); columns: {}",
        r["mode"].as_str().unwrap_or(""),
        src.metadata
            .get("mode evidence")
            .map_or("-", String::as_str),
        cols.join(", ")
    );
    let tr = r["temp_range_c"].as_array().map(|a| {
        format!(
            "{:.2} … {:.2} °C",
            a[0].as_f64().unwrap_or(f64::NAN),
            a[1].as_f64().unwrap_or(f64::NAN)
        )
    });
    let fr = r["freq_range_hz"].as_array().map(|a| {
        format!(
            "{:.4} … {:.4} Hz",
            a[0].as_f64().unwrap_or(f64::NAN),
            a[1].as_f64().unwrap_or(f64::NAN)
        )
    });
    errln!(
        "  isotherms: {}, mean temperature {}, frequency {}, points: {}",
        r["isotherms"],
        tr.unwrap_or_else(|| "—".into()),
        fr.unwrap_or_else(|| "—".into()),
        r["points"]
    );
}

/// Run `viscoroll ingest`.
pub fn run(args: Args) -> anyhow::Result<()> {
    let opts = options(&args)?;
    let m = dma::read_files(&args.files, &opts)?;
    let mut files = Vec::new();
    for si in 0..m.sources.len() {
        let r = file_report(&m, si);
        print_file(&m.sources[si], &r);
        files.push(r);
    }
    let shown = 20;
    for w in m.warnings.iter().take(shown) {
        errln!("  warning: {w}");
    }
    if m.warnings.len() > shown {
        errln!(
            "  … and {} more (see --json or the output file)",
            m.warnings.len() - shown
        );
    }
    let s = &m.summary;
    use crate::results::counted;
    errln!(
        "total: {}, {}, {} ({} flagged), {}, {}",
        counted(s.files, "file"),
        counted(s.isotherms, "isotherm"),
        counted(s.points, "point"),
        s.flagged_points,
        counted(s.errors, "error"),
        counted(s.warnings, "warning")
    );
    if let Some(out) = &args.output {
        let json = serde_json::to_vec_pretty(&m)?;
        super::output::write_atomic(out, &json, args.force)?;
        errln!("wrote {}", out.display());
    }
    if args.json {
        let obj = serde_json::json!({
            "command": "ingest",
            "kind": dma::columns::kind_name(m.kind),
            "poisson": m.poisson,
            "files": files,
            "summary": m.summary,
            "warnings": m.warnings,
            "output": args.output.as_ref().map(|p| p.display().to_string()),
        });
        outln!("{}", super::output::versioned(obj));
    }
    Ok(())
}
