//! Longitudinal creepage of a centred wheelset against CONTACT module 1 (issue 17.1).
//!
//! Set-up: S1002 on UIC60 (the Manchester profiles, wrc's defaults), back-to-back 1353 mm, right
//! wheel, dy = 0, yaw 0, V = 200 km/h, pitch rate |Ω| = V / 460 mm, `Normalisation::Mean`.
//! CONTACT (module 1, `m_wr_rigslip.f90`) gives ξ_C = −4.623e-4 at F_z = 83.3 kN (its approach
//! 0.0889 mm) and −4.577e-4 at 120 kN (approach 0.1132 mm).
//!
//! Sign mapping (methods.md §0.2, §7.4): CONTACT's module 1 has Ω = −V/460 for forward rolling
//! and ξ_C = (v_rail − v_wheel)/V_ref; wrc has Ω = +V/460 for forward rolling and
//! ξ = (v_wheel − v_rail)/V_ref, so ξ_wrc = −ξ_C with the same |Ω|.

use wrc_host_tests::wheelrail::{tables, NODES};
use wrc_kernel::geometry::{Normalisation, Side, TrackSetup, WheelRail, WheelsetPose};
use wrc_kernel::wheel::{solve_wheel, DefaultWheelWorkspace, WheelConfig};
use wrc_kernel::Material;

/// ξ (wrc sign), the normal approach and the rolling radius of the main patch at vertical load
/// `fz` (N).
fn xi_at(fz: f64) -> (f64, f64, f64) {
    let (w, r) = tables().unwrap();
    let setup = TrackSetup {
        back_to_back: 1353.0,
        ..TrackSetup::standard()
    };
    let pose = WheelsetPose::from_contact(0.0, 0.0, 0.0);
    let g =
        WheelRail::<f64, NODES, NODES>::place(&*r, &*w, &setup, &pose, Side::Right, 0.05).unwrap();
    let mat = Material::<f64>::identical(205_900.0, 0.28).unwrap();
    let speed = 200.0 / 3.6 * 1e3;
    let mut cfg = WheelConfig::recommended(0.3, speed, 460.0);
    cfg.kinematics.normalisation = Normalisation::Mean;
    let mut ws = Box::new(DefaultWheelWorkspace::<f64>::new());
    let res = solve_wheel(&g, fz, &mat, &cfg, &mut ws, &mut ()).unwrap();
    assert!(res.converged, "F_z {fz}");
    let main = res
        .patches
        .iter()
        .max_by(|a, b| a.load.total_cmp(&b.load))
        .unwrap();
    (
        main.creepage.xi,
        main.frame.approach,
        main.frame.rolling_radius,
    )
}

/// ξ of a lever arm equal to the rolling radius `r` (Ω = V/460, V_ref = (V + ΩR)/2).
fn xi_of_radius(r: f64) -> f64 {
    let b = r / 460.0;
    2.0 * (1.0 - b) / (1.0 + b)
}

/// ξ within 0.5 % of CONTACT at 83.3 and 120 kN (measured 0.02 %), and nearly load-independent.
///
/// Tolerance: ξ = 1 − R_eff/R0 is the difference of two radii ≈ 460 mm, so a 1 % error in ξ is
/// a 2 µm error in the lever arm, so 0.5 % is 1 µm. What remains after evaluating the wheel velocity on the wheel
/// surface (as CONTACT does) is the geometry of the reference point (wrc's weighted y_ref vs
/// CONTACT's, and the profile smoothing: the S1002 tread has dR/dy ≈ 0.05, so 0.02 mm in y_ref is
/// 1e-3 mm in R, 0.2 % of ξ) and wrc's own approach vs CONTACT's, which enters only through the
/// reference point. The old evaluation at the rail point with the loaded centre was off by
/// approach/R0 ≈ 1.9e-4 (+42 %) at 83.3 kN.
#[test]
fn centred_xi_matches_contact_module_1() {
    let cases = [(83_300.0, 4.623e-4, 0.0889), (120_000.0, 4.577e-4, 0.1132)];
    for (fz, xi_c, pen_c) in cases {
        let (xi, pen, rr) = xi_at(fz);
        let e = (xi / xi_c - 1.0) * 100.0;
        println!(
            "F_z {fz}: xi {xi:.5e} vs CONTACT {xi_c:.4e} ({e:+.2} %), approach {pen:.4} vs \
             {pen_c}, R {rr:.4}, xi(R) {:.5e}",
            xi_of_radius(rr)
        );
        assert!(
            e.abs() <= 0.5,
            "F_z {fz}: xi {xi} vs CONTACT {xi_c} ({e:+.2} %)"
        );
    }
    // The lever arm is the wheel's rolling radius at the paired point, not that radius minus
    // the approach: ξ equals 1 − R/R0 (V_ref-normalised) to 0.5 % of ξ (1 µm in the lever arm;
    // measured 0.17 % and 0.29 % at 83.3 and 120 kN: the paired wheel point lies `approach`
    // below P only up to the separation f_n at the weighted reference point, which is not the
    // deepest point — CONTACT uses the approach too) at every load, and ξ changes
    // between 1 and 120 kN only by the move of the reference point (the old evaluation moved it
    // by approach/R0: 1.2e-5 → 2.4e-4, about 50 %).
    let (x1, _, r1) = xi_at(1_000.0);
    let (x120, _, r120) = xi_at(120_000.0);
    println!("1 kN: xi {x1:.5e} (R {r1:.4}); 120 kN: {x120:.5e} (R {r120:.4})");
    for (x, r) in [(x1, r1), (x120, r120)] {
        assert!(
            (x / xi_of_radius(r) - 1.0).abs() <= 5e-3,
            "xi {x} vs 1 − R/R0 {}",
            xi_of_radius(r)
        );
    }
    assert!(
        (x120 / x1 - 1.0).abs() <= 0.05,
        "xi 1 kN {x1} vs 120 kN {x120}"
    );
}
