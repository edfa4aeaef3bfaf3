//! Repeats one tangential kernel call for a profiler (callgrind counts are deterministic):
//!
//! `tangential_profile <workload> <reps>`, workloads:
//! * `fastsim-parabolic`, `fastsim-clip`, `fastsim-coulomb`, `fastsim-crs` — FASTSIM on CONTACT's
//!   8 × 4 mm example, 32 × 32 (parabolic bound with `Clip`, elliptic bound with each slip rule);
//! * `fastrip` — FaStrip defaults on the same patch (the firmware's "fastrip default 32x32");
//! * `fastrip-sat` — FaStrip defaults at large creepage (ξ = 2e-3, η = −3e-3, φ = 2e-4 rad/mm: most
//!   cells slip, the Coulomb solve runs everywhere);
//! * `ac`, `ft`, `ft-wear`, `patch` — on the heaviest patch of the first sweep case (dy = −3 mm,
//!   1353 mm, right wheel): the Ayasse–Chollet region set-up (`adapt::region_patch`, all regions),
//!   FaStrip with a `()` sink, FaStrip with a KTH wear sink, and `pipeline::solve_patch`
//!   (STRIPES + AC + FaStrip + wear); `patch-forces`: `pipeline::solve_patch_forces` (no wear).
//!
//! Per call = (count at `reps` − count at 0 reps) / reps:
//! `valgrind --tool=callgrind --callgrind-out-file=/dev/null target/release/examples/tangential_profile fastrip 100`.

use std::hint::black_box;
use wrc_host_tests::cases::{a8b4, contact_material};
use wrc_kernel::adapt::{region_patch, solve_tangential, LocalEllipse};
use wrc_kernel::fastrip::{fastrip, FastripSettings};
use wrc_kernel::fastsim::{fastsim, FastsimSettings, SlipRule};
use wrc_kernel::geometry::{contact_patches, Patches, WheelRail};
use wrc_kernel::patch::{
    CellOut, CellSink, Creepage, HertzPressure, SemiEllipticStrips, TractionBound,
};
use wrc_kernel::pipeline::{solve_patch, solve_patch_forces, DefaultWorkspace};
use wrc_kernel::stripes::StripSample;
use wrc_kernel::wear::{StripWear, WearMap};
use wrc_kernel::wheel::{solve_wheel, DefaultWheelWorkspace, WheelConfig};
use wrc_kernel::Material;

struct Wear<'a> {
    w: &'a mut StripWear<f64, 128>,
    map: WearMap<f64>,
    v: f64,
    dx: f64,
}

impl CellSink<f64> for Wear<'_> {
    fn cell(&mut self, j: usize, _i: usize, out: &CellOut<f64>) {
        if out.slip {
            let s = wrc_kernel::math::hypot(out.sx, out.sy);
            self.w.add_cell(&self.map, j, out.pn, s, self.v, self.dx);
        }
    }
}

fn main() {
    let mut args = std::env::args().skip(1);
    let work = args.next().unwrap_or_else(|| "fastrip".into());
    let reps: usize = args.next().and_then(|s| s.parse().ok()).unwrap_or(1);
    let mut acc = 0.0f64;
    let elliptic = work.starts_with("fastsim") || work.starts_with("fastrip");
    if elliptic {
        let (patch, ell) = a8b4::<f64, 32, 32>();
        let pr = HertzPressure(ell);
        let cr = if work == "fastrip-sat" {
            Creepage {
                xi: 2e-3,
                eta: -3e-3,
                phi: 2e-4,
            }
        } else {
            Creepage {
                xi: 0.0,
                eta: -6.25e-4,
                phi: 6.25e-4,
            }
        };
        let _ = contact_material::<f64>();
        let mu = 0.3;
        let fs = |bound, slip| FastsimSettings::with_slip(mu, bound, slip);
        let set = match work.as_str() {
            "fastsim-parabolic" => Some(fs(TractionBound::Parabolic(ell), SlipRule::Clip)),
            "fastsim-clip" => Some(fs(TractionBound::Elliptic, SlipRule::Clip)),
            "fastsim-coulomb" => Some(fs(TractionBound::Elliptic, SlipRule::Coulomb)),
            "fastsim-crs" => Some(fs(TractionBound::Elliptic, SlipRule::CoulombRigidSlip)),
            _ => None,
        };
        let def = FastripSettings::new(mu);
        for _ in 0..reps {
            let t = match &set {
                Some(s) => fastsim(black_box(&patch), &pr, black_box(&cr), s, &mut ()),
                None => fastrip(black_box(&patch), &pr, black_box(&cr), &def, &mut ()),
            }
            .expect("solve");
            acc += t.total.fy;
        }
        println!("{work} × {reps}: Σ Fy = {acc:.6}");
        return;
    }
    // A wheel/rail patch: the heaviest patch of the first sweep case.
    let pair = wrc_bench::tables::<f64>();
    let cases = wrc_bench::sweep(&pair);
    let (w, r) = (&*pair.0, &*pair.1);
    let mat = Material::<f64>::steel();
    let v = 100.0 / 3.6 * 1000.0;
    let cfg = WheelConfig::recommended(0.3, v, 460.0);
    let mut ws = Box::new(DefaultWheelWorkspace::<f64>::new());
    let cs = &cases[0];
    let g = WheelRail::<f64, 2048, 2048>::place(r, w, &cs.setup, &cs.pose, cs.side, 0.05)
        .expect("placement");
    let res = solve_wheel(&g, 83_300.0, &mat, &cfg, &mut ws, &mut ()).expect("wheel");
    let mut patches = Box::new(Patches::<f64, 4, 128>::new());
    contact_patches(&g, res.vertical_approach, &cfg.patches, &mut patches).expect("patches");
    let p = res
        .patches
        .iter()
        .max_by(|a, b| a.load.total_cmp(&b.load))
        .expect("a patch");
    let mut kk = 0;
    for (i, it) in patches.as_slice().iter().enumerate() {
        if (it.frame.y_ref_rail - p.frame.y_ref_rail).abs() < 1e-9 {
            kk = i;
        }
    }
    let sm = &patches.items[kk].samples;
    let samples: Vec<StripSample<f64>> = (0..sm.n)
        .map(|i| StripSample {
            y: sm.s(i),
            dy: sm.width[i],
            z: sm.f_n[i],
            curv_a: sm.a_long[i],
            curv_b: sm.b_lat[i],
            xc: sm.x_c[i],
        })
        .collect();
    let pc = &cfg.pipeline;
    let mut pw = Box::new(DefaultWorkspace::<f64>::new());
    if work == "patch-forces" {
        for _ in 0..reps {
            let r = solve_patch_forces(
                black_box(&samples[..]),
                p.load,
                &p.creepage,
                &mat,
                pc,
                &mut pw,
            )
            .expect("patch");
            acc += r.totals.fy;
        }
        println!("{work} × {reps}: Σ Fy = {acc:.6}");
        return;
    }
    if work == "patch" {
        for _ in 0..reps {
            let r = solve_patch(
                black_box(&samples[..]),
                p.load,
                &p.creepage,
                &mat,
                pc,
                &mut pw,
                &mut (),
            )
            .expect("patch");
            acc += r.totals.fy;
        }
        println!("{work} × {reps}: Σ Fy = {acc:.6}");
        return;
    }
    let sol = pw
        .stripes
        .solve(&samples, p.load, &mat, &pc.stripes)
        .expect("stripes");
    pw.stripes
        .layout(&sol, &samples, p.load, pc.strips_per_region, &mut pw.set)
        .expect("layout");
    let mut local = [LocalEllipse::<f64>::default(); 32];
    let bound = pc.adapt.default_bound();
    let mut wear = Box::new(StripWear::<f64, 128>::new());
    let n_reg = pw.set.n_regions;
    let regs: Vec<_> = (0..n_reg)
        .map(|k| {
            region_patch::<f64, 32, 32, 128, 4>(&pw.set, k, &pc.adapt, &mat, &mut local)
                .expect("AC")
        })
        .collect();
    for _ in 0..reps {
        match work.as_str() {
            "ac" => {
                for k in 0..n_reg {
                    let pt = region_patch::<f64, 32, 32, 128, 4>(
                        black_box(&pw.set),
                        k,
                        &pc.adapt,
                        &mat,
                        &mut local,
                    )
                    .expect("AC");
                    acc += pt.dx;
                }
            }
            "ft" | "ft-wear" => {
                for patch in &regs {
                    let t = if work == "ft" {
                        solve_tangential(
                            black_box(patch),
                            &SemiEllipticStrips,
                            &p.creepage,
                            pc.method,
                            bound,
                            pc.mu,
                            &mut (),
                        )
                    } else {
                        let mut sink = Wear {
                            w: &mut wear,
                            map: pc.wear,
                            v,
                            dx: patch.dx,
                        };
                        solve_tangential(
                            black_box(patch),
                            &SemiEllipticStrips,
                            &p.creepage,
                            pc.method,
                            bound,
                            pc.mu,
                            &mut sink,
                        )
                    }
                    .expect("fastrip");
                    acc += t.total.fy;
                }
            }
            _ => panic!("unknown workload {work}"),
        }
    }
    println!(
        "{work} × {reps} ({n_reg} regions): Σ = {acc:.6} {}",
        wear.depth[0]
    );
}
