//! What each sampler promises beyond the contract: one line per kind.

use wellspread::{
    AnySampler, CorrelatedMultiJittered, Hammersley, MultiJittered, NRooks, SamplerKind,
};

/// Where a point sits inside the finest stratum its sampler guarantees.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Offset {
    /// Uniform and independent in x and y (jitter; for `Random` the
    /// stratum is the whole square).
    Uniform,
    /// At the centre of its coarse cell, to within 2^-24.
    Centre,
}

/// What one sampler promises beyond the contract.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Guarantees {
    /// Exactly one point in each of the `n` columns of width `1 / n`.
    pub(crate) latin_x: bool,
    /// Exactly one point in each of the `n` rows of height `1 / n`.
    pub(crate) latin_y: bool,
    /// Exactly one point in each cell of the coarse `columns() x rows()` grid.
    pub(crate) strata: bool,
    /// Different patterns give different sets (`false`: only the order changes).
    pub(crate) pattern_changes_set: bool,
    /// The largest `n` its constructor accepts.
    pub(crate) max_n: u32,
    /// Its constructor also rejects an `n` whose most square grid has a
    /// side above 2^24 (a prime above 2^24, say).
    pub(crate) grid_sides_limited: bool,
    /// `None` when nothing is known about where points sit in their strata.
    pub(crate) offset: Option<Offset>,
    /// A whole set of `n = 2^m` points is a (0,m,2)-net in base 2.
    pub(crate) net_at_powers_of_two: bool,
    /// A sequence: `sample(index, pattern)` takes every u32 `index`
    /// whatever `n` is, and gives the same point for every `n` (a set is a
    /// prefix of the one sequence).
    pub(crate) any_index: bool,
    /// Every aligned block of `2^m` indices, anywhere in the u32 range (the
    /// power-of-two prefixes among them), is a (0,m,2)-net in base 2.
    pub(crate) block_nets: bool,
    /// Every prefix of `4^k` points is stratified on `2^k x 2^k`
    /// (progressive multi-jitter).
    pub(crate) square_prefixes: bool,
    /// Every run of `2^a 3^b` consecutive indices, starting anywhere, is
    /// stratified on `2^a x 3^b` (Halton's bases).
    pub(crate) halton_runs: bool,
}

/// Nothing beyond the contract; each line below says what it adds.
pub(crate) const CONTRACT: Guarantees = Guarantees {
    latin_x: false,
    latin_y: false,
    strata: false,
    pattern_changes_set: true,
    max_n: u32::MAX,
    grid_sides_limited: false,
    offset: None,
    net_at_powers_of_two: false,
    any_index: false,
    block_nets: false,
    square_prefixes: false,
    halton_runs: false,
};

/// One line per sampler: its specific guarantees. The match is exhaustive,
/// so a new kind does not compile until it has its line.
pub(crate) fn guarantees(kind: SamplerKind) -> Guarantees {
    use Offset::{Centre, Uniform};
    const SEQUENCE: Guarantees = Guarantees {
        net_at_powers_of_two: true,
        any_index: true,
        block_nets: true,
        ..CONTRACT
    };
    #[rustfmt::skip]
    let g = match kind {
        SamplerKind::Regular => Guarantees { strata: true, pattern_changes_set: false, grid_sides_limited: true, offset: Some(Centre), ..CONTRACT },
        SamplerKind::Random => Guarantees { offset: Some(Uniform), ..CONTRACT },
        SamplerKind::Jittered => Guarantees { strata: true, grid_sides_limited: true, offset: Some(Uniform), ..CONTRACT },
        SamplerKind::NRooks => Guarantees { latin_x: true, latin_y: true, max_n: NRooks::MAX_SAMPLES, offset: Some(Uniform), ..CONTRACT },
        SamplerKind::MultiJittered => Guarantees { latin_x: true, latin_y: true, strata: true, max_n: MultiJittered::MAX_SAMPLES, offset: Some(Uniform), ..CONTRACT },
        SamplerKind::CorrelatedMultiJittered => Guarantees { latin_x: true, latin_y: true, strata: true, max_n: CorrelatedMultiJittered::MAX_SAMPLES, offset: Some(Uniform), ..CONTRACT },
        SamplerKind::Hammersley => Guarantees { latin_x: true, max_n: Hammersley::MAX_SAMPLES, net_at_powers_of_two: true, ..CONTRACT },
        SamplerKind::Halton => Guarantees { any_index: true, halton_runs: true, ..CONTRACT },
        SamplerKind::Sobol => SEQUENCE,
        SamplerKind::Pmj02 => Guarantees { square_prefixes: true, ..SEQUENCE },
    };
    g
}

/// The coarse grid of the samplers that have one.
pub(crate) fn coarse_grid(sampler: &AnySampler) -> Option<(u32, u32)> {
    match sampler {
        AnySampler::Regular(s) => Some((s.columns(), s.rows())),
        AnySampler::Jittered(s) => Some((s.columns(), s.rows())),
        AnySampler::MultiJittered(s) => Some((s.columns(), s.rows())),
        AnySampler::CorrelatedMultiJittered(s) => Some((s.columns(), s.rows())),
        AnySampler::Random(_)
        | AnySampler::NRooks(_)
        | AnySampler::Hammersley(_)
        | AnySampler::Halton(_)
        | AnySampler::Sobol(_)
        | AnySampler::Pmj02(_) => None,
    }
}

/// The kinds whose line in [`guarantees`] has `property`.
pub(crate) fn kinds_with(property: fn(&Guarantees) -> bool) -> impl Iterator<Item = SamplerKind> {
    SamplerKind::ALL
        .iter()
        .copied()
        .filter(move |&kind| property(&guarantees(kind)))
}

/// Whether `kind`'s constructor must accept `n`: 1 to its `max_n`, and
/// with `grid_sides_limited` only when the most square grid of `n` has no
/// side above 2^24.
pub(crate) fn must_accept(kind: SamplerKind, n: u32) -> bool {
    let g = guarantees(kind);
    if !(1..=g.max_n).contains(&n) {
        return false;
    }
    if g.grid_sides_limited {
        let columns = (1..=n.isqrt())
            .rev()
            .find(|d| n.is_multiple_of(*d))
            .unwrap();
        return n / columns <= 1 << 24;
    }
    true
}
