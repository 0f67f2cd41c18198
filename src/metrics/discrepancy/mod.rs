//! Star discrepancy (exact) and the L2 discrepancies (Warnock's L2-star,
//! Hickernell's centred and wrap-around), one file per algorithm.

mod l2;
mod star;
mod wraparound;

pub use l2::{centered_l2_discrepancy, l2_star_discrepancy};
pub use star::star_discrepancy;
pub use wraparound::wraparound_l2_discrepancy;
#[doc(hidden)]
pub use wraparound::wraparound_l2_discrepancy_quadratic;
