//! The whole study in the report's order ([`Report::compute`]): the two
//! wings across Mach number ([`Study`]), each section's figures
//! ([`SECTIONS`]), §10 (ours), the tail the 45° delta needs
//! ([`crate::tail`], sized beside the study), the findings and the largest
//! μ₁ ([`crate::summary`]), the note's conclusions swept over the unstated
//! inputs ([`crate::conclusions`]) and how sure the headlines are
//! ([`crate::certainty`]); then `summary.json` ([`Report::summary_json`]).
//! Figures that need no study (Fig 1) are drawn before it.
//! The caller is told of each step as it begins and ends, and handed each
//! section's figures when drawn, so that a front end shows its progress
//! and writes the first files early.

use crate::certainty::Certainty;
use crate::conclusions::{self, Judged};
use crate::summary::{self, Findings};
use crate::tail::TailNeeded;
use crate::{Figures, Plate, SECTIONS, Study};
use stability_core::aerodynamics::lifting_surface::precomputed::PrecomputedError;
use stability_io::diag::InputError;

/// The title of §10 (ours), in the progress and on the page.
pub const TAIL_TITLE: &str = "§10 (ours): the tail the 45° delta needs";

/// How many steps [`Report::compute`] reports ([`Step::Begins`] … [`Step::Done`]):
/// the study, each section, §10 (ours), the findings, the conclusions and
/// how sure.
pub const STEPS: usize = SECTIONS.len() + 5;

/// What [`Report::compute`] tells its caller as it goes.
#[derive(Debug, Clone, Copy)]
pub enum Step<'a> {
    /// A step begins: what it computes, in words.
    Begins(&'a str),
    /// Figures were drawn: the caller may write them now.
    Drew(&'a [Plate]),
    /// The step that began last is done.
    Done,
}

/// Why [`Report::compute`] stopped.
#[derive(Debug)]
pub enum Stopped<E> {
    /// The caller's function said stop (a file it could not write).
    Caller(E),
    /// A part of the study could not be computed: what, and why.
    Study { what: &'static str, why: String },
}

impl<E> From<E> for Stopped<E> {
    fn from(e: E) -> Self {
        Stopped::Caller(e)
    }
}

/// The study, computed (and told to `on`) when first asked for.
fn computed<'s, E>(
    study: &'s mut Option<Study>,
    on: &mut impl FnMut(Step<'_>) -> Result<(), E>,
) -> Result<&'s Study, E> {
    if study.is_none() {
        on(Step::Begins("the 45° and 60° deltas across Mach number"))?;
        *study = Some(Study::compute());
        on(Step::Done)?;
    }
    Ok(study.get_or_insert_with(Study::compute))
}

/// The note's study, computed whole.
pub struct Report {
    /// The note's sections and §10 (ours), in order: each its title and
    /// figures.
    pub sections: Vec<(&'static str, Vec<Plate>)>,
    /// What the study found (it holds the [`Study`]).
    pub findings: Findings,
    /// The note's conclusions, judged and swept.
    pub judged: Vec<Judged>,
    /// How sure the headline conclusions are.
    pub sure: Certainty,
    /// Its figure (`how-sure`), shown with its own section.
    pub sure_plate: Plate,
    /// §10 (ours): the tail and foreplane the 45° delta needs.
    pub tail: TailNeeded,
    /// How many precomputed lifting-surface solutions were preloaded
    /// ([`crate::study::preload`]), or why none were (a stale file);
    /// `None`: solved afresh ([`Report::compute_afresh`]).
    pub precomputed: Option<Result<usize, PrecomputedError>>,
}

impl Report {
    /// The study, every step told to `on` ([`Step`]); `on`'s error stops it.
    ///
    /// §10 (ours) sizes surfaces over Mach with the study's assumptions
    /// ([`TailNeeded::ours`], as [`Study::new`] takes them): begun beside
    /// the study, whose sweeps leave a core idle between their parallel
    /// parts.
    /// The lifting-surface solutions the study needs come from
    /// [`crate::study::PRECOMPUTED`] where it holds them.
    pub fn compute<E>(on: impl FnMut(Step<'_>) -> Result<(), E>) -> Result<Report, Stopped<E>> {
        let precomputed = Some(crate::study::preload());
        Report::compute_with(precomputed, on)
    }

    /// As [`Report::compute`], every lifting-surface solution solved (none
    /// preloaded): what `cargo xtask tables` writes.
    pub fn compute_afresh<E>(
        on: impl FnMut(Step<'_>) -> Result<(), E>,
    ) -> Result<Report, Stopped<E>> {
        Report::compute_with(None, on)
    }

    fn compute_with<E>(
        precomputed: Option<Result<usize, PrecomputedError>>,
        mut on: impl FnMut(Step<'_>) -> Result<(), E>,
    ) -> Result<Report, Stopped<E>> {
        std::thread::scope(|scope| {
            let sizing = scope.spawn(TailNeeded::ours);
            let mut study = None;
            let mut sections = Vec::new();
            for section in &SECTIONS {
                let plates = match section.plates {
                    Figures::Alone(draw) => {
                        on(Step::Begins(section.title))?;
                        draw()
                    }
                    Figures::FromStudy(draw) => {
                        let study = computed(&mut study, &mut on)?;
                        on(Step::Begins(section.title))?;
                        draw(study)
                    }
                };
                on(Step::Drew(&plates))?;
                sections.push((section.title, plates));
                on(Step::Done)?;
            }
            computed(&mut study, &mut on)?;
            let study = study.unwrap_or_default();
            on(Step::Begins(TAIL_TITLE))?;
            let tail = sizing
                .join()
                .unwrap_or_else(|_| Err("the sizing's thread panicked".into()))
                .map_err(|why| Stopped::Study {
                    what: "cannot size the tail",
                    why,
                })?;
            let tail_plate = tail.plate();
            on(Step::Drew(std::slice::from_ref(&tail_plate)))?;
            sections.push((TAIL_TITLE, vec![tail_plate]));
            on(Step::Done)?;
            let mut report = Self::judge(study, sections, tail, on)?;
            report.precomputed = precomputed;
            Ok(report)
        })
    }

    /// The steps after the figures: the findings, the conclusions and how
    /// sure.
    fn judge<E>(
        study: Study,
        sections: Vec<(&'static str, Vec<Plate>)>,
        tail: TailNeeded,
        mut on: impl FnMut(Step<'_>) -> Result<(), E>,
    ) -> Result<Report, Stopped<E>> {
        on(Step::Begins(
            "summary: intervals and the largest μ₁ (bisection)",
        ))?;
        let findings = Findings::new(study);
        findings.max_mu1(0);
        findings.max_mu1(1);
        on(Step::Done)?;
        on(Step::Begins("conclusions, swept over i_B and C_L·M²"))?;
        let judged = conclusions::judge_all(&findings);
        on(Step::Done)?;
        on(Step::Begins(
            "how sure: the headline conclusions as probabilities",
        ))?;
        let sure = Certainty::new().map_err(|why| Stopped::Study {
            what: "cannot weigh the headline conclusions",
            why,
        })?;
        let sure_plate = sure.plate();
        on(Step::Drew(std::slice::from_ref(&sure_plate)))?;
        on(Step::Done)?;
        Ok(Report {
            sections,
            findings,
            judged,
            sure,
            sure_plate,
            tail,
            precomputed: None,
        })
    }

    /// The study with nothing told ([`Report::compute`]).
    pub fn quietly() -> Result<Report, Stopped<std::convert::Infallible>> {
        Report::compute(|_| Ok(()))
    }

    /// Every figure: the sections' and how sure's.
    pub fn plates(&self) -> impl Iterator<Item = &Plate> {
        self.sections
            .iter()
            .flat_map(|(_, p)| p)
            .chain(std::iter::once(&self.sure_plate))
    }

    /// `summary.json`'s text ([`summary::summary_file`]).
    pub fn summary_json(&self) -> Result<String, InputError> {
        summary::summary_file(&self.findings, &self.judged, &self.sure, &self.tail)
    }
}
