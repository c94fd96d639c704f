//! Small HTML helpers shared by the datasheet and the index page: escaping, the page head, and a
//! plot embedded inline as SVG with links to its SVG and PNG files.

use super::error::{io, ReportError};
use super::plots;
use std::path::Path;

/// HTML-escape text.
pub fn esc(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// The style sheet of the report pages.
pub const STYLE: &str = "body{font-family:sans-serif;max-width:1000px;margin:1em auto;padding:0 1em}table{border-collapse:collapse;margin:.5em 0}td,th{border:1px solid #bbb;padding:2px 6px;text-align:right}th{background:#eee}td.l{text-align:left}pre{background:#f6f6f6;padding:.5em;overflow-x:auto;font-size:11px}.bad{color:#b00}.warn{color:#a60}svg{max-width:100%;height:auto}";

/// Draw `stem.svg` and its PNG twin `stem.png` in `dir`; returns the HTML to embed: the SVG inline
/// and links to both files (or a note when there is nothing to plot).
pub fn plot_pair<F>(dir: &Path, stem: &str, draw: F) -> Result<String, ReportError>
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
    fn escapes_markup() {
        assert_eq!(
            esc("<a href=\"x\">&</a>"),
            "&lt;a href=&quot;x&quot;&gt;&amp;&lt;/a&gt;"
        );
    }
}
