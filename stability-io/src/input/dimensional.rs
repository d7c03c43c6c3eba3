//! The `[dimensional]` table: the flight condition in SI units, which
//! gives times in seconds (τ = m/(½ρSV)) and, where a notation has none,
//! μ₁ = m/(½ρSc̄) and i_B = I_y/(mc̄²).

use super::raw::{Ctx, RawDimensional};
use crate::diag::InputError;
use stability_core::analysis::Dimensional;
use stability_core::numerics::display::Num;
use std::ops::Range;
use toml::Spanned;

/// A value of the table and where it was written.
#[derive(Debug, Clone)]
pub struct Given {
    pub value: f64,
    pub span: Range<usize>,
    pub field: &'static str,
}

/// The `[dimensional]` values given, each positive and finite.
#[derive(Debug, Clone, Default)]
pub struct Dims {
    pub v: Option<Given>,
    pub rho: Option<Given>,
    pub s: Option<Given>,
    pub chord: Option<Given>,
    pub mass: Option<Given>,
    pub i_y: Option<Given>,
    /// The table's span (where a missing value is reported).
    pub span: Range<usize>,
}

fn positive(
    cx: &Ctx<'_>,
    field: &'static str,
    v: &Option<Spanned<f64>>,
) -> Result<Option<Given>, InputError> {
    let Some(v) = v else { return Ok(None) };
    let x = *v.get_ref();
    if x.is_finite() && x > 0.0 {
        Ok(Some(Given {
            value: x,
            span: v.span(),
            field,
        }))
    } else {
        Err(cx.err(
            v.span(),
            field,
            format!("must be a positive finite number, not {}", Num(x)),
        ))
    }
}

impl Dims {
    pub fn read(cx: &Ctx<'_>, raw: &Option<Spanned<RawDimensional>>) -> Result<Dims, InputError> {
        let Some(raw) = raw else {
            return Ok(Dims::default());
        };
        let d = raw.get_ref();
        Ok(Dims {
            v: positive(cx, "[dimensional] V", &d.v)?,
            rho: positive(cx, "[dimensional] rho", &d.rho)?,
            s: positive(cx, "[dimensional] S", &d.s)?,
            chord: positive(cx, "[dimensional] chord", &d.chord)?,
            mass: positive(cx, "[dimensional] mass", &d.mass)?,
            i_y: positive(cx, "[dimensional] I_y", &d.i_y)?,
            span: raw.span(),
        })
    }

    /// A value the notation cannot do without, or an error saying why it
    /// is needed.
    pub fn need<'d>(
        &self,
        cx: &Ctx<'_>,
        given: &'d Option<Given>,
        name: &str,
        why: &str,
    ) -> Result<&'d Given, InputError> {
        given.as_ref().ok_or_else(|| {
            cx.err(
                self.span.clone(),
                format!("[dimensional] {name}"),
                format!("missing: {why}"),
            )
        })
    }

    /// μ₁ = m/(½ρSc̄), where mass, rho, S and chord are given.
    pub fn mu1(&self) -> Option<(f64, &Given)> {
        let (m, rho, s, c) = (
            self.mass.as_ref()?,
            self.rho.as_ref()?,
            self.s.as_ref()?,
            self.chord.as_ref()?,
        );
        Some((m.value / (0.5 * rho.value * s.value * c.value), m))
    }

    /// i_B = I_y/(mc̄²), where mass, I_y and chord are given.
    pub fn i_b(&self) -> Option<(f64, &Given)> {
        let (m, iy, c) = (
            self.mass.as_ref()?,
            self.i_y.as_ref()?,
            self.chord.as_ref()?,
        );
        Some((iy.value / (m.value * c.value * c.value), iy))
    }

    /// The flight condition, where all of V, rho, S, chord and mass are given.
    pub fn dimensional(&self) -> Option<Dimensional> {
        Some(Dimensional {
            v: self.v.as_ref()?.value,
            rho: self.rho.as_ref()?.value,
            s: self.s.as_ref()?.value,
            chord: self.chord.as_ref()?.value,
            mass: self.mass.as_ref()?.value,
        })
    }
}
