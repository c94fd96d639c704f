//! Plots of a compound's fit (plotters; SVG or PNG chosen by the file extension): raw isotherms, the
//! master curve with the Prony fit, log a_T with the WLF and Arrhenius laws, and the spectrum.
//!
//! Input: [`Measurement`], [`MasterPoint`]s, [`RelaxationSpectrum`], [`ShiftLaw`]s; output: image
//! files, written atomically (temp file + rename). Text is drawn with DejaVu Sans embedded in the
//! binary (assets/fonts/, Bitstream Vera licence), registered with plotters' `ab_glyph` backend, so
//! PNG works on machines with no font libraries. The library never prints; errors are [`PlotError`].

use crate::prony::kernel::dynamic_moduli_pa;
use crate::prony::MasterPoint;
use crate::{Measurement, RelaxationSpectrum, ShiftLaw};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;
use thiserror::Error;

/// DejaVu Sans (see assets/fonts/LICENSE-DejaVu.txt).
static FONT: &[u8] = include_bytes!("../../assets/fonts/DejaVuSans.ttf");

/// Size of every plot in pixels (SVG user units).
pub const PLOT_SIZE: (u32, u32) = (900, 640);

/// Why a plot could not be made.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum PlotError {
    /// The file extension is neither `.svg` nor `.png`.
    #[error("{path}: unknown plot format (use a .svg or .png file name)")]
    UnknownFormat {
        /// The path.
        path: PathBuf,
    },
    /// Nothing to plot (no points with positive values).
    #[error("nothing to plot for {what}: {reason}")]
    NoData {
        /// Which plot.
        what: &'static str,
        /// Why.
        reason: &'static str,
    },
    /// Drawing failed (plotters' message).
    #[error("{path}: drawing failed: {message}")]
    Draw {
        /// The path.
        path: PathBuf,
        /// plotters' message.
        message: String,
    },
    /// Moving the finished file into place failed.
    #[error("{path}: {source}")]
    Io {
        /// The path.
        path: PathBuf,
        /// The I/O error.
        source: std::io::Error,
    },
}

type DrawResult = Result<(), String>;

fn ensure_font() {
    static DONE: OnceLock<()> = OnceLock::new();
    DONE.get_or_init(|| {
        // The embedded font is a valid TrueType file (checked by the tests); were it not, text would
        // fail to draw and each plot would return a PlotError::Draw naming the cause.
        let _ = plotters::style::register_font("sans-serif", FontStyle::Normal, FONT);
    });
}

/// Render with the backend that matches `path`'s extension (SVG or PNG) into a temp file beside it
/// ([`crate::fsutil::temp_path`], keeping the extension, which the bitmap encoder reads), then move
/// it into place ([`crate::fsutil::commit`]).
macro_rules! render_to {
    ($path:expr, $draw:ident ( $($arg:expr),* )) => {{
        let path: &Path = $path;
        ensure_font();
        let ext = path.extension().and_then(|e| e.to_str()).map(|e| e.to_ascii_lowercase());
        let draw_err = |message: String| PlotError::Draw { path: path.to_path_buf(), message };
        if !matches!(ext.as_deref(), Some("svg" | "png")) {
            return Err(PlotError::UnknownFormat { path: path.to_path_buf() });
        }
        let tmp = crate::fsutil::temp_path(path);
        let result: Result<(), PlotError> = if ext.as_deref() == Some("svg") {
            let root = SVGBackend::new(&tmp, PLOT_SIZE).into_drawing_area();
            $draw(&root, $($arg),*).map_err(draw_err)
                .and_then(|_| root.present().map_err(|e| draw_err(e.to_string())))
        } else {
            let root = BitMapBackend::new(&tmp, PLOT_SIZE).into_drawing_area();
            $draw(&root, $($arg),*).map_err(draw_err)
                .and_then(|_| root.present().map_err(|e| draw_err(e.to_string())))
        };
        match result {
            Ok(()) => crate::fsutil::commit(&tmp, path, true)
                .map_err(|source| PlotError::Io { path: path.to_path_buf(), source }),
            Err(e) => {
                let _ = std::fs::remove_file(&tmp);
                Err(e)
            }
        }
    }};
}

type LogLogChart<'a, DB> = ChartContext<'a, DB, Cartesian2d<LogCoord<f64>, LogCoord<f64>>>;

/// The common set-up of the log–log charts: white background, caption, margins, mesh with labels
/// and exponent tick labels.
fn log_log_chart<'a, DB: DrawingBackend>(
    root: &'a DrawingArea<DB, Shift>,
    caption: &str,
    xr: (f64, f64),
    yr: (f64, f64),
    x_desc: &str,
    y_desc: &str,
) -> Result<LogLogChart<'a, DB>, String> {
    root.fill(&WHITE).map_err(e)?;
    let mut chart = ChartBuilder::on(root)
        .caption(caption, ("sans-serif", 22))
        .margin(12)
        .x_label_area_size(45)
        .y_label_area_size(70)
        .build_cartesian_2d((xr.0..xr.1).log_scale(), (yr.0..yr.1).log_scale())
        .map_err(e)?;
    chart
        .configure_mesh()
        .x_desc(x_desc)
        .y_desc(y_desc)
        .y_label_formatter(&|v| format!("{v:.0e}"))
        .x_label_formatter(&|v| format!("{v:.0e}"))
        .draw()
        .map_err(e)?;
    Ok(chart)
}

/// The legend box of every chart: white, framed, at `position`, labels of `size` px.
fn legend<'a, DB: DrawingBackend + 'a, CT: CoordTranslate>(
    chart: &mut ChartContext<'a, DB, CT>,
    position: SeriesLabelPosition,
    size: u32,
) -> Result<(), String> {
    chart
        .configure_series_labels()
        .position(position)
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .label_font(("sans-serif", size))
        .draw()
        .map_err(e)
}

/// Colour of temperature `t` within [`lo`, `hi`]: blue (cold) → red (hot).
fn temp_colour(t: f64, lo: f64, hi: f64) -> RGBColor {
    let s = if hi > lo {
        ((t - lo) / (hi - lo)).clamp(0.0, 1.0)
    } else {
        0.5
    };
    let hsl = HSLColor(0.66 * (1.0 - s), 0.85, 0.45);
    let (r, g, b) = hsl.rgb();
    RGBColor(r, g, b)
}

/// Padded log range [lo/pad, hi·pad] of positive values.
fn log_range(values: impl Iterator<Item = f64>) -> Option<(f64, f64)> {
    let (lo, hi) = values
        .filter(|v| v.is_finite() && *v > 0.0)
        .fold((f64::INFINITY, 0.0f64), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
    (hi > 0.0).then(|| {
        let pad = if hi > lo { (hi / lo).powf(0.03) } else { 2.0 };
        (lo / pad, hi * pad)
    })
}

fn e<E: std::fmt::Display>(err: E) -> String {
    err.to_string()
}

/// Raw isotherms: log f vs log E′ (filled dots, lines) and E″ (open dots), coloured by temperature.
pub fn plot_isotherms(m: &Measurement, path: &Path) -> Result<(), PlotError> {
    let pts = || m.isotherms.iter().flat_map(|i| i.points.iter());
    let xr = log_range(pts().map(|p| p.freq_hz));
    let yr = log_range(pts().flat_map(|p| [p.storage_pa, p.loss_pa]));
    let (Some(xr), Some(yr)) = (xr, yr) else {
        return Err(PlotError::NoData {
            what: "isotherms",
            reason: "no point with positive frequency and moduli",
        });
    };
    render_to!(path, draw_isotherms(m, xr, yr))
}

fn draw_isotherms<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    m: &Measurement,
    xr: (f64, f64),
    yr: (f64, f64),
) -> DrawResult {
    let sym = if m.kind == crate::ModulusKind::Shear {
        ("G′", "G″")
    } else {
        ("E′", "E″")
    };
    let mut chart = log_log_chart(
        root,
        &format!("Isotherms: {} (filled), {} (open)", sym.0, sym.1),
        xr,
        yr,
        "frequency f [Hz]",
        "modulus [Pa]",
    )?;
    let (lo, hi) = m
        .isotherms
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), i| {
            (lo.min(i.temp_nominal_c), hi.max(i.temp_nominal_c))
        });
    for iso in &m.isotherms {
        let c = temp_colour(iso.temp_nominal_c, lo, hi);
        let ok: Vec<_> = iso.points.iter().filter(|p| p.freq_hz > 0.0).collect();
        let s: Vec<(f64, f64)> = ok
            .iter()
            .filter(|p| p.storage_pa > 0.0)
            .map(|p| (p.freq_hz, p.storage_pa))
            .collect();
        let l: Vec<(f64, f64)> = ok
            .iter()
            .filter(|p| p.loss_pa > 0.0)
            .map(|p| (p.freq_hz, p.loss_pa))
            .collect();
        let (s, l) = (thinned(&s), thinned(&l));
        chart
            .draw_series(LineSeries::new(s.iter().copied(), c.stroke_width(1)))
            .map_err(e)?
            .label(format!("{:.0} °C", iso.temp_nominal_c))
            .legend(move |(x, y)| Circle::new((x + 8, y), 4, c.filled()));
        chart
            .draw_series(s.iter().map(|&p| Circle::new(p, 3, c.filled())))
            .map_err(e)?;
        chart
            .draw_series(LineSeries::new(l.iter().copied(), c.stroke_width(1)))
            .map_err(e)?;
        chart
            .draw_series(l.iter().map(|&p| Circle::new(p, 3, c.stroke_width(1))))
            .map_err(e)?;
    }
    legend(&mut chart, SeriesLabelPosition::LowerRight, 12)?;
    Ok(())
}

/// Most markers drawn per series: a 1e6-point export would otherwise put 1e6 circles into every SVG
/// (hundreds of MB) and take minutes to draw; 2000 markers already overlap on a 900-pixel-wide plot.
pub const MAX_MARKERS: usize = 2000;

/// Every k-th item so that at most [`MAX_MARKERS`] remain (the first one always kept).
pub fn thinned<T: Copy>(v: &[T]) -> Vec<T> {
    let k = v.len().div_ceil(MAX_MARKERS).max(1);
    v.iter().step_by(k).copied().collect()
}

/// Master curve (points) with the Prony fit (lines): E′ and E″ against reduced frequency.
pub fn plot_master_fit(
    points: &[MasterPoint],
    spectrum: &RelaxationSpectrum,
    path: &Path,
) -> Result<(), PlotError> {
    let xr = log_range(points.iter().map(|p| p.reduced_freq_hz));
    let yr = log_range(points.iter().flat_map(|p| [p.storage_pa, p.loss_pa]));
    let (Some(xr), Some(yr)) = (xr, yr) else {
        return Err(PlotError::NoData {
            what: "master curve",
            reason: "no point with positive frequency and moduli",
        });
    };
    render_to!(path, draw_master(points, spectrum, xr, yr))
}

fn draw_master<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    points: &[MasterPoint],
    spectrum: &RelaxationSpectrum,
    xr: (f64, f64),
    yr: (f64, f64),
) -> DrawResult {
    let mut chart = log_log_chart(
        root,
        "Master curve and Prony fit",
        xr,
        yr,
        "reduced frequency a_T·f [Hz]",
        "modulus [Pa]",
    )?;
    let (blue, red) = (RGBColor(30, 90, 200), RGBColor(210, 50, 40));
    let points = &thinned(points)[..];
    chart
        .draw_series(
            points
                .iter()
                .map(|p| Circle::new((p.reduced_freq_hz, p.storage_pa), 3, blue.filled())),
        )
        .map_err(e)?
        .label("storage (data)")
        .legend(move |(x, y)| Circle::new((x + 8, y), 4, blue.filled()));
    chart
        .draw_series(
            points
                .iter()
                .map(|p| Circle::new((p.reduced_freq_hz, p.loss_pa), 3, red.stroke_width(1))),
        )
        .map_err(e)?
        .label("loss (data)")
        .legend(move |(x, y)| Circle::new((x + 8, y), 4, red.stroke_width(1)));
    // The fit on a fine grid: 20 points per decade.
    let (l0, l1) = (xr.0.log10(), xr.1.log10());
    let n = ((l1 - l0) * 20.0).ceil().max(2.0) as usize;
    let curve: Vec<(f64, (f64, f64))> = (0..=n)
        .map(|k| {
            let f = 10f64.powf(l0 + (l1 - l0) * k as f64 / n as f64);
            (
                f,
                dynamic_moduli_pa(spectrum, 2.0 * std::f64::consts::PI * f),
            )
        })
        .collect();
    chart
        .draw_series(LineSeries::new(
            curve.iter().map(|&(f, (s, _))| (f, s)),
            blue.stroke_width(2),
        ))
        .map_err(e)?
        .label("storage (Prony fit)")
        .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 16, y)], blue.stroke_width(2)));
    chart
        .draw_series(LineSeries::new(
            curve
                .iter()
                .filter(|c| c.1 .1 >= yr.0)
                .map(|&(f, (_, l))| (f, l)),
            red.stroke_width(2),
        ))
        .map_err(e)?
        .label("loss (Prony fit)")
        .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 16, y)], red.stroke_width(2)));
    legend(&mut chart, SeriesLabelPosition::UpperLeft, 14)?;
    Ok(())
}

/// log10 a_T against temperature: the shifts found (points) and the WLF and Arrhenius laws (lines).
/// `shifts` are (temperature in °C, log10 a_T); `laws` are drawn over the shifts' temperature range.
pub fn plot_shift_factors(
    shifts: &[(f64, f64)],
    laws: &[(&str, &ShiftLaw)],
    path: &Path,
) -> Result<(), PlotError> {
    let finite: Vec<(f64, f64)> = shifts
        .iter()
        .copied()
        .filter(|(t, a)| t.is_finite() && a.is_finite())
        .collect();
    if finite.is_empty() {
        return Err(PlotError::NoData {
            what: "shift factors",
            reason: "no finite (T, log a_T) pair",
        });
    }
    render_to!(path, draw_shifts(&finite, laws))
}

fn draw_shifts<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    shifts: &[(f64, f64)],
    laws: &[(&str, &ShiftLaw)],
) -> DrawResult {
    root.fill(&WHITE).map_err(e)?;
    let (t0, t1) = shifts
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
            (a.min(p.0), b.max(p.0))
        });
    let (t0, t1) = if t1 > t0 {
        (t0, t1)
    } else {
        (t0 - 1.0, t1 + 1.0)
    };
    let n = 200;
    let curves: Vec<Vec<(f64, f64)>> = laws
        .iter()
        .map(|(_, law)| {
            (0..=n)
                .map(|k| t0 + (t1 - t0) * k as f64 / n as f64)
                .map(|t| (t, law.log10_a_t(t)))
                .filter(|p| p.1.is_finite())
                .collect()
        })
        .collect();
    let ys = shifts
        .iter()
        .map(|p| p.1)
        .chain(curves.iter().flatten().map(|p| p.1));
    let (y0, y1) = ys.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), y| {
        (a.min(y), b.max(y))
    });
    let pad = ((y1 - y0) * 0.05).max(0.5);
    let dt = (t1 - t0) * 0.03;
    let mut chart = ChartBuilder::on(root)
        .caption("Shift factors log a_T", ("sans-serif", 22))
        .margin(12)
        .x_label_area_size(45)
        .y_label_area_size(60)
        .build_cartesian_2d((t0 - dt)..(t1 + dt), (y0 - pad)..(y1 + pad))
        .map_err(e)?;
    chart
        .configure_mesh()
        .x_desc("temperature T [°C]")
        .y_desc("log10 a_T")
        .draw()
        .map_err(e)?;
    let palette = [
        RGBColor(210, 50, 40),
        RGBColor(30, 140, 60),
        RGBColor(130, 60, 170),
    ];
    for (i, ((name, law), curve)) in laws.iter().zip(&curves).enumerate() {
        let c = palette[i % palette.len()];
        let label = match law {
            ShiftLaw::Wlf { t_ref_c, c1, c2_k } => {
                format!("{name}: C1 = {c1:.2}, C2 = {c2_k:.1} K, T_ref = {t_ref_c:.2} °C")
            }
            ShiftLaw::Arrhenius {
                t_ref_c,
                activation_energy_j_per_mol,
            } => {
                format!(
                    "{name}: E_a = {:.0} kJ/mol, T_ref = {t_ref_c:.2} °C",
                    activation_energy_j_per_mol / 1e3
                )
            }
            ShiftLaw::Table { t_ref_c, .. } => format!("{name}: table, T_ref = {t_ref_c:.2} °C"),
        };
        chart
            .draw_series(LineSeries::new(curve.iter().copied(), c.stroke_width(2)))
            .map_err(e)?
            .label(label)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 16, y)], c.stroke_width(2)));
    }
    chart
        .draw_series(shifts.iter().map(|&p| Circle::new(p, 4, BLACK.filled())))
        .map_err(e)?
        .label("shifts found")
        .legend(|(x, y)| Circle::new((x + 8, y), 4, BLACK.filled()));
    legend(&mut chart, SeriesLabelPosition::UpperRight, 14)?;
    Ok(())
}

/// The relaxation spectrum: a stem Eᵢ at each τᵢ (log–log), E∞ stated in the caption.
pub fn plot_spectrum(spectrum: &RelaxationSpectrum, path: &Path) -> Result<(), PlotError> {
    let xr = log_range(spectrum.terms.iter().map(|t| t.tau_s));
    let yr = log_range(spectrum.terms.iter().map(|t| t.modulus_pa));
    let (Some(xr), Some(yr)) = (xr, yr) else {
        return Err(PlotError::NoData {
            what: "spectrum",
            reason: "no term with positive strength and time",
        });
    };
    // Stems start a decade below the smallest strength so every term is visible.
    let yr = (yr.0 / 10.0, yr.1 * 2.0);
    render_to!(path, draw_spectrum(spectrum, xr, yr))
}

fn draw_spectrum<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    spectrum: &RelaxationSpectrum,
    xr: (f64, f64),
    yr: (f64, f64),
) -> DrawResult {
    let mut chart = log_log_chart(
        root,
        &format!(
            "Relaxation spectrum: {} terms, E∞ = {:.3e} Pa",
            spectrum.terms.len(),
            spectrum.modulus_inf_pa
        ),
        xr,
        yr,
        "relaxation time τ [s]",
        "strength E_i [Pa]",
    )?;
    let c = RGBColor(30, 90, 200);
    chart
        .draw_series(spectrum.terms.iter().map(|t| {
            PathElement::new(
                vec![(t.tau_s, yr.0), (t.tau_s, t.modulus_pa)],
                c.stroke_width(2),
            )
        }))
        .map_err(e)?;
    chart
        .draw_series(
            spectrum
                .terms
                .iter()
                .map(|t| Circle::new((t.tau_s, t.modulus_pa), 4, c.filled())),
        )
        .map_err(e)?;
    Ok(())
}

/// A short label for an axis value: three significant digits, exponent form outside [0.01, 1e4).
fn short(v: f64) -> String {
    let a = v.abs();
    if a == 0.0 {
        "0".into()
    } else if !(0.01..1e4).contains(&a) {
        format!("{v:.2e}")
    } else {
        let decimals = (2 - a.log10().floor() as i32).max(0) as usize;
        let t = format!("{v:.decimals$}");
        if t.contains('.') {
            t.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            t
        }
    }
}

/// Series colours of the line charts.
const PALETTE: [RGBColor; 7] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(255, 127, 14),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
];

/// One named curve: (x, y) points.
pub type Series = (String, Vec<(f64, f64)>);

/// Curves of positive y on a log axis against x, linear or (when `log_x`) logarithmic: the friction
/// against temperature, speed and load. Points with y ≤ 0 or non-finite values are left out.
pub fn plot_lines(
    title: &str,
    x_label: &str,
    y_label: &str,
    series: &[Series],
    log_x: bool,
    path: &Path,
) -> Result<(), PlotError> {
    // Both axes are drawn in log10 on linear coordinates labelled with 10^v (so short log ranges,
    // under a decade, still get evenly spaced tick labels); x stays linear unless `log_x`.
    let pts: Vec<Series> = series
        .iter()
        .map(|(n, p)| {
            let kept = p
                .iter()
                .filter(|(x, y)| x.is_finite() && y.is_finite() && *y > 0.0 && (!log_x || *x > 0.0))
                .map(|&(x, y)| (if log_x { x.log10() } else { x }, y.log10()))
                .collect();
            (n.clone(), kept)
        })
        .collect();
    let range = |f: &dyn Fn(&(f64, f64)) -> f64| {
        pts.iter()
            .flat_map(|s| s.1.iter().map(f))
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
                (a.min(v), b.max(v))
            })
    };
    let ((x0, x1), (y0, y1)) = (range(&|p| p.0), range(&|p| p.1));
    if !x0.is_finite() {
        return Err(PlotError::NoData {
            what: "line chart",
            reason: "no point with finite x and positive y",
        });
    }
    let padded = |a: f64, b: f64, min: f64| {
        let pad = if b > a { 0.04 * (b - a) } else { min };
        (a - pad, b + pad)
    };
    let xr = padded(x0, x1, 0.5);
    let yr = padded(y0, y1, 0.1);
    render_to!(
        path,
        draw_lines(title, x_label, y_label, &pts, log_x, xr, yr)
    )
}

#[allow(clippy::too_many_arguments)]
fn draw_lines<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    title: &str,
    x_label: &str,
    y_label: &str,
    series: &[Series],
    log_x: bool,
    xr: (f64, f64),
    yr: (f64, f64),
) -> DrawResult {
    root.fill(&WHITE).map_err(e)?;
    let mut chart = ChartBuilder::on(root)
        .caption(title, ("sans-serif", 22))
        .margin(12)
        .x_label_area_size(45)
        .y_label_area_size(80)
        .build_cartesian_2d(xr.0..xr.1, yr.0..yr.1)
        .map_err(e)?;
    let x_fmt = |v: &f64| {
        if log_x {
            short(10f64.powf(*v))
        } else {
            short(*v)
        }
    };
    chart
        .configure_mesh()
        .x_desc(x_label)
        .y_desc(y_label)
        .x_label_formatter(&x_fmt)
        .y_label_formatter(&|v| format!("{:.2e}", 10f64.powf(*v)))
        .draw()
        .map_err(e)?;
    for (i, (name, p)) in series.iter().enumerate() {
        let c = PALETTE[i % PALETTE.len()];
        chart
            .draw_series(LineSeries::new(p.iter().copied(), c.stroke_width(2)))
            .map_err(e)?
            .label(name.as_str())
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 16, y)], c.stroke_width(2)));
        chart
            .draw_series(p.iter().map(|&q| Circle::new(q, 3, c.filled())))
            .map_err(e)?;
    }
    legend(&mut chart, SeriesLabelPosition::UpperRight, 14)?;
    Ok(())
}

/// One panel of a heat map: its title and z\[i\]\[j\] at (x\[i\], y\[j\]).
#[derive(Debug, Clone)]
pub struct HeatPanel {
    /// Panel title (e.g. the temperature).
    pub title: String,
    /// Values, `z[i][j]` at `x[i]`, `y[j]`; non-positive or non-finite cells are left white.
    pub z: Vec<Vec<f64>>,
}

/// Colour of s ∈ [0, 1] on a dark-blue → green → yellow scale.
fn heat_colour(s: f64) -> RGBColor {
    let s = s.clamp(0.0, 1.0);
    let (r, g, b) = HSLColor(0.7 - 0.55 * s, 0.8, 0.25 + 0.35 * s).rgb();
    RGBColor(r, g, b)
}

/// Heat maps side by side on log x and log y axes (x and y > 0, log-spaced grids), coloured by
/// log10 z on one scale shared by all panels, with a colour bar: the 2-D friction maps (speed ×
/// load, one panel per temperature).
pub fn plot_heatmaps(
    title: &str,
    axes: (&str, &str, &str),
    x: &[f64],
    y: &[f64],
    panels: &[HeatPanel],
    path: &Path,
) -> Result<(), PlotError> {
    let zs = panels.iter().flat_map(|p| p.z.iter().flatten().copied());
    let (z0, z1) = zs
        .filter(|z| z.is_finite() && *z > 0.0)
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), z| {
            (a.min(z.log10()), b.max(z.log10()))
        });
    let ok = z0.is_finite()
        && x.len() >= 2
        && y.len() >= 2
        && x.iter().chain(y).all(|v| v.is_finite() && *v > 0.0)
        && panels
            .iter()
            .all(|p| p.z.len() == x.len() && p.z.iter().all(|r| r.len() == y.len()));
    if !ok {
        return Err(PlotError::NoData {
            what: "heat map",
            reason: "needs ≥ 2 positive x and y and one positive value per cell",
        });
    }
    let zr = if z1 > z0 {
        (z0, z1)
    } else {
        (z0 - 0.5, z1 + 0.5)
    };
    render_to!(path, draw_heatmaps(title, axes, x, y, panels, zr))
}

/// Cell edges in log10 of a log-spaced grid: midpoints, and half a step beyond each end.
fn log_edges(v: &[f64]) -> Vec<f64> {
    let l: Vec<f64> = v.iter().map(|x| x.log10()).collect();
    let n = l.len();
    let mut edges = vec![l[0] - 0.5 * (l[1] - l[0])];
    edges.extend(l.windows(2).map(|w| 0.5 * (w[0] + w[1])));
    edges.push(l[n - 1] + 0.5 * (l[n - 1] - l[n - 2]));
    edges
}

fn draw_heatmaps<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    title: &str,
    (x_label, y_label, z_label): (&str, &str, &str),
    x: &[f64],
    y: &[f64],
    panels: &[HeatPanel],
    zr: (f64, f64),
) -> DrawResult {
    root.fill(&WHITE).map_err(e)?;
    let body = root.titled(title, ("sans-serif", 22)).map_err(e)?;
    let h = body.dim_in_pixel().1;
    let (maps, bar) = body.split_vertically(h.saturating_sub(90));
    let (xe, ye) = (log_edges(x), log_edges(y));
    let tick = |v: &f64| short(10f64.powf(*v));
    for (area, panel) in maps
        .split_evenly((1, panels.len().max(1)))
        .iter()
        .zip(panels)
    {
        let mut chart = ChartBuilder::on(area)
            .caption(&panel.title, ("sans-serif", 16))
            .margin(8)
            .x_label_area_size(40)
            .y_label_area_size(60)
            .build_cartesian_2d(xe[0]..xe[xe.len() - 1], ye[0]..ye[ye.len() - 1])
            .map_err(e)?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc(x_label)
            .y_desc(y_label)
            .x_labels(5)
            .y_labels(6)
            .x_label_formatter(&tick)
            .y_label_formatter(&tick)
            .draw()
            .map_err(e)?;
        let mut cells = Vec::new();
        for (i, row) in panel.z.iter().enumerate() {
            for (j, &z) in row.iter().enumerate() {
                if z.is_finite() && z > 0.0 {
                    let s = (z.log10() - zr.0) / (zr.1 - zr.0);
                    cells.push(Rectangle::new(
                        [(xe[i], ye[j]), (xe[i + 1], ye[j + 1])],
                        heat_colour(s).filled(),
                    ));
                }
            }
        }
        chart.draw_series(cells).map_err(e)?;
    }
    // colour bar: log10 z from zr.0 to zr.1
    let mut cb = ChartBuilder::on(&bar)
        .margin_left(120)
        .margin_right(120)
        .margin_top(10)
        .x_label_area_size(45)
        .build_cartesian_2d(zr.0..zr.1, 0.0..1.0)
        .map_err(e)?;
    cb.configure_mesh()
        .disable_mesh()
        .disable_y_axis()
        .x_desc(z_label)
        .x_labels(6)
        .label_style(("sans-serif", 14))
        .axis_desc_style(("sans-serif", 16))
        .x_label_formatter(&|v| format!("{:.2e}", 10f64.powf(*v)))
        .draw()
        .map_err(e)?;
    let n = 100;
    cb.draw_series((0..n).map(|k| {
        let a = zr.0 + (zr.1 - zr.0) * k as f64 / n as f64;
        let b = zr.0 + (zr.1 - zr.0) * (k + 1) as f64 / n as f64;
        Rectangle::new(
            [(a, 0.0), (b, 1.0)],
            heat_colour((k as f64 + 0.5) / n as f64).filled(),
        )
    }))
    .map_err(e)?;
    Ok(())
}
