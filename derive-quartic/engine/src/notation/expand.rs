//! The Rust that `notations!` emits for a verified notation spec: the tables
//! of names, a module per notation with one plain function per conversion
//! (the report's quantity of a row from the notation's, and back) and the
//! two functions over a whole row of values, and the two functions that pick
//! a notation by index.
//!
//! Values travel as arrays indexed by row, `None` where a quantity is
//! absent; a conversion is `None` when a value it needs is. The code is
//! allocation-free, uses only `core`, and is what `cargo xtask regen` writes
//! to `docs/generated/` for review.

use super::model::{Entry, Notation, NotationModel, SymbolKind};
use crate::codegen::{self, Node, Program, ident};
use crate::expr::{Symbol, SymbolTable};
use crate::poly::Poly;
use crate::render::poly_text;
use proc_macro2::{Literal, TokenStream};
use quote::quote;
use std::collections::BTreeSet;

/// A conversion's direction.
#[derive(Clone, Copy)]
enum Direction {
    /// The report's quantities from the notation's.
    ToReport,
    /// The notation's quantities from the report's.
    FromReport,
}

impl Direction {
    fn name(self) -> &'static str {
        match self {
            Direction::ToReport => "to_report",
            Direction::FromReport => "from_report",
        }
    }

    fn poly(self, e: &Entry) -> Option<&Poly> {
        match self {
            Direction::ToReport => e.to_report.as_ref(),
            Direction::FromReport => e.from_report.as_ref(),
        }
    }
}

/// The array types of the generated signatures.
struct Types {
    values: TokenStream,
    parameters: TokenStream,
    n_rows: Literal,
}

impl Types {
    fn of(model: &NotationModel) -> Types {
        let n_rows = Literal::usize_unsuffixed(model.rows.len());
        let n_par = Literal::usize_unsuffixed(model.parameters.len());
        Types {
            values: quote!(&[Option<f64>; #n_rows]),
            parameters: quote!(&[f64; #n_par]),
            n_rows,
        }
    }
}

/// Everything `notations!` emits.
pub fn notation_items(model: &NotationModel) -> TokenStream {
    let tables = tables(model);
    let types = Types::of(model);
    let to = dispatch(model, &types, Direction::ToReport);
    let from = dispatch(model, &types, Direction::FromReport);
    let modules = (model.notations.iter()).map(|n| notation_module(model, n, &types));
    quote! {
        #tables
        #to
        #from
        #(#modules)*
    }
}

/// The tables of names: rows, notations, each notation's names, parameters.
fn tables(model: &NotationModel) -> TokenStream {
    let rows = strings(model.rows.iter().map(|r| &r.name));
    let row_docs = strings(model.rows.iter().map(|r| &r.doc));
    let names = strings(model.notations.iter().map(|n| &n.name));
    let titles = strings(model.notations.iter().map(|n| &n.title));
    let params = strings(model.parameters.iter().map(|p| &p.name));
    let name_rows = model.notations.iter().map(|n| {
        let cells = n.entries.iter().map(|e| match e {
            Some(e) => {
                let l = Literal::string(&e.name);
                quote!(Some(#l))
            }
            None => quote!(None),
        });
        quote!([#(#cells),*])
    });
    let n_rows = Literal::usize_unsuffixed(model.rows.len());
    let n_not = Literal::usize_unsuffixed(model.notations.len());
    let n_par = Literal::usize_unsuffixed(model.parameters.len());
    let rows_doc = format!(
        " The rows of `{}`: the quantities the notations define.",
        model.file
    );
    quote! {
        #[doc = #rows_doc]
        pub const ROWS: [&str; #n_rows] = [#(#rows),*];
        /// What each row is.
        pub const ROW_DOCS: [&str; #n_rows] = [#(#row_docs),*];
        /// The notations, the report's first among them marked `reference`.
        pub const NOTATIONS: [&str; #n_not] = [#(#names),*];
        /// Their titles.
        pub const TITLES: [&str; #n_not] = [#(#titles),*];
        /// `NAMES[notation][row]`: each notation's name for each row's quantity.
        pub const NAMES: [[Option<&str>; #n_rows]; #n_not] = [#(#name_rows),*];
        /// The dimensionless parameters a conversion may need.
        pub const PARAMETERS: [&str; #n_par] = [#(#params),*];
    }
}

fn strings<'a>(it: impl Iterator<Item = &'a String>) -> Vec<Literal> {
    it.map(|s| Literal::string(s)).collect()
}

/// `to_report(notation, …)` or `from_report(notation, …)`: the notation's
/// module's function of the same name, by the notation's index in
/// `NOTATIONS`.
fn dispatch(model: &NotationModel, types: &Types, dir: Direction) -> TokenStream {
    let name = ident(dir.name());
    let arms = model.notations.iter().enumerate().map(|(k, n)| {
        let k = Literal::usize_unsuffixed(k);
        let module = ident(&n.name);
        quote!(#k => #module::#name(values, parameters),)
    });
    let doc = match dir {
        Direction::ToReport => quote! {
            /// The report's quantities (by row) from notation `notation`'s
            /// `values` (by row); derived from the notations' definitions.
        },
        Direction::FromReport => quote! {
            /// Notation `notation`'s quantities (by row) from the report's
            /// `values` (by row): the inverse of [`to_report`].
        },
    };
    let Types {
        values,
        parameters,
        n_rows,
    } = types;
    quote! {
        #doc
        ///
        /// `notation` indexes [`NOTATIONS`]; past its end there is no value.
        #[must_use]
        pub fn #name(notation: usize, values: #values, parameters: #parameters) -> [Option<f64>; #n_rows] {
            match notation {
                #(#arms)*
                _ => [None; #n_rows],
            }
        }
    }
}

/// A notation's module: the two functions over a row of values and one
/// function per conversion.
fn notation_module(model: &NotationModel, n: &Notation, types: &Types) -> TokenStream {
    let code = code_table(n);
    let mut items = TokenStream::new();
    let mut cells = TokenStream::new();
    for dir in [Direction::ToReport, Direction::FromReport] {
        let conversions: Vec<Option<Conversion>> = (model.rows.iter().zip(&n.entries))
            .enumerate()
            .map(|(ri, (_, e))| {
                let e = e.as_ref()?;
                Some(Conversion::new(model, n, &code, ri, e, dir.poly(e)?, dir))
            })
            .collect();
        items.extend(row_function(&conversions, types, dir));
        for c in conversions.iter().flatten() {
            cells.extend(c.item(types));
        }
    }
    let module = ident(&n.name);
    let doc = format!(" `{}`: {}. {}", n.name, n.title, n.source);
    quote! {
        #[doc = #doc]
        pub mod #module {
            #items
            #cells
        }
    }
}

/// `to_report(values, parameters)` or `from_report(…)` of one notation: a
/// row of values converted, cell by cell.
fn row_function(conversions: &[Option<Conversion>], types: &Types, dir: Direction) -> TokenStream {
    let cells = conversions.iter().map(|c| match c {
        Some(c) => c.call(),
        None => quote!(None),
    });
    let reads = |f: fn(&Conversion) -> bool| conversions.iter().flatten().any(f);
    let values = if reads(|c| c.reads_values) {
        quote!(values)
    } else {
        quote!(_values)
    };
    let parameters = if reads(|c| c.reads_parameters) {
        quote!(parameters)
    } else {
        quote!(_parameters)
    };
    let doc = match dir {
        Direction::ToReport => {
            " The report's quantities (by row) from this notation's `values` (by row)."
        }
        Direction::FromReport => {
            " This notation's quantities (by row) from the report's `values` (by row)."
        }
    };
    let name = ident(dir.name());
    let Types {
        values: v,
        parameters: p,
        n_rows,
    } = types;
    quote! {
        #[doc = #doc]
        #[must_use]
        pub fn #name(#values: #v, #parameters: #p) -> [Option<f64>; #n_rows] {
            [#(#cells),*]
        }
    }
}

/// The names of a notation's symbols in the generated code: lower case
/// (`C_La` is `c_la`), each distinct; the dimensional quantities, which
/// never occur in the code, yield their names to the others.
fn code_table(n: &Notation) -> SymbolTable {
    let mut taken = BTreeSet::new();
    let symbols = (n.table.symbols.iter().zip(&n.kinds))
        .map(|(s, kind)| {
            let wanted = match kind {
                SymbolKind::Dimensional => format!("dimensional_{}", s.name.to_lowercase()),
                _ => s.name.to_lowercase(),
            };
            let mut name = wanted.clone();
            let mut k = 2;
            while !taken.insert(name.clone()) {
                name = format!("{wanted}_{k}");
                k += 1;
            }
            Symbol { name, ..s.clone() }
        })
        .collect();
    SymbolTable { symbols }
}

/// One conversion: the function computing one row's quantity (or, for a
/// value passed through unchanged, the row it is read from).
struct Conversion {
    name: proc_macro2::Ident,
    /// The row of a value passed through unchanged: no function.
    passed_through: Option<Literal>,
    doc: Vec<String>,
    /// The statements reading the inputs, then the program's `let`s.
    body: TokenStream,
    /// The value returned.
    value: TokenStream,
    reads_values: bool,
    reads_parameters: bool,
}

impl Conversion {
    fn new(
        model: &NotationModel,
        n: &Notation,
        code: &SymbolTable,
        ri: usize,
        e: &Entry,
        poly: &Poly,
        dir: Direction,
    ) -> Conversion {
        let program = codegen::program(code, &[("out".to_string(), poly.clone())]);
        let name = ident(&format!("{}_{}", model.rows[ri].name, dir.name()));
        let doc = conversion_doc(model, n, ri, e, poly, dir);
        let reads = |f: fn(&SymbolKind) -> bool| program.inputs.iter().any(|i| f(&n.kinds[i.id]));
        let reads_values = reads(|k| matches!(k, SymbolKind::Own(_) | SymbolKind::Report(_)));
        let reads_parameters = reads(|k| matches!(k, SymbolKind::Parameter(_)));
        let passed_through = identity(&program, n);
        let (body, value) = evaluation(&program, n);
        Conversion {
            name,
            passed_through,
            doc,
            body,
            value,
            reads_values,
            reads_parameters,
        }
    }

    /// The call in the notation's row function.
    fn call(&self) -> TokenStream {
        let name = &self.name;
        if let Some(row) = &self.passed_through {
            return quote!(values[#row]);
        }
        match (self.reads_values, self.reads_parameters) {
            (true, true) => quote!(#name(values, parameters)),
            (true, false) => quote!(#name(values)),
            (false, true) => quote!(#name(parameters)),
            (false, false) => quote!(#name()),
        }
    }

    /// The function.
    fn item(&self, types: &Types) -> TokenStream {
        if self.passed_through.is_some() {
            return TokenStream::new();
        }
        let Conversion {
            name,
            doc,
            body,
            value,
            ..
        } = self;
        let (v, p) = (&types.values, &types.parameters);
        let args = match (self.reads_values, self.reads_parameters) {
            (true, true) => quote!(values: #v, parameters: #p),
            (true, false) => quote!(values: #v),
            (false, true) => quote!(parameters: #p),
            (false, false) => quote!(),
        };
        quote! {
            #(#[doc = #doc])*
            fn #name(#args) -> Option<f64> {
                #body
                #value
            }
        }
    }
}

/// The row read when a conversion is a value passed through unchanged.
fn identity(program: &Program, n: &Notation) -> Option<Literal> {
    let [input] = program.inputs.as_slice() else {
        return None;
    };
    let passes = program.lets.is_empty()
        && matches!(&program.outputs[..], [(_, Node::Var(v))] if *v == input.name);
    match n.kinds[input.id] {
        SymbolKind::Own(row) | SymbolKind::Report(row) if passes => {
            Some(Literal::usize_unsuffixed(row))
        }
        _ => None,
    }
}

/// The statements of a conversion — each input read (a value by its row,
/// `?` when it is absent; a parameter by its index), the program's `let`s —
/// and the value returned.
fn evaluation(program: &Program, n: &Notation) -> (TokenStream, TokenStream) {
    let mut body = TokenStream::new();
    for input in &program.inputs {
        let var = ident(&input.name);
        body.extend(match n.kinds[input.id] {
            SymbolKind::Own(row) | SymbolKind::Report(row) => {
                let row = Literal::usize_unsuffixed(row);
                quote!(let #var = values[#row]?;)
            }
            SymbolKind::Parameter(k) => {
                let k = Literal::usize_unsuffixed(k);
                quote!(let #var = parameters[#k];)
            }
            SymbolKind::Dimensional => {
                let message = format!(
                    "the conversion needs the dimensional quantity `{}`",
                    input.name
                );
                quote!(compile_error!(#message);)
            }
        });
    }
    for (name, node) in &program.lets {
        let (var, value) = (ident(name), codegen::node_tokens(node));
        body.extend(quote!(let #var = #value;));
    }
    let value = codegen::node_tokens(&program.outputs[0].1);
    (body, quote!(Some(#value)))
}

/// What a conversion computes, and from where it was derived.
fn conversion_doc(
    model: &NotationModel,
    n: &Notation,
    ri: usize,
    e: &Entry,
    poly: &Poly,
    dir: Direction,
) -> Vec<String> {
    let row = &model.rows[ri];
    let report_name =
        (model.reference().entries[ri].as_ref()).map_or(row.name.as_str(), |r| r.name.as_str());
    let formula = poly_text(poly, &n.table).replace("report_", "");
    let mut doc = match dir {
        Direction::ToReport => vec![format!(
            " The report's `{report_name}` ({}) from this notation's quantities: `{formula}`.",
            row.doc
        )],
        Direction::FromReport => vec![format!(
            " This notation's `{}` ({}) from the report's quantities: `{formula}`.",
            e.name, row.doc
        )],
    };
    doc.push(format!(
        " Derived from its definition `{} = {}` (`{}` line {}).",
        e.name, e.define, model.file, e.line
    ));
    if let (Direction::ToReport, Some(printed)) = (dir, &e.printed) {
        doc.push(match &e.erratum {
            None => format!(" The appendix prints `{printed}`."),
            Some(er) => format!(
                " The appendix prints `{printed}`, an erratum corrected to `{}`.",
                er.corrected
            ),
        });
    }
    doc
}
