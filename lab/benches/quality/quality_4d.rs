//! The quality report's 4D section: a non-separable integrand that couples
//! the film and the lens, as depth of field does, through one 4D draw
//! (`Domain::next_4d`) and through two padded pairs.

use std::fmt::Write as _;

use wellspread::glam::Vec4;
use wellspread::{AnyPixelSampler, PixelSampler, PixelSamplerKind};

/// `exp(-((x0 - x2)^2 + (x1 - x3)^2))`, with its integral over `[0, 1)^4`:
/// `(sqrt(pi) erf(1) - (1 - 1/e))^2` (the 2D integral of `exp(-(a-b)^2)`
/// is `2 int_0^1 (1 - u) exp(-u^2) du`).
fn coupled(p: Vec4) -> f64 {
    let (dx, dy) = (f64::from(p.x - p.z), f64::from(p.y - p.w));
    (-(dx * dx + dy * dy)).exp()
}

fn coupled_exact() -> f64 {
    let erf1 = 0.842_700_792_949_714_9_f64;
    let one = std::f64::consts::PI.sqrt() * erf1 - (1.0 - (-1.0f64).exp());
    one * one
}

/// How one row draws its 4D point.
#[derive(Clone, Copy)]
enum Draw {
    FourD,
    Pairs,
}

/// RMSE over the pixels of a `side x side` film of each pixel's
/// `n`-sample estimate.
fn rmse(sampler: &AnyPixelSampler, side: u32, n: u32, draw: Draw) -> f64 {
    let exact = coupled_exact();
    let mut sum_squares = 0.0;
    for y in 0..side {
        for x in 0..side {
            let mut sum = 0.0;
            for i in 0..n {
                let mut d = sampler.start([x, y], i);
                let p = match draw {
                    Draw::FourD => d.next_4d(),
                    Draw::Pairs => {
                        let (a, b) = (d.next_2d(), d.next_2d());
                        Vec4::new(a.x, a.y, b.x, b.y)
                    }
                };
                sum += coupled(p);
            }
            let e = sum / f64::from(n) - exact;
            sum_squares += e * e;
        }
    }
    (sum_squares / f64::from(side * side)).sqrt()
}

/// The section: RMSE at each n for each row, and the least-squares slope
/// of log RMSE against log n.
pub fn section(quick: bool, slope: impl Fn(&[u32], &[Option<f64>]) -> Option<f64>) -> String {
    let (side, sizes): (u32, &[u32]) = if quick {
        (16, &[16, 32, 64, 128, 256])
    } else {
        (64, &[16, 32, 64, 128, 256, 512, 1024])
    };
    // `faure` and `orthogonal` read both ways from one page of one set, so
    // their two `next_2d` are stratified jointly too.
    let rows: [(&str, &str, Draw); 9] = [
        ("sobol", "`next_4d`", Draw::FourD),
        ("pmj02", "`next_4d`", Draw::FourD),
        ("zsobol", "`next_4d`", Draw::FourD),
        ("faure", "`next_4d`", Draw::FourD),
        ("faure", "two `next_2d`", Draw::Pairs),
        ("orthogonal", "two `next_2d`", Draw::Pairs),
        ("sobol", "two `next_2d`", Draw::Pairs),
        ("cmj", "two `next_2d`", Draw::Pairs),
        ("random", "two `next_2d`", Draw::Pairs),
    ];
    let mut t = String::new();
    let _ = writeln!(
        t,
        "## RMSE: coupled 4D integrand exp(-((x0-x2)^2+(x1-x3)^2)) (exact {:.15})\n\n\
         Each pixel of a {side} x {side} film estimates the integral from its n samples, \
         frame 0; RMSE over the {} pixels. One 4D draw against two pairs (padded, or one page \
         of `faure`'s and `orthogonal`'s sets).\n",
        coupled_exact(),
        side * side
    );
    let _ = write!(t, "| sampler | draws |");
    for n in sizes {
        let _ = write!(t, " {n} |");
    }
    let _ = writeln!(t, " slope |\n|---|---|{}---|", "---|".repeat(sizes.len()));
    for (name, how, draw) in rows {
        let kind: PixelSamplerKind = name.parse().expect("a pixel sampler name");
        let errors: Vec<Option<f64>> = sizes
            .iter()
            .map(|&n| {
                kind.build(n, [side, side], 0)
                    .ok()
                    .map(|s| rmse(&s, side, n, draw))
            })
            .collect();
        let _ = write!(t, "| {name} | {how} |");
        for e in &errors {
            let _ = write!(t, " {} |", e.map_or("-".to_owned(), |v| format!("{v:.3e}")));
        }
        let _ = writeln!(
            t,
            " {} |",
            slope(sizes, &errors).map_or("-".to_owned(), |s| format!("{s:.2}"))
        );
    }
    t.push('\n');
    t
}
