//! AVL's stability-derivative output (the `ST` command's `.st` file) and its
//! conversion into the report's notation.
//!
//! AVL (M. Drela & H. Youngren, vortex lattice) prints, under
//! "Vortex Lattice Output -- Total Forces", the reference quantities
//! (`Sref = … Cref = … Bref = …`, `Xref = …`), the run case (`Alpha =`,
//! `Mach =`), the totals (`CLtot =`, `CDtot =`, `Cmtot =`, optionally
//! `CDind =`, `e =`), then "Stability-axis derivatives..." with `CLa`, `Cma`
//! (per radian) and `CLq`, `Cmq` (per q̂ = qc/2V), control columns, and
//! `Neutral point  Xnp =`. Axes: stability axes, X forward, Z down;
//! coefficients on ½ρV²Sref, moments also on Cref. AVL is quasi-steady:
//! there are no α̇ derivatives, and no speed derivatives.

use crate::numerics::display::{Excerpt, Num, excerpt};
use serde::Serialize;

/// Why a `.st` file cannot be read.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum AvlError {
    #[error(
        "line {line}: this is not AVL stability-derivative output (no `Vortex Lattice Output -- Total Forces` header before `{found}`)"
    )]
    NotStFile { line: usize, found: String },
    #[error("the file is empty")]
    Empty,
    #[error(
        "line {last_line}: the file ends without `{name}` (truncated, or written by an AVL version that does not print it); the derivatives need Sref, Cref, Bref, Alpha, Mach, CLtot, CDtot, Cmtot, CLa, Cma, CLq, Cmq"
    )]
    Missing {
        name: &'static str,
        last_line: usize,
    },
    #[error(
        "line {line}: `{} = {}`: the value is not a number",
        Excerpt(name),
        Excerpt(text)
    )]
    BadNumber {
        name: String,
        line: usize,
        text: String,
    },
    #[error(
        "line {line}: `{name} = {}`: the reference {what} must be positive (the coefficients are made non-dimensional on it)",
        Num(*value)
    )]
    NotPositive {
        name: &'static str,
        what: &'static str,
        value: f64,
        line: usize,
    },
    #[error(
        "line {line}: the section \"Stability-axis derivatives...\" is missing; found \"{found}\" (an AVL version or output this reader does not know)"
    )]
    NoStabilityAxes { line: usize, found: String },
}

impl AvlError {
    /// The 1-based line the error is on (0: the file as a whole).
    pub fn line(&self) -> usize {
        match self {
            AvlError::NotStFile { line, .. }
            | AvlError::BadNumber { line, .. }
            | AvlError::NotPositive { line, .. }
            | AvlError::NoStabilityAxes { line, .. } => *line,
            AvlError::Missing { last_line, .. } => *last_line,
            AvlError::Empty => 0,
        }
    }
}

/// The quantities of a `.st` file this program uses.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct StFile {
    pub sref: f64,
    pub cref: f64,
    pub bref: f64,
    pub xref: f64,
    /// Angle of attack (degrees).
    pub alpha_deg: f64,
    pub mach: f64,
    pub cl: f64,
    pub cd: f64,
    pub cm: f64,
    /// Induced drag, when printed.
    pub cd_ind: Option<f64>,
    /// Span efficiency, when printed.
    pub e: Option<f64>,
    /// ∂C_L/∂α, ∂C_m/∂α (per radian).
    pub cl_a: f64,
    pub cm_a: f64,
    /// ∂C_L/∂q̂, ∂C_m/∂q̂ with q̂ = qc/2V.
    pub cl_q: f64,
    pub cm_q: f64,
    /// Neutral point, when printed.
    pub xnp: Option<f64>,
}

/// Every `name = value` pair of a line (AVL glues a long negative number to
/// its `=`: `Cmb =-10.123456`).
fn pairs(line: &str) -> Vec<(String, String)> {
    let mut out = Vec::new();
    let mut start = 0;
    while let Some(rel) = line[start..].find('=') {
        let eq = start + rel;
        let name = line[start..eq]
            .split_whitespace()
            .last()
            .unwrap_or("")
            .to_string();
        let after = &line[eq + 1..];
        let trimmed = after.trim_start();
        let value: String = trimmed.chars().take_while(|c| !c.is_whitespace()).collect();
        if !name.is_empty() {
            out.push((name, value.clone()));
        }
        start = eq + 1 + (after.len() - trimmed.len()) + value.len();
        if start >= line.len() {
            break;
        }
    }
    out
}

/// Parse a `.st` file's text. Errors carry 1-based line numbers.
pub fn parse_st(text: &str) -> Result<StFile, AvlError> {
    if text.trim().is_empty() {
        return Err(AvlError::Empty);
    }
    let scan = Scan::of(text)?;
    let st = scan.st_file()?;
    if !scan.stability {
        return Err(AvlError::NoStabilityAxes {
            line: scan.last_line,
            found: "end of file".into(),
        });
    }
    scan.check_references(&st)?;
    Ok(st)
}

/// The `name = value` pairs of a `.st` file, with their lines.
struct Scan {
    values: Vec<(String, f64, usize)>,
    /// Whether the "Stability-axis derivatives" section was seen.
    stability: bool,
    last_line: usize,
}

impl Scan {
    fn of(text: &str) -> Result<Scan, AvlError> {
        let mut scan = Scan {
            values: Vec::new(),
            stability: false,
            last_line: 0,
        };
        let mut header = false;
        for (i, line) in text.lines().enumerate() {
            let n = i + 1;
            scan.last_line = n;
            if line.contains("Vortex Lattice Output") && line.contains("Total Forces") {
                header = true;
                continue;
            }
            if line.contains("Stability-axis derivatives") {
                scan.stability = true;
                continue;
            }
            if line.contains("Geometry-axis derivatives") && !scan.stability {
                return Err(AvlError::NoStabilityAxes {
                    line: n,
                    found: excerpt(line.trim()),
                });
            }
            let ps = pairs(line);
            if ps.is_empty() {
                continue;
            }
            if !header {
                return Err(not_st_file(n, line));
            }
            scan.line(n, ps)?;
        }
        if !header {
            return Err(not_st_file(1, text.lines().next().unwrap_or("")));
        }
        Ok(scan)
    }

    /// A line's pairs: the numbers kept, text after '=' that is not one of
    /// ours tolerated (e.g. "Configuration: …"), ours required to be
    /// finite numbers.
    fn line(&mut self, n: usize, pairs: Vec<(String, String)>) -> Result<(), AvlError> {
        for (name, v) in pairs {
            match v.parse::<f64>() {
                Ok(x) if x.is_finite() => self.values.push((name, x, n)),
                _ if REQUIRED.contains(&name.as_str()) || OPTIONAL.contains(&name.as_str()) => {
                    return Err(AvlError::BadNumber {
                        name,
                        line: n,
                        text: v,
                    });
                }
                _ => {}
            }
        }
        Ok(())
    }

    fn get(&self, name: &str) -> Option<(f64, usize)> {
        self.values
            .iter()
            .find(|(k, _, _)| k == name)
            .map(|(_, v, line)| (*v, *line))
    }

    fn st_file(&self) -> Result<StFile, AvlError> {
        let get = |name: &'static str| self.get(name).map(|(v, _)| v);
        let last_line = self.last_line;
        let need = |name: &'static str| get(name).ok_or(AvlError::Missing { name, last_line });
        Ok(StFile {
            sref: need("Sref")?,
            cref: need("Cref")?,
            bref: need("Bref")?,
            xref: get("Xref").unwrap_or(0.0),
            alpha_deg: need("Alpha")?,
            mach: need("Mach")?,
            cl: need("CLtot")?,
            cd: need("CDtot")?,
            cm: need("Cmtot")?,
            cd_ind: get("CDind"),
            e: get("e"),
            cl_a: need("CLa")?,
            cm_a: need("Cma")?,
            cl_q: need("CLq")?,
            cm_q: need("Cmq")?,
            xnp: get("Xnp"),
        })
    }

    /// Sref, Cref and Bref positive: the coefficients are made
    /// non-dimensional on them (μ₁ = m/(½ρ·Sref·Cref) downstream).
    fn check_references(&self, st: &StFile) -> Result<(), AvlError> {
        for (name, what, value) in [
            ("Sref", "area", st.sref),
            ("Cref", "chord", st.cref),
            ("Bref", "span", st.bref),
        ] {
            if value <= 0.0 {
                let line = self.get(name).map_or(self.last_line, |(_, l)| l);
                return Err(AvlError::NotPositive {
                    name,
                    what,
                    value,
                    line,
                });
            }
        }
        Ok(())
    }
}

fn not_st_file(line: usize, text: &str) -> AvlError {
    AvlError::NotStFile {
        line,
        found: text.trim().chars().take(40).collect(),
    }
}

const REQUIRED: [&str; 12] = [
    "Sref", "Cref", "Bref", "Alpha", "Mach", "CLtot", "CDtot", "Cmtot", "CLa", "Cma", "CLq", "Cmq",
];
const OPTIONAL: [&str; 4] = ["Xref", "CDind", "e", "Xnp"];

/// The report's derivatives from an `.st` file, with what had to be assumed.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FromAvl {
    pub x_u: f64,
    pub x_w: f64,
    pub z_u: f64,
    pub z_w: f64,
    pub z_q: f64,
    pub m_u: f64,
    pub m_w: f64,
    pub m_q: f64,
    pub c_l: f64,
    /// What the conversion assumed.
    pub notes: Vec<String>,
}

/// Convert AVL's stability-axis coefficients into the report's notation:
/// z_w = −C_Lα − C_D (eq 12), m_w = C_mα (14), z_q = −½C_Lq and
/// m_q = ½C_mq (q̂ = qc/2V), x_w = C_L − ∂C_D/∂α (11) with ∂C_D/∂α from the
/// induced drag of a parabolic polar, 2C_Di C_Lα/C_L; the speed derivatives
/// of eqs (9), (10), (13) without Mach effects (AVL has none):
/// x_u = −2C_D, z_u = −2C_L, m_u = 0. The acceleration derivatives are
/// zero: AVL is quasi-steady.
pub fn to_report(st: &StFile) -> FromAvl {
    let mut notes = vec![
        "AVL is quasi-steady: z_ẇ = m_ẇ = 0, and no speed derivatives: x_u = −2C_D, z_u = −2C_L, m_u = 0 (eqs 9, 10, 13 without Mach effects)".to_string(),
        "AVL's own eigenmodes add the apparent mass of its lifting surfaces, which the .st derivatives do not carry: expect its modes to differ".to_string(),
    ];
    let dcd_da = match st.cd_ind {
        Some(cdi) if st.cl != 0.0 => 2.0 * cdi * st.cl_a / st.cl,
        _ => {
            notes.push("no CDind in the file: ∂C_D/∂α taken as 0 in x_w".into());
            0.0
        }
    };
    if st.cm.abs() > 1e-3 {
        notes.push(format!(
            "Cmtot = {} ≠ 0: the case is not trimmed, and m_u = 0 assumes it is",
            st.cm
        ));
    }
    FromAvl {
        x_u: -2.0 * st.cd,
        x_w: st.cl - dcd_da,
        z_u: -2.0 * st.cl,
        z_w: -st.cl_a - st.cd,
        z_q: -0.5 * st.cl_q,
        m_u: 0.0,
        m_w: st.cm_a,
        m_q: 0.5 * st.cm_q,
        c_l: st.cl,
        notes,
    }
}
