//! The dynamics of the rigid aircraft in the pitch plane, from a derivative
//! set ([`crate::derivatives`]): the stability quartic (eqs 4–6,
//! [`quartic`]), its modes (eqs 7–8, [`modes`]) and the note's own method
//! for them ([`classical`]), responses (§11, [`response`]), the state-space
//! model ([`linear`]), mode shapes ([`mode_shape`]), the modes in seconds
//! ([`damp`]) and which derivative drives the damping (§10,
//! [`sensitivity`]).
//!
//! The longitudinal axis only today: each mode carries its name
//! ([`modes::ModeName`]) and so its axis; the lateral-directional axis
//! (Bryan's sideslip, roll and yaw equations, its own quartic from
//! `specs/`) goes beside these as `dynamics::lateral`.

pub mod classical;
pub mod damp;
pub mod linear;
pub mod mode_shape;
pub mod modes;
pub mod p_method;
pub mod quartic;
pub mod response;
pub mod sensitivity;
