//! The order in which the declaration stage reads declarations, so that their order in the
//! source carries no meaning.
//!
//! Input: the POUs of the program (as the declaration stage lists them), the constants of a
//! declaration scope. Output: the same POUs, each one after the user function blocks (and
//! classes) its variables hold by value, directly or as array elements; the scope's constants
//! with their values, whatever their order. Invariants: every POU is in the output exactly once; a cycle of blocks
//! holding each other by value (E1080, `block_cycles`) is broken where it is met; the walk uses an
//! explicit stack, no recursion, so a long chain of blocks is no deep stack; constants are
//! evaluated in at most one round more than there are constants, silently (their errors are
//! reported once, when the declarations are read in order).
//!
//! IEC 61131-3 (ed. 3, 6.1 and 6.6) declares POUs at configuration level in no order, and an
//! instance's initial value names the block's inputs (`fb : FB_Conn := (sPrefix := 'A::')`):
//! those are known only once the block's variables are declared, so the block is declared first.

use super::decls::Consts;
use super::model::{PouId, Type};
use crate::ast::{self, TypeRef};
use std::collections::HashMap;

/// `pous` reordered so that each POU comes after the blocks its variables hold (see the module
/// documentation); POUs unrelated to each other keep their order.
pub(super) fn pou_declaration_order<'u>(
    pous: &[(PouId, &'u ast::Pou)],
) -> Vec<(PouId, &'u ast::Pou)> {
    let mut index: HashMap<String, usize> = HashMap::new();
    for (i, (_, p)) in pous.iter().enumerate() {
        index.entry(p.name.key()).or_insert(i);
    }
    // the blocks the variables of `p` hold by value (an array's element included)
    let needs = |p: &ast::Pou| -> Vec<usize> {
        let mut out = Vec::new();
        for d in p.var_blocks.iter().flat_map(|b| b.vars.iter()) {
            let mut ty = &d.ty;
            while let TypeRef::Array { element, .. } = ty {
                ty = element;
            }
            if let TypeRef::Named(n) = ty {
                if let Some(&i) = index.get(&n.key()) {
                    out.push(i);
                }
            }
        }
        // popped from the end: reversed, the first-declared variable's block is placed first
        out.reverse();
        out
    };
    let mut state = vec![0u8; pous.len()]; // 0 new, 1 on the path, 2 placed
    let mut order = Vec::with_capacity(pous.len());
    for start in 0..pous.len() {
        if state[start] != 0 {
            continue;
        }
        state[start] = 1;
        let mut stack: Vec<(usize, Vec<usize>)> = vec![(start, needs(pous[start].1))];
        while let Some((at, pending)) = stack.last_mut() {
            let at = *at;
            match pending.pop() {
                Some(next) if state[next] == 0 => {
                    state[next] = 1;
                    let n = needs(pous[next].1);
                    stack.push((next, n));
                }
                Some(_) => {}
                None => {
                    state[at] = 2;
                    order.push(pous[at]);
                    stack.pop();
                }
            }
        }
    }
    order
}

impl super::Analyzer<'_> {
    /// Adds to `consts` the constants `decls` declare (the variables of CONSTANT blocks), evaluated
    /// silently in rounds until a round adds none: a constant may name one declared after it
    /// (`stepSize : INT := DEFAULT_STEP;` above `VAR_GLOBAL CONSTANT DEFAULT_STEP : INT := 10;`),
    /// as IEC 61131-3 (ed. 3, 6.5.1: an initial value is a constant expression) sets no textual
    /// order, and CODESYS, TwinCAT and SIMATIC AX resolve names, not positions. A name already in
    /// `consts` is replaced (the nearer declaration hides the farther one). Their errors are
    /// reported when the declarations are read in order. With `scalar_only`, only constants of
    /// elementary, string and enumerated types (structures may not be declared yet).
    pub(super) fn constants_in_any_order(
        &mut self,
        decls: &[&ast::VarDecl],
        consts: &mut Consts,
        scalar_only: bool,
    ) {
        let silent = std::mem::replace(&mut self.silent, true);
        let mut done = vec![false; decls.len()];
        // each round places at least one constant or is the last: at most `decls.len() + 1`
        loop {
            let mut placed = false;
            for (d, done) in decls.iter().zip(done.iter_mut()) {
                if *done {
                    continue;
                }
                let Some(init @ ast::Initializer::Value(_)) = &d.init else {
                    *done = true;
                    continue;
                };
                if scalar_only && !matches!(d.ty, TypeRef::Named(_) | TypeRef::String { .. }) {
                    *done = true;
                    continue;
                }
                let ty = self.resolve_type(&d.ty);
                if scalar_only
                    && !matches!(
                        ty,
                        Type::Elementary(_) | Type::String { .. } | Type::Enum(_)
                    )
                {
                    *done = true;
                    continue;
                }
                if let Some(v) = self.const_init(init, &ty, consts) {
                    consts.insert(d.name.key(), (ty, v));
                    *done = true;
                    placed = true;
                }
            }
            if !placed {
                break;
            }
        }
        self.silent = silent;
    }
}
