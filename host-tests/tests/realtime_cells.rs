//! The real-time step with per-cell fields and wear (`wrc_kernel::step::step_cells`, issue 14):
//! the same result as the forces-only step, cells that add up to the closed-form forces, and a
//! wear rate against the converged per-wheel solver's on the same states (S1002/UIC60, 1353 mm,
//! right wheel, the examples' table).

use wrc_host_tests::realtime::{s1002_uic60_table, standard_spec, step_strip};
use wrc_host_tests::wheelrail::{tables, NODES, R0, SWEEP_SPEED};
use wrc_kernel::geometry::{
    equilibrium_roll, Kinematics, Side, TrackSetup, WheelRail, WheelsetPose,
};
use wrc_kernel::patch::{CellOut, CellSink};
use wrc_kernel::step::{step, step_cells, step_from, StepInput};
use wrc_kernel::table::ContactTable;
use wrc_kernel::wear::WearMap;
use wrc_kernel::wheel::{
    resolve_patch_strips, solve_wheel, DefaultWheelWorkspace, WheelConfig, WheelSink,
};
use wrc_kernel::Material;

const K: usize = 3;
const ST: usize = 16;
const C: usize = 32;
const MU: f64 = 0.3;

/// Sums what the cells carry: forces, the KTH wear rate Σ k p |s| ΔA / H over slipping cells
/// (mm² of worn cross-section per passage: the wear depth integrated across the patch), and the
/// slip and contact cell counts.
#[derive(Default)]
struct Sums {
    fx: f64,
    fy: f64,
    wear: f64,
    slip: usize,
    cells: usize,
    speed: f64,
}

impl CellSink<f64> for Sums {
    fn cell(&mut self, _j: usize, _i: usize, o: &CellOut<f64>) {
        self.fx += o.px * o.area;
        self.fy += o.py * o.area;
        self.cells += 1;
        if o.slip {
            self.slip += 1;
            let (d, _) =
                WearMap::<f64>::kth().cell_depth(o.pn, o.sx.hypot(o.sy), self.speed, o.area);
            self.wear += d;
        }
    }
}

impl WheelSink<f64> for Sums {}

fn input(dy: f64, yaw: f64, fz: f64) -> StepInput<f64> {
    StepInput {
        pose: WheelsetPose { dy, yaw, roll: 0.0 },
        fz,
        kinematics: Kinematics::nominal(SWEEP_SPEED, R0),
        mu: MU,
    }
}

#[test]
fn cells_and_wear_of_the_step() {
    let bytes = s1002_uic60_table::<f64, K, ST>(&standard_spec()).unwrap().0;
    let t = ContactTable::<f64>::from_bytes(&bytes).unwrap();
    let (w, r) = tables().unwrap();
    let setup = TrackSetup {
        back_to_back: 1353.0,
        ..TrackSetup::standard()
    };
    let cfg = WheelConfig::recommended(MU, SWEEP_SPEED, R0);
    let mat = Material::<f64>::steel();
    let mut ws = Box::new(DefaultWheelWorkspace::<f64>::new());
    let mut geom = Box::new(WheelRail::<f64, NODES, NODES>::unplaced(&r, &w, &setup));
    let mut worst_force = 0.0f64;
    let mut ratios = vec![];
    // tread (dy −2 … 2 mm) to flange (−7.5 mm), yaw 1.2·dy mrad as the seed's cases, 83.3 kN
    for &dy in &[2.0, 0.0, -2.0, -4.0, -6.0, -7.5] {
        let yaw = 1.2e-3 * dy;
        let inp = input(dy, yaw, 83_300.0);
        let cold = step::<f64, K, ST>(&t, &inp).unwrap();
        let mut sums = Sums {
            speed: SWEEP_SPEED,
            ..Sums::default()
        };
        let (rc, wear) = step_cells::<f64, K, ST, C, _>(&t, &inp, None, &mut sums).unwrap();
        // the same numbers as the forces-only step, with and without a previous result
        assert_eq!(rc, cold, "dy {dy}");
        let warm = step_from::<f64, K, ST>(&t, &inp, &cold).unwrap();
        let mut none = ();
        let (rw, _) = step_cells::<f64, K, ST, C, _>(&t, &inp, Some(&cold), &mut none).unwrap();
        assert_eq!(rw, warm, "dy {dy}");
        // the cells carry the closed form's forces (cell FaStrip on 16 × 32 cells)
        let (fx, fy) = cold
            .slots
            .iter()
            .fold((0.0, 0.0), |(a, b), s| (a + s.fx, b + s.fy));
        let muf = MU * inp.fz;
        let df = (sums.fx - fx).hypot(sums.fy - fy) / muf;
        worst_force = worst_force.max(df);
        // wear: finite, not negative, and only where cells slip
        for k in 0..K {
            for d in wear.depth[k] {
                assert!(d.is_finite() && d >= 0.0);
            }
        }
        assert!(sums.cells > 0);
        // against the converged solver's cells at the same pose (its own strips and grid)
        let roll = equilibrium_roll::<f64, NODES, NODES>(&r, &w, &setup, dy, 0.0, 0.05)
            .unwrap()
            .roll;
        let pose = WheelsetPose { dy, yaw, roll };
        geom.place_in(&r, &w, &setup, &pose, Side::Right, 0.05)
            .unwrap();
        let mut conv = Sums {
            speed: SWEEP_SPEED,
            ..Sums::default()
        };
        solve_wheel(&geom, inp.fz, &mat, &cfg, &mut ws, &mut conv).unwrap();
        let ratio = sums.wear / conv.wear;
        eprintln!(
            "dy {dy:+.1}: |ΔF| cells vs closed form {:.3} % of μF_z; wear rate {:.3e} vs converged {:.3e} mm² (ratio {ratio:.3}); slip cells {}/{} vs {}/{}",
            100.0 * df,
            sums.wear,
            conv.wear,
            sums.slip,
            sums.cells,
            conv.slip,
            conv.cells
        );
        ratios.push(ratio);
    }
    eprintln!(
        "worst |ΔF| of the cells against the closed form: {:.3} % of μF_z",
        100.0 * worst_force
    );
    // measured 0.07 % (dy −7.5 mm; 0.44 % with the closed form's 8 slip intervals)
    assert!(worst_force < 0.01, "{worst_force}");
    // wear rate within 3 % of the converged solver's on every state (measured within 0.5 %: the
    // table's 16 strips and their interpolation against the solver's own strips and grid)
    for (q, r) in ratios.iter().enumerate() {
        assert!((r - 1.0).abs() < 0.03, "state {q}: wear rate ratio {r:.4}");
    }
}

/// The closed-form strip forces (`fastrip::strip_forces`, what the step runs) on the converged
/// solver's own strips and creepages against its cell FaStrip, from the tread into deep flange
/// contact (S1002/UIC60, 1353 mm, right wheel, yaw 0, 83.3 kN, μ 0.3): large longitudinal
/// creepage with spin (ξ down to −4.4e-2, φ up to 1.9e-3 1/mm), where the relaxation of the
/// traction direction is stiff and the rigid slip turns along each strip. Before the direction
/// integrator followed that turn (the s-derivative term of its Rosenbrock step) the closed form
/// was 4.6–13 % of μN off here; measured now 0.3–1.3 %.
#[test]
fn closed_form_follows_the_cell_fastrip_into_deep_flange_contact() {
    let (w, r) = tables().unwrap();
    let setup = TrackSetup {
        back_to_back: 1353.0,
        ..TrackSetup::standard()
    };
    let mat = Material::<f64>::steel();
    let mut ws = Box::new(DefaultWheelWorkspace::<f64>::new());
    let cfg = WheelConfig::recommended(MU, SWEEP_SPEED, R0);
    let mut worst = 0.0f64;
    for dy in [-4.0, -7.5, -8.5, -9.5, -10.5, -11.5] {
        let roll = equilibrium_roll::<f64, NODES, NODES>(&r, &w, &setup, dy, 0.0, 0.05)
            .unwrap()
            .roll;
        let pose = WheelsetPose { dy, yaw: 0.0, roll };
        let geom = WheelRail::<f64, NODES, NODES>::place(&r, &w, &setup, &pose, Side::Right, 0.05)
            .unwrap();
        let res = solve_wheel(&geom, 83_300.0, &mat, &cfg, &mut ws, &mut ()).unwrap();
        for (q, p) in res.patches.iter().enumerate() {
            let mut c = cfg;
            c.creepage = Some(p.creepage);
            resolve_patch_strips(&mut ws, q, p.load, &mat, &c).unwrap();
            let set = &ws.pipeline.set;
            let (mut fx, mut fy) = (0.0, 0.0);
            for j in 0..set.n_strips {
                // the strip as the step builds it
                let Some(st) = step_strip(set, j, mat.nu) else {
                    continue;
                };
                let st = st.unwrap();
                let (a, b, _) =
                    wrc_kernel::fastrip::strip_forces(&st, &p.creepage, MU, mat.g, mat.nu).unwrap();
                fx += a;
                fy += b;
            }
            let t = &p.result.totals;
            let d = (fx - t.fx).hypot(fy - t.fy) / (MU * p.load);
            eprintln!(
                "dy {dy:+.1}: angle {:.3}, creepages ({:.2e}, {:.2e}, {:.2e}): cells ({:.0}, {:.0}) N, closed form ({fx:.0}, {fy:.0}) N: {:.2} % of μN",
                p.frame.angle, p.creepage.xi, p.creepage.eta, p.creepage.phi, t.fx, t.fy, 100.0 * d
            );
            worst = worst.max(d);
        }
    }
    // the cell FaStrip's own grid error in these patches is of the order of 1 % of μN
    assert!(
        worst < 0.02,
        "closed form {:.2} % of μN off the cell FaStrip",
        100.0 * worst
    );
}

/// The closed-form strip forces on one long strip of deep flange contact, where the rigid slip
/// turns fast along the strip, against the cell FaStrip on 4096 cells (grid-converged): strip
/// j = 15 of the issue-14 sweep's worst flange state (S1002/UIC60, 1353 mm, right wheel, dy
/// −9.555 mm, 131 kN, μ 0.12: a_j = 24.2 mm, δy = 0.08 mm, n/m = 0.053, the Ayasse–Chollet
/// flexibilities of the converged solver), at ξ = −2.92e-2, η = 5.17e-3 and spin 0 … 2.03e-3
/// 1/mm, and at ξ = −5e-3, η = 1e-3 under the same spin (the rigid slip passes close to zero
/// and turns by nearly π along the strip). The direction's error is second order in the slip
/// zone's interval ([`wrc_kernel::fastrip::SLIP_STEPS`]): measured with 8 / 16 / 32 intervals
/// 6.50 / 1.03 / 0.22 % of μN at the largest spin and 21.9 / 4.63 / 0.58 % at ξ = −5e-3; 0.36 /
/// 0.16 / 0.03 % at spin 1e-3, 5e-4, 0 (16 intervals). Asserted at the measured values of the
/// default (16) with a margin of a fifth.
#[test]
fn closed_form_follows_a_fast_turning_rigid_slip_on_a_long_strip() {
    use wrc_kernel::fastrip::{fastrip, strip_forces, FastripSettings};
    use wrc_kernel::patch::{Creepage, Flexibilities, SemiEllipticStrips, Strip, StripPatch};
    const CELLS: usize = 4096;
    let mat = Material::<f64>::steel();
    let mu = 0.12;
    let (a, dy, g) = (24.214, 0.0797, 0.053f64);
    let mun = 2004.0;
    let p_hat = mun / mu / (std::f64::consts::FRAC_PI_2 * a * dy);
    let kc = wrc_kernel::kalker::coefficients(1.0 / g, mat.nu).unwrap();
    let strip = Strip {
        y: 0.237,
        dy,
        a,
        xc: 0.0,
        p_hat,
        flex: Flexibilities {
            l1: 4.55e-5,
            l2: 3.91e-5,
            l3: 3.19e-5,
        },
        c11: kc.c11,
        c22: kc.c22,
        c23: kc.c23,
        c33: kc.c33,
        sqrt_b_over_a: g.sqrt(),
    };
    // the cell FaStrip needs at least 8 strips: the others empty, far from the first
    let mut strips = [Strip {
        a: 0.0,
        p_hat: 0.0,
        y: 5.0,
        ..strip
    }; 8];
    strips[0] = strip;
    let patch = StripPatch::<f64, 8, CELLS>::new(strips, -a, 2.0 * a / CELLS as f64, mat).unwrap();
    for (xi, eta, phi, limit) in [
        (-2.92e-2, 5.17e-3, 2.03e-3, 0.0125),
        (-2.92e-2, 5.17e-3, 1.0e-3, 0.0045),
        (-2.92e-2, 5.17e-3, 5.0e-4, 0.002),
        (-2.92e-2, 5.17e-3, 0.0, 0.0005),
        (-5e-3, 1e-3, 2.03e-3, 0.056),
    ] {
        let cr = Creepage { xi, eta, phi };
        let (fx, fy, _) = strip_forces(&strip, &cr, mu, mat.g, mat.nu).unwrap();
        let t = fastrip(
            &patch,
            &SemiEllipticStrips,
            &cr,
            &FastripSettings::new(mu),
            &mut (),
        )
        .unwrap();
        let n = std::f64::consts::FRAC_PI_2 * a * p_hat * dy;
        let d = (fx - t.total.fx).hypot(fy - t.total.fy) / (mu * n);
        eprintln!(
            "ξ {xi:.2e} η {eta:.2e} φ {phi:.2e}: cells ({:.1}, {:.1}), closed form ({fx:.1}, {fy:.1}) N: {:.2} % of μN",
            t.total.fx,
            t.total.fy,
            100.0 * d
        );
        assert!(d <= limit, "{:.2} % > {:.2} %", 100.0 * d, 100.0 * limit);
    }
}

/// The real-time step's FaStrip runs a slot's strips side by side (`strip_forces_lanes`, in
/// groups of `fastrip::LANES`: 16 on 64-bit hosts, 1 on the microcontrollers): every strip's
/// forces must be bit-identical to `strip_forces` of that strip alone, whatever its group (16, 4
/// or 1 here) and its neighbours, over strips with and without slip zone, FASTSIM strips (failing
/// the bound check), set and Kalker flexibilities, empty strips and creepages from 1e-5 to 5e-2
/// with spin.
#[test]
fn strips_side_by_side_are_bit_identical_to_one_at_a_time() {
    use wrc_kernel::fastrip::{strip_forces, strip_forces_lanes};
    use wrc_kernel::patch::{Creepage, Flexibilities, Strip};
    let mut seed: u64 = 0x2545_f491_4f6c_dd1d;
    let mut rnd = || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    let mat = Material::<f64>::steel();
    let (mut slipping, mut checked) = (0, 0);
    for q in 0..400 {
        let sc = [1e-5, 1e-4, 1e-3, 1e-2, 5e-2][q % 5];
        let cr = Creepage {
            xi: sc * (2.0 * rnd() - 1.0),
            eta: sc * (2.0 * rnd() - 1.0),
            phi: if q % 7 == 0 {
                0.0
            } else {
                3e-3 * (2.0 * rnd() - 1.0)
            },
        };
        let mu = 0.1 + 0.4 * rnd();
        let strips: Vec<Strip<f64>> = (0..37)
            .map(|j| {
                let g = 0.05 + 0.95 * rnd();
                let kc = wrc_kernel::kalker::coefficients(1.0 / g, mat.nu).unwrap();
                let flex = if (q + j) % 3 == 0 {
                    Flexibilities {
                        l1: 1e-5 + 5e-5 * rnd(),
                        l2: 1e-5 + 5e-5 * rnd(),
                        l3: 1e-5 + 5e-5 * rnd(),
                    }
                } else {
                    Flexibilities::default()
                };
                Strip {
                    y: -5.0 + 10.0 * rnd(),
                    dy: 0.05 + rnd(),
                    a: if (q + j) % 11 == 0 {
                        0.0
                    } else {
                        0.5 + 20.0 * rnd()
                    },
                    xc: -1.0 + 2.0 * rnd(),
                    p_hat: 100.0 + 1500.0 * rnd(),
                    flex,
                    c11: kc.c11,
                    c22: kc.c22,
                    c23: kc.c23,
                    c33: kc.c33,
                    sqrt_b_over_a: g.sqrt(),
                }
            })
            .collect();
        // 37 = 16 + 16 + 4 + 1
        let mut all = vec![];
        for g in strips[..32].chunks(16) {
            let g: &[Strip<f64>; 16] = g.try_into().unwrap();
            all.extend(strip_forces_lanes(g, &cr, mu, mat.g, mat.nu).unwrap());
        }
        let g: &[Strip<f64>; 4] = strips[32..36].try_into().unwrap();
        all.extend(strip_forces_lanes(g, &cr, mu, mat.g, mat.nu).unwrap());
        let g: &[Strip<f64>; 1] = strips[36..].try_into().unwrap();
        all.extend(strip_forces_lanes(g, &cr, mu, mat.g, mat.nu).unwrap());
        for (s, got) in strips.iter().zip(&all) {
            let one = strip_forces(s, &cr, mu, mat.g, mat.nu).unwrap();
            assert_eq!(
                (one.0.to_bits(), one.1.to_bits(), one.2.to_bits()),
                (got.0.to_bits(), got.1.to_bits(), got.2.to_bits()),
                "strip {s:?} under {cr:?}"
            );
            checked += 1;
            if one.0.hypot(one.1) > 0.5 * mu * std::f64::consts::FRAC_PI_2 * s.a * s.p_hat * s.dy {
                slipping += 1;
            }
        }
    }
    // the set holds mostly slipping strips as well as mostly adhering ones
    assert!(
        slipping > checked / 5 && slipping < checked * 4 / 5,
        "{slipping} of {checked}"
    );
}
