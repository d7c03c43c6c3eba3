//! `delta-stability convert --from X --to Y FILE [--json]`: a derivative set
//! from one notation into another, by the factors derived in
//! `stability-core/specs/notation.toml` (see docs/notations.md), through
//! [`stability_io::convert`].

use crate::Failure;
use crate::args::{NotationArg, TargetNotation};
use crate::output::print_as;
use stability_io::convert::{Target, convert, written_in};
use stability_io::diag::InputError;
use stability_io::format::Format;
use stability_io::input;

/// The command's options.
#[derive(Debug, Clone, clap::Args)]
pub struct Args {
    /// The file's notation.
    #[arg(long, value_enum)]
    pub from: NotationArg,
    /// The notation to write.
    #[arg(long, value_enum)]
    pub to: TargetNotation,
    /// The derivative file (TOML).
    pub file: String,
    /// Print one JSON object instead of TOML.
    #[arg(long)]
    pub json: bool,
}

pub fn run(args: &Args) -> Result<(), Failure> {
    let (from, to, file) = (args.from, args.to, args.file.as_str());
    let any = input::read_any(file)?;
    let (written, form) = written_in(&any);
    if written != from.name() && form != from.name() {
        return Err(InputError::file(
            file,
            format!(
                "--from {}: the file is in notation `{written}` (its `notation` key)",
                from.name()
            ),
        )
        .into());
    }
    let target = match to {
        TargetNotation::Table(n) => Target::Table(n),
        TargetNotation::Dimensional => Target::Dimensional,
    };
    let conversion = convert(&any, from.name(), target)?;
    crate::output::warn_all(conversion.warnings());
    print_as(Format::printed(args.json), file, &conversion.json(), || {
        Ok(conversion.toml()?)
    })
}
