//! The one guard every writer of results passes: no value that is not
//! finite is written. JSON has no infinity or not-a-number (serde_json
//! writes `null` for them, indistinguishable from a value that is absent
//! by design), TOML and the pages would print `inf` or `NaN`; so a result
//! is checked, field by field, before any of its forms is written, and a
//! value that is not finite is an error naming the field
//! (`modes[1].period`).
//!
//! The check walks a result through its [`Serialize`] implementation — the
//! very fields its JSON has — and stops at the first `f32` or `f64` that is
//! not finite. An absent value (`None`, serialized as `null` on purpose)
//! passes.

use serde::Serialize;
use serde::ser;
use std::fmt;

/// A field of a result that is not finite.
#[derive(Debug, Clone, PartialEq)]
pub struct NotFinite {
    /// The field's path in the result's JSON: `short_period_frequency.cap`,
    /// `modes[1].period`, `values.C_La`.
    pub field: String,
    pub value: f64,
}

impl fmt::Display for NotFinite {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "`{}` = {} is not finite", self.field, self.value)
    }
}

impl std::error::Error for NotFinite {}

/// Whether every number of `value` is finite; the first that is not, with
/// its field, if any. (A value whose serialization fails for another
/// reason is not this guard's concern, and passes.)
pub fn check<T: Serialize + ?Sized>(value: &T) -> Result<(), NotFinite> {
    let mut c = Checker { path: Vec::new() };
    match value.serialize(&mut c) {
        Err(Stop::NotFinite(e)) => Err(e),
        _ => Ok(()),
    }
}

/// [`check`] as an input error about `source`, the file the result is of:
/// the program's words for a result that cannot be written.
pub fn guard<T: Serialize + ?Sized>(
    source: &str,
    value: &T,
) -> Result<(), crate::diag::InputError> {
    check(value).map_err(|e| {
        crate::diag::InputError::file(
            source,
            format!(
                "the result's {e}: nothing is written (an input lies outside the range in which this result can be computed; check the values of the largest or smallest magnitude)"
            ),
        )
    })
}

/// Why the walk stopped.
#[derive(Debug)]
enum Stop {
    NotFinite(NotFinite),
    Other(String),
}

impl fmt::Display for Stop {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Stop::NotFinite(e) => e.fmt(f),
            Stop::Other(m) => f.write_str(m),
        }
    }
}

impl std::error::Error for Stop {}

impl ser::Error for Stop {
    fn custom<T: fmt::Display>(msg: T) -> Self {
        Stop::Other(msg.to_string())
    }
}

struct Checker {
    /// The path to the value being walked: field names and `[i]`.
    path: Vec<String>,
}

impl Checker {
    fn number(&self, v: f64) -> Result<(), Stop> {
        if v.is_finite() {
            return Ok(());
        }
        let mut field = String::new();
        for p in &self.path {
            if !field.is_empty() && !p.starts_with('[') {
                field.push('.');
            }
            field.push_str(p);
        }
        Err(Stop::NotFinite(NotFinite { field, value: v }))
    }

    /// Walks `value` under the path element `at`.
    fn under<T: Serialize + ?Sized>(&mut self, at: String, value: &T) -> Result<(), Stop> {
        self.path.push(at);
        let r = value.serialize(&mut *self);
        self.path.pop();
        r
    }
}

/// A sequence's, tuple's, map's or struct's elements being walked.
struct Compound<'a> {
    c: &'a mut Checker,
    index: usize,
    key: Option<String>,
}

impl<'a> Compound<'a> {
    fn new(c: &'a mut Checker) -> Self {
        Compound {
            c,
            index: 0,
            key: None,
        }
    }

    fn element<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Stop> {
        let at = format!("[{}]", self.index);
        self.index += 1;
        self.c.under(at, value)
    }
}

/// The name of a map's key, as its JSON has it.
fn key_name<T: Serialize + ?Sized>(key: &T) -> String {
    match serde_json::to_value(key) {
        Ok(serde_json::Value::String(s)) => s,
        Ok(v) => v.to_string(),
        Err(_) => "?".into(),
    }
}

macro_rules! scalars {
    ($($method:ident: $t:ty),*) => {
        $(fn $method(self, _: $t) -> Result<(), Stop> { Ok(()) })*
    };
}

impl<'a> ser::Serializer for &'a mut Checker {
    type Ok = ();
    type Error = Stop;
    type SerializeSeq = Compound<'a>;
    type SerializeTuple = Compound<'a>;
    type SerializeTupleStruct = Compound<'a>;
    type SerializeTupleVariant = Compound<'a>;
    type SerializeMap = Compound<'a>;
    type SerializeStruct = Compound<'a>;
    type SerializeStructVariant = Compound<'a>;

    scalars!(serialize_bool: bool, serialize_i8: i8, serialize_i16: i16, serialize_i32: i32,
        serialize_i64: i64, serialize_i128: i128, serialize_u8: u8, serialize_u16: u16,
        serialize_u32: u32, serialize_u64: u64, serialize_u128: u128, serialize_char: char,
        serialize_str: &str, serialize_bytes: &[u8]);

    fn serialize_f32(self, v: f32) -> Result<(), Stop> {
        self.number(f64::from(v))
    }
    fn serialize_f64(self, v: f64) -> Result<(), Stop> {
        self.number(v)
    }
    fn serialize_none(self) -> Result<(), Stop> {
        Ok(())
    }
    fn serialize_some<T: Serialize + ?Sized>(self, value: &T) -> Result<(), Stop> {
        value.serialize(self)
    }
    fn serialize_unit(self) -> Result<(), Stop> {
        Ok(())
    }
    fn serialize_unit_struct(self, _: &'static str) -> Result<(), Stop> {
        Ok(())
    }
    fn serialize_unit_variant(self, _: &'static str, _: u32, _: &'static str) -> Result<(), Stop> {
        Ok(())
    }
    fn serialize_newtype_struct<T: Serialize + ?Sized>(
        self,
        _: &'static str,
        value: &T,
    ) -> Result<(), Stop> {
        value.serialize(self)
    }
    fn serialize_newtype_variant<T: Serialize + ?Sized>(
        self,
        _: &'static str,
        _: u32,
        variant: &'static str,
        value: &T,
    ) -> Result<(), Stop> {
        self.under(variant.to_string(), value)
    }
    fn serialize_seq(self, _: Option<usize>) -> Result<Compound<'a>, Stop> {
        Ok(Compound::new(self))
    }
    fn serialize_tuple(self, _: usize) -> Result<Compound<'a>, Stop> {
        Ok(Compound::new(self))
    }
    fn serialize_tuple_struct(self, _: &'static str, _: usize) -> Result<Compound<'a>, Stop> {
        Ok(Compound::new(self))
    }
    fn serialize_tuple_variant(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: usize,
    ) -> Result<Compound<'a>, Stop> {
        Ok(Compound::new(self))
    }
    fn serialize_map(self, _: Option<usize>) -> Result<Compound<'a>, Stop> {
        Ok(Compound::new(self))
    }
    fn serialize_struct(self, _: &'static str, _: usize) -> Result<Compound<'a>, Stop> {
        Ok(Compound::new(self))
    }
    fn serialize_struct_variant(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: usize,
    ) -> Result<Compound<'a>, Stop> {
        Ok(Compound::new(self))
    }
}

macro_rules! elements {
    ($($tr:ident: $method:ident),*) => {
        $(impl ser::$tr for Compound<'_> {
            type Ok = ();
            type Error = Stop;
            fn $method<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Stop> {
                self.element(value)
            }
            fn end(self) -> Result<(), Stop> {
                Ok(())
            }
        })*
    };
}

elements!(SerializeSeq: serialize_element, SerializeTuple: serialize_element,
    SerializeTupleStruct: serialize_field, SerializeTupleVariant: serialize_field);

macro_rules! fields {
    ($($tr:ident),*) => {
        $(impl ser::$tr for Compound<'_> {
            type Ok = ();
            type Error = Stop;
            fn serialize_field<T: Serialize + ?Sized>(
                &mut self,
                key: &'static str,
                value: &T,
            ) -> Result<(), Stop> {
                self.c.under(key.to_string(), value)
            }
            fn end(self) -> Result<(), Stop> {
                Ok(())
            }
        })*
    };
}

fields!(SerializeStruct, SerializeStructVariant);

impl ser::SerializeMap for Compound<'_> {
    type Ok = ();
    type Error = Stop;
    fn serialize_key<T: Serialize + ?Sized>(&mut self, key: &T) -> Result<(), Stop> {
        self.key = Some(key_name(key));
        Ok(())
    }
    fn serialize_value<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Stop> {
        let key = self.key.take().unwrap_or_else(|| "?".into());
        self.c.under(key, value)
    }
    fn end(self) -> Result<(), Stop> {
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::BTreeMap;

    #[derive(Serialize)]
    struct Mode {
        re: f64,
        period: Option<f64>,
    }

    #[derive(Serialize)]
    struct Result_ {
        modes: Vec<Mode>,
        #[serde(flatten)]
        extra: BTreeMap<&'static str, f64>,
        pair: (f64, f32),
    }

    fn result(period: Option<f64>, extra: f64, pair: (f64, f32)) -> Result_ {
        Result_ {
            modes: vec![
                Mode {
                    re: -1.0,
                    period: None,
                },
                Mode { re: -2.0, period },
            ],
            extra: [("C_La", extra)].into_iter().collect(),
            pair,
        }
    }

    #[test]
    fn the_first_value_that_is_not_finite_is_named_by_its_field() {
        assert_eq!(check(&result(Some(3.0), 1.0, (0.0, 0.0))), Ok(()));
        let e = check(&result(Some(f64::INFINITY), 1.0, (0.0, 0.0))).unwrap_err();
        assert_eq!(e.field, "modes[1].period");
        assert_eq!(e.to_string(), "`modes[1].period` = inf is not finite");
        let e = check(&result(None, f64::NAN, (0.0, 0.0))).unwrap_err();
        assert_eq!(e.field, "C_La");
        let e = check(&result(None, 1.0, (0.0, f32::NEG_INFINITY))).unwrap_err();
        assert_eq!((e.field.as_str(), e.value), ("pair[1]", f64::NEG_INFINITY));
        // an absent value passes, a bare number is checked
        assert_eq!(check(&None::<f64>), Ok(()));
        assert!(check(&f64::NAN).is_err());
    }
}
