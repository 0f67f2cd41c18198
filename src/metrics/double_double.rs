//! Double-double arithmetic: a value held as an unevaluated sum `hi + lo` of
//! two f64 with `|lo| <= ulp(hi) / 2`, about 106 significant bits.
//!
//! Error-free transformations from Dekker 1971, "A floating-point technique
//! for extending the available precision", Numer. Math. 18 (Fast2Sum,
//! splitting, TwoProduct) and Knuth, TAOCP vol. 2, 4.2.2 (TwoSum). Products
//! use Dekker's splitting rather than a fused multiply-add, which is a slow
//! library call on targets built without FMA. Valid while no intermediate
//! value exceeds about 2^995 (splitting multiplies by 2^27 + 1).

/// `hi + lo`, normalised.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Dd {
    pub(crate) hi: f64,
    pub(crate) lo: f64,
}

/// `a + b = s + e` exactly (Knuth's TwoSum, any order of magnitudes).
#[inline(always)]
pub(crate) fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// `a + b = s + e` exactly, given `|a| >= |b|` or `a = 0` (Dekker's Fast2Sum).
#[inline(always)]
fn fast_two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    (s, b - (s - a))
}

/// `a = hi + lo` with both halves of at most 26 significant bits.
#[inline(always)]
fn split(a: f64) -> (f64, f64) {
    const SPLITTER: f64 = 134_217_729.0; // 2^27 + 1
    let t = SPLITTER * a;
    let hi = t - (t - a);
    (hi, a - hi)
}

/// `a b = p + e` exactly (Dekker's TwoProduct).
#[inline(always)]
pub(crate) fn two_prod(a: f64, b: f64) -> Dd {
    let p = a * b;
    let (ah, al) = split(a);
    let (bh, bl) = split(b);
    let e = ((ah * bh - p) + ah * bl + al * bh) + al * bl;
    Dd { hi: p, lo: e }
}

impl Dd {
    pub(crate) const ZERO: Dd = Dd { hi: 0.0, lo: 0.0 };

    /// `num / den` to double-double precision, for small integers.
    pub(crate) fn ratio(num: f64, den: f64) -> Dd {
        let hi = num / den;
        let p = two_prod(hi, den);
        let lo = ((num - p.hi) - p.lo) / den;
        let (hi, lo) = fast_two_sum(hi, lo);
        Dd { hi, lo }
    }

    /// The sum, with a relative error near 2^-104 even under cancellation
    /// (the "accurate" addition of Bailey's QD library).
    #[inline(always)]
    pub(crate) fn add(self, o: Dd) -> Dd {
        let (s, e) = two_sum(self.hi, o.hi);
        let (t, f) = two_sum(self.lo, o.lo);
        let (s, e) = fast_two_sum(s, e + t);
        let (hi, lo) = fast_two_sum(s, e + f);
        Dd { hi, lo }
    }

    /// The sum without renormalising `lo` (for accumulators): exact TwoSum on
    /// the high parts, low parts added in f64. The absolute error per step is
    /// near `2^-53 |lo|`, so a running sum of N terms of size up to T stays
    /// within about `N 2^-106 T`, under any cancellation.
    #[inline(always)]
    pub(crate) fn plus(self, o: Dd) -> Dd {
        let (hi, e) = two_sum(self.hi, o.hi);
        Dd {
            hi,
            lo: self.lo + o.lo + e,
        }
    }

    /// [`plus`](Self::plus) for an f64 term.
    #[inline(always)]
    pub(crate) fn plus_f64(self, b: f64) -> Dd {
        let (hi, e) = two_sum(self.hi, b);
        Dd {
            hi,
            lo: self.lo + e,
        }
    }

    /// The product with `b` of at most 26 significant bits (an f32 value or
    /// an integer below 2^26): Dekker's product with `b` needing no split.
    #[inline(always)]
    pub(crate) fn mul_short(self, b: f64) -> Dd {
        let (ah, al) = split(self.hi);
        let p = self.hi * b;
        let e = ((ah * b - p) + al * b) + self.lo * b;
        let (hi, lo) = fast_two_sum(p, e);
        Dd { hi, lo }
    }

    #[inline(always)]
    pub(crate) fn sub(self, o: Dd) -> Dd {
        self.add(o.neg())
    }

    #[inline(always)]
    pub(crate) fn neg(self) -> Dd {
        Dd {
            hi: -self.hi,
            lo: -self.lo,
        }
    }

    #[inline(always)]
    pub(crate) fn mul_f64(self, b: f64) -> Dd {
        let p = two_prod(self.hi, b);
        let (hi, lo) = fast_two_sum(p.hi, p.lo + self.lo * b);
        Dd { hi, lo }
    }

    #[inline(always)]
    pub(crate) fn mul(self, o: Dd) -> Dd {
        let p = two_prod(self.hi, o.hi);
        let (hi, lo) = fast_two_sum(p.hi, p.lo + (self.hi * o.lo + self.lo * o.hi));
        Dd { hi, lo }
    }

    #[inline(always)]
    pub(crate) fn value(self) -> f64 {
        self.hi + self.lo
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn products_and_sums_are_exact_where_they_must_be() {
        let a = 1.0 + f64::EPSILON;
        let p = two_prod(a, a);
        // (1 + e)² = 1 + 2e + e², with e² below one ulp of the product.
        assert_eq!(p.hi, 1.0 + 2.0 * f64::EPSILON);
        assert_eq!(p.lo, f64::EPSILON * f64::EPSILON);
        let s = Dd::ZERO.plus_f64(1.0).plus_f64(1e-30).plus_f64(-1.0);
        assert_eq!(s.value(), 1e-30);
        let third = Dd::ratio(1.0, 3.0);
        let back = third.mul_f64(3.0).plus_f64(-1.0);
        assert!(back.value().abs() < 1e-31);
        let q = third.mul(third).sub(Dd::ratio(1.0, 9.0));
        assert!(q.value().abs() < 1e-31);
        // 3 (1/3) with the short product, and a lazy sum that cancels.
        let back = third.mul_short(3.0).plus_f64(-1.0);
        assert!(back.value().abs() < 1e-31);
        let lazy = Dd::ZERO
            .plus_f64(1.0)
            .plus_f64(1e-20)
            .plus(Dd::ratio(-1.0, 1.0));
        assert_eq!(lazy.value(), 1e-20);
    }
}
