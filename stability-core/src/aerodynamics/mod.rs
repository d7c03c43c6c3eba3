//! The aerodynamics of §5–7: from a planform (and a configuration's
//! surfaces and body) at a Mach number and a reduced frequency to the
//! coefficients and derivatives of the derivative set
//! ([`crate::derivatives`]).
//!
//! In layers, each naming only those below it:
//!
//! | module | what |
//! | --- | --- |
//! | [`theory`], [`warnings`] | the registry of the damping theories; validity limits approached |
//! | [`lifting_surface`] | one linear lifting-surface theory from M = 0 to 3: the doublet lattice, its near-sonic extrapolation, the Mach box, the multi-surface lattice, and the one store of their solutions |
//! | [`theodorsen`] | Theodorsen's function at a complex reduced frequency: the closed-form case the p-method is checked on |
//! | [`supersonic`], [`body`] | the closed-form theories: linear supersonic theory of deltas (eq 36 and beyond the sonic edge), a configuration's surfaces supersonic, slender-body theory (eq 43) |
//! | [`damping`], [`figures`] | each theory's damping derivatives (§7); the data of the note's figures that set theories side by side |
//! | [`models`] | the damping models (the default `faired` and the others), the aerodynamic model of the coefficients, the stiffness derivatives, a configuration's increment, the user's derivative tables |

pub mod body;
pub mod damping;
pub mod figures;
pub mod lifting_surface;
pub mod models;
pub mod supersonic;
pub mod theodorsen;
pub mod theory;
pub mod warnings;
