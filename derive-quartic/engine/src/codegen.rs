//! From polynomials to flat, allocation-free Rust.
//!
//! Several polynomials (outputs) over the same inputs become one straight-line
//! program:
//! 1. each symbol divided by becomes one reciprocal, `let inv_mu1 = 1.0 / mu1;`;
//! 2. products shared between terms are computed once: the most frequent pair
//!    of factors over all terms of all outputs becomes a `let`, repeatedly,
//!    until no pair occurs twice (greedy pairwise common-subexpression
//!    elimination); a `let` left with a single use is folded back;
//! 3. each output is factored by the factor common to most of its terms,
//!    recursively (multivariate Horner form), which saves multiplications.
//!
//! The program only uses `f64` arithmetic: no allocation, no branch, no call,
//! nothing from `std`.

use crate::expr::SymbolTable;
use crate::poly::Poly;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};
use proc_macro2::{Ident, Literal, Span, TokenStream};
use quote::quote;
use std::collections::{BTreeMap, BTreeSet};

/// A factor of a term.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
enum Atom {
    /// An input symbol.
    Sym(usize),
    /// The reciprocal of an input symbol.
    Inv(usize),
    /// A shared product (index into the temporaries).
    Tmp(usize),
}

/// An expression of the emitted program.
#[derive(Clone, Debug, PartialEq)]
pub enum Node {
    /// An input or a `let`.
    Var(String),
    Const(BigRational),
    /// `1.0 / name`.
    Recip(String),
    Mul(Vec<Node>),
    /// Signed summands (`true` = subtract).
    Sum(Vec<(bool, Node)>),
}

/// An input a program reads: a symbol of its table.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Input {
    /// The symbol's id in the table the program was built over.
    pub id: usize,
    pub name: String,
}

/// A straight-line program: `let`s, then the outputs.
#[derive(Clone, Debug)]
pub struct Program {
    /// The inputs the program reads, in spec order.
    pub inputs: Vec<Input>,
    pub lets: Vec<(String, Node)>,
    /// One expression per output (`Const(0)` for an output that is zero).
    pub outputs: Vec<(String, Node)>,
}

type Term = (BigRational, Vec<Atom>);

/// Build the program that evaluates `outputs` (polynomials over `table`).
pub fn program(table: &SymbolTable, outputs: &[(String, Poly)]) -> Program {
    let mut terms: Vec<Vec<Term>> = outputs.iter().map(|(_, p)| atoms_of(p, table)).collect();
    let temps = shared_products(&mut terms);
    let temps = fold_single_uses(&mut terms, temps);
    let names = Names::new(table, &terms, &temps);
    let atom_node = |a: &Atom| names.node(a, table);
    let mut lets: Vec<(String, Node)> = (names.inverses.iter())
        .map(|(id, name)| (name.clone(), Node::Recip(table.get(*id).name.clone())))
        .collect();
    for (k, body) in temps.iter().enumerate() {
        let product = Node::Mul(body.iter().map(atom_node).collect());
        lets.push((names.temps[k].clone(), product));
    }
    let outputs = (outputs.iter().zip(terms))
        .map(|((name, _), ts)| (name.clone(), horner(ts, &atom_node)))
        .collect();
    let inputs = (names.inputs.iter())
        .map(|&id| Input {
            id,
            name: table.get(id).name.clone(),
        })
        .collect();
    Program {
        inputs,
        lets,
        outputs,
    }
}

/// The terms of `p` in display order, each as its coefficient and the
/// sorted multiset of its factors.
fn atoms_of(p: &Poly, table: &SymbolTable) -> Vec<Term> {
    (crate::render::ordered_terms(p, table).into_iter())
        .map(|(m, c)| {
            let mut atoms = Vec::new();
            for (id, e) in m.factors() {
                let a = if e > 0 { Atom::Sym(id) } else { Atom::Inv(id) };
                atoms.extend(std::iter::repeat_n(a, e.unsigned_abs() as usize));
            }
            atoms.sort();
            (c.clone(), atoms)
        })
        .collect()
}

/// Step 2, greedy pairwise CSE: the most frequent pair of factors over all
/// terms becomes a temporary, repeatedly, until no pair occurs twice. The
/// temporaries' bodies, in order.
fn shared_products(terms: &mut [Vec<Term>]) -> Vec<Vec<Atom>> {
    let mut temps: Vec<Vec<Atom>> = Vec::new();
    loop {
        let mut counts: BTreeMap<(Atom, Atom), usize> = BTreeMap::new();
        for (_, atoms) in terms.iter().flatten() {
            let mut seen = BTreeSet::new();
            for i in 0..atoms.len() {
                for j in i + 1..atoms.len() {
                    seen.insert((atoms[i], atoms[j]));
                }
            }
            for p in seen {
                *counts.entry(p).or_default() += 1;
            }
        }
        // The most frequent pair; ties go to the first in atom order.
        let best = counts
            .iter()
            .fold(None::<(&(Atom, Atom), usize)>, |best, (p, &c)| match best {
                Some((_, bc)) if bc >= c => best,
                _ => Some((p, c)),
            });
        let Some((&(a, b), count)) = best else { break };
        if count < 2 {
            break;
        }
        let t = Atom::Tmp(temps.len());
        temps.push(vec![a, b]);
        for (_, atoms) in terms.iter_mut().flatten() {
            if take_pair(atoms, a, b) {
                atoms.push(t);
                atoms.sort();
            }
        }
    }
    temps
}

/// How often each temporary is used, by the terms and by other temporaries.
fn uses(terms: &[Vec<Term>], temps: &[Vec<Atom>]) -> Vec<usize> {
    let mut uses = vec![0usize; temps.len()];
    for atoms in terms.iter().flatten().map(|(_, a)| a).chain(temps.iter()) {
        for a in atoms {
            if let Atom::Tmp(k) = a {
                uses[*k] += 1;
            }
        }
    }
    uses
}

/// Fold temporaries used once back into their single user, then drop the
/// unused ones and renumber.
fn fold_single_uses(terms: &mut [Vec<Term>], mut temps: Vec<Vec<Atom>>) -> Vec<Vec<Atom>> {
    loop {
        let uses = uses(terms, &temps);
        let Some(k) = (0..temps.len()).rev().find(|&k| uses[k] == 1) else {
            return renumber(terms, &temps, &uses);
        };
        let body = std::mem::take(&mut temps[k]);
        let splice = |atoms: &mut Vec<Atom>| {
            if let Some(i) = atoms.iter().position(|a| *a == Atom::Tmp(k)) {
                atoms.remove(i);
                atoms.extend(body.iter().copied());
                atoms.sort();
                true
            } else {
                false
            }
        };
        let mut done = false;
        for t in temps.iter_mut() {
            if !done {
                done = splice(t);
            }
        }
        for (_, atoms) in terms.iter_mut().flatten() {
            if !done {
                done = splice(atoms);
            }
        }
    }
}

/// The used temporaries, renumbered in order (the terms updated to match).
fn renumber(terms: &mut [Vec<Term>], temps: &[Vec<Atom>], uses: &[usize]) -> Vec<Vec<Atom>> {
    let keep: Vec<usize> = (0..temps.len()).filter(|&k| uses[k] > 0).collect();
    let renumber: BTreeMap<usize, usize> = (keep.iter().enumerate())
        .map(|(new, &old)| (old, new))
        .collect();
    let fix = |atoms: &mut Vec<Atom>| {
        for a in atoms.iter_mut() {
            if let Atom::Tmp(k) = a {
                *k = renumber[k];
            }
        }
        atoms.sort();
    };
    let mut kept: Vec<Vec<Atom>> = keep.iter().map(|&k| temps[k].clone()).collect();
    kept.iter_mut().for_each(fix);
    for (_, atoms) in terms.iter_mut().flatten() {
        fix(atoms);
    }
    kept
}

/// The names of a program: the inputs it reads, a `inv_x` per reciprocal,
/// a readable name per temporary, none of them clashing with a symbol.
struct Names {
    inputs: BTreeSet<usize>,
    inverses: BTreeMap<usize, String>,
    temps: Vec<String>,
}

impl Names {
    fn new(table: &SymbolTable, terms: &[Vec<Term>], temps: &[Vec<Atom>]) -> Names {
        let mut inputs = BTreeSet::new();
        let mut used_inverses = BTreeSet::new();
        for atoms in terms.iter().flatten().map(|(_, a)| a).chain(temps.iter()) {
            for a in atoms {
                match a {
                    Atom::Sym(id) => {
                        inputs.insert(*id);
                    }
                    Atom::Inv(id) => {
                        inputs.insert(*id);
                        used_inverses.insert(*id);
                    }
                    Atom::Tmp(_) => {}
                }
            }
        }
        let mut taken: BTreeSet<String> = table.symbols.iter().map(|s| s.name.clone()).collect();
        let mut fresh = |wanted: String| {
            let mut name = wanted.clone();
            let mut k = 2;
            while taken.contains(&name) {
                name = format!("{wanted}_{k}");
                k += 1;
            }
            taken.insert(name.clone());
            name
        };
        let inverses = (used_inverses.iter())
            .map(|&id| (id, fresh(format!("inv_{}", table.get(id).name))))
            .collect();
        let temps = temp_names(table, temps, &mut fresh);
        Names {
            inputs,
            inverses,
            temps,
        }
    }

    fn node(&self, a: &Atom, table: &SymbolTable) -> Node {
        match a {
            Atom::Sym(id) => Node::Var(table.get(*id).name.clone()),
            Atom::Inv(id) => Node::Var(self.inverses[id].clone()),
            Atom::Tmp(k) => Node::Var(self.temps[*k].clone()),
        }
    }
}

/// Each temporary named after the product it holds (`t{k}` when that is
/// too long).
fn temp_names(
    table: &SymbolTable,
    temps: &[Vec<Atom>],
    fresh: &mut impl FnMut(String) -> String,
) -> Vec<String> {
    let n = table.len();
    // Exponents of each temporary over the input symbols, for its name.
    let mut temp_exps: Vec<Vec<i32>> = Vec::new();
    let mut names: Vec<String> = Vec::new();
    for (k, body) in temps.iter().enumerate() {
        let mut e = vec![0i32; n];
        for a in body {
            match a {
                Atom::Sym(id) => e[*id] += 1,
                Atom::Inv(id) => e[*id] -= 1,
                Atom::Tmp(j) => {
                    for (i, x) in temp_exps[*j].iter().enumerate() {
                        e[i] += x;
                    }
                }
            }
        }
        let name = product_name(table, &e);
        let name = if name.len() > 48 {
            format!("t{k}")
        } else {
            name
        };
        names.push(fresh(name));
        temp_exps.push(e);
    }
    names
}

/// Remove one `a` and one `b` from a sorted multiset; false if not both there.
fn take_pair(atoms: &mut Vec<Atom>, a: Atom, b: Atom) -> bool {
    let Some(i) = atoms.iter().position(|x| *x == a) else {
        return false;
    };
    let j = atoms
        .iter()
        .enumerate()
        .position(|(k, x)| k != i && *x == b);
    let Some(j) = j else { return false };
    let (hi, lo) = if i > j { (i, j) } else { (j, i) };
    atoms.remove(hi);
    atoms.remove(lo);
    true
}

/// A readable name for a product of symbols: `m_q_over_i_b`, `x_u_z_w`,
/// `inv_i_b_mu1`, `mu1_sq`.
fn product_name(table: &SymbolTable, e: &[i32]) -> String {
    let part = |id: usize, k: i32| {
        let name = &table.get(id).name;
        match k {
            1 => name.clone(),
            2 => format!("{name}_sq"),
            3 => format!("{name}_cube"),
            _ => format!("{name}_pow{k}"),
        }
    };
    let num: Vec<String> = e
        .iter()
        .enumerate()
        .filter(|(_, k)| **k > 0)
        .map(|(i, k)| part(i, *k))
        .collect();
    let den: Vec<String> = e
        .iter()
        .enumerate()
        .filter(|(_, k)| **k < 0)
        .map(|(i, k)| part(i, -*k))
        .collect();
    match (num.is_empty(), den.is_empty()) {
        (false, true) => num.join("_"),
        (false, false) => format!("{}_over_{}", num.join("_"), den.join("_")),
        (true, false) => format!("inv_{}", den.join("_")),
        (true, true) => "one".into(),
    }
}

/// Multivariate Horner form: factor the atom common to most terms, recursively.
fn horner(terms: Vec<Term>, atom_node: &impl Fn(&Atom) -> Node) -> Node {
    let mut summands: Vec<(bool, Node)> = Vec::new();
    horner_into(terms, atom_node, &mut summands);
    // Added terms first: `z - 1.0` reads better than `-1.0 + z`.
    summands.sort_by_key(|(neg, _)| *neg);
    match summands.len() {
        0 => Node::Const(BigRational::zero()),
        1 if !summands[0].0 => summands
            .pop()
            .map(|(_, n)| n)
            .unwrap_or(Node::Const(BigRational::zero())),
        _ => Node::Sum(summands),
    }
}

fn horner_into(terms: Vec<Term>, atom_node: &impl Fn(&Atom) -> Node, out: &mut Vec<(bool, Node)>) {
    if terms.is_empty() {
        return;
    }
    let mut counts: BTreeMap<Atom, usize> = BTreeMap::new();
    for (_, atoms) in &terms {
        let distinct: BTreeSet<&Atom> = atoms.iter().collect();
        for a in distinct {
            *counts.entry(*a).or_default() += 1;
        }
    }
    let best = counts
        .iter()
        .fold(None::<(&Atom, usize)>, |best, (a, &c)| match best {
            Some((_, bc)) if bc >= c => best,
            _ => Some((a, c)),
        });
    match best {
        Some((&a, c)) if c >= 2 => {
            let (mut with, without): (Vec<Term>, Vec<Term>) =
                terms.into_iter().partition(|(_, atoms)| atoms.contains(&a));
            for (_, atoms) in with.iter_mut() {
                if let Some(i) = atoms.iter().position(|x| *x == a) {
                    atoms.remove(i);
                }
            }
            // a·(Σ with) — pull a common sign out so that `a * (-x - y)`
            // reads `-(a * (x + y))`.
            let all_negative = with.iter().all(|(c, _)| c.is_negative());
            if all_negative {
                for (c, _) in with.iter_mut() {
                    *c = -c.clone();
                }
            }
            let inner = horner(with, atom_node);
            let product = match inner {
                Node::Const(ref k) if k.is_one() => atom_node(&a),
                Node::Mul(mut fs) => {
                    fs.insert(0, atom_node(&a));
                    Node::Mul(fs)
                }
                other => Node::Mul(vec![atom_node(&a), other]),
            };
            out.push((all_negative, product));
            horner_into(without, atom_node, out);
        }
        _ => {
            for (c, atoms) in terms {
                let neg = c.is_negative();
                let mag = c.abs();
                let mut factors: Vec<Node> = Vec::new();
                if !mag.is_one() || atoms.is_empty() {
                    factors.push(Node::Const(mag));
                }
                factors.extend(atoms.iter().map(atom_node));
                let node = if factors.len() == 1 {
                    factors.pop().unwrap_or(Node::Const(BigRational::one()))
                } else {
                    Node::Mul(factors)
                };
                out.push((neg, node));
            }
        }
    }
}

// ------------------------------------------------------------------ emission

pub(crate) fn ident(name: &str) -> Ident {
    Ident::new(name, Span::call_site())
}

/// An `f64` literal for a rational: exact decimals where the value is a
/// dyadic fraction, `(p / q)` otherwise (folded by the compiler). A
/// constant beyond the range of `f64` is a compile error, not a guess.
fn constant(r: &BigRational) -> TokenStream {
    let dyadic = {
        let d = r.denom();
        let power_of_two = d.magnitude().count_ones() == 1;
        power_of_two && d.bits() <= 53 && r.numer().bits() <= 53
    };
    let finite = |x: Option<f64>| x.filter(|v| v.is_finite()).map(Literal::f64_unsuffixed);
    let literals = if dyadic {
        finite(r.to_f64()).map(|lit| quote!(#lit))
    } else {
        (finite(r.numer().to_f64()).zip(finite(r.denom().to_f64()))).map(|(p, q)| quote!((#p / #q)))
    };
    literals.unwrap_or_else(|| {
        let message = format!("the constant {r} of a generated formula is beyond the range of f64");
        quote!(compile_error!(#message))
    })
}

/// How a program's numbers are written: as `f64` literals, or in a generic
/// function over a scalar `T` as `T::from(…)` (so that the same program
/// evaluates over complex numbers).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scalar {
    F64,
    Generic,
}

impl Scalar {
    fn literal(self, lit: TokenStream) -> TokenStream {
        match self {
            Scalar::F64 => lit,
            Scalar::Generic => quote!(T::from(#lit)),
        }
    }
}

/// Tokens of a node.
pub fn node_tokens(node: &Node) -> TokenStream {
    node_tokens_in(node, Scalar::F64)
}

/// Tokens of a node, its numbers written as `scalar` says.
pub fn node_tokens_in(node: &Node, scalar: Scalar) -> TokenStream {
    let node_tokens = |n: &Node| node_tokens_in(n, scalar);
    match node {
        Node::Var(name) => {
            let i = ident(name);
            quote!(#i)
        }
        Node::Const(r) => scalar.literal(constant(r)),
        Node::Recip(name) => {
            let i = ident(name);
            let one = scalar.literal(quote!(1.0));
            quote!(#one / #i)
        }
        Node::Mul(fs) => {
            let parts: Vec<TokenStream> = fs
                .iter()
                .map(|f| match f {
                    Node::Sum(_) | Node::Recip(_) => {
                        let t = node_tokens(f);
                        quote!((#t))
                    }
                    _ => node_tokens(f),
                })
                .collect();
            let mut ts = TokenStream::new();
            for (i, p) in parts.into_iter().enumerate() {
                if i > 0 {
                    ts.extend(quote!(*));
                }
                ts.extend(p);
            }
            ts
        }
        Node::Sum(items) => {
            let mut ts = TokenStream::new();
            for (i, (neg, n)) in items.iter().enumerate() {
                let t = match n {
                    Node::Sum(_) => {
                        let t = node_tokens(n);
                        quote!((#t))
                    }
                    _ => node_tokens(n),
                };
                match (i, neg) {
                    (0, false) => ts.extend(t),
                    (0, true) => ts.extend(quote!(-#t)),
                    (_, false) => ts.extend(quote!(+ #t)),
                    (_, true) => ts.extend(quote!(- #t)),
                }
            }
            ts
        }
    }
}

/// The statements of a program: reads of the used inputs from `source`
/// (e.g. `self`), the `let`s, and a `let` per non-zero output named by
/// `output_name`.
pub fn statements(
    program: &Program,
    source: &TokenStream,
    output_name: impl Fn(&str) -> String,
) -> TokenStream {
    let mut ts = TokenStream::new();
    for input in &program.inputs {
        let i = ident(&input.name);
        ts.extend(quote!(let #i = #source.#i;));
    }
    ts.extend(body_statements(program, Scalar::F64, output_name));
    ts
}

/// The `let`s of a program and a `let` per non-zero output, its inputs
/// already bound, numbers written as `scalar` says.
pub fn body_statements(
    program: &Program,
    scalar: Scalar,
    output_name: impl Fn(&str) -> String,
) -> TokenStream {
    let mut ts = TokenStream::new();
    for (name, node) in &program.lets {
        let i = ident(name);
        let v = node_tokens_in(node, scalar);
        ts.extend(quote!(let #i = #v;));
    }
    for (name, node) in &program.outputs {
        if matches!(node, Node::Const(c) if c.is_zero()) {
            continue;
        }
        let i = ident(&output_name(name));
        let v = node_tokens_in(node, scalar);
        ts.extend(quote!(let #i = #v;));
    }
    ts
}

/// The value of an output in the program's final expression: its `let`
/// name, or `0.0` when it is identically zero.
pub fn output_ref(
    program: &Program,
    index: usize,
    output_name: impl Fn(&str) -> String,
) -> TokenStream {
    output_ref_in(program, index, Scalar::F64, output_name)
}

/// As [`output_ref`], a zero written as `scalar` says.
pub fn output_ref_in(
    program: &Program,
    index: usize,
    scalar: Scalar,
    output_name: impl Fn(&str) -> String,
) -> TokenStream {
    let (name, node) = &program.outputs[index];
    if matches!(node, Node::Const(c) if c.is_zero()) {
        scalar.literal(quote!(0.0))
    } else {
        let i = ident(&output_name(name));
        quote!(#i)
    }
}

/// Count of floating-point operations of a program (additions,
/// multiplications, divisions), for the docs and for the tests that keep
/// the generator honest.
pub fn op_count(program: &Program) -> (usize, usize, usize) {
    fn walk(n: &Node, c: &mut (usize, usize, usize)) {
        match n {
            Node::Var(_) | Node::Const(_) => {}
            Node::Recip(_) => c.2 += 1,
            Node::Mul(fs) => {
                c.1 += fs.len().saturating_sub(1);
                fs.iter().for_each(|f| walk(f, c));
            }
            Node::Sum(items) => {
                c.0 += items.len().saturating_sub(1);
                if items.first().is_some_and(|(neg, _)| *neg) {
                    c.0 += 1;
                }
                items.iter().for_each(|(_, f)| walk(f, c));
            }
        }
    }
    let mut c = (0, 0, 0);
    for (_, n) in program.lets.iter().chain(program.outputs.iter()) {
        walk(n, &mut c);
    }
    c
}
