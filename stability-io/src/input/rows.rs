//! The rows of `stability-core/specs/notation.toml` the reader uses,
//! resolved at compile time: a name that is not a row stops the build (no
//! run-time fallback that could write a misspelt row into another).

use stability_core::data::notation::tables::ROWS;

const fn same(a: &str, b: &str) -> bool {
    let (a, b) = (a.as_bytes(), b.as_bytes());
    if a.len() != b.len() {
        return false;
    }
    let mut i = 0;
    while i < a.len() {
        if a[i] != b[i] {
            return false;
        }
        i += 1;
    }
    true
}

/// The row called `name`; not a row: a compile-time error where a
/// constant is defined with it.
pub const fn index(name: &str) -> usize {
    let mut i = 0;
    while i < ROWS.len() {
        if same(ROWS[i], name) {
            return i;
        }
        i += 1;
    }
    panic!("not a row of stability-core/specs/notation.toml")
}

const fn indices<const N: usize>(names: [&str; N]) -> [usize; N] {
    let mut out = [0; N];
    let mut i = 0;
    while i < N {
        out[i] = index(names[i]);
        i += 1;
    }
    out
}

/// The rows of a derivative set's `[derivatives]` table …
pub const DERIVATIVE_ROWS: [&str; 12] = [
    "x_u", "x_w", "x_wdot", "x_q", "z_u", "z_w", "z_wdot", "z_q", "m_u", "m_w", "m_wdot", "m_q",
];
/// … and of its `[flight]` table.
pub const FLIGHT_ROWS: [&str; 4] = ["c_l", "mu", "i_b", "c_d"];

pub const DERIVATIVES: [usize; 12] = indices(DERIVATIVE_ROWS);
pub const FLIGHT: [usize; 4] = indices(FLIGHT_ROWS);

pub const X_WDOT: usize = index("x_wdot");
pub const X_Q: usize = index("x_q");
pub const Z_WDOT: usize = index("z_wdot");
pub const C_L: usize = index("c_l");
pub const MU: usize = index("mu");
pub const I_B: usize = index("i_b");
pub const C_D: usize = index("c_d");

/// The fifteen rows the quartic needs: the derivatives, c_l, μ₁ and i_B.
pub const QUARTIC: [usize; 15] = {
    let mut out = [0; 15];
    let mut i = 0;
    while i < 12 {
        out[i] = DERIVATIVES[i];
        i += 1;
    }
    out[12] = C_L;
    out[13] = MU;
    out[14] = I_B;
    out
};

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_are_the_specs() {
        assert_eq!(ROWS[MU], "mu");
        assert_eq!(ROWS[QUARTIC[14]], "i_b");
        for (k, name) in DERIVATIVE_ROWS.iter().enumerate() {
            assert_eq!(ROWS[DERIVATIVES[k]], *name);
        }
    }
}
