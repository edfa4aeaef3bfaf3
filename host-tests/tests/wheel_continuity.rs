//! Continuity of the per-wheel solve in the lateral shift on real geometry (issue 6, methods.md §6
//! item 8): S1002/UIC60, right wheel, back-to-back 1360 mm, 83.3 kN, yaw 1.2·dy mrad, equilibrium
//! roll, the kernel's default `wheel::solve_wheel` (f64), in **0.01 mm steps** over windows
//! where the contact changes character (found with `wheelrail::transition_cases` on the sweep and
//! listed below): STRIPES regions appear or split at the gauge corner (dy ≈ 3.98 and 4.75 mm) and
//! at the flange root (dy ≈ 5.88 mm), and the flange-root contact sets in and merges with a
//! gauge-corner region (dy ≈ 4.49…4.51 mm).
//!
//! Quantities per wheel: Σ N_k, Σ F_x,k, Σ F_y,k (patch frames), pmax (max over patches and
//! regions), area (sum over patches).
//!
//! # Measure: jumps do not shrink under refinement, kinks do
//! pmax is a maximum over regions and strips and the contact regions appear, split and merge, so
//! the quantities are continuous but only piecewise smooth: kinks (slope breaks) are legitimate.
//! They show on the 0.01 mm grid as steps much larger than their neighbours, e.g. (measured)
//! * dy 4.50→4.51: Δpmax = +238 MPa against −14 and +75 MPa beside it — the flange-root region
//!   (pmax 627 MPa at 4.49, rising 45 MPa per 0.00125 mm) takes over the maximum from the tread
//!   region at 4.5037, and its growth slows ninefold at 4.5113 (its load grows 350 N per
//!   0.0001 mm before, 55 N after — a slope break of the geometry, continuous at 0.0001 mm);
//! * dy 4.57→4.58 and 4.59→4.60: Δpmax ≈ +30 MPa against ±2…5 MPa — the peak strip of the
//!   merged flange region changes (a max over strips: rise, turn, plateau);
//! * dy 4.71→4.72: ΔF_x = −86 N against −24 and −3 N — not FaStrip noise: the gauge-corner
//!   region's F_x/N stays 0.2106…0.2107 while its load wanders 4403 → 3457 N over 0.02 mm (the
//!   region moves along the rail head 12× faster than dy), continuous at 0.0001 mm with slope
//!   breaks (e.g. at 4.7012, 4.7021).
//!
//! A neighbour ratio alone cannot tell these from a jump. Refinement can: at a discontinuity J
//! the change over the sub-interval containing it stays ≥ J however fine the steps, while a
//! continuous, piecewise-smooth quantity's sub-steps shrink and become like their neighbours
//! (a kink's sub-step lies between its neighbours' sizes). So every 0.01 mm step whose change
//! exceeds the floor 1e-4·S_q (S_q = F_z for the forces, the window's largest pmax and area;
//! solver tolerances are 1e-6) is refined 8× (0.00125 mm); a sub-step is *suspect* when it is
//! above the floor and holds more than ¼ of the step's variation V = Σ|sub-steps| or more than
//! 1.5× its larger neighbour. A step without suspects is continuous at this resolution; each
//! suspect is refined 8× again, down to four levels (0.01/4096 ≈ 2.4e-6 mm); a suspect at the
//! last level is a **jump**. (Four since the creepages are taken on the wheel surface, issue
//! 17.1: the flange-root region at dy ≈ 5.8822 now sets in over 4.5e-5 mm — area +0.023 mm²,
//! continuous at 2e-6 mm with kinks at both ends — which three levels, 2e-5 mm, called a jump.)
//! (Limit: a jump below the floor, or smaller than the smooth change of its 2.4e-6 mm sub-step,
//! is not seen — e.g. F_x micro-steps of ≈ 2 N = 2.4e-5·S at dy 4.0660 and 4.0668 from the
//! tangential solve, found at 0.0001 mm.)
//!
//! Result (2026-12-01, `StripesConfig::b_floor` 0.1, soft basins, neck blend): no jump in any
//! window; every refinement shift converges. Before: the curvature-floor and basin jumps (at
//! 0.001 mm: dy 4.002→4.003 pmax −0.30 %, area +0.33 %; 5.873→5.874 area +0.44 %; 4.480→4.481 a
//! flange-root region edge moving 0.22 mm), then the strip layout's jumps at merges and splits
//! of regions ([`KNOWN_JUMPS`] docs) with non-converged load–traction coupling at the exact
//! split shifts (dy 4.6836328, 5.8825) — all rejected by this measure.

use std::collections::BTreeMap;
use wrc_host_tests::wheelrail::*;
use wrc_kernel::geometry::Side;
use wrc_kernel::wheel::{solve_wheel, DefaultWheelWorkspace};
use wrc_kernel::Material;

/// (b2b, first shift, steps of 0.01 mm)
const WINDOWS: [(f64, f64, usize); 4] = [
    (1360.0, 3.88, 20),
    (1360.0, 4.45, 20),
    (1360.0, 4.68, 20),
    (1360.0, 5.80, 20),
];
const LOAD: f64 = 83_300.0;
/// Base step, mm.
const H: f64 = 0.01;
/// Refinement factor per level and the number of levels (finest step H/4096 ≈ 2.4e-6 mm); positions
/// are kept in units of the finest step.
const R: usize = 8;
const LEVELS: u32 = 4;
const UNIT: usize = R * R * R * R;
/// Jumps the measure finds that are not fixed yet: (b2b, start of the 0.01 mm step, quantity).
/// Each must still be found (a fix shows up as a failure that asks to shorten the list). Empty
/// since the neck blend of `pipeline::solve_patch`; before it the strip layout (32 evenly spaced
/// strips per connected region) jumped at merges and splits: dy 4.61 merge (pmax 1840 → 1794 MPa,
/// −2.5 %: the 3 mm flange part went from 32 strips to ≈ 6; area −0.9 mm², F_x +58 N), 4.68
/// split (F_x −30 N, pmax +3.4 MPa), 4.74 merge (area −0.39 mm², pmax −1.9 MPa).
const KNOWN_JUMPS: [(f64, &str, &str); 0] = [];
const NAMES: [&str; 5] = ["N", "Fx", "Fy", "pmax", "area"];

struct Solver<'a> {
    w: &'a Table,
    r: &'a Table,
    ws: Box<DefaultWheelWorkspace<f64>>,
    b2b: f64,
    from: f64,
    /// solved quantities by position in units of H/`UNIT` from `from`
    cache: BTreeMap<usize, [f64; 5]>,
    sig: BTreeMap<usize, Vec<usize>>,
}

impl Solver<'_> {
    fn q(&mut self, pos: usize) -> [f64; 5] {
        if let Some(q) = self.cache.get(&pos) {
            return *q;
        }
        let dy = self.from + H * pos as f64 / UNIT as f64;
        let c = sweep_case(self.w, self.r, Side::Right, self.b2b, dy, LOAD).unwrap();
        let g = c.place(self.w, self.r).unwrap();
        let res = solve_wheel(
            &g,
            LOAD,
            &Material::steel(),
            &c.config(),
            &mut self.ws,
            &mut (),
        )
        .unwrap();
        assert!(res.converged, "{} (dy {dy:.7})", c.label);
        let ps: Vec<_> = res.patches.iter().collect();
        let q = [
            ps.iter().map(|p| p.load).sum(),
            ps.iter().map(|p| p.result.totals.fx).sum(),
            ps.iter().map(|p| p.result.totals.fy).sum(),
            ps.iter().map(|p| p.result.pmax).fold(0.0, f64::max),
            ps.iter().map(|p| p.result.area).sum(),
        ];
        self.cache.insert(pos, q);
        self.sig.insert(pos, contact_signature(&res));
        q
    }

    /// Whether quantity `k` is continuous on [a, a + len] (positions in H/`UNIT`) at this
    /// resolution (module docs): the `R` sub-steps spread the change (largest ≤ ¼ of their total
    /// variation) or stay below `floor`; otherwise every sub-step above ¼ of the variation is
    /// checked one level finer, and a sub-step that still holds the change at the last level is a
    /// jump. Returns the smallest spread factor V/max met on the way (for the printout) and the
    /// verdict.
    fn continuous(
        &mut self,
        a: usize,
        len: usize,
        k: usize,
        floor: f64,
        level: u32,
    ) -> (f64, bool) {
        let sub = len / R;
        let d: Vec<f64> = (0..R)
            .map(|j| self.q(a + (j + 1) * sub)[k] - self.q(a + j * sub)[k])
            .collect();
        let v: f64 = d.iter().map(|x| x.abs()).sum();
        let m = d.iter().map(|x| x.abs()).fold(0.0, f64::max);
        if m <= floor {
            return (f64::INFINITY, true);
        }
        // a sub-step that holds most of the change or stands out from its neighbours
        let suspect = |j: usize| {
            let nb = match j {
                0 => d[1].abs(),
                _ if j == R - 1 => d[R - 2].abs(),
                _ => d[j - 1].abs().max(d[j + 1].abs()),
            };
            d[j].abs() > floor && (d[j].abs() > v / 4.0 || d[j].abs() > 1.5 * nb)
        };
        if !(0..R).any(suspect) {
            return (v / m, true);
        }
        if level == LEVELS {
            return (v / m, false);
        }
        let mut worst = (v / m, true);
        for j in 0..R {
            if suspect(j) {
                let (f, ok) = self.continuous(a + j * sub, sub, k, floor, level + 1);
                worst = (worst.0.min(f), worst.1 && ok);
            }
        }
        worst
    }
}

/// Σ N, Σ F_x, Σ F_y, pmax and area of the per-wheel solve are continuous in the lateral shift
/// over the four windows (module docs: neighbour flag + refinement; jumps do not shrink).
#[test]
fn wheel_solve_is_continuous_in_the_shift() {
    let (w, r) = tables().unwrap();
    let mut fails = vec![];
    let mut still: Vec<(f64, String, &str)> = vec![];
    for (b2b, from, steps) in WINDOWS {
        let mut s = Solver {
            w: &w,
            r: &r,
            ws: Box::new(DefaultWheelWorkspace::<f64>::new()),
            b2b,
            from,
            cache: BTreeMap::new(),
            sig: BTreeMap::new(),
        };
        let base = UNIT;
        let rows: Vec<[f64; 5]> = (0..=steps).map(|i| s.q(i * base)).collect();
        let sigs: Vec<Vec<usize>> = (0..=steps).map(|i| s.sig[&(i * base)].clone()).collect();
        let changes: Vec<String> = sigs
            .windows(2)
            .enumerate()
            .filter(|(_, g)| g[0] != g[1])
            .map(|(i, g)| format!("{:.2}: {:?}→{:?}", from + H * (i + 1) as f64, g[0], g[1]))
            .collect();
        println!(
            "b2b {b2b} dy {from:.2}…{:.2} region changes {changes:?}",
            from + H * steps as f64
        );
        let scale = [
            LOAD,
            LOAD,
            LOAD,
            rows.iter().map(|q| q[3]).fold(0.0, f64::max),
            rows.iter().map(|q| q[4]).fold(0.0, f64::max),
        ];
        for k in 0..5 {
            let d: Vec<f64> = rows.windows(2).map(|p| p[1][k] - p[0][k]).collect();
            let floor = 1e-4 * scale[k];
            let maxstep = d.iter().map(|x| x.abs()).fold(0.0, f64::max) / scale[k];
            let mut line = format!("  {} max step {:.2e}·S;", NAMES[k], maxstep);
            let mut least = (f64::INFINITY, 0usize);
            for (i, di) in d.iter().enumerate() {
                if di.abs() <= floor {
                    continue;
                }
                let (f, ok) = s.continuous(i * base, base, k, floor, 1);
                if f < least.0 {
                    least = (f, i);
                }
                if !ok {
                    let key = format!("{:.2}", from + H * i as f64);
                    let known = KNOWN_JUMPS
                        .iter()
                        .any(|(b, at, q)| *b == b2b && *at == key && *q == NAMES[k]);
                    line += &format!(
                        " JUMP {key}→{:.2} Δ {di:+.4e}{};",
                        from + H * (i + 1) as f64,
                        if known { " (known)" } else { "" }
                    );
                    if known {
                        still.push((b2b, key, NAMES[k]));
                    } else {
                        fails.push(format!(
                            "b2b {b2b} dy {key}→{:.2}: Δ{} {di:+.4e} does not spread under \
                             refinement to {:.1e} mm (a jump)",
                            from + H * (i + 1) as f64,
                            NAMES[k],
                            H / UNIT as f64
                        ));
                    }
                }
            }
            line += &format!(
                " least spread V/max {:.1} at {:.2}",
                least.0,
                from + H * least.1 as f64
            );
            println!("{line}");
        }
        println!("  {} wheel solves (all converged)", s.cache.len());
    }
    for (b, at, q) in KNOWN_JUMPS {
        if !still
            .iter()
            .any(|(b2, a2, q2)| *b2 == b && a2 == at && *q2 == q)
        {
            fails.push(format!(
                "known jump b2b {b} dy {at} {q} is gone — shorten KNOWN_JUMPS"
            ));
        }
    }
    assert!(fails.is_empty(), "{fails:#?}");
}
