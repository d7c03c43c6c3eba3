//! Shared helpers of the workspace-level tests: the spec model, a small
//! deterministic random generator and random derivative sets.

use formula_engine::notation::NotationModel;
use formula_engine::{QuarticModel, SourceFile};
use stability_core::Derivatives;
use std::path::Path;

/// The workspace root.
pub fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("the tests crate sits in the workspace root")
}

/// `stability-core/specs/quartic.toml`, loaded and verified by the engine.
pub fn quartic_model() -> QuarticModel {
    let rel = "stability-core/specs/quartic.toml";
    let text =
        std::fs::read_to_string(root().join(rel)).expect("read stability-core/specs/quartic.toml");
    match QuarticModel::load(&SourceFile::new(rel, text)) {
        Ok(m) => m,
        Err(d) => panic!("{d}"),
    }
}

/// `stability-core/specs/notation.toml`, loaded and verified by the engine.
pub fn notation_model() -> NotationModel {
    let rel = "stability-core/specs/notation.toml";
    let text =
        std::fs::read_to_string(root().join(rel)).expect("read stability-core/specs/notation.toml");
    match NotationModel::load(&SourceFile::new(rel, text)) {
        Ok(m) => m,
        Err(d) => panic!("{d}"),
    }
}

/// SplitMix64 (Steele, Lea & Flood, "Fast splittable pseudorandom number
/// generators", OOPSLA 2014): a deterministic generator for test data.
pub struct SplitMix64(pub u64);

impl SplitMix64 {
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in [lo, hi).
    pub fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }

    /// Log-uniform in [lo, hi), lo > 0.
    pub fn log_uniform(&mut self, lo: f64, hi: f64) -> f64 {
        (lo.ln() + (hi.ln() - lo.ln()) * self.unit()).exp()
    }
}

/// A random derivative set: every derivative of either sign with a
/// magnitude spread over three decades, μ₁ from 5 to 5000, i_B from 0.01 to
/// 2, C_L from 0.01 to 1.5.
pub fn random_derivatives(rng: &mut SplitMix64) -> Derivatives {
    let mut v = [0.0; 15];
    for x in v.iter_mut().take(12) {
        let mag = rng.log_uniform(1e-2, 10.0);
        *x = if rng.unit() < 0.5 { -mag } else { mag };
    }
    v[12] = rng.log_uniform(0.01, 1.5);
    v[13] = rng.log_uniform(5.0, 5000.0);
    v[14] = rng.log_uniform(0.01, 2.0);
    Derivatives::from_quartic_input_values(v)
}
