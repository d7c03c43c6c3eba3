//! The report's eq (6) exactly as printed, with no errata declared: the
//! build must name the three misprints.
use derive_quartic::Quartic;

#[derive(Quartic)]
#[quartic(spec = "tests/ui/specs/eq6_as_printed.toml")]
struct Derivatives {
    x_u: f64,
    x_w: f64,
    x_wdot: f64,
    x_q: f64,
    z_u: f64,
    z_w: f64,
    z_wdot: f64,
    z_q: f64,
    m_u: f64,
    m_w: f64,
    m_wdot: f64,
    m_q: f64,
    c_l: f64,
    mu1: f64,
    i_b: f64,
}

fn main() {}
