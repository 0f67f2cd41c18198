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
        [0x3f600000, 0x3e000000], // (0.875, 0.125)
        [0x3ec00000, 0x3f200000], // (0.375, 0.625)
        [0x3ec00000, 0x3e000000], // (0.375, 0.125)
        [0x3f200000, 0x3ec00000], // (0.625, 0.375)
        [0x3f200000, 0x3e000000], // (0.625, 0.125)
        [0x3f600000, 0x3ec00000], // (0.875, 0.375)
        [0x3e000000, 0x3f200000], // (0.125, 0.625)
        [0x3e000000, 0x3e000000], // (0.125, 0.125)
    ]),
    ("regular", 16, 0xdeadbeef, [
        [0x3e000000, 0x3f600000], // (0.125, 0.875)
        [0x3ec00000, 0x3f600000], // (0.375, 0.875)
        [0x3ec00000, 0x3ec00000], // (0.375, 0.375)
        [0x3f200000, 0x3e000000], // (0.625, 0.125)
        [0x3f600000, 0x3ec00000], // (0.875, 0.375)
        [0x3f200000, 0x3ec00000], // (0.625, 0.375)
        [0x3f600000, 0x3e000000], // (0.875, 0.125)
        [0x3f200000, 0x3f200000], // (0.625, 0.625)
    ]),
    ("regular", 100, 0x0, [
        [0x3f0ccccd, 0x3f400000], // (0.55, 0.75)
        [0x3f733333, 0x3eb33334], // (0.95, 0.35000002)
        [0x3eb33334, 0x3eb33334], // (0.35000002, 0.35000002)
        [0x3f266667, 0x3eb33334], // (0.65000004, 0.35000002)
        [0x3eb33334, 0x3f0ccccd], // (0.35000002, 0.55)
        [0x3e800000, 0x3e800000], // (0.25, 0.25)
        [0x3d4cccd0, 0x3eb33334], // (0.050000012, 0.35000002)
        [0x3e19999c, 0x3e19999c], // (0.15000004, 0.15000004)
    ]),
    ("regular", 100, 0xdeadbeef, [
        [0x3e19999c, 0x3d4cccd0], // (0.15000004, 0.050000012)
        [0x3f0ccccd, 0x3f733333], // (0.55, 0.95)
        [0x3f59999a, 0x3eb33334], // (0.85, 0.35000002)
        [0x3f0ccccd, 0x3e800000], // (0.55, 0.25)
        [0x3f266667, 0x3f733333], // (0.65000004, 0.95)
        [0x3e19999c, 0x3f733333], // (0.15000004, 0.95)
        [0x3ee66666, 0x3f266667], // (0.45, 0.65000004)
        [0x3e800000, 0x3eb33334], // (0.25, 0.35000002)
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
        [0x3f5bf726, 0x3e0c6008], // (0.85923994, 0.13708508)
        [0x3ef316ee, 0x3f149290], // (0.4747843, 0.58036137)
        [0x3ef9d760, 0x3e4df46c], // (0.4879713, 0.20112771)
        [0x3f13ae46, 0x3ec63b50], // (0.57687795, 0.38717127)
        [0x3f1bf433, 0x3d0a0cc0], // (0.60919493, 0.033703566)
        [0x3f7c3210, 0x3ea3ef8a], // (0.9851389, 0.3201869)
        [0x3d33ab40, 0x3f03a286], // (0.04386449, 0.51419866)
        [0x3d516600, 0x3e253128], // (0.051122665, 0.16132033)
    ]),
    ("jittered", 16, 0xdeadbeef, [
        [0x3e632320, 0x3f74ba38], // (0.22181368, 0.9559665)
        [0x3eb0dc04, 0x3f476a3a], // (0.3454286, 0.77896464)
        [0x3ea993d0, 0x3ecf58ec], // (0.33120584, 0.4049753)
        [0x3f02cfd0, 0x3d7302c0], // (0.51098347, 0.059328794)
        [0x3f4df2d0, 0x3eda40a6], // (0.8044863, 0.42627448)
        [0x3f37443a, 0x3eac025a], // (0.7158848, 0.33595544)
        [0x3f7b42f1, 0x3dc8c9e0], // (0.9814902, 0.098041296)
        [0x3f08e25f, 0x3f31cea4], // (0.53470415, 0.69455934)
    ]),
    ("jittered", 100, 0x0, [
        [0x3f05f750, 0x3f38e051], // (0.52330494, 0.7221728)
        [0x3f69fa20, 0x3eacafa6], // (0.91397285, 0.3372776)
        [0x3ea1cb1e, 0x3e9e91b6], // (0.3160028, 0.30970544)
        [0x3f270151, 0x3eaf9f08], // (0.65236384, 0.3430102)
        [0x3ea001ea, 0x3f0859a0], // (0.3125146, 0.53261757)
        [0x3e706d40, 0x3e88cff6], // (0.23479176, 0.26721162)
        [0x3ce2ae60, 0x3ea2ad10], // (0.02767104, 0.3177266)
        [0x3e3d7b00, 0x3df50868], // (0.18503952, 0.11964494)
    ]),
    ("jittered", 100, 0xdeadbeef, [
        [0x3dee1cb8, 0x3dc1e4e8], // (0.116265714, 0.094674885)
        [0x3f0f0740, 0x3f76a512], // (0.5587044, 0.9634563)
        [0x3f64e51f, 0x3eba8948], // (0.8941211, 0.36432862)
        [0x3f171a46, 0x3e86af0c], // (0.59024465, 0.26305425)
        [0x3f1b695d, 0x3f7aa1ba], // (0.60707647, 0.97903025)
        [0x3e410d60, 0x3f7b0392], // (0.18852758, 0.9805232)
        [0x3ed4800e, 0x3f2b8404], // (0.41503948, 0.66998315)
        [0x3e50c364, 0x3ec54440], // (0.20387036, 0.38528633)
    ]),
    ("n-rooks", 16, 0x0, [
        [0x3e0d1660, 0x3f3a5312], // (0.13778067, 0.72783005)
        [0x3f6f3aec, 0x3ef9be8c], // (0.9344928, 0.48778188)
        [0x3f46fd0c, 0x3c0a0cc0], // (0.7772987, 0.008425891)
        [0x3f36fdc9, 0x3e631800], // (0.71480995, 0.22177124)
        [0x3f7d3288, 0x3eb7619a], // (0.9890523, 0.35816652)
        [0x3f177bf1, 0x3f2dc6ec], // (0.59173495, 0.67881656)
        [0x3ee9d722, 0x3f48c76a], // (0.45671946, 0.7842928)
        [0x3e9e1908, 0x3e88fbe2], // (0.30878472, 0.2675467)
    ]),
    ("n-rooks", 16, 0xdeadbeef, [
        [0x3e493618, 0x3e1c4574], // (0.19649541, 0.1526087)
        [0x3f629a3e, 0x3f6f25e2], // (0.88516605, 0.9341718)
        [0x3b33f400, 0x3f23cc0b], // (0.0027458668, 0.6398322)
        [0x3f1ed0bc, 0x3eac8c9e], // (0.62037253, 0.33701032)
        [0x3ee8a7d8, 0x3e899eb6], // (0.45440555, 0.268789)
        [0x3e8a64f4, 0x3f49eb1d], // (0.27030146, 0.7887438)
        [0x3f2dd10e, 0x3e56012c], // (0.6789712, 0.20898885)
        [0x3f337cb4, 0x3f0b4814], // (0.70112157, 0.5440686)
    ]),
    ("n-rooks", 100, 0x0, [
        [0x3edd34fe, 0x3e5da5d0], // (0.43204492, 0.21645284)
        [0x3df4c648, 0x3f37d1ce], // (0.11951882, 0.7180451)
        [0x3f107a68, 0x3ec85eca], // (0.5643678, 0.39134818)
        [0x3ee3846a, 0x3f468615], // (0.4443696, 0.7754834)
        [0x3f30310c, 0x3eacb376], // (0.6882484, 0.33730668)
        [0x3c707a40, 0x3f289ab5], // (0.014677584, 0.65861064)
        [0x3ed37e94, 0x3e482db8], // (0.4130751, 0.1954869)
        [0x3c1a19c0, 0x3f1532df], // (0.009405553, 0.5828075)
    ]),
    ("n-rooks", 100, 0xdeadbeef, [
        [0x3f19f7ec, 0x3dfece88], // (0.60143924, 0.124417365)
        [0x3f69605c, 0x3f63b425], // (0.9116266, 0.88946754)
        [0x3e803994, 0x3da8b340], // (0.2504393, 0.08237314)
        [0x3e89dc66, 0x3f64d80d], // (0.26925963, 0.8939217)
        [0x3f129cca, 0x3ee7f070], // (0.5727049, 0.45300627)
        [0x3e45e2e0, 0x3e346d84], // (0.19324827, 0.17619902)
        [0x3dca0158, 0x3d31ec40], // (0.098635375, 0.043438196)
        [0x3f4feafe, 0x3f35014b], // (0.81217945, 0.707051)
    ]),
    ("multi-jittered", 16, 0x0, [
        [0x3f76fdc9, 0x3e231800], // (0.96480995, 0.15927124)
        [0x3efcc5ba, 0x3f1524a4], // (0.49369603, 0.58259034)
        [0x3ebe75d8, 0x3d4df460], // (0.37199283, 0.050281882)
        [0x3f24eb91, 0x3e918ed4], // (0.64421946, 0.28429282)
        [0x3f16fd0c, 0x3e48a0cc], // (0.5897987, 0.19592589)
        [0x3f4f0c84, 0x3ee8fbe2], // (0.8087847, 0.4550467)
        [0x3e0b3ab4, 0x3f00e8a1], // (0.13596612, 0.50354964)
        [0x3e4d1660, 0x3dd29890], // (0.20028067, 0.10283005)
    ]),
    ("multi-jittered", 16, 0xdeadbeef, [
        [0x3df19190, 0x3f5d2e8e], // (0.11795342, 0.8639916)
        [0x3ecc3700, 0x3f61da8e], // (0.39885712, 0.88224113)
        [0x3eaa64f4, 0x3eb3d63a], // (0.33280146, 0.3512438)
        [0x3f20b3f4, 0x3e0f302c], // (0.62774587, 0.1398322)
        [0x3f437cb4, 0x3ef69028], // (0.76362157, 0.48156857)
        [0x3f1dd10e, 0x3ecb0096], // (0.6164712, 0.39648885)
        [0x3f7ed0bc, 0x3cc8c9e0], // (0.99537253, 0.024510324)
        [0x3f023897, 0x3f0c73a9], // (0.508676, 0.54863983)
    ]),
    ("multi-jittered", 100, 0x0, [
        [0x3f0098bb, 0x3f3e01f3], // (0.5023305, 0.74221724)
        [0x3f6be0b1, 0x3ec477f8], // (0.92139727, 0.3837278)
        [0x3ea4a8cc, 0x3e9a18ce], // (0.32160032, 0.3009705)
        [0x3f229eda, 0x3eb566f2], // (0.6352364, 0.35430104)
        [0x3ea999ca, 0x3f0da290], // (0.33125144, 0.55326176)
        [0x3e505cd8, 0x3e726708], // (0.20347917, 0.23672116)
        [0x3dbdfcb0, 0x3ea4bf64], // (0.09276712, 0.3217727)
        [0x3e0dd3fc, 0x3de54da0], // (0.13850397, 0.111964464)
    ]),
    ("multi-jittered", 100, 0xdeadbeef, [
        [0x3df91758, 0x3cf165e0], // (0.121626556, 0.029467523)
        [0x3f0e4d86, 0x3f680644], // (0.5558704, 0.9063456)
        [0x3f5e91ca, 0x3ec0bbd0], // (0.86941206, 0.3764329)
        [0x3f09fd82, 0x3e9296a0], // (0.5390245, 0.28630543)
        [0x3f1c5756, 0x3f72a9c6], // (0.61070764, 0.94790304)
        [0x3e186cdc, 0x3f7f805b], // (0.14885277, 0.9980523)
        [0x3ef687b0, 0x3f28310b], // (0.48150396, 0.65699834)
        [0x3e8032ba, 0x3ea834e8], // (0.250387, 0.32852864)
    ]),
    ("correlated-multi-jittered", 16, 0x0, [
        [0x3f76fdc9, 0x3d0c6000], // (0.96480995, 0.03427124)
        [0x3e9cc5ba, 0x3f3524a4], // (0.30619603, 0.70759034)
        [0x3efe75d8, 0x3e737d18], // (0.49699283, 0.23778188)
        [0x3f14eb91, 0x3eb18ed4], // (0.58171946, 0.34679282)
        [0x3f36fd0c, 0x3d914198], // (0.7147987, 0.07092589)
        [0x3f5f0c84, 0x3e88fbe2], // (0.8712847, 0.2675467)
        [0x3c33ab40, 0x3f20e8a1], // (0.010966122, 0.62854964)
        [0x3e4d1660, 0x3e294c48], // (0.20028067, 0.16533005)
    ]),
    ("correlated-multi-jittered", 16, 0xdeadbeef, [
        [0x3e78c8c8, 0x3f4d2e8e], // (0.24295342, 0.8014916)
        [0x3eec3700, 0x3f51da8e], // (0.46135712, 0.81974113)
        [0x3eca64f4, 0x3eb3d63a], // (0.39530146, 0.3512438)
        [0x3f00b3f4, 0x3e0f302c], // (0.50274587, 0.1398322)
        [0x3f637cb4, 0x3ef69028], // (0.88862157, 0.48156857)
        [0x3f2dd10e, 0x3ecb0096], // (0.6789712, 0.39648885)
        [0x3f4ed0bc, 0x3e59193c], // (0.80787253, 0.21201032)
        [0x3f123897, 0x3f2c73a9], // (0.571176, 0.67363983)
    ]),
    ("correlated-multi-jittered", 100, 0x0, [
        [0x3f0098bb, 0x3f38e33b], // (0.5023305, 0.72221726)
        [0x3f78ad7e, 0x3e9b8234], // (0.9713973, 0.30372775)
        [0x3ebe4264, 0x3eb3b268], // (0.37160027, 0.3509705)
        [0x3f2cdc4a, 0x3eb0483a], // (0.67523634, 0.34430104)
        [0x3eb3d73a, 0x3f0da290], // (0.35125142, 0.55326176)
        [0x3e91242e, 0x3e5dec28], // (0.28347915, 0.21672118)
        [0x3d9506f0, 0x3ea9de1c], // (0.07276714, 0.33177269)
        [0x3e18116c, 0x3e449258], // (0.14850396, 0.1919645)
    ]),
    ("correlated-multi-jittered", 100, 0xdeadbeef, [
        [0x3e2fbee0, 0x3d8e44f8], // (0.17162657, 0.069467485)
        [0x3f069f72, 0x3f7243b5], // (0.52587044, 0.9463456)
        [0x3f56e3b6, 0x3ecaf940], // (0.8394121, 0.39643288)
        [0x3f0c8cde, 0x3e7c377c], // (0.54902446, 0.2463054)
        [0x3f1ee6b2, 0x3f7ce736], // (0.62070763, 0.987903)
        [0x3e03f1fc, 0x3f77d247], // (0.12885278, 0.9680523)
        [0x3ee72b88, 0x3f2d4fc3], // (0.451504, 0.6769983)
        [0x3e6bea94, 0x3ea834e8], // (0.23038703, 0.32852864)
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
    assert_eq!(permute(3, 10, 0x2a), 8);
    assert_eq!(permute(0, 16, 0xdeadbeef), 1);
    assert_eq!(permute(99, 100, 0x7), 44);
    assert_eq!(permute(12345, 1 << 24, 0x1234_5678), 12712790);
    assert_eq!(permute(0, 4294967295, 0x1), 2808128383);
    assert_eq!(u32_to_unit_f32(0x8000_0000), 0.5);
    assert_eq!(u32_to_unit_f32(u32::MAX).to_bits(), 0x3f7f_ffff);
    assert_eq!(stratum_to_unit_f32(2, 3, 0).to_bits(), 0x3f2a_aaab);
    assert_eq!(stratum_to_unit_f32(0, 1, 1 << 31), 0.5);
}
