//! The one line chart every x–y plot of the reports is drawn with: curves (lines, markers or
//! stems) on linear or log axes with 1-2-5 ticks ([`super::ticks`]), shaded uncertainty bands, and
//! the legend or a colour bar in a panel beside the plot, never over the data.
//!
//! Input: a `Chart` (plain data: curves in the values' own units); output: drawing on a plotters
//! area (`draw_chart`); [`super::plots`] renders it to SVG or PNG. Log axes are drawn as log10 of
//! the value on a linear coordinate (points ≤ 0 on a log axis are left out).

use super::ticks::{linear_ticks, log_tick_label, log_ticks, tick_label};
use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::ops::Range;

/// A linear f64 coordinate whose tick marks are exactly the given positions (plotters picks its
/// own otherwise).
#[derive(Debug, Clone)]
pub(crate) struct Ticked {
    lo: f64,
    hi: f64,
    ticks: Vec<f64>,
}

impl Ticked {
    /// The coordinate over [lo, hi] with ticks at `ticks`.
    pub fn new(lo: f64, hi: f64, ticks: Vec<f64>) -> Self {
        Self { lo, hi, ticks }
    }
}

impl Ranged for Ticked {
    type FormatOption = DefaultFormatting;
    type ValueType = f64;

    fn map(&self, v: &f64, limit: (i32, i32)) -> i32 {
        let s = (v - self.lo) / (self.hi - self.lo);
        limit.0 + (s * f64::from(limit.1 - limit.0)).round() as i32
    }

    fn key_points<H: KeyPointHint>(&self, hint: H) -> Vec<f64> {
        if hint.weight().allow_light_points() {
            vec![]
        } else {
            self.ticks.clone()
        }
    }

    fn range(&self) -> Range<f64> {
        self.lo..self.hi
    }
}

/// Tick labels, in plotters font units (the SVG backend writes 0.806 of it: 17.7 SVG px, ≥ 12 px on
/// screen for a 900 px plot shown ≥ 620 px wide, as in the two-column layout at 1400 px).
pub(crate) const TICK_PX: u32 = 22;
/// Axis titles and legend text.
pub(crate) const LABEL_PX: u32 = 22;
/// Chart titles.
pub(crate) const TITLE_PX: u32 = 26;

/// How a curve is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mark {
    /// A line through the points.
    Line,
    /// A dashed line.
    Dashed,
    /// A line and filled dots.
    LineDots,
    /// Filled dots only.
    Dots,
    /// Open circles only.
    Circles,
    /// A line and open circles.
    LineCircles,
    /// A vertical stem from the bottom of the plot to each point, with a dot.
    Stems,
}

/// One curve: points in the values' own units, an optional band (x, low, high) shaded beneath it.
#[derive(Debug, Clone)]
pub struct Curve {
    /// Legend entry (empty: not listed).
    pub name: String,
    /// The points.
    pub points: Vec<(f64, f64)>,
    /// The band: (x, low, high), shaded in the curve's colour.
    pub band: Vec<(f64, f64, f64)>,
    /// How it is drawn.
    pub mark: Mark,
    /// Its colour (None: the palette by curve index).
    pub colour: Option<RGBColor>,
    /// The points (by index into `points`) drawn hollow whatever the mark: not determined.
    pub hollow: Vec<usize>,
    /// Where the band was cut to fit the plot: (x, the cut end's y, `true` when the high end was
    /// cut). Each is drawn as a triangle pointing on beyond the cut, which the legend explains
    /// ([`CUT_LEGEND`]).
    pub band_cut: Vec<(f64, f64, bool)>,
}

/// The legend's line for the cut marks of [`Curve::band_cut`] (one legend line: at most
/// `LEGEND_CHARS` characters, so a page's text holds it whole).
pub const CUT_LEGEND: &str = "band cut at edge";

impl Curve {
    /// A curve of `mark` with no band and the palette's colour.
    pub fn new(name: impl Into<String>, points: Vec<(f64, f64)>, mark: Mark) -> Self {
        Self {
            name: name.into(),
            points,
            band: vec![],
            mark,
            colour: None,
            hollow: vec![],
            band_cut: vec![],
        }
    }

    /// The same curve in `colour`.
    pub(crate) fn coloured(mut self, colour: RGBColor) -> Self {
        self.colour = Some(colour);
        self
    }
}

/// An axis: its title (with unit) and scale.
#[derive(Debug, Clone)]
pub(crate) struct Axis {
    /// Title with unit, e.g. `temperature [°C]`.
    pub label: String,
    /// Logarithmic.
    pub log: bool,
}

impl Axis {
    /// A linear axis.
    pub(crate) fn lin(label: &str) -> Self {
        Self {
            label: label.into(),
            log: false,
        }
    }
    /// A log axis.
    pub fn log(label: &str) -> Self {
        Self {
            label: label.into(),
            log: true,
        }
    }
}

/// A colour bar beside the plot, for curves coloured by a quantity (e.g. isotherm temperature).
#[derive(Debug, Clone)]
pub(crate) struct ColourBar {
    /// Title with unit.
    pub label: String,
    /// The quantity's range, coloured by [`ramp`] from `lo` to `hi`.
    pub lo: f64,
    /// Upper end.
    pub hi: f64,
}

/// A chart.
#[derive(Debug, Clone)]
pub(crate) struct Chart {
    /// Title above the plot.
    pub title: String,
    /// x axis.
    pub x: Axis,
    /// y axis.
    pub y: Axis,
    /// The curves, drawn in order.
    pub curves: Vec<Curve>,
    /// A colour bar instead of a legend.
    pub colour_bar: Option<ColourBar>,
}

/// Series colours (colour-blind-safe order of the Tableau 10 palette).
pub(crate) const PALETTE: [RGBColor; 10] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(255, 127, 14),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
    RGBColor(188, 189, 34),
    RGBColor(23, 190, 207),
];

/// Colour of s ∈ [0, 1] on a blue (0) → red (1) ramp through violet, for quantities such as
/// temperature.
pub fn ramp(s: f64) -> RGBColor {
    let s = if s.is_finite() {
        s.clamp(0.0, 1.0)
    } else {
        0.5
    };
    let (r, g, b) = HSLColor(0.66 * (1.0 - s), 0.85, 0.45).rgb();
    RGBColor(r, g, b)
}

/// The points of a chart in axis coordinates (log10 on log axes), non-finite and (on log axes)
/// non-positive values left out.
fn to_axes(c: &Chart, p: (f64, f64)) -> Option<(f64, f64)> {
    let f = |v: f64, log: bool| {
        if !v.is_finite() || (log && v <= 0.0) {
            None
        } else if log {
            Some(v.log10())
        } else {
            Some(v)
        }
    };
    Some((f(p.0, c.x.log)?, f(p.1, c.y.log)?))
}

/// The ranges of the data in axis coordinates, padded 4 % (or ±0.5 when flat); None when no point
/// can be drawn.
pub(crate) fn ranges(c: &Chart) -> Option<((f64, f64), (f64, f64))> {
    let mut xs = (f64::INFINITY, f64::NEG_INFINITY);
    let mut ys = xs;
    let mut add = |p: (f64, f64)| {
        if let Some((x, y)) = to_axes(c, p) {
            xs = (xs.0.min(x), xs.1.max(x));
            ys = (ys.0.min(y), ys.1.max(y));
        }
    };
    for cv in &c.curves {
        cv.points.iter().for_each(|&p| add(p));
        for &(x, lo, hi) in &cv.band {
            add((x, lo));
            add((x, hi));
        }
    }
    if !xs.0.is_finite() {
        return None;
    }
    let pad = |(a, b): (f64, f64)| {
        let d = if b > a { 0.04 * (b - a) } else { 0.5 };
        (a - d, b + d)
    };
    Some((pad(xs), pad(ys)))
}

fn ticks(lo: f64, hi: f64, log: bool) -> Vec<f64> {
    if log {
        log_ticks(lo, hi)
    } else {
        linear_ticks(lo, hi)
    }
}

fn label(v: f64, log: bool) -> String {
    if log {
        log_tick_label(v)
    } else {
        tick_label(v)
    }
}

fn e<E: std::fmt::Display>(err: E) -> String {
    err.to_string()
}

/// Width of the legend panel (px).
const LEGEND_W: u32 = 225;
/// Width of the colour-bar panel (px).
const BAR_W: u32 = 120;
/// Characters per legend line before wrapping.
const LEGEND_CHARS: usize = 18;

/// A legend entry broken into lines of at most `LEGEND_CHARS` characters, only at spaces or
/// after a hyphen, underscore or slash (`conveyor-idler-` / `half-space`, never inside a word); a
/// single piece longer than a line is shortened with `…`; at most three lines, the last cut with
/// `…`.
fn wrap(name: &str) -> Vec<String> {
    // the pieces a line may break after, each with whether a space stood before it
    let mut pieces: Vec<(String, bool)> = Vec::new();
    for (k, word) in name.split(' ').enumerate() {
        let mut cur = String::new();
        let mut spaced = k > 0;
        for ch in word.chars() {
            cur.push(ch);
            if matches!(ch, '-' | '_' | '/') {
                pieces.push((std::mem::take(&mut cur), spaced));
                spaced = false;
            }
        }
        if !cur.is_empty() {
            pieces.push((cur, spaced));
        }
    }
    let mut lines: Vec<String> = vec![String::new()];
    for (piece, spaced) in pieces {
        let piece = ellipsised(&piece, LEGEND_CHARS);
        let cur = lines.last_mut().expect("never empty");
        let len = cur.chars().count();
        let sep = usize::from(spaced && len > 0);
        if len == 0 || len + sep + piece.chars().count() <= LEGEND_CHARS {
            if sep == 1 {
                cur.push(' ');
            }
            cur.push_str(&piece);
        } else {
            lines.push(piece);
        }
    }
    if lines.len() > 3 {
        lines.truncate(3);
        let last = ellipsised(&lines[2], LEGEND_CHARS - 1);
        lines[2] = if last.ends_with('…') {
            last
        } else {
            format!("{last}…")
        };
    }
    lines
}

/// `s` cut to at most `n` characters, the last one `…` when it was cut.
fn ellipsised(s: &str, n: usize) -> String {
    if s.chars().count() <= n {
        return s.to_string();
    }
    let mut out: String = s.chars().take(n.saturating_sub(1)).collect();
    out.push('…');
    out
}

/// Draw `c` on `root` (which it fills white). Errors are plotters' messages.
pub(crate) fn draw_chart<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    c: &Chart,
) -> Result<(), String> {
    root.fill(&WHITE).map_err(e)?;
    let Some(((x0, x1), (y0, y1))) = ranges(c) else {
        return Err("no point to draw".into());
    };
    let body = root.titled(&c.title, ("sans-serif", TITLE_PX)).map_err(e)?;
    let w = body.dim_in_pixel().0;
    let named: Vec<(usize, &Curve)> = c
        .curves
        .iter()
        .enumerate()
        .filter(|(_, cv)| !cv.name.is_empty())
        .collect();
    let side = if c.colour_bar.is_some() {
        BAR_W
    } else if named.is_empty() {
        0
    } else {
        LEGEND_W
    };
    let (plot, panel) = body.split_horizontally(w.saturating_sub(side));
    let (xt, yt) = (ticks(x0, x1, c.x.log), ticks(y0, y1, c.y.log));
    let (xlog, ylog) = (c.x.log, c.y.log);
    let mut chart = ChartBuilder::on(&plot)
        .margin(10)
        .margin_right(18)
        .x_label_area_size(62)
        .y_label_area_size(96)
        .build_cartesian_2d(Ticked::new(x0, x1, xt), Ticked::new(y0, y1, yt))
        .map_err(e)?;
    chart
        .configure_mesh()
        .x_desc(c.x.label.as_str())
        .y_desc(c.y.label.as_str())
        .label_style(("sans-serif", TICK_PX))
        .axis_desc_style(("sans-serif", LABEL_PX))
        .bold_line_style(RGBColor(225, 225, 225))
        .x_label_formatter(&|v| label(*v, xlog))
        .y_label_formatter(&|v| label(*v, ylog))
        .draw()
        .map_err(e)?;
    let colour = |i: usize, cv: &Curve| cv.colour.unwrap_or(PALETTE[i % PALETTE.len()]);
    for (i, cv) in c.curves.iter().enumerate() {
        draw_curve(&mut chart, c, cv, colour(i, cv), y0)?;
    }
    if let Some(bar) = &c.colour_bar {
        draw_colour_bar(&panel, bar)?;
    } else if !named.is_empty() {
        draw_legend(&panel, &named, &colour)?;
    }
    Ok(())
}

/// One curve of `c` on the chart in colour `col`: its band (a shaded polygon, or an error bar when
/// it has one point), its line and its marks (stems drop to the axis at `y0`).
fn draw_curve<DB: DrawingBackend>(
    chart: &mut ChartContext<'_, DB, Cartesian2d<Ticked, Ticked>>,
    c: &Chart,
    cv: &Curve,
    col: RGBColor,
    y0: f64,
) -> Result<(), String> {
    // the band: a polygon along the lows and back along the highs
    let band: Vec<((f64, f64), (f64, f64))> = cv
        .band
        .iter()
        .filter_map(|&(x, lo, hi)| Some((to_axes(c, (x, lo))?, to_axes(c, (x, hi))?)))
        .collect();
    if band.len() >= 2 {
        let poly: Vec<(f64, f64)> = band
            .iter()
            .map(|b| b.0)
            .chain(band.iter().rev().map(|b| b.1))
            .collect();
        chart
            .draw_series(std::iter::once(Polygon::new(poly, col.mix(0.2).filled())))
            .map_err(e)?;
    } else {
        // a single band: an error bar
        chart
            .draw_series(
                band.iter()
                    .map(|&(lo, hi)| PathElement::new(vec![lo, hi], col.mix(0.6).stroke_width(3))),
            )
            .map_err(e)?;
    }
    // the cut marks: a triangle at the cut end, pointing on beyond it
    chart
        .draw_series(cv.band_cut.iter().filter_map(|&(x, y, high)| {
            let at = to_axes(c, (x, y))?;
            Some(EmptyElement::at(at) + cut_triangle(high, col))
        }))
        .map_err(e)?;
    let pts: Vec<(f64, f64)> = cv.points.iter().filter_map(|&p| to_axes(c, p)).collect();
    if matches!(cv.mark, Mark::Line | Mark::LineDots | Mark::LineCircles) {
        chart
            .draw_series(LineSeries::new(pts.iter().copied(), col.stroke_width(2)))
            .map_err(e)?;
    }
    if cv.mark == Mark::Dashed {
        chart
            .draw_series(DashedLineSeries::new(
                pts.iter().copied(),
                10,
                6,
                col.stroke_width(2),
            ))
            .map_err(e)?;
    }
    let solid: Vec<(f64, f64)> = cv
        .points
        .iter()
        .enumerate()
        .filter(|(i, _)| !cv.hollow.contains(i))
        .filter_map(|(_, &p)| to_axes(c, p))
        .collect();
    let hollow: Vec<(f64, f64)> = cv
        .hollow
        .iter()
        .filter_map(|&i| cv.points.get(i).and_then(|&p| to_axes(c, p)))
        .collect();
    chart
        .draw_series(hollow.iter().map(|&p| Circle::new(p, 4, WHITE.filled())))
        .map_err(e)?;
    chart
        .draw_series(
            hollow
                .iter()
                .map(|&p| Circle::new(p, 4, col.stroke_width(2))),
        )
        .map_err(e)?;
    match cv.mark {
        Mark::LineDots | Mark::Dots | Mark::Stems => {
            chart
                .draw_series(solid.iter().map(|&p| Circle::new(p, 3, col.filled())))
                .map_err(e)?;
        }
        Mark::Circles | Mark::LineCircles => {
            chart
                .draw_series(pts.iter().map(|&p| Circle::new(p, 3, col.stroke_width(1))))
                .map_err(e)?;
        }
        _ => {}
    }
    if cv.mark == Mark::Stems {
        chart
            .draw_series(
                pts.iter()
                    .map(|&(x, y)| PathElement::new(vec![(x, y0), (x, y)], col.stroke_width(2))),
            )
            .map_err(e)?;
    }
    Ok(())
}

/// A cut mark in pixel offsets from its point: a filled triangle pointing up (`high`) or down.
fn cut_triangle(high: bool, col: RGBColor) -> Polygon<(i32, i32)> {
    let s = if high { -1 } else { 1 };
    Polygon::new(vec![(-6, 0), (6, 0), (0, 9 * s)], col.filled())
}

/// The legend panel: one entry per named curve (a sample of its mark and its name, wrapped), as
/// many as fit, then `… and N more`; a line on the cut marks when a curve has one.
fn draw_legend<DB: DrawingBackend>(
    panel: &DrawingArea<DB, Shift>,
    named: &[(usize, &Curve)],
    colour: &dyn Fn(usize, &Curve) -> RGBColor,
) -> Result<(), String> {
    let h = panel.dim_in_pixel().1 as i32;
    let line = LABEL_PX as i32 + 4;
    let mut y = 24;
    let font = ("sans-serif", LABEL_PX).into_font().color(&BLACK);
    for (k, (i, cv)) in named.iter().enumerate() {
        let lines = wrap(&cv.name);
        if y + line * lines.len() as i32 > h - line {
            let more = format!("… and {} more", named.len() - k);
            panel
                .draw(&Text::new(more, (8, y), font.clone()))
                .map_err(e)?;
            break;
        }
        let col = colour(*i, cv);
        let mid = y + line / 2 - 2;
        match cv.mark {
            Mark::Dots | Mark::Circles => {}
            Mark::Dashed => {
                panel
                    .draw(&PathElement::new(
                        vec![(6, mid), (14, mid)],
                        col.stroke_width(2),
                    ))
                    .map_err(e)?;
                panel
                    .draw(&PathElement::new(
                        vec![(20, mid), (28, mid)],
                        col.stroke_width(2),
                    ))
                    .map_err(e)?;
            }
            _ => {
                panel
                    .draw(&PathElement::new(
                        vec![(6, mid), (28, mid)],
                        col.stroke_width(2),
                    ))
                    .map_err(e)?;
            }
        }
        if !cv.band.is_empty() {
            panel
                .draw(&Rectangle::new(
                    [(6, mid - 7), (28, mid + 7)],
                    col.mix(0.2).filled(),
                ))
                .map_err(e)?;
        }
        match cv.mark {
            Mark::LineDots | Mark::Dots | Mark::Stems => {
                panel
                    .draw(&Circle::new((17, mid), 4, col.filled()))
                    .map_err(e)?;
            }
            Mark::Circles | Mark::LineCircles => {
                panel
                    .draw(&Circle::new((17, mid), 4, col.stroke_width(1)))
                    .map_err(e)?;
            }
            _ => {}
        }
        for l in lines {
            panel
                .draw(&Text::new(l, (36, y), font.clone()))
                .map_err(e)?;
            y += line;
        }
        y += 6;
    }
    let cut = wrap(CUT_LEGEND);
    if named.iter().any(|(_, cv)| !cv.band_cut.is_empty()) && y + line * cut.len() as i32 <= h {
        panel
            .draw(&(EmptyElement::at((17, y + line / 2 + 2)) + cut_triangle(true, BLACK)))
            .map_err(e)?;
        for l in cut {
            panel
                .draw(&Text::new(l, (36, y), font.clone()))
                .map_err(e)?;
            y += line;
        }
    }
    Ok(())
}

/// The colour bar panel: the ramp from `lo` (bottom) to `hi` (top) with 1-2-5 ticks.
fn draw_colour_bar<DB: DrawingBackend>(
    panel: &DrawingArea<DB, Shift>,
    bar: &ColourBar,
) -> Result<(), String> {
    let (lo, hi) = if bar.hi > bar.lo {
        (bar.lo, bar.hi)
    } else {
        (bar.lo - 0.5, bar.lo + 0.5)
    };
    let mut cb = ChartBuilder::on(panel)
        .margin_top(20)
        .margin_bottom(72)
        .margin_right(58)
        .y_label_area_size(0)
        .right_y_label_area_size(0)
        .build_cartesian_2d(0.0..1.0, Ticked::new(lo, hi, linear_ticks(lo, hi)))
        .map_err(e)?;
    let n = 100;
    cb.draw_series((0..n).map(|k| {
        let a = lo + (hi - lo) * k as f64 / n as f64;
        let b = lo + (hi - lo) * (k + 1) as f64 / n as f64;
        Rectangle::new(
            [(0.0, a), (1.0, b)],
            ramp((k as f64 + 0.5) / n as f64).filled(),
        )
    }))
    .map_err(e)?;
    // ticks and labels to the right of the bar, the title above it
    let font = ("sans-serif", TICK_PX).into_font().color(&BLACK);
    for t in linear_ticks(lo, hi) {
        // backend_coord is in the root's pixels; the panel draws relative to its own corner
        let (bx, by) = cb.backend_coord(&(1.0, t));
        let (ox, oy) = panel.get_base_pixel();
        let (px, py) = (bx - ox, by - oy);
        panel
            .draw(&PathElement::new(
                vec![(px, py), (px + 5, py)],
                BLACK.stroke_width(1),
            ))
            .map_err(e)?;
        panel
            .draw(&Text::new(
                tick_label(t),
                (px + 8, py - TICK_PX as i32 / 2),
                font.clone(),
            ))
            .map_err(e)?;
    }
    panel
        .draw(&Text::new(bar.label.clone(), (4, 0), font))
        .map_err(e)?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn legend_names_wrap_at_spaces_and_are_cut_after_three_lines() {
        assert_eq!(wrap("conveyor-idler"), ["conveyor-idler"]);
        let w = wrap("WLF: C1 = 13.50, C2 = 141.2 K");
        assert_eq!(w.join(" "), "WLF: C1 = 13.50, C2 = 141.2 K");
        assert!(w.len() == 2 && w.iter().all(|l| l.chars().count() <= LEGEND_CHARS));
        // long names break after hyphens and underscores, never inside a word
        let w = wrap("conveyor-idler-half-space");
        assert_eq!(w, ["conveyor-idler-", "half-space"]);
        let w = wrap("trios_aresg2_lims_frequency_sweep");
        assert_eq!(w.concat(), "trios_aresg2_lims_frequency_sweep");
        assert!(
            w.iter().all(|l| l.ends_with('_') || l.ends_with("sweep")),
            "{w:?}"
        );
        // a word longer than a line is shortened, not split; more than three lines are cut
        let w = wrap(&"x".repeat(100));
        assert_eq!(w, [format!("{}…", "x".repeat(LEGEND_CHARS - 1))]);
        let w = wrap("a-b-c-d-e-f-g-h-i-j-k-l-m-n-o-p-q-r-s-t-u-v-w-x-y-z-a-b-c-d");
        assert_eq!(w.len(), 3);
        assert!(w[2].ends_with('…'));
        assert!(w.iter().all(|l| l.chars().count() <= LEGEND_CHARS));
    }

    #[test]
    fn ranges_leave_out_what_a_log_axis_cannot_show() {
        let c = Chart {
            title: String::new(),
            x: Axis::lin("x"),
            y: Axis::log("y"),
            curves: vec![Curve::new(
                "a",
                vec![(0.0, 10.0), (1.0, 0.0), (2.0, 1000.0), (f64::NAN, 1.0)],
                Mark::Line,
            )],
            colour_bar: None,
        };
        let ((x0, x1), (y0, y1)) = ranges(&c).unwrap();
        // x over 0…2 and log10 y over 1…3, each padded 4 %
        assert!((x0 + 0.08).abs() < 1e-12 && (x1 - 2.08).abs() < 1e-12);
        assert!((y0 - 0.92).abs() < 1e-12 && (y1 - 3.08).abs() < 1e-12);
        let empty = Chart {
            curves: vec![Curve::new("a", vec![(1.0, -1.0)], Mark::Line)],
            ..c
        };
        assert!(ranges(&empty).is_none());
    }
}
