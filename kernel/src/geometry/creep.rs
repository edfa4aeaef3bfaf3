//! Creepages from the wheelset kinematics (methods.md §7.4; signs §0.2).
//!
//! General form: with the contact normal n (into the wheel), e_x = track x (the rolling direction
//! lies in the tangent plane because the normal at the wheel's lowest point has no x component),
//! e_y = n × e_x, the wheel material velocity at the reference point P (relative to the wheelset
//! centre c) is v = v_ws + ω × (P − c), with v_ws = (V, v_lat, 0) and
//! ω = Ω e_axle + ψ̇ e_z + φ̇ e_x, e_axle = (−sin ψ cos φ, cos ψ cos φ, sin φ) in the track frame.
//! Rail at rest (straight track): ξ = v·e_x / V_n, η = v·e_y / V_n, φ = ω·n / V_n.
//! V_n = V (`Normalisation::Forward`, default) or V_ref = (|V| + |Ω R|)/2
//! (`Normalisation::Mean`, CONTACT module 1, `m_wr_rigslip.f90`), R the patch rolling radius.
//! Normal: n = (0, −sin δ, cos δ) for the left wheel, (0, +sin δ, cos δ) for the right wheel,
//! δ the patch contact angle in the track frame (it includes the roll).
//!
//! Where the wheel velocity is taken (CONTACT module 1, `m_wr_rigslip.f90`, point Q; seed A
//! eq. 30 with R the profile's rolling radius at the contact point): the patch reference point
//! P (`x_ref`, `y_ref_track`, `z_ref_track`) lies on the rail surface, which does not move; the
//! wheelset centre is at its loaded position (lowered by `approach_vertical` from touching), so
//! the undeformed wheel interpenetrates the rail and its surface crosses the normal through P a
//! distance `approach` (the patch's normal approach) *below* P. The wheel velocity is evaluated
//! there, at Q = P − approach·n (n into the wheel). The lever arm |Q − c| is then the profile's
//! rolling radius at the wheel point paired with P (`rolling_radius`, exactly so when P is the
//! deepest point of the patch), independent of the load. Evaluating at P itself would shorten
//! the lever arm by the approach and bias ξ by ≈ approach/R0 (≈ 1.9e-4 at 83 kN, 40 % of ξ in
//! centred running on S1002/UIC60, issue 17.1).
//!
//! Seed A's approximation (eq. 30) is [`creepages_seed_a`]. It agrees with the general form to
//! first order in the contact angle; in η the exact kinematics (wheel velocity in the tangent
//! plane) give η ≈ −(Ωρ/V) sin ψ / cos δ instead of −sin ψ cos δ, a factor ≈ 1/cos²δ that is
//! 0.7 % at δ = 0.08 and ×4 at flange contact (δ ≈ 1.06); CONTACT agrees with the general form
//! (mbench, right wheel, y_ws ≥ 6.5 mm: η within 0.05 %).

use super::patch::PatchFrame;
use super::placement::{Side, WheelRail};
use crate::{math, Error, Real};

/// Speed used to normalise the creepages.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Normalisation {
    /// Forward speed V of the wheelset (kernel default, §7.4).
    Forward,
    /// Mean of the forward and circumferential speeds, (|V| + |Ω R|)/2 (CONTACT module 1).
    Mean,
}

/// Wheelset kinematics (track frame T; straight track, rail at rest).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Kinematics<T> {
    /// Forward speed V of the wheelset centre along x_T, mm/s (> 0).
    pub speed: T,
    /// Pitch (spin) rate Ω about the axle, rad/s; positive for forward rolling
    /// (nominal Ω = V / R0, see [`Kinematics::nominal`]).
    pub pitch_rate: T,
    /// Lateral velocity of the wheelset centre along +y_T, mm/s.
    pub lateral_velocity: T,
    /// Yaw rate about +z_T, rad/s.
    pub yaw_rate: T,
    /// Roll rate about +x_T, rad/s.
    pub roll_rate: T,
    /// Normalising speed.
    pub normalisation: Normalisation,
}

impl<T: Real> Kinematics<T> {
    /// Steady forward rolling at speed `v` (mm/s) with Ω = V / R0, no lateral, yaw or roll rates,
    /// normalised by V.
    pub fn nominal(v: T, r0: T) -> Self {
        Kinematics {
            speed: v,
            pitch_rate: v / r0,
            lateral_velocity: T::ZERO,
            yaw_rate: T::ZERO,
            roll_rate: T::ZERO,
            normalisation: Normalisation::Forward,
        }
    }
}

/// Creepages at a patch reference point (§0.2): ξ, η dimensionless, φ in rad/mm.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Creepages<T> {
    /// Longitudinal creepage ξ.
    pub xi: T,
    /// Lateral creepage η.
    pub eta: T,
    /// Spin creepage φ, rad/mm.
    pub phi: T,
}

fn cross<T: Real>(a: [T; 3], b: [T; 3]) -> [T; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn dot<T: Real>(a: [T; 3], b: [T; 3]) -> T {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// Creepages at the reference point of `frame` (a patch of `geom`) by the general form.
///
/// Errors: `NonPositive("speed")`, `NonFinite` for non-finite inputs.
pub fn creepages<T: Real, const N: usize, const M: usize>(
    geom: &WheelRail<'_, T, N, M>,
    frame: &PatchFrame<T>,
    kin: &Kinematics<T>,
) -> Result<Creepages<T>, Error> {
    creepages_at(&geom.pose, geom.side, geom.wheel.cz, frame, kin)
}

/// [`creepages`] from the parts of the placed pair it uses: the wheelset `pose`, the analysed
/// `side`, the wheel centre height `wheel_cz` of the touching position (mm, track frame; the
/// loaded centre is `wheel_cz` − `frame.approach_vertical`) and the patch `frame` (for the
/// real-time step, whose frames come from a contact table).
///
/// Errors: as [`creepages`].
pub fn creepages_at<T: Real>(
    pose: &super::placement::WheelsetPose<T>,
    side: Side,
    wheel_cz: T,
    frame: &PatchFrame<T>,
    kin: &Kinematics<T>,
) -> Result<Creepages<T>, Error> {
    let trig = PoseTrig {
        yaw: (math::sin(pose.yaw), math::cos(pose.yaw)),
        roll: (math::sin(pose.roll), math::cos(pose.roll)),
    };
    let angle = (math::sin(frame.angle), math::cos(frame.angle));
    creepages_trig(pose, &trig, side, wheel_cz, frame, angle, kin)
}

/// Sines and cosines of a wheelset pose's yaw and roll, (sin, cos) each: computed once per call
/// by a caller that evaluates several patches ([`creepages_trig`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PoseTrig<T> {
    /// (sin ψ, cos ψ) of the yaw.
    pub yaw: (T, T),
    /// (sin φ, cos φ) of the roll.
    pub roll: (T, T),
}

/// [`creepages_at`] with the trigonometry given: `trig` of the pose's yaw and roll and `angle`
/// = (sin δ, cos δ) of `frame.angle` (the real-time step computes them once, by series).
///
/// Errors: as [`creepages`].
pub fn creepages_trig<T: Real>(
    pose: &super::placement::WheelsetPose<T>,
    trig: &PoseTrig<T>,
    side: Side,
    wheel_cz: T,
    frame: &PatchFrame<T>,
    angle: (T, T),
    kin: &Kinematics<T>,
) -> Result<Creepages<T>, Error> {
    crate::error::check_positive(kin.speed, "speed")?;
    crate::error::check_finite(kin.pitch_rate, "pitch_rate")?;
    crate::error::check_finite(kin.lateral_velocity, "lateral_velocity")?;
    crate::error::check_finite(kin.yaw_rate, "yaw_rate")?;
    crate::error::check_finite(kin.roll_rate, "roll_rate")?;
    let (spsi, cpsi) = trig.yaw;
    let (sphi, cphi) = trig.roll;
    let axle = [-spsi * cphi, cpsi * cphi, sphi];
    let omega = [
        kin.pitch_rate * axle[0] + kin.roll_rate,
        kin.pitch_rate * axle[1],
        kin.pitch_rate * axle[2] + kin.yaw_rate,
    ];
    let (sd, cd) = angle;
    let n = match side {
        Side::Left => [T::ZERO, -sd, cd],
        Side::Right => [T::ZERO, sd, cd],
    };
    // wheelset centre in T at the loaded position (lowered by δ_v from touching)
    let centre = [T::ZERO, pose.dy, wheel_cz - frame.approach_vertical];
    // Q: the wheel surface point of the loaded (undeformed, interpenetrating) wheel on the normal
    // through the rail reference point P, `approach` below P (see the module docs)
    let pen = frame.approach;
    let q = [
        frame.x_ref - pen * n[0],
        frame.y_ref_track - pen * n[1],
        frame.z_ref_track - pen * n[2],
    ];
    let r = [q[0] - centre[0], q[1] - centre[1], q[2] - centre[2]];
    let wr = cross(omega, r);
    let v = [kin.speed + wr[0], kin.lateral_velocity + wr[1], wr[2]];
    let ex = [T::ONE, T::ZERO, T::ZERO];
    let ey = cross(n, ex);
    let vn = match kin.normalisation {
        Normalisation::Forward => kin.speed,
        Normalisation::Mean => {
            (math::abs(kin.speed) + math::abs(kin.pitch_rate * frame.rolling_radius)) * T::HALF
        }
    };
    let c = Creepages {
        xi: dot(v, ex) / vn,
        eta: dot(v, ey) / vn,
        phi: dot(omega, n) / vn,
    };
    if !(math::is_finite(c.xi) && math::is_finite(c.eta) && math::is_finite(c.phi)) {
        return Err(Error::NonFinite("creepages"));
    }
    Ok(c)
}

/// Seed A eq. (30) (An et al. 2019), in the convention of methods.md §7.4: yaw `psi` about +z_T,
/// roll `roll` about +x_T, `delta` the contact angle **relative to the axle** (left wheel:
/// δ = δ_c − φ_ws; right wheel: δ = δ_c + φ_ws), rolling radius `r`, nominal radius `r0`:
/// ξ = (1 − R/R0) cos ψ; η = −sin ψ cos δ_c; φ = ∓ sin δ / R0 (− left, + right).
pub fn creepages_seed_a<T: Real>(
    side: Side,
    psi: T,
    roll: T,
    delta: T,
    r: T,
    r0: T,
) -> Creepages<T> {
    let delta_c = match side {
        Side::Left => delta + roll,
        Side::Right => delta - roll,
    };
    let spin = math::sin(delta) / r0;
    Creepages {
        xi: (T::ONE - r / r0) * math::cos(psi),
        eta: -math::sin(psi) * math::cos(delta_c),
        phi: match side {
            Side::Left => -spin,
            Side::Right => spin,
        },
    }
}
