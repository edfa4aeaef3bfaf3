//! Profile readers and preprocessing: error cases, table contents on the Manchester profiles.

use std::path::Path;
use wrc_host_tests::profiles::{self, ProfileError, SmoothOptions};
use wrc_kernel::profile::ProfileKind;

#[test]
fn manchester_tables_look_right() {
    let (w, r) = profiles::manchester_tables::<f64>(&SmoothOptions::default()).unwrap();
    println!("wheel len {} y {}..{}  rail len {} y {}..{}", w.len, w.y[0], w.y[w.len-1], r.len, r.y[0], r.y[r.len-1]);
}
