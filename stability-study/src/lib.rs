//! The note's whole study on its built-in cases (`delta-stability report`,
//! Python's `report()`): the figures it draws, grouped as the note groups
//! them — §6 wave drag, coefficients and stiffness ([`coefficients`], Figs
//! 1–12), §7 damping ([`damping`], 13–24; the lifting-surface Figs 4 and
//! 14–15 from [`lifting_surface`]), §8 the standard ([`standard`], 25–26),
//! §9 the quartic and margins ([`quartic`], 27–35), §10 taper ([`taper`],
//! 36), §11 responses ([`responses`], 37–38), with the regime bands and
//! sonic edges of [`regimes`] on those against Mach number — then the
//! [`summary`] of what was found (`summary.json`), the note's
//! [`conclusions`] set beside it, how sure the two headline conclusions are
//! as probabilities ([`certainty`]), the tail the 45° delta needs
//! ([`tail`]); the whole computed in the report's order by [`report`]; and
//! what README.md shows of it ([`readme`]).
//!
//! Everything here computes: each figure is data
//! ([`stability_io::plot::Figure`], drawn to SVG there); writing the files,
//! the page and the terminal's summary are the front ends'.

pub mod certainty;
pub mod coefficients;
pub mod conclusions;
pub mod damping;
pub mod lifting_surface;
pub mod methods;
pub mod quartic;
pub mod readme;
pub mod regimes;
pub mod report;
pub mod responses;
pub mod standard;
pub mod study;
pub mod summary;
pub mod tail;
pub mod taper;

pub use report::Report;
pub use stability_io::plot::Plate;
pub use study::Study;

/// How a section's figures are drawn.
#[derive(Debug, Clone, Copy)]
pub enum Figures {
    /// Without the study: drawn before it is computed ([`Report::compute`]).
    Alone(fn() -> Vec<Plate>),
    /// From the study.
    FromStudy(fn(&Study) -> Vec<Plate>),
}

/// A section of the note: its figures.
pub struct Section {
    /// What the progress bar shows while it is computed.
    pub title: &'static str,
    pub plates: Figures,
}

/// The note's sections with figures, in its order.
///
/// Fig 1, needing no study and quick, is a section of its own ahead of the
/// rest of §6 (whose Fig 4 solves many lattices), drawn before the study
/// is computed: the report's first files are written at once.
pub const SECTIONS: [Section; 7] = [
    Section {
        title: "§6: wave drag at zero lift (Fig 1)",
        plates: Figures::Alone(coefficients::wave_drag_plates),
    },
    Section {
        title: "§6: aerodynamic coefficients and stiffness derivatives (Figs 2–12; Fig 4 by the lifting surface)",
        plates: Figures::FromStudy(coefficients::plates),
    },
    Section {
        title: "§7: damping theories and derivatives (Figs 13–24; Figs 14–15 by the lifting surface)",
        plates: Figures::FromStudy(damping::plates),
    },
    Section {
        title: "§8: the damping standard (Figs 25–26)",
        plates: Figures::FromStudy(standard::plates),
    },
    Section {
        title: "§9: the quartic, its modes and the margins (Figs 27–35)",
        plates: Figures::FromStudy(quartic::plates),
    },
    Section {
        title: "§10: taper (Fig 36)",
        plates: Figures::FromStudy(taper::plates),
    },
    Section {
        title: "§11: responses (Figs 37–38)",
        plates: Figures::FromStudy(responses::plates),
    },
];
