//! Small HTML helpers shared by the datasheet and the index page: escaping, the page head, and a
//! plot embedded inline as SVG with links to its SVG and PNG files.

use super::error::{io, ReportError};
use super::plots;
use std::path::Path;

/// HTML-escape text.
pub(crate) fn esc(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            // control characters (an escape sequence from file metadata) shown, never passed on
            c if c.is_control() && c != '\n' && c != '\t' => {
                out.extend(c.escape_unicode());
            }
            c => out.push(c),
        }
    }
    out
}

/// The style sheet of the report pages: two plot columns from 1300 px, one below; print: A4, one
/// plot column, collapsed sections left out.
pub(crate) const STYLE: &str = "body{font:15px/1.4 sans-serif;max-width:1360px;margin:0 auto;padding:0 16px;color:#222}\
h1{font-size:26px;margin:.5em 0 0}h2{font-size:20px;border-bottom:2px solid #ddd;margin:1.2em 0 .4em}h3{font-size:16px;margin:.8em 0 .3em}\
.sub{color:#555;margin:0 0 .5em}\
.first{display:grid;grid-template-columns:minmax(420px,1fr) minmax(600px,1.35fr);gap:16px;align-items:start}\
.grid{display:grid;grid-template-columns:repeat(auto-fill,minmax(620px,1fr));gap:10px 16px}\
figure{margin:0}figcaption{font-size:12px;color:#666}\
table{border-collapse:collapse;margin:.4em 0;font-size:14px}td,th{border:1px solid #ccc;padding:2px 6px;text-align:right;vertical-align:top}\
th{background:#f0f0f0}td.l,th.l{text-align:left}table.kv td{text-align:left}table.kv td:first-child{color:#555;white-space:nowrap}\
.band{display:block;color:#666;font-size:12px}.tie{color:#36c}.small{font-size:13px}ul.small{margin:.2em 0;padding-left:1.2em}\
.ok{color:#060}.bad{color:#b00}.warn{color:#a60}\
details{margin:.3em 0}summary{cursor:pointer;font-weight:600}\
pre{background:#f6f6f6;padding:.5em;overflow-x:auto;font-size:12px}svg{width:100%;height:auto;display:block}\
@media (max-width:1100px){.first{grid-template-columns:1fr}}\
@page{size:A4;margin:12mm}\
@media print{body{max-width:none;padding:0;font-size:9.5pt}.first,.grid{display:block}\
figure{break-inside:avoid;max-width:150mm;margin:0 auto 3mm}figcaption,details:not([open]){display:none}\
h2,h3{break-after:avoid}tr{break-inside:avoid}a{color:inherit;text-decoration:none}}";

/// Superscript digits of an exponent (`-4` → `⁻⁴`).
fn sup(n: i32) -> String {
    n.to_string()
        .chars()
        .map(|c| match c {
            '-' => '⁻',
            d => ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹']
                [d.to_digit(10).unwrap_or(0) as usize],
        })
        .collect()
}

/// The power of ten that puts `v`'s mantissa in [1, 10) (0 for 0 and non-finite values).
fn exponent(v: f64) -> i32 {
    if v.is_finite() && v != 0.0 {
        v.abs().log10().floor() as i32
    } else {
        0
    }
}

/// `v` to three significant digits: plain in [0.01, 1000), else `1.23·10⁻⁴`; `–` when not finite.
pub fn num(v: f64) -> String {
    if !v.is_finite() {
        return "–".into();
    }
    let a = v.abs();
    if a == 0.0 || (0.01..1000.0).contains(&a) {
        let d = (2 - exponent(v)).max(0) as usize;
        return format!("{v:.d$}");
    }
    let e = exponent(v);
    format!("{:.2}·10{}", v / 10f64.powi(e), sup(e))
}

/// `v` and its band (p05–p95) in one power of ten: `1.23·10⁻⁴` and `1.10–1.35 ·10⁻⁴`; the band
/// part empty when there is none.
pub(crate) fn num_band(v: f64, band: Option<(f64, f64)>) -> (String, String) {
    let Some((lo, hi)) = band.filter(|(a, b)| a.is_finite() && b.is_finite()) else {
        return (num(v), String::new());
    };
    let e = exponent(v);
    // a band over more than two decades (widened for extrapolation, crate::bands eqs. 15.8, 15.9):
    // each end with its own power of ten, else the low end reads 0.00 and the high end a long
    // integer
    if !v.is_finite() || (-2..3).contains(&e) || hi > 100.0 * lo {
        return (num(v), format!("{}–{}", num(lo), num(hi)));
    }
    let s = 10f64.powi(e);
    (num(v), format!("{:.2}–{:.2} ·10{}", lo / s, hi / s, sup(e)))
}

/// Draw `stem.svg` and its PNG twin `stem.png` in `dir`; returns the HTML to embed: the SVG inline
/// and links to both files (or a note when there is nothing to plot).
pub(crate) fn plot_pair<F>(dir: &Path, stem: &str, draw: F) -> Result<String, ReportError>
where
    F: Fn(&Path) -> Result<(), plots::PlotError>,
{
    let svg = dir.join(format!("{stem}.svg"));
    match draw(&svg) {
        Ok(()) => {}
        // nothing to draw (e.g. every solve failed): say so in the datasheet instead of failing it
        Err(e @ plots::PlotError::NoData { .. }) => {
            return Ok(format!(
                "<p class=\"bad\">{}: {}</p>",
                esc(stem),
                esc(&e.to_string())
            ))
        }
        Err(e) => return Err(e.into()),
    }
    draw(&dir.join(format!("{stem}.png")))?;
    let text = std::fs::read_to_string(&svg).map_err(io(&svg))?;
    Ok(format!(
        "<figure>{text}<figcaption><a href=\"{0}.png\">{0}.png</a> · <a href=\"{0}.svg\">{0}.svg</a></figcaption></figure>\n",
        esc(stem)
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_have_three_significant_digits_and_bands_share_the_power_of_ten() {
        assert_eq!(num(1.2345e-4), "1.23·10⁻⁴");
        assert_eq!(num(0.0123), "0.0123");
        assert_eq!(num(250.0), "250");
        assert_eq!(num(f64::NAN), "–");
        assert_eq!(
            num_band(1.2345e-4, Some((1.1e-4, 1.35e-4))),
            ("1.23·10⁻⁴".to_string(), "1.10–1.35 ·10⁻⁴".to_string())
        );
        assert_eq!(num_band(0.5, Some((0.4, 0.6))).1, "0.400–0.600");
        assert_eq!(num_band(0.5, None).1, "");
    }

    #[test]
    fn escapes_markup() {
        assert_eq!(
            esc("<a href=\"x\">&</a>"),
            "&lt;a href=&quot;x&quot;&gt;&amp;&lt;/a&gt;"
        );
        assert_eq!(esc("a\u{1b}[31mb\u{7}"), "a\\u{1b}[31mb\\u{7}");
    }
}
