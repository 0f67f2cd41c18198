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
        [0x3f600000, 0x3f600000], // (0.875, 0.875)
        [0x3e000000, 0x3e000000], // (0.125, 0.125)
        [0x3e000000, 0x3ec00000], // (0.125, 0.375)
        [0x3f200000, 0x3f200000], // (0.625, 0.625)
        [0x3f200000, 0x3f600000], // (0.625, 0.875)
        [0x3ec00000, 0x3f600000], // (0.375, 0.875)
        [0x3ec00000, 0x3ec00000], // (0.375, 0.375)
        [0x3f600000, 0x3ec00000], // (0.875, 0.375)
    ]),
    ("regular", 16, 0xdeadbeef, [
        [0x3e000000, 0x3ec00000], // (0.125, 0.375)
        [0x3f200000, 0x3ec00000], // (0.625, 0.375)
        [0x3e000000, 0x3f600000], // (0.125, 0.875)
        [0x3ec00000, 0x3f200000], // (0.375, 0.625)
        [0x3f200000, 0x3f200000], // (0.625, 0.625)
        [0x3f600000, 0x3f200000], // (0.875, 0.625)
        [0x3f200000, 0x3f600000], // (0.625, 0.875)
        [0x3e000000, 0x3f200000], // (0.125, 0.625)
    ]),
    ("regular", 100, 0x0, [
        [0x3f400000, 0x3f400000], // (0.75, 0.75)
        [0x3e19999c, 0x3ee66666], // (0.15000004, 0.45)
        [0x3f400000, 0x3e19999c], // (0.75, 0.15000004)
        [0x3f733333, 0x3eb33334], // (0.95, 0.35000002)
        [0x3e800000, 0x3f733333], // (0.25, 0.95)
        [0x3eb33334, 0x3f266667], // (0.35000002, 0.65000004)
        [0x3ee66666, 0x3f400000], // (0.45, 0.75)
        [0x3e19999c, 0x3e19999c], // (0.15000004, 0.15000004)
    ]),
    ("regular", 100, 0xdeadbeef, [
        [0x3f0ccccd, 0x3d4cccd0], // (0.55, 0.050000012)
        [0x3f0ccccd, 0x3e19999c], // (0.55, 0.15000004)
        [0x3eb33334, 0x3d4cccd0], // (0.35000002, 0.050000012)
        [0x3e19999c, 0x3eb33334], // (0.15000004, 0.35000002)
        [0x3f59999a, 0x3e800000], // (0.85, 0.25)
        [0x3f400000, 0x3e800000], // (0.75, 0.25)
        [0x3ee66666, 0x3f733333], // (0.45, 0.95)
        [0x3eb33334, 0x3f266667], // (0.35000002, 0.65000004)
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
        [0x3f453189, 0x3f640d7f], // (0.7702871, 0.89083093)
        [0x3d516600, 0x3e253128], // (0.051122665, 0.16132033)
        [0x3e532888, 0x3edd866e], // (0.2062093, 0.43266624)
        [0x3f26d01d, 0x3f27df77], // (0.65161306, 0.65575355)
        [0x3f22aec3, 0x3f46b4b8], // (0.63547915, 0.77619505)
        [0x3ed76ee4, 0x3f40a452], // (0.4207679, 0.7525073)
        [0x3ebbdf8a, 0x3eee3764], // (0.36693984, 0.46526635)
        [0x3f7c3210, 0x3ea3ef8a], // (0.9851389, 0.3201869)
    ]),
    ("jittered", 16, 0xdeadbeef, [
        [0x3d8a7d80, 0x3ea67adc], // (0.067622185, 0.3251561)
        [0x3f37443a, 0x3eac025a], // (0.7158848, 0.33595544)
        [0x3e632320, 0x3f74ba38], // (0.22181368, 0.9559665)
        [0x3eda5e46, 0x3f3a0f25], // (0.4265005, 0.7267936)
        [0x3f08e25f, 0x3f31cea4], // (0.53470415, 0.69455934)
        [0x3f73be5c, 0x3f226b85], // (0.9521234, 0.6344531)
        [0x3f364cb6, 0x3f6578d5], // (0.712108, 0.896375)
        [0x3d248270, 0x3f307e37], // (0.040163457, 0.6894259)
    ]),
    ("jittered", 100, 0x0, [
        [0x3f44a980, 0x3f341be7], // (0.76821136, 0.70355076)
        [0x3e24f428, 0x3eff4a78], // (0.16108763, 0.49861503)
        [0x3f3b5c28, 0x3e11d608], // (0.73187494, 0.14241803)
        [0x3f69fa20, 0x3eacafa6], // (0.91397285, 0.3372776)
        [0x3e78926c, 0x3f78e328], // (0.24274606, 0.9722161)
        [0x3eb5c748, 0x3f25397c], // (0.35503602, 0.6454084)
        [0x3eef248a, 0x3f475016], // (0.46707565, 0.77856576)
        [0x3e3d7b00, 0x3df50868], // (0.18503952, 0.11964494)
    ]),
    ("jittered", 100, 0xdeadbeef, [
        [0x3f0850c3, 0x3d7de960], // (0.5324823, 0.061990142)
        [0x3f15a27b, 0x3e0321a8], // (0.5845105, 0.12805808)
        [0x3ec9025a, 0x3d20a180], // (0.39259607, 0.03921652)
        [0x3e324638, 0x3ea26c46], // (0.17409599, 0.3172323)
        [0x3f589a7c, 0x3e970a80], // (0.84610724, 0.29500198)
        [0x3f3bcfbe, 0x3e5ed8c4], // (0.73363864, 0.21762377)
        [0x3ef03f9a, 0x3f752d80], // (0.46923524, 0.9577255)
        [0x3eab0da0, 0x3f19d39d], // (0.33408833, 0.6008852)
    ]),
    ("n-rooks", 16, 0x0, [
        [0x3f434598, 0x3f1a5312], // (0.76278067, 0.60283005)
        [0x3f0f3aec, 0x3f7cdf46], // (0.5594928, 0.9877819)
        [0x3e8dfa18, 0x3f622833], // (0.2772987, 0.8834259)
        [0x3db7ee48, 0x3f38c600], // (0.089809954, 0.72177124)
        [0x3efa6510, 0x3eb7619a], // (0.4890523, 0.35816652)
        [0x3e5defc4, 0x3f2dc6ec], // (0.21673495, 0.67881656)
        [0x3f24eb91, 0x3ed18ed4], // (0.64421946, 0.40929282)
        [0x3ede1908, 0x3e11f7c4], // (0.43378472, 0.14254671)
    ]),
    ("n-rooks", 16, 0xdeadbeef, [
        [0x3f424d86, 0x3f27115d], // (0.7589954, 0.6526087)
        [0x3c268f80, 0x3f1f25e2], // (0.010166049, 0.6216718)
        [0x3f10b3f4, 0x3d9e6058], // (0.56524587, 0.0773322)
        [0x3ebda178, 0x3f36464f], // (0.37037253, 0.7120103)
        [0x3e514fb0, 0x3f04cf5b], // (0.20440555, 0.518789)
        [0x3f75327a, 0x3ed3d63a], // (0.95780146, 0.4137438)
        [0x3f2dd10e, 0x3e16012c], // (0.6789712, 0.14648885)
        [0x3f637cb4, 0x3e969028], // (0.88862157, 0.29406857)
    ]),
    ("n-rooks", 100, 0x0, [
        [0x3f4d52d0, 0x3efe2f10], // (0.80204487, 0.4964528)
        [0x3f0a1de8, 0x3e408ee8], // (0.53951883, 0.18804514)
        [0x3eab3242, 0x3f59f1f4], // (0.3343678, 0.85134816)
        [0x3f2ca37c, 0x3f10c385], // (0.6743696, 0.5654834)
        [0x3f569772, 0x3e7d3df4], // (0.8382484, 0.24730664)
        [0x3f108eb6, 0x3e84689e], // (0.5646776, 0.25861067)
        [0x3cbd0800, 0x3f15e278], // (0.023075104, 0.5854869)
        [0x3da29f60, 0x3e4facc4], // (0.079405546, 0.20280749)
    ]),
    ("n-rooks", 100, 0xdeadbeef, [
        [0x3d924ec0, 0x3dfece88], // (0.071439266, 0.124417365)
        [0x3f6befb8, 0x3f44fbd3], // (0.92162657, 0.76946753)
        [0x3f70c0a2, 0x3ef1dae4], // (0.94043934, 0.47237313)
        [0x3f596914, 0x3e27db14], // (0.8492596, 0.16392165)
        [0x3d57e110, 0x3b450400], // (0.05270487, 0.0030062199)
        [0x3e81a9c0, 0x3e0b77c4], // (0.2532482, 0.13619906)
        [0x3eb28056, 0x3f12ccd9], // (0.34863538, 0.5734382)
        [0x3ec3ad08, 0x3ed587b4], // (0.3821795, 0.41705096)
    ]),
    ("multi-jittered", 16, 0x0, [
        [0x3f714c62, 0x3f49035f], // (0.94257176, 0.7852077)
        [0x3e4d1660, 0x3d253120], // (0.20028067, 0.040330052)
        [0x3de99440, 0x3ef7619a], // (0.114052296, 0.48316652)
        [0x3f29b407, 0x3f19f7dd], // (0.66290325, 0.60143834)
        [0x3f18abb0, 0x3f61ad2e], // (0.59636974, 0.88154876)
        [0x3ed5dbb8, 0x3f502914], // (0.41769195, 0.8131268)
        [0x3e8ef7e2, 0x3ebb8dd8], // (0.27923495, 0.36631656)
        [0x3f4f0c84, 0x3e88fbe2], // (0.8087847, 0.2675467)
    ]),
    ("multi-jittered", 16, 0xdeadbeef, [
        [0x3da29f60, 0x3ec99eb6], // (0.079405546, 0.393789)
        [0x3f2dd10e, 0x3e8b0096], // (0.6789712, 0.27148885)
        [0x3e78c8c8, 0x3f5d2e8e], // (0.24295342, 0.8639916)
        [0x3e969790, 0x3f0e83c9], // (0.29412508, 0.5566984)
        [0x3f123897, 0x3f1c73a9], // (0.571176, 0.61113983)
        [0x3f6cef97, 0x3f389ae1], // (0.92553085, 0.72111326)
        [0x3f3d932d, 0x3f795e35], // (0.740527, 0.97409374)
        [0x3e0a4824, 0x3f2c1f8d], // (0.13504082, 0.6723564)
    ]),
    ("multi-jittered", 100, 0x0, [
        [0x3f34f23b, 0x3f42a6a2], // (0.70682114, 0.7603551)
        [0x3e3e934c, 0x3efacf20], // (0.18610877, 0.4898615)
        [0x3f487efa, 0x3e46e754], // (0.7831875, 0.19424182)
        [0x3f6be0b1, 0x3eaade5e], // (0.92139727, 0.33372778)
        [0x3e874f00, 0x3f727d1e], // (0.2642746, 0.94722164)
        [0x3eca7f74, 0x3f2500a1], // (0.39550364, 0.64454085)
        [0x3efe5074, 0x3f3a54cf], // (0.49670756, 0.7278566)
        [0x3e0dd3fc, 0x3e301774], // (0.13850397, 0.17196447)
    ]),
    ("multi-jittered", 100, 0xdeadbeef, [
        [0x3f00d4e0, 0x3d3d3b30], // (0.5032482, 0.046199024)
        [0x3f074891, 0x3e07fe40], // (0.528451, 0.13280582)
        [0x3ea894b8, 0x3d5cdcf0], // (0.32925963, 0.05392164)
        [0x3e16f28c, 0x3ec88ff2], // (0.14740962, 0.39172322)
        [0x3f5ac7c5, 0x3e89fbee], // (0.85461074, 0.2695002)
        [0x3f3e4d18, 0x3e6315ac], // (0.74336386, 0.22176236)
        [0x3efe6cc2, 0x3f74ad83], // (0.4969235, 0.9557726)
        [0x3eafd348, 0x3f214d7c], // (0.34340882, 0.63008857)
    ]),
    ("correlated-multi-jittered", 16, 0x0, [
        [0x3f414c62, 0x3f69035f], // (0.75507176, 0.9102077)
        [0x3e4d1660, 0x3d253120], // (0.20028067, 0.040330052)
        [0x3de99440, 0x3e97619a], // (0.114052296, 0.29566652)
        [0x3f29b407, 0x3f39f7dd], // (0.66290325, 0.72643834)
        [0x3f08abb0, 0x3f71ad2e], // (0.53386974, 0.94404876)
        [0x3e95dbb8, 0x3f502914], // (0.29269195, 0.8131268)
        [0x3eaef7e2, 0x3ebb8dd8], // (0.34173495, 0.36631656)
        [0x3f5f0c84, 0x3ec8fbe2], // (0.8712847, 0.3925467)
    ]),
    ("correlated-multi-jittered", 16, 0xdeadbeef, [
        [0x3e114fb0, 0x3e899eb6], // (0.14190555, 0.268789)
        [0x3f2dd10e, 0x3eeb0096], // (0.6789712, 0.45898885)
        [0x3df19190, 0x3f4d2e8e], // (0.11795342, 0.8014916)
        [0x3ef69790, 0x3f1e83c9], // (0.48162508, 0.6191984)
        [0x3f323897, 0x3f3c73a9], // (0.696176, 0.73613983)
        [0x3f7cef97, 0x3f289ae1], // (0.98803085, 0.65861326)
        [0x3f1d932d, 0x3f795e35], // (0.615527, 0.97409374)
        [0x3e4a4824, 0x3f0c1f8d], // (0.19754082, 0.5473564)
    ]),
    ("correlated-multi-jittered", 100, 0x0, [
        [0x3f3a10f3, 0x3f334a79], // (0.7268211, 0.7003551)
        [0x3e0b6018, 0x3eeb72f8], // (0.13610876, 0.45986152)
        [0x3f3e4189, 0x3dd57cb8], // (0.7431875, 0.10424179)
        [0x3f738ec6, 0x3eaffd16], // (0.9513973, 0.34372777)
        [0x3e5b6acc, 0x3f779bd6], // (0.21427459, 0.9672216)
        [0x3ebb234a, 0x3f227145], // (0.3655036, 0.63454086)
        [0x3eda796a, 0x3f47219c], // (0.42670757, 0.7778566)
        [0x3e18116c, 0x3e1b9c94], // (0.14850396, 0.15196449)
    ]),
    ("correlated-multi-jittered", 100, 0xdeadbeef, [
        [0x3f103109, 0x3db08920], // (0.5632482, 0.086199045)
        [0x3f0c6749, 0x3e3b3170], // (0.548451, 0.18280578)
        [0x3ebd0f98, 0x3d0af170], // (0.3692596, 0.03392166)
        [0x3e4a25c0, 0x3e9f9a30], // (0.19740963, 0.31172323)
        [0x3f55a90d, 0x3e7f7cf8], // (0.83461076, 0.24950016)
        [0x3f3bbdbc, 0x3e9561e0], // (0.73336387, 0.29176235)
        [0x3ee9f1e2, 0x3f67e0b6], // (0.45692354, 0.90577257)
        [0x3ea595d8, 0x3f214d7c], // (0.32340884, 0.63008857)
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
    // Short lengths take more rounds (13 up to 8, 5 up to 32): pinned too.
    assert_eq!(permute(1, 4, 0x0), 0);
    assert_eq!(permute(2, 6, 0xdeadbeef), 3);
    assert_eq!(permute(5, 20, 0x3), 7);
    assert_eq!(permute(0, 16, 0xdeadbeef), 7);
    assert_eq!(permute(99, 100, 0x7), 22);
    assert_eq!(permute(12345, 1 << 24, 0x1234_5678), 12712790);
    assert_eq!(permute(0, 4294967295, 0x1), 2808128383);
    assert_eq!(u32_to_unit_f32(0x8000_0000), 0.5);
    assert_eq!(u32_to_unit_f32(u32::MAX).to_bits(), 0x3f7f_ffff);
    assert_eq!(stratum_to_unit_f32(2, 3, 0).to_bits(), 0x3f2a_aaab);
    assert_eq!(stratum_to_unit_f32(0, 1, 1 << 31), 0.5);
}

/// `ZSobol` (a `PixelSampler`, so not in the table above): samples 0..8 of
/// one pixel and dimension pair, as `[x bits, y bits]`, at an even and an
/// odd log2(spp). Cross-checked against an independent Python
/// transcription of the algorithm in `ZSobol`'s docs.
/// (spp, resolution, seed, pixel, dimension, samples as `[x bits, y bits]`).
type ZSobolCase = (u32, [u32; 2], u32, [u32; 2], u32, [[u32; 2]; 8]);

#[rustfmt::skip]
const ZSOBOL_GOLDEN: &[ZSobolCase] = &[
    (16, [64, 48], 0x0, [5, 9], 0, [
        [0x3c316000, 0x3f3a2ed1], // (0.010826111, 0.72727686)
        [0x3f24b54e, 0x3e97ef0e], // (0.6433915, 0.29674572)
        [0x3f69c6be, 0x3f48e7c0], // (0.9131888, 0.7847862)
        [0x3ea36270, 0x3dcf78f8], // (0.3191104, 0.10130495)
        [0x3e6099a0, 0x3f5fbb0a], // (0.21933603, 0.87394774)
        [0x3ec25c7e, 0x3ea1237a], // (0.3796119, 0.3147238)
        [0x3f509874, 0x3f258cb6], // (0.81482625, 0.6466783)
        [0x3f1f8865, 0x3c778d40], // (0.62317497, 0.01510936)
    ]),
    (8, [1920, 1080], 0xdeadbeef, [1000, 700], 3, [
        [0x3e95dca4, 0x3f2a46e8], // (0.29269898, 0.66514444)
        [0x3f3b49b3, 0x3d4f8470], // (0.7315933, 0.05066341)
        [0x3ef2e2c0, 0x3e708704], // (0.47438622, 0.23489004)
        [0x3f047a29, 0x3f1ac279], // (0.517489, 0.6045299)
        [0x3f770d77, 0x3f54d498], // (0.9650492, 0.8313689)
        [0x3e533ad8, 0x3ec8fa7a], // (0.20627916, 0.39253598)
        [0x3f4997aa, 0x3e8546ec], // (0.78747046, 0.26030672)
        [0x3dc433d0, 0x3f7f5320], // (0.09580195, 0.99736214)
    ]),
];

#[test]
fn zsobol_samples_are_pinned() {
    use wellspread::{PixelSampler, ZSobol};
    for &(spp, resolution, seed, pixel, dimension, expected) in ZSOBOL_GOLDEN {
        let zsobol = ZSobol::new(spp, resolution, seed).unwrap();
        for (index, &[x, y]) in (0..).zip(&expected) {
            let p = zsobol.sample_pixel(pixel, index, dimension);
            assert_eq!(
                [p.x.to_bits(), p.y.to_bits()],
                [x, y],
                "zsobol spp {spp} seed {seed:#x} pixel {pixel:?} dimension {dimension} index {index}"
            );
        }
    }
}
