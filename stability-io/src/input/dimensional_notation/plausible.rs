//! Warnings for a set no aircraft has: derivatives off
//! by orders from their class and roots faster than
//! [`RATE_MAX`] s⁻¹ ([`stability_core::data::dimensional::form::implausible`]),
//! with the likely unit mistake named.

use super::DimensionalFile;
use stability_core::data::dimensional::form::{RATE_MAX, implausible};
use stability_core::data::dimensional::{DimensionalAnalysis, Form};
use stability_core::numerics::display::sig;

impl DimensionalFile {
    /// The warnings about magnitudes no aircraft has: at most one about the
    /// derivatives and one about the roots.
    pub(super) fn implausible(&self) -> Vec<String> {
        let mut out = Vec::new();
        let off = implausible(&self.model);
        if !off.is_empty() {
            let list: Vec<String> = off
                .iter()
                .take(6)
                .map(|x| {
                    format!(
                        "{} = {} ({} = {} > {})",
                        x.name,
                        sig(x.value, 4),
                        x.class.measure_name(x.name),
                        sig(x.measure, 3),
                        sig(x.bound, 3)
                    )
                })
                .collect();
            out.push(format!(
                "{}: off by orders from what an aircraft has, in the model's form (per unit mass and inertia): {}{}; {}",
                self.path,
                list.join(", "),
                if off.len() > 6 { ", …" } else { "" },
                self.likely_mistake()
            ));
        }
        if let Ok(a) = DimensionalAnalysis::of(&self.model, None) {
            let fastest = a.roots.iter().map(|z| z.norm()).fold(0.0, f64::max);
            if fastest > RATE_MAX {
                out.push(format!(
                    "{}: a root of {} s⁻¹, faster than any aircraft's longitudinal motion ({} s⁻¹); {}",
                    self.path,
                    sig(fastest, 4),
                    sig(RATE_MAX, 3),
                    self.likely_mistake()
                ));
            }
        }
        out
    }

    /// The unit mistake that gives such magnitudes, in the file's form.
    fn likely_mistake(&self) -> &'static str {
        match self.form {
            Form::PerUnitMass => {
                "this looks like a table per force and moment (Etkin & Reid's Table 4.4: N·s/m, kg, N·m·s) typed as per unit mass: divide X and Z by m and M by I_y, or set form = \"per_force\" and give [reference] mass and I_y"
            }
            Form::PerForce => {
                "check that [reference] mass and I_y are in the table's units (kg and kg·m² with N·s/m; slug and slug·ft² with lbf·s/ft), and that the mass is not the weight"
            }
            Form::Alpha => {
                "check the units: the α form is per unit mass and per radian (Z_alpha = U₀Z_w in ft/s² or m/s²); a table per force, or per degree, gives this"
            }
        }
    }
}
