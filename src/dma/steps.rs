//! Which steps of a multi-step export are oscillatory frequency sweeps. TRIOS procedures and
//! RheoCompass tests often hold a conditioning step, a flow curve, a creep or stress-ramp step, an
//! amplitude sweep or a time sweep beside the frequency sweeps; those are skipped with a note that
//! names each step, never read as isotherms and never a reason to stop.
//!
//! Input: a step, interval or result name ([`super::table::Block::label`]); output: why it is not a
//! frequency sweep, or `None` (read it; its columns and frequencies then decide, see
//! `columns::map_file`).

/// Name fragments (lower case) of steps that are not oscillatory frequency sweeps, with the reason.
const NOT_A_SWEEP: &[(&str, &str)] = &[
    ("amplitude", "an amplitude sweep"),
    ("strain sweep", "an amplitude (strain) sweep"),
    ("stress sweep", "an amplitude (stress) sweep"),
    ("oscillation strain", "an amplitude (strain) sweep"),
    ("amplitudentest", "an amplitude sweep"),
    ("balayage en déformation", "an amplitude sweep"),
    ("time sweep", "a time sweep"),
    ("zeittest", "a time sweep"),
    ("zeitsweep", "a time sweep"),
    ("balayage en temps", "a time sweep"),
    ("flow", "not oscillatory (a flow step)"),
    ("viscosity", "not oscillatory (a flow step)"),
    ("steady", "not oscillatory (a steady-shear step)"),
    ("rotation", "not oscillatory (a rotational step)"),
    ("fließ", "not oscillatory (a flow step)"),
    ("fliess", "not oscillatory (a flow step)"),
    ("viskosität", "not oscillatory (a flow step)"),
    ("écoulement", "not oscillatory (a flow step)"),
    ("ecoulement", "not oscillatory (a flow step)"),
    ("viscosité", "not oscillatory (a flow step)"),
    ("creep", "not oscillatory (a creep step)"),
    ("kriech", "not oscillatory (a creep step)"),
    ("fluage", "not oscillatory (a creep step)"),
    ("recovery", "not oscillatory (a recovery step)"),
    (
        "stress relaxation",
        "not oscillatory (a stress-relaxation step)",
    ),
    ("stress ramp", "not oscillatory (a stress ramp)"),
    ("strain ramp", "not oscillatory (a strain ramp)"),
    ("peak hold", "not oscillatory (a peak hold)"),
    ("conditioning", "not a measurement (conditioning)"),
    ("equilibrat", "not a measurement (equilibration)"),
    ("soak", "not a measurement (a soak)"),
    ("pre-shear", "not a measurement (pre-shear)"),
    ("preshear", "not a measurement (pre-shear)"),
];

/// Why the step named `label` is not an oscillatory frequency sweep, or `None` when its name does
/// not say (a name that says "frequency" is always read).
pub(crate) fn not_a_sweep(label: &str) -> Option<&'static str> {
    let l = label.to_lowercase();
    if ["frequency", "frequenz", "fréquence", "frequence"]
        .iter()
        .any(|w| l.contains(w))
    {
        return None;
    }
    NOT_A_SWEEP
        .iter()
        .find(|(w, _)| l.contains(w))
        .map(|(_, why)| *why)
}

#[cfg(test)]
mod tests {
    use super::not_a_sweep;

    #[test]
    fn names_each_kind_of_step() {
        assert_eq!(not_a_sweep("Frequency sweep (25.0 °C)"), None);
        assert_eq!(not_a_sweep("FS -42,5 °C"), None);
        assert!(not_a_sweep("Flow ramp - 1").unwrap().contains("flow"));
        assert!(not_a_sweep("Amplitude sweep - 2")
            .unwrap()
            .contains("amplitude"));
        assert!(not_a_sweep("Time sweep - 5").unwrap().contains("time"));
        assert!(not_a_sweep("Creep - 3").unwrap().contains("creep"));
        assert!(not_a_sweep("Conditioning Sample").is_some());
        assert!(not_a_sweep("Fließkurve").is_some());
        assert!(not_a_sweep("Courbe d'écoulement").is_some());
        // A frequency sweep after a flow step in the same name is still a frequency sweep.
        assert_eq!(not_a_sweep("Frequency sweep after flow"), None);
    }
}
