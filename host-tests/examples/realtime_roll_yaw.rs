//! How much roll (about the equilibrium roll) and yaw move the contact and its forces: the
//! measurement behind the contact table's roll mapping and the step's first-order yaw
//! (docs/realtime.md, "Roll and yaw"). The converged per-wheel solver (`solve_wheel`) on
//! S1002/UIC60, right wheel, at 80 kN, nominal rolling at 100 km/h, μ 0.3, dy −11 … 11 mm in
//! 0.5 mm steps: per shift the change of the most loaded patch's rail contact point (mm), rolling
//! radius (mm), contact angle (mrad), pmax and area (%) and, for roll, of the total creep force
//! (% of μF_z) at roll = equilibrium ± 2 and ± 5 mrad and at yaw ± 10 mrad, and what the plain
//! equivalent shift R·Δθ (R = 460 mm) leaves at ±5 mrad.
//!
//! Run: `cargo run --release -p wrc-host-tests --example realtime_roll_yaw [BACK_TO_BACK]`
//! (default 1353 mm).

use wrc_host_tests::realtime::{R0, SPEED};
use wrc_host_tests::wheelrail::{tables, Table, NODES};
use wrc_kernel::geometry::{equilibrium_roll, Side, TrackSetup, WheelRail, WheelsetPose};
use wrc_kernel::wheel::{solve_wheel, DefaultWheelWorkspace, WheelConfig};
use wrc_kernel::Material;

/// The most loaded patch's frame and the totals of one solve.
#[derive(Clone, Copy, Default)]
struct Contact {
    y_rail: f64,
    radius: f64,
    angle: f64,
    pmax: f64,
    area: f64,
    fx: f64,
    fy: f64,
}

/// Solves at shift `dy`, the equilibrium roll + `d_roll`, `yaw`; `None` where the geometry or
/// the solver fails.
fn solve(
    w: &Table,
    r: &Table,
    setup: &TrackSetup<f64>,
    dy: f64,
    yaw: f64,
    d_roll: f64,
) -> Option<Contact> {
    let roll = equilibrium_roll::<f64, NODES, NODES>(r, w, setup, dy, 0.0, 0.05)
        .ok()?
        .roll
        + d_roll;
    let pose = WheelsetPose { dy, yaw, roll };
    let g = WheelRail::<f64, NODES, NODES>::place(r, w, setup, &pose, Side::Right, 0.05).ok()?;
    let cfg = WheelConfig::recommended(0.3, SPEED, R0);
    let mut ws = Box::new(DefaultWheelWorkspace::<f64>::new());
    let res = solve_wheel(&g, 80_000.0, &Material::steel(), &cfg, &mut ws, &mut ()).ok()?;
    let mut c = Contact::default();
    let mut most = 0.0;
    for p in res.patches.iter() {
        c.fx += p.result.totals.fx;
        c.fy += p.result.totals.fy;
        c.pmax = c.pmax.max(p.result.pmax);
        c.area += p.result.area;
        if p.load > most {
            most = p.load;
            c.y_rail = p.frame.y_ref_rail;
            c.radius = p.frame.rolling_radius;
            c.angle = p.frame.angle;
        }
    }
    Some(c)
}

/// The change from `a` to `b`: rail point, rolling radius, angle (mrad), pmax and area (%),
/// force (% of μF_z at 80 kN, μ 0.3).
fn change(a: &Contact, b: &Contact) -> String {
    format!(
        "y {:+6.2} r {:+6.3} δ {:+6.1} pmax {:+5.1} area {:+5.1} F {:5.1}",
        b.y_rail - a.y_rail,
        b.radius - a.radius,
        (b.angle - a.angle) * 1e3,
        (b.pmax / a.pmax - 1.0) * 100.0,
        (b.area / a.area - 1.0) * 100.0,
        (b.fx - a.fx).hypot(b.fy - a.fy) / (0.3 * 80_000.0) * 100.0
    )
}

fn main() {
    let b2b: f64 = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(1353.0);
    let (w, r) = tables().expect("built-in profiles");
    let setup = TrackSetup {
        back_to_back: b2b,
        ..TrackSetup::standard()
    };
    println!(
        "S1002/UIC60 {b2b} mm, right wheel, 80 kN; changes against the equilibrium roll, yaw 0"
    );
    for q in 0..=44 {
        let dy = -11.0 + 0.5 * q as f64;
        let Some(base) = solve(&w, &r, &setup, dy, 0.0, 0.0) else {
            println!("dy {dy:+5.1}: no solution");
            continue;
        };
        println!("dy {dy:+5.1} (angle {:.3} rad):", base.angle);
        for d_roll in [-5e-3, -2e-3, 2e-3, 5e-3] {
            let Some(rolled) = solve(&w, &r, &setup, dy, 0.0, d_roll) else {
                continue;
            };
            print!(
                "  roll {:+.0} mrad: {}",
                d_roll * 1e3,
                change(&base, &rolled)
            );
            if d_roll.abs() > 4e-3 {
                // the plain equivalent shift R·Δθ at the equilibrium roll, against the rolled solve
                if let Some(shifted) = solve(&w, &r, &setup, dy + R0 * d_roll, 0.0, 0.0) {
                    print!("  | R·Δθ shift leaves {}", change(&rolled, &shifted));
                }
            }
            println!();
        }
        for yaw in [-0.01, 0.01] {
            // (the creep force's change with yaw is the yaw creepage's, which the step computes)
            if let Some(yawed) = solve(&w, &r, &setup, dy, yaw, 0.0) {
                let c = change(&base, &yawed);
                let geometry = c.split(" F ").next().unwrap_or(&c);
                println!("  yaw {:+.0} mrad: {geometry}", yaw * 1e3);
            }
        }
    }
}
