//! Quality metrics for point sets in `[0, 1)^2`: discrepancies, minimum
//! distances and stratification checks. They take `&[Vec2]` and know nothing
//! about samplers.
