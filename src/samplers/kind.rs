//! [`SamplerKind`] and [`AnySampler`]: choosing a sampler by name at run
//! time (tools, settings files, command lines), from the one registry
//! table `sampler_kinds!`, and the `serde` impls of `SamplerKind`.

use core::fmt;
use core::str::FromStr;

use glam::{Vec2, Vec3, Vec4};

use super::{
    BlueMultiJittered, CorrelatedMultiJittered, Halton, Hammersley, Jittered, MultiJittered,
    NRooks, Pmj02, Random, Regular, Sobol,
};
use crate::error::{Error, UnknownName, same_name};
use crate::traits::Sampler2D;
use crate::traits::{DomainSampler, Sequence2D};

/// Declares the sampler list once: the kind enum, its names, the dispatching
/// enum and its `Sampler2D` and `DomainSampler` impls all come from this
/// one table.
macro_rules! sampler_kinds {
    ($($variant:ident => $name:literal,)*) => {
        /// The kinds of [`Sampler2D`] wellspread offers, named as the tools
        /// name them. The pixel samplers ([`ZSobol`](crate::ZSobol),
        /// [`Padded`](crate::Padded)) are not sampler kinds: they implement
        /// [`PixelSampler`](crate::PixelSampler) instead.
        ///
        /// ```
        /// use wellspread::{SamplerKind, Sampler2D};
        /// let kind: SamplerKind = "multi-jittered".parse()?;
        /// let sampler = kind.build(64)?;
        /// assert_eq!(sampler.len(), 64);
        /// assert_eq!(kind.name(), "multi-jittered");
        /// # Ok::<(), Box<dyn std::error::Error>>(())
        /// ```
        ///
        /// Not `#[non_exhaustive]`, on purpose: a `match` over the kinds, in
        /// this crate or its tests and tools, fails to compile until a new
        /// kind has its line (a new kind is a new minor version).
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        pub enum SamplerKind {
            $(
                #[doc = concat!("[`", stringify!($variant), "`], named `", $name, "`.")]
                $variant,
            )*
        }

        impl SamplerKind {
            /// All kinds, in the order tools list them: from the baseline
            /// to the best distributed.
            pub const ALL: &'static [SamplerKind] = &[$(SamplerKind::$variant,)*];

            /// The kebab-case name the tools use (`"n-rooks"`, ...).
            #[must_use]
            pub const fn name(self) -> &'static str {
                match self {
                    $(SamplerKind::$variant => $name,)*
                }
            }

            /// The sampler of this kind for `n` samples, through its checked
            /// constructor.
            ///
            /// # Errors
            ///
            /// Whatever that constructor rejects (`n = 0`, too large an `n`).
            pub fn build(self, n: u32) -> Result<AnySampler, Error> {
                Ok(match self {
                    $(SamplerKind::$variant => AnySampler::$variant($variant::new(n)?),)*
                })
            }
        }

        /// Any one of wellspread's samplers, chosen at run time, with static
        /// dispatch (a `match`, no allocation).
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        #[repr(u8)]
        pub enum AnySampler {
            $(
                #[doc = concat!("A [`", stringify!($variant), "`].")]
                $variant($variant),
            )*
        }

        impl AnySampler {
            /// Which kind of sampler this is.
            #[must_use]
            pub const fn kind(&self) -> SamplerKind {
                match self {
                    $(AnySampler::$variant(_) => SamplerKind::$variant,)*
                }
            }

            /// Runs `visitor` on the concrete sampler inside: one `match`,
            /// then code compiled for that type (see [`SamplerVisitor`]).
            #[inline]
            pub fn visit<V: SamplerVisitor>(&self, visitor: V) -> V::Output {
                match self {
                    $(AnySampler::$variant(s) => visitor.visit(s),)*
                }
            }
        }

        impl Sampler2D for AnySampler {
            #[inline]
            fn len(&self) -> u32 {
                match self {
                    $(AnySampler::$variant(s) => s.len(),)*
                }
            }

            #[inline]
            fn sample(&self, index: u32, pattern: u32) -> Vec2 {
                match self {
                    $(AnySampler::$variant(s) => s.sample(index, pattern),)*
                }
            }

            #[inline]
            fn fill(&self, pattern: u32, out: &mut [Vec2]) {
                match self {
                    $(AnySampler::$variant(s) => s.fill(pattern, out),)*
                }
            }
        }

        impl DomainSampler for AnySampler {
            #[inline]
            fn is_progressive(&self) -> bool {
                match self {
                    $(AnySampler::$variant(s) => s.is_progressive(),)*
                }
            }

            #[inline]
            fn locate(&self, index: u32, key: u64) -> (u32, u64) {
                match self {
                    $(AnySampler::$variant(s) => s.locate(index, key),)*
                }
            }

            #[inline(always)]
            fn domain_1d(&self, index: u32, stream: u64) -> f32 {
                match self {
                    $(AnySampler::$variant(s) => kernel_1d(s, index, stream),)*
                }
            }

            #[inline(always)]
            fn domain_2d(&self, index: u32, stream: u64) -> Vec2 {
                match self {
                    $(AnySampler::$variant(s) => kernel_2d(s, index, stream),)*
                }
            }

            #[inline(always)]
            fn domain_3d(&self, index: u32, stream: u64) -> Vec3 {
                match self {
                    $(AnySampler::$variant(s) => kernel_3d(s, index, stream),)*
                }
            }

            #[inline(always)]
            fn domain_4d(&self, index: u32, stream: u64) -> Vec4 {
                match self {
                    $(AnySampler::$variant(s) => kernel_4d(s, index, stream),)*
                }
            }
        }
    };
}

/// Code generic over the sampler type, run by [`AnySampler::visit`] on the
/// concrete sampler an `AnySampler` holds: a tool picks the kind at run
/// time and pays one dispatch per `visit`, not one per sample.
///
/// ```
/// use wellspread::implement::DomainSampler;
/// use wellspread::{SamplerKind, SamplerVisitor};
/// struct FirstDraw;
/// impl SamplerVisitor for FirstDraw {
///     type Output = f32;
///     fn visit<S: DomainSampler + Copy + Send + Sync>(self, sampler: &S) -> f32 {
///         sampler.domain_1d(0, 7)
///     }
/// }
/// let sampler = SamplerKind::Sobol.build(16)?;
/// assert_eq!(sampler.visit(FirstDraw), sampler.domain_1d(0, 7));
/// # Ok::<(), wellspread::Error>(())
/// ```
pub trait SamplerVisitor {
    /// What [`visit`](Self::visit) returns.
    type Output;
    /// Runs on the concrete sampler.
    fn visit<S: DomainSampler + Copy + Send + Sync>(self, sampler: &S) -> Self::Output;
}

// The kernels behind `AnySampler`'s draws, one out-of-line copy per kind,
// with the sampler, index and stream in registers: the dispatch is a jump
// table whose arms jump to these, not one function holding every kernel
// (whose register saves and stack frame every draw paid).
#[inline(never)]
fn kernel_1d<S: DomainSampler>(s: &S, index: u32, stream: u64) -> f32 {
    s.domain_1d(index, stream)
}
#[inline(never)]
fn kernel_2d<S: DomainSampler>(s: &S, index: u32, stream: u64) -> Vec2 {
    s.domain_2d(index, stream)
}
#[inline(never)]
fn kernel_3d<S: DomainSampler>(s: &S, index: u32, stream: u64) -> Vec3 {
    s.domain_3d(index, stream)
}
#[inline(never)]
fn kernel_4d<S: DomainSampler>(s: &S, index: u32, stream: u64) -> Vec4 {
    s.domain_4d(index, stream)
}

sampler_kinds! {
    Regular => "regular",
    Random => "random",
    Jittered => "jittered",
    NRooks => "n-rooks",
    MultiJittered => "multi-jittered",
    CorrelatedMultiJittered => "correlated-multi-jittered",
    BlueMultiJittered => "blue-multi-jittered",
    Hammersley => "hammersley",
    Halton => "halton",
    Sobol => "sobol",
    Pmj02 => "pmj02",
}

impl AnySampler {
    /// The sampler as a progressive [`Sequence2D`], if it is one (Sobol,
    /// Pmj02, Halton): the way to its
    /// [`fill_from`](Sequence2D::fill_from) at run time.
    ///
    /// ```
    /// use wellspread::SamplerKind;
    /// assert!(SamplerKind::Sobol.build(16)?.as_sequence().is_some());
    /// assert!(SamplerKind::Hammersley.build(16)?.as_sequence().is_none());
    /// # Ok::<(), wellspread::Error>(())
    /// ```
    #[must_use]
    pub fn as_sequence(&self) -> Option<&dyn Sequence2D> {
        match self {
            AnySampler::Halton(s) => Some(s),
            AnySampler::Sobol(s) => Some(s),
            AnySampler::Pmj02(s) => Some(s),
            AnySampler::Regular(_)
            | AnySampler::Random(_)
            | AnySampler::Jittered(_)
            | AnySampler::NRooks(_)
            | AnySampler::MultiJittered(_)
            | AnySampler::CorrelatedMultiJittered(_)
            | AnySampler::BlueMultiJittered(_)
            | AnySampler::Hammersley(_) => None,
        }
    }
}

impl fmt::Display for SamplerKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// Short names accepted besides the full ones, each with its kind: the one
/// alias table, which [`SamplerKind`]'s and
/// [`PixelSamplerKind`](crate::PixelSamplerKind)'s parsers and their error
/// messages read. (`latin-hypercube` and `lhs` are the N-dimensional
/// pixel sampler's names, not aliases of `n-rooks`.)
pub(crate) const ALIASES: [(&str, SamplerKind); 6] = [
    ("cmj", SamplerKind::CorrelatedMultiJittered),
    ("mj", SamplerKind::MultiJittered),
    ("pmj", SamplerKind::Pmj02),
    ("rooks", SamplerKind::NRooks),
    ("stratified", SamplerKind::Jittered),
    ("white", SamplerKind::Random),
];

/// Every kind's name, in [`SamplerKind::ALL`]'s order, for error messages.
pub(crate) const NAMES: [&str; SamplerKind::ALL.len()] = {
    let mut names = [""; SamplerKind::ALL.len()];
    let mut i = 0;
    while i < names.len() {
        names[i] = SamplerKind::ALL[i].name();
        i += 1;
    }
    names
};

/// [`ALIASES`]' names, for error messages.
pub(crate) const ALIAS_NAMES: [&str; ALIASES.len()] = {
    let mut names = [""; ALIASES.len()];
    let mut i = 0;
    while i < names.len() {
        names[i] = ALIASES[i].0;
        i += 1;
    }
    names
};

impl FromStr for SamplerKind {
    type Err = Error;

    /// The kind named `name` or one of its aliases (`cmj`, `mj`, `pmj`,
    /// ...), ignoring ASCII case and the separators `-`, `_` and spaces:
    /// `"Sobol"`, `"n_rooks"` and `"CMJ"` all parse.
    ///
    /// # Errors
    ///
    /// [`Error::UnknownSampler`], which names the input and lists the
    /// valid names.
    fn from_str(name: &str) -> Result<Self, Self::Err> {
        SamplerKind::ALL
            .iter()
            .copied()
            .find(|kind| same_name(kind.name(), name))
            .or_else(|| {
                ALIASES
                    .iter()
                    .find(|(alias, _)| same_name(alias, name))
                    .map(|&(_, kind)| kind)
            })
            .ok_or(Error::UnknownSampler(UnknownName::new(
                name,
                &NAMES,
                &ALIAS_NAMES,
            )))
    }
}

/// `SamplerKind` in settings files (feature `serde`): serialized as its
/// kebab-case [`name`](SamplerKind::name), deserialized from it with the
/// same error as [`FromStr`].
#[cfg(feature = "serde")]
mod serde_impls {
    use serde::de::{Deserialize, Deserializer};
    use serde::ser::{Serialize, Serializer};

    use super::SamplerKind;

    #[cfg_attr(docsrs, doc(cfg(feature = "serde")))]
    impl Serialize for SamplerKind {
        fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
            serializer.serialize_str(self.name())
        }
    }

    #[cfg_attr(docsrs, doc(cfg(feature = "serde")))]
    impl<'de> Deserialize<'de> for SamplerKind {
        fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
            crate::error::deserialize_name(
                deserializer,
                "a sampler name such as \"sobol\" or \"n-rooks\"",
            )
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_sequences_are_sobol_pmj02_and_halton() {
        let sequences: std::vec::Vec<SamplerKind> = SamplerKind::ALL
            .iter()
            .copied()
            .filter(|kind| kind.build(16).unwrap().as_sequence().is_some())
            .collect();
        assert_eq!(
            sequences,
            [SamplerKind::Halton, SamplerKind::Sobol, SamplerKind::Pmj02]
        );
    }

    #[test]
    fn the_progressive_flag_is_the_sequence_trait() {
        for &kind in SamplerKind::ALL {
            let sampler = kind.build(16).unwrap();
            assert_eq!(
                sampler.is_progressive(),
                sampler.as_sequence().is_some(),
                "{kind}"
            );
        }
    }

    #[test]
    fn every_sequence_fills_any_run_as_it_samples() {
        for &kind in SamplerKind::ALL {
            let sampler = kind.build(16).unwrap();
            let Some(sequence) = sampler.as_sequence() else {
                continue;
            };
            // Runs past the set size, across 2^24, and up to the last index.
            for start in [0, 5, 16, (1 << 24) - 3, u32::MAX - 20] {
                let mut out = [Vec2::NAN; 21];
                sequence.fill_from(start, 7, &mut out);
                for (offset, point) in (0..).zip(&out) {
                    let expected = sequence.sample(start + offset, 7);
                    assert_eq!(
                        (point.x.to_bits(), point.y.to_bits()),
                        (expected.x.to_bits(), expected.y.to_bits()),
                        "{kind} index {}",
                        start + offset
                    );
                }
            }
        }
    }
}
