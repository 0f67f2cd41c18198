//! Peak heap of every metric, per point: a counting global allocator
//! records the largest number of bytes alive while one metric runs, beyond
//! what was alive when it started (the points themselves).
//!
//! The `metrics` tool holds the points (8 bytes each) and runs the metrics
//! one after another, so its peak is the points plus the largest single
//! metric's peak; the bounds below keep that near 3x the point data (about
//! 25 bytes a point) for spread-out sets. Allocation sizes are linear in n,
//! so 2^18 points (set `METRIC_MEMORY_M` for another 2^m) stand for any size.

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

use wellspread::glam::Vec2;
use wellspread::{Sampler2D, Sobol, metrics};

struct Counting;

static LIVE: AtomicUsize = AtomicUsize::new(0);
static PEAK: AtomicUsize = AtomicUsize::new(0);

// SAFETY: every method forwards to `System` with the caller's arguments,
// so `System`'s guarantees carry over; the counters do not touch memory.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let p = unsafe { System.alloc(layout) };
        if !p.is_null() {
            let live = LIVE.fetch_add(layout.size(), Ordering::SeqCst) + layout.size();
            PEAK.fetch_max(live, Ordering::SeqCst);
        }
        p
    }
    unsafe fn dealloc(&self, p: *mut u8, layout: Layout) {
        unsafe { System.dealloc(p, layout) };
        LIVE.fetch_sub(layout.size(), Ordering::SeqCst);
    }
    unsafe fn realloc(&self, p: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        let q = unsafe { System.realloc(p, layout, new_size) };
        if !q.is_null() {
            // Counted as alloc-then-free: realloc may copy, and both blocks
            // are alive during the copy.
            let live = LIVE.fetch_add(new_size, Ordering::SeqCst) + new_size;
            PEAK.fetch_max(live, Ordering::SeqCst);
            LIVE.fetch_sub(layout.size(), Ordering::SeqCst);
        }
        q
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

/// Bytes per point of the heap `f` allocates at its peak beyond what was
/// alive when it started.
fn peak_per_point<T>(n: usize, f: impl FnOnce() -> T) -> f64 {
    let base = LIVE.load(Ordering::SeqCst);
    PEAK.store(base, Ordering::SeqCst);
    let out = f();
    let peak = PEAK.load(Ordering::SeqCst) - base;
    drop(out);
    peak as f64 / n as f64
}

/// SplitMix64.
struct Mix(u64);
impl Mix {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }
}

/// Point sets that take each metric's different paths: a 2^m Sobol' net
/// (distinct coordinates on the 2^-32 grid, a net), uniform f32 on the
/// 2^-24 grid (ties), and f32 values with every mantissa bit used down to
/// tiny exponents (off the 2^-32 grid, so the wrap-around metric takes its
/// double-double path).
fn point_sets(m: u32) -> Vec<(&'static str, Vec<Vec2>)> {
    let n = 1usize << m;
    let sobol = Sobol::new(n as u32).unwrap();
    let mut net = vec![Vec2::ZERO; n];
    sobol.fill(7, &mut net);
    let mut rng = Mix(1);
    let grid: Vec<Vec2> = (0..n)
        .map(|_| {
            let mut unit = || (rng.next() >> 40) as f32 / (1u32 << 24) as f32;
            Vec2::new(unit(), unit())
        })
        .collect();
    let mut rng = Mix(2);
    let fine: Vec<Vec2> = (0..n)
        .map(|_| {
            let mut unit = || {
                let v = (rng.next() >> 11) as f64 / (1u64 << 53) as f64;
                (v * v * v) as f32 * 0.999
            };
            Vec2::new(unit(), unit())
        })
        .collect();
    vec![("sobol", net), ("grid24", grid), ("fine", fine)]
}

/// A metric, run for its side effect on the heap, and the most bytes per
/// point it may allocate at its peak on the spread-out sets (`sobol`,
/// `grid24`) and on any set (`fine` included, whose cluster near the origin
/// sends the distances to their sorted-cell grid).
type Metric = (&'static str, fn(&[Vec2]) -> bool, [f64; 2]);

fn all_metrics() -> Vec<Metric> {
    vec![
        (
            "star_discrepancy",
            |p| metrics::star_discrepancy(p).is_ok(),
            [18.5; 2],
        ),
        (
            "l2_star_discrepancy",
            |p| metrics::l2_star_discrepancy(p).is_ok(),
            [17.5; 2],
        ),
        (
            "centered_l2_discrepancy",
            |p| metrics::centered_l2_discrepancy(p).is_ok(),
            [16.5; 2],
        ),
        // Off the 2^-32 grid, the double-double dominance sweep needs 4 more.
        (
            "wraparound_l2_discrepancy",
            |p| metrics::wraparound_l2_discrepancy(p).is_ok(),
            [16.5, 20.5],
        ),
        // On `fine` the distances take their z-order bound and sorted-cell
        // grid: 16.1 B/pt at 2^20 (16.5 at 2^18 with the radix sort's
        // counts; 84 and 120 B/pt before that fallback was slimmed).
        (
            "min_distance",
            |p| metrics::min_distance(p).is_ok(),
            [16.5, 17.0],
        ),
        (
            "toroidal_min_distance",
            |p| metrics::toroidal_min_distance(p).is_ok(),
            [16.5, 17.0],
        ),
        (
            "normalized_toroidal_min_distance",
            |p| metrics::normalized_toroidal_min_distance(p).is_ok(),
            [16.5, 17.0],
        ),
        ("is_latin", |p| metrics::is_latin(p).is_ok(), [2.5; 2]),
        (
            "is_net_base2",
            |p| metrics::is_net_base2(p).is_ok(),
            [12.5; 2],
        ),
        (
            "net_t_value",
            |p| metrics::net_t_value(p).is_ok(),
            [12.5; 2],
        ),
    ]
}

#[test]
fn every_metric_peaks_below_its_bytes_per_point() {
    let m: u32 = std::env::var("METRIC_MEMORY_M")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(18);
    let n = 1usize << m;
    let sets = point_sets(m);
    let mut over = Vec::new();
    for (name, metric, [spread, any]) in all_metrics() {
        for (set, points) in &sets {
            let per_point = peak_per_point(n, || assert!(metric(points), "{name} on {set}"));
            let bound = if *set == "fine" { any } else { spread };
            println!("{name:34} {set:8} {per_point:6.2} B/pt (bound {bound})");
            if per_point > bound {
                over.push(format!(
                    "{name} on {set}: {per_point:.2} B/pt, bound {bound}"
                ));
            }
        }
    }
    assert!(
        over.is_empty(),
        "peak heap above its bound at n = {n}: {over:?}"
    );
}
