//! Regression digest of the tangential solvers, for checking that an optimisation changes results
//! only by floating-point reassociation:
//!
//! * `tangential_digest write <file>` — runs FASTSIM (three slip rules × elliptic/parabolic bound)
//!   and FaStrip (defaults, `spec_clip`, `FullSlip`, `Local` check, CONTACT M5/M6 both λ forms) on
//!   Hertz patches a/b ∈ {0.2, 0.5, 1, 2, 5} × 12 creepage sets (32 × 32, CONTACT and tight grids),
//!   per cell (p_n, bound, p_x, p_y, s_x, s_y, slip) and totals, plus `wheel::solve_wheel` on the
//!   40 sweep cases (per patch and region: forces, moment, load, p_max, area, wear), in f64 and
//!   f32, and writes every value as raw little-endian f64;
//! * `tangential_digest compare <old> <new>` — prints, per group, the number of values that differ,
//!   the largest relative change |Δ|/max(|old|, |new|) and the largest change scaled by the
//!   group's largest magnitude (near-zero values of symmetric cases make the first one noisy).
//!
//! `cargo run --release -p wrc-bench --example tangential_digest -- write /tmp/old.bin`

use std::io::{Read, Write};
use wrc_host_tests::cases::contact_material;
use wrc_kernel::fastrip::{fastrip, BoundCheck, FastripSettings, LambdaVariant, LargeSpin};
use wrc_kernel::fastsim::{fastsim, FastsimSettings, SlipRule};
use wrc_kernel::geometry::{TrackSetup, WheelRail, WheelsetPose};
use wrc_kernel::patch::{
    CellOut, CellSink, Creepage, GridExtent, HertzPressure, StripPatch, Tangential, TractionBound,
};
use wrc_kernel::wheel::{solve_wheel, DefaultWheelWorkspace, WheelConfig};
use wrc_kernel::{Material, Real};

/// Groups of values (one scale each).
const GROUPS: [&str; 6] = [
    "f64 elliptic cells",
    "f64 elliptic totals",
    "f32 elliptic cells",
    "f32 elliptic totals",
    "f64 wheel",
    "f32 wheel",
];

struct Out {
    vals: Vec<(u8, f64)>,
}

impl Out {
    /// A value of group `g` (kind 0).
    fn push(&mut self, g: u8, v: f64) {
        self.vals.push((g * 16, v));
    }
    /// A value of group `g` and quantity kind `k` (< 16; the compare scales by kind and case).
    fn pushk(&mut self, g: u8, k: u8, v: f64) {
        self.vals.push((g * 16 + k, v));
    }
    /// Starts a new case.
    fn case(&mut self) {
        self.vals.push((255, 0.0));
    }
}

struct Cells<'a> {
    o: &'a mut Out,
    g: u8,
}

impl<T: Real> CellSink<T> for Cells<'_> {
    fn cell(&mut self, j: usize, i: usize, c: &CellOut<T>) {
        self.o.pushk(self.g, 0, (j * 1000 + i) as f64);
        for (k, v) in [c.pn, c.bound, c.px, c.py, c.sx, c.sy]
            .into_iter()
            .enumerate()
        {
            self.o.pushk(self.g, 1 + k as u8, v.to_f64());
        }
        self.o.pushk(self.g, 7, if c.slip { 1.0 } else { 0.0 });
    }
}

fn totals<T: Real, const S: usize>(o: &mut Out, g: u8, t: &Tangential<T, S>) {
    let tt = &t.total;
    // Forces (kind 1: F_x, F_y, per-strip forces), moment (2), normal force (3), counts (4).
    o.pushk(g, 1, tt.fx.to_f64());
    o.pushk(g, 1, tt.fy.to_f64());
    o.pushk(g, 2, tt.mz.to_f64());
    o.pushk(g, 3, tt.fn_.to_f64());
    o.pushk(g, 4, tt.n_contact as f64);
    o.pushk(g, 4, tt.n_slip as f64);
    for s in t.strips.iter() {
        o.pushk(g, 1, s.fx.to_f64());
        o.pushk(g, 1, s.fy.to_f64());
    }
}

fn elliptic<T: Real>(o: &mut Out, gc: u8, gt: u8) {
    let mat: Material<T> = contact_material();
    let mu = T::from_f64(0.3);
    let creeps: [(f64, f64, f64); 12] = [
        (0.0, -6.25e-4, 6.25e-4),
        (1e-4, 0.0, 0.0),
        (0.0, 2e-4, 0.0),
        (0.0, 0.0, 3e-4),
        (-1e-3, 5e-4, 0.0),
        (2e-3, -3e-3, 2e-4),
        (5e-4, 5e-4, -1e-3),
        (-3e-4, -2e-4, 4e-3),
        (1e-2, 0.0, 0.0),
        (0.0, -1e-2, 1e-3),
        (1e-6, 1e-6, 1e-6),
        (3e-4, 1e-3, -2e-2),
    ];
    for &ab in &[0.2, 0.5, 1.0, 2.0, 5.0] {
        let (b, n) = (4.0, 60_000.0);
        let a = ab * b;
        for ext in [GridExtent::contact(), GridExtent::tight()] {
            let (patch, ell) = StripPatch::<T, 32, 32>::hertz(
                T::from_f64(a),
                T::from_f64(b),
                T::from_f64(n),
                &mat,
                ext,
            )
            .expect("patch");
            let pr = HertzPressure(ell);
            for &(xi, eta, phi) in &creeps {
                let cr = Creepage {
                    xi: T::from_f64(xi),
                    eta: T::from_f64(eta),
                    phi: T::from_f64(phi),
                };
                for bound in [TractionBound::Elliptic, TractionBound::Parabolic(ell)] {
                    for rule in [
                        SlipRule::Clip,
                        SlipRule::Coulomb,
                        SlipRule::CoulombRigidSlip,
                    ] {
                        let set = FastsimSettings::with_slip(mu, bound, rule);
                        o.case();
                        let t = fastsim(&patch, &pr, &cr, &set, &mut Cells { o, g: gc })
                            .expect("fastsim");
                        totals(o, gt, &t);
                        let t2 = fastsim(&patch, &pr, &cr, &set, &mut ()).expect("fastsim");
                        totals(o, gt, &t2);
                    }
                }
                let mut sets = vec![
                    FastripSettings::new(mu),
                    FastripSettings::spec_clip(mu),
                    FastripSettings::contact_m6(mu, ell, LambdaVariant::StripTheory),
                    FastripSettings::contact_m6(mu, ell, LambdaVariant::ContactCompat),
                ];
                let mut s = FastripSettings::new(mu);
                s.large_spin = LargeSpin::FullSlip;
                sets.push(s);
                s.bound_check = BoundCheck::Local;
                sets.push(s);
                let mut s = FastripSettings::new(mu);
                s.direction.slip = SlipRule::Coulomb;
                sets.push(s);
                for set in &sets {
                    o.case();
                    let t =
                        fastrip(&patch, &pr, &cr, set, &mut Cells { o, g: gc }).expect("fastrip");
                    totals(o, gt, &t);
                    let t2 = fastrip(&patch, &pr, &cr, set, &mut ()).expect("fastrip");
                    totals(o, gt, &t2);
                }
                let mut p5 = patch;
                let eq = p5
                    .modified_fastrip_reference(&pr, T::from_f64(n))
                    .expect("m5");
                for lam in [LambdaVariant::StripTheory, LambdaVariant::ContactCompat] {
                    let set = FastripSettings::contact_m5(
                        mu,
                        T::from_f64(a),
                        T::from_f64(b),
                        T::from_f64(n),
                        eq,
                        lam,
                    );
                    o.case();
                    let t = fastrip(&p5, &pr, &cr, &set, &mut Cells { o, g: gc }).expect("m5");
                    totals(o, gt, &t);
                }
            }
        }
    }
}

fn wheel<T: Real>(o: &mut Out, g: u8) {
    let pair = wrc_bench::tables::<T>();
    let pair64 = wrc_bench::tables::<f64>();
    let cases = wrc_bench::sweep(&pair64);
    let (w, r) = (&*pair.0, &*pair.1);
    let mat = Material::<T>::steel();
    let v = T::from_f64(100.0 / 3.6 * 1000.0);
    let cfg = WheelConfig::recommended(T::from_f64(0.3), v, T::from_f64(460.0));
    let mut ws = Box::new(DefaultWheelWorkspace::<T>::new());
    for cs in &cases {
        o.case();
        let f = T::from_f64;
        let st = &cs.setup;
        let setup = TrackSetup {
            gauge: f(st.gauge),
            gauge_depth: f(st.gauge_depth),
            back_to_back: f(st.back_to_back),
            flange_back_pos: f(st.flange_back_pos),
            r0: f(st.r0),
            cant: f(st.cant),
        };
        let pose = WheelsetPose {
            dy: f(cs.pose.dy),
            yaw: f(cs.pose.yaw),
            roll: f(cs.pose.roll),
        };
        let Ok(geo) =
            WheelRail::<T, 2048, 2048>::place(r, w, &setup, &pose, cs.side, T::from_f64(0.05))
        else {
            o.push(g, -1.0);
            continue;
        };
        match solve_wheel(&geo, T::from_f64(83_300.0), &mat, &cfg, &mut ws, &mut ()) {
            Ok(res) => {
                // kinds: approach 0, counts 1, loads 2, forces 3, moment 4, pmax 5, area 6,
                // wear 7.
                o.pushk(g, 0, res.vertical_approach.to_f64());
                o.pushk(g, 1, res.coupling_rounds as f64);
                for p in res.patches.iter() {
                    o.pushk(g, 2, p.load.to_f64());
                    let t = &p.result.totals;
                    o.pushk(g, 3, t.fx.to_f64());
                    o.pushk(g, 3, t.fy.to_f64());
                    o.pushk(g, 4, t.mz.to_f64());
                    o.pushk(g, 5, p.result.pmax.to_f64());
                    o.pushk(g, 6, p.result.area.to_f64());
                    o.pushk(g, 1, t.n_slip as f64);
                    for rg in p.result.regions.iter() {
                        o.pushk(g, 3, rg.totals.fx.to_f64());
                        o.pushk(g, 3, rg.totals.fy.to_f64());
                        o.pushk(g, 7, rg.wear_max.to_f64());
                    }
                }
            }
            Err(_) => o.push(g, -2.0),
        }
    }
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.first().map(|s| s.as_str()) {
        Some("write") => {
            let mut o = Out { vals: vec![] };
            elliptic::<f64>(&mut o, 0, 1);
            elliptic::<f32>(&mut o, 2, 3);
            wheel::<f64>(&mut o, 4);
            wheel::<f32>(&mut o, 5);
            let mut f = std::io::BufWriter::new(std::fs::File::create(&args[1]).expect("create"));
            for (g, v) in &o.vals {
                f.write_all(&[*g]).expect("write");
                f.write_all(&v.to_le_bytes()).expect("write");
            }
            println!("{} values written", o.vals.len());
        }
        Some("compare") => {
            let read = |p: &str| {
                let mut b = vec![];
                std::fs::File::open(p)
                    .expect("open")
                    .read_to_end(&mut b)
                    .expect("read");
                b.chunks_exact(9)
                    .map(|c| {
                        let mut x = [0u8; 8];
                        x.copy_from_slice(&c[1..]);
                        (c[0], f64::from_le_bytes(x))
                    })
                    .collect::<Vec<_>>()
            };
            let (a, b) = (read(&args[1]), read(&args[2]));
            if a.len() != b.len() {
                println!("different lengths: {} vs {}", a.len(), b.len());
            }
            // Scale of each value: the largest |old| of its kind in its case.
            let mut scale = vec![0.0f64; a.len()];
            let mut k0 = 0;
            while k0 < a.len() {
                let mut k1 = k0 + 1;
                while k1 < a.len() && a[k1].0 != 255 {
                    k1 += 1;
                }
                let mut mx = [0.0f64; 256];
                for x in &a[k0..k1] {
                    mx[x.0 as usize] = mx[x.0 as usize].max(x.1.abs());
                }
                for (k, x) in a[k0..k1].iter().enumerate() {
                    let t = x.0 as usize;
                    // Totals: forces and moment also at least relative to the normal force
                    // (zero by symmetry in many cases).
                    let floor = if t / 16 == 1 || t / 16 == 3 {
                        mx[(t / 16) * 16 + 3]
                    } else {
                        0.0
                    };
                    scale[k0 + k] = if t % 16 == 1 || t % 16 == 2 {
                        mx[t].max(floor)
                    } else {
                        mx[t]
                    };
                }
                k0 = k1;
            }
            for (gi, name) in GROUPS.iter().enumerate() {
                let (mut n, mut ndiff, mut rel, mut sc) = (0, 0, 0.0f64, 0.0f64);
                let mut worst = (0usize, 0u8, 0.0, 0.0);
                for (k, (x, y)) in a.iter().zip(b.iter()).enumerate() {
                    if x.0 == 255 || (x.0 / 16) as usize != gi {
                        continue;
                    }
                    n += 1;
                    if x.1.to_bits() != y.1.to_bits() {
                        ndiff += 1;
                        let d = (x.1 - y.1).abs();
                        rel = rel.max(d / x.1.abs().max(y.1.abs()));
                        let r = d / scale[k];
                        if r > sc {
                            sc = r;
                            worst = (k, x.0 % 16, x.1, y.1);
                        }
                    }
                }
                println!(
                    "{name}: {n} values, {ndiff} differ; max |Δ|/(largest |value| of its kind in its case) {sc:.3e} \
                     (#{} kind {}: {:e} → {:e}); max plain relative {rel:.3e}",
                    worst.0, worst.1, worst.2, worst.3
                );
            }
        }
        _ => eprintln!("usage: tangential_digest write <file> | compare <old> <new>"),
    }
}
