//! Every [`Sampler2D`](crate::Sampler2D), one file per sampler, in two
//! families with a shared core each: [`grid`] (stratified sets on a
//! `columns x rows` grid) and [`sequence`] (progressive sequences); and
//! the [`SamplerNd`](crate::SamplerNd) point sets of many dimensions in
//! [`nd`] (Latin hypercubes, orthogonal arrays). Two
//! samplers stand alone ([`Hammersley`], [`Random`]), and [`kind`] names
//! them all for choosing one at run time. Pixel samplers live in
//! `crate::pixel`.

mod grid;
mod hammersley;
mod kind;
mod nd;
mod random;
pub(crate) mod sequence;

pub use grid::{
    BlueMultiJittered, CorrelatedMultiJittered, Jittered, MultiJittered, NRooks, Regular,
};
pub use hammersley::Hammersley;
pub(crate) use kind::ALIAS_NAMES;
pub use kind::{AnySampler, SamplerKind, SamplerVisitor};
pub use nd::{LatinHypercube, OrthogonalArray, OrthogonalArrayOffset};
pub use random::Random;
pub use sequence::{Faure4D, Halton, Pmj02, Sobol, Sobol4D};
