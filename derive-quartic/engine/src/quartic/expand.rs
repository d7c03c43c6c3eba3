//! The Rust that `#[derive(Quartic)]` emits for a verified spec, item by
//! item: the names of the inputs and coefficients, the conversions to and
//! from an array of the inputs, the coefficients, and their gradient.
//!
//! The same functions serve the proc-macro (at compile time) and
//! `cargo xtask regen` (which writes them, formatted, into
//! `docs/generated/` for review), so what a reviewer reads is what the
//! compiler compiles.

use super::model::QuarticModel;
use crate::codegen::{self, Program, Scalar};
use crate::poly::Poly;
use crate::render;
use proc_macro2::{Ident, Literal, Span, TokenStream};
use quote::quote;

/// The name of coefficient `name`'s local variable.
fn coef_var(name: &str) -> String {
    format!("coef_{}", name.to_lowercase())
}

/// The name of ∂(coefficient)/∂(input)'s local variable.
fn gradient_var(name: &str) -> String {
    name.to_string()
}

/// The program evaluating the coefficients, highest power first.
pub fn coefficient_program(model: &QuarticModel) -> Program {
    let outputs: Vec<(String, Poly)> = model
        .coefficients
        .iter()
        .map(|c| (c.name.clone(), c.expansion.clone()))
        .collect();
    codegen::program(&model.table, &outputs)
}

/// The program evaluating ∂(coefficient)/∂(input) for every input (rows) and
/// coefficient (columns).
pub fn gradient_program(model: &QuarticModel) -> Program {
    let mut outputs = Vec::new();
    for (id, input) in model.inputs().iter().enumerate() {
        for c in &model.coefficients {
            outputs.push((
                format!("d{}_d{}", c.name.to_lowercase(), input.name),
                c.expansion.derivative(id),
            ));
        }
    }
    codegen::program(&model.table, &outputs)
}

/// The `impl` block for the struct `ty` whose fields are the spec's inputs.
pub fn quartic_impl(model: &QuarticModel, ty: &Ident) -> TokenStream {
    let names = names(model);
    let values = input_values(model);
    let coefficients = coefficients_fn(model);
    let coefficients_of = coefficients_of_fn(model);
    let gradient = gradient_fn(model);
    quote! {
        impl #ty {
            #names
            #values
            #coefficients
            #coefficients_of
            #gradient
        }
    }
}

fn usize_lit(n: usize) -> Literal {
    Literal::usize_unsuffixed(n)
}

fn fields(model: &QuarticModel) -> Vec<Ident> {
    (model.inputs().iter())
        .map(|s| Ident::new(&s.name, Span::call_site()))
        .collect()
}

/// `QUARTIC_INPUTS` and `QUARTIC_COEFFICIENTS`.
fn names(model: &QuarticModel) -> TokenStream {
    let n_in = usize_lit(model.inputs().len());
    let n_coef = usize_lit(model.coefficients.len());
    let inputs = model.inputs().iter().map(|s| Literal::string(&s.name));
    let coefs = model.coefficients.iter().map(|c| Literal::string(&c.name));
    let inputs_doc = format!(
        " The inputs of the stability polynomial of `{}`, in the order of the gradient's rows.",
        model.file
    );
    quote! {
        #[doc = #inputs_doc]
        pub const QUARTIC_INPUTS: [&'static str; #n_in] = [#(#inputs),*];
        #[doc = " The coefficients' names, highest power first."]
        pub const QUARTIC_COEFFICIENTS: [&'static str; #n_coef] = [#(#coefs),*];
    }
}

/// `quartic_input_values` and `from_quartic_input_values`.
fn input_values(model: &QuarticModel) -> TokenStream {
    let n_in = usize_lit(model.inputs().len());
    let fields = fields(model);
    quote! {
        /// The inputs' values, in the order of [`Self::QUARTIC_INPUTS`].
        #[inline]
        #[must_use]
        pub fn quartic_input_values(&self) -> [f64; #n_in] {
            [#(self.#fields),*]
        }

        /// The struct from its inputs' values, in the order of [`Self::QUARTIC_INPUTS`].
        #[inline]
        #[must_use]
        pub fn from_quartic_input_values(values: [f64; #n_in]) -> Self {
            let [#(#fields),*] = values;
            Self { #(#fields),* }
        }
    }
}

/// `quartic_coefficients`, highest power first.
fn coefficients_fn(model: &QuarticModel) -> TokenStream {
    let n_coef = usize_lit(model.coefficients.len());
    let program = coefficient_program(model);
    let body = codegen::statements(&program, &quote!(self), coef_var);
    let refs = (0..model.coefficients.len()).map(|k| codegen::output_ref(&program, k, coef_var));
    let doc = coefficients_doc(model);
    quote! {
        #(#[doc = #doc])*
        #[inline]
        #[must_use]
        pub fn quartic_coefficients(&self) -> [f64; #n_coef] {
            #body
            [#(#refs),*]
        }
    }
}

/// `quartic_coefficients_of`: the same program over any scalar `T` (the
/// p-method's complex derivatives), the inputs given as an array.
fn coefficients_of_fn(model: &QuarticModel) -> TokenStream {
    let n_in = usize_lit(model.inputs().len());
    let n_coef = usize_lit(model.coefficients.len());
    let program = coefficient_program(model);
    let body = codegen::body_statements(&program, Scalar::Generic, coef_var);
    let refs = (0..model.coefficients.len())
        .map(|k| codegen::output_ref_in(&program, k, Scalar::Generic, coef_var));
    let fields = fields(model);
    quote! {
        /// [`Self::quartic_coefficients`] over any scalar `T` (complex
        /// derivatives: the air forces at a complex frequency, the
        /// p-method), the inputs in the order of [`Self::QUARTIC_INPUTS`].
        /// The same program, its numbers written `T::from(…)`.
        #[inline]
        #[must_use]
        #[allow(unused_variables)]
        pub fn quartic_coefficients_of<T>(values: [T; #n_in]) -> [T; #n_coef]
        where
            T: Copy
                + ::core::convert::From<f64>
                + ::core::ops::Add<Output = T>
                + ::core::ops::Sub<Output = T>
                + ::core::ops::Mul<Output = T>
                + ::core::ops::Div<Output = T>
                + ::core::ops::Neg<Output = T>,
        {
            let [#(#fields),*] = values;
            #body
            [#(#refs),*]
        }
    }
}

fn coefficients_doc(model: &QuarticModel) -> Vec<String> {
    let mut doc = vec![
        format!(
            " The coefficients [{}] of {} = 0, highest power first:",
            model.coefficient_names(),
            model.polynomial("·").join(" + ")
        ),
        format!(
            " the exact expansion of the determinant of eq ({}) ({}).",
            model.determinant.equation, model.source
        ),
        String::new(),
    ];
    for c in &model.coefficients {
        doc.push(format!(
            " - `{} = {}` (eq ({}))",
            c.name,
            render::poly_text(&c.expansion, &model.table),
            c.equation
        ));
    }
    doc.push(String::new());
    doc.push(format!(
        " Generated by derive-quartic from `{}`; allocation-free, branch-free.",
        model.file
    ));
    doc
}

/// `quartic_gradient`: one row per input, one column per coefficient.
fn gradient_fn(model: &QuarticModel) -> TokenStream {
    let n_in = model.inputs().len();
    let n_coef = model.coefficients.len();
    let program = gradient_program(model);
    let body = codegen::statements(&program, &quote!(self), gradient_var);
    let rows = (0..n_in).map(|i| {
        let cells =
            (0..n_coef).map(|k| codegen::output_ref(&program, i * n_coef + k, gradient_var));
        quote!([#(#cells),*])
    });
    let doc = [
        format!(
            " The exact gradient of [`Self::quartic_coefficients`]: row `i` holds ∂[{}]/∂(input `i`),",
            model.coefficient_names()
        ),
        " with the inputs in the order of [`Self::QUARTIC_INPUTS`]. Differentiated symbolically"
            .to_string(),
        format!(
            " from the expansion of eq ({}); allocation-free.",
            model.determinant.equation
        ),
    ];
    let (n_in, n_coef) = (usize_lit(n_in), usize_lit(n_coef));
    quote! {
        #(#[doc = #doc])*
        #[inline]
        #[must_use]
        pub fn quartic_gradient(&self) -> [[f64; #n_coef]; #n_in] {
            #body
            [#(#rows),*]
        }
    }
}
