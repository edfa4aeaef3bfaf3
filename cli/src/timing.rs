//! Wall time of a kernel call: median of a few repeats.

use std::time::Instant;

/// Runs `f` a few times and returns the median wall time in µs.
pub fn median_time_us(mut f: impl FnMut()) -> f64 {
    let mut t: Vec<f64> = (0..7)
        .map(|_| {
            let s = Instant::now();
            f();
            s.elapsed().as_secs_f64() * 1e6
        })
        .collect();
    t.sort_by(f64::total_cmp);
    t[t.len() / 2]
}
