//! The derive input: `#[quartic(spec = "…")]` and the struct's fields.

use formula_engine::{QuarticModel, SourceFile};
use std::path::PathBuf;
use syn::{Data, DeriveInput, Fields, LitStr, Type};

/// The struct the derive is on, and its spec path.
pub struct Target<'a> {
    pub spec: LitStr,
    input: &'a DeriveInput,
}

impl<'a> Target<'a> {
    pub fn parse(input: &'a DeriveInput) -> syn::Result<Self> {
        let mut spec = None;
        for attr in input.attrs.iter().filter(|a| a.path().is_ident("quartic")) {
            attr.parse_nested_meta(|meta| {
                if meta.path.is_ident("spec") {
                    if spec.is_some() {
                        return Err(meta.error("`spec` is given twice"));
                    }
                    spec = Some(meta.value()?.parse::<LitStr>()?);
                    Ok(())
                } else {
                    Err(meta.error("unknown key; the only key is `spec = \"path/to/spec.toml\"`"))
                }
            })?;
        }
        let spec = spec.ok_or_else(|| {
            syn::Error::new_spanned(
                &input.ident,
                "missing `#[quartic(spec = \"path/to/spec.toml\")]` (the path is relative to this crate's Cargo.toml)",
            )
        })?;
        Ok(Target { spec, input })
    }

    /// The struct's fields must be exactly the spec's inputs, each an `f64`.
    pub fn check_fields(&self, model: &QuarticModel) -> syn::Result<()> {
        let fields = match &self.input.data {
            Data::Struct(s) => match &s.fields {
                Fields::Named(f) => &f.named,
                _ => {
                    return Err(syn::Error::new_spanned(
                        &self.input.ident,
                        "`Quartic` needs a struct with named fields, one per spec input",
                    ));
                }
            },
            _ => {
                return Err(syn::Error::new_spanned(
                    &self.input.ident,
                    "`Quartic` can only be derived for a struct",
                ));
            }
        };
        let inputs: Vec<&str> = model.inputs().iter().map(|s| s.name.as_str()).collect();
        let mut errors: Vec<syn::Error> = Vec::new();
        for f in fields {
            let Some(ident) = &f.ident else { continue };
            let name = ident.to_string();
            if !inputs.contains(&name.as_str()) {
                errors.push(syn::Error::new_spanned(
                    ident,
                    format!(
                        "field `{name}` is not an input of the spec `{}`; its inputs are {}",
                        model.file,
                        inputs.join(", ")
                    ),
                ));
            }
            let is_f64 =
                matches!(&f.ty, Type::Path(p) if p.qself.is_none() && p.path.is_ident("f64"));
            if !is_f64 {
                errors.push(syn::Error::new_spanned(
                    &f.ty,
                    format!("field `{name}` must be `f64`"),
                ));
            }
        }
        for name in &inputs {
            let present = fields
                .iter()
                .any(|f| f.ident.as_ref().is_some_and(|i| i == name));
            if !present {
                errors.push(syn::Error::new_spanned(
                    &self.input.ident,
                    format!(
                        "missing field `{name}: f64`, an input of the spec `{}`",
                        model.file
                    ),
                ));
            }
        }
        formula_engine::diag::combine(errors).map_or(Ok(()), Err)
    }
}

/// A spec read from disk.
pub struct Spec {
    pub file: SourceFile,
    pub absolute: PathBuf,
}

impl Spec {
    /// The generated items, with what makes the build re-run when the spec
    /// changes.
    pub fn rerun_when_changed(&self, items: proc_macro2::TokenStream) -> proc_macro2::TokenStream {
        let path = self.absolute.to_string_lossy().into_owned();
        quote::quote! {
            // Re-run this expansion when the spec changes.
            const _: &[u8] = include_bytes!(#path);
            #items
        }
    }
}

/// Read the spec at `lit`, relative to the invoking crate's manifest
/// directory. (`DERIVE_QUARTIC_MANIFEST_DIR` overrides that directory; the
/// compile-fail tests use it, since trybuild builds them elsewhere.)
pub fn read_spec(lit: &LitStr) -> syn::Result<Spec> {
    let rel = lit.value();
    let base = std::env::var_os("DERIVE_QUARTIC_MANIFEST_DIR")
        .or_else(|| std::env::var_os("CARGO_MANIFEST_DIR"))
        .map(PathBuf::from)
        .unwrap_or_default();
    let absolute = base.join(&rel);
    match std::fs::read_to_string(&absolute) {
        Ok(text) => Ok(Spec {
            file: SourceFile::new(rel, text),
            absolute,
        }),
        Err(e) => Err(syn::Error::new_spanned(
            lit,
            format!("cannot read the spec `{rel}` (relative to this crate's Cargo.toml): {e}"),
        )),
    }
}
