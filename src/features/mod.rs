//! Optional integrations with other crates, each behind its feature.

#[cfg(feature = "approx")]
mod impl_approx;
#[cfg(feature = "mint")]
mod impl_mint;
