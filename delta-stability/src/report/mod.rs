//! The note's whole study on its built-in cases (`delta-stability report`):
//! the figures it draws, grouped as the note groups them — §6 wave drag,
//! coefficients and stiffness ([`coefficients`], Figs 1–12), §7 damping
//! ([`damping`], 13–24; the lifting-surface Figs 4 and 14–15 from
//! [`lifting_surface`]), §8 the standard ([`standard`], 25–26), §9 the
//! quartic and margins ([`quartic`], 27–35), §10 taper ([`taper`], 36),
//! §11 responses ([`responses`], 37–38), with the regime bands and sonic
//! edges of [`regimes`] on those against Mach number — then the
//! [`summary`] of what was found, the note's [`conclusions`] set beside
//! it, how sure the two headline conclusions are as probabilities
//! ([`certainty`]), and the page ([`html`]); and what README.md shows of
//! it ([`readme`]).
//!
//! Everything here computes; writing the files is `cmd::report`'s.

pub mod certainty;
pub mod coefficients;
pub mod conclusions;
pub mod damping;
pub mod design;
pub mod html;
pub mod lifting_surface;
pub mod manifest;
pub mod quartic;
pub mod readme;
pub mod regimes;
pub mod responses;
pub mod standard;
pub mod study;
pub mod summary;
pub mod tail;
pub mod taper;

use crate::plot::Figure;
pub use study::Study;

/// One figure of the note, with its caption for the page.
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

/// A section of the note: its figures, computed from the study.
pub struct Section {
    /// What the progress bar shows while it is computed.
    pub title: &'static str,
    pub plates: fn(&Study) -> Vec<Plate>,
}

/// The note's sections with figures, in its order.
///
/// Fig 1, needing no study and quick, is a section of its own ahead of the
/// rest of §6 (whose Fig 4 solves many lattices): the report's first
/// files are written early.
pub const SECTIONS: [Section; 7] = [
    Section {
        title: "§6: wave drag at zero lift (Fig 1)",
        plates: coefficients::wave_drag_plates,
    },
    Section {
        title: "§6: aerodynamic coefficients and stiffness derivatives (Figs 2–12; Fig 4 by the lifting surface)",
        plates: coefficients::plates,
    },
    Section {
        title: "§7: damping theories and derivatives (Figs 13–24; Figs 14–15 by the lifting surface)",
        plates: damping::plates,
    },
    Section {
        title: "§8: the damping standard (Figs 25–26)",
        plates: standard::plates,
    },
    Section {
        title: "§9: the quartic, its modes and the margins (Figs 27–35)",
        plates: quartic::plates,
    },
    Section {
        title: "§10: taper (Fig 36)",
        plates: taper::plates,
    },
    Section {
        title: "§11: responses (Figs 37–38)",
        plates: responses::plates,
    },
];
