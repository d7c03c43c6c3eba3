//! Figures as SVG (plotters) and the data behind them as CSV.

use plotters::prelude::*;
use std::fmt::Write;

/// The figure's size in the page (px).
const WIDTH: u32 = 800;
const HEIGHT: u32 = 520;
/// The drawing's resolution relative to that.
const SCALE: u32 = 4;

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
    /// Fixed y range; automatic when `None`.
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

    /// The figure as an SVG document.
    ///
    /// plotters draws on a grid of whole pixels; the figure is drawn at
    /// `SCALE` times its size and shown at 800 × 520 through the viewBox,
    /// so that slowly varying curves are smooth, not stepped.
    pub fn to_svg(&self) -> Result<String, String> {
        let mut buf = String::new();
        self.draw(&mut buf)
            .map_err(|e| format!("figure {}: {e}", self.id))?;
        let (w, h) = (WIDTH * SCALE, HEIGHT * SCALE);
        Ok(buf.replacen(
            &format!("width=\"{w}\" height=\"{h}\""),
            &format!("width=\"{WIDTH}\" height=\"{HEIGHT}\""),
            1,
        ))
    }

    /// The title as drawn: "Fig. 33 — …" for a figure of the note.
    fn caption(&self) -> String {
        if self.id.chars().all(|c| c.is_ascii_digit()) {
            format!("Fig. {} — {}", self.id, self.title)
        } else {
            self.title.clone()
        }
    }

    fn draw(&self, buf: &mut String) -> Result<(), Box<dyn std::error::Error + '_>> {
        let k = SCALE;
        let root = SVGBackend::with_string(buf, (WIDTH * k, HEIGHT * k)).into_drawing_area();
        let font = |size: u32| ("sans-serif", size * k);
        root.fill(&WHITE)?;
        let ((x0, x1), (y0, y1)) = self.ranges();
        let mut chart = ChartBuilder::on(&root)
            .caption(self.caption(), font(18))
            .margin(14 * k)
            .x_label_area_size(44 * k)
            .y_label_area_size(70 * k)
            .build_cartesian_2d(x0..x1, y0..y1)?;
        chart
            .configure_mesh()
            .x_desc(self.x_label.as_str())
            .y_desc(self.y_label.as_str())
            .light_line_style(RGBColor(235, 235, 235))
            .bold_line_style(BLACK.mix(0.2).stroke_width(k))
            .axis_style(BLACK.stroke_width(k))
            .label_style(font(12))
            .axis_desc_style(font(13))
            .set_all_tick_mark_size(4 * k)
            .draw()?;
        for (y, label) in &self.reference_lines {
            let y = *y;
            chart
                .draw_series(LineSeries::new(
                    [(x0, y), (x1, y)],
                    BLACK.mix(0.6).stroke_width(k),
                ))?
                .label(label.as_str())
                .legend(move |(x, yy)| {
                    PathElement::new(
                        vec![(x, yy), (x + 20 * k as i32, yy)],
                        BLACK.mix(0.6).stroke_width(k),
                    )
                });
        }
        for (i, s) in self.series.iter().enumerate() {
            let color = Palette99::pick(i).to_rgba();
            let mut first = true;
            for seg in segments(&s.points, y0, y1) {
                let drawn = chart.draw_series(LineSeries::new(seg, color.stroke_width(2 * k)))?;
                if first {
                    drawn.label(s.label.as_str()).legend(move |(x, y)| {
                        PathElement::new(
                            vec![(x, y), (x + 20 * k as i32, y)],
                            color.stroke_width(2 * k),
                        )
                    });
                    first = false;
                }
            }
        }
        if !self.series.is_empty() || !self.reference_lines.is_empty() {
            chart
                .configure_series_labels()
                .position(SeriesLabelPosition::UpperRight)
                .background_style(WHITE.mix(0.85))
                .border_style(BLACK.mix(0.4))
                .label_font(font(12))
                .legend_area_size(28 * k)
                .margin(10 * k)
                .draw()?;
        }
        root.present()?;
        Ok(())
    }

    /// The data as CSV, one column per series sharing x when they do, else
    /// long form (series, x, y).
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

/// The drawable runs of a curve: split at non-finite points and at points
/// far outside the y range [y0, y1].
fn segments(points: &[(f64, f64)], y0: f64, y1: f64) -> Vec<Vec<(f64, f64)>> {
    let mut out: Vec<Vec<(f64, f64)>> = vec![Vec::new()];
    for &(x, y) in points {
        if x.is_finite() && y.is_finite() && y >= y0 - (y1 - y0) && y <= y1 + (y1 - y0) {
            if let Some(seg) = out.last_mut() {
                seg.push((x, y));
            }
        } else if out.last().is_some_and(|seg| !seg.is_empty()) {
            out.push(Vec::new());
        }
    }
    out.retain(|s| !s.is_empty());
    out
}

/// A CSV number: empty for a non-finite value (never NaN in the output).
pub fn num(v: f64) -> String {
    if v.is_finite() {
        format!("{v}")
    } else {
        String::new()
    }
}

/// A CSV field, quoted when needed.
pub fn csv_field(s: &str) -> String {
    if s.contains([',', '"', '\n']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn svg_has_axes_labels_and_legend() {
        let fig = Figure::new("33", "Cycles to half amplitude", "Mach number M", "cycles")
            .with(Series::new(
                "45° delta",
                vec![(0.5, 0.3), (1.0, f64::NAN), (1.5, 0.8)],
            ))
            .with(Series::new(
                "60° delta",
                vec![(0.5, 0.2), (1.0, 0.4), (1.5, 0.5)],
            ));
        let svg = fig.to_svg().unwrap();
        assert!(svg.starts_with("<svg"));
        for text in [
            "Fig. 33",
            "Mach number M",
            "cycles",
            "45° delta",
            "60° delta",
        ] {
            assert!(svg.contains(text), "{text}");
        }
        assert!(!svg.contains("NaN"));
    }

    #[test]
    fn csv_shares_x_and_blanks_non_finite() {
        let fig = Figure::new("x", "t", "M", "y")
            .with(Series::new("a", vec![(0.5, 1.0), (1.0, f64::NAN)]))
            .with(Series::new("b", vec![(0.5, 2.0), (1.0, 3.0)]));
        assert_eq!(fig.to_csv(), "M,y [a],y [b]\n0.5,1,2\n1,,3\n");
    }
}
