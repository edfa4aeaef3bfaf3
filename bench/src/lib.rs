//! Host benchmarks of the wrc kernel live in `benches/`; the QEMU firmware in `bench/firmware/`.
