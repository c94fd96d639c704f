//! FEA material cards from a [`RelaxationSpectrum`] (+ optional WLF [`ShiftLaw`]), and readers of such
//! cards back into spectra: Abaqus, ANSYS Mechanical APDL, LS-DYNA.
//!
//! Input: [`RelaxationSpectrum`], [`ShiftLaw`] (WLF or Arrhenius), [`CardOptions`]; output: card text
//! (`String`); [`card`] adds the warnings a shift law brings. Readers:
//! [`read_abaqus`], [`read_ansys`], [`read_lsdyna`] → [`CardContents`] → [`CardContents::to_spectrum`].
//! Units are SI (Pa, s, temperatures in °C as in the shift law); each card says so in a comment.
//!
//! Formats written (relative moduli are kind-independent: Eᵢ/E₀ = Gᵢ/G₀ for a constant ν):
//! - **Abaqus** `*VISCOELASTIC, TIME=PRONY`, one data line `gᵢ, kᵢ, τᵢ` per term with gᵢ = Eᵢ/E₀
//!   normalised to the *instantaneous* modulus (kᵢ: bulk ratios, 0 by default = elastic bulk response,
//!   the usual choice for rubber; [`BulkRelaxation::SameAsShear`] writes kᵢ = gᵢ, constant ν).
//!   `*TRS, DEFINITION=WLF` with one data line `θ₀, C1, C2`, Abaqus' WLF being
//!   −log A = C1(θ − θ₀)/(C2 + θ − θ₀), i.e. log10 A = our log10 a_T.
//!   Checked against: Abaqus Keywords Reference, `*TRS` (v2016 and 2017 pages: DEFINITION=WLF default,
//!   data line "reference temperature, C1, C2") and the theory page "Time domain viscoelasticity" (WLF as
//!   −log A = h(θ) = C1(θ−θ₀)/(C2+θ−θ₀)); `*VISCOELASTIC` (v6.5 keywords page: TIME=PRONY, elasticity
//!   from `*ELASTIC`/`*HYPERELASTIC`). The card must be combined with an elastic definition of the
//!   instantaneous modulus (`*ELASTIC, MODULI=INSTANTANEOUS`), given in a comment.
//!   `tests/cards_vendor.rs` reads our *TRS with its own parser and, with Abaqus' form, reproduces
//!   the EPLEXOR software's own WLF table of EMS-CA (RMS 0.21 decade; the flipped sign 11.9).
//! - **ANSYS** `TB,PRONY,mat,1,n,SHEAR` then `TBDATA` with pairs `aᵢ, τᵢ` (aᵢ = Gᵢ/G₀ relative to the
//!   instantaneous modulus), six values per `TBDATA` line with the start index, and
//!   `TB,SHIFT,mat,1,3,WLF` + `TBDATA,1,T_ref,C1,C2`. Checked against: a real card written by ANSYS 2020 R1
//!   (`data/pyvisco-ems-ca/ansys_prony_terms_freq_user_master.MPL`: `TB,PRON,_MATL,1,27,SHEA`,
//!   `TBDATA,1,a1,t1,a2,t2,a3,t3`, `TBDATA,4,…`) and the ANSYS 18.2 command reference page of `TBDATA`
//!   (STLOC + up to six constants). TB,SHIFT's fields are checked against the TB command reference
//!   Ansys ships in PyMAPDL (`ansys/pymapdl`, `_commands/prep7/materials.py`, `tb`, Mechanical APDL
//!   2023 R2 text: Lab = SHIFT "allows one temperature"; NPTS = 3 for TBOPT = WLF, 2 for TBOPT = TN;
//!   TBOPT WLF, TN, FICT, PLIN, USER). Not checked against ANSYS (its Material Reference page
//!   `ans_mat/evis.html` and any ANSYS-written TB,SHIFT card could not be retrieved here): the
//!   order of the constants (T_r, C1, C2 for WLF; T_r, H/R for TN) and the forms
//!   log10 A = C1(T−T_r)/(C2+T−T_r) and A = exp[(H/R)(1/T_r − 1/T)] for the factor A that divides
//!   relaxation times (τ(T) = τ(T_r)/A, so A = 1/a_T and ANSYS's C1, C2 are ours). WELSIM's manual,
//!   which follows the ANSYS conventions, states the same WLF form and τ(T) = τ(T_r)/A. An
//!   Arrhenius law goes in as TN without fictive temperature (H = E_a), in absolute temperatures:
//!   the card says to set TOFFST,273.15 for a °C model. The TB,PRONY layout is compared with
//!   ANSYS's own card by an independent parser in `tests/cards_vendor.rs`.
//! - **Abaqus Arrhenius**: `*TRS, DEFINITION=ARRHENIUS` with one data line θ₀, E₀ (Keywords
//!   Reference v2016 `*TRS`: "you need to specify the universal gas constant and absolute zero using
//!   the *PHYSICAL CONSTANTS option"; the form ln A = (E₀/R)(1/(θ−θ_Z) − 1/(θ₀−θ_Z)) from the
//!   Abaqus/3DEXPERIENCE materials guide "Thermorheologically simple temperature effects").
//!   *PHYSICAL CONSTANTS is model data (once per model), so the card states it in a comment and
//!   [`card`] returns it as a note.
//! - **LS-DYNA** `*MAT_GENERAL_VISCOELASTIC` (MAT_076): card 1 `MID, RO, BULK, PCF, EF, TREF, A, B`,
//!   card 2 (`LCID, NT, BSTART, TRAMP, LCIDK, NTK, BSTARTK, TRAMPK`) left blank because the Prony terms are
//!   given directly, then one card `GI, BETAI, KI, BETAKI` per term with *absolute shear* moduli Gᵢ and
//!   decay constants βᵢ = 1/τᵢ; the equilibrium modulus G∞ is a term with β = 0 (MAT_076 has no separate
//!   long-term field: G(t) = Σ Gᵢ e^(−βᵢt)). Fixed 10-character fields; numbers are written with the most
//!   significant digits that fit (5–7). TREF, A, B: WLF shift (A = C1, B = C2), TREF in kelvin
//!   because the keyword requires TREF > 0 (WLF depends on T − TREF only, so A and B do not change;
//!   the deck's temperatures must then be in K). At most 18 terms.
//!   Checked against: the keyword definition Ansys publishes in its PyDyna package
//!   (`keyword_classes/auto/mat_general_viscoelastic.py` and its documentation page: card 1 MID, RO,
//!   BULK, PCF, EF, TREF, A, B in 10-column fields at columns 1, 11, …, 71; card 2 LCID, NT, BSTART,
//!   TRAMP, LCIDK, NTK, BSTARTK, TRAMPK; cards 3+ GI, BETAI, KI, BETAKI at columns 1, 11, 21, 31;
//!   "TREF: reference temperature for shift function (must be greater than zero)"; A: coefficient of
//!   the Arrhenius and WLF shift, B: of the WLF shift). Until this check TREF was written in °C,
//!   which LS-DYNA refuses at or below 0 °C (e.g. EMS-CA's −5 °C). The WLF sign convention and log
//!   base of A, B were not in that source, nor the form of the Arrhenius shift, so an Arrhenius law
//!   is refused for LS-DYNA (`LSDYNA_NO_ARRHENIUS`; [`card`] writes the card without it and says
//!   so).
//!
//! Readers: our own three formats (round trips) and ANSYS `TB,PRON`/`TB,PRONY` cards written by ANSYS
//! itself (abbreviated keywords, `_MATL` placeholders, `TBFIELD`/`TBIN` lines ignored).

use crate::material::{GAS_CONSTANT_J_PER_MOL_K, ZERO_CELSIUS_K};
use crate::prony::{RelaxationSpectrum, RelaxationTerm};
use crate::{ModulusKind, ShiftLaw};
use serde::{Deserialize, Serialize};

/// Errors of card writing and reading.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum CardError {
    /// The spectrum cannot be written (e.g. E₀ ≤ 0).
    #[error("cannot write the card: {0}")]
    Unwritable(String),
    /// The shift law is a table (the cards carry WLF or Arrhenius laws only).
    #[error(
        "the {format} card carries a WLF or Arrhenius shift only; the shift law given is {law}"
    )]
    ShiftNotWlf {
        /// Card format.
        format: &'static str,
        /// The law found.
        law: &'static str,
    },
    /// The target code has no documented form for the shift law given (the card without a shift can
    /// still be written: [`card`] does so and says why).
    #[error("the {format} card cannot carry this shift law: {why}")]
    ShiftUnsupported {
        /// Card format.
        format: &'static str,
        /// Why.
        why: String,
    },
    /// A line of a card could not be parsed.
    #[error("line {line}: {message}")]
    Parse {
        /// 1-based line number.
        line: usize,
        /// What was wrong.
        message: String,
    },
    /// The card holds no Prony data.
    #[error("no Prony series found in the card ({0})")]
    Missing(&'static str),
}

/// How the bulk modulus relaxes (Abaqus kᵢ, LS-DYNA KI).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum BulkRelaxation {
    /// Elastic bulk response (kᵢ = 0), the usual choice for rubber.
    #[default]
    Elastic,
    /// The bulk modulus relaxes like the shear modulus (kᵢ = gᵢ): a constant Poisson's ratio.
    SameAsShear,
}

/// Options of the card writers.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct CardOptions {
    /// Material id (ANSYS MAT, LS-DYNA MID).
    pub material_id: u32,
    /// Bulk relaxation (Abaqus kᵢ).
    pub bulk: BulkRelaxation,
    /// Mass density in kg/m³ for LS-DYNA's RO (blank when None: set it in the deck).
    pub density_kg_m3: Option<f64>,
}

impl Default for CardOptions {
    fn default() -> Self {
        CardOptions {
            material_id: 1,
            bulk: BulkRelaxation::Elastic,
            density_kg_m3: None,
        }
    }
}

/// What a card holds, normalised: relative strengths and times, plus what the card states about the
/// instantaneous modulus (our own cards write it in a comment; foreign cards usually do not).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CardContents {
    /// Instantaneous modulus E₀ (or G₀ for shear) in Pa, if the card states it.
    pub instantaneous_modulus_pa: Option<f64>,
    /// Tensile or shear, as the card states (LS-DYNA and ANSYS SHEAR: shear).
    pub kind: ModulusKind,
    /// Poisson's ratio, if the card states it.
    pub poisson: Option<f64>,
    /// (relative strength aᵢ = Eᵢ/E₀, τᵢ in s).
    pub terms: Vec<(f64, f64)>,
    /// WLF shift if the card carries one.
    pub shift: Option<ShiftLaw>,
}

impl CardContents {
    /// The spectrum, with E₀ = `instantaneous_modulus_pa` (overrides the card's) and ν = `poisson`
    /// (overrides; default the card's or 0.5). E∞ = E₀(1 − Σ aᵢ).
    pub fn to_spectrum(
        &self,
        instantaneous_modulus_pa: Option<f64>,
        poisson: Option<f64>,
    ) -> Result<RelaxationSpectrum, CardError> {
        let e0 = instantaneous_modulus_pa
            .or(self.instantaneous_modulus_pa)
            .ok_or_else(|| {
                CardError::Unwritable(
                    "the card gives relative moduli only: state the instantaneous modulus".into(),
                )
            })?;
        let sum: f64 = self.terms.iter().map(|t| t.0).sum();
        Ok(RelaxationSpectrum {
            kind: self.kind,
            poisson: poisson.or(self.poisson).unwrap_or(0.5),
            modulus_inf_pa: e0 * (1.0 - sum).max(0.0),
            terms: self
                .terms
                .iter()
                .map(|&(a, tau)| RelaxationTerm {
                    modulus_pa: a * e0,
                    tau_s: tau,
                })
                .collect(),
        })
    }
}

/// A number with 17 significant digits (exact round trip), exponent with sign and two digits.
fn sci(x: f64) -> String {
    let s = format!("{x:.16e}");
    let (m, e) = s.split_once('e').expect("exponent");
    let e: i32 = e.parse().expect("exponent");
    format!("{m}e{}{:02}", if e < 0 { '-' } else { '+' }, e.abs())
}

/// A number in at most `width` characters with as many significant digits as fit (≥ 2).
fn fixed_width(x: f64, width: usize) -> String {
    if x == 0.0 {
        return format!("{:>width$}", "0.0");
    }
    for digits in (1..=9).rev() {
        let s = format!("{x:.digits$e}");
        if s.len() <= width {
            return format!("{s:>width$}");
        }
    }
    format!("{:>width$}", format!("{x:.0e}"))
}

/// The shift law as a card writes it.
enum CardLaw {
    /// (T_ref °C, C1, C2 K).
    Wlf(f64, f64, f64),
    /// (T_ref °C, E_a J/mol).
    Arrhenius(f64, f64),
}

fn shift_of(law: Option<&ShiftLaw>, format: &'static str) -> Result<Option<CardLaw>, CardError> {
    match law {
        None => Ok(None),
        Some(ShiftLaw::Wlf { t_ref_c, c1, c2_k }) => Ok(Some(CardLaw::Wlf(*t_ref_c, *c1, *c2_k))),
        Some(ShiftLaw::Arrhenius {
            t_ref_c,
            activation_energy_j_per_mol,
        }) => Ok(Some(CardLaw::Arrhenius(
            *t_ref_c,
            *activation_energy_j_per_mol,
        ))),
        Some(ShiftLaw::Table { .. }) => Err(CardError::ShiftNotWlf {
            format,
            law: "a table",
        }),
    }
}

fn checked(spectrum: &RelaxationSpectrum) -> Result<f64, CardError> {
    spectrum
        .validate()
        .map_err(|e| CardError::Unwritable(e.to_string()))?;
    Ok(spectrum.instantaneous_modulus())
}

fn kind_name(kind: ModulusKind) -> &'static str {
    match kind {
        ModulusKind::Tensile => "tensile",
        ModulusKind::Shear => "shear",
    }
}

/// The instantaneous elastic constants a card's elastic definition takes, saying which modulus
/// each number is: Young's modulus E₀ of a tensile spectrum as it is; for a shear spectrum G₀ and
/// the Young's modulus E₀ = 2(1 + ν)G₀ that the elastic slot (Abaqus `*ELASTIC`, ANSYS `MP,EX`)
/// takes.
fn elastic_constants(spectrum: &RelaxationSpectrum, e0: f64) -> String {
    let nu = spectrum.poisson;
    match spectrum.kind {
        ModulusKind::Tensile => format!("E0 = {} Pa (Young's modulus), nu = {nu}", sci(e0)),
        ModulusKind::Shear => format!(
            "G0 = {} Pa (shear modulus): Young's modulus E0 = 2(1+nu)G0 = {} Pa, nu = {nu}",
            sci(e0),
            sci(2.0 * (1.0 + nu) * e0)
        ),
    }
}

/// The viscoroll comment line that lets our readers recover E₀, the kind and ν.
fn provenance(prefix: &str, spectrum: &RelaxationSpectrum, e0: f64) -> String {
    format!(
        "{prefix} viscoroll: instantaneous_modulus_pa={} kind={} poisson={}\n",
        sci(e0),
        kind_name(spectrum.kind),
        spectrum.poisson
    )
}

/// Abaqus `*VISCOELASTIC, TIME=PRONY` (+ `*TRS, DEFINITION=WLF` when a WLF law is given).
pub fn abaqus(
    spectrum: &RelaxationSpectrum,
    shift: Option<&ShiftLaw>,
    options: &CardOptions,
) -> Result<String, CardError> {
    let e0 = checked(spectrum)?;
    let law = shift_of(shift, "Abaqus")?;
    let mut s = String::new();
    s.push_str(&provenance("**", spectrum, e0));
    let m = if spectrum.kind == ModulusKind::Shear {
        "G"
    } else {
        "E"
    };
    s.push_str(&format!(
        "** Units: Pa, s, degC. Prony ratios g_i = {m}_i/{m}0 relative to the instantaneous modulus.\n"
    ));
    s.push_str(&format!(
        "** Combine with *ELASTIC, MODULI=INSTANTANEOUS (Young's modulus): {}\n",
        elastic_constants(spectrum, e0)
    ));
    s.push_str("*VISCOELASTIC, TIME=PRONY\n");
    for t in &spectrum.terms {
        let g = t.modulus_pa / e0;
        let k = match options.bulk {
            BulkRelaxation::Elastic => 0.0,
            BulkRelaxation::SameAsShear => g,
        };
        s.push_str(&format!("{}, {}, {}\n", sci(g), sci(k), sci(t.tau_s)));
    }
    match law {
        Some(CardLaw::Wlf(t_ref, c1, c2)) => {
            s.push_str("*TRS, DEFINITION=WLF\n");
            s.push_str(&format!("{}, {}, {}\n", sci(t_ref), sci(c1), sci(c2)));
        }
        Some(CardLaw::Arrhenius(t_ref, ea)) => {
            // ln A = (E0/R)(1/(θ − θ_Z) − 1/(θ0 − θ_Z)); R and θ_Z come from *PHYSICAL CONSTANTS,
            // which is model data (one per model), so it is stated here, not written.
            s.push_str(&format!(
                "** *TRS ARRHENIUS needs in the model: *PHYSICAL CONSTANTS, ABSOLUTE ZERO={}, UNIVERSAL GAS CONSTANT={}\n",
                -ZERO_CELSIUS_K, GAS_CONSTANT_J_PER_MOL_K
            ));
            s.push_str("*TRS, DEFINITION=ARRHENIUS\n");
            s.push_str(&format!("{}, {}\n", sci(t_ref), sci(ea)));
        }
        None => {}
    }
    Ok(s)
}

/// ANSYS APDL `TB,PRONY … SHEAR` (+ `TB,SHIFT … WLF`).
pub fn ansys(
    spectrum: &RelaxationSpectrum,
    shift: Option<&ShiftLaw>,
    options: &CardOptions,
) -> Result<String, CardError> {
    let e0 = checked(spectrum)?;
    let law = shift_of(shift, "ANSYS")?;
    let m = options.material_id;
    let mut s = String::new();
    s.push_str(&provenance("!", spectrum, e0));
    s.push_str("! Units: Pa, s, degC. Relative moduli a_i = G_i/G0 (instantaneous), relaxation times tau_i.\n");
    s.push_str(&format!(
        "! Combine with the instantaneous elastic constants (MP,EX takes Young's modulus): {}\n",
        elastic_constants(spectrum, e0)
    ));
    s.push_str(&format!("TB,PRONY,{m},1,{},SHEAR\n", spectrum.terms.len()));
    let values: Vec<f64> = spectrum
        .terms
        .iter()
        .flat_map(|t| [t.modulus_pa / e0, t.tau_s])
        .collect();
    for (c, chunk) in values.chunks(6).enumerate() {
        let vals: Vec<String> = chunk.iter().map(|&v| sci(v)).collect();
        s.push_str(&format!("TBDATA,{},{}\n", 6 * c + 1, vals.join(",")));
    }
    match law {
        Some(CardLaw::Wlf(t_ref, c1, c2)) => {
            s.push_str(&format!("TB,SHIFT,{m},1,3,WLF\n"));
            s.push_str(&format!(
                "TBDATA,1,{},{},{}\n",
                sci(t_ref),
                sci(c1),
                sci(c2)
            ));
        }
        Some(CardLaw::Arrhenius(t_ref, ea)) => {
            // Tool–Narayanaswamy without fictive temperature: A = exp[(H/R)(1/T_r − 1/T)] in
            // absolute temperatures, constants T_r and H/R; with E_a = H this is our Arrhenius law
            // (A = 1/a_T).
            s.push_str("! Tool-Narayanaswamy shift (Arrhenius): absolute temperatures, so with degC use TOFFST,273.15\n");
            s.push_str(&format!("TB,SHIFT,{m},1,2,TN\n"));
            s.push_str(&format!(
                "TBDATA,1,{},{}\n",
                sci(t_ref),
                sci(ea / GAS_CONSTANT_J_PER_MOL_K)
            ));
        }
        None => {}
    }
    Ok(s)
}

/// Maximum number of Prony cards (terms including the β = 0 one) written for LS-DYNA.
pub const LSDYNA_MAX_TERMS: usize = 18;

/// LS-DYNA `*MAT_GENERAL_VISCOELASTIC` with absolute shear moduli and βᵢ = 1/τᵢ.
pub fn lsdyna(
    spectrum: &RelaxationSpectrum,
    shift: Option<&ShiftLaw>,
    options: &CardOptions,
) -> Result<String, CardError> {
    let e0 = checked(spectrum)?;
    let wlf = match shift_of(shift, "LS-DYNA")? {
        None => None,
        Some(CardLaw::Wlf(t, c1, c2)) => Some((t, c1, c2)),
        Some(CardLaw::Arrhenius(..)) => {
            return Err(CardError::ShiftUnsupported {
                format: "LS-DYNA",
                why: LSDYNA_NO_ARRHENIUS.into(),
            })
        }
    };
    let g = spectrum.to_kind(ModulusKind::Shear);
    let n = g.terms.len() + usize::from(g.modulus_inf_pa > 0.0);
    if n > LSDYNA_MAX_TERMS {
        return Err(CardError::Unwritable(format!(
            "{n} Prony terms (with the β = 0 equilibrium term); *MAT_GENERAL_VISCOELASTIC takes at most {LSDYNA_MAX_TERMS}"
        )));
    }
    let f = |x: f64| fixed_width(x, 10);
    let blank = " ".repeat(10);
    let mut s = String::new();
    s.push_str(&provenance("$", spectrum, e0));
    s.push_str("$ Units: kg, m, s, Pa, K (TREF must be > 0: temperatures in kelvin). Shear moduli G_i (absolute), decay constants BETA_i = 1/tau_i.\n");
    s.push_str("*MAT_GENERAL_VISCOELASTIC\n");
    s.push_str(
        "$      MID        RO      BULK       PCF        EF      TREF         A         B\n",
    );
    // TREF in kelvin: the keyword's definition asks for TREF > 0 (an absolute temperature); WLF
    // depends on T − TREF only, so A = C1 and B = C2 are the same in K as in °C.
    let (tref, a, b) = match wlf {
        Some((t, c1, c2)) => (f(t + ZERO_CELSIUS_K), f(c1), f(c2)),
        None => (blank.clone(), blank.clone(), blank.clone()),
    };
    let ro = options
        .density_kg_m3
        .map(f)
        .unwrap_or_else(|| blank.clone());
    let bulk = if spectrum.poisson < 0.5 {
        f(e0 * spectrum.kind.to_tensile_factor(spectrum.poisson)
            / (3.0 * (1.0 - 2.0 * spectrum.poisson)))
    } else {
        blank.clone()
    };
    s.push_str(&format!(
        "{:>10}{ro}{bulk}{blank}{blank}{tref}{a}{b}\n",
        options.material_id
    ));
    s.push_str(
        "$     LCID        NT    BSTART     TRAMP     LCIDK       NTK   BSTARTK    TRAMPK\n",
    );
    s.push('\n');
    s.push_str("$       GI     BETAI        KI    BETAKI\n");
    if g.modulus_inf_pa > 0.0 {
        s.push_str(&format!("{}{}\n", f(g.modulus_inf_pa), f(0.0)));
    }
    for t in &g.terms {
        s.push_str(&format!("{}{}\n", f(t.modulus_pa), f(1.0 / t.tau_s)));
    }
    Ok(s)
}

/// Why the LS-DYNA card carries no Arrhenius shift.
pub(crate) const LSDYNA_NO_ARRHENIUS: &str = "*MAT_GENERAL_VISCOELASTIC's A is the coefficient of \
its Arrhenius and its WLF shift (keyword definition in PyDyna), but the form of its Arrhenius shift (log \
base, sign, units of A) is in no source we could check, and it takes no tabulated shift (its only load curve, \
LCID, is a relaxation curve to fit, not a shift): give the shift in the deck";

/// The three card formats.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CardTarget {
    /// [`abaqus`].
    Abaqus,
    /// [`ansys`].
    Ansys,
    /// [`lsdyna`].
    Lsdyna,
}

impl CardTarget {
    /// The name used in messages.
    pub fn name(self) -> &'static str {
        match self {
            CardTarget::Abaqus => "Abaqus",
            CardTarget::Ansys => "ANSYS",
            CardTarget::Lsdyna => "LS-DYNA",
        }
    }
}

/// The card for `target` with the shift law it can carry, and the warnings that go with it: a law
/// the target has no documented form for is left out (the card without it is written) and said so;
/// an Arrhenius law says what else the model needs (Abaqus *PHYSICAL CONSTANTS, ANSYS TOFFST).
pub fn card(
    target: CardTarget,
    spectrum: &RelaxationSpectrum,
    shift: Option<&ShiftLaw>,
    options: &CardOptions,
) -> Result<(String, Vec<String>), CardError> {
    let write = |law: Option<&ShiftLaw>| match target {
        CardTarget::Abaqus => abaqus(spectrum, law, options),
        CardTarget::Ansys => ansys(spectrum, law, options),
        CardTarget::Lsdyna => lsdyna(spectrum, law, options),
    };
    let mut notes = vec![];
    match write(shift) {
        Ok(text) => {
            if let Some(ShiftLaw::Arrhenius { .. }) = shift {
                notes.push(match target {
                    CardTarget::Abaqus => format!(
                        "the Abaqus card's *TRS, DEFINITION=ARRHENIUS needs *PHYSICAL CONSTANTS, ABSOLUTE ZERO={}, UNIVERSAL GAS CONSTANT={} in the model",
                        -ZERO_CELSIUS_K, GAS_CONSTANT_J_PER_MOL_K
                    ),
                    _ => "the ANSYS card's shift is TB,SHIFT Tool-Narayanaswamy (TN: T_r, H/R = E_a/R), in absolute temperatures: with degC in the model, set TOFFST,273.15".into(),
                });
            }
            Ok((text, notes))
        }
        Err(e @ (CardError::ShiftUnsupported { .. } | CardError::ShiftNotWlf { .. })) => {
            notes.push(format!(
                "WARNING: no shift in the {} card: {e}",
                target.name()
            ));
            Ok((write(None)?, notes))
        }
        Err(e) => Err(e),
    }
}

fn parse_f64(tok: &str, line: usize) -> Result<f64, CardError> {
    let t = tok.trim();
    if t.is_empty() {
        return Ok(0.0);
    }
    t.parse::<f64>().map_err(|_| CardError::Parse {
        line,
        message: format!("`{t}` is not a number"),
    })
}

/// Parse our provenance comment (any comment prefix).
fn read_provenance(line: &str, c: &mut CardContents) {
    if let Some(rest) = line.split("viscoroll:").nth(1) {
        for kv in rest.split_whitespace() {
            match kv.split_once('=') {
                Some(("instantaneous_modulus_pa", v)) => {
                    c.instantaneous_modulus_pa = v.parse().ok()
                }
                Some(("kind", "shear")) => c.kind = ModulusKind::Shear,
                Some(("kind", "tensile")) => c.kind = ModulusKind::Tensile,
                Some(("poisson", v)) => c.poisson = v.parse().ok(),
                _ => {}
            }
        }
    }
}

fn empty_contents(kind: ModulusKind) -> CardContents {
    CardContents {
        instantaneous_modulus_pa: None,
        kind,
        poisson: None,
        terms: vec![],
        shift: None,
    }
}

/// Read an Abaqus `*VISCOELASTIC, TIME=PRONY` card (and `*TRS, DEFINITION=WLF`).
pub fn read_abaqus(text: &str) -> Result<CardContents, CardError> {
    let mut c = empty_contents(ModulusKind::Tensile);
    #[derive(PartialEq)]
    enum Block {
        None,
        Prony,
        Wlf,
        Arrhenius,
    }
    let mut block = Block::None;
    let mut found = false;
    for (i, raw) in text.lines().enumerate() {
        let line = raw.trim();
        if line.starts_with("**") {
            read_provenance(line, &mut c);
            continue;
        }
        if line.is_empty() {
            continue;
        }
        if line.starts_with('*') {
            let up = line.to_ascii_uppercase().replace(' ', "");
            block = if up.starts_with("*VISCOELASTIC") && up.contains("TIME=PRONY") {
                found = true;
                Block::Prony
            } else if up.starts_with("*TRS")
                && (!up.contains("DEFINITION=") || up.contains("DEFINITION=WLF"))
            {
                Block::Wlf
            } else if up.starts_with("*TRS") && up.contains("DEFINITION=ARRHENIUS") {
                Block::Arrhenius
            } else {
                Block::None
            };
            continue;
        }
        let v: Vec<f64> = line
            .split(',')
            .map(|t| parse_f64(t, i + 1))
            .collect::<Result<_, _>>()?;
        match block {
            Block::Prony => {
                if v.len() < 3 {
                    return Err(CardError::Parse {
                        line: i + 1,
                        message: "expected g_i, k_i, tau_i".into(),
                    });
                }
                c.terms.push((v[0], v[2]));
            }
            Block::Wlf => {
                if v.len() < 3 {
                    return Err(CardError::Parse {
                        line: i + 1,
                        message: "expected theta_0, C1, C2".into(),
                    });
                }
                c.shift = Some(ShiftLaw::Wlf {
                    t_ref_c: v[0],
                    c1: v[1],
                    c2_k: v[2],
                });
                block = Block::None;
            }
            Block::Arrhenius => {
                if v.len() < 2 {
                    return Err(CardError::Parse {
                        line: i + 1,
                        message: "expected theta_0, E_0".into(),
                    });
                }
                c.shift = Some(ShiftLaw::Arrhenius {
                    t_ref_c: v[0],
                    activation_energy_j_per_mol: v[1],
                });
                block = Block::None;
            }
            Block::None => {}
        }
    }
    if !found {
        return Err(CardError::Missing("no *VISCOELASTIC, TIME=PRONY"));
    }
    Ok(c)
}

/// Read an ANSYS APDL card: `TB,PRONY`/`TB,PRON` (SHEAR; a BULK table is skipped) with its `TBDATA`
/// lines, and `TB,SHIFT … WLF`. Written by ANSYS itself or by [`ansys`].
pub fn read_ansys(text: &str) -> Result<CardContents, CardError> {
    let mut c = empty_contents(ModulusKind::Shear);
    #[derive(PartialEq, Clone, Copy)]
    enum Table {
        None,
        PronyShear,
        Wlf,
        Tn,
    }
    let mut table = Table::None;
    let mut prony: Vec<f64> = vec![];
    let mut wlf: Vec<f64> = vec![];
    let mut shift_kind = Table::None;
    let mut found = false;
    for (i, raw) in text.lines().enumerate() {
        let line = raw.trim();
        if let Some(rest) = line.strip_prefix('!') {
            read_provenance(rest, &mut c);
            continue;
        }
        let line = line.split('!').next().unwrap_or("").trim();
        if line.is_empty() {
            continue;
        }
        let fields: Vec<&str> = line.split(',').map(str::trim).collect();
        let cmd = fields[0].to_ascii_uppercase();
        if cmd == "TB" {
            let lab = fields
                .get(1)
                .map(|s| s.to_ascii_uppercase())
                .unwrap_or_default();
            let opt = fields
                .get(5)
                .map(|s| s.to_ascii_uppercase())
                .unwrap_or_default();
            let t = if lab.starts_with("PRON") && (opt.is_empty() || opt.starts_with("SHEA")) {
                found = true;
                prony.clear();
                Table::PronyShear
            } else if lab.starts_with("SHIF") && opt.starts_with("WLF") {
                wlf.clear();
                Table::Wlf
            } else if lab.starts_with("SHIF") && opt == "TN" {
                wlf.clear();
                Table::Tn
            } else {
                Table::None
            };
            if matches!(t, Table::Wlf | Table::Tn) {
                shift_kind = t;
            }
            table = t;
        } else if cmd.starts_with("TBDA") {
            let start = parse_f64(fields.get(1).copied().unwrap_or("1"), i + 1)? as usize;
            if start == 0 {
                return Err(CardError::Parse {
                    line: i + 1,
                    message: "TBDATA start location must be ≥ 1".into(),
                });
            }
            let target = match table {
                Table::PronyShear => &mut prony,
                Table::Wlf | Table::Tn => &mut wlf,
                Table::None => continue,
            };
            for (k, tok) in fields.iter().skip(2).enumerate() {
                let idx = start - 1 + k;
                if target.len() <= idx {
                    target.resize(idx + 1, 0.0);
                }
                target[idx] = parse_f64(tok, i + 1)?;
            }
        }
    }
    if !found {
        return Err(CardError::Missing("no TB,PRONY … SHEAR table"));
    }
    if prony.len() % 2 == 1 {
        prony.push(0.0);
    }
    c.terms = prony.chunks(2).map(|p| (p[0], p[1])).collect();
    // The last TB,SHIFT table read decides the law.
    if shift_kind == Table::Wlf && wlf.len() >= 3 {
        c.shift = Some(ShiftLaw::Wlf {
            t_ref_c: wlf[0],
            c1: wlf[1],
            c2_k: wlf[2],
        });
    } else if shift_kind == Table::Tn && wlf.len() >= 2 {
        c.shift = Some(ShiftLaw::Arrhenius {
            t_ref_c: wlf[0],
            activation_energy_j_per_mol: wlf[1] * GAS_CONSTANT_J_PER_MOL_K,
        });
    }
    Ok(c)
}

/// Read an LS-DYNA `*MAT_GENERAL_VISCOELASTIC` card written in fixed 10-character fields (or with
/// commas). Terms with β = 0 make up the equilibrium modulus. Returns shear moduli relative to G₀ with
/// G₀ = Σ GI stated as the instantaneous modulus.
pub fn read_lsdyna(text: &str) -> Result<CardContents, CardError> {
    let mut c = empty_contents(ModulusKind::Shear);
    let mut in_card = false;
    let mut card_no = 0;
    let mut g_inf = 0.0;
    let mut terms: Vec<(f64, f64)> = vec![];
    let mut wlf = None;
    let fields_of = |line: &str, i: usize| -> Result<Vec<f64>, CardError> {
        if line.contains(',') {
            line.split(',').map(|t| parse_f64(t, i)).collect()
        } else {
            let chars: Vec<char> = line.chars().collect();
            chars
                .chunks(10)
                .map(|ch| parse_f64(&ch.iter().collect::<String>(), i))
                .collect()
        }
    };
    for (i, raw) in text.lines().enumerate() {
        if raw.starts_with('$') {
            read_provenance(raw, &mut c);
            continue;
        }
        if raw.starts_with('*') {
            in_card = raw
                .trim()
                .to_ascii_uppercase()
                .starts_with("*MAT_GENERAL_VISCOELASTIC");
            card_no = 0;
            continue;
        }
        if !in_card {
            continue;
        }
        card_no += 1;
        match card_no {
            1 => {
                let v = fields_of(raw, i + 1)?;
                let get = |k: usize| v.get(k).copied().unwrap_or(0.0);
                if get(6) != 0.0 || get(7) != 0.0 {
                    wlf = Some(ShiftLaw::Wlf {
                        t_ref_c: get(5) - ZERO_CELSIUS_K,
                        c1: get(6),
                        c2_k: get(7),
                    });
                }
            }
            2 => {}
            _ => {
                if raw.trim().is_empty() {
                    continue;
                }
                let v = fields_of(raw, i + 1)?;
                let gi = v.first().copied().unwrap_or(0.0);
                let beta = v.get(1).copied().unwrap_or(0.0);
                if beta == 0.0 {
                    g_inf += gi;
                } else {
                    terms.push((gi, 1.0 / beta));
                }
            }
        }
    }
    if card_no == 0 {
        return Err(CardError::Missing("no *MAT_GENERAL_VISCOELASTIC"));
    }
    let g0 = g_inf + terms.iter().map(|t| t.0).sum::<f64>();
    if g0 <= 0.0 {
        return Err(CardError::Missing("all GI are zero"));
    }
    // The card's moduli are shear; keep them shear and relative to G₀.
    c.kind = ModulusKind::Shear;
    c.instantaneous_modulus_pa = Some(g0);
    c.terms = terms.into_iter().map(|(g, tau)| (g / g0, tau)).collect();
    c.shift = wlf;
    Ok(c)
}

impl CardContents {
    /// Most Prony cards (terms including the β = 0 one) written for LS-DYNA (`LSDYNA_MAX_TERMS`).
    pub const LSDYNA_MAX_TERMS: usize = LSDYNA_MAX_TERMS;

    /// Read an Abaqus card (`read_abaqus`).
    pub fn from_abaqus(text: &str) -> Result<Self, CardError> {
        read_abaqus(text)
    }

    /// Read an ANSYS APDL card (`read_ansys`).
    pub fn from_ansys(text: &str) -> Result<Self, CardError> {
        read_ansys(text)
    }

    /// Read an LS-DYNA card (`read_lsdyna`).
    pub fn from_lsdyna(text: &str) -> Result<Self, CardError> {
        read_lsdyna(text)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn number_formats() {
        assert_eq!(sci(1.5e-3), "1.5000000000000000e-03");
        assert_eq!(sci(-2.0e12), "-2.0000000000000000e+12");
        assert_eq!(fixed_width(1.234567891e9, 10), "1.234568e9");
        assert_eq!(fixed_width(1.234567891e-9, 10), "1.23457e-9");
        assert_eq!(fixed_width(0.0, 10), "       0.0");
        assert_eq!(fixed_width(1e200, 10).trim().parse::<f64>().unwrap(), 1e200);
    }
}
