//! Which reader a file needs, from its content (not its name): the Excel container magic numbers,
//! then the marks each text export carries. Bytes (+ decoded text) → [`Format`].

use std::str::FromStr;

/// The export formats read by the `dma` stage.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Format {
    /// Netzsch-Gabo EPLEXOR Excel export (.xls or .xlsx).
    Eplexor,
    /// TA Instruments TRIOS "Export to LIMS" text.
    TriosLims,
    /// TA Instruments TRIOS plain text/CSV export.
    TriosText,
    /// Anton Paar RheoCompass CSV export.
    Rheocompass,
    /// Netzsch Proteus ASCII export.
    Proteus,
    /// RepTate data file (`.osc` sweep or `.tts` master curve).
    Reptate,
    /// Generic delimited text with a header.
    Generic,
}

impl Format {
    /// All formats, for help texts.
    pub const ALL: [Format; 7] = [
        Format::Eplexor,
        Format::TriosLims,
        Format::TriosText,
        Format::Rheocompass,
        Format::Proteus,
        Format::Reptate,
        Format::Generic,
    ];

    /// The name used on the command line and in `SourceFile::format`.
    pub fn name(self) -> &'static str {
        match self {
            Format::Eplexor => "eplexor",
            Format::TriosLims => "trios-lims",
            Format::TriosText => "trios-text",
            Format::Rheocompass => "rheocompass",
            Format::Proteus => "proteus",
            Format::Reptate => "reptate",
            Format::Generic => "generic",
        }
    }
}

impl FromStr for Format {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        Format::ALL
            .into_iter()
            .find(|f| f.name().eq_ignore_ascii_case(s.trim()))
            .ok_or_else(|| {
                format!(
                    "unknown format `{s}` (one of: {})",
                    Format::ALL.map(|f| f.name()).join(", ")
                )
            })
    }
}

/// OLE2 compound document (BIFF .xls).
pub fn is_ole2(bytes: &[u8]) -> bool {
    bytes.starts_with(&[0xD0, 0xCF, 0x11, 0xE0, 0xA1, 0xB1, 0x1A, 0xE1])
}

/// ZIP container (.xlsx).
pub fn is_zip(bytes: &[u8]) -> bool {
    bytes.starts_with(b"PK\x03\x04")
}

/// Detect the format of a file from its bytes and decoded text.
pub fn detect(bytes: &[u8], text: &str) -> Format {
    if is_ole2(bytes) || is_zip(bytes) {
        return Format::Eplexor;
    }
    let head: Vec<&str> = text.lines().take(400).collect();
    let first = head
        .iter()
        .find(|l| !l.trim().is_empty())
        .map(|l| l.trim())
        .unwrap_or("");
    if first == "[Version]"
        || head.iter().any(|l| l.contains("LIMS export format"))
        || (head.iter().any(|l| l.trim() == "[Step]")
            && head.iter().any(|l| l.starts_with("Variables\t")))
    {
        return Format::TriosLims;
    }
    if head.iter().any(|l| l.trim().eq_ignore_ascii_case("[step]")) {
        return Format::TriosText;
    }
    if super::proteus::looks_like(text) {
        return Format::Proteus;
    }
    if super::rheocompass::looks_like(text) {
        return Format::Rheocompass;
    }
    if super::reptate::looks_like(text) {
        return Format::Reptate;
    }
    Format::Generic
}
