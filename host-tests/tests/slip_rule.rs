//! The slip rule of FASTSIM's slipping cells (`SlipRule`, methods.md §3.3) and FaStrip's default
//! direction pass: at full slip the creep force must point against the rigid slip with magnitude
//! μF_n (methods.md §10.7; exact theory: p = −μp_n s/|s|, s → w as the creepage grows).
//! `Clip` (seed A, CONTACT) saturates along (ξ/L1, η/L2) instead; the Hertzian-matrix study
//! (`study-hertz`, README) measures what that costs against TANG.

use wrc_kernel::fastrip::{fastrip, FastripSettings};
use wrc_kernel::fastsim::{fastsim, FastsimSettings, SlipRule};
use wrc_kernel::patch::{Creepage, GridExtent, HertzPressure, StripPatch, TractionBound};
use wrc_kernel::Material;

const N: f64 = 82_000.0;
const MU: f64 = 0.3;

/// Angle (deg) between the force and −(ξ, η), and |F|/(μN), for a Hertz patch a × b.
fn direction_error(a: f64, b: f64, alpha_deg: f64, model: &str) -> (f64, f64) {
    let mat = Material::from_g_nu(82_000.0, 0.28).unwrap();
    let (patch, ell): (StripPatch<f64, 32, 32>, _) =
        StripPatch::hertz(a, b, N, &mat, GridExtent::contact()).unwrap();
    let pr = HertzPressure(ell);
    let al = alpha_deg.to_radians();
    // 12 × the saturation creepage scale μc/ρ of methods.md §10.10 (ρ ≈ 600 mm here): deep full slip.
    let m = 0.05;
    let cr = Creepage {
        xi: m * al.cos(),
        eta: m * al.sin(),
        phi: 0.0,
    };
    let t = match model {
        "clip" => {
            let s = FastsimSettings::canonical(MU, TractionBound::Elliptic);
            fastsim(&patch, &pr, &cr, &s, &mut ()).unwrap().total
        }
        "coulomb" => {
            let s = FastsimSettings::with_slip(MU, TractionBound::Elliptic, SlipRule::Coulomb);
            fastsim(&patch, &pr, &cr, &s, &mut ()).unwrap().total
        }
        "rigid" => {
            let s =
                FastsimSettings::with_slip(MU, TractionBound::Elliptic, SlipRule::CoulombRigidSlip);
            fastsim(&patch, &pr, &cr, &s, &mut ()).unwrap().total
        }
        _ => {
            fastrip(&patch, &pr, &cr, &FastripSettings::new(MU), &mut ())
                .unwrap()
                .total
        }
    };
    let ang = (t.fy.atan2(t.fx) - (-cr.eta).atan2(-cr.xi)).to_degrees();
    let ang = (ang + 180.0).rem_euclid(360.0) - 180.0;
    (ang.abs(), t.fx.hypot(t.fy) / (MU * t.fn_))
}

/// Coulomb rules and the FaStrip default: direction within 0.05° and magnitude within 0.5 % of
/// μF_n for a/b = 0.2, 1, 5 and creepage directions 30°, 60°. `Clip` misses the direction by
/// 3–10° on a/b = 0.2 (L1 ≠ L2), which is why it is no longer FaStrip's direction pass.
#[test]
fn full_slip_follows_the_rigid_slip() {
    for (a, b) in [(4.0, 20.0), (9.0, 9.0), (20.0, 4.0)] {
        for alpha in [30.0, 60.0] {
            for model in ["coulomb", "rigid", "fastrip"] {
                let (ang, mag) = direction_error(a, b, alpha, model);
                assert!(ang < 0.05, "{model} a/b={} α={alpha}: {ang}°", a / b);
                assert!((mag - 1.0).abs() < 5e-3, "{model} a/b={}: |F| {mag}", a / b);
            }
        }
    }
    let (ang, _) = direction_error(4.0, 20.0, 60.0, "clip");
    assert!(ang > 3.0, "clip on a/b = 0.2 deviates by {ang}°");
}
