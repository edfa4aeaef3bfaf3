//! Isosceles-pairs correspondence (seed B; methods.md §7.5 item 3).
//!
//! A rail point A and a wheel point B correspond when the tangents at A and B and the segment AB
//! form an isosceles triangle with its apex at the tangents' crossing point. With both curves
//! traversed in the same lateral sense (increasing y), unit tangents T_A, T_B and d = B − A:
//! θ_A = arccos(d·T_A/|d|), θ_B = arccos(−d·T_B/|d|), θ_c = (θ_A + θ_B)/2, Δθ = θ_A − θ_B; the
//! pair is isosceles iff Δθ = 0.
//!
//! Traversal (seed B §3.2), as implemented:
//! * **Stepping**: both points advance by the same arc length h along their curves. Here h is
//!   chosen so that the pair's midpoint lands on the next sample of the patch's uniform s grid
//!   (s = tangential coordinate of the midpoint in the patch frame): h = Δs / c with
//!   c = σ·½(T_A + T_B)·t̂. The first pair starts from the projection pair of the first sample.
//! * **Correction** (seed eqs. 2–5): the curves are replaced by their tangent lines and A moves by
//!   Δ = −(|d|/2)·sin(Δθ/2)/sin θ_c along Γ_rail, B by −Δ along Γ_wheel; repeated until
//!   |Δθ| < 1e-10 rad (f64; 1e-5 for f32) or |d| < 1e-12 mm, at most 20 times.
//! * A second stepping + correction pass (at most 6) puts the midpoint on the sample within
//!   1e-9 mm.
//!
//! Per sample: separation ±|d| (negative when B is inside the rail, i.e. d·n_A < 0), the wheel's
//! tilt and radius at B, B curvature from both points, and the strip width = arc-length increment
//! of the midpoint curve per ds, ds/|cos α| with α the angle between the midpoint curve and the
//! tangent plane (seed eq. 16).
//!
//! The rigid contact pair is the pair with θ_c = 90° inside the penetrated zone
//! ([`isosceles_rigid_pair`]): the sign change of θ_c − 90° between consecutive samples is refined
//! by bisection on s; its contact angle is the direction of d (the common normal).

use super::patch::{FrameS, PatchSamples};
use super::placement::{PlacedRail, PlacedWheel, WheelRail};
use crate::{math, Error, Real};

/// One isosceles pair.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct IsoscelesPair<T> {
    /// Rail curve parameter of A.
    pub t_rail: T,
    /// Wheel curve parameter of B.
    pub t_wheel: T,
    /// Signed separation ±|AB|, mm (negative when B is inside the rail).
    pub separation: T,
    /// θ_c = (θ_A + θ_B)/2, rad.
    pub theta_c: T,
    /// Remaining Δθ = θ_A − θ_B, rad.
    pub delta_theta: T,
    /// Tangential coordinate s of the midpoint in the patch frame, mm.
    pub s_mid: T,
    /// Tilt of the common normal −d/|d| (contact-angle sign, track frame), rad; meaningful where
    /// |d| > 0.
    pub normal_angle: T,
    /// Correction iterations of the last sample.
    pub iterations: usize,
}

struct Ctx<'r, 'a, T, const N: usize> {
    rail: &'r PlacedRail<'a, T, N>,
    wheel: &'r PlacedWheel<'a, T, N>,
    fr: &'r FrameS<T>,
}

impl<T: Real, const N: usize> Ctx<'_, '_, T, N> {
    fn clamp_r(&self, t: T) -> T {
        math::clamp(t, T::ZERO, self.rail.table.t_max())
    }
    fn clamp_w(&self, t: T) -> T {
        math::clamp(t, T::ZERO, self.wheel.table.t_max())
    }

    /// Evaluates the pair (tr, tw).
    fn eval(&self, tr: T, tw: T) -> IsoscelesPair<T> {
        let a = self.rail.at_local(tr);
        let b = self.wheel.at_local(tw);
        let (dy, dz) = (b.y - a.y, b.z - a.z);
        let dl = math::hypot(dy, dz);
        let (ta_y, ta_z) = (math::cos(a.angle), math::sin(a.angle));
        let (tb_y, tb_z) = (math::cos(b.angle), math::sin(b.angle));
        let (theta_a, theta_b) = if dl > T::ZERO {
            (
                math::acos(math::clamp((dy * ta_y + dz * ta_z) / dl, -T::ONE, T::ONE)),
                math::acos(math::clamp(-(dy * tb_y + dz * tb_z) / dl, -T::ONE, T::ONE)),
            )
        } else {
            (T::PI * T::HALF, T::PI * T::HALF)
        };
        // normal of the rail at A (upwards, into the wheel)
        let na = -dy * ta_z + dz * ta_y;
        let sep = if na < T::ZERO { -dl } else { dl };
        let (my, mz) = ((a.y + b.y) * T::HALF, (a.z + b.z) * T::HALF);
        let normal_angle = if dl > T::ZERO {
            // common normal pointing into the wheel: +d when separated, −d when penetrating
            let (ny, nz) = if sep < T::ZERO { (-dy, -dz) } else { (dy, dz) };
            math::atan2(-ny, nz)
        } else {
            a.angle
        };
        IsoscelesPair {
            t_rail: tr,
            t_wheel: tw,
            separation: sep,
            theta_c: (theta_a + theta_b) * T::HALF,
            delta_theta: theta_a - theta_b,
            s_mid: self.fr.s(my, mz),
            normal_angle,
            iterations: 0,
        }
    }

    /// Correction iterations from (tr, tw).
    fn correct(&self, mut tr: T, mut tw: T) -> IsoscelesPair<T> {
        let tol = if T::EPSILON < math::c(1e-10) {
            math::c::<T>(1e-10)
        } else {
            math::c::<T>(1e-5)
        };
        let hr = self.rail.table.ds;
        let hw = self.wheel.table.ds;
        let mut p = self.eval(tr, tw);
        let mut it = 0;
        for i in 0..20 {
            it = i;
            let a = self.rail.at_local(tr);
            let b = self.wheel.at_local(tw);
            let dl = math::hypot(b.y - a.y, b.z - a.z);
            if math::abs(p.delta_theta) < tol || dl < math::c(1e-12) {
                break;
            }
            let st = math::sin(p.theta_c);
            if math::abs(st) < math::c(1e-6) {
                break;
            }
            let delta = -(dl * T::HALF) * math::sin(p.delta_theta * T::HALF) / st;
            tr = self.clamp_r(tr + delta / hr);
            tw = self.clamp_w(tw - delta / hw);
            p = self.eval(tr, tw);
            it = i + 1;
        }
        p.iterations = it;
        p
    }

    /// Stepping factor c = σ·½(T_A + T_B)·t̂ (ds_mid / dh).
    fn step_factor(&self, tr: T, tw: T) -> T {
        let a = self.rail.at_local(tr);
        let b = self.wheel.at_local(tw);
        let my = (math::cos(a.angle) + math::cos(b.angle)) * T::HALF;
        let mz = (math::sin(a.angle) + math::sin(b.angle)) * T::HALF;
        self.fr.sigma * (my * self.fr.c + mz * self.fr.sn)
    }

    /// Steps and corrects until the midpoint sits at `s` (bounded).
    fn pair_at(&self, mut tr: T, mut tw: T, s: T) -> IsoscelesPair<T> {
        let hr = self.rail.table.ds;
        let hw = self.wheel.table.ds;
        let mut p = self.correct(tr, tw);
        for _ in 0..8 {
            let err = s - p.s_mid;
            if math::abs(err) < math::c(1e-9) {
                break;
            }
            let c = self.step_factor(p.t_rail, p.t_wheel);
            if math::abs(c) < math::c(1e-3) {
                break;
            }
            let h = err / c;
            tr = self.clamp_r(p.t_rail + h / hr);
            tw = self.clamp_w(p.t_wheel + h / hw);
            p = self.correct(tr, tw);
        }
        p
    }
}

/// Signed separation of the isosceles pair whose midpoint lies at `s` (None if not found).
pub(crate) fn separation_at<T: Real, const N: usize>(
    rail: &PlacedRail<'_, T, N>,
    wheel: &PlacedWheel<'_, T, N>,
    fr: &FrameS<T>,
    tr_ref: T,
    tw_ref: T,
    s: T,
) -> Option<T> {
    let ctx = Ctx { rail, wheel, fr };
    let rpos = |t: T| {
        let p = rail.at_local(t);
        (p.y, p.z)
    };
    let wpos = |t: T| {
        let p = wheel.at_local(t);
        (p.y, p.z)
    };
    let tr = super::patch::solve_s(&rpos, fr, rail.table.len, tr_ref, s)?;
    let tw = super::patch::solve_s(&wpos, fr, wheel.table.len, tw_ref, s)?;
    let p = ctx.pair_at(tr, tw, s);
    if math::abs(p.s_mid - s) > math::c::<T>(1e-6) {
        return None;
    }
    Some(p.separation)
}

/// Fills the samples of `out` (n, s0, ds already set) with isosceles pairs.
pub(crate) fn sample_isosceles<T: Real, const N: usize, const S: usize>(
    rail: &PlacedRail<'_, T, N>,
    wheel: &PlacedWheel<'_, T, N>,
    fr: &FrameS<T>,
    tr_ref: T,
    tw_ref: T,
    x_ref: T,
    out: &mut PatchSamples<T, S>,
) -> Result<(), Error> {
    let ctx = Ctx { rail, wheel, fr };
    let rpos = |t: T| {
        let p = rail.at_local(t);
        (p.y, p.z)
    };
    let wpos = |t: T| {
        let p = wheel.at_local(t);
        (p.y, p.z)
    };
    let s_first = out.s(0);
    let tr0 = super::patch::solve_s(&rpos, fr, rail.table.len, tr_ref, s_first)
        .ok_or(Error::NoContact)?;
    let tw0 = super::patch::solve_s(&wpos, fr, wheel.table.len, tw_ref, s_first)
        .ok_or(Error::NoContact)?;
    let (mut tr, mut tw) = (tr0, tw0);
    for i in 0..out.n.min(S) {
        let s = out.s(i);
        let p = ctx.pair_at(tr, tw, s);
        if math::abs(p.s_mid - s) > math::c::<T>(1e-3) * math::max(out.ds, T::ONE) {
            return Err(Error::NoContact);
        }
        tr = p.t_rail;
        tw = p.t_wheel;
        let a = rail.at_local(tr);
        let b = wheel.at_local(tw);
        out.f_n[i] = p.separation;
        out.angle[i] = b.angle;
        out.radius[i] = b.radius;
        out.a_long[i] = math::cos(b.angle) / (T::TWO * b.radius);
        out.b_lat[i] = T::HALF * (a.curvature + b.curvature);
        let c = ctx.step_factor(tr, tw);
        let my = (math::cos(a.angle) + math::cos(b.angle)) * T::HALF;
        let mz = (math::sin(a.angle) + math::sin(b.angle)) * T::HALF;
        let m = math::hypot(my, mz);
        out.width[i] = if math::abs(c) > math::c(1e-6) {
            out.ds * m / math::abs(c)
        } else {
            out.ds
        };
        out.y_rail[i] = a.y + rail.y_origin();
        out.x_c[i] = b.x - x_ref;
    }
    Ok(())
}

/// The rigid contact pair (θ_c = 90°) of a patch by isosceles traversal at vertical approach
/// `dv`, searched over s ∈ [s_lo, s_hi] in `steps` equal steps (the seed's 0.5/0.1 mm arc steps
/// correspond to steps = width/0.5 or width/0.1), refined by 40 bisections on s. Only pairs with
/// negative separation (inside the penetrated zone) qualify; θ_c = 90° holds at every extremum of
/// the separation, so of all such crossings the deepest one is returned.
///
/// Returns the pair; its `normal_angle` is the isosceles contact angle and the rail point A is
/// `geom.rail.at(pair.t_rail)`. Errors: `NoContact` if no sign change is found.
pub fn isosceles_rigid_pair<T: Real, const N: usize, const M: usize>(
    geom: &WheelRail<'_, T, N, M>,
    frame: &super::patch::PatchFrame<T>,
    s_lo: T,
    s_hi: T,
    steps: usize,
) -> Result<IsoscelesPair<T>, Error> {
    if steps < 2 || !math::is_finite(s_hi - s_lo) || s_hi <= s_lo {
        return Err(Error::OutOfRange("isosceles search range"));
    }
    let fr = FrameS::new(geom, frame);
    let wheel = geom.wheel.lowered(frame.approach_vertical);
    let rail = geom.rail;
    let ctx = Ctx {
        rail: &rail,
        wheel: &wheel,
        fr: &fr,
    };
    let rpos = |t: T| {
        let p = rail.at_local(t);
        (p.y, p.z)
    };
    let wpos = |t: T| {
        let p = wheel.at_local(t);
        (p.y, p.z)
    };
    let y_ref = fr.py;
    let tr0 = super::patch::solve_s(
        &rpos,
        &fr,
        rail.table.len,
        geom.rail_t_at_local(y_ref),
        s_lo,
    )
    .ok_or(Error::NoContact)?;
    let tw0 = super::patch::solve_s(
        &wpos,
        &fr,
        wheel.table.len,
        geom.wheel_t_at_local(y_ref),
        s_lo,
    )
    .ok_or(Error::NoContact)?;
    let half_pi = T::PI * T::HALF;
    let ds = (s_hi - s_lo) / T::from_usize(steps);
    let mut prev = ctx.pair_at(tr0, tw0, s_lo);
    let mut best: Option<IsoscelesPair<T>> = None;
    for i in 1..=steps {
        let s = s_lo + T::from_usize(i) * ds;
        let p = ctx.pair_at(prev.t_rail, prev.t_wheel, s);
        let (fa, fb) = (prev.theta_c - half_pi, p.theta_c - half_pi);
        if prev.separation < T::ZERO && p.separation < T::ZERO && (fa <= T::ZERO) != (fb <= T::ZERO)
        {
            // bisection on s
            let (mut a, mut b) = (prev, p);
            let (mut sa, mut sb) = (s - ds, s);
            for _ in 0..40 {
                let sm = (sa + sb) * T::HALF;
                let m = ctx.pair_at(a.t_rail, a.t_wheel, sm);
                if ((m.theta_c - half_pi) <= T::ZERO) == ((a.theta_c - half_pi) <= T::ZERO) {
                    a = m;
                    sa = sm;
                } else {
                    b = m;
                    sb = sm;
                }
            }
            let _ = b;
            // θ_c = 90° at every extremum of the separation: keep the deepest
            match best {
                Some(q) if q.separation <= a.separation => {}
                _ => best = Some(a),
            }
        }
        prev = p;
    }
    best.ok_or(Error::NoContact)
}
