//! The finite fields GF(q), `q = p^k` a prime power up to [`MAX_ORDER`],
//! that the orthogonal arrays are built over: a few words per field and a
//! few dozen integer operations per product, with no tables.
//!
//! An element is the integer whose base-`p` digits are the coefficients of
//! its polynomial in `x` (digit `i` is the coefficient of `x^i`), so the
//! elements are exactly `0..q`, `0` and `1` are the field's zero and one,
//! and for `k = 1` the arithmetic is the integers modulo `p`. For `k > 1`
//! products are reduced modulo the first monic irreducible polynomial of
//! degree `k` over GF(p), in the order of its low coefficients read as a
//! base-`p` number (for GF(4) that is `x^2 + x + 1`, for GF(8) `x^3 + x +
//! 1`, for GF(9) `x^2 + 1`), found by trial division when the field is
//! made.

use crate::primitives::InvariantDivisor;

/// The largest field order: `4096 = 2^12`, the largest `q` with `q^2` at
/// most `2^24` (the most samples a stratified f32 axis holds).
pub(crate) const MAX_ORDER: u32 = 4096;

/// The finite field of `q = p^k` elements (see the module docs for the
/// encoding).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) struct Field {
    /// The characteristic `p`, a prime, with its reciprocal, so that the digit and remainder operations
    /// multiply instead of dividing.
    divisor: InvariantDivisor,
    /// The degree over GF(p).
    k: u32,
    /// `p^(k - 1)`: the place value of the top digit.
    top_place: u32,
    /// `x^k` reduced modulo the field's polynomial, as an element: the
    /// negated low coefficients of the monic modulus (0 for `k = 1`).
    x_to_the_k: u32,
}

/// `(p, k)` with `q = p^k` and `p` prime, if `q` is a prime power (`q >= 2`).
pub(crate) const fn prime_power(q: u32) -> Option<(u32, u32)> {
    if q < 2 {
        return None;
    }
    // The smallest divisor above 1 is prime.
    let mut p = 2;
    while p <= q / p && !q.is_multiple_of(p) {
        p += 1;
    }
    if !q.is_multiple_of(p) {
        p = q;
    }
    let (mut rest, mut k) = (q, 0);
    while rest.is_multiple_of(p) {
        rest /= p;
        k += 1;
    }
    if rest == 1 { Some((p, k)) } else { None }
}

/// Coefficients of a polynomial over GF(p) of degree at most 12, lowest
/// first.
type Poly = [u32; 13];

/// The polynomial whose coefficients are the base-`p` digits of `value`,
/// `len` of them.
const fn digits(value: u32, p: u32, len: u32) -> Poly {
    let mut poly = [0; 13];
    let (mut value, mut i) = (value, 0);
    while i < len {
        poly[i as usize] = value % p;
        value /= p;
        i += 1;
    }
    poly
}

/// Whether the monic `g` of degree `d` divides the monic `f` of degree
/// `k >= d` over GF(p): the remainder of the long division is zero.
const fn divides(g: &Poly, d: u32, f: &Poly, k: u32, p: u32) -> bool {
    let mut r = *f;
    let mut top = k;
    while top >= d {
        // Subtract r[top] x^(top - d) g, which clears coefficient `top`.
        let c = r[top as usize];
        let shift = top - d;
        let mut j = 0;
        while j <= d {
            let i = (shift + j) as usize;
            r[i] = (r[i] + (p - c) * g[j as usize]) % p;
            j += 1;
        }
        top -= 1;
    }
    let mut i = 0;
    while i < d {
        if r[i as usize] != 0 {
            return false;
        }
        i += 1;
    }
    true
}

/// Whether `x^k + low` (`low`'s base-`p` digits the coefficients of `x^0`
/// to `x^(k - 1)`) is irreducible over GF(p): no monic divisor of degree
/// 1 to `k / 2`.
const fn is_irreducible(p: u32, k: u32, low: u32) -> bool {
    let mut f = digits(low, p, k);
    f[k as usize] = 1;
    let mut d = 1;
    let mut count = p;
    while d <= k / 2 {
        let mut g_low = 0;
        while g_low < count {
            let mut g = digits(g_low, p, d);
            g[d as usize] = 1;
            if divides(&g, d, &f, k, p) {
                return false;
            }
            g_low += 1;
        }
        d += 1;
        count *= p;
    }
    true
}

/// The odd prime fields GF(p): sums and products modulo `p`.
pub(crate) const PRIME: u8 = 0;
/// GF(2^k), `1 <= k <=` [`TABLED_DEGREE`]: sums by xor, products by
/// [`BINARY_TABLES`].
pub(crate) const TABLED: u8 = 1;
/// GF(2^k), `k >` [`TABLED_DEGREE`]: sums by xor, products by shift and
/// xor.
pub(crate) const BINARY: u8 = 2;
/// GF(p^k), `p` odd and `k > 1`: digit by digit.
pub(crate) const DIGITS: u8 = 3;
/// Any field, the kind chosen at each operation: for code that runs too
/// seldom to be compiled once per kind.
pub(crate) const ANY: u8 = 4;

/// The largest `k` whose GF(2^k) products come from [`BINARY_TABLES`].
const TABLED_DEGREE: u32 = 8;

/// Logarithms and powers in GF(2^k), `k` from 1 to [`TABLED_DEGREE`], to
/// the base of the smallest generator `g` of the field's nonzero elements
/// (under the modulus [`Field::new`] picks), laid out so that a product is
/// three loads and no branch: for `q = 2^k`, `log[q + a]` is `i < q - 1`
/// with `g^i = a` for `a != 0`, and `2 q - 1` for `a = 0`; `exp[4 q + i]`
/// is `g^i` for `i < 2 (q - 1)` (twice round the cycle, so a sum of two
/// logarithms needs no reduction) and 0 from there to `4 q`, where every
/// sum with a zero's logarithm lands. 3 KiB, built at compile time.
static BINARY_TABLES: ([u16; 512], [u8; 2048]) = binary_tables();

/// [`BINARY_TABLES`], from [`Field::mul_binary`].
const fn binary_tables() -> ([u16; 512], [u8; 2048]) {
    let (mut log, mut exp) = ([0; 512], [0; 2048]);
    let mut k = 1;
    while k <= TABLED_DEGREE {
        let q = 1 << k;
        let Some(field) = Field::new(q) else {
            panic!("GF(2^k) exists for every k");
        };
        // The smallest element of order q - 1 (1, for GF(2)).
        let mut g = 1;
        loop {
            let (mut x, mut order) = (g, 1);
            while x != 1 {
                x = field.mul_binary(x, g);
                order += 1;
            }
            if order == q - 1 {
                break;
            }
            g += 1;
        }
        log[q as usize] = (2 * q - 1) as u16;
        let (mut x, mut i) = (1, 0);
        while i < 2 * (q - 1) {
            // Every element of GF(2^8) fits in a u8; logarithms are < 255.
            exp[(4 * q + i) as usize] = x as u8;
            if i < q - 1 {
                log[(q + x) as usize] = i as u16;
            }
            x = field.mul_binary(x, g);
            i += 1;
        }
        k += 1;
    }
    (log, exp)
}

/// A keyed permutation of GF(q), `x -> scale x + shift` with `scale !=
/// 0`: an element of the field's affine group, which an
/// [`OrthogonalArray`](crate::OrthogonalArray) uses to permute the `q`
/// levels of a column (and, at strength 2, the `q` sub-strata of a level).
///
/// The affine group is sharply 2-transitive: with `scale` and `shift`
/// uniform, the images of two distinct elements are a uniformly random
/// ordered pair of distinct elements, as under a uniform shuffle. The
/// variance of an estimate over a randomised array takes its points two at
/// a time, and Owen's (1992) analysis of it uses only that joint law of two
/// levels' images, so the affine group serves as well as all `q!`
/// permutations, for one product and one sum in the field instead of a
/// shuffle of `q` elements. (It reaches `q (q - 1)` of the `q!` orders:
/// three or more levels are not uniform jointly.)
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) struct Affine {
    scale: u32,
    shift: u32,
}

impl Field {
    /// GF(q), if `q` is a prime power from 2 to [`MAX_ORDER`].
    pub(crate) const fn new(q: u32) -> Option<Self> {
        if q > MAX_ORDER {
            return None;
        }
        let Some((p, k)) = prime_power(q) else {
            return None;
        };
        let top_place = q / p;
        let divisor = InvariantDivisor::new(p);
        if k == 1 {
            return Some(Self {
                divisor,
                k,
                top_place,
                x_to_the_k: 0,
            });
        }
        // The first irreducible modulus (one exists for every p and k).
        let mut low = 0;
        while !is_irreducible(p, k, low) {
            low += 1;
        }
        // x^k = -(low part): negate every digit.
        let low_digits = digits(low, p, k);
        let (mut x_to_the_k, mut place, mut i) = (0, 1, 0);
        while i < k {
            x_to_the_k += (p - low_digits[i as usize]) % p * place;
            place *= p;
            i += 1;
        }
        Some(Self {
            divisor,
            k,
            top_place,
            x_to_the_k,
        })
    }

    /// The affine permutation keyed by `key`: `shift` and then `e` are the
    /// two mixed-radix digits of `key / 2^32` in bases `q` and `q - 1`, by
    /// multiply-high, so each of the `q (q - 1)` maps is drawn `floor` or
    /// `ceil` of `2^32 / (q (q - 1))` times over the keys. The scale is
    /// `1 + e`, or `g^e` in a field whose products come from
    /// [`BINARY_TABLES`] (so that [`apply_keyed_as`](Self::apply_keyed_as)
    /// reads `e` as the scale's logarithm): either is a bijection of `e`
    /// onto the nonzero elements.
    #[inline(always)]
    pub(crate) const fn affine(self, key: u32) -> Affine {
        let (e, shift) = self.affine_digits(key);
        let scale = if self.arithmetic() == TABLED {
            let q = self.order() as usize;
            BINARY_TABLES.1[4 * q + e as usize] as u32
        } else {
            1 + e
        };
        Affine { scale, shift }
    }

    /// `(e, shift)` of [`affine`](Self::affine).
    #[inline(always)]
    const fn affine_digits(self, key: u32) -> (u32, u32) {
        let q = self.order() as u64;
        let product = key as u64 * q;
        let rest = product as u32 as u64;
        (((rest * (q - 1)) >> 32) as u32, (product >> 32) as u32)
    }

    /// `map` applied to the element `x < q`, for a field whose
    /// [`arithmetic`](Self::arithmetic) is `A`.
    #[inline(always)]
    pub(crate) const fn apply_as<const A: u8>(self, map: Affine, x: u32) -> u32 {
        self.add_as::<A>(self.mul_as::<A>(map.scale, x), map.shift)
    }

    /// `apply_as(affine(key), x)`, for a field whose
    /// [`arithmetic`](Self::arithmetic) is `A`: in a tabled field the
    /// scale's logarithm is the key's digit `e` itself, so the product is
    /// two table loads instead of three.
    #[inline(always)]
    pub(crate) const fn apply_keyed_as<const A: u8>(self, key: u32, x: u32) -> u32 {
        if A == TABLED {
            let (e, shift) = self.affine_digits(key);
            let q = self.order() as usize;
            let (log, exp) = &BINARY_TABLES;
            let log_x = log[(q + x as usize) & 511] as usize;
            (exp[(4 * q + e as usize + log_x) & 2047] as u32) ^ shift
        } else {
            self.apply_as::<A>(self.affine(key), x)
        }
    }

    /// The number of elements, `q`.
    #[inline(always)]
    pub(crate) const fn order(self) -> u32 {
        self.top_place * self.divisor.get()
    }

    /// `a + b` (`a, b < q`).
    #[inline(always)]
    pub(crate) const fn add(self, a: u32, b: u32) -> u32 {
        match self.arithmetic() {
            PRIME => self.add_as::<PRIME>(a, b),
            TABLED => self.add_as::<TABLED>(a, b),
            BINARY => self.add_as::<BINARY>(a, b),
            _ => self.add_as::<DIGITS>(a, b),
        }
    }

    /// Which of [`PRIME`], [`TABLED`], [`BINARY`] and [`DIGITS`] computes
    /// this field's sums and products.
    #[inline(always)]
    pub(crate) const fn arithmetic(self) -> u8 {
        // Characteristic 2 first: two tests pick the tabled fields, the
        // arrays' most common kind (GF(2) is one of them).
        if self.divisor.get() == 2 {
            if self.k <= TABLED_DEGREE {
                TABLED
            } else {
                BINARY
            }
        } else if self.k == 1 {
            PRIME
        } else {
            DIGITS
        }
    }

    /// `a + b` for a field whose [`arithmetic`](Self::arithmetic) is `A`:
    /// callers that add and multiply many times choose `A` once and
    /// compile a loop for each kind.
    #[inline(always)]
    pub(crate) const fn add_as<const A: u8>(self, a: u32, b: u32) -> u32 {
        match A {
            PRIME => {
                let s = a + b;
                if s >= self.divisor.get() {
                    s - self.divisor.get()
                } else {
                    s
                }
            }
            TABLED | BINARY => a ^ b,
            DIGITS => self.add_digits(a, b),
            _ => self.add(a, b),
        }
    }

    /// `a + b` digit by digit, for any `p`.
    const fn add_digits(self, mut a: u32, mut b: u32) -> u32 {
        let (mut sum, mut place, mut i) = (0, 1, 0);
        while i < self.k {
            let (a_rest, a_digit) = self.divisor.div_rem(a);
            let (b_rest, b_digit) = self.divisor.div_rem(b);
            let s = a_digit + b_digit;
            sum += if s >= self.divisor.get() {
                s - self.divisor.get()
            } else {
                s
            } * place;
            (a, b) = (a_rest, b_rest);
            place *= self.divisor.get();
            i += 1;
        }
        sum
    }

    /// `c a` for `c` in GF(p), digit by digit.
    const fn scale_digits(self, mut a: u32, c: u32) -> u32 {
        let (mut product, mut place, mut i) = (0, 1, 0);
        while i < self.k {
            let (rest, digit) = self.divisor.div_rem(a);
            product += self.divisor.div_rem(digit * c).1 * place;
            a = rest;
            place *= self.divisor.get();
            i += 1;
        }
        product
    }

    /// `x a`, reduced: the top digit comes back as that multiple of `x^k`.
    const fn times_x_digits(self, a: u32) -> u32 {
        // The top digit, and the rest shifted up one place.
        let mut top = a;
        let mut i = 1;
        while i < self.k {
            top = self.divisor.div_rem(top).0;
            i += 1;
        }
        let shifted = (a - top * self.top_place) * self.divisor.get();
        self.add_digits(shifted, self.scale_digits(self.x_to_the_k, top))
    }

    /// `a b` (`a, b < q`).
    #[inline(always)]
    pub(crate) const fn mul(self, a: u32, b: u32) -> u32 {
        match self.arithmetic() {
            PRIME => self.mul_as::<PRIME>(a, b),
            TABLED => self.mul_as::<TABLED>(a, b),
            BINARY => self.mul_as::<BINARY>(a, b),
            _ => self.mul_as::<DIGITS>(a, b),
        }
    }

    /// `a b` for a field whose [`arithmetic`](Self::arithmetic) is `A`.
    #[inline(always)]
    pub(crate) const fn mul_as<const A: u8>(self, a: u32, b: u32) -> u32 {
        match A {
            // a, b < 4096: the product fits in u32.
            PRIME => self.divisor.div_rem(a * b).1,
            TABLED => self.mul_tabled(a, b),
            BINARY => self.mul_binary(a, b),
            DIGITS => self.mul_digits(a, b),
            _ => self.mul(a, b),
        }
    }

    /// `a b` in GF(2^k), `k <= 8`, by logarithms: `g^(log a + log b)`, and
    /// 0 through the tables' zeros when either is 0.
    #[inline(always)]
    const fn mul_tabled(self, a: u32, b: u32) -> u32 {
        let q = self.order() as usize;
        let (log, exp) = &BINARY_TABLES;
        // The masks change nothing for a, b < q <= 256 and let the
        // compiler drop the bounds checks.
        let (log_a, log_b) = (log[(q + a as usize) & 511], log[(q + b as usize) & 511]);
        exp[(4 * q + log_a as usize + log_b as usize) & 2047] as u32
    }

    /// `a b` in GF(2^k): carry-less shift-and-add from `b`'s top bit down,
    /// folding `x^k` back in as `x_to_the_k`.
    #[inline(always)]
    const fn mul_binary(self, a: u32, b: u32) -> u32 {
        let mut product = 0;
        let mut i = self.k;
        while i > 0 {
            i -= 1;
            let carry = product >> (self.k - 1);
            product = ((product << 1) & (self.order() - 1)) ^ (carry * self.x_to_the_k);
            product ^= ((b >> i) & 1) * a;
        }
        product
    }

    /// `a b` for any `p`, by Horner's rule on `b`'s digits from the top:
    /// `product = x product + b_i a`.
    const fn mul_digits(self, a: u32, b: u32) -> u32 {
        // b's digits, lowest first.
        let mut digits = [0; 12];
        let (mut rest, mut i) = (b, 0);
        while i < self.k {
            let (next, digit) = self.divisor.div_rem(rest);
            digits[i as usize] = digit;
            rest = next;
            i += 1;
        }
        let mut product = 0;
        while i > 0 {
            i -= 1;
            product = self.times_x_digits(product);
            product = self.add_digits(product, self.scale_digits(a, digits[i as usize]));
        }
        product
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every prime power the fields accept, and a few numbers that are not.
    #[test]
    fn prime_powers_are_recognised() {
        assert_eq!(prime_power(0), None);
        assert_eq!(prime_power(1), None);
        assert_eq!(prime_power(2), Some((2, 1)));
        assert_eq!(prime_power(4), Some((2, 2)));
        assert_eq!(prime_power(6), None);
        assert_eq!(prime_power(9), Some((3, 2)));
        assert_eq!(prime_power(12), None);
        assert_eq!(prime_power(4093), Some((4093, 1)));
        assert_eq!(prime_power(4096), Some((2, 12)));
        assert_eq!(prime_power(3_721), Some((61, 2)));
        assert_eq!(prime_power(2_187), Some((3, 7)));
        assert_eq!(prime_power(u32::MAX), None);
        let count = (2..=MAX_ORDER).filter(|&q| Field::new(q).is_some()).count();
        // 564 primes below 4096, and 35 higher prime powers: 2^2..2^12,
        // 3^2..3^7, 5^2..5^5, 7^2..7^4, 11^2, 11^3, 13^2, 13^3 and the
        // squares of the 12 primes from 17 to 61.
        assert_eq!(count, 564 + 11 + 6 + 4 + 3 + 2 + 2 + 12);
        assert_eq!(Field::new(MAX_ORDER + 1), None);
    }

    /// The moduli the search finds, checked by hand: GF(4) = GF(2)[x] /
    /// (x^2 + x + 1), GF(8) with x^3 + x + 1, GF(9) = GF(3)[x] / (x^2 + 1).
    #[test]
    fn small_fields_multiply_as_by_hand() {
        let gf4 = Field::new(4).unwrap();
        // x = 2, x + 1 = 3: x^2 = x + 1, x (x + 1) = 1, (x + 1)^2 = x.
        assert_eq!(gf4.mul(2, 2), 3);
        assert_eq!(gf4.mul(2, 3), 1);
        assert_eq!(gf4.mul(3, 3), 2);
        let gf8 = Field::new(8).unwrap();
        // x^3 = x + 1: x * x^2 = 0b011; x^2 * x^2 = x^4 = x^2 + x.
        assert_eq!(gf8.mul(2, 4), 3);
        assert_eq!(gf8.mul(4, 4), 6);
        let gf9 = Field::new(9).unwrap();
        // x = 3: x^2 = -1 = 2; (x + 1)^2 = x^2 + 2x + 1 = 2x = 6.
        assert_eq!(gf9.mul(3, 3), 2);
        assert_eq!(gf9.mul(4, 4), 6);
        // (2 + x) + (1 + 2x) = 3 + 3x = 0; (2 + x) + (2 + x) = 1 + 2x.
        assert_eq!(gf9.add(5, 7), 0);
        assert_eq!(gf9.add(5, 5), 7);
    }

    /// The keyed affine maps: over keys spread evenly across u32, every
    /// one of the `q (q - 1)` maps is drawn, each as often as any other to
    /// within one (the keys are the multiples of `2^32 / k` for `k` a
    /// multiple of `q (q - 1)`, so each map gets exactly `k / (q (q - 1))`);
    /// each is a bijection; and the pair of images of two distinct
    /// elements is every ordered distinct pair exactly once over the maps
    /// (sharply 2-transitive).
    #[test]
    fn affine_maps_are_uniform_bijections_and_sharply_2_transitive() {
        for q in [2, 3, 4, 5, 7, 8, 9, 16, 25, 27, 32, 49] {
            let f = Field::new(q).unwrap();
            let apply = |map, x| f.apply_as::<ANY>(map, x);
            let maps = q * (q - 1);
            let keys = maps * 64;
            let mut drawn = std::collections::HashMap::new();
            for k in 0..keys {
                let key = (u64::from(k) << 32).div_ceil(u64::from(keys)) as u32;
                *drawn.entry(f.affine(key)).or_insert(0u32) += 1;
            }
            assert_eq!(drawn.len() as u32, maps, "GF({q}): maps reached");
            assert!(drawn.values().all(|&c| c == 64), "GF({q}): {drawn:?}");
            for &map in drawn.keys() {
                let mut seen = std::vec![false; q as usize];
                for x in 0..q {
                    let y = apply(map, x);
                    assert!(y < q && !seen[y as usize], "GF({q}) {map:?}");
                    seen[y as usize] = true;
                }
            }
            for (x, y) in [(0, 1), (1, q - 1), (q / 2, q - 1)] {
                if x == y {
                    continue;
                }
                let mut pairs = std::vec![0u32; (q * q) as usize];
                for &map in drawn.keys() {
                    pairs[(apply(map, x) * q + apply(map, y)) as usize] += 1;
                }
                for a in 0..q {
                    for b in 0..q {
                        let expected = u32::from(a != b);
                        assert_eq!(pairs[(a * q + b) as usize], expected, "GF({q}) {x} {y}");
                    }
                }
            }
        }
    }

    /// The keyed application's shortcut (the scale's logarithm read off
    /// the key) is the map `affine` draws, in every kind of field, for
    /// keys across the whole range.
    #[test]
    fn keyed_application_is_the_drawn_map() {
        for q in [2, 3, 4, 5, 8, 9, 16, 25, 64, 256, 512, 4096] {
            let f = Field::new(q).unwrap();
            for k in 0..2_000u32 {
                let key = k.wrapping_mul(0x9e37_79b9) ^ (k >> 3);
                let map = f.affine(key);
                for x in [0, 1, q / 2, q - 1] {
                    let expected = f.apply_as::<ANY>(map, x);
                    let keyed = match f.arithmetic() {
                        PRIME => f.apply_keyed_as::<PRIME>(key, x),
                        TABLED => f.apply_keyed_as::<TABLED>(key, x),
                        BINARY => f.apply_keyed_as::<BINARY>(key, x),
                        _ => f.apply_keyed_as::<DIGITS>(key, x),
                    };
                    assert_eq!(keyed, expected, "GF({q}) key {key:#x} x {x}");
                }
            }
        }
    }

    /// Which arithmetic serves which field: tables for GF(2^k) up to
    /// degree 8 (GF(2) among them, whose sums and products are those
    /// modulo 2), shift and xor above, modular arithmetic for the odd
    /// primes and digits for their powers.
    #[test]
    fn each_field_gets_its_arithmetic() {
        for (q, arithmetic) in [
            (2, TABLED),
            (4, TABLED),
            (256, TABLED),
            (512, BINARY),
            (3, PRIME),
            (251, PRIME),
            (9, DIGITS),
            (243, DIGITS),
        ] {
            assert_eq!(Field::new(q).unwrap().arithmetic(), arithmetic, "GF({q})");
        }
        let f = Field::new(2).unwrap();
        for a in 0..2 {
            for b in 0..2 {
                assert_eq!(f.add_as::<TABLED>(a, b), (a + b) % 2, "{a} + {b}");
                assert_eq!(f.mul_as::<TABLED>(a, b), a * b, "{a} {b}");
            }
        }
    }

    /// The logarithm tables give the shift-and-xor product for every pair
    /// of elements of every GF(2^k) they serve.
    #[test]
    fn tabled_binary_products_match_shift_and_xor() {
        for k in 1..=TABLED_DEGREE {
            let f = Field::new(1 << k).unwrap();
            for a in 0..1 << k {
                for b in 0..1 << k {
                    assert_eq!(f.mul_tabled(a, b), f.mul_binary(a, b), "GF(2^{k}) {a} {b}");
                }
            }
        }
    }

    /// Field axioms over every element of every field up to 64 elements and
    /// of GF(2^8), GF(3^5) and GF(4096) on sampled triples: 0 and 1 are
    /// the identities, multiplication by a nonzero element is a bijection
    /// of the nonzero elements (so every element has an inverse, which
    /// holds only when the modulus is irreducible), and both operations
    /// commute, associate and distribute.
    #[test]
    fn fields_satisfy_the_axioms() {
        let mut state = 0x2545_f491_u32;
        let mut next = |q: u32| {
            state ^= state << 13;
            state ^= state >> 17;
            state ^= state << 5;
            state % q
        };
        for q in (2..=64).chain([81, 125, 128, 243, 256, 343, 1024, 2187, 3481, 4096]) {
            let Some(f) = Field::new(q) else { continue };
            assert_eq!(f.order(), q);
            if q <= 256 {
                for a in 1..q {
                    let mut seen = std::vec![false; q as usize];
                    for b in 0..q {
                        let c = f.mul(a, b);
                        assert!(c < q, "GF({q}): {a} {b} -> {c}");
                        assert!(!seen[c as usize], "GF({q}): {a} x is not a bijection");
                        seen[c as usize] = true;
                    }
                }
            }
            for _ in 0..2000 {
                let (a, b, c) = (next(q), next(q), next(q));
                assert_eq!(f.add(a, 0), a);
                assert_eq!(f.mul(a, 1), a);
                assert_eq!(f.mul(a, 0), 0);
                assert_eq!(f.add(a, b), f.add(b, a));
                assert_eq!(f.mul(a, b), f.mul(b, a), "GF({q}) {a} {b}");
                assert_eq!(f.add(f.add(a, b), c), f.add(a, f.add(b, c)));
                assert_eq!(f.mul(f.mul(a, b), c), f.mul(a, f.mul(b, c)), "GF({q})");
                assert_eq!(
                    f.mul(a, f.add(b, c)),
                    f.add(f.mul(a, b), f.mul(a, c)),
                    "GF({q})"
                );
                if f.divisor.get() == 2 {
                    assert_eq!(f.mul_binary(a, b), f.mul_digits(a, b), "GF({q})");
                    if f.k <= TABLED_DEGREE {
                        assert_eq!(f.mul_tabled(a, b), f.mul_binary(a, b), "GF({q})");
                    }
                    assert_eq!(f.add(a, b), f.add_digits(a, b));
                }
            }
            // The additive group has characteristic p: p copies of a sum to 0.
            let a = next(q);
            let mut sum = 0;
            for _ in 0..f.divisor.get() {
                sum = f.add(sum, a);
            }
            assert_eq!(sum, 0, "GF({q})");
        }
    }
}
