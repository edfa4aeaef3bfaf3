//! Host benchmarks of the elliptic core on CONTACT's 8 × 4 mm example (methods.md §10.1, §10.4):
//! Hertz solve, Kalker coefficients, patch set-up, FASTSIM and FaStrip on a 32 × 32 grid, in f64
//! and f32. Run with `cargo bench -p wrc-bench --bench elliptic`; CI only builds them
//! (`cargo bench --workspace --no-run`). Instruction counts on Cortex-M come from the QEMU firmware
//! (bench/firmware), not from here.

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use wrc_host_tests::cases::{a8b4, contact_material};
use wrc_kernel::fastrip::{fastrip, FastripSettings, LambdaVariant};
use wrc_kernel::fastsim::{fastsim, FastsimSettings};
use wrc_kernel::patch::{Creepage, GridExtent, HertzPressure, StripPatch, TractionBound};
use wrc_kernel::{hertz, kalker, Real};

const MU: f64 = 0.3;
const N: f64 = 82_000.0;

fn creep<T: Real>() -> Creepage<T> {
    Creepage {
        xi: T::ZERO,
        eta: T::from_f64(-6.25e-4),
        phi: T::from_f64(6.25e-4),
    }
}

fn bench_precision<T: Real>(c: &mut Criterion, tag: &str) {
    let mat = contact_material::<T>();
    let (ca, cb, n) = (
        T::from_f64(0.846_419_467_532_808e-3),
        T::from_f64(2.406_161_741_852_433e-3),
        T::from_f64(N),
    );
    c.bench_function(&format!("{tag}/hertz::from_load a8b4"), |b| {
        b.iter(|| hertz::from_load(black_box(ca), black_box(cb), black_box(n), &mat))
    });
    let (sa, sb) = (T::from_f64(1e-6), T::from_f64(1e-3));
    c.bench_function(&format!("{tag}/hertz::from_load A/B=1e-3"), |b| {
        b.iter(|| hertz::from_load(black_box(sa), black_box(sb), black_box(n), &mat))
    });
    let (ab, nu) = (T::from_f64(2.0), T::from_f64(0.28));
    c.bench_function(&format!("{tag}/kalker::coefficients a/b=2"), |b| {
        b.iter(|| kalker::coefficients(black_box(ab), black_box(nu)))
    });
    let (a, bb) = (T::from_f64(8.0), T::from_f64(4.0));
    c.bench_function(&format!("{tag}/StripPatch::hertz 32x32"), |b| {
        b.iter(|| {
            StripPatch::<T, 32, 32>::hertz(
                black_box(a),
                black_box(bb),
                black_box(n),
                &mat,
                GridExtent::contact(),
            )
        })
    });
    let (patch, ell) = a8b4::<T, 32, 32>();
    let pr = HertzPressure(ell);
    let cr = creep::<T>();
    let mu = T::from_f64(MU);
    let par = FastsimSettings::canonical(mu, TractionBound::Parabolic(ell));
    c.bench_function(&format!("{tag}/fastsim parabolic 32x32"), |b| {
        b.iter(|| fastsim(black_box(&patch), &pr, black_box(&cr), &par, &mut ()))
    });
    let ell_set = FastsimSettings::canonical(mu, TractionBound::Elliptic);
    c.bench_function(&format!("{tag}/fastsim elliptic 32x32"), |b| {
        b.iter(|| fastsim(black_box(&patch), &pr, black_box(&cr), &ell_set, &mut ()))
    });
    let def = FastripSettings::new(mu);
    c.bench_function(&format!("{tag}/fastrip default 32x32"), |b| {
        b.iter(|| fastrip(black_box(&patch), &pr, black_box(&cr), &def, &mut ()))
    });
    let m6 = FastripSettings::contact_m6(mu, ell, LambdaVariant::StripTheory);
    c.bench_function(&format!("{tag}/fastrip original (M6) 32x32"), |b| {
        b.iter(|| fastrip(black_box(&patch), &pr, black_box(&cr), &m6, &mut ()))
    });
    let mut p5 = patch;
    let eq = p5
        .modified_fastrip_reference(&pr, n)
        .expect("valid M5 set-up");
    let m5 = FastripSettings::contact_m5(mu, a, bb, n, eq, LambdaVariant::StripTheory);
    c.bench_function(&format!("{tag}/fastrip modified (M5) 32x32"), |b| {
        b.iter(|| fastrip(black_box(&p5), &pr, black_box(&cr), &m5, &mut ()))
    });
}

fn benches(c: &mut Criterion) {
    bench_precision::<f64>(c, "f64");
    bench_precision::<f32>(c, "f32");
}

criterion_group!(elliptic, benches);
criterion_main!(elliptic);
