//! [`FilterKind`] and [`AnyFilter`]: choosing a filter by name at run time
//! (tools, settings files, command lines), and the `serde` impls of
//! `FilterKind`.

use core::fmt;
use core::str::FromStr;

use glam::Vec2;

use super::{
    BlackmanHarrisFilter, BoxFilter, Filter, FilterSample, GaussianFilter, LanczosFilter,
    MitchellFilter, TentFilter,
};
use crate::error::{Error, UnknownName, same_name};

/// The kinds of [`Filter`] wellspread offers, named as the tools name
/// them.
///
/// [`build`](Self::build) gives the filter of a kind with pbrt-v4's
/// default parameters (`Create` in pbrt-v4's `src/pbrt/filters.cpp`); to
/// choose the parameters, build the concrete filter through its checked
/// constructor and convert it, `AnyFilter::from(GaussianFilter::new(2.0,
/// 0.7)?)`.
///
/// | kind | name | default parameters | pbrt-v4 |
/// | --- | --- | --- | --- |
/// | `Box` | `box` | radius 0.5 | `BoxFilter` |
/// | `Tent` | `tent` | radius 2 | `TriangleFilter` |
/// | `Gaussian` | `gaussian` | radius 1.5, sigma 0.5 | `GaussianFilter` |
/// | `Mitchell` | `mitchell` | radius 2, `B = C = 1/3` | `MitchellFilter` |
/// | `Lanczos` | `lanczos` | radius 4, `tau = 3` | `LanczosSincFilter` |
/// | `BlackmanHarris` | `blackman-harris` | radius 2 | none |
///
/// pbrt-v4 has no Blackman-Harris filter: its default radius, 2, is the
/// one the lab's tracer renders with. The defaults are each filter's
/// `Default` impl.
///
/// ```
/// use wellspread::filter::{Filter, FilterKind, GaussianFilter};
/// let kind: FilterKind = "Gaussian".parse()?;
/// assert_eq!(kind, FilterKind::Gaussian);
/// assert_eq!(kind.to_string(), "gaussian");
/// let filter = kind.build();
/// assert_eq!(filter, GaussianFilter::new(1.5, 0.5)?.into());
/// assert_eq!(filter.radius(), 1.5);
/// # Ok::<(), wellspread::Error>(())
/// ```
///
/// Not `#[non_exhaustive]`, on purpose: a `match` over the kinds fails to
/// compile until a new kind has its arm (a new kind is a new minor
/// version).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum FilterKind {
    /// [`BoxFilter`], named `box`.
    Box,
    /// [`TentFilter`], named `tent`.
    Tent,
    /// [`GaussianFilter`], named `gaussian`.
    Gaussian,
    /// [`MitchellFilter`], named `mitchell`.
    Mitchell,
    /// [`LanczosFilter`], named `lanczos`.
    Lanczos,
    /// [`BlackmanHarrisFilter`], named `blackman-harris`.
    BlackmanHarris,
}

/// The kinds' names, in the order of [`FilterKind::ALL`]: what
/// [`FilterKind::name`] returns and [`Error::UnknownFilter`] lists.
const NAMES: &[&str] = &[
    "box",
    "tent",
    "gaussian",
    "mitchell",
    "lanczos",
    "blackman-harris",
];

impl FilterKind {
    /// All kinds, in the order tools list them: the exactly sampled
    /// filters, then the tabulated ones.
    pub const ALL: &'static [FilterKind] = &[
        FilterKind::Box,
        FilterKind::Tent,
        FilterKind::Gaussian,
        FilterKind::Mitchell,
        FilterKind::Lanczos,
        FilterKind::BlackmanHarris,
    ];

    /// The kebab-case name the tools use (`"gaussian"`,
    /// `"blackman-harris"`, ...).
    #[must_use]
    pub const fn name(self) -> &'static str {
        NAMES[self as usize]
    }

    /// The filter of this kind with its default parameters (pbrt-v4's,
    /// see the table above).
    #[must_use]
    pub fn build(self) -> AnyFilter {
        match self {
            FilterKind::Box => BoxFilter::default().into(),
            FilterKind::Tent => TentFilter::default().into(),
            FilterKind::Gaussian => GaussianFilter::default().into(),
            FilterKind::Mitchell => MitchellFilter::default().into(),
            FilterKind::Lanczos => LanczosFilter::default().into(),
            FilterKind::BlackmanHarris => BlackmanHarrisFilter::default().into(),
        }
    }
}

impl fmt::Display for FilterKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for FilterKind {
    type Err = Error;

    /// The kind named `name`, ignoring ASCII case and the separators `-`,
    /// `_` and spaces, as sampler names are: `"Gaussian"`, `"TENT"` and
    /// `"blackman_harris"` all parse.
    ///
    /// # Errors
    ///
    /// [`Error::UnknownFilter`], which names the input and lists the
    /// valid names.
    fn from_str(name: &str) -> Result<Self, Self::Err> {
        FilterKind::ALL
            .iter()
            .copied()
            .find(|kind| same_name(kind.name(), name))
            .ok_or(Error::UnknownFilter(UnknownName::new(name, NAMES, &[])))
    }
}

/// Any one of wellspread's filters, chosen at run time, with static
/// dispatch (a `match`, no allocation): what [`FilterKind::build`]
/// returns, and what each concrete filter converts into (`From`).
///
/// The size of the largest filter (a tabulated one, under 4 KiB): pass it
/// by reference.
///
/// ```
/// use wellspread::filter::{AnyFilter, Filter, FilterKind, LanczosFilter};
/// use wellspread::glam::Vec2;
/// let lanczos3 = AnyFilter::from(LanczosFilter::new(3.0, 3.0)?);
/// assert_eq!(lanczos3.kind(), FilterKind::Lanczos);
/// let u = Vec2::new(0.3, 0.8);
/// assert_eq!(lanczos3.sample(u), LanczosFilter::new(3.0, 3.0)?.sample(u));
/// # Ok::<(), wellspread::Error>(())
/// ```
// Boxing the tabulated filters would need `alloc` and lose `Copy`.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum AnyFilter {
    /// A [`BoxFilter`].
    Box(BoxFilter),
    /// A [`TentFilter`].
    Tent(TentFilter),
    /// A [`GaussianFilter`].
    Gaussian(GaussianFilter),
    /// A [`MitchellFilter`].
    Mitchell(MitchellFilter),
    /// A [`LanczosFilter`].
    Lanczos(LanczosFilter),
    /// A [`BlackmanHarrisFilter`].
    BlackmanHarris(BlackmanHarrisFilter),
}

impl AnyFilter {
    /// Which kind of filter this is.
    #[must_use]
    pub const fn kind(&self) -> FilterKind {
        match self {
            AnyFilter::Box(_) => FilterKind::Box,
            AnyFilter::Tent(_) => FilterKind::Tent,
            AnyFilter::Gaussian(_) => FilterKind::Gaussian,
            AnyFilter::Mitchell(_) => FilterKind::Mitchell,
            AnyFilter::Lanczos(_) => FilterKind::Lanczos,
            AnyFilter::BlackmanHarris(_) => FilterKind::BlackmanHarris,
        }
    }

    /// The concrete filter inside, behind its trait: the one dispatch
    /// every method of `Filter for AnyFilter` goes through.
    #[inline]
    fn concrete(&self) -> &dyn Filter {
        match self {
            AnyFilter::Box(f) => f,
            AnyFilter::Tent(f) => f,
            AnyFilter::Gaussian(f) => f,
            AnyFilter::Mitchell(f) => f,
            AnyFilter::Lanczos(f) => f,
            AnyFilter::BlackmanHarris(f) => f,
        }
    }
}

/// The filter inside, dispatched once per call: the 2D methods run the
/// concrete filter's own, so their values are that filter's, bit for bit.
impl Filter for AnyFilter {
    #[inline]
    fn radius(&self) -> f32 {
        self.concrete().radius()
    }

    #[inline]
    fn evaluate_1d(&self, x: f64) -> f64 {
        self.concrete().evaluate_1d(x)
    }

    #[inline]
    fn sample_1d(&self, u: f32) -> (f64, f64) {
        self.concrete().sample_1d(u)
    }

    #[inline]
    fn weight_magnitude_1d(&self) -> f64 {
        self.concrete().weight_magnitude_1d()
    }

    #[inline]
    fn evaluate(&self, p: Vec2) -> f32 {
        self.concrete().evaluate(p)
    }

    #[inline]
    fn sample(&self, u: Vec2) -> FilterSample {
        self.concrete().sample(u)
    }

    #[inline]
    fn weight_magnitude(&self) -> f32 {
        self.concrete().weight_magnitude()
    }
}

impl From<BoxFilter> for AnyFilter {
    fn from(filter: BoxFilter) -> Self {
        AnyFilter::Box(filter)
    }
}

impl From<TentFilter> for AnyFilter {
    fn from(filter: TentFilter) -> Self {
        AnyFilter::Tent(filter)
    }
}

impl From<GaussianFilter> for AnyFilter {
    fn from(filter: GaussianFilter) -> Self {
        AnyFilter::Gaussian(filter)
    }
}

impl From<MitchellFilter> for AnyFilter {
    fn from(filter: MitchellFilter) -> Self {
        AnyFilter::Mitchell(filter)
    }
}

impl From<LanczosFilter> for AnyFilter {
    fn from(filter: LanczosFilter) -> Self {
        AnyFilter::Lanczos(filter)
    }
}

impl From<BlackmanHarrisFilter> for AnyFilter {
    fn from(filter: BlackmanHarrisFilter) -> Self {
        AnyFilter::BlackmanHarris(filter)
    }
}

/// `FilterKind` in settings files (feature `serde`): serialized as its
/// kebab-case [`name`](FilterKind::name), deserialized from it with the
/// same error as [`FromStr`].
#[cfg(feature = "serde")]
mod serde_impls {
    use serde::de::{Deserialize, Deserializer};
    use serde::ser::{Serialize, Serializer};

    use super::FilterKind;

    #[cfg_attr(docsrs, doc(cfg(feature = "serde")))]
    impl Serialize for FilterKind {
        fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
            serializer.serialize_str(self.name())
        }
    }

    #[cfg_attr(docsrs, doc(cfg(feature = "serde")))]
    impl<'de> Deserialize<'de> for FilterKind {
        fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
            crate::error::deserialize_name(
                deserializer,
                "a filter name such as \"gaussian\" or \"blackman-harris\"",
            )
        }
    }
}
