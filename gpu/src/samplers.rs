//! The pixel samplers on both sides: one [`Case`] per sampler setting, the
//! inputs (random plus every edge), the test shader and the CPU twin of
//! what it writes.

use wellspread::implement::{Draw, PixelSamplerHooks};
use wellspread::{AnyPixelSampler, Jittered, PixelSampler, PixelSamplerKind, SamplerKind};

use crate::{Gpu, HARNESS};

/// Words per input: pixel x, y, index, key, draw, split count, split j,
/// branch depth.
pub const INPUT_WORDS: usize = 8;

/// Words per output, in order: `next_1d`, `next_2d`, `next_3d`, `next_4d`
/// at draws `draw .. draw + 4` (10 f32s); `branch(key).next_2d()` (2);
/// `split(key, count, j)`: `next_1d`, `next_4d` (5), its index and key (3);
/// a chain of `depth` branches: `next_2d` and its key (4).
pub const OUTPUT_WORDS: usize = 24;

/// What each output word is, for the failure message.
pub const OUTPUT_NAMES: [&str; OUTPUT_WORDS] = [
    "next_1d",
    "next_2d.x",
    "next_2d.y",
    "next_3d.x",
    "next_3d.y",
    "next_3d.z",
    "next_4d.x",
    "next_4d.y",
    "next_4d.z",
    "next_4d.w",
    "branch.next_2d.x",
    "branch.next_2d.y",
    "split.next_1d",
    "split.next_4d.x",
    "split.next_4d.y",
    "split.next_4d.z",
    "split.next_4d.w",
    "split.index",
    "split.key.low",
    "split.key.high",
    "chain.next_2d.x",
    "chain.next_2d.y",
    "chain.key.low",
    "chain.key.high",
];

/// The test kernel: [`HARNESS`], then this, after `wgsl::SOURCE`.
pub const KERNEL: &str = "
// The sampler's kind, a pipeline constant: the compiler keeps one sampler.
override KIND: u32;

@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = invocation(id);
    if (i >= params[2].x) {
        return;
    }
    let s = WsSampler(KIND, params[0].y, params[0].z, params[0].w,
                      params[1].x, params[1].y, params[1].z, params[1].w);
    let a = i * 8u;
    let pixel = vec2<u32>(input[a], input[a + 1u]);
    let key = input[a + 3u];
    let root = ws_start(s, pixel, input[a + 2u]);
    var d = root;
    d.draws = input[a + 4u];
    let o = i * 24u;
    output[o] = bitcast<u32>(ws_next_1d(s, &d));
    let p2 = ws_next_2d(s, &d);
    output[o + 1u] = bitcast<u32>(p2.x);
    output[o + 2u] = bitcast<u32>(p2.y);
    let p3 = bitcast<vec3<u32>>(ws_next_3d(s, &d));
    output[o + 3u] = p3.x;
    output[o + 4u] = p3.y;
    output[o + 5u] = p3.z;
    let p4 = bitcast<vec4<u32>>(ws_next_4d(s, &d));
    output[o + 6u] = p4.x;
    output[o + 7u] = p4.y;
    output[o + 8u] = p4.z;
    output[o + 9u] = p4.w;
    var b = ws_branch(root, key);
    let b2 = bitcast<vec2<u32>>(ws_next_2d(s, &b));
    output[o + 10u] = b2.x;
    output[o + 11u] = b2.y;
    var sp = ws_split(s, root, key, input[a + 5u], input[a + 6u]);
    let split_index = sp.index;
    let split_key = sp.key;
    output[o + 12u] = bitcast<u32>(ws_next_1d(s, &sp));
    let s4 = bitcast<vec4<u32>>(ws_next_4d(s, &sp));
    output[o + 13u] = s4.x;
    output[o + 14u] = s4.y;
    output[o + 15u] = s4.z;
    output[o + 16u] = s4.w;
    output[o + 17u] = split_index;
    output[o + 18u] = split_key.x;
    output[o + 19u] = split_key.y;
    var c = root;
    for (var t = 0u; t < input[a + 7u]; t++) {
        c = ws_branch(c, key + t);
    }
    let chain_key = c.key;
    let c2 = bitcast<vec2<u32>>(ws_next_2d(s, &c));
    output[o + 20u] = c2.x;
    output[o + 21u] = c2.y;
    output[o + 22u] = chain_key.x;
    output[o + 23u] = chain_key.y;
}
";

/// One sampler setting, with its CPU sampler and its `WsSampler` words.
#[derive(Clone, Copy, Debug)]
pub struct Case {
    /// A name for the log.
    pub name: &'static str,
    /// The CPU sampler.
    pub cpu: AnyPixelSampler,
    /// `WsSampler`'s eight words.
    pub gpu: [u32; 8],
}

/// The test's kind numbers (`WS_RANDOM` ...).
const RANDOM: u32 = 0;
const SOBOL: u32 = 1;
const PMJ02: u32 = 2;
const JITTERED: u32 = 3;
const ZSOBOL: u32 = 4;
const BLUE_NOISE: u32 = 5;

impl Case {
    /// A padded sampler (`random`, `sobol`, `pmj02`) at `n` samples.
    pub fn padded(name: &'static str, kind: SamplerKind, n: u32, frame: u32) -> Case {
        let code = match kind {
            SamplerKind::Random => RANDOM,
            SamplerKind::Sobol => SOBOL,
            SamplerKind::Pmj02 => PMJ02,
            _ => panic!("{kind} has no WGSL twin"),
        };
        Case {
            name,
            cpu: PixelSamplerKind::Padded(kind)
                .build(n, [1, 1], frame)
                .unwrap(),
            gpu: [code, n, 1, n, frame, 0, 0, 0],
        }
    }

    /// `Padded<Jittered>` at `n` samples (the most square grid).
    pub fn jittered(name: &'static str, n: u32, frame: u32) -> Case {
        let j = Jittered::new(n).unwrap();
        Case {
            name,
            cpu: PixelSamplerKind::Padded(SamplerKind::Jittered)
                .build(n, [1, 1], frame)
                .unwrap(),
            gpu: [JITTERED, n, j.columns(), j.rows(), frame, 0, 0, 0],
        }
    }

    /// `ZSobol` at `spp` (a power of two) on a `width` x `height` film.
    pub fn zsobol(name: &'static str, spp: u32, [width, height]: [u32; 2], frame: u32) -> Case {
        Case {
            name,
            cpu: PixelSamplerKind::ZSobol
                .build(spp, [width, height], frame)
                .unwrap(),
            gpu: [
                ZSOBOL,
                spp,
                0,
                0,
                frame,
                width,
                height,
                spp.trailing_zeros(),
            ],
        }
    }

    /// `BlueNoise` (its count and resolution change no draw).
    pub fn blue_noise(name: &'static str, spp: u32, frame: u32) -> Case {
        Case {
            name,
            cpu: PixelSamplerKind::BlueNoise
                .build(spp, [64, 64], frame)
                .unwrap(),
            gpu: [BLUE_NOISE, spp, 0, 0, frame, 0, 0, 0],
        }
    }

    /// The CPU's outputs for one input, in the kernel's order.
    pub fn cpu_outputs(&self, input: &[u32]) -> [u32; OUTPUT_WORDS] {
        let s = self.cpu;
        let [x, y, index, key, draw, count, j, depth] = input.try_into().unwrap();
        let root = s.root([x, y]);
        let (at, domain_key) = s.locate(index, root.key);
        // Dimension 0: only PaddedNd reads it, and it has no WGSL twin.
        let d = |k: u32| Draw::new(domain_key, draw.wrapping_add(k), 0, at, root.pixel_state);
        let mut o = [0u32; OUTPUT_WORDS];
        o[0] = s.draw_1d(d(0)).to_bits();
        let p2 = s.draw_2d(d(1));
        o[1..3].copy_from_slice(&p2.to_array().map(f32::to_bits));
        let p3 = s.draw_3d(d(2));
        o[3..6].copy_from_slice(&p3.to_array().map(f32::to_bits));
        let p4 = s.draw_4d(d(3));
        o[6..10].copy_from_slice(&p4.to_array().map(f32::to_bits));
        // The domain API for the children (draw 0, whatever the parent drew).
        let start = s.start([x, y], index);
        assert_eq!((start.index(), start.key()), (at, domain_key));
        let b = start.branch(key).next_2d();
        o[10..12].copy_from_slice(&b.to_array().map(f32::to_bits));
        let mut sp = start.split(key, count, j);
        let (split_index, split_key) = (sp.index(), sp.key());
        o[12] = sp.next_1d().to_bits();
        o[13..17].copy_from_slice(&sp.next_4d().to_array().map(f32::to_bits));
        o[17] = split_index;
        o[18] = split_key as u32;
        o[19] = (split_key >> 32) as u32;
        let mut c = start;
        for t in 0..depth {
            c = c.branch(key.wrapping_add(t));
        }
        let chain_key = c.key();
        o[20..22].copy_from_slice(&c.next_2d().to_array().map(f32::to_bits));
        o[22] = chain_key as u32;
        o[23] = (chain_key >> 32) as u32;
        o
    }
}

/// A small, fixed random generator for the inputs (SplitMix64).
#[derive(Debug)]
pub struct Inputs(u64);

impl Inputs {
    /// Seeded.
    pub fn new(seed: u64) -> Inputs {
        Inputs(seed)
    }

    fn next(&mut self) -> u32 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        ((z ^ (z >> 31)) >> 16) as u32
    }

    /// A random u32, an edge one time in eight.
    fn pick(&mut self, edges: &[u32], small: u32) -> u32 {
        let r = self.next();
        match r & 7 {
            0 => edges[(r >> 3) as usize % edges.len()],
            1..=3 => self.next() % small,
            _ => self.next(),
        }
    }

    /// `count` inputs of [`INPUT_WORDS`] words: pixels, indices, keys and
    /// draws at random and at their edges (0, 1, `u32::MAX`, powers of
    /// two), split counts 1 to `u32::MAX` with `j < count`, branch chains
    /// 0 to 300 deep.
    pub fn make(&mut self, count: usize) -> Vec<u32> {
        let max = u32::MAX;
        let mut words = Vec::with_capacity(count * INPUT_WORDS);
        for _ in 0..count {
            let x = self.pick(&[0, 1, max, max - 1, 65_535, 65_536, 63, 64], 256);
            let y = self.pick(&[0, 1, max, max - 1, 65_535, 65_536, 47, 48], 256);
            let index = self.pick(&[0, 1, 15, 16, 17, max, max - 1, 1 << 31], 64);
            let key = self.pick(&[0, 1, max, max - 1], 16);
            let draw = self.pick(&[0, 1, max, max - 1, max - 2, max - 3], 8);
            let count = self
                .pick(&[1, 1, 2, 4, 1 << 16, 1 << 31, max, 3, 12], 64)
                .max(1);
            let j = match self.next() & 3 {
                0 => 0,
                1 => count - 1,
                _ => self.next() % count,
            };
            let depth = match self.next() & 63 {
                0 => 300,
                1..=8 => self.next() % 64,
                _ => self.next() % 4,
            };
            words.extend_from_slice(&[x, y, index, key, draw, count, j, depth]);
        }
        words
    }
}

/// Runs `case` over `count` inputs from `seed` on the GPU and the CPU,
/// in batches; returns the mismatches as lines (empty when bit-identical)
/// and the GPU time.
pub fn compare(
    gpu: &Gpu,
    source: &str,
    case: &Case,
    count: usize,
    seed: u64,
) -> (Vec<String>, std::time::Duration) {
    let kernel = gpu.kernel_with(
        &format!("{source}\n{HARNESS}\n{KERNEL}"),
        &[("KIND", f64::from(case.gpu[0]))],
    );
    let mut inputs = Inputs::new(seed);
    let mut failures = Vec::new();
    let mut mismatched_words = 0usize;
    let mut gpu_time = std::time::Duration::ZERO;
    const BATCH: usize = 1 << 18;
    let mut done = 0;
    while done < count {
        let n = BATCH.min(count - done);
        let input = inputs.make(n);
        let mut params = [0u32; 16];
        params[..8].copy_from_slice(&case.gpu);
        params[8] = n as u32;
        let t = std::time::Instant::now();
        let got = kernel.run(&params, &input, n as u32, n * OUTPUT_WORDS);
        gpu_time += t.elapsed();
        for (i, (input, got)) in input
            .chunks_exact(INPUT_WORDS)
            .zip(got.chunks_exact(OUTPUT_WORDS))
            .enumerate()
        {
            let want = case.cpu_outputs(input);
            for (w, (&g, &c)) in got.iter().zip(&want).enumerate() {
                if g != c {
                    mismatched_words += 1;
                    if failures.len() < 12 {
                        failures.push(format!(
                            "{}: input {} {input:?}: {} GPU {g:#010x} ({}) CPU {c:#010x} ({})",
                            case.name,
                            done + i,
                            OUTPUT_NAMES[w],
                            f32::from_bits(g),
                            f32::from_bits(c)
                        ));
                    }
                }
            }
        }
        done += n;
    }
    if mismatched_words > 0 {
        failures.push(format!(
            "{}: {mismatched_words} of {} words differ",
            case.name,
            count * OUTPUT_WORDS
        ));
    }
    (failures, gpu_time)
}
