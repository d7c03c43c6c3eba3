//! Drawing a [`Figure`] as SVG (plotters). The rules, each defined once:
//!
//! - series k is told apart by colour *and* line: an Okabe–Ito colour
//!   ([`PALETTE`], safe for the common colour-vision deficiencies), a dash
//!   pattern ([`DASHES`]) and a marker ([`MARKERS`]) — [`style`] — so the
//!   curves can be told apart in print too; the legend shows each
//!   series' line and marker as drawn;
//! - the legend lies below the frame ([`super::legend`]), never over a
//!   curve;
//! - bands are shaded ([`BAND`]) behind the curves; vertical lines are
//!   dashed ([`GUIDE`]) and, with the regions, labelled in a strip above
//!   the frame;
//! - a curve is clipped at the frame; where it leaves a fixed y range an
//!   arrow marks the place on the frame's edge and its legend entry says
//!   how far (`Figure::off_scale_note`).
//!
//! plotters draws on a grid of whole pixels; the figure is drawn at
//! [`SCALE`] times its size and shown at 800 × 520 through the viewBox, so
//! that slowly varying curves are smooth, not stepped. Lengths below are
//! in the page's pixels.

use super::legend::{Entry, Legend, Sample, text_width};
use super::{Figure, Series};
use plotters::coord::Shift;
use plotters::coord::types::RangedCoordf64;
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// The figure's size in the page (px).
pub(super) const WIDTH: u32 = 800;
pub(super) const HEIGHT: u32 = 520;
/// The drawing's resolution relative to that.
pub(super) const SCALE: u32 = 4;

const MARGIN: u32 = 14;
const TITLE_FONT: u32 = 18;
/// The title's line, font and spacing.
const TITLE: u32 = 28;
const X_LABEL_AREA: u32 = 44;
const Y_LABEL_AREA: u32 = 70;
/// One row of the strip above the frame (regions, vertical lines' labels).
const STRIP_ROW: u32 = 15;
const STRIP_FONT: u32 = 11;
const TICK_FONT: u32 = 12;
const AXIS_FONT: u32 = 13;
/// The width the legend may take: the frame's.
pub(super) const LEGEND_WIDTH: u32 = WIDTH - 2 * MARGIN - Y_LABEL_AREA;

/// Okabe & Ito's colour-blind-safe palette (Color Universal Design, 2008)
/// without its yellow, too faint on white: blue, vermillion, bluish green,
/// reddish purple, orange, sky blue, black.
pub(super) const PALETTE: [RGBColor; 7] = [
    RGBColor(0, 114, 178),
    RGBColor(213, 94, 0),
    RGBColor(0, 158, 115),
    RGBColor(204, 121, 167),
    RGBColor(230, 159, 0),
    RGBColor(86, 180, 233),
    RGBColor(0, 0, 0),
];
/// A band's shade: black at this opacity, so the grid shows through.
pub(super) const BAND: (RGBColor, f64) = (RGBColor(0, 0, 0), 0.09);
/// Reference and vertical lines.
pub(super) const GUIDE: RGBColor = RGBColor(80, 80, 80);
/// The frame around the plotting area.
pub(super) const FRAME: RGBColor = RGBColor(64, 64, 64);

/// A line's dash pattern: (dash, gap) in px, or solid.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Dash {
    Solid,
    Dashed,
    Dotted,
}

impl Dash {
    fn pattern(self) -> Option<(u32, u32)> {
        match self {
            Dash::Solid => None,
            Dash::Dashed => Some((9, 5)),
            Dash::Dotted => Some((2, 4)),
        }
    }
}

/// A series' point marker.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Marker {
    None,
    Circle,
    Triangle,
    Square,
}

pub(super) const DASHES: [Dash; 3] = [Dash::Solid, Dash::Dashed, Dash::Dotted];
pub(super) const MARKERS: [Marker; 4] = [
    Marker::None,
    Marker::Circle,
    Marker::Triangle,
    Marker::Square,
];
/// A curve's line width.
const LINE: u32 = 2;
/// A marker's half-size.
const MARK: u32 = 4;
/// About this many markers along a curve.
const MARKS_PER_CURVE: usize = 12;

/// How series k is drawn.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Style {
    pub colour: RGBColor,
    pub dash: Dash,
    pub marker: Marker,
}

/// Series k's style: colour k mod 7, dash k mod 3, marker k mod 4 — no two
/// of twelve consecutive series alike even without colour.
pub(super) fn style(k: usize) -> Style {
    Style {
        colour: PALETTE[k % PALETTE.len()],
        dash: DASHES[k % DASHES.len()],
        marker: MARKERS[k % MARKERS.len()],
    }
}

/// A length in the drawing's pixels.
pub(super) const fn px(v: u32) -> i32 {
    (v * SCALE) as i32
}

/// The figures' one typeface, black, at a size (px).
pub(super) fn font(size: u32) -> TextStyle<'static> {
    TextStyle::from(("sans-serif", px(size)).into_font()).color(&BLACK)
}

type Root<'b> = DrawingArea<SVGBackend<'b>, Shift>;
type DrawResult = Result<(), DrawingAreaErrorKind<std::io::Error>>;

/// The plotting area in the drawing's pixels and the map to it.
pub(super) struct Frame {
    x: (f64, f64),
    y: (f64, f64),
    pub left: i32,
    pub right: i32,
    pub top: i32,
    pub bottom: i32,
}

impl Frame {
    /// A point's pixel (linear, as plotters maps the mesh).
    fn at(&self, (x, y): (f64, f64)) -> (i32, i32) {
        let lerp = |v: f64, (v0, v1): (f64, f64), p0: i32, p1: i32| {
            (f64::from(p0) + (v - v0) / (v1 - v0) * f64::from(p1 - p0)).round() as i32
        };
        (
            lerp(x, self.x, self.left, self.right),
            lerp(y, self.y, self.bottom, self.top),
        )
    }

    /// x clamped to the frame's range.
    fn clamp_x(&self, x: f64) -> f64 {
        x.clamp(self.x.0, self.x.1)
    }
}

pub(super) fn render(fig: &Figure) -> Result<String, String> {
    let mut buf = String::new();
    draw(fig, &mut buf).map_err(|e| format!("figure {}: {e}", fig.id))?;
    let (w, h) = (WIDTH * SCALE, HEIGHT * SCALE);
    Ok(buf.replacen(
        &format!("width=\"{w}\" height=\"{h}\""),
        &format!("width=\"{WIDTH}\" height=\"{HEIGHT}\""),
        1,
    ))
}

fn draw<'a>(fig: &Figure, buf: &'a mut String) -> Result<(), Box<dyn std::error::Error + 'a>> {
    let root = SVGBackend::with_string(buf, (WIDTH * SCALE, HEIGHT * SCALE)).into_drawing_area();
    root.fill(&WHITE)?;
    let ((x0, x1), (y0, y1)) = fig.ranges();
    let legend = Legend::new(legend_entries(fig, (y0, y1)), LEGEND_WIDTH);
    let strip = strip_rows(fig) * STRIP_ROW;
    let (upper, _) = root.split_vertically(px(HEIGHT - legend.height()));
    root.draw(&Text::new(
        fig.caption(),
        (px(WIDTH / 2), px(MARGIN)),
        font(TITLE_FONT).pos(Pos::new(HPos::Center, VPos::Top)),
    ))?;
    let mut chart = ChartBuilder::on(&upper)
        .margin(px(MARGIN))
        .margin_top(px(MARGIN + TITLE + strip))
        .x_label_area_size(px(X_LABEL_AREA))
        .y_label_area_size(px(Y_LABEL_AREA))
        .build_cartesian_2d(x0..x1, y0..y1)?;
    mesh(&mut chart, fig)?;
    let corner = |p| chart.backend_coord(&p);
    let ((left, bottom), (right, top)) = (corner((x0, y0)), corner((x1, y1)));
    let frame = Frame {
        x: (x0, x1),
        y: (y0, y1),
        left,
        right,
        top,
        bottom,
    };
    backdrop(&root, &frame, fig)?;
    for (k, s) in fig.series.iter().enumerate() {
        curve(&root, &frame, s, style(k))?;
    }
    strip_labels(&root, &frame, fig)?;
    legend.draw(
        &root,
        (px(MARGIN + Y_LABEL_AREA), px(HEIGHT - legend.height())),
        LEGEND_WIDTH,
    )?;
    root.present()?;
    Ok(())
}

type Chart<'a, 'b> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

fn mesh(chart: &mut Chart<'_, '_>, fig: &Figure) -> DrawResult {
    chart
        .configure_mesh()
        .x_desc(fig.x_label.as_str())
        .y_desc(fig.y_label.as_str())
        .light_line_style(RGBColor(235, 235, 235))
        .bold_line_style(BLACK.mix(0.2).stroke_width(SCALE))
        .axis_style(FRAME.stroke_width(SCALE))
        .label_style(font(TICK_FONT))
        .axis_desc_style(font(AXIS_FONT))
        .set_all_tick_mark_size(px(4))
        .draw()
}

/// What lies behind the curves: the bands, the frame, the reference and
/// vertical lines.
fn backdrop(root: &Root<'_>, frame: &Frame, fig: &Figure) -> DrawResult {
    let (fill, alpha) = BAND;
    for b in &fig.bands {
        let (from, to) = (frame.clamp_x(b.from), frame.clamp_x(b.to));
        if to > from {
            let (a, z) = (frame.at((from, frame.y.1)), frame.at((to, frame.y.0)));
            root.draw(&Rectangle::new([a, z], fill.mix(alpha).filled()))?;
        }
    }
    root.draw(&Rectangle::new(
        [(frame.left, frame.top), (frame.right, frame.bottom)],
        FRAME,
    ))?;
    for (y, _) in &fig.reference_lines {
        if (frame.y.0..=frame.y.1).contains(y) {
            let (a, z) = (frame.at((frame.x.0, *y)), frame.at((frame.x.1, *y)));
            root.draw(&PathElement::new(vec![a, z], GUIDE.stroke_width(SCALE)))?;
        }
    }
    for m in &fig.markers {
        if let Some(x) = visible_x(frame, m.x) {
            let top = frame.top - px(STRIP_ROW) * strip_row_of_markers(fig) as i32;
            let line = [(x, frame.bottom), (x, top)];
            root.draw(&DashedPathElement::new(
                line,
                px(6),
                px(4),
                GUIDE.stroke_width(SCALE),
            ))?;
        }
    }
    Ok(())
}

/// x's pixel when it lies within the frame's x range.
fn visible_x(frame: &Frame, x: f64) -> Option<i32> {
    (x.is_finite() && x >= frame.x.0 && x <= frame.x.1).then(|| frame.at((x, frame.y.0)).0)
}

/// A series: its line clipped to the frame, its markers, and an arrow at
/// the frame's edge where it leaves the y range.
fn curve(root: &Root<'_>, frame: &Frame, s: &Series, st: Style) -> DrawResult {
    for run in clipped(&s.points, frame.y) {
        let pixels: Vec<(i32, i32)> = run.into_iter().map(|p| frame.at(p)).collect();
        line(root, pixels, st)?;
    }
    let inside: Vec<(f64, f64)> = s
        .points
        .iter()
        .copied()
        .filter(|&(x, y)| x.is_finite() && (frame.y.0..=frame.y.1).contains(&y))
        .collect();
    let stride = inside.len().div_ceil(MARKS_PER_CURVE).max(1);
    // staggered by the marker's kind, so that neighbouring curves' markers
    // do not sit on one another
    let offset = (st.marker as usize * stride) / MARKERS.len();
    for (i, p) in inside.iter().enumerate() {
        if (i + offset).is_multiple_of(stride) {
            marker(root, frame.at(*p), st)?;
        }
    }
    let [above, below] = Figure::excursions(s, frame.y);
    for (p, up) in [(above, true), (below, false)] {
        if let Some((x, _)) = p {
            arrow(root, frame, x, up, st.colour)?;
        }
    }
    Ok(())
}

/// A line through pixels in a series' style.
pub(super) fn line(root: &Root<'_>, pixels: Vec<(i32, i32)>, st: Style) -> DrawResult {
    let stroke = st.colour.stroke_width(px(LINE) as u32);
    match st.dash.pattern() {
        None => root.draw(&PathElement::new(pixels, stroke)),
        Some((on, off)) => root.draw(&DashedPathElement::new(pixels, px(on), px(off), stroke)),
    }
}

/// A series' marker centred at a pixel.
pub(super) fn marker(root: &Root<'_>, (x, y): (i32, i32), st: Style) -> DrawResult {
    let r = px(MARK);
    let fill = st.colour.filled();
    match st.marker {
        Marker::None => Ok(()),
        Marker::Circle => root.draw(&Circle::new((x, y), r * 4 / 5, fill)),
        Marker::Triangle => root.draw(&Polygon::new(
            vec![(x, y - r), (x - r, y + r * 4 / 5), (x + r, y + r * 4 / 5)],
            fill,
        )),
        Marker::Square => root.draw(&Rectangle::new(
            [
                (x - r * 7 / 10, y - r * 7 / 10),
                (x + r * 7 / 10, y + r * 7 / 10),
            ],
            fill,
        )),
    }
}

/// An arrow on the frame's top (`up`) or bottom edge at x: the curve
/// leaves the frame there.
fn arrow(root: &Root<'_>, frame: &Frame, x: f64, up: bool, colour: RGBColor) -> DrawResult {
    let (x, r) = (frame.at((x, frame.y.0)).0, px(5));
    let (tip, base) = if up {
        (frame.top + px(1), frame.top + px(1) + 2 * r)
    } else {
        (frame.bottom - px(1), frame.bottom - px(1) - 2 * r)
    };
    root.draw(&Polygon::new(
        vec![(x, tip), (x - r, base), (x + r, base)],
        colour.filled(),
    ))
}

/// The drawable runs of a curve: split at non-finite points, and clipped
/// to y0 ≤ y ≤ y1, a run ending (or starting) where the curve crosses the
/// frame's edge.
pub(super) fn clipped(points: &[(f64, f64)], (y0, y1): (f64, f64)) -> Vec<Vec<(f64, f64)>> {
    let mut out: Vec<Vec<(f64, f64)>> = Vec::new();
    let finite = |p: &(f64, f64)| p.0.is_finite() && p.1.is_finite();
    for w in points.windows(2) {
        let (a, b) = (w[0], w[1]);
        if !(finite(&a) && finite(&b)) {
            continue;
        }
        // the part of a + t(b − a), 0 ≤ t ≤ 1, with y0 ≤ y ≤ y1
        let (mut t0, mut t1) = (0.0f64, 1.0f64);
        let dy = b.1 - a.1;
        if dy == 0.0 {
            if a.1 < y0 || a.1 > y1 {
                continue;
            }
        } else {
            let (ta, tb) = ((y0 - a.1) / dy, (y1 - a.1) / dy);
            t0 = t0.max(ta.min(tb));
            t1 = t1.min(ta.max(tb));
        }
        if t0 > t1 {
            continue;
        }
        let at = |t: f64| (a.0 + t * (b.0 - a.0), (a.1 + t * dy).clamp(y0, y1));
        let (p, q) = (at(t0), at(t1));
        match out.last_mut() {
            Some(run) if t0 == 0.0 && run.last() == Some(&p) => run.push(q),
            _ => out.push(vec![p, q]),
        }
    }
    out
}

/// The legend's entries: the series (with any off-scale note), the
/// reference lines, each band label once.
fn legend_entries(fig: &Figure, y: (f64, f64)) -> Vec<Entry> {
    let mut out: Vec<Entry> = fig
        .series
        .iter()
        .enumerate()
        .map(|(k, s)| Entry {
            sample: Sample::Series(style(k)),
            label: match fig.off_scale_note(s, y) {
                Some(note) => format!("{} ({note})", s.label),
                None => s.label.clone(),
            },
        })
        .collect();
    out.extend(fig.reference_lines.iter().map(|(_, l)| Entry {
        sample: Sample::Reference,
        label: l.clone(),
    }));
    for b in &fig.bands {
        if !out
            .iter()
            .any(|e| e.sample == Sample::Band && e.label == b.label)
        {
            out.push(Entry {
                sample: Sample::Band,
                label: b.label.clone(),
            });
        }
    }
    out
}

/// The strip's rows: one for the regions' names, one for the vertical
/// lines' labels, each when there are any.
fn strip_rows(fig: &Figure) -> u32 {
    u32::from(!fig.regions.is_empty()) + u32::from(!fig.markers.is_empty())
}

/// The vertical lines' labels take the strip's lower row (next to the
/// frame) …
fn strip_row_of_markers(fig: &Figure) -> u32 {
    u32::from(!fig.markers.is_empty())
}

/// … and the regions' names the row above them. A vertical line's label
/// ends just left of it, or, with no room there (the frame's edge, the
/// label before it), starts just right of it; a region's name is centred
/// over the visible part of it.
fn strip_labels(root: &Root<'_>, frame: &Frame, fig: &Figure) -> DrawResult {
    let baseline = |row: u32| frame.top - px(3) - px(STRIP_ROW) * (row as i32);
    let text = font(STRIP_FONT).color(&GUIDE);
    let mut lines: Vec<(i32, &str)> = fig
        .markers
        .iter()
        .filter_map(|m| visible_x(frame, m.x).map(|x| (x, m.label.as_str())))
        .collect();
    lines.sort_by_key(|l| l.0);
    // the right end of the label before
    let mut taken = frame.left;
    for (x, label) in lines {
        let w = px(text_width(label, STRIP_FONT));
        let (at, h, end) = if x - px(4) - w >= taken {
            (x - px(4), HPos::Right, x - px(4))
        } else {
            (x + px(4), HPos::Left, x + px(4) + w)
        };
        taken = end + px(6);
        let pos = Pos::new(h, VPos::Bottom);
        root.draw(&Text::new(label, (at, baseline(0)), text.pos(pos)))?;
    }
    let row = strip_row_of_markers(fig);
    for r in &fig.regions {
        let (from, to) = (frame.clamp_x(r.from), frame.clamp_x(r.to));
        if to > from {
            let x = frame.at((0.5 * (from + to), frame.y.0)).0;
            let pos = Pos::new(HPos::Center, VPos::Bottom);
            root.draw(&Text::new(
                r.label.as_str(),
                (x, baseline(row)),
                text.pos(pos),
            ))?;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::super::legend::BORDER;
    use super::super::{Band, Series, VerticalLine};
    use super::*;

    /// An SVG element: its attributes, and its text if a `<text>`.
    struct Element {
        attrs: Vec<(String, String)>,
        text: String,
    }

    impl Element {
        fn get(&self, name: &str) -> &str {
            self.attrs
                .iter()
                .find(|(k, _)| k == name)
                .map_or("", |(_, v)| v.as_str())
        }
        fn num(&self, name: &str) -> f64 {
            self.get(name).parse().unwrap_or(f64::NAN)
        }
        fn points(&self) -> Vec<(f64, f64)> {
            self.get("points")
                .split_whitespace()
                .filter_map(|p| p.split_once(','))
                .map(|(x, y)| (x.parse().unwrap(), y.parse().unwrap()))
                .collect()
        }
    }

    /// Every `<tag …>` of an SVG document, read from the text alone.
    fn elements(svg: &str, tag: &str) -> Vec<Element> {
        let open = format!("<{tag} ");
        svg.match_indices(&open)
            .map(|(i, _)| {
                let rest = &svg[i + open.len()..];
                let end = rest.find('>').unwrap();
                let mut attrs = Vec::new();
                let mut head = &rest[..end];
                while let Some((key, after)) = head.split_once("=\"") {
                    let (value, tail) = after.split_once('"').unwrap();
                    attrs.push((key.trim().to_string(), value.to_string()));
                    head = tail;
                }
                let text = rest[end + 1..]
                    .split("</")
                    .next()
                    .unwrap_or_default()
                    .trim()
                    .to_string();
                Element { attrs, text }
            })
            .collect()
    }

    fn hex(c: RGBColor) -> String {
        format!("#{:02X}{:02X}{:02X}", c.0, c.1, c.2)
    }

    /// A rectangle (x0, y0, x1, y1) from a `<rect>`.
    type Rect = (f64, f64, f64, f64);

    fn rect(e: &Element) -> Rect {
        let (x, y) = (e.num("x"), e.num("y"));
        (x, y, x + e.num("width"), y + e.num("height"))
    }

    /// The one unfilled `<rect>` stroked in `colour`.
    fn outline(svg: &str, colour: RGBColor) -> Rect {
        let found: Vec<Rect> = elements(svg, "rect")
            .iter()
            .filter(|e| e.get("fill") == "none" && e.get("stroke") == hex(colour))
            .map(rect)
            .collect();
        assert_eq!(found.len(), 1, "{found:?}");
        found[0]
    }

    fn inside((x, y): (f64, f64), r: Rect) -> bool {
        x >= r.0 && x <= r.2 && y >= r.1 && y <= r.3
    }

    /// A figure that fills its frame: curves through the corners, one
    /// leaving a fixed y range, with a band, a region and a line.
    fn crowded() -> Figure {
        let mut fig = Figure::new("33", "Cycles", "Mach number M", "cycles");
        for k in 0..5 {
            let c = f64::from(k);
            let pts = (0..=150)
                .map(|i| {
                    let m = 0.5 + 0.01 * f64::from(i);
                    (m, (0.5 + c) * (1.0 + (6.0 * m + c).sin()))
                })
                .collect();
            fig = fig.with(Series::new(format!("series {k}"), pts));
        }
        fig.series[0].points[70].1 = 12.34;
        fig.y_range = Some((0.0, 6.0));
        fig.reference_lines.push((1.0, "one cycle".into()));
        fig.bands.push(Band {
            from: 0.9,
            to: 1.2,
            label: "faired between theories".into(),
        });
        fig.regions.push(Band {
            from: f64::NEG_INFINITY,
            to: 0.9,
            label: "subsonic theory".into(),
        });
        fig.markers.push(VerticalLine {
            x: 2f64.sqrt(),
            label: "45° edge sonic".into(),
        });
        fig
    }

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
        assert!(svg.starts_with("<svg") && svg.contains("width=\"800\" height=\"520\""));
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
    fn the_legend_lies_outside_the_frame_and_every_curve_inside_it() {
        let fig = crowded();
        let svg = fig.to_svg().unwrap();
        let frame = outline(&svg, FRAME);
        let legend = outline(&svg, BORDER);
        // the legend box below the frame, not meeting it
        assert!(legend.1 > frame.3, "{legend:?} {frame:?}");
        // each label in the legend box
        let texts = elements(&svg, "text");
        for s in &fig.series {
            let t = texts.iter().find(|t| t.text.starts_with(&s.label)).unwrap();
            assert!(inside((t.num("x"), t.num("y")), legend), "{}", s.label);
        }
        // every drawn piece of a curve: in the frame, or a sample in the box
        let colours: Vec<String> = PALETTE.iter().map(|&c| hex(c)).collect();
        let curves: Vec<Vec<(f64, f64)>> = elements(&svg, "polyline")
            .iter()
            .filter(|e| colours.contains(&e.get("stroke").to_string()))
            .map(Element::points)
            .collect();
        let (mut plotted, mut samples) = (0, 0);
        for pts in &curves {
            if pts.iter().all(|&p| inside(p, frame)) {
                plotted += pts.len();
            } else {
                assert!(pts.iter().all(|&p| inside(p, legend)), "{pts:?}");
                samples += 1;
            }
        }
        assert!(
            plotted > 500 && samples >= fig.series.len(),
            "{plotted} {samples}"
        );
    }

    #[test]
    fn a_band_spans_its_mach_range_and_the_frame_height() {
        let svg = crowded().to_svg().unwrap();
        let frame = outline(&svg, FRAME);
        let (x0, x1) = (0.5, 2.0);
        let to_px = |x: f64| frame.0 + (x - x0) / (x1 - x0) * (frame.2 - frame.0);
        let bands: Vec<Rect> = elements(&svg, "rect")
            .iter()
            .filter(|e| e.get("fill") == hex(BAND.0) && e.num("opacity") == BAND.1)
            .map(rect)
            .collect();
        // the band, and the legend's sample of it
        assert_eq!(bands.len(), 2, "{bands:?}");
        let b = bands[0];
        assert!((b.0 - to_px(0.9)).abs() <= 1.0, "{b:?} {}", to_px(0.9));
        assert!((b.2 - to_px(1.2)).abs() <= 1.0, "{b:?} {}", to_px(1.2));
        assert_eq!((b.1, b.3), (frame.1, frame.3));
        // labelled once, in the legend
        let texts = elements(&svg, "text");
        let named = |s: &str| texts.iter().filter(|t| t.text == s).count();
        assert_eq!(named("faired between theories"), 1);
        assert_eq!(named("subsonic theory"), 1);
        // the sonic edge: a dashed vertical line at √2, labelled
        let line: Vec<(f64, f64)> = elements(&svg, "polyline")
            .iter()
            .filter(|e| e.get("stroke") == hex(GUIDE))
            .flat_map(|e| e.points())
            .filter(|p| p.1 > frame.1 && p.1 < frame.3)
            .collect();
        let xs: Vec<f64> = line
            .iter()
            .map(|p| p.0)
            .filter(|&x| x != frame.0 && x != frame.2)
            .collect();
        assert!(xs.len() > 20, "dashes: {xs:?}");
        assert!(
            xs.iter().all(|&x| (x - to_px(2f64.sqrt())).abs() <= 1.0),
            "{xs:?}"
        );
        assert_eq!(named("45° edge sonic"), 1);
    }

    #[test]
    fn the_csv_holds_the_curves_alone() {
        let fig = crowded();
        let csv = fig.to_csv();
        let header = csv.lines().next().unwrap();
        assert_eq!(header.split(',').count(), 1 + fig.series.len(), "{header}");
        assert_eq!(csv.lines().count(), 1 + fig.series[0].points.len());
        for word in ["faired", "sonic", "subsonic", "one cycle", "off scale"] {
            assert!(!csv.contains(word), "{word}");
        }
    }

    #[test]
    fn a_curve_off_scale_is_clipped_at_the_frame_with_an_arrow_and_a_note() {
        let fig = crowded();
        let svg = fig.to_svg().unwrap();
        let frame = outline(&svg, FRAME);
        let texts = elements(&svg, "text");
        assert!(
            texts
                .iter()
                .any(|t| t.text == "series 0 (↑ off scale: max 12.3 at M = 1.2)"),
            "{:?}",
            texts.iter().map(|t| &t.text).collect::<Vec<_>>()
        );
        // the arrow: series 0's colour, its tip on the frame's top edge
        let colour = hex(style(0).colour);
        let tips: Vec<(f64, f64)> = elements(&svg, "polygon")
            .iter()
            .filter(|e| e.get("fill") == colour)
            .filter_map(|e| e.points().into_iter().min_by(|a, b| a.1.total_cmp(&b.1)))
            .filter(|p| (p.1 - frame.1).abs() <= f64::from(px(1)))
            .collect();
        assert_eq!(tips.len(), 1, "{tips:?}");
    }

    #[test]
    fn no_two_series_of_twelve_look_alike_without_colour_and_the_legend_shows_each() {
        for i in 0..12 {
            for j in 0..i {
                let (a, b) = (style(i), style(j));
                assert!((a.dash, a.marker) != (b.dash, b.marker), "{i} {j}");
            }
        }
        let svg = crowded().to_svg().unwrap();
        let legend = outline(&svg, BORDER);
        for k in 0..5 {
            let st = style(k);
            let colour = hex(st.colour);
            let in_box = |tag: &str, paint: &str| {
                elements(&svg, tag).iter().any(|e| {
                    e.get(paint) == colour
                        && match tag {
                            "circle" => inside((e.num("cx"), e.num("cy")), legend),
                            "rect" => inside((e.num("x"), e.num("y")), legend),
                            _ => e.points().iter().all(|&p| inside(p, legend)),
                        }
                })
            };
            let pieces = elements(&svg, "polyline")
                .iter()
                .filter(|e| e.get("stroke") == colour)
                .filter(|e| e.points().iter().all(|&p| inside(p, legend)))
                .count();
            let dashed = st.dash != Dash::Solid;
            assert_eq!(pieces > 1, dashed, "series {k}: {pieces} pieces");
            let marker = match st.marker {
                Marker::None => None,
                Marker::Circle => Some(("circle", "fill")),
                Marker::Triangle => Some(("polygon", "fill")),
                Marker::Square => Some(("rect", "fill")),
            };
            if let Some((tag, paint)) = marker {
                assert!(in_box(tag, paint), "series {k}'s {tag}");
            }
        }
    }

    #[test]
    fn clipping_ends_a_run_where_the_curve_crosses_the_edge() {
        let pts = [
            (0.0, 1.0),
            (1.0, 3.0),
            (2.0, 1.0),
            (3.0, f64::NAN),
            (4.0, 1.0),
            (5.0, 1.5),
        ];
        assert_eq!(
            clipped(&pts, (0.0, 2.0)),
            vec![
                vec![(0.0, 1.0), (0.5, 2.0)],
                vec![(1.5, 2.0), (2.0, 1.0)],
                vec![(4.0, 1.0), (5.0, 1.5)],
            ]
        );
    }

    #[test]
    fn the_automatic_range_holds_every_finite_point() {
        let fig = crowded();
        let fig = Figure {
            y_range: None,
            ..fig
        };
        let (_, (y0, y1)) = fig.ranges();
        for (_, y) in fig.finite_points() {
            assert!(y > y0 && y < y1, "{y} outside {y0}..{y1}");
        }
        assert!(y1 > 12.34);
    }
}
