//! Plots on EMS-CA: the master curve with its Prony fit, the spectrum, the shift factors with a WLF
//! and an Arrhenius law, and isotherms regenerated from the fit and the shift table. Written to
//! the system temp folder's `viscoroll-plots/` (look at them there) and checked as files.

use crate::tests::shipped::ems_ca_master;
use std::path::{Path, PathBuf};
use viscoroll::dma::{DataPoint, Isotherm, Measurement};
use viscoroll::prony::kernel::dynamic_moduli_pa;
use viscoroll::prony::RelaxationSpectrum;
use viscoroll::prony::{fit_prony, PronySettings};
use viscoroll::report::plots::{
    plot_isotherms, plot_master_fit, plot_shift_factors, plot_spectrum, PlotError,
};
use viscoroll::{ModulusKind, ShiftLaw};

/// (T in °C, log10 a_T) from pyvisco's shift-factor table (a name row, then a unit row).
fn ems_ca_shifts() -> Vec<(f64, f64)> {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/data/pyvisco-ems-ca/freq_user_master__shift_factors.csv"
    );
    let text = std::fs::read_to_string(path).unwrap();
    text.lines()
        .skip(2)
        .filter(|l| !l.trim().is_empty())
        .map(|l| {
            let mut it = l.split(',').map(|s| s.trim().parse::<f64>().unwrap());
            (it.next().unwrap(), it.next().unwrap())
        })
        .collect()
}

fn out_dir() -> PathBuf {
    let d = std::env::temp_dir().join("viscoroll-plots");
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn check_png(p: &Path) {
    let bytes = std::fs::read(p).unwrap();
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n", "{p:?} is not a PNG");
    // IHDR width and height (big-endian u32 at 16 and 20) are the plot size.
    assert_eq!(u32::from_be_bytes(bytes[16..20].try_into().unwrap()), 900);
    assert_eq!(u32::from_be_bytes(bytes[20..24].try_into().unwrap()), 640);
}

fn check_svg(p: &Path, needle: &str) {
    let s = std::fs::read_to_string(p).unwrap();
    assert!(
        s.starts_with("<svg") && s.contains(needle),
        "{p:?} lacks {needle:?}"
    );
}

/// Every text of the SVG is at least 16 SVG px (≥ 12 px on screen at the 0.75 scale of the
/// datasheet's two-column layout at 1400 px), and no tick label is in `1.23e-4` form or an
/// unrounded value such as `5012` (tick labels are 1-2-5 values: at most two significant digits
/// besides zeros, or a power of ten).
fn check_legible(p: &Path) {
    let s = std::fs::read_to_string(p).unwrap();
    let mut n = 0;
    for t in s.split("<text").skip(1) {
        let size: f64 = t
            .split("font-size=\"")
            .nth(1)
            .and_then(|r| r.split('"').next())
            .and_then(|v| v.parse().ok())
            .unwrap();
        assert!(size >= 16.0, "{p:?}: text of {size} px");
        let text = t
            .split('>')
            .nth(1)
            .unwrap_or("")
            .split('<')
            .next()
            .unwrap_or("")
            .trim();
        let is_number = !text.is_empty()
            && text
                .chars()
                .all(|c| c.is_ascii_digit() || "-.·⁰¹²³⁴⁵⁶⁷⁸⁹⁻".contains(c));
        if is_number {
            n += 1;
            let digits: String = text
                .split('·')
                .next()
                .unwrap()
                .chars()
                .filter(|c| c.is_ascii_digit())
                .collect();
            let significant = digits.trim_matches('0').len();
            assert!(significant <= 2, "{p:?}: tick label {text}");
        }
        assert!(
            !(text.contains("e-") && text.chars().next().is_some_and(|c| c.is_ascii_digit())),
            "{p:?}: {text}"
        );
    }
    assert!(n >= 4, "{p:?}: {n} tick labels");
}

/// Isotherms 0.1–100 Hz regenerated from a fit: E*(a_T f) at each tabulated temperature of
/// `shifts` (°C, log10 a_T).
fn regenerated(spectrum: &RelaxationSpectrum, shifts: &[(f64, f64)]) -> Measurement {
    let isotherms = shifts
        .iter()
        .map(|&(t, log_at)| Isotherm {
            temp_nominal_c: t,
            temp_mean_c: t,
            source: 0,
            nominal_source: String::new(),
            sheet: None,
            label: None,
            points: (0..10)
                .map(|i| {
                    let f = 0.1 * 10f64.powf(i as f64 / 3.0);
                    let (s, l) = dynamic_moduli_pa(
                        spectrum,
                        2.0 * std::f64::consts::PI * f * 10f64.powf(log_at),
                    );
                    DataPoint {
                        freq_hz: f,
                        storage_pa: s,
                        loss_pa: l,
                        temp_c: None,
                        line: i + 1,
                        flags: vec![],
                    }
                })
                .collect(),
        })
        .collect();
    Measurement {
        sources: vec![],
        kind: ModulusKind::Tensile,
        poisson: 0.5,
        isotherms,
        warnings: vec![],
        issues: vec![],
        summary: Default::default(),
    }
}

#[test]
fn ems_ca_plots_are_written_as_png_and_svg() {
    let dir = out_dir();
    let pts = ems_ca_master();
    let fit = fit_prony(&pts, ModulusKind::Tensile, 0.5, &PronySettings::default()).unwrap();
    let shifts = ems_ca_shifts();
    assert_eq!(shifts.len(), 21);
    // Illustrative laws through the table (not fits: the tts stage fits them): the EPLEXOR software's
    // WLF constants of a sibling specimen (C1 = 13.50, C2 = 141.19 K at 25 °C) moved to the table's
    // −5 °C by log a_T(−5 °C), and an Arrhenius law through the table's end points.
    let wlf25 = ShiftLaw::Wlf {
        t_ref_c: 25.0,
        c1: 13.50,
        c2_k: 141.19,
    };
    let c2 = 141.19 - 30.0;
    let c1 = 13.50 * 141.19 / c2;
    let wlf = ShiftLaw::Wlf {
        t_ref_c: -5.0,
        c1,
        c2_k: c2,
    };
    assert!((wlf.log10_a_t(25.0) - (wlf25.log10_a_t(25.0) - wlf25.log10_a_t(-5.0))).abs() < 1e-12);
    let (t_hi, a_hi) = shifts
        .iter()
        .copied()
        .fold((f64::MIN, 0.0), |a, p| if p.0 > a.0 { p } else { a });
    let k = |t: f64| 1.0 / (t + 273.15) - 1.0 / (-5.0 + 273.15);
    let ea = a_hi / k(t_hi) * viscoroll::tts::GAS_CONSTANT_J_PER_MOL_K * std::f64::consts::LN_10;
    let arr = ShiftLaw::Arrhenius {
        t_ref_c: -5.0,
        activation_energy_j_per_mol: ea,
    };
    let m = regenerated(&fit.spectrum, &shifts);
    for ext in ["png", "svg"] {
        let p = |name: &str| dir.join(format!("ems_ca_{name}.{ext}"));
        plot_master_fit(&pts, &fit.spectrum, &p("master_fit")).unwrap();
        plot_spectrum(&fit.spectrum, &p("spectrum")).unwrap();
        plot_shift_factors(
            &shifts,
            &[("WLF", &wlf), ("Arrhenius", &arr)],
            &p("shift_factors"),
        )
        .unwrap();
        plot_isotherms(&m, &p("isotherms")).unwrap();
        for name in ["master_fit", "spectrum", "shift_factors", "isotherms"] {
            if ext == "png" {
                check_png(&p(name));
            } else {
                check_svg(&p(name), "<text");
            }
        }
    }
    check_svg(
        &dir.join("ems_ca_master_fit.svg"),
        "Master curve of E′ and E″ with the Prony fit",
    );
    for name in ["master_fit", "spectrum", "shift_factors", "isotherms"] {
        check_legible(&dir.join(format!("ems_ca_{name}.svg")));
    }
    // 21 isotherms: a colour bar, not a legend entry per temperature
    let iso = std::fs::read_to_string(dir.join("ems_ca_isotherms.svg")).unwrap();
    assert!(iso.contains("T [°C]") && !iso.contains(">-50 °C<"));
    // No temp files are left behind.
    assert!(std::fs::read_dir(&dir).unwrap().all(|e| !e
        .unwrap()
        .file_name()
        .to_string_lossy()
        .starts_with('.')));
}

#[test]
fn plot_refusals_name_the_problem() {
    let dir = out_dir();
    let pts = ems_ca_master();
    let fit = fit_prony(
        &pts[..20],
        ModulusKind::Tensile,
        0.5,
        &PronySettings::default(),
    )
    .unwrap();
    let err = plot_spectrum(&fit.spectrum, &dir.join("x.jpg")).unwrap_err();
    assert!(matches!(err, PlotError::UnknownFormat { .. }), "{err}");
    let err = plot_master_fit(&[], &fit.spectrum, &dir.join("empty.svg")).unwrap_err();
    assert!(
        err.to_string().contains("nothing to plot for master curve"),
        "{err}"
    );
}
