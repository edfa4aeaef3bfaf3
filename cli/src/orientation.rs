//! Plausibility of a profile's orientation (contract: docs/cli.md, "Profile files").
//!
//! Profiles are read in CONTACT's canonical coordinates (`data/profiles/PROFILES.md`): mm, y
//! positive towards the field side, z positive downwards. A rail then has its top (smallest z)
//! between its two flanks, both flanks reaching far below it; a wheel has its flange tip (largest
//! z, the largest radius) on the track-centre side (negative y of the tread), the tread and the
//! field-side end far above it. A file in another orientation (y and z swapped, mirrored in y or
//! z, a wheel given as `--rail`) is rejected with the orientation expected, before it can produce
//! a plausible-looking but wrong solution.

use wrc_kernel::profile::ProfileKind;

/// Height (mm) by which the flanks of a rail, or the flange of a wheel, must stand out from the
/// rest of the profile (UIC60: 38 mm, S1002 flange: 28 mm).
const RELIEF_MM: f64 = 10.0;

/// What the canonical orientation of `kind` is, for messages.
pub fn expected(kind: ProfileKind) -> &'static str {
    match kind {
        ProfileKind::Rail => {
            "rail files need y positive towards the field side and z positive downwards: \
             the rail top is the smallest z, both flanks reach far below it (larger z)"
        }
        ProfileKind::Wheel => {
            "wheel files need y positive towards the field side and z positive downwards \
             (z = increase of the rolling radius): the flange tip is the largest z and lies at \
             the negative-y (track-centre) end, the field side at positive y"
        }
    }
}

/// `Err(cause)` if the points (y, z) are not in the canonical orientation of `kind`.
pub fn check(points: &[(f64, f64)], kind: ProfileKind) -> Result<(), String> {
    if points.len() < 4 {
        return Ok(()); // the reader reports too few points
    }
    let mut p = points.to_vec();
    p.sort_by(|a, b| a.0.total_cmp(&b.0));
    let (first, last) = (p[0], p[p.len() - 1]);
    let (kmin, pmin) = p
        .iter()
        .enumerate()
        .min_by(|a, b| a.1 .1.total_cmp(&b.1 .1))
        .map(|(k, q)| (k, *q))
        .unwrap_or((0, first));
    let (kmax, pmax) = p
        .iter()
        .enumerate()
        .max_by(|a, b| a.1 .1.total_cmp(&b.1 .1))
        .map(|(k, q)| (k, *q))
        .unwrap_or((0, first));
    // a rail's shape: smallest z inside, both ends well below (larger z)
    let rail_like = first.1 - pmin.1 > RELIEF_MM && last.1 - pmin.1 > RELIEF_MM;
    // a rail upside down: largest z inside, both ends well above
    let inverted_rail = pmax.1 - first.1 > RELIEF_MM && pmax.1 - last.1 > RELIEF_MM;
    let mid = 0.5 * (first.0 + last.0);
    let why = match kind {
        ProfileKind::Rail => {
            if rail_like {
                return Ok(());
            }
            if inverted_rail {
                "its largest z lies between two higher ends: z points up, or this is a wheel profile"
            } else {
                "one end stands far above the other, like a wheel's flange (a wheel profile?), \
                 or y and z are swapped"
            }
        }
        ProfileKind::Wheel => {
            if rail_like {
                "its smallest z lies between two lower ends: a rail profile, or a wheel with z pointing up"
            } else if pmax.1 - pmin.1 <= RELIEF_MM {
                "no flange found (z varies by less than 10 mm), or y and z are swapped"
            } else if kmax != 0
                && kmax != p.len() - 1
                && (pmax.1 - first.1).min(pmax.1 - last.1) > RELIEF_MM
            {
                if pmax.0 < mid {
                    return Ok(()); // flange tip between the flange back and the tread
                }
                "its flange is at the positive-y end (mirrored in y?)"
            } else if kmin != 0
                && kmin != p.len() - 1
                && pmax.1 - pmin.1 > RELIEF_MM
                && pmin.0 < mid
            {
                "its flange points to negative z (z points up?)"
            } else if pmax.0 < mid {
                return Ok(()); // flange tip at the track-centre end
            } else if pmin.0 < mid {
                "its flange points to negative z (z points up?)"
            } else {
                "its flange is at the positive-y end (mirrored in y?)"
            }
        }
    };
    Err(format!(
        "not a {} profile in the expected orientation: {why}; {}",
        match kind {
            ProfileKind::Rail => "rail",
            ProfileKind::Wheel => "wheel",
        },
        expected(kind)
    ))
}

#[cfg(test)]
mod tests {
    use super::check;
    use wrc_host_tests::profiles::{parse_profile, S1002_NAME, S1002_PRW, UIC60_NAME, UIC60_PRR};
    use wrc_kernel::profile::ProfileKind::{Rail, Wheel};

    fn pts(text: &str, name: &str) -> Vec<(f64, f64)> {
        parse_profile(text, std::path::Path::new(name), None)
            .expect("built-in profile parses")
            .points
    }

    #[test]
    fn built_in_profiles_pass_and_their_misoriented_copies_fail() {
        let w = pts(S1002_PRW, S1002_NAME);
        let r = pts(UIC60_PRR, UIC60_NAME);
        assert_eq!(check(&w, Wheel), Ok(()));
        assert_eq!(check(&r, Rail), Ok(()));
        let mirror_y = |p: &[(f64, f64)]| p.iter().map(|&(y, z)| (-y, z)).collect::<Vec<_>>();
        let mirror_z = |p: &[(f64, f64)]| p.iter().map(|&(y, z)| (y, -z)).collect::<Vec<_>>();
        let swap = |p: &[(f64, f64)]| p.iter().map(|&(y, z)| (z, y)).collect::<Vec<_>>();
        for bad in [mirror_y(&w), mirror_z(&w), swap(&w), r.clone()] {
            let e = check(&bad, Wheel).unwrap_err();
            assert!(e.contains("flange tip is the largest z"), "{e}");
        }
        for bad in [mirror_z(&r), swap(&r), w.clone()] {
            let e = check(&bad, Rail).unwrap_err();
            assert!(e.contains("rail top is the smallest z"), "{e}");
        }
    }
}
