//! The `[control]` table of a derivative file or config: the control
//! derivatives of the state space's input matrix B
//! ([`stability_core::dynamics::linear::Control`]).
//!
//! ```toml
//! [control]
//! name = "elevator"   # optional; what δ is (default "delta")
//! C_mdelta = -1.20    # ∂C_m/∂δ per radian (moment on ½ρV²Sc̄)
//! C_zdelta = -0.35    # ∂C_Z/∂δ per radian (Z down), or C_Ldelta = ∂C_L/∂δ (C_Z = −C_L); default 0
//! C_xdelta = 0.0      # ∂C_X/∂δ per radian; default 0
//! ```
//!
//! in the report's stability axes.

use crate::diag::InputError;
use crate::input::toml_error;
use serde::Deserialize;
use stability_core::dynamics::linear::Control;
use stability_core::numerics::display::Num;
use toml::Spanned;

#[derive(Deserialize)]
struct WithControl {
    control: Option<Spanned<RawControl>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
#[allow(non_snake_case)] // the fields are the coefficients' names
struct RawControl {
    name: Option<String>,
    C_xdelta: Option<Spanned<f64>>,
    C_zdelta: Option<Spanned<f64>>,
    C_Ldelta: Option<Spanned<f64>>,
    C_mdelta: Option<Spanned<f64>>,
}

/// The `[control]` table of a file's text, if it has one; every error
/// names the file, line and field.
pub fn read_control(path: &str, text: &str) -> Result<Option<Control>, InputError> {
    let raw: WithControl = toml::from_str(text).map_err(|e| toml_error(path, text, &e))?;
    let Some(c) = raw.control else {
        return Ok(None);
    };
    let span = c.span();
    let c = c.into_inner();
    let value = |field: &str, v: &Option<Spanned<f64>>| -> Result<Option<f64>, InputError> {
        match v {
            Some(v) if !v.get_ref().is_finite() => Err(InputError::at(
                path,
                text,
                v.span(),
                format!("[control] {field}"),
                format!("{} is not a finite number", Num(*v.get_ref())),
            )),
            Some(v) => Ok(Some(*v.get_ref())),
            None => Ok(None),
        }
    };
    let Some(c_m) = value("C_mdelta", &c.C_mdelta)? else {
        let m = "missing field `C_mdelta`: the control's moment derivative ∂C_m/∂δ per radian";
        return Err(InputError::at(path, text, span, "[control] C_mdelta", m));
    };
    let c_z = match (
        value("C_zdelta", &c.C_zdelta)?,
        value("C_Ldelta", &c.C_Ldelta)?,
    ) {
        (Some(_), Some(_)) => {
            let s = c.C_Ldelta.as_ref().map_or(span, |v| v.span());
            let m = "[control] C_zdelta and [control] C_Ldelta both give the control's normal force (C_Z = −C_L): give one";
            return Err(InputError::at(path, text, s, "[control] C_Ldelta", m));
        }
        (Some(z), None) => z,
        (None, Some(l)) => -l,
        (None, None) => 0.0,
    };
    let name = c.name.unwrap_or_else(|| "delta".into());
    let plain = |ch: char| ch.is_ascii_alphanumeric() || "_- ".contains(ch);
    if name.is_empty() || name.chars().count() > 32 || !name.chars().all(plain) {
        let m = format!(
            "the control's name `{}` must be 1 to 32 letters, digits, spaces, `_` or `-` (it names the input in the scripts)",
            crate::diag::quote(&name)
        );
        return Err(InputError::at(path, text, span, "[control] name", m));
    }
    Ok(Some(Control {
        name,
        c_x: value("C_xdelta", &c.C_xdelta)?.unwrap_or(0.0),
        c_z,
        c_m,
    }))
}
