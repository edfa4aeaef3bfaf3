//! Deterministic cost meters under QEMU (see docs/embedded.md §1 and §3).
//!
//! * Instructions: the CMSDK APB TIMER0 of mps2-an386/an500, a 32-bit down-counter at 25 MHz.
//!   With QEMU's `-icount shift=10,align=off,sleep=off` the virtual clock advances 1024 ns per guest
//!   instruction, so instructions = ticks × 5 / 128 exactly; the cost of an empty region is
//!   measured at start-up and subtracted.
//! * Stack: painting. Below the caller's stack pointer a window is filled with a pattern, the call
//!   runs, and the lowest overwritten word gives the call's stack high-water mark (including every
//!   callee: soft-float, libm); the cost of an empty call is subtracted.

use core::hint::black_box;
use core::ptr::{addr_of, read_volatile, write_volatile};
use core::sync::atomic::{AtomicU32, Ordering};

use cortex_m_rt::exception;

use cortex_m_semihosting::hprintln;

use crate::cases::Meter;

const TIMER0_CTRL: *mut u32 = 0x4000_0000 as *mut u32;
const TIMER0_VALUE: *mut u32 = 0x4000_0004 as *mut u32;
const TIMER0_RELOAD: *mut u32 = 0x4000_0008 as *mut u32;
const TIMER0_INTCLEAR: *mut u32 = 0x4000_000C as *mut u32;
/// TIMER0's interrupt line on mps2-an386/an500 (QEMU `mps2.c`: CMSDK APB timer 0 → IRQ 8).
const TIMER0_IRQ: i16 = 8;
/// NVIC interrupt set-enable register 0.
const NVIC_ISER0: *mut u32 = 0xE000_E100 as *mut u32;

/// Wraps of TIMER0 (2³² ticks ≈ 168 M instructions each), counted by its interrupt: calls beyond
/// one wrap (soft-float f64 on the M4F) are metered exactly.
static WRAPS: AtomicU32 = AtomicU32::new(0);

#[exception]
unsafe fn DefaultHandler(irqn: i16) {
    if irqn == TIMER0_IRQ {
        // SAFETY: TIMER0's interrupt-clear register.
        unsafe { write_volatile(TIMER0_INTCLEAR, 1) };
        WRAPS.fetch_add(1, Ordering::Relaxed);
    }
}

/// Paint pattern.
const PAINT: u32 = 0xCCCC_CCCC;
/// Bytes painted below the caller's stack pointer (bounded by the stack's end).
const WINDOW: usize = 1024 * 1024;

extern "C" {
    /// Lowest stack address (cortex-m-rt's link.x).
    static _stack_end: u32;
}

/// Starts TIMER0 free-running from 0xFFFF_FFFF, its wrap interrupt counting into `WRAPS`.
pub fn timer_start() {
    // SAFETY: TIMER0's registers on mps2-an386/an500; no other code touches them.
    unsafe {
        write_volatile(TIMER0_CTRL, 0);
        write_volatile(TIMER0_RELOAD, u32::MAX);
        write_volatile(TIMER0_VALUE, u32::MAX);
        write_volatile(NVIC_ISER0, 1 << TIMER0_IRQ);
        // enable | interrupt enable
        write_volatile(TIMER0_CTRL, 1 | 8);
    }
}

/// Elapsed ticks since start (wrapping).
/// Ticks since start as a 64-bit count (wraps included).
#[inline(always)]
fn now() -> u64 {
    // re-read when a wrap interrupt lands between the two reads
    loop {
        let w = WRAPS.load(Ordering::Relaxed);
        // SAFETY: volatile read of TIMER0's VALUE register.
        let v = !unsafe { read_volatile(TIMER0_VALUE) };
        if WRAPS.load(Ordering::Relaxed) == w {
            return ((w as u64) << 32) | v as u64;
        }
    }
}

/// Ticks (25 MHz at shift=10) to instructions, rounded.
fn ticks_to_instructions(ticks: u64) -> u64 {
    (ticks * 5 + 64) / 128
}

fn stack_bottom(sp: usize) -> usize {
    // Only the address of the linker symbol is taken.
    let end = addr_of!(_stack_end) as usize;
    let lo = sp.saturating_sub(WINDOW);
    if lo > end {
        lo
    } else {
        end
    }
}

/// Fills the window below this function's own frame with the pattern.
#[inline(never)]
fn paint() {
    let sp = cortex_m::register::msp::read() as usize;
    let mut p = (stack_bottom(sp) + 3) & !3;
    while p < sp - 8 {
        // SAFETY: unused stack below the current stack pointer, above the stack's end.
        unsafe { write_volatile(p as *mut u32, PAINT) };
        p += 4;
    }
}

/// Bytes of stack used below `sp` since the last [`paint`]; `None` if the window overflowed.
fn high_water(sp: usize) -> Option<usize> {
    let bottom = (stack_bottom(sp) + 3) & !3;
    let mut p = bottom;
    while p < sp {
        // SAFETY: reading painted stack memory below `sp`.
        if unsafe { read_volatile(p as *const u32) } != PAINT {
            return if p == bottom { None } else { Some(sp - p) };
        }
        p += 4;
    }
    Some(0)
}

#[inline(never)]
fn run<R, F: FnOnce() -> R>(f: F) -> R {
    black_box(f())
}

/// One measurement: instructions and stack bytes.
#[derive(Clone, Copy, Default)]
pub struct Sample {
    /// Guest instructions (empty-region cost subtracted).
    pub instructions: u64,
    /// Stack bytes (empty-call cost subtracted); `None` if beyond the painted window.
    pub stack: Option<usize>,
}

/// Calls a series can summarise (the state sweep's 1024 and more).
const SERIES_CAP: usize = 1100;

/// The instruction counts of a running series.
struct Series {
    n: usize,
    instructions: [u64; SERIES_CAP],
    max_stack: Option<usize>,
    code: usize,
}

/// The target meter: prints one line per metered kernel call.
pub struct TargetMeter {
    empty_ticks: u64,
    empty_stack: usize,
    /// Prefix printed before each line (board and precision).
    pub prefix: &'static str,
    /// Largest stack high-water mark seen (bytes).
    pub max_stack: usize,
    series: Option<Series>,
}

impl TargetMeter {
    /// Calibrates the empty-region instruction cost and the empty-call stack cost.
    pub fn new() -> Self {
        let mut m = Self {
            empty_ticks: 0,
            empty_stack: 0,
            prefix: "",
            max_stack: 0,
            series: None,
        };
        let (t, s) = m.raw(|| ());
        m.empty_ticks = t;
        m.empty_stack = s.unwrap_or(0);
        m
    }

    /// The calibration constants: (empty-region ticks, empty-call stack bytes).
    pub fn calibration(&self) -> (u64, usize) {
        (self.empty_ticks, self.empty_stack)
    }

    fn raw<R>(&mut self, f: impl FnOnce() -> R) -> (u64, Option<usize>) {
        let sp = cortex_m::register::msp::read() as usize;
        paint();
        let t0 = now();
        let r = run(f);
        let t1 = now();
        black_box(r);
        (t1.saturating_sub(t0), high_water(sp))
    }

    /// Meters `f` without printing.
    pub fn sample<R>(&mut self, f: impl FnOnce() -> R) -> (R, Sample) {
        let sp = cortex_m::register::msp::read() as usize;
        paint();
        let t0 = now();
        let r = run(f);
        let t1 = now();
        let ticks = t1.saturating_sub(t0).saturating_sub(self.empty_ticks);
        let stack = high_water(sp).map(|s| s.saturating_sub(self.empty_stack));
        (
            r,
            Sample {
                instructions: ticks_to_instructions(ticks),
                stack,
            },
        )
    }
}

impl Meter for TargetMeter {
    fn call<R, F: FnOnce() -> R>(&mut self, label: &'static str, f: F) -> R {
        // Address of the metered code (`run` instantiated for this call, the kernel code inlined
        // into it); .ci/run maps it to the symbol's size. Thumb bit cleared.
        let code = (run::<R, F> as fn(F) -> R) as usize & !1;
        let (r, s) = self.sample(f);
        if let Some(b) = s.stack {
            if b > self.max_stack {
                self.max_stack = b;
            }
        }
        if let Some(ser) = &mut self.series {
            if ser.n < SERIES_CAP {
                ser.instructions[ser.n] = s.instructions;
            }
            ser.n += 1;
            ser.max_stack = match (ser.max_stack, s.stack) {
                (Some(a), Some(b)) => Some(if a > b { a } else { b }),
                _ => None,
            };
            ser.code = code;
            return r;
        }
        match s.stack {
            Some(b) => {
                hprintln!(
                    "  meter {} {}: {} instructions, {} B stack, code@{:#010x}",
                    self.prefix,
                    label,
                    s.instructions,
                    b,
                    code
                );
            }
            None => hprintln!(
                "  meter {} {}: {} instructions, stack > {} B (window overflow), code@{:#010x}",
                self.prefix,
                label,
                s.instructions,
                WINDOW,
                code
            ),
        }
        r
    }

    fn series_begin(&mut self) {
        self.series = Some(Series {
            n: 0,
            instructions: [0; SERIES_CAP],
            max_stack: Some(0),
            code: 0,
        });
    }

    fn series_end(&mut self, label: &'static str) {
        let Some(mut ser) = self.series.take() else {
            return;
        };
        let n = if ser.n < SERIES_CAP {
            ser.n
        } else {
            SERIES_CAP
        };
        if n == 0 {
            return;
        }
        let v = &mut ser.instructions[..n];
        // the worst call (first of equals), before sorting
        let mut worst = 0;
        for (q, x) in v.iter().enumerate() {
            if *x > v[worst] {
                worst = q;
            }
        }
        v.sort_unstable();
        // the upper median for an even count, as the host example
        let (median, max) = (v[n / 2], v[n - 1]);
        // P99 by nearest rank: the ⌈0.99 n⌉-th smallest
        let p99 = v[(99 * n).div_ceil(100) - 1];
        let stack = ser.max_stack.unwrap_or(WINDOW);
        hprintln!(
            "  meter {} {} (median of {}): {} instructions, {} B stack, code@{:#010x}",
            self.prefix,
            label,
            n,
            median,
            stack,
            ser.code
        );
        hprintln!(
            "  series {} {}: {} calls, median {} / min {} / max {} instructions, max/median {}.{:03}, P99 {}, worst call #{}",
            self.prefix,
            label,
            n,
            median,
            v[0],
            max,
            max / median.max(1),
            (max % median.max(1)) * 1000 / median.max(1),
            p99,
            worst
        );
    }
}
