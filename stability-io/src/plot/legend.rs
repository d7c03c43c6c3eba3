//! The legend: in a box below the frame, so it never covers a curve, its
//! entries in as many columns as fit the frame's width (column by column),
//! each with its series' line and marker as drawn.

use super::svg::{BAND, GUIDE, SCALE, Style, font, line, marker, px};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

const FONT: u32 = 12;
/// A row's height.
const ROW: u32 = 18;
/// Inside the box, around the entries.
const PAD: u32 = 6;
/// Between the x axis' label and the box.
const GAP: u32 = 4;
/// Below the box.
const BELOW: u32 = 8;
/// An entry's sample line, and the space between it and the text.
const SAMPLE: u32 = 30;
const SAMPLE_GAP: u32 = 6;
/// Between columns.
const COLUMN_GAP: u32 = 18;
/// The box's border.
pub(super) const BORDER: RGBColor = RGBColor(150, 150, 150);

/// What an entry shows beside its label.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Sample {
    /// A series' line and marker.
    Series(Style),
    /// A reference line.
    Reference,
    /// A band's shade.
    Band,
}

#[derive(Debug, Clone, PartialEq)]
pub(super) struct Entry {
    pub sample: Sample,
    pub label: String,
}

/// An estimate of a text's width (px) at a font size: 0.6 em a character
/// (sans-serif averages about 0.5–0.55; better too wide than overlapping),
/// combining marks (the dot of θ̇) taking none.
pub(super) fn text_width(s: &str, size: u32) -> u32 {
    let chars = s
        .chars()
        .filter(|c| !('\u{300}'..='\u{36f}').contains(c))
        .count() as f64;
    (chars * 0.6 * f64::from(size)).ceil() as u32
}

/// The entries and their layout.
pub(super) struct Legend {
    entries: Vec<Entry>,
    rows: usize,
    /// Each column's width (px), sample and text.
    columns: Vec<u32>,
}

impl Legend {
    /// The legend of `entries` in as many columns as fit `width`.
    pub fn new(entries: Vec<Entry>, width: u32) -> Legend {
        let widths: Vec<u32> = entries
            .iter()
            .map(|e| SAMPLE + SAMPLE_GAP + text_width(&e.label, FONT))
            .collect();
        let n = widths.len();
        let layout = |rows: usize| -> Vec<u32> {
            widths
                .chunks(rows)
                .map(|c| c.iter().copied().max().unwrap_or(0))
                .collect()
        };
        let fits = |cols: &[u32]| span(cols) + 2 * PAD <= width;
        let rows = (1..=n.max(1))
            .find(|&r| fits(&layout(r)))
            .unwrap_or(n.max(1));
        let columns = layout(rows);
        Legend {
            entries,
            rows,
            columns,
        }
    }

    /// The height the legend takes below the chart (px); 0 when empty.
    pub fn height(&self) -> u32 {
        if self.entries.is_empty() {
            0
        } else {
            GAP + self.box_size().1 + BELOW
        }
    }

    /// The box's size (px).
    fn box_size(&self) -> (u32, u32) {
        (
            span(&self.columns) + 2 * PAD,
            self.rows as u32 * ROW + 2 * PAD,
        )
    }

    /// Draw the legend centred in the `width` from `(left, top)` (drawing
    /// pixels), `top` the top of the space [`Legend::height`] reserved.
    pub fn draw(
        &self,
        root: &DrawingArea<SVGBackend<'_>, Shift>,
        (left, top): (i32, i32),
        width: u32,
    ) -> Result<(), DrawingAreaErrorKind<std::io::Error>> {
        if self.entries.is_empty() {
            return Ok(());
        }
        let (w, h) = self.box_size();
        let x0 = left + px((width - w.min(width)) / 2);
        let y0 = top + px(GAP);
        root.draw(&Rectangle::new(
            [(x0, y0), (x0 + px(w), y0 + px(h))],
            BORDER,
        ))?;
        let mut x = x0 + px(PAD);
        for (col, chunk) in self.entries.chunks(self.rows).enumerate() {
            for (row, e) in chunk.iter().enumerate() {
                let y = y0 + px(PAD) + px(ROW) * row as i32 + px(ROW) / 2;
                entry(root, e, (x, y))?;
            }
            x += px(self.columns[col] + COLUMN_GAP);
        }
        Ok(())
    }
}

/// The width of columns side by side, with the gaps between them.
fn span(columns: &[u32]) -> u32 {
    columns.iter().sum::<u32>() + COLUMN_GAP * columns.len().saturating_sub(1) as u32
}

/// One entry, its sample from `x`, centred on the row's middle `y`.
fn entry(
    root: &DrawingArea<SVGBackend<'_>, Shift>,
    e: &Entry,
    (x, y): (i32, i32),
) -> Result<(), DrawingAreaErrorKind<std::io::Error>> {
    let end = x + px(SAMPLE);
    match e.sample {
        Sample::Series(st) => {
            line(root, vec![(x, y), (end, y)], st)?;
            marker(root, ((x + end) / 2, y), st)?;
        }
        Sample::Reference => {
            root.draw(&PathElement::new(
                vec![(x, y), (end, y)],
                GUIDE.stroke_width(SCALE),
            ))?;
        }
        Sample::Band => {
            let (fill, alpha) = BAND;
            root.draw(&Rectangle::new(
                [(x, y - px(6)), (end, y + px(6))],
                fill.mix(alpha).filled(),
            ))?;
        }
    }
    let text = font(FONT).pos(Pos::new(HPos::Left, VPos::Center));
    root.draw(&Text::new(
        e.label.as_str(),
        (end + px(SAMPLE_GAP), y),
        text,
    ))
}
