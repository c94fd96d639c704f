//! Plots of a compound's fit (plotters; SVG or PNG chosen by the file extension): raw isotherms, the
//! master curve with the Prony fit, log a_T with the WLF and Arrhenius laws, the spectrum, line
//! charts of friction, and heat maps. Every x–y plot is a `Chart` ([`super::chart`]).
//!
//! Input: [`Measurement`], [`MasterPoint`]s, [`RelaxationSpectrum`], [`ShiftLaw`]s, `Chart`s;
//! output: image files, written atomically (temp file + rename). Text is drawn with DejaVu Sans embedded in the
//! binary (assets/fonts/, Bitstream Vera licence), registered with plotters' `ab_glyph` backend, so
//! PNG works on machines with no font libraries. The library never prints; errors are [`PlotError`].

use super::chart::{
    self, draw_chart, Axis, Chart, ColourBar, Curve, Mark, Ticked, TICK_PX, TITLE_PX,
};
use super::ticks::{log_tick_label, log_ticks};
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
/// ([`crate::fsutil::TempFile`]: created exclusively, keeping the extension, which the bitmap encoder
/// reads), then move it into place.
macro_rules! render_to {
    ($path:expr, $draw:ident ( $($arg:expr),* )) => {{
        let path: &Path = $path;
        ensure_font();
        let ext = path.extension().and_then(|e| e.to_str()).map(|e| e.to_ascii_lowercase());
        let draw_err = |message: String| PlotError::Draw { path: path.to_path_buf(), message };
        if !matches!(ext.as_deref(), Some("svg" | "png")) {
            return Err(PlotError::UnknownFormat { path: path.to_path_buf() });
        }
        let io_err = |source| PlotError::Io { path: path.to_path_buf(), source };
        let temp = crate::fsutil::TempFile::beside(path).map_err(io_err)?;
        let tmp = temp.path().to_path_buf();
        let result: Result<(), PlotError> = if ext.as_deref() == Some("svg") {
            let root = SVGBackend::new(&tmp, PLOT_SIZE).into_drawing_area();
            $draw(&root, $($arg),*).map_err(draw_err)
                .and_then(|_| root.present().map_err(|e| draw_err(e.to_string())))
        } else {
            let root = BitMapBackend::new(&tmp, PLOT_SIZE).into_drawing_area();
            $draw(&root, $($arg),*).map_err(draw_err)
                .and_then(|_| root.present().map_err(|e| draw_err(e.to_string())))
        };
        // on an error the temp file is removed when dropped
        result.and_then(|()| temp.commit(true, false).map_err(io_err))
    }};
}

/// Draw `chart` to `path` (SVG or PNG by the extension); [`PlotError::NoData`] when no point can
/// be drawn.
pub(crate) fn plot_chart(chart: &Chart, what: &'static str, path: &Path) -> Result<(), PlotError> {
    if chart::ranges(chart).is_none() {
        return Err(PlotError::NoData {
            what,
            reason: "no point with finite values (positive on a log axis)",
        });
    }
    render_to!(path, draw_chart(chart))
}

/// Most markers drawn per series: a 1e6-point export would otherwise put 1e6 circles into every SVG
/// (hundreds of MB) and take minutes to draw; 2000 markers already overlap on a 900-pixel-wide plot.
pub(crate) const MAX_MARKERS: usize = 2000;

/// Every k-th item so that at most `MAX_MARKERS` remain (the first one always kept).
pub fn thinned<T: Copy>(v: &[T]) -> Vec<T> {
    let k = v.len().div_ceil(MAX_MARKERS).max(1);
    v.iter().step_by(k).copied().collect()
}

/// The symbols of a measurement's moduli: (storage, loss).
pub(crate) fn symbols(kind: crate::ModulusKind) -> (&'static str, &'static str) {
    let (storage, loss, _) = kind.symbols();
    (storage, loss)
}

/// Raw isotherms: storage modulus (filled dots, lines) and loss modulus (open circles) against
/// frequency, coloured by temperature with a colour bar.
pub(crate) fn isotherms_chart(m: &Measurement) -> Chart {
    let (lo, hi) = m
        .isotherms
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), i| {
            (lo.min(i.temp_nominal_c), hi.max(i.temp_nominal_c))
        });
    let sym = symbols(m.kind);
    let mut curves = Vec::new();
    for iso in &m.isotherms {
        let s = if hi > lo {
            (iso.temp_nominal_c - lo) / (hi - lo)
        } else {
            0.5
        };
        let c = chart::ramp(s);
        let k = iso.points.len().div_ceil(MAX_MARKERS).max(1);
        let pts: Vec<&crate::dma::DataPoint> = iso.points.iter().step_by(k).collect();
        curves.push(
            Curve::new(
                "",
                pts.iter().map(|p| (p.freq_hz, p.storage_pa)).collect(),
                Mark::LineDots,
            )
            .coloured(c),
        );
        curves.push(
            Curve::new(
                "",
                pts.iter().map(|p| (p.freq_hz, p.loss_pa)).collect(),
                Mark::LineCircles,
            )
            .coloured(c),
        );
    }
    Chart {
        title: format!("Isotherms: {} (dots), {} (circles)", sym.0, sym.1),
        x: Axis::log("frequency f [Hz]"),
        y: Axis::log("modulus [Pa]"),
        curves,
        colour_bar: Some(ColourBar {
            label: "T [°C]".into(),
            lo,
            hi,
        }),
    }
}

/// Raw isotherms (see `isotherms_chart`).
pub fn plot_isotherms(m: &Measurement, path: &Path) -> Result<(), PlotError> {
    plot_chart(&isotherms_chart(m), "isotherms", path)
}

/// The Prony fit sampled at 20 points per decade over the reduced frequencies of `points`:
/// (f, E′, E″).
pub(crate) fn fit_curve(
    points: &[MasterPoint],
    spectrum: &RelaxationSpectrum,
) -> Vec<(f64, f64, f64)> {
    let (l0, l1) = points
        .iter()
        .filter(|p| p.reduced_freq_hz > 0.0 && p.reduced_freq_hz.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
            let l = p.reduced_freq_hz.log10();
            (a.min(l), b.max(l))
        });
    if !l0.is_finite() {
        return vec![];
    }
    let n = ((l1 - l0) * 20.0).ceil().clamp(2.0, 2000.0) as usize;
    (0..=n)
        .map(|k| {
            let f = 10f64.powf(l0 + (l1 - l0) * k as f64 / n as f64);
            let (s, l) = dynamic_moduli_pa(spectrum, 2.0 * std::f64::consts::PI * f);
            (f, s, l)
        })
        .collect()
}

/// Master curve (points) with the Prony fit (lines): storage and loss modulus against reduced
/// frequency.
pub(crate) fn master_chart(points: &[MasterPoint], spectrum: &RelaxationSpectrum) -> Chart {
    let (blue, red) = (chart::PALETTE[0], chart::PALETTE[1]);
    let sym = symbols(spectrum.kind);
    let pts = thinned(points);
    let fit = fit_curve(points, spectrum);
    Chart {
        title: format!("Master curve of {} and {} with the Prony fit", sym.0, sym.1),
        x: Axis::log("reduced frequency a_T·f [Hz]"),
        y: Axis::log("modulus [Pa]"),
        curves: vec![
            Curve::new(
                format!("{} data", sym.0),
                pts.iter()
                    .map(|p| (p.reduced_freq_hz, p.storage_pa))
                    .collect(),
                Mark::Dots,
            )
            .coloured(blue),
            Curve::new(
                format!("{} data", sym.1),
                pts.iter().map(|p| (p.reduced_freq_hz, p.loss_pa)).collect(),
                Mark::Circles,
            )
            .coloured(red),
            Curve::new(
                format!("{} Prony fit", sym.0),
                fit.iter().map(|p| (p.0, p.1)).collect(),
                Mark::Line,
            )
            .coloured(blue),
            Curve::new(
                format!("{} Prony fit", sym.1),
                fit.iter().map(|p| (p.0, p.2)).collect(),
                Mark::Line,
            )
            .coloured(red),
        ],
        colour_bar: None,
    }
}

/// Master curve with the Prony fit (see `master_chart`).
pub fn plot_master_fit(
    points: &[MasterPoint],
    spectrum: &RelaxationSpectrum,
    path: &Path,
) -> Result<(), PlotError> {
    if points.is_empty() {
        return Err(PlotError::NoData {
            what: "master curve",
            reason: "no point with positive frequency and moduli",
        });
    }
    plot_chart(&master_chart(points, spectrum), "master curve", path)
}

/// A shift law in a legend entry.
fn law_label(name: &str, law: &ShiftLaw) -> String {
    match law {
        ShiftLaw::Wlf { t_ref_c, c1, c2_k } => {
            format!("{name}: C1 = {c1:.2}, C2 = {c2_k:.1} K, T_ref = {t_ref_c:.1} °C")
        }
        ShiftLaw::Arrhenius {
            t_ref_c,
            activation_energy_j_per_mol,
        } => format!(
            "{name}: E_a = {:.0} kJ/mol, T_ref = {t_ref_c:.1} °C",
            activation_energy_j_per_mol / 1e3
        ),
        ShiftLaw::Table { t_ref_c, .. } => format!("{name}: table, T_ref = {t_ref_c:.1} °C"),
    }
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
    let (t0, t1) = finite
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
            (a.min(p.0), b.max(p.0))
        });
    let n = 200;
    let mut curves: Vec<Curve> = laws
        .iter()
        .enumerate()
        .map(|(i, (name, law))| {
            let pts = (0..=n)
                .map(|k| t0 + (t1 - t0) * k as f64 / n as f64)
                .map(|t| (t, law.log10_a_t(t)))
                .filter(|p| p.1.is_finite())
                .collect();
            Curve::new(law_label(name, law), pts, Mark::Line).coloured(chart::PALETTE[1 + i])
        })
        .collect();
    curves.push(Curve::new("shifts found", finite, Mark::Dots).coloured(BLACK));
    let c = Chart {
        title: "Shift factors log10 a_T".into(),
        x: Axis::lin("temperature T [°C]"),
        y: Axis::lin("log10 a_T"),
        curves,
        colour_bar: None,
    };
    plot_chart(&c, "shift factors", path)
}

/// The relaxation spectrum: a stem Eᵢ (Gᵢ for shear) at each τᵢ (log–log), E∞ (G∞) stated in the
/// title.
#[cfg(test)]
pub fn plot_spectrum(spectrum: &RelaxationSpectrum, path: &Path) -> Result<(), PlotError> {
    let c = Chart {
        title: format!(
            "Relaxation spectrum: {} terms, {} = {:.3e} Pa",
            spectrum.terms.len(),
            spectrum.kind.symbols().2,
            spectrum.modulus_inf_pa
        ),
        x: Axis::log("relaxation time τ [s]"),
        y: Axis::log(&format!("strength {}_i [Pa]", spectrum.kind.letter())),
        curves: vec![Curve::new(
            "",
            spectrum
                .terms
                .iter()
                .map(|t| (t.tau_s, t.modulus_pa))
                .collect(),
            Mark::Stems,
        )],
        colour_bar: None,
    };
    plot_chart(&c, "spectrum", path)
}

fn e<E: std::fmt::Display>(err: E) -> String {
    err.to_string()
}

/// One panel of a heat map: its title and z\[i\]\[j\] at (x\[i\], y\[j\]).
#[derive(Debug, Clone)]
pub(crate) struct HeatPanel {
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
pub(crate) fn plot_heatmaps(
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
    let body = root.titled(title, ("sans-serif", TITLE_PX)).map_err(e)?;
    let h = body.dim_in_pixel().1;
    let (maps, bar) = body.split_vertically(h.saturating_sub(100));
    let (xe, ye) = (log_edges(x), log_edges(y));
    let tick = |v: &f64| log_tick_label(*v);
    for (area, panel) in maps
        .split_evenly((1, panels.len().max(1)))
        .iter()
        .zip(panels)
    {
        let (x0, x1, y0, y1) = (xe[0], xe[xe.len() - 1], ye[0], ye[ye.len() - 1]);
        let mut chart = ChartBuilder::on(area)
            .caption(&panel.title, ("sans-serif", TICK_PX + 2))
            .margin(8)
            .x_label_area_size(56)
            .y_label_area_size(86)
            .build_cartesian_2d(
                Ticked::new(x0, x1, log_ticks(x0, x1)),
                Ticked::new(y0, y1, log_ticks(y0, y1)),
            )
            .map_err(e)?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc(x_label)
            .y_desc(y_label)
            .label_style(("sans-serif", TICK_PX))
            .axis_desc_style(("sans-serif", TICK_PX))
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
        .x_label_area_size(50)
        .build_cartesian_2d(Ticked::new(zr.0, zr.1, log_ticks(zr.0, zr.1)), 0.0..1.0)
        .map_err(e)?;
    cb.configure_mesh()
        .disable_mesh()
        .disable_y_axis()
        .x_desc(z_label)
        .label_style(("sans-serif", TICK_PX))
        .axis_desc_style(("sans-serif", TICK_PX))
        .x_label_formatter(&|v| log_tick_label(*v))
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
