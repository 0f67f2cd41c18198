//! One file per sampler, and [`SamplerKind`] / [`AnySampler`] for choosing
//! one by name at run time (tools, configuration files, command lines).

#[macro_use]
pub(crate) mod sequence;
#[macro_use]
mod grid;

mod correlated_multi_jittered;
pub(crate) mod digital;
mod halton;
mod hammersley;
mod jittered;
mod multi_jittered;
mod n_rooks;
pub(crate) mod pmj02;
mod random;
mod regular;
pub(crate) mod sobol;

use core::fmt;
use core::str::FromStr;

use glam::Vec2;

pub use correlated_multi_jittered::CorrelatedMultiJittered;
pub use halton::Halton;
pub use hammersley::Hammersley;
pub use jittered::Jittered;
pub use multi_jittered::MultiJittered;
pub use n_rooks::{LatinHypercube, NRooks};
pub use pmj02::Pmj02;
pub use random::Random;
pub use regular::Regular;
pub use sobol::Sobol;

use crate::sampler::FillOn;
use crate::simd::Isa;
use crate::{Error, Sampler2D};

/// Declares the sampler list once: the kind enum, its names, the dispatching
/// enum and its `Sampler2D` impl all come from this one table.
macro_rules! sampler_kinds {
    ($($variant:ident => $name:literal,)*) => {
        /// Every sampler wellspread offers, named as the tools name them.
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

        impl FillOn for AnySampler {
            fn fill_on(&self, isa: Isa, pattern: u32, out: &mut [Vec2]) {
                match self {
                    $(AnySampler::$variant(s) => s.fill_on(isa, pattern, out),)*
                }
            }
        }
    };
}

sampler_kinds! {
    Regular => "regular",
    Random => "random",
    Jittered => "jittered",
    NRooks => "n-rooks",
    MultiJittered => "multi-jittered",
    CorrelatedMultiJittered => "correlated-multi-jittered",
    Hammersley => "hammersley",
    Halton => "halton",
    Sobol => "sobol",
    Pmj02 => "pmj02",
}

impl fmt::Display for SamplerKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for SamplerKind {
    type Err = Error;

    /// The kind named `name` (exactly, as [`SamplerKind::name`] spells it).
    ///
    /// # Errors
    ///
    /// [`Error::UnknownSampler`], which names the input and lists the
    /// valid names.
    fn from_str(name: &str) -> Result<Self, Self::Err> {
        SamplerKind::ALL
            .iter()
            .copied()
            .find(|kind| kind.name() == name)
            .ok_or(Error::UnknownSampler {
                name: crate::error::InputText::new(name),
            })
    }
}

/// `SamplerKind` in settings files (feature `serde`): serialized as its
/// kebab-case [`name`](SamplerKind::name), deserialized from it with the
/// same error as [`FromStr`].
#[cfg(feature = "serde")]
mod serde_impls {
    use core::fmt;

    use serde::de::{self, Deserialize, Deserializer, Visitor};
    use serde::ser::{Serialize, Serializer};

    use super::SamplerKind;

    impl Serialize for SamplerKind {
        fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
            serializer.serialize_str(self.name())
        }
    }

    impl<'de> Deserialize<'de> for SamplerKind {
        fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
            struct Name;
            impl Visitor<'_> for Name {
                type Value = SamplerKind;

                fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                    f.write_str("a sampler name such as \"sobol\" or \"n-rooks\"")
                }

                fn visit_str<E: de::Error>(self, name: &str) -> Result<SamplerKind, E> {
                    name.parse().map_err(E::custom)
                }
            }
            deserializer.deserialize_str(Name)
        }
    }
}
