//! `wrc solve --plot DIR --plot-reference`: the exact reference of the case (Kalker's exact
//! steady rolling, TANG, on Kalker's exact normal pressure, NORM: what `--tangential exact
//! --normal norm` computes) and its patches paired with the model's for y0.svg and strips.svg.

use crate::args::{Normal, Precision, SolveArgs, Tangential};
use crate::doc::{Patch, Status};

/// Largest distance between the reference points of a model patch and its reference patch, mm
/// (the two runs place the patches with the same kernel wheel solve, so matched reference points
/// agree to rounding; flange and tread patches lie tens of mm apart).
const MATCH_MM: f64 = 2.0;

/// The name of the reference in legends.
pub const LABEL: &str = "reference: exact on norm";

/// Whether the model of `a` is the reference itself (`--tangential exact` on NORM pressure).
pub fn is_reference(a: &SolveArgs) -> bool {
    a.common.tangential == Tangential::Exact && a.normal() == Normal::Norm
}

/// The command line of the reference: `a` with `--tangential exact --normal norm` in f64, the
/// wheel/rail `--flex` kept (it enters only the kernel's wheel solve that places the patches),
/// the elliptic one dropped (TANG takes no flexibility), and no plots.
fn reference_args(a: &SolveArgs) -> SolveArgs {
    let mut r = a.clone();
    r.common.tangential = Tangential::Exact;
    r.common.normal = Some(Normal::Norm);
    r.common.precision = Precision::F64;
    if r.elliptic() {
        r.common.flex = None;
    }
    r.plot = None;
    r.plot_reference = false;
    r
}

/// Runs the reference of `a` and returns its patches and status. When the model is the
/// reference, `model` is returned as it is (no second run).
pub fn run(a: &SolveArgs, model: &[Patch]) -> Result<(Vec<Patch>, Status), String> {
    if is_reference(a) {
        return Ok((
            model.to_vec(),
            Status {
                path: if a.elliptic() {
                    "elliptic"
                } else {
                    "converged"
                },
                converged: true,
                ..Status::default()
            },
        ));
    }
    let r = reference_args(a);
    let solved = if r.elliptic() {
        // the exact branch runs before any use of the capacity
        crate::elliptic::solve::<f64, { crate::MAX_GRID }, { crate::MAX_GRID }>(&r, false)
            .map(|s| (vec![s.patch], s.status))
    } else {
        crate::wheelrail::solve::<f64, 64>(&r, false).map(|s| (s.patches, s.status))
    };
    solved.map_err(|e| format!("--plot-reference: the exact reference failed: {e}"))
}

/// Pairs every model patch with the reference patch whose reference point (`y_ref_mm`) is
/// nearest, within [`MATCH_MM`], each reference patch used once (the same index first when it
/// qualifies). Returns the reference index per model patch and the warnings for `status`: a
/// different number of patches and any patch left unpaired.
pub fn pair(model: &[Patch], reference: &[Patch]) -> (Vec<Option<usize>>, Vec<String>) {
    let mut used = vec![false; reference.len()];
    let mut out = vec![None; model.len()];
    let dist = |m: &Patch, r: &Patch| (m.y_ref_mm - r.y_ref_mm).abs();
    for (k, m) in model.iter().enumerate() {
        if let Some(r) = reference.get(k) {
            if dist(m, r) <= MATCH_MM {
                out[k] = Some(k);
                used[k] = true;
            }
        }
    }
    for (k, m) in model.iter().enumerate() {
        if out[k].is_some() {
            continue;
        }
        let best = reference
            .iter()
            .enumerate()
            .filter(|(j, r)| !used[*j] && dist(m, r) <= MATCH_MM)
            .min_by(|x, y| dist(m, x.1).total_cmp(&dist(m, y.1)));
        if let Some((j, _)) = best {
            out[k] = Some(j);
            used[j] = true;
        }
    }
    let mut warnings = vec![];
    if model.len() != reference.len() {
        warnings.push(format!(
            "--plot-reference: the reference has {} patches, the model {}; plotted the {} that \
             match by reference point",
            reference.len(),
            model.len(),
            out.iter().flatten().count()
        ));
    }
    for (k, m) in model.iter().enumerate() {
        if out[k].is_none() {
            warnings.push(format!(
                "--plot-reference: no reference patch near model patch {k} (y_ref {:.3} mm); \
                 plotted without the reference",
                m.y_ref_mm
            ));
        }
    }
    for (j, r) in reference.iter().enumerate() {
        if !used[j] {
            warnings.push(format!(
                "--plot-reference: reference patch {j} (y_ref {:.3} mm) matches no model patch; \
                 not plotted",
                r.y_ref_mm
            ));
        }
    }
    (out, warnings)
}

#[cfg(test)]
mod tests {
    use super::pair;
    use crate::doc::Patch;

    fn at(y: f64) -> Patch {
        Patch {
            y_ref_mm: y,
            ..Patch::default()
        }
    }

    #[test]
    fn patches_pair_by_reference_point_and_report_the_rest() {
        let (p, w) = pair(&[at(-5.0), at(30.0)], &[at(-5.0), at(30.1)]);
        assert_eq!(p, vec![Some(0), Some(1)]);
        assert!(w.is_empty());
        // the reference found one patch only, the flange one
        let (p, w) = pair(&[at(-5.0), at(30.0)], &[at(30.2)]);
        assert_eq!(p, vec![None, Some(0)]);
        assert_eq!(w.len(), 2, "{w:?}");
        assert!(w[0].contains("the reference has 1 patches, the model 2"));
        // the reference has a second patch the model lacks
        let (p, w) = pair(&[at(1.0)], &[at(-20.0), at(1.5)]);
        assert_eq!(p, vec![Some(1)]);
        assert_eq!(w.len(), 2, "{w:?}");
    }
}
