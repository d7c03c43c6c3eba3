//! Figures as SVG (plotters) and the data behind them as CSV.
//!
//! A [`Figure`] is its curves ([`Series`]) and what is drawn behind them:
//! horizontal reference lines, shaded [`Band`]s (e.g. where a model is
//! faired between theories), labelled [`VerticalLine`]s (e.g. where a
//! wing's leading edge turns sonic) and [`Band`]s named along the top
//! (`regions`). How it is drawn — the series' styles, the legend below the
//! frame, the off-scale notes — is the private module `svg`'s; the CSV
//! ([`Figure::to_csv`]) holds the curves' data only, its numbers written by
//! [`num`]. A [`Plate`] is a figure of a report with its caption and
//! file name.

mod legend;
mod svg;

use std::fmt::Write;

/// Significant digits of a number written on a figure (off-scale notes).
pub const LABEL_DIGITS: usize = 3;

/// One curve of a figure.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    pub label: String,
    /// (x, y); non-finite points break the line.
    pub points: Vec<(f64, f64)>,
}

impl Series {
    pub fn new(label: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Series {
            label: label.into(),
            points,
        }
    }
}

/// A range of x: shaded behind the curves (`Figure::bands`, labelled once
/// in the legend) or named along the top (`Figure::regions`). Either end
/// may lie outside the figure's x range (infinite, say); it is drawn
/// clipped to it.
#[derive(Debug, Clone, PartialEq)]
pub struct Band {
    pub from: f64,
    pub to: f64,
    pub label: String,
}

/// A vertical dashed line at `x`, labelled above the frame.
#[derive(Debug, Clone, PartialEq)]
pub struct VerticalLine {
    pub x: f64,
    pub label: String,
}

/// A line chart with labelled axes (units in the labels) and a legend.
#[derive(Debug, Clone, PartialEq)]
pub struct Figure {
    /// The report's figure number (e.g. "33") or a name.
    pub id: String,
    pub title: String,
    pub x_label: String,
    pub y_label: String,
    pub series: Vec<Series>,
    /// Horizontal reference lines (y, label), e.g. the one-cycle standard.
    pub reference_lines: Vec<(f64, String)>,
    /// Shaded ranges of x behind the curves, each label once in the legend.
    pub bands: Vec<Band>,
    /// Ranges of x named along the top of the frame.
    pub regions: Vec<Band>,
    /// Vertical lines, labelled above the frame.
    pub markers: Vec<VerticalLine>,
    /// Fixed y range; automatic (every finite point inside) when `None`.
    pub y_range: Option<(f64, f64)>,
}

impl Figure {
    pub fn new(
        id: impl Into<String>,
        title: impl Into<String>,
        x_label: impl Into<String>,
        y_label: impl Into<String>,
    ) -> Self {
        Figure {
            id: id.into(),
            title: title.into(),
            x_label: x_label.into(),
            y_label: y_label.into(),
            series: Vec::new(),
            reference_lines: Vec::new(),
            bands: Vec::new(),
            regions: Vec::new(),
            markers: Vec::new(),
            y_range: None,
        }
    }

    pub fn with(mut self, s: Series) -> Self {
        self.series.push(s);
        self
    }

    fn finite_points(&self) -> impl Iterator<Item = (f64, f64)> + '_ {
        self.series
            .iter()
            .flat_map(|s| s.points.iter().copied())
            .filter(|(x, y)| x.is_finite() && y.is_finite())
    }

    /// The axes' ranges: x over every finite point; y fixed, or over every
    /// finite point and reference line with 5 % to spare.
    fn ranges(&self) -> ((f64, f64), (f64, f64)) {
        let (mut x0, mut x1, mut y0, mut y1) = (
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
        );
        for (x, y) in self.finite_points() {
            x0 = x0.min(x);
            x1 = x1.max(x);
            y0 = y0.min(y);
            y1 = y1.max(y);
        }
        for (y, _) in &self.reference_lines {
            y0 = y0.min(*y);
            y1 = y1.max(*y);
        }
        if !x0.is_finite() {
            (x0, x1) = (0.0, 1.0);
        }
        if !y0.is_finite() {
            (y0, y1) = (0.0, 1.0);
        }
        if x1 <= x0 {
            x1 = x0 + 1.0;
        }
        if let Some(r) = self.y_range {
            (y0, y1) = r;
        } else {
            let pad = if y1 > y0 {
                0.05 * (y1 - y0)
            } else {
                0.5 * y0.abs().max(1.0)
            };
            y0 -= pad;
            y1 += pad;
        }
        ((x0, x1), (y0, y1))
    }

    /// The title as drawn: "Fig. 33 — …" for a figure of the note.
    fn caption(&self) -> String {
        if self.id.chars().all(|c| c.is_ascii_digit()) {
            format!("Fig. {} — {}", self.id, self.title)
        } else {
            self.title.clone()
        }
    }

    /// The x variable's symbol, for notes like "max 12.3 at M = 1.2": the
    /// x label without its parenthesis, up to its first " = " ("t̂ = t/τ":
    /// t̂), else its last word ("Mach number M": M).
    fn x_symbol(&self) -> &str {
        let label = self.x_label.split(" (").next().unwrap_or_default();
        match label.split_once(" = ") {
            Some((lhs, _)) => lhs,
            None => label.rsplit(' ').next().unwrap_or(label),
        }
    }

    /// Where series `s` leaves the y range [y0, y1]: its largest value
    /// above, its smallest below, each as (x, y) — the off-scale notes.
    fn excursions(s: &Series, (y0, y1): (f64, f64)) -> [Option<(f64, f64)>; 2] {
        let finite = || {
            s.points
                .iter()
                .copied()
                .filter(|p| p.0.is_finite() && p.1.is_finite())
        };
        let above = finite()
            .filter(|p| p.1 > y1)
            .max_by(|a, b| a.1.total_cmp(&b.1));
        let below = finite()
            .filter(|p| p.1 < y0)
            .min_by(|a, b| a.1.total_cmp(&b.1));
        [above, below]
    }

    /// Series `s`'s note when it leaves the y range, for its legend entry:
    /// "↑ off scale: max 12.3 at M = 1.2".
    fn off_scale_note(&self, s: &Series, y: (f64, f64)) -> Option<String> {
        let [above, below] = Self::excursions(s, y);
        let say = |arrow: &str, what: &str, (x, v): (f64, f64)| {
            format!(
                "{arrow} off scale: {what} {} at {} = {}",
                short(v),
                self.x_symbol(),
                short(x)
            )
        };
        let notes: Vec<String> = [
            above.map(|p| say("↑", "max", p)),
            below.map(|p| say("↓", "min", p)),
        ]
        .into_iter()
        .flatten()
        .collect();
        (!notes.is_empty()).then(|| notes.join("; "))
    }

    /// The figure as an SVG document (800 × 520).
    pub fn to_svg(&self) -> Result<String, String> {
        svg::render(self)
    }

    /// The data as CSV, one column per series sharing x when they do, else
    /// long form (series, x, y). Bands, regions and lines are not data.
    pub fn to_csv(&self) -> String {
        let mut s = String::new();
        let shared_x = self.series.windows(2).all(|w| {
            w[0].points.len() == w[1].points.len()
                && w[0]
                    .points
                    .iter()
                    .zip(&w[1].points)
                    .all(|(a, b)| a.0 == b.0)
        });
        if shared_x && !self.series.is_empty() {
            let _ = write!(s, "{}", csv_field(&self.x_label));
            for ser in &self.series {
                let _ = write!(
                    s,
                    ",{}",
                    csv_field(&format!("{} [{}]", self.y_label, ser.label))
                );
            }
            s.push('\n');
            for (i, (x, _)) in self.series[0].points.iter().enumerate() {
                let _ = write!(s, "{}", num(*x));
                for ser in &self.series {
                    let _ = write!(s, ",{}", num(ser.points[i].1));
                }
                s.push('\n');
            }
        } else {
            let _ = writeln!(
                s,
                "series,{},{}",
                csv_field(&self.x_label),
                csv_field(&self.y_label)
            );
            for ser in &self.series {
                for (x, y) in &ser.points {
                    let _ = writeln!(s, "{},{},{}", csv_field(&ser.label), num(*x), num(*y));
                }
            }
        }
        s
    }
}

/// One figure of a report, with its caption for the page: written as
/// `figNN.svg` and `figNN.csv` (the note's figure NN), or under a name of
/// its own.
#[derive(Debug, Clone, PartialEq)]
pub struct Plate {
    pub figure: Figure,
    pub caption: String,
    /// The files' name, when not the note's `figNN` ([`Plate::named`]).
    pub file: Option<String>,
}

impl Plate {
    pub fn new(figure: Figure, caption: impl Into<String>) -> Plate {
        Plate {
            figure,
            caption: caption.into(),
            file: None,
        }
    }

    /// A figure written as `file.svg` and `file.csv` (a design report's
    /// `cycles-to-half`, say).
    pub fn named(file: &str, figure: Figure, caption: impl Into<String>) -> Plate {
        Plate {
            file: Some(file.to_string()),
            ..Plate::new(figure, caption)
        }
    }

    /// The file name without extension: `fig02`, `fig33` (or its own).
    pub fn name(&self) -> String {
        if let Some(f) = &self.file {
            return f.clone();
        }
        format!("fig{:0>2}", self.figure.id)
    }

    /// The figure's two files, `figNN.svg` and `figNN.csv`.
    pub fn files(&self) -> Result<[(String, Vec<u8>); 2], String> {
        let name = self.name();
        Ok([
            (format!("{name}.svg"), self.figure.to_svg()?.into_bytes()),
            (format!("{name}.csv"), self.figure.to_csv().into_bytes()),
        ])
    }
}

/// A CSV number: [`crate::csv::number`], the one rule for every
/// number the program writes in CSV (12 significant digits, the shortest
/// decimal that reads back, exponent form for the very small and large,
/// empty where not finite).
pub use crate::csv::number as num;

/// A number written on a figure or its caption: [`LABEL_DIGITS`]
/// significant digits, shortest form (12.3, 1.2, 100).
pub fn short(v: f64) -> String {
    format!(
        "{}",
        stability_core::numerics::display::round_to(v, LABEL_DIGITS)
    )
}

pub use crate::csv::field as csv_field;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn csv_shares_x_and_blanks_non_finite() {
        let fig = Figure::new("x", "t", "M", "y")
            .with(Series::new("a", vec![(0.5, 1.0), (1.0, f64::NAN)]))
            .with(Series::new("b", vec![(0.5, 2.0), (1.0, 3.0)]));
        assert_eq!(fig.to_csv(), "M,y [a],y [b]\n0.5,1,2\n1,,3\n");
    }

    #[test]
    fn csv_numbers_carry_no_grid_noise_and_twelve_significant_digits() {
        // a Mach grid built as a + step·i (the library's `grid` rounds its
        // values itself; a caller's own may not)
        let ms: Vec<f64> = (0..=150).map(|i| 0.5 + 0.01 * i as f64).collect();
        assert_ne!(ms[7], 0.57, "the grid point carries float noise");
        let fig = Figure::new("x", "t", "Mach number M", "y")
            .with(Series::new("a", ms.iter().map(|&m| (m, m)).collect()));
        let csv = fig.to_csv();
        assert!(csv.lines().any(|l| l == "0.57,0.57"), "{csv}");
        assert!(!csv.contains("00000000"), "{csv}");
        // every x reads back as the decimal grid point, 0.50 … 2.00
        for (i, line) in csv.lines().skip(1).enumerate() {
            let x: f64 = line.split(',').next().unwrap().parse().unwrap();
            let decimal = format!("{}.{:02}", (50 + i) / 100, (50 + i) % 100);
            assert_eq!(x, decimal.parse::<f64>().unwrap(), "{line}");
        }
        // data keep 12 significant digits, whatever their magnitude
        assert_eq!(num(0.11371015967272328), "0.113710159673");
        assert_eq!(num(-123456.78901234567), "-123456.789012");
        assert_eq!(num(1.0 / 3.0 * 1e-7), "3.33333333333e-8");
        assert_eq!(num(2.0), "2");
        assert_eq!(num(-0.0), "0");
        assert_eq!(num(f64::NAN), "");
        assert_eq!(num(f64::INFINITY), "");
    }

    #[test]
    fn the_x_symbol_names_the_variable() {
        let sym = |x: &str| Figure::new("1", "t", x, "y").x_symbol().to_string();
        assert_eq!(sym("Mach number M"), "M");
        assert_eq!(sym("t̂ = t/τ"), "t̂");
        assert_eq!(sym("m = β cot Λ = cot Λ/tan μ"), "m");
        assert_eq!(sym("aspect ratio A (true delta, A = 4 cot Λ)"), "A");
        assert_eq!(sym("c.g. position h (fraction of M.A.C.)"), "h");
    }

    #[test]
    fn a_curve_leaving_a_fixed_range_is_noted_with_its_extreme() {
        let mut fig = Figure::new("33", "t", "Mach number M", "cycles").with(Series::new(
            "45° delta",
            vec![
                (1.0, 2.0),
                (1.02, 12.34),
                (1.04, 7.0),
                (1.1, -3.0),
                (1.2, 1.0),
            ],
        ));
        fig.y_range = Some((-2.0, 6.0));
        let note = fig.off_scale_note(&fig.series[0], (-2.0, 6.0));
        assert_eq!(
            note.as_deref(),
            Some("↑ off scale: max 12.3 at M = 1.02; ↓ off scale: min -3 at M = 1.1")
        );
        assert_eq!(fig.off_scale_note(&fig.series[0], (-5.0, 20.0)), None);
    }
}
