//! Golden values: the first samples of every sampler, pinned bit for bit.
//!
//! Sample values are part of wellspread's contract: a renderer that stores
//! seeds, or compares images across versions, relies on them. **Changing any
//! value below is a breaking change**: bump the version accordingly and record
//! it in CHANGELOG.md, saying which samplers changed and why.
//!
//! The values were generated from the implementation after the property tests
//! in `tests/samplers.rs` passed, then pasted here as literals (f32 bits via
//! `f32::to_bits`; the decimal value in each comment is for reading only).

use wellspread::hash::{
    hash_combine, hash_u32, pattern_seed, permute, rand_u32, stratum_to_unit_f32, u32_to_unit_f32,
};
use wellspread::{Sampler2D, SamplerKind};

/// (sampler name, n, pattern, the first 8 samples as `[x bits, y bits]`).
#[rustfmt::skip]
const GOLDEN: &[(&str, u32, u32, [[u32; 2]; 8])] = &[
    ("regular", 16, 0x0, [
        [0x3e000000, 0x3e000000], // (0.125, 0.125)
        [0x3ec00000, 0x3e000000], // (0.375, 0.125)
        [0x3f200000, 0x3e000000], // (0.625, 0.125)
        [0x3f600000, 0x3e000000], // (0.875, 0.125)
        [0x3ec00000, 0x3ec00000], // (0.375, 0.375)
        [0x3e000000, 0x3ec00000], // (0.125, 0.375)
        [0x3f600000, 0x3ec00000], // (0.875, 0.375)
        [0x3f200000, 0x3ec00000], // (0.625, 0.375)
    ]),
    ("regular", 16, 0xdeadbeef, [
        [0x3ec00000, 0x3ec00000], // (0.375, 0.375)
        [0x3f600000, 0x3e000000], // (0.875, 0.125)
        [0x3f600000, 0x3f200000], // (0.875, 0.625)
        [0x3f200000, 0x3ec00000], // (0.625, 0.375)
        [0x3f600000, 0x3f600000], // (0.875, 0.875)
        [0x3f600000, 0x3ec00000], // (0.875, 0.375)
        [0x3e000000, 0x3f200000], // (0.125, 0.625)
        [0x3f200000, 0x3e000000], // (0.625, 0.125)
    ]),
    ("regular", 100, 0x0, [
        [0x3d4cccd0, 0x3d4cccd0], // (0.050000012, 0.050000012)
        [0x3e19999c, 0x3d4cccd0], // (0.15000004, 0.050000012)
        [0x3e800000, 0x3d4cccd0], // (0.25, 0.050000012)
        [0x3eb33334, 0x3d4cccd0], // (0.35000002, 0.050000012)
        [0x3ee66666, 0x3d4cccd0], // (0.45, 0.050000012)
        [0x3f0ccccd, 0x3d4cccd0], // (0.55, 0.050000012)
        [0x3f266667, 0x3d4cccd0], // (0.65000004, 0.050000012)
        [0x3f400000, 0x3d4cccd0], // (0.75, 0.050000012)
    ]),
    ("regular", 100, 0xdeadbeef, [
        [0x3f400000, 0x3e19999c], // (0.75, 0.15000004)
        [0x3f733333, 0x3d4cccd0], // (0.95, 0.050000012)
        [0x3e800000, 0x3f0ccccd], // (0.25, 0.55)
        [0x3f59999a, 0x3f59999a], // (0.85, 0.85)
        [0x3ee66666, 0x3d4cccd0], // (0.45, 0.050000012)
        [0x3f266667, 0x3e800000], // (0.65000004, 0.25)
        [0x3e800000, 0x3f400000], // (0.25, 0.75)
        [0x3f59999a, 0x3eb33334], // (0.85, 0.35000002)
    ]),
    ("random", 16, 0x0, [
        [0x3f4d1ebc, 0x3f128a72], // (0.8012502, 0.572425)
        [0x3f5837e5, 0x3f3dfe06], // (0.8446029, 0.74215734)
        [0x3eb0f1a0, 0x3e1a79e4], // (0.34559345, 0.1508556)
        [0x3d6de3e0, 0x3df6bb60], // (0.058078647, 0.12047458)
        [0x3f150389, 0x3e9b0958], // (0.5820852, 0.30280566)
        [0x3f0f73cb, 0x3e7deebc], // (0.5603606, 0.24798101)
        [0x3f533fc1, 0x3f57e236], // (0.82519156, 0.84329545)
        [0x3f03036e, 0x3e29b3c4], // (0.5117711, 0.16572481)
    ]),
    ("random", 16, 0xdeadbeef, [
        [0x3f126bde, 0x3d6f4290], // (0.5719584, 0.05841309)
        [0x3f7465fa, 0x3e8615b0], // (0.95468104, 0.2618842)
        [0x3f3dee00, 0x3f4e75b8], // (0.74191284, 0.80648375)
        [0x3f0731f6, 0x3f32a2ea], // (0.5281061, 0.6977984)
        [0x3f097879, 0x3f22d7f0], // (0.5369945, 0.63610744)
        [0x3f4ce0a4, 0x3e10e7b4], // (0.80030274, 0.14150888)
        [0x3ec665b8, 0x3ea15172], // (0.3874948, 0.3150745)
        [0x3e2e30f4, 0x3f4e7a22], // (0.17010862, 0.8065511)
    ]),
    ("random", 100, 0x0, [
        [0x3f4d1ebc, 0x3f128a72], // (0.8012502, 0.572425)
        [0x3f5837e5, 0x3f3dfe06], // (0.8446029, 0.74215734)
        [0x3eb0f1a0, 0x3e1a79e4], // (0.34559345, 0.1508556)
        [0x3d6de3e0, 0x3df6bb60], // (0.058078647, 0.12047458)
        [0x3f150389, 0x3e9b0958], // (0.5820852, 0.30280566)
        [0x3f0f73cb, 0x3e7deebc], // (0.5603606, 0.24798101)
        [0x3f533fc1, 0x3f57e236], // (0.82519156, 0.84329545)
        [0x3f03036e, 0x3e29b3c4], // (0.5117711, 0.16572481)
    ]),
    ("random", 100, 0xdeadbeef, [
        [0x3f126bde, 0x3d6f4290], // (0.5719584, 0.05841309)
        [0x3f7465fa, 0x3e8615b0], // (0.95468104, 0.2618842)
        [0x3f3dee00, 0x3f4e75b8], // (0.74191284, 0.80648375)
        [0x3f0731f6, 0x3f32a2ea], // (0.5281061, 0.6977984)
        [0x3f097879, 0x3f22d7f0], // (0.5369945, 0.63610744)
        [0x3f4ce0a4, 0x3e10e7b4], // (0.80030274, 0.14150888)
        [0x3ec665b8, 0x3ea15172], // (0.3874948, 0.3150745)
        [0x3e2e30f4, 0x3f4e7a22], // (0.17010862, 0.8065511)
    ]),
    ("jittered", 16, 0x0, [
        [0x3d516600, 0x3e253128], // (0.051122665, 0.16132033)
        [0x3ef9d760, 0x3e4df46c], // (0.4879713, 0.20112771)
        [0x3f1bf433, 0x3d0a0cc0], // (0.60919493, 0.033703566)
        [0x3f5bf726, 0x3e0c6008], // (0.85923994, 0.13708508)
        [0x3ebbdf8a, 0x3eee3764], // (0.36693984, 0.46526635)
        [0x3e532888, 0x3edd866e], // (0.2062093, 0.43266624)
        [0x3f7c3210, 0x3ea3ef8a], // (0.9851389, 0.3201869)
        [0x3f13ae46, 0x3ec63b50], // (0.57687795, 0.38717127)
    ]),
    ("jittered", 16, 0xdeadbeef, [
        [0x3ea993d0, 0x3ecf58ec], // (0.33120584, 0.4049753)
        [0x3f7b42f1, 0x3dc8c9e0], // (0.9814902, 0.098041296)
        [0x3f73be5c, 0x3f226b85], // (0.9521234, 0.6344531)
        [0x3f37443a, 0x3eac025a], // (0.7158848, 0.33595544)
        [0x3f761633, 0x3f51f509], // (0.96127623, 0.8201452)
        [0x3f4df2d0, 0x3eda40a6], // (0.8044863, 0.42627448)
        [0x3d248270, 0x3f307e37], // (0.040163457, 0.6894259)
        [0x3f02cfd0, 0x3d7302c0], // (0.51098347, 0.059328794)
    ]),
    ("jittered", 100, 0x0, [
        [0x3ca784c0, 0x3d842758], // (0.020449042, 0.06452817)
        [0x3e47df84, 0x3da4c388], // (0.19518858, 0.08045107)
        [0x3e7986b8, 0x3c5ce140], // (0.24367797, 0.013481438)
        [0x3eaff8ec, 0x3d6099b0], // (0.343696, 0.054834068)
        [0x3ef7081a, 0x3d95a3e0], // (0.48248369, 0.07306647)
        [0x3f0bf982, 0x3db058a0], // (0.54677594, 0.08610654)
        [0x3f2178e9, 0x3d60bdd0], // (0.6307512, 0.05486852)
        [0x3f4b473a, 0x3ce5fd00], // (0.7940556, 0.028074741)
    ]),
    ("jittered", 100, 0xdeadbeef, [
        [0x3f39c7b6, 0x3e3a2690], // (0.7257036, 0.18178773)
        [0x3f787941, 0x3db9ca10], // (0.9706002, 0.090717435)
        [0x3e8d0566, 0x3f0701ff], // (0.2754318, 0.5273742)
        [0x3f4ea848, 0x3f62517b], // (0.80725527, 0.8840558)
        [0x3edaa626, 0x3cf64580], // (0.42704886, 0.030062437)
        [0x3f23cc7a, 0x3e604c7c], // (0.6398388, 0.21904176)
        [0x3e6b601c, 0x3f393aea], // (0.22985882, 0.7235552)
        [0x3f64e51f, 0x3eba8948], // (0.8941211, 0.36432862)
    ]),
    ("n-rooks", 16, 0x0, [
        [0x3c516600, 0x3d253120], // (0.012780666, 0.040330052)
        [0x3df9d760, 0x3de6fa30], // (0.12199283, 0.11278188)
        [0x3e1bf430, 0x3e08a0cc], // (0.15229869, 0.13342589)
        [0x3e5bf724, 0x3e631800], // (0.21480995, 0.22177124)
        [0x3eba6510, 0x3eb7619a], // (0.3640523, 0.35816652)
        [0x3e8ef7e2, 0x3e9b8dd8], // (0.27923495, 0.30381656)
        [0x3ee9d722, 0x3ef18ed4], // (0.45671946, 0.47179282)
        [0x3ede1908, 0x3ec8fbe2], // (0.43378472, 0.3925467)
    ]),
    ("n-rooks", 16, 0xdeadbeef, [
        [0x3f424d86, 0x3f77115d], // (0.7589954, 0.9651087)
        [0x3f729a3e, 0x3f2f25e2], // (0.94766605, 0.6841718)
        [0x3f30b3f4, 0x3e879816], // (0.69024587, 0.2648322)
        [0x3efda178, 0x3eec8c9e], // (0.49537253, 0.46201032)
        [0x3e114fb0, 0x3f54cf5b], // (0.14190555, 0.831289)
        [0x3f15327a, 0x3f39eb1d], // (0.58280146, 0.7262438)
        [0x3ebba21c, 0x3eab0096], // (0.36647117, 0.33398885)
        [0x3f037cb4, 0x3f6b4814], // (0.51362157, 0.9190686)
    ]),
    ("n-rooks", 100, 0x0, [
        [0x3b060400, 0x3bd37200], // (0.0020449162, 0.006452799)
        [0x3c9fe600, 0x3c93d360], // (0.019518852, 0.018045127)
        [0x3cc79f00, 0x3caee260], // (0.02436781, 0.021348178)
        [0x3d0cc720, 0x3d115710], // (0.034369588, 0.03548342)
        [0x3d45a010, 0x3d41c4a0], // (0.04824835, 0.047306657)
        [0x3d5ff590, 0x3d7011b0], // (0.054677546, 0.058610618)
        [0x3d812d88, 0x3d861df8], // (0.063075125, 0.06548685)
        [0x3da29f60, 0x3d951c18], // (0.079405546, 0.07280749)
    ]),
    ("n-rooks", 100, 0xdeadbeef, [
        [0x3e255054, 0x3f79736b], // (0.16143924, 0.9744174)
        [0x3f5a0433, 0x3f1e956c], // (0.8516266, 0.6194675)
        [0x3f668331, 0x3f713f5e], // (0.9004393, 0.94237316)
        [0x3ee6055c, 0x3e136034], // (0.44925964, 0.14392167)
        [0x3f64884f, 0x3f1a5e9e], // (0.8927049, 0.60300624)
        [0x3e649b30, 0x3ecada9a], // (0.22324824, 0.39619905)
        [0x3f237d9c, 0x3f4b1ec4], // (0.6386354, 0.7934382)
        [0x3e3a8d40, 0x3e68800c], // (0.18217945, 0.22705096)
    ]),
    ("multi-jittered", 16, 0x0, [
        [0x3d9a2cc0, 0x3d253120], // (0.07528067, 0.040330052)
        [0x3e9e75d8, 0x3e737d18], // (0.30949283, 0.23778188)
        [0x3f36fd0c, 0x3e08a0cc], // (0.7147987, 0.13342589)
        [0x3f76fdc9, 0x3dc63000], // (0.96480995, 0.09677124)
        [0x3ecef7e2, 0x3ebb8dd8], // (0.40423495, 0.36631656)
        [0x3e74ca20, 0x3ed7619a], // (0.2390523, 0.42066652)
        [0x3f4f0c84, 0x3e88fbe2], // (0.8087847, 0.2675467)
        [0x3f24eb91, 0x3ef18ed4], // (0.64421946, 0.47179282)
    ]),
    ("multi-jittered", 16, 0xdeadbeef, [
        [0x3eca64f4, 0x3e93d63a], // (0.39530146, 0.2887438)
        [0x3f7ed0bc, 0x3cc8c9e0], // (0.99537253, 0.024510324)
        [0x3f6cef97, 0x3f089ae1], // (0.92553085, 0.53361326)
        [0x3f0dd10e, 0x3ecb0096], // (0.5539712, 0.39648885)
        [0x3f4d858c, 0x3f447d42], // (0.802819, 0.7675363)
        [0x3f537cb4, 0x3eb69028], // (0.82612157, 0.35656857)
        [0x3c248240, 0x3f2c1f8d], // (0.01004082, 0.6723564)
        [0x3f30b3f4, 0x3d9e6058], // (0.69024587, 0.0773322)
    ]),
    ("multi-jittered", 100, 0x0, [
        [0x3dbc8208, 0x3cd8b3a0], // (0.09204489, 0.02645284)
        [0x3e4c4eac, 0x3d9fd620], // (0.19951886, 0.07804513)
        [0x3e7a3b8c, 0x3d525270], // (0.24436778, 0.05134815)
        [0x3e9bd654, 0x3d861c28], // (0.30436957, 0.06548339)
        [0x3ee580d0, 0x3d18cee0], // (0.4482484, 0.037306666)
        [0x3f131e12, 0x3c987560], // (0.5746776, 0.018610656)
        [0x3f29bf4a, 0x3dc38ea0], // (0.6630751, 0.09548688)
        [0x3f3d49ae, 0x3d2f56e0], // (0.7394055, 0.04280746)
    ]),
    ("multi-jittered", 100, 0xdeadbeef, [
        [0x3f4337d0, 0x3ddd8cd0], // (0.7625704, 0.108178735)
        [0x3f77913f, 0x3c14a1c0], // (0.96706, 0.009071767)
        [0x3e9338dc, 0x3f17bda4], // (0.28754318, 0.59273744)
        [0x3f5739ca, 0x3f60df30], // (0.84072554, 0.8784056)
        [0x3edd8b7e, 0x3d302750], // (0.43270487, 0.04300624)
        [0x3f1d2e0c, 0x3e8b3706], // (0.61398387, 0.27190417)
        [0x3e8bc4ce, 0x3f4ad7cf], // (0.27298588, 0.7923555)
        [0x3f663fdf, 0x3eac40ee], // (0.8994121, 0.33643287)
    ]),
    ("correlated-multi-jittered", 16, 0x0, [
        [0x3d9a2cc0, 0x3dd29890], // (0.07528067, 0.10283005)
        [0x3ebe75d8, 0x3e337d18], // (0.37199283, 0.17528188)
        [0x3f16fd0c, 0x3e48a0cc], // (0.5897987, 0.19592589)
        [0x3f56fdc9, 0x3d0c6000], // (0.83980995, 0.03427124)
        [0x3ecef7e2, 0x3edb8dd8], // (0.40423495, 0.42881656)
        [0x3e34ca20, 0x3eb7619a], // (0.1765523, 0.35816652)
        [0x3f6f0c84, 0x3e88fbe2], // (0.9337847, 0.2675467)
        [0x3f24eb91, 0x3ef18ed4], // (0.64421946, 0.47179282)
    ]),
    ("correlated-multi-jittered", 16, 0xdeadbeef, [
        [0x3eea64f4, 0x3eb3d63a], // (0.45780146, 0.3512438)
        [0x3f4ed0bc, 0x3e19193c], // (0.80787253, 0.14951032)
        [0x3f5cef97, 0x3f289ae1], // (0.86303085, 0.65861326)
        [0x3f3dd10e, 0x3e8b0096], // (0.7414712, 0.27148885)
        [0x3f6d858c, 0x3f647d42], // (0.927819, 0.8925363)
        [0x3f737cb4, 0x3ed69028], // (0.95112157, 0.41906857)
        [0x3d949048, 0x3f3c1f8d], // (0.07254082, 0.7348564)
        [0x3f00b3f4, 0x3c7302c0], // (0.50274587, 0.014832199)
    ]),
    ("correlated-multi-jittered", 100, 0x0, [
        [0x3b060400, 0x3bd37200], // (0.0020449162, 0.006452799)
        [0x3de04b68, 0x3c93d360], // (0.109518826, 0.018045127)
        [0x3e5145cc, 0x3caee260], // (0.20436782, 0.021348178)
        [0x3e9bd654, 0x3d115710], // (0.30436957, 0.03548342)
        [0x3ed105ee, 0x3d6aba60], // (0.40824836, 0.057306647)
        [0x3f01328d, 0x3d471bf0], // (0.5046776, 0.048610628)
        [0x3f1a6321, 0x3d9a98e0], // (0.6030751, 0.0754869)
        [0x3f359b9a, 0x3d80a130], // (0.70940554, 0.06280744)
    ]),
    ("correlated-multi-jittered", 100, 0xdeadbeef, [
        [0x3f485688, 0x3ddd8cd0], // (0.78257036, 0.108178735)
        [0x3f683516, 0x3cee27e0], // (0.90706, 0.029071748)
        [0x3e8e1a24, 0x3f100f8f], // (0.2775432, 0.5627374)
        [0x3f521b12, 0x3f56a1c0], // (0.82072556, 0.8384056)
        [0x3ece2f56, 0x3dbe7a10], // (0.4027049, 0.09300625)
        [0x3f31a8ee, 0x3e9055be], // (0.6939839, 0.28190416)
        [0x3e86a616, 0x3f4329bb], // (0.2629859, 0.7623555)
        [0x3f5c026e, 0x3eac40ee], // (0.8594121, 0.33643287)
    ]),
];

#[test]
fn first_samples_are_pinned() {
    for &(name, n, pattern, expected) in GOLDEN {
        let kind: SamplerKind = name.parse().unwrap();
        let sampler = kind.build(n).unwrap();
        for (index, want) in (0..).zip(expected) {
            let p = sampler.sample(index, pattern);
            assert_eq!(
                [p.x.to_bits(), p.y.to_bits()],
                want,
                "{name} n = {n} pattern {pattern:#x} index {index}: got ({}, {}), pinned ({}, {})",
                p.x,
                p.y,
                f32::from_bits(want[0]),
                f32::from_bits(want[1]),
            );
        }
        // fill must agree with the pinned values too.
        let mut filled = [wellspread::glam::Vec2::ZERO; 8];
        sampler.fill(pattern, &mut filled);
        for (p, want) in filled.iter().zip(expected) {
            assert_eq!([p.x.to_bits(), p.y.to_bits()], want, "{name} fill");
        }
    }
}

#[test]
fn the_six_samplers_are_all_pinned() {
    for name in [
        "regular",
        "random",
        "jittered",
        "n-rooks",
        "multi-jittered",
        "correlated-multi-jittered",
    ] {
        let mut cases: Vec<(u32, u32)> = GOLDEN
            .iter()
            .filter(|g| g.0 == name)
            .map(|g| (g.1, g.2))
            .collect();
        cases.sort_unstable();
        assert_eq!(
            cases,
            [(16, 0), (16, 0xdead_beef), (100, 0), (100, 0xdead_beef)],
            "{name}"
        );
    }
}

/// The arguments of `pattern_seed`: `(x, y, frame, dimension)`.
type PixelFrameDimension = (u32, u32, u32, u32);

/// `pattern_seed(x, y, frame, dimension)`: renderers store and derive
/// patterns from it, so its values are pinned like the samples.
#[test]
fn pattern_seeds_are_pinned() {
    #[rustfmt::skip]
    let pinned: &[(PixelFrameDimension, u32)] = &[
    ((0, 0, 0, 0), 0x1a5905f6),
    ((1, 0, 0, 0), 0x87e58df0),
    ((0, 1, 0, 0), 0xded7d127),
    ((0, 0, 1, 0), 0x3244c546),
    ((0, 0, 0, 1), 0x47cc53fb),
    ((120, 45, 0, 0), 0x136c10a7),
    ((120, 45, 7, 3), 0x66d0781e),
    ((1919, 1079, 59, 12), 0x9a107ad1),
    ((4294967295, 4294967295, 4294967295, 4294967295), 0x0c2bc6ba),
    ];
    for &((x, y, frame, dimension), want) in pinned {
        assert_eq!(
            pattern_seed(x, y, frame, dimension),
            want,
            "pattern_seed({x}, {y}, {frame}, {dimension})"
        );
    }
}

/// The primitives every sampler is built from.
#[test]
fn hash_primitives_are_pinned() {
    assert_eq!(hash_u32(0x0), 0x00000000);
    assert_eq!(hash_u32(0x1), 0x688990c0);
    assert_eq!(hash_u32(0x2), 0xd1132181);
    assert_eq!(hash_u32(0xdeadbeef), 0xe628c683);
    assert_eq!(hash_u32(0xffffffff), 0x6768824a);
    assert_eq!(hash_combine(0x0, 0), 0x01fce552);
    assert_eq!(hash_combine(0x1, 2), 0x6287eb6e);
    assert_eq!(hash_combine(0xdeadbeef, 7), 0x88cc31ae);
    assert_eq!(rand_u32(0, 0x0), 0xdf6e5fc8);
    assert_eq!(rand_u32(1, 0x2), 0xf6f8e090);
    assert_eq!(rand_u32(5, 0xdeadbeef), 0xe7f686d1);
    assert_eq!(permute(0, 1, 0x0), 0);
    assert_eq!(permute(3, 10, 0x2a), 3);
    // Short lengths are Fisher-Yates shuffles, 9 to 32 take five rounds:
    // pinned too.
    assert_eq!(permute(1, 4, 0x0), 2);
    assert_eq!(permute(2, 6, 0xdeadbeef), 1);
    assert_eq!(permute(5, 20, 0x3), 10);
    assert_eq!(permute(0, 16, 0xdeadbeef), 14);
    assert_eq!(permute(99, 100, 0x7), 84);
    assert_eq!(permute(12345, 1 << 24, 0x1234_5678), 3162989);
    assert_eq!(permute(0, 4294967295, 0x1), 818759797);
    assert_eq!(u32_to_unit_f32(0x8000_0000), 0.5);
    assert_eq!(u32_to_unit_f32(u32::MAX).to_bits(), 0x3f7f_ffff);
    assert_eq!(stratum_to_unit_f32(2, 3, 0).to_bits(), 0x3f2a_aaab);
    assert_eq!(stratum_to_unit_f32(0, 1, 1 << 31), 0.5);
}
