//! The models a design point is computed with: the damping model
//! (the type [`damping_model::DampingModel`]: [`faired`] and the others), the aerodynamic
//! model of the coefficients ([`aero`]), the stiffness derivatives
//! ([`stiffness`]), a configuration's increment over its wing
//! ([`increment`]) and the user's derivative tables
//! ([`derivative_tables`]).

pub mod aero;
pub mod damping_model;
pub mod defaults;
pub mod derivative_tables;
pub mod error;
pub mod faired;
pub mod increment;
pub mod regime;
pub mod stiffness;
pub mod table;
